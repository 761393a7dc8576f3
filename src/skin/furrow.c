/* Distance to the furrow: the true distance from a point to the perturbed boundary of its
 * cell (not the (F2 - F1) / 2 shortcut of cellular noise, which is off by up to 0.4 cell
 * widths). The nearest boundary point of a point's own cell is the nearest furrow point,
 * since the segment to it crosses no other furrow. */
#include <math.h>

#include "skin/skin_internal.h"

static float seg_dist2(float px, float py, float ax, float ay, float bx, float by)
{
    float ex = bx - ax, ey = by - ay, wx = px - ax, wy = py - ay;
    float l2 = ex * ex + ey * ey;
    float t = l2 > 0 ? (wx * ex + wy * ey) / l2 : 0.0f;
    t = t < 0 ? 0 : (t > 1 ? 1 : t);
    float dx = wx - t * ex, dy = wy - t * ey;
    return dx * dx + dy * dy;
}

/* Squared distance from r (the edge's frame) to polyline segment i (vertices i, i + 1). */
static float polyline_dist2(const sk__edge *e, const float *f, float inv, int i, float rx, float ry)
{
    float t0 = (float)i * inv, t1 = (float)(i + 1) * inv;
    float x0 = e->ax + t0 * (e->bx - e->ax) + f[i] * e->dx;
    float y0 = e->ay + t0 * (e->by - e->ay) + f[i] * e->dy;
    float x1 = e->ax + t1 * (e->bx - e->ax) + f[i + 1] * e->dx;
    float y1 = e->ay + t1 * (e->by - e->ay) + f[i + 1] * e->dy;
    return seg_dist2(rx, ry, x0, y0, x1, y1);
}

/* Relative slack of the lower bounds that skip edges and segments: far above rounding, so
 * whatever is skipped could not have been the nearest. */
#define SK__FURROW_SLACK 1e-3f

/* Distance to the perturbed polyline of edge e from r (the edge's frame), at most best2 on
 * entry. With r = a + t_p (b - a) + s_p d (d the unit normal of the straight edge), a point
 * (t, f(t)) of the polyline lies (L (t - t_p))^2 + (f - s_p)^2 away (L = |b - a|): search
 * the segments outwards from t_p, skipping those whose bound is already too far. */
static float polyline_distance(const sk__level *lv, const sk__edge *e, float rx, float ry,
                               float best2)
{
    /* |f| <= bulge: every polyline point is at least |s_p| - bulge across */
    const float *f = lv->f + e->f_first;
    int segs = lv->f_count - 1;
    float inv = 1.0f / (float)segs;
    float ex = e->bx - e->ax, ey = e->by - e->ay, len2 = ex * ex + ey * ey;
    float wx = rx - e->ax, wy = ry - e->ay;
    float tp = e->atx * wx + e->aty * wy, sp = e->dx * wx + e->dy * wy;
    float ts = tp * (float)segs;
    int i0 = ts < 0.0f ? 0 : (ts >= (float)segs ? segs - 1 : (int)ts);
    float a = fabsf(sp) - e->bulge, a2 = a > 0 ? a * a : 0.0f;
    float limit = best2 * (1.0f + SK__FURROW_SLACK);
    for (int side = 0; side < 2; side++)
        for (int i = side ? i0 + 1 : i0; i >= 0 && i < segs; i += side ? 1 : -1) {
            /* along the edge */
            float gap = side ? (float)i * inv - tp : (i == i0 ? 0.0f : tp - (float)(i + 1) * inv);
            float b2 = gap > 0 ? len2 * gap * gap : 0.0f;
            if (b2 + a2 >= limit) break; /* and every segment beyond */
            /* across it */
            float lo = f[i] < f[i + 1] ? f[i] : f[i + 1], hi = f[i] < f[i + 1] ? f[i + 1] : f[i];
            float across = sp > hi ? sp - hi : (sp < lo ? lo - sp : 0.0f);
            if (b2 + across * across >= limit) continue;
            float s2 = polyline_dist2(e, f, inv, i, rx, ry);
            if (s2 < best2) best2 = s2, limit = best2 * (1.0f + SK__FURROW_SLACK);
        }
    return best2;
}

float sk__furrow_distance(const sk__level *lv, uint32_t c, float px, float py)
{
    const sk__cell *cell = &lv->cells[c];
    uint32_t n = cell->use_count, first = cell->first_use;
    /* distances to the sides' lines (lower bounds); the nearest side is searched first */
    float ld[SK__POLY_MAX];
    uint32_t nearest = 0;
    for (uint32_t k = 0; k < n && k < SK__POLY_MAX; k++) {
        const sk__use *u = &lv->uses[first + k];
        ld[k] = u->d - (u->nx * px + u->ny * py);
        if (ld[k] < ld[nearest]) nearest = k;
    }
    float best2 = INFINITY;
    for (uint32_t q = 0; q < n && q < SK__POLY_MAX; q++) {
        uint32_t k = q == 0 ? nearest : (q <= nearest ? q - 1 : q);
        const sk__use *u = &lv->uses[first + k];
        bool perturbed = lv->perturbed && u->edge != SK__SKIN_NONE;
        /* the polyline strays at most `bulge` from the straight side */
        float lb = ld[k] - (perturbed ? lv->edges[u->edge].bulge : 0.0f);
        if (lb > 0 && lb * lb >= best2 * (1.0f + SK__FURROW_SLACK)) continue;
        if (perturbed) {
            best2 = polyline_distance(lv, &lv->edges[u->edge], px + u->shx, py + u->shy, best2);
        } else {
            const sk__use *v = &lv->uses[k + 1 == n ? first : first + k + 1];
            float d2 = seg_dist2(px, py, u->vx, u->vy, v->vx, v->vy);
            if (d2 < best2) best2 = d2;
        }
    }
    return sqrtf(best2);
}
