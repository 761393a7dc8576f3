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

float sk__furrow_distance(const sk__level *lv, uint32_t c, float px, float py)
{
    const sk__cell *cell = &lv->cells[c];
    float best2 = INFINITY;
    for (uint32_t k = 0; k < cell->use_count; k++) {
        uint32_t ui = cell->first_use + k;
        uint32_t un = k + 1 == cell->use_count ? cell->first_use : ui + 1;
        const sk__use *u = &lv->uses[ui];
        float ax = u->vx, ay = u->vy, bx = lv->uses[un].vx, by = lv->uses[un].vy;
        float d2 = seg_dist2(px, py, ax, ay, bx, by);
        if (!lv->perturbed || u->edge == SK__SKIN_NONE) {
            if (d2 < best2) best2 = d2;
            continue;
        }
        const sk__edge *e = &lv->edges[u->edge];
        float lb = sqrtf(d2) - e->bulge;
        if (lb > 0 && lb * lb >= best2) continue;
        /* the polyline, in the edge's frame */
        float rx = px + u->shx, ry = py + u->shy;
        const float *f = lv->f + e->f_first;
        float inv = 1.0f / (float)(lv->f_count - 1);
        float qx = e->ax, qy = e->ay;
        for (int i = 1; i < lv->f_count; i++) {
            float t = (float)i * inv;
            float nx = e->ax + t * (e->bx - e->ax) + f[i] * e->dx;
            float ny = e->ay + t * (e->by - e->ay) + f[i] * e->dy;
            float s2 = seg_dist2(rx, ry, qx, qy, nx, ny);
            if (s2 < best2) best2 = s2;
            qx = nx, qy = ny;
        }
    }
    return sqrtf(best2);
}
