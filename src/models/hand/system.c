/* Assembly of the equilibrium system (K + A'WA) theta = tau_hat - A'Wb (eq. 3.17) and
 * of the energy 1/2 th'K th - tau_hat'th + J (eqs. 3.8, 3.14) whose minimum it is. */
#include <string.h>

#include "models/hand/dense_internal.h"
#include "models/hand/solver_internal.h"

void sk__hand_assemble(sk_hand_solver *s)
{
    memset(s->h, 0, sizeof s->h);
    memset(s->g0, 0, sizeof s->g0);
    memset(s->lut_curv, 0, sizeof s->lut_curv);
    s->c0 = 0.0;
    for (int i = 0; i < N_DOF; i++) s->h[i * N_DOF + i] = s->k[i];
    for (int r = 0; r < s->rows.row_count; r++) {
        const sk_hand_row *row = &s->rows.rows[r];
        for (int a = 0; a < row->term_count; a++) {
            double wa = row->weight * row->coeff[a];
            for (int b = 0; b < row->term_count; b++)
                s->h[row->dof[b] * N_DOF + row->dof[a]] += wa * row->coeff[b];
            s->g0[row->dof[a]] -= wa * row->b;
        }
        s->c0 += 0.5 * row->weight * row->b * row->b;
    }
    for (int p = 0; p < s->lut_count; p++) {
        s->lut_curv[s->luts[p].dof_x] += 2.0 * s->luts[p].weight;
        s->lut_curv[s->luts[p].dof_y] += 2.0 * s->luts[p].weight;
    }
    for (int i = 0; i < SK_HAND_MAX_CACHE; i++) s->cache[i].valid = false;
}

void sk__hand_matvec(const double *h, const double *x, double *y)
{
    double acc[N_DOF] = {0}; /* local, so the column updates vectorize (each entry's own
                                sum, in the same order) */
    for (int j = 0; j < N_DOF; j++) {
        double xj = x[j];
        if (xj == 0.0) continue;
        const double *col = h + (size_t)j * N_DOF;
#pragma omp simd
        for (int i = 0; i < N_DOF; i++) acc[i] += col[i] * xj;
    }
    memcpy(y, acc, sizeof acc);
}

double sk__hand_energy(const sk_hand_solver *s, const double *theta, const double *rhs,
                       double *grad)
{
    double ht[N_DOF];
    sk__hand_matvec(s->h, theta, ht);
    double e = s->c0;
    for (int i = 0; i < N_DOF; i++) {
        e += theta[i] * (0.5 * ht[i] - rhs[i]);
        if (grad) grad[i] = ht[i] - rhs[i];
    }
    for (int p = 0; p < s->lut_count; p++) {
        const sk_hand_lut *lut = &s->luts[p];
        int x = lut->dof_x, y = lut->dof_y;
        double gx, gy;
        e += sk_hand_lut_eval(lut, s->relaxed[x] + theta[x], s->relaxed[y] + theta[y], &gx, &gy);
        if (grad) {
            grad[x] += gx;
            grad[y] += gy;
        }
    }
    return e;
}

void sk__hand_equilibrium_matrix(const sk_hand_skeleton *skel, const sk_hand_constraints *c,
                                 double *h)
{
    memset(h, 0, sizeof(double) * N_DOF * N_DOF);
    for (int i = 0; i < N_DOF; i++)
        h[i * N_DOF + i] = c && c->has_stiffness[i] ? c->stiffness[i] : skel->dof[i].stiffness;
    for (int r = 0; c && r < c->row_count; r++) {
        const sk_hand_row *row = &c->rows[r];
        for (int a = 0; a < row->term_count; a++)
            for (int b = 0; b < row->term_count; b++)
                h[row->dof[b] * N_DOF + row->dof[a]] += row->weight * row->coeff[a] * row->coeff[b];
    }
}

sk_result sk__hand_check_positive_definite(const sk_hand_skeleton *skel,
                                           const sk_hand_constraints *c, sk_error *err)
{
    double h[N_DOF * N_DOF];
    sk__hand_equilibrium_matrix(skel, c, h);
    int info = sk__hand_cholesky_at(h, N_DOF);
    if (info > 0)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "K + A'WA is not positive definite (Cholesky fails at %s): a negative "
                       "weight outweighs the stiffness",
                       sk_hand_dof((int)info - 1)->name);
    return SK_OK;
}
