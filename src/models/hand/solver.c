/* The natural-posture solver of thesis 3.2: K theta = tau_hat + tau_c (eqs. 3.8, 3.9)
 * with tau_c = -dJ/dtheta (3.15), i.e. (K + A'WA) theta = tau_hat - A'Wb (3.17), driven
 * by torques and by pinned angles, within the joint limits. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "models/hand/solver_internal.h"

static sk_hand_solver_desc resolve_desc(const sk_hand_solver_desc *desc)
{
    sk_hand_solver_desc d = {0};
    if (desc) d = *desc;
    sk_schema_apply_defaults(&sk_hand_solver_schema, &d);
    return d;
}

sk_result sk_hand_solver_create(sk_hand_solver **out, const sk_hand_skeleton *skel,
                                const sk_hand_constraints *c, const sk_hand_lut *luts,
                                int lut_count, const sk_hand_solver_desc *desc, sk_error *err)
{
    *out = NULL;
    sk_hand_solver_desc d = resolve_desc(desc);
    sk_result r = sk_schema_check(&sk_hand_solver_schema, &d, "", err);
    if (r == SK_OK) r = sk_check_range_i(err, "lut_count", lut_count, 0, 64);
    if (r != SK_OK) return r;
    if (lut_count > 0 && !luts)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "luts is NULL with lut_count = %d",
                       lut_count);
    for (int p = 0; p < lut_count; p++)
        if (!sk_hand_dof(luts[p].dof_x) || !sk_hand_dof(luts[p].dof_y) || !luts[p].value)
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "luts[%d] is not built", p);
    if (c) {
        r = sk__hand_check_positive_definite(skel, c, err);
        if (r != SK_OK) return r;
    }
    sk_hand_solver *s = calloc(1, sizeof *s);
    if (!s) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    s->desc = d;
    for (int i = 0; i < N_DOF; i++) {
        s->relaxed[i] = skel->dof[i].relaxed;
        s->min_abs[i] = skel->dof[i].min;
        s->max_abs[i] = skel->dof[i].max;
        s->lo[i] = skel->dof[i].min - skel->dof[i].relaxed;
        s->hi[i] = skel->dof[i].max - skel->dof[i].relaxed;
        s->k[i] = c && c->has_stiffness[i] ? c->stiffness[i] : skel->dof[i].stiffness;
    }
    if (c) s->rows = *c;
    s->luts = luts;
    s->lut_count = lut_count;
    sk__hand_assemble(s);
    *out = s;
    return SK_OK;
}

void sk_hand_solver_destroy(sk_hand_solver *s) { free(s); }

sk_result sk_hand_solver_set_stiffness(sk_hand_solver *s, int dof, double k, sk_error *err)
{
    if (!sk_hand_dof(dof))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "dof = %d is not a DOF", dof);
    if (!(k > 0.0) || !isfinite(k))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "stiffness of %s = %g must be positive",
                       sk_hand_dof(dof)->name, k);
    s->k[dof] = k;
    sk__hand_assemble(s);
    return SK_OK;
}

sk_result sk_hand_solver_set_weight(sk_hand_solver *s, int row, double w, sk_error *err)
{
    if (row < 0 || row >= s->rows.row_count)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "row = %d is out of range [0, %d]", row,
                       s->rows.row_count - 1);
    if (!isfinite(w) || w == 0.0)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "weight = %g must be non-zero", w);
    double old = s->rows.rows[row].weight;
    s->rows.rows[row].weight = w;
    sk__hand_assemble(s);
    /* a negative weight may break positive definiteness: check with the full set */
    const sk_hand_factor *f = sk__hand_factor(s, 0, err);
    if (!f) {
        s->rows.rows[row].weight = old;
        sk__hand_assemble(s);
        return SK_ERROR_INVALID_ARGUMENT;
    }
    return SK_OK;
}

const double *sk_hand_solver_matrix(const sk_hand_solver *s) { return s->h; }
const double *sk_hand_solver_rhs_constant(const sk_hand_solver *s) { return s->g0; }

sk_result sk_hand_solve(sk_hand_solver *s, const sk_hand_input *in, double dofs[SK_HAND_DOF_COUNT],
                        sk_hand_solve_info *info, sk_error *err)
{
    double theta[N_DOF], rhs[N_DOF];
    int pins_clamped = 0;
    for (int i = 0; i < N_DOF; i++) {
        if (!isfinite(in->torque[i]))
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "torque of %s is not finite",
                           sk_hand_dof(i)->name);
        rhs[i] = in->torque[i] + s->g0[i];
        theta[i] = 0.0;
        if (in->pinned[i]) {
            if (!isfinite(in->pin_value[i]))
                return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "pin of %s is not finite",
                               sk_hand_dof(i)->name);
            double v = in->pin_value[i] - s->relaxed[i];
            double c = sk_clampd(v, s->lo[i], s->hi[i]);
            pins_clamped += c != v;
            theta[i] = c;
        }
    }
    sk_hand_solve_info local;
    sk_hand_solve_info *inf = info ? info : &local;
    memset(inf, 0, sizeof *inf);
    sk_result r = s->lut_count > 0 ? sk__hand_solve_lut(s, in->pinned, theta, rhs, inf, err)
                                   : sk__hand_solve_linear(s, in->pinned, theta, rhs, inf, err);
    if (r != SK_OK) return r;
    inf->pins_clamped = pins_clamped;
    for (int i = 0; i < N_DOF; i++) {
        /* a DOF held at a limit reports the limit exactly (relaxed + (min - relaxed) may
           differ from min in the last bit) */
        if (theta[i] <= s->lo[i])
            dofs[i] = s->min_abs[i];
        else if (theta[i] >= s->hi[i])
            dofs[i] = s->max_abs[i];
        else
            dofs[i] = sk_clampd(s->relaxed[i] + theta[i], s->min_abs[i], s->max_abs[i]);
    }
    return SK_OK;
}
