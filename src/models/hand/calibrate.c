/* Calibration of constraint rows, thesis 3.2.2: a least-squares line through measured
 * samples of each correlated joint pair gives a row of A and b, and the spread of the
 * samples about the line its weight, w_k = sum_i l_i^2 / (n w_max) (eq. 3.18). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "models/hand/hand_internal.h"

sk_result sk_hand_calibrate(const double *const columns[SK_HAND_DOF_COUNT], int n,
                            const int (*pairs)[2], int pair_count, sk_hand_weight_rule rule,
                            sk_hand_fit *fits, sk_error *err)
{
    if (rule == SK_HAND_WEIGHT_DEFAULT) rule = SK_HAND_WEIGHT_THESIS;
    if (rule != SK_HAND_WEIGHT_THESIS && rule != SK_HAND_WEIGHT_INVERSE_VARIANCE)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "weight rule %d is unknown", (int)rule);
    if (n < 3)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "%d samples: a fit needs at least 3", n);
    if (pair_count < 1) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "no pairs to fit");
    for (int k = 0; k < pair_count; k++) {
        int dx = pairs[k][0], dy = pairs[k][1];
        if (!sk_hand_dof(dx) || !sk_hand_dof(dy))
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "pair %d: not a DOF index", k);
        const double *x = columns[dx], *y = columns[dy];
        if (!x || !y)
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "pair %s:%s: no samples of %s",
                           sk_hand_dof(dx)->name, sk_hand_dof(dy)->name,
                           sk_hand_dof(x ? dy : dx)->name);
        /* ordinary least squares y = a x + c (step 6 of 3.2.2), centred sums */
        double mx = 0.0, my = 0.0;
        for (int i = 0; i < n; i++) {
            mx += x[i];
            my += y[i];
        }
        mx /= n;
        my /= n;
        double sxx = 0.0, sxy = 0.0;
        for (int i = 0; i < n; i++) {
            sxx += (x[i] - mx) * (x[i] - mx);
            sxy += (x[i] - mx) * (y[i] - my);
        }
        if (!(sxx > 1e-18 * n))
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "pair %s:%s: %s does not vary in the samples, no line can be fitted",
                           sk_hand_dof(dx)->name, sk_hand_dof(dy)->name, sk_hand_dof(dx)->name);
        double a = sxy / sxx, c = my - a * mx;
        /* l_i: Euclidean distance of sample i from the line */
        double norm = sqrt(a * a + 1.0), sum = 0.0;
        for (int i = 0; i < n; i++) {
            double l = (a * x[i] - y[i] + c) / norm;
            sum += l * l;
        }
        fits[k] = (sk_hand_fit){dx, dy, a, c, sum / n, 0.0, n};
    }
    double max_ms = 0.0, min_ms = INFINITY;
    for (int k = 0; k < pair_count; k++) {
        max_ms = fmax(max_ms, fits[k].mean_sq_distance);
        min_ms = fmin(min_ms, fits[k].mean_sq_distance);
    }
    /* samples exactly on their lines leave the spread undefined: weight 1 */
    const double floor_ms = 1e-16;
    for (int k = 0; k < pair_count; k++) {
        double ms = fits[k].mean_sq_distance;
        if (rule == SK_HAND_WEIGHT_THESIS)
            fits[k].weight = max_ms > floor_ms ? fmax(ms, floor_ms) / max_ms : 1.0;
        else
            fits[k].weight = fmax(min_ms, floor_ms) / fmax(ms, floor_ms);
    }
    /* sums of huge samples overflow: a row that is not finite would be written as null */
    for (int k = 0; k < pair_count; k++) {
        const sk_hand_fit *f = &fits[k];
        if (!isfinite(f->slope) || !isfinite(f->intercept) || !isfinite(f->mean_sq_distance) ||
            !isfinite(f->weight))
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "pair %s:%s: the fit overflows (samples too large to square)",
                           sk_hand_dof(f->dof_x)->name, sk_hand_dof(f->dof_y)->name);
    }
    return SK_OK;
}
