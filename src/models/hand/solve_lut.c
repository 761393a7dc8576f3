/* Equilibrium with lookup-table potentials (thesis 3.2.3): the energy
 * 1/2 th'K th - tau_hat'th + J + sum_p V_p is no longer quadratic, so the equilibrium
 * (zero gradient, internal input = minus the tabulated gradient) is found iteratively by
 * a globalised projected Newton method: the exact Hessian of the interpolated energy
 * (K + A'WA plus each table's second derivatives), shifted toward the identity until
 * positive definite (Levenberg), a backtracking line search that never lets the energy
 * increase, and the Gauss-Newton step (curvature 2w of the squared distance) as the
 * fallback direction; limits kept by projection. A solve that can make no more progress
 * stops and says so (converged false, its residual). */
#include <math.h>
#include <string.h>

#include "models/hand/dense_internal.h"
#include "models/hand/solver_internal.h"

/* Free DOFs: not pinned and not held at a limit by a gradient pushing outward. */
static uint64_t fixed_set(const sk_hand_solver *s, const bool *pinned, const double *theta,
                          const double *grad)
{
    uint64_t m = 0;
    for (int i = 0; i < N_DOF; i++) {
        bool held = pinned[i] || (theta[i] <= s->lo[i] && grad[i] > 0.0) ||
                    (theta[i] >= s->hi[i] && grad[i] < 0.0);
        if (held) m |= (uint64_t)1 << i;
    }
    return m;
}

/* Projected backtracking line search along d (indexed by free[]); true if accepted. */
static bool line_search(sk_hand_solver *s, const int *free_dof, int nf, const double *d,
                        const double *rhs, double *theta, double *grad, double *energy)
{
    double trial[N_DOF], grad_new[N_DOF];
    double alpha = 1.0;
    for (int ls = 0; ls < 40; ls++, alpha *= 0.5) {
        for (int i = 0; i < N_DOF; i++) trial[i] = theta[i];
        double slope = 0.0;
        bool moved = false;
        for (int a = 0; a < nf; a++) {
            int i = free_dof[a];
            trial[i] = sk_clampd(theta[i] + alpha * d[a], s->lo[i], s->hi[i]);
            slope += grad[i] * (trial[i] - theta[i]);
            moved |= trial[i] != theta[i];
        }
        if (!moved || slope >= 0.0) return false;
        double e = sk__hand_energy(s, trial, rhs, grad_new);
        /* Armijo on the projected step: a real decrease, never an increase */
        if (e <= *energy + 1e-4 * slope) {
            *energy = e;
            memcpy(theta, trial, sizeof trial);
            memcpy(grad, grad_new, sizeof grad_new);
            return true;
        }
    }
    return false;
}

/* Newton direction on the free DOFs from the exact Hessian of the interpolated energy,
 * shifted by mu I until positive definite. */
static bool newton_direction(const sk_hand_solver *s, const int *free_dof, int nf,
                             const double *theta, const double *grad, double *d)
{
    double hess[N_DOF * N_DOF];
    memcpy(hess, s->h, sizeof hess);
    for (int p = 0; p < s->lut_count; p++) {
        const sk_hand_lut *lut = &s->luts[p];
        int x = lut->dof_x, y = lut->dof_y;
        double g[2], h[3];
        sk__hand_lut_eval_hessian(lut, s->relaxed[x] + theta[x], s->relaxed[y] + theta[y], g, h);
        hess[x * N_DOF + x] += h[0];
        hess[y * N_DOF + y] += h[1];
        hess[x * N_DOF + y] += h[2];
        hess[y * N_DOF + x] += h[2];
    }
    double m[N_DOF * N_DOF], scale = 0.0;
    for (int a = 0; a < nf; a++) scale = fmax(scale, fabs(hess[free_dof[a] * N_DOF + free_dof[a]]));
    double mu = 0.0;
    for (int attempt = 0; attempt < 30; attempt++) {
        for (int b = 0; b < nf; b++)
            for (int a = 0; a < nf; a++)
                m[b * nf + a] = hess[free_dof[b] * N_DOF + free_dof[a]] + (a == b ? mu : 0.0);
        if (sk__hand_cholesky(m, nf)) {
            for (int a = 0; a < nf; a++) d[a] = -grad[free_dof[a]];
            sk__hand_cholesky_solve(m, nf, d, 1);
            return true;
        }
        mu = mu == 0.0 ? 1e-6 * fmax(scale, 1e-12) : mu * 10.0;
    }
    return false;
}

sk_result sk__hand_solve_lut(sk_hand_solver *s, const bool *pinned, double *theta,
                             const double *rhs, sk_hand_solve_info *info, sk_error *err)
{
    /* start from the equilibrium of the linear part alone */
    sk_result r = sk__hand_solve_linear(s, pinned, theta, rhs, info, err);
    if (r != SK_OK) return r;
    int linear_iterations = info ? info->active_set_iterations : 0;
    double grad[N_DOF], d[N_DOF];
    double energy = sk__hand_energy(s, theta, rhs, grad);
    double residual = 0.0;
    bool converged = false;
    int it = 0;
    for (;;) {
        uint64_t fixed = fixed_set(s, pinned, theta, grad);
        residual = 0.0;
        int free_dof[N_DOF], nf = 0;
        for (int i = 0; i < N_DOF; i++)
            if (!(fixed >> i & 1)) {
                residual = fmax(residual, fabs(grad[i]));
                free_dof[nf++] = i;
            }
        if (residual <= s->desc.tolerance) {
            converged = true;
            break;
        }
        if (it >= s->desc.max_newton_iterations) break;
        it++;
        bool accepted = newton_direction(s, free_dof, nf, theta, grad, d) &&
                        line_search(s, free_dof, nf, d, rhs, theta, grad, &energy);
        if (!accepted) {
            /* fallback: the Gauss-Newton step of the cached factorisation */
            const sk_hand_factor *f = sk__hand_factor(s, fixed | SK_HAND_FACTOR_LUT_BIT, err);
            if (!f) return err ? err->result : SK_ERROR_NUMERIC;
            for (int a = 0; a < f->nf; a++) d[a] = -grad[f->free_dof[a]];
            sk__hand_factor_solve(f, d);
            accepted = line_search(s, f->free_dof, f->nf, d, rhs, theta, grad, &energy);
        }
        if (!accepted) break; /* no descent left: reported as not converged */
    }
    if (info) {
        int clamped = 0;
        for (int i = 0; i < N_DOF; i++)
            if (!pinned[i] && (theta[i] <= s->lo[i] || theta[i] >= s->hi[i])) clamped++;
        info->active_set_iterations = linear_iterations;
        info->newton_iterations = it;
        info->clamped_count = clamped;
        info->residual = residual;
        info->energy = energy;
        info->converged = converged;
    }
    return SK_OK;
}
