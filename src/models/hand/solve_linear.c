/* The equilibrium (3.17) with pinned DOFs and joint limits: the free DOFs solve the
 * reduced system H_ff th_f = (tau_hat - A'Wb)_f - H_fp th_p with a cached Cholesky
 * factorisation; DOFs that leave their range are held at the limit and the system is
 * solved again, and a held DOF is released when its equilibrium would pull it back
 * inside (a primal active-set method for the box-constrained quadratic energy). */
#include <math.h>

#include "models/hand/solver_internal.h"

/* state: 0 free, -1 at the lower limit, +1 at the upper limit, 2 pinned */
static uint64_t fixed_mask(const int8_t *state)
{
    uint64_t m = 0;
    for (int i = 0; i < N_DOF; i++)
        if (state[i] != 0) m |= (uint64_t)1 << i;
    return m;
}

sk_result sk__hand_solve_linear(sk_hand_solver *s, const bool *pinned, double *theta,
                                const double *rhs, sk_hand_solve_info *info, sk_error *err)
{
    int8_t state[N_DOF];
    for (int i = 0; i < N_DOF; i++) {
        state[i] = pinned[i] ? 2 : s->clamp_side[i];
        if (state[i] == -1) theta[i] = s->lo[i];
        if (state[i] == 1) theta[i] = s->hi[i];
    }
    double b[N_DOF], grad[N_DOF];
    const int max_iterations = 4 * N_DOF + 8;
    bool converged = false;
    int it = 0;
    while (it < max_iterations) {
        it++;
        const sk_hand_factor *f = sk__hand_factor(s, fixed_mask(state), err);
        if (!f) return err ? err->result : SK_ERROR_NUMERIC;
        int fixed[N_DOF], fixed_count = 0; /* the held DOFs, in order */
        for (int j = 0; j < N_DOF; j++)
            if (state[j] != 0) fixed[fixed_count++] = j;
        for (int a = 0; a < f->nf; a++) {
            int i = f->free_dof[a];
            double v = rhs[i];
            for (int q = 0; q < fixed_count; q++)
                v -= s->h[(size_t)fixed[q] * N_DOF + i] * theta[fixed[q]];
            b[a] = v;
        }
        sk__hand_factor_solve(f, b);
        bool violated = false;
        for (int a = 0; a < f->nf; a++) {
            int i = f->free_dof[a];
            theta[i] = b[a];
            if (theta[i] < s->lo[i]) {
                state[i] = -1;
                theta[i] = s->lo[i];
                violated = true;
            } else if (theta[i] > s->hi[i]) {
                state[i] = 1;
                theta[i] = s->hi[i];
                violated = true;
            }
        }
        if (violated) continue;
        /* a DOF held at a limit stays held only while its equilibrium pushes outward */
        sk__hand_matvec(s->h, theta, grad);
        int worst = -1;
        double worst_v = 1e-12;
        for (int i = 0; i < N_DOF; i++) {
            grad[i] -= rhs[i];
            if (state[i] == -1 || state[i] == 1) {
                double pull_inside = state[i] == -1 ? -grad[i] : grad[i];
                if (pull_inside > worst_v) {
                    worst_v = pull_inside;
                    worst = i;
                }
            }
        }
        if (worst < 0) {
            converged = true;
            break;
        }
        state[worst] = 0;
    }
    double residual = 0.0, energy = s->c0;
    int clamped = 0;
    if (!converged) { /* (converged, grad is already H th - rhs at this theta) */
        sk__hand_matvec(s->h, theta, grad);
        for (int i = 0; i < N_DOF; i++) grad[i] -= rhs[i];
    }
    for (int i = 0; i < N_DOF; i++) {
        /* 1/2 th'H th - rhs'th = th'(grad - rhs) / 2 */
        energy += 0.5 * theta[i] * (grad[i] - rhs[i]);
        if (state[i] == 0) residual = fmax(residual, fabs(grad[i]));
        if (state[i] == -1 || state[i] == 1) clamped++;
        s->clamp_side[i] = state[i] == 2 ? 0 : state[i];
    }
    if (info) {
        info->active_set_iterations = it;
        info->clamped_count = clamped;
        info->residual = residual;
        info->converged = converged;
        info->energy = energy;
    }
    return SK_OK;
}
