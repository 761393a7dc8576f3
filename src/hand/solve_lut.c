/* Equilibrium with lookup-table potentials (thesis 3.2.3): the energy
 * 1/2 th'K th - tau_hat'th + J + sum_p V_p is no longer quadratic, so the equilibrium
 * (zero gradient, internal input = minus the tabulated gradient) is found iteratively:
 * projected damped Newton steps with the exact linear part K + A'WA plus the squared
 * distance's curvature 2w on the paired DOFs, a backtracking line search that never
 * lets the energy increase, limits kept by projection. */
#include <math.h>

#include "hand/solver_private.h"

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

sk_result sk_hand__solve_lut(sk_hand_solver *s, const bool *pinned, double *theta,
                             const double *rhs, sk_hand_solve_info *info, sk_error *err)
{
    /* start from the equilibrium of the linear part alone */
    sk_result r = sk_hand__solve_linear(s, pinned, theta, rhs, info, err);
    if (r != SK_OK) return r;
    int linear_iterations = info ? info->active_set_iterations : 0;
    double grad[N_DOF], grad_new[N_DOF], trial[N_DOF], d[N_DOF];
    double energy = sk_hand__energy(s, theta, rhs, grad);
    double residual = 0.0;
    bool converged = false;
    int it = 0;
    for (;;) {
        uint64_t fixed = fixed_set(s, pinned, theta, grad);
        residual = 0.0;
        for (int i = 0; i < N_DOF; i++)
            if (!(fixed >> i & 1)) residual = fmax(residual, fabs(grad[i]));
        if (residual <= s->desc.tolerance) {
            converged = true;
            break;
        }
        if (it >= s->desc.max_newton_iterations) break;
        it++;
        const sk_hand_factor *f = sk_hand__factor(s, fixed | SK_HAND_FACTOR_LUT_BIT, err);
        if (!f) return err ? err->result : SK_ERROR_NUMERIC;
        for (int a = 0; a < f->nf; a++) d[a] = -grad[f->free_dof[a]];
        sk_hand__factor_solve(f, d);
        double alpha = 1.0;
        bool accepted = false;
        for (int ls = 0; ls < 40; ls++, alpha *= 0.5) {
            for (int i = 0; i < N_DOF; i++) trial[i] = theta[i];
            double slope = 0.0;
            for (int a = 0; a < f->nf; a++) {
                int i = f->free_dof[a];
                trial[i] = sk_clampd(theta[i] + alpha * d[a], s->lo[i], s->hi[i]);
                slope += grad[i] * (trial[i] - theta[i]);
            }
            double e = sk_hand__energy(s, trial, rhs, grad_new);
            /* Armijo on the projected step; never an increase */
            if (e <= energy + 1e-4 * fmin(slope, 0.0)) {
                accepted = true;
                energy = e;
                for (int i = 0; i < N_DOF; i++) {
                    theta[i] = trial[i];
                    grad[i] = grad_new[i];
                }
                break;
            }
        }
        if (!accepted) break; /* no descent left along the Newton direction */
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
