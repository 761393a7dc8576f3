/* Constraint sets of natural posture, thesis 3.2.2: rows of A theta + b = 0 (eq. 3.13)
 * with their weights W (eq. 3.14), read from JSON files keyed by DOF names. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "models/hand/hand_internal.h"
#include "models/hand/potential_internal.h"
#include "models/hand/solver_internal.h"
#include "shitsukan/io.h"

/* Adds a row given on absolute angles or displacements (radians). */
sk_result sk__hand_constraints_add_row(sk_hand_constraints *c, const sk_hand_skeleton *s,
                                       const int *dof, const double *coeff, int n, double b,
                                       double weight, bool absolute, const char *label,
                                       const char *path, sk_error *err)
{
    if (c->row_count >= SK_HAND_MAX_ROWS)
        return sk_fail(err, SK_ERROR_LIMIT, "%s: more than %d rows", path, SK_HAND_MAX_ROWS);
    if (!isfinite(weight) || weight == 0.0)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "%s.W = %g must be a non-zero number", path,
                       weight);
    sk_hand_row *row = &c->rows[c->row_count];
    memset(row, 0, sizeof *row);
    double shift = 0.0;
    for (int i = 0; i < n; i++) {
        if (!isfinite(coeff[i]))
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "%s: coefficient of %s is not finite",
                           path, sk_hand_dof(dof[i])->name);
        if (sk_hand_dof(dof[i])->translation)
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "%s: %s is a translation; rows relate joint angles only", path,
                           sk_hand_dof(dof[i])->name);
        for (int j = 0; j < i; j++)
            if (dof[j] == dof[i])
                return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "%s: %s appears twice", path,
                               sk_hand_dof(dof[i])->name);
        row->dof[i] = dof[i];
        row->coeff[i] = coeff[i];
        shift += coeff[i] * s->dof[dof[i]].relaxed;
    }
    row->term_count = n;
    /* sum c (theta + theta_bar) + b = 0  <=>  sum c theta + (b + sum c theta_bar) = 0 */
    row->b = absolute ? b + shift : b;
    row->weight = weight;
    snprintf(row->label, sizeof row->label, "%s", label);
    c->row_count++;
    return SK_OK;
}

sk_result sk_hand_constraints_add_pair(sk_hand_constraints *c, const sk_hand_skeleton *s, int dof_x,
                                       int dof_y, double slope, double intercept, double weight,
                                       bool absolute, sk_error *err)
{
    if (!sk_hand_dof(dof_x) || !sk_hand_dof(dof_y) || dof_x == dof_y)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "pair needs two different DOFs");
    int dof[2] = {dof_x, dof_y};
    double coeff[2] = {slope, -1.0};
    char label[64];
    snprintf(label, sizeof label, "%s:%s", sk_hand_dof(dof_x)->name, sk_hand_dof(dof_y)->name);
    return sk__hand_constraints_add_row(c, s, dof, coeff, 2, intercept, weight, absolute, label,
                                        label, err);
}
