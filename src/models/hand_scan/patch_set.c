/* Fitting all 96 patches of thesis 4.1.4 and their errors in the form of Table 4.1: every
 * patch fitted to its region's points (in parallel, each patch on one thread), then the
 * distance of each of its points to the nearest of its 100 x 100 facets, for the scanned
 * points and for the true surface points they sampled, summed per side in patch order. */
#include <stdlib.h>
#include <string.h>

#include "models/hand_scan/scan_internal.h"

/* Runs `work` on every patch with data, in parallel; the first failure wins. */
typedef sk_result (*patch_work)(sk_hand_patch_set *set, int k, const sk_hand_cloud *cloud,
                                const void *arg, sk_error *err);

static sk_result for_each_patch(sk_hand_patch_set *set, const sk_hand_cloud *cloud, patch_work work,
                                const void *arg, sk_error *err)
{
    sk_result first_error = SK_OK;
    sk_error first_err = {0};
#pragma omp parallel for schedule(dynamic, 1)
    for (int k = 0; k < set->count; k++) {
        if (set->data[k].count < 16) continue;
        sk_error e = {0};
        sk_result rk = work(set, k, cloud, arg, &e);
        if (rk != SK_OK) {
#pragma omp critical(sk_hand_patch_set)
            if (first_error == SK_OK) {
                first_error = rk;
                first_err = e;
            }
        }
    }
    if (first_error != SK_OK && err) *err = first_err;
    return first_error;
}

static sk_vec3d *gather(const sk_hand_patch_data *d, const sk_vec3d *from)
{
    sk_vec3d *p = malloc(sizeof *p * d->count);
    if (p)
        for (size_t i = 0; i < d->count; i++) p[i] = from[d->point[i]];
    return p;
}

static sk_result fit_one(sk_hand_patch_set *set, int k, const sk_hand_cloud *cloud, const void *arg,
                         sk_error *err)
{
    const sk_hand_patch_data *d = &set->data[k];
    sk_vec3d *pts = gather(d, cloud->position);
    if (!pts) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "fitting patch %d", k);
    sk_result r =
        sk_hand_patch_fit(pts, d->count, d->u, d->v, arg, &set->patch[k], &set->fit[k], NULL, err);
    free(pts);
    set->fitted[k] = r == SK_OK;
    return r;
}

sk_result sk_hand_patch_set_fit(sk_hand_patch_set *set, const sk_hand_cloud *cloud,
                                const sk_hand_patch_fit_desc *desc, sk_error *err)
{
    return for_each_patch(set, cloud, fit_one, desc, err);
}

static sk_result measure_one(sk_hand_patch_set *set, int k, const sk_hand_cloud *cloud,
                             const void *arg, sk_error *err)
{
    if (!set->fitted[k]) return SK_OK;
    const sk_hand_patch_data *d = &set->data[k];
    int splits = *(const int *)arg;
    for (int pass = 0; pass < 2; pass++) {
        const sk_vec3d *from = pass == 0 ? cloud->position : cloud->true_position;
        double **slot = pass == 0 ? &set->error_scan[k] : &set->error_truth[k];
        free(*slot);
        *slot = NULL;
        if (!from) continue;
        sk_vec3d *pts = gather(d, from);
        double *e = malloc(sizeof *e * d->count);
        sk_result r = pts && e ? sk_hand_patch_facet_distances(&set->patch[k], splits, pts,
                                                               d->count, d->u, d->v, e, err)
                               : sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "measuring patch %d", k);
        free(pts);
        if (r != SK_OK) {
            free(e);
            return r;
        }
        *slot = e;
    }
    return SK_OK;
}

sk_result sk_hand_patch_set_measure(sk_hand_patch_set *set, const sk_hand_cloud *cloud, int splits,
                                    sk_error *err)
{
    if (splits == 0) splits = 100;
    sk_result r = sk_check_range_i(err, "facet_splits", splits, 1, 1024);
    if (r != SK_OK) return r;
    return for_each_patch(set, cloud, measure_one, &splits, err);
}

static void accumulate(const sk_hand_patch_set *set, bool truth, int side, sk_hand_fit_error *out)
{
    double sum = 0.0;
    *out = (sk_hand_fit_error){0, 0, 0, -1};
    for (int k = 0; k < set->count; k++) {
        if (!set->fitted[k] || (side >= 0 && (int)set->patch[k].side != side)) continue;
        const double *e = truth ? set->error_truth[k] : set->error_scan[k];
        if (!e) continue;
        for (size_t i = 0; i < set->data[k].count; i++) {
            sum += e[i];
            if (e[i] > out->max_mm || out->worst_patch < 0)
                out->max_mm = e[i], out->worst_patch = k;
        }
        out->points += set->data[k].count;
    }
    out->mean_mm = out->points ? sum / (double)out->points : 0.0;
}

void sk_hand_table41_compute(const sk_hand_patch_set *set, sk_hand_table41 *out)
{
    memset(out, 0, sizeof *out);
    for (int side = 0; side < SK_HAND_SCAN_SIDE_COUNT; side++) {
        accumulate(set, false, side, &out->scan[side]);
        accumulate(set, true, side, &out->truth[side]);
        for (int k = 0; k < set->count; k++)
            out->patches_fitted[side] += set->fitted[k] && (int)set->patch[k].side == side;
    }
    accumulate(set, false, -1, &out->scan_all);
    accumulate(set, true, -1, &out->truth_all);
    out->has_truth = out->truth_all.points > 0;
}
