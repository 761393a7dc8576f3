/* Segmentation of the registered data, thesis 4.1.2: slice planes across the links (x =
 * const of the scanner, y = const of the hand frame; the thesis's about 50, 75 by default
 * here: the spacing at which 10 points per segment give its about 4000 polygon vertices),
 * the points "sufficiently near" each plane projected onto it, and every projected point
 * given to its nearest link, with polar coordinates about the point where that link's
 * axis crosses the plane. This re-orders the data, whose scan lines registration has
 * skewed. */
#include <stdlib.h>
#include <string.h>

#include "models/hand_scan/scan_internal.h"

static int compare_slice_points(const void *a, const void *b)
{
    const sk_hand_slice_point *x = a, *y = b;
    if (x->link != y->link) return x->link < y->link ? -1 : 1;
    if (x->theta != y->theta) return x->theta < y->theta ? -1 : 1;
    return x->point < y->point ? -1 : (x->point > y->point);
}

/* Where the link's axis crosses the plane y = c, clamped to the segment, in the plane. */
static sk_vec3d axis_crossing(const sk_hand_link_geometry *links, int l, double c)
{
    sk_vec3d a = links->a[l], b = links->b[l];
    double dy = b.y - a.y, t = fabs(dy) > 1e-9 ? (c - a.y) / dy : 0.5;
    t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
    sk_vec3d p = sk_v3d_add(a, sk_v3d_scale(sk_v3d_sub(b, a), t));
    p.y = c;
    return p;
}

sk_result sk_hand_slices_build(const sk_hand_cloud *cloud, const sk_hand_link_geometry *links,
                               const sk_hand_slices_desc *desc, sk_hand_slices *out, sk_error *err)
{
    memset(out, 0, sizeof *out);
    sk_hand_slices_desc d = desc ? *desc : (sk_hand_slices_desc){0};
    const sk_schema *schema = sk_schema_find(&sk_hand_scan_schema, "slices")->schema;
    sk_schema_apply_defaults(schema, &d);
    sk_result r = sk_schema_check(schema, &d, "slices", err);
    if (r != SK_OK) return r;
    if (cloud->count == 0)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "slices: the point cloud is empty");
    double lo = INFINITY, hi = -INFINITY;
    for (size_t i = 0; i < cloud->count; i++) {
        double y = cloud->position[i].y;
        if (y < lo) lo = y;
        if (y > hi) hi = y;
    }
    if (!(hi > lo))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "slices: the points have no extent along y");
    int n = d.count;
    double spacing = (hi - lo) / n;
    out->count = n;
    out->half_thickness_mm = d.half_thickness_mm;
    out->y = malloc(sizeof *out->y * (size_t)n);
    out->first = calloc((size_t)n + 1, sizeof *out->first);
    out->centre = malloc(sizeof *out->centre * (size_t)n);
    int *slice_of = malloc(sizeof *slice_of * cloud->count);
    if (!out->y || !out->first || !out->centre || !slice_of) {
        free(slice_of);
        sk_hand_slices_free(out);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "slices of %zu points", cloud->count);
    }
    for (int s = 0; s < n; s++) {
        out->y[s] = lo + (s + 0.5) * spacing;
        for (int l = 0; l < SK_HAND_LINK_COUNT; l++)
            out->centre[s][l] = axis_crossing(links, l, out->y[s]);
    }
    for (size_t i = 0; i < cloud->count; i++) {
        double y = cloud->position[i].y;
        int s = (int)floor((y - lo) / spacing);
        s = s < 0 ? 0 : (s >= n ? n - 1 : s);
        slice_of[i] = fabs(y - out->y[s]) <= d.half_thickness_mm ? s : -1;
        if (slice_of[i] >= 0) out->first[s + 1]++;
    }
    for (int s = 0; s < n; s++) out->first[s + 1] += out->first[s];
    size_t total = out->first[n];
    out->points = malloc(sizeof *out->points * (total ? total : 1));
    size_t *fill = malloc(sizeof *fill * (size_t)n);
    if (!out->points || !fill) {
        free(slice_of), free(fill);
        sk_hand_slices_free(out);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "slices of %zu points", total);
    }
    memcpy(fill, out->first, sizeof *fill * (size_t)n);
    for (size_t i = 0; i < cloud->count; i++)
        if (slice_of[i] >= 0) out->points[fill[slice_of[i]]++].point = (uint32_t)i;
    free(fill);
    free(slice_of);
#pragma omp parallel for schedule(dynamic, 1)
    for (int s = 0; s < n; s++) {
        for (size_t k = out->first[s]; k < out->first[s + 1]; k++) {
            sk_hand_slice_point *sp = &out->points[k];
            sk_vec3d q = cloud->position[sp->point];
            q.y = out->y[s]; /* projected onto the plane */
            int l = sk_hand_nearest_link(links, q, NULL);
            sk_vec3d c = out->centre[s][l];
            sp->link = (int16_t)l;
            sp->side = cloud->side[sp->point];
            sp->theta = (float)atan2(q.z - c.z, q.x - c.x);
            sp->r = (float)hypot(q.z - c.z, q.x - c.x);
        }
        qsort(out->points + out->first[s], out->first[s + 1] - out->first[s], sizeof *out->points,
              compare_slice_points);
    }
    return SK_OK;
}

void sk_hand_slices_free(sk_hand_slices *slices)
{
    free(slices->y);
    free(slices->first);
    free(slices->points);
    free(slices->centre);
    memset(slices, 0, sizeof *slices);
}
