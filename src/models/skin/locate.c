/* Point location in the cell hierarchy (paper sec. 3.2.3 (2): find the polygon that holds
 * the point at every level), and the perturbation as a map: a point is tested against the
 * perturbed polyline of the one edge whose support can hold it, then carried back
 * ("unwarped") into the straight cell, where the next level and the section profile live.
 *
 * The unwarp acts along the edge normal inside the support |s| < H(t):
 *   left of the polyline (s > f):  u = (s - f) / (H - f),  s0 = s - f (1 - u)^2
 *   right of it (s < f):           u = (f - s) / (H + f),  s0 = s - f (1 - u)^2
 * so the polyline s = f goes to the straight edge s0 = 0, the support's border stays put
 * with a continuous derivative, and the map is monotone in s for |f| < H. */
#include <math.h>

#include "models/skin/skin_internal.h"

/* Gauge of p in cell c seen from its site (<= 1 inside the straight cell) and the use that
 * attains it (the fan triangle). */
static float gauge_site(const sk__level *lv, uint32_t c, float px, float py, uint32_t *use)
{
    const sk__cell *cell = &lv->cells[c];
    const sk__fan *f = lv->fans + cell->first_use;
    float qx = px - cell->sx, qy = py - cell->sy;
    float best = -INFINITY;
    uint32_t arg = 0;
    for (uint32_t k = 0; k < cell->use_count; k++) {
        float g = f[k].gx * qx + f[k].gy * qy;
        if (g > best) best = g, arg = k;
    }
    if (use) *use = cell->first_use + arg;
    return best;
}

uint32_t sk__fan_use(const sk__level *lv, uint32_t c, float px, float py)
{
    uint32_t u;
    gauge_site(lv, c, px, py, &u);
    return u;
}

uint32_t sk__locate_level1(const sk_skin *skin, double x, double y, float *px, float *py,
                           uint32_t *use, double shift[2])
{
    const sk__grid *g = &skin->grid;
    const sk__level *lv = &skin->levels[0];
    x = sk__wrap(x, skin->period[0]);
    y = sk__wrap(y, skin->period[1]);
    int gx = (int)(x * g->inv_w), gy = (int)(y * g->inv_h);
    if (gx >= g->nx) gx = g->nx - 1;
    if (gy >= g->ny) gy = g->ny - 1;
    size_t sq = (size_t)gy * (size_t)g->nx + (size_t)gx;
    uint32_t best = SK__SKIN_NONE, best_use = 0, best_e = 0;
    float best_g = INFINITY;
    for (uint32_t e = g->start[sq]; e < g->start[sq + 1]; e++) {
        uint32_t c = g->cell[e], u;
        float lx = (float)(x - g->shift[2 * e]), ly = (float)(y - g->shift[2 * e + 1]);
        float gauge = gauge_site(lv, c, lx, ly, &u);
        if (gauge < best_g) best_g = gauge, best = c, best_use = u, best_e = e;
        if (gauge <= 1.0f) break;
    }
    if (best == SK__SKIN_NONE) return best;
    shift[0] = g->shift[2 * best_e], shift[1] = g->shift[2 * best_e + 1];
    *px = (float)(x - shift[0]), *py = (float)(y - shift[1]);
    *use = best_use;
    return best;
}

uint32_t sk__locate_child(const sk__level *lv, uint32_t first, uint32_t count, float px, float py)
{
    float zx = lv->minvf[0][0] * px + lv->minvf[0][1] * py;
    float zy = lv->minvf[1][0] * px + lv->minvf[1][1] * py;
    const sk__cell *c = lv->cells + first;
    float best = INFINITY;
    uint32_t arg = 0;
    for (uint32_t i = 0; i < count; i++) {
        float dx = c[i].zx - zx, dy = c[i].zy - zy, d2 = dx * dx + dy * dy;
        if (d2 < best) best = d2, arg = i;
    }
    return first + arg;
}

uint32_t sk__locate_straight(const sk_skin *skin, int level, double x, double y, float *px,
                             float *py)
{
    uint32_t use;
    double shift[2];
    uint32_t c = sk__locate_level1(skin, x, y, px, py, &use, shift);
    for (int k = 1; k <= level && c != SK__SKIN_NONE; k++) {
        const sk__cell *pc = &skin->levels[k - 1].cells[c];
        c = sk__locate_child(&skin->levels[k], pc->first_child, pc->child_count, *px, *py);
    }
    return c;
}

/* Perturbation offset f(t), its slope, and the support height H(t) with its slope. */
typedef struct edge_frame {
    float t, s, f, ft, H, Ht;
    float rx, ry; /* the point in the edge's (left) frame */
} edge_frame;

static bool edge_frame_at(const sk__level *lv, const sk__edge *e, float rx, float ry,
                          edge_frame *ef)
{
    float dx = rx - e->ax, dy = ry - e->ay;
    float t = e->atx * dx + e->aty * dy;
    if (!(t > 0.0f && t < 1.0f)) return false;
    float s = e->asx * dx + e->asy * dy;
    float H, Ht;
    if (t < e->t_apex)
        H = e->rise * t, Ht = e->rise;
    else
        H = e->fall * (1.0f - t), Ht = -e->fall;
    if (!(fabsf(s) < H)) return false;
    const float *f = lv->f + e->f_first;
    float tf = t * (float)(lv->f_count - 1);
    int i = (int)tf;
    if (i > lv->f_count - 2) i = lv->f_count - 2;
    float fr = tf - (float)i;
    ef->t = t, ef->s = s;
    ef->f = f[i] + (f[i + 1] - f[i]) * fr;
    ef->ft = (f[i + 1] - f[i]) * (float)(lv->f_count - 1);
    ef->H = H, ef->Ht = Ht;
    ef->rx = rx, ef->ry = ry;
    return true;
}

uint32_t sk__unwarp(const sk__level *lv, const sk__fan *fan, float *px, float *py, float jac[2][2],
                    float *pre_x, float *pre_y)
{
    const sk__edge *e = &lv->edges[fan->edge];
    edge_frame ef;
    if (!edge_frame_at(lv, e, *px + fan->shx, *py + fan->shy, &ef)) return fan->cell;
    bool left = ef.s > ef.f;
    uint32_t owner = left ? e->left : e->right;
    float f = ef.f, s = ef.s, H = ef.H;
    float k1 = 1.0f / (left ? H - f : H + f);
    float uu = left ? (s - f) * k1 : (f - s) * k1;
    float om = 1.0f - uu, w = om * om;
    float s0 = s - f * w;
    /* gradient of u (y space) */
    float gux, guy;
    if (left) {
        float k2 = uu * (ef.Ht - ef.ft) * k1;
        gux = (e->asx - ef.ft * e->atx) * k1 - k2 * e->atx;
        guy = (e->asy - ef.ft * e->aty) * k1 - k2 * e->aty;
    } else {
        float k2 = uu * (ef.Ht + ef.ft) * k1;
        gux = (ef.ft * e->atx - e->asx) * k1 - k2 * e->atx;
        guy = (ef.ft * e->aty - e->asy) * k1 - k2 * e->aty;
    }
    /* gradient of (s0 - s) = -f (1 - u)^2 */
    float gx = -w * ef.ft * e->atx + 2.0f * f * om * gux;
    float gy = -w * ef.ft * e->aty + 2.0f * f * om * guy;
    float ds = s0 - s;
    float nx = ef.rx + ds * e->dx, ny = ef.ry + ds * e->dy;
    float ox = ef.rx, oy = ef.ry;
    if (!left) nx -= e->shx, ny -= e->shy, ox -= e->shx, oy -= e->shy;
    *px = nx, *py = ny;
    *pre_x = ox, *pre_y = oy;
    /* jac <- (I + d g^T) jac */
    float a00 = 1.0f + e->dx * gx, a01 = e->dx * gy, a10 = e->dy * gx, a11 = 1.0f + e->dy * gy;
    float j00 = a00 * jac[0][0] + a01 * jac[1][0], j01 = a00 * jac[0][1] + a01 * jac[1][1];
    float j10 = a10 * jac[0][0] + a11 * jac[1][0], j11 = a10 * jac[0][1] + a11 * jac[1][1];
    jac[0][0] = j00, jac[0][1] = j01, jac[1][0] = j10, jac[1][1] = j11;
    return owner;
}

/* The inverse of the unwarp: moves a point of the straight cell (at use ui's fan) onto the
 * perturbed geometry (outlines and pore positions; not a per-pixel path). */
static void warp(const sk__level *lv, uint32_t ui, double *px, double *py)
{
    const sk__fan *fan = &lv->fans[ui];
    if (fan->edge == SK__SKIN_NONE) return;
    const sk__edge *e = &lv->edges[fan->edge];
    edge_frame ef;
    double rx = *px + fan->shx, ry = *py + fan->shy;
    if (!edge_frame_at(lv, e, (float)rx, (float)ry, &ef)) return;
    double s0 = ef.s, f = ef.f, H = ef.H;
    /* Solve s0 = s - f (1 - u(s))^2 on the side of the polyline that s0 is on. */
    double lo, hi;
    if (s0 > 0)
        lo = f, hi = H;
    else if (s0 < 0)
        lo = -H, hi = f;
    else
        lo = hi = f;
    for (int it = 0; it < 60 && hi - lo > 1e-12 * (H + 1e-30); it++) {
        double s = 0.5 * (lo + hi);
        double uu = s > f ? (s - f) / (H - f) : (f - s) / (H + f);
        double val = s - f * (1.0 - uu) * (1.0 - uu);
        if (val < s0)
            lo = s;
        else
            hi = s;
    }
    double s = 0.5 * (lo + hi);
    *px += (s - s0) * e->dx;
    *py += (s - s0) * e->dy;
}

void sk__to_world(const sk_skin *skin, int k, uint32_t c, double px, double py, double *wx,
                  double *wy)
{
    for (int j = k; j >= 0; j--) {
        const sk__level *lv = &skin->levels[j];
        uint32_t u = sk__fan_use(lv, c, (float)px, (float)py);
        warp(lv, u, &px, &py);
        if (j > 0) c = lv->cells[c].parent;
    }
    *wx = px + skin->origin[2 * c];
    *wy = py + skin->origin[2 * c + 1];
}
