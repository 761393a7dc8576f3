/* Distance to the furrow: the true distance from a point to the perturbed boundary of its
 * cell (not the (F2 - F1) / 2 shortcut of cellular noise, which is off by up to 0.4 cell
 * widths). The nearest boundary point of a point's own cell is the nearest furrow point,
 * since the segment to it crosses no other furrow. */
#include <math.h>

#include "models/skin/skin_internal.h"

static float seg_dist2(float px, float py, float ax, float ay, float bx, float by)
{
    float ex = bx - ax, ey = by - ay, wx = px - ax, wy = py - ay;
    float l2 = ex * ex + ey * ey;
    float t = l2 > 0 ? (wx * ex + wy * ey) / l2 : 0.0f;
    t = t < 0 ? 0 : (t > 1 ? 1 : t);
    float dx = wx - t * ex, dy = wy - t * ey;
    return dx * dx + dy * dy;
}

/* Relative slack of the lower bounds that skip edges and segments: far above rounding, so
 * whatever is skipped could not have been the nearest. */
#define SK__FURROW_SLACK 1e-3f

/* The polyline in the edge's own orthonormal frame: u along the straight edge (u = L t,
 * L = |b - a|) and s across it (d is the unit normal), vertex i at (i h, f_i) with
 * h = L / segments. Distances are the same as in y space, with no vertex built there. */
typedef struct polyline_frame {
    const float *f;
    float h, up, sp; /* segment length along u; the point's u and s */
} polyline_frame;

/* Squared distance from the point to segment i, (i h, f_i) - ((i + 1) h, f_{i+1}). */
static inline float segment_dist2(const polyline_frame *pf, int i)
{
    float ey = pf->f[i + 1] - pf->f[i];
    float wx = pf->up - (float)i * pf->h, wy = pf->sp - pf->f[i];
    float l2 = pf->h * pf->h + ey * ey;
    float t = l2 > 0 ? (wx * pf->h + wy * ey) / l2 : 0.0f;
    t = t < 0 ? 0 : (t > 1 ? 1 : t);
    float dx = wx - t * pf->h, dy = wy - t * ey;
    return dx * dx + dy * dy;
}

/* Segment i, unless its lower bound (b2 along the edge, and across it the distance from
 * s_p to the segment's range of f) is already beyond `limit`. */
static inline void try_segment(const polyline_frame *pf, int i, float b2, float *best2,
                               float *limit)
{
    const float *f = pf->f;
    float lo = f[i] < f[i + 1] ? f[i] : f[i + 1], hi = f[i] < f[i + 1] ? f[i + 1] : f[i];
    float across = pf->sp > hi ? pf->sp - hi : (pf->sp < lo ? lo - pf->sp : 0.0f);
    if (b2 + across * across >= *limit) return;
    float s2 = segment_dist2(pf, i);
    if (s2 < *best2) *best2 = s2, *limit = s2 * (1.0f + SK__FURROW_SLACK);
}

/* Distance to the perturbed polyline of edge e from r (the edge's frame), at most best2 on
 * entry. With r = a + t_p (b - a) + s_p d, a point (t, f(t)) of the polyline lies
 * (L (t - t_p))^2 + (f - s_p)^2 away: search the segments outwards from t_p, skipping
 * those whose bound is already too far. */
static float polyline_distance(const sk__level *lv, const sk__edge *e, float rx, float ry,
                               float best2)
{
    int segs = lv->f_count - 1;
    float inv = lv->f_step;
    float ex = e->bx - e->ax, ey = e->by - e->ay, len2 = ex * ex + ey * ey, len = sqrtf(len2);
    float wx = rx - e->ax, wy = ry - e->ay;
    float tp = e->atx * wx + e->aty * wy;
    polyline_frame pf = {lv->f + e->f_first, len * inv, len * tp, e->dx * wx + e->dy * wy};
    float ts = tp * (float)segs;
    int i0 = ts < 0.0f ? 0 : (ts >= (float)segs ? segs - 1 : (int)ts);
    /* |f| <= bulge: every polyline point is at least |s_p| - bulge across */
    float a = fabsf(pf.sp) - e->bulge, a2 = a > 0 ? a * a : 0.0f;
    float limit = best2 * (1.0f + SK__FURROW_SLACK);
    /* towards t = 0 (segment i0 holds t_p), then towards t = 1; past the first segment
       whose bound along the edge is too far, every one beyond it is too */
    try_segment(&pf, i0, 0.0f, &best2, &limit);
    for (int i = i0 - 1; i >= 0; i--) {
        float gap = tp - (float)(i + 1) * inv;
        float b2 = gap > 0 ? len2 * gap * gap : 0.0f;
        if (b2 + a2 >= limit) break;
        try_segment(&pf, i, b2, &best2, &limit);
    }
    for (int i = i0 + 1; i < segs; i++) {
        float gap = (float)i * inv - tp;
        float b2 = gap > 0 ? len2 * gap * gap : 0.0f;
        if (b2 + a2 >= limit) break;
        try_segment(&pf, i, b2, &best2, &limit);
    }
    return best2;
}

/* Distance to a side of the cell: its perturbed polyline, or the straight side. */
static float side_distance(const sk__level *lv, const sk__use *u, const sk__use *next, float px,
                           float py, float best2)
{
    if (lv->perturbed && u->edge != SK__SKIN_NONE)
        return polyline_distance(lv, &lv->edges[u->edge], px + u->shx, py + u->shy, best2);
    float d2 = seg_dist2(px, py, u->vx, u->vy, next->vx, next->vy);
    return d2 < best2 ? d2 : best2;
}

/* The minimum over the sides is the same in any order, since a side or segment is skipped
 * only when its lower bound is beyond the nearest found: the side whose line is nearest
 * comes first (its furrow is usually the nearest), and sets the bound for the others. */
float sk__furrow_distance(const sk__level *lv, uint32_t c, float px, float py)
{
    const sk__cell *cell = &lv->cells[c];
    const sk__use *u = lv->uses + cell->first_use;
    uint32_t n = cell->use_count, nearest = 0;
    float nearest_line = INFINITY;
    for (uint32_t k = 0; k < n; k++) {
        float line = u[k].d - (u[k].nx * px + u[k].ny * py);
        if (line < nearest_line) nearest_line = line, nearest = k;
    }
    float best2 =
        side_distance(lv, &u[nearest], &u[nearest + 1 == n ? 0 : nearest + 1], px, py, INFINITY);
    for (uint32_t k = 0; k < n; k++) {
        if (k == nearest) continue;
        /* the polyline strays at most `bulge` from the straight side */
        float lb = u[k].d - (u[k].nx * px + u[k].ny * py) - u[k].bulge;
        if (lb > 0 && lb * lb >= best2 * (1.0f + SK__FURROW_SLACK)) continue;
        best2 = side_distance(lv, &u[k], &u[k + 1 == n ? 0 : k + 1], px, py, best2);
    }
    return sqrtf(best2);
}
