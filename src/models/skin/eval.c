/* Point query (paper sec. 3.2.3 (2), Fig. 10): walk down the levels, find the cell at each
 * level, evaluate its section profile, and sum heights over levels; normals combine as
 * gradients add (each level's normal scaled to z = 1, x and y parts summed), carried
 * through the perturbation maps by the chain rule, so the normal is the exact normal of
 * the height field. Allocation-free and thread-safe. */
#include <math.h>

#include "models/skin/skin_internal.h"

void sk__hint_reset(sk__hint *hint)
{
    for (int k = 0; k < SK_SKIN_MAX_LEVELS; k++)
        hint->fan[k] = SK__SKIN_NONE, hint->sector[k] = UINT32_MAX;
    hint->shift[0] = hint->shift[1] = 0.0;
}

/* When the point has left the hinted fan hf: a fan beside it in the same cell, or for a
 * child level (sibling cells share their parent's frame) the fan of the cell across hf's
 * edge, if it holds the point by the margin; else SK__SKIN_NONE. */
static uint32_t fan_nearby(const sk__level *lv, int k, uint32_t hf, float px, float py)
{
    const sk__cell *c = &lv->cells[lv->fans[hf].cell];
    uint32_t i = hf - c->first_use, n = c->use_count;
    uint32_t next = c->first_use + (i + 1 == n ? 0 : i + 1);
    uint32_t prev = c->first_use + (i == 0 ? n - 1 : i - 1);
    if (sk__in_fan(&lv->fans[next], px, py)) return next;
    if (sk__in_fan(&lv->fans[prev], px, py)) return prev;
    uint32_t nb = lv->uses[hf].neighbour;
    if (k == 0 || nb == SK__SKIN_NONE) return SK__SKIN_NONE;
    uint32_t f = sk__fan_use(lv, nb, px, py);
    return sk__in_fan(&lv->fans[f], px, py) ? f : SK__SKIN_NONE;
}

/* Level-1 fan of a point of the tile period: the hinted fan or one beside it, else from
 * the grid. Returns false if no cell holds the point. */
static bool locate_level1(const sk_skin *skin, double wx, double wy, sk__hint *hint, uint32_t *u,
                          float *px, float *py)
{
    const sk__level *lv = &skin->levels[0];
    uint32_t hf = hint->fan[0];
    if (hf != SK__SKIN_NONE) {
        float lx = (float)(wx - hint->shift[0]), ly = (float)(wy - hint->shift[1]);
        if (!sk__in_fan(&lv->fans[hf], lx, ly)) hf = fan_nearby(lv, 0, hf, lx, ly);
        if (hf != SK__SKIN_NONE) {
            *u = hint->fan[0] = hf, *px = lx, *py = ly;
            return true;
        }
    }
    double shift[2];
    if (sk__locate_level1(skin, wx, wy, px, py, u, shift) == SK__SKIN_NONE) return false;
    hint->fan[0] = *u, hint->shift[0] = shift[0], hint->shift[1] = shift[1];
    return true;
}

/* Fan of a point of level k >= 1 inside parent cell `parent`: the hinted fan or one near
 * it, else the nearest sibling's. */
static uint32_t locate_child(const sk_skin *skin, int k, uint32_t parent, float px, float py,
                             sk__hint *hint)
{
    const sk__level *lv = &skin->levels[k];
    uint32_t hf = hint->fan[k];
    if (hf != SK__SKIN_NONE && lv->fans[hf].parent == parent) {
        if (sk__in_fan(&lv->fans[hf], px, py)) return hf;
        uint32_t f = fan_nearby(lv, k, hf, px, py);
        if (f != SK__SKIN_NONE) return hint->fan[k] = f;
    }
    const sk__cell *pc = &skin->levels[k - 1].cells[parent];
    uint32_t c = sk__locate_child(lv, pc->first_child, pc->child_count, px, py);
    return hint->fan[k] = sk__fan_use(lv, c, px, py);
}

void sk__query(const sk_skin *skin, int n, const double *x, const double *y, unsigned flags,
               sk_skin_sample *out, sk__hint *hint)
{
    int L = skin->level_count;
    sk__hint local;
    if (!hint) {
        sk__hint_reset(&local);
        hint = &local;
    }
    unsigned furrow = flags & SK_SKIN_QUERY_FURROW ? ~0u : flags >> SK__FURROW_LEVEL_SHIFT;
    /* levels walked: every one, or the first `depth` with no relief (cells and furrows) */
    int depth = (int)(flags >> SK__QUERY_DEPTH_SHIFT & 0xffu);
    bool relief = depth == 0 || depth > L;
    int walked = relief ? L : depth;
    /* Points that lie in the skin, with their fan and position at the current level. */
    int idx[SK__QUERY_BATCH], m = 0;
    uint32_t u[SK__QUERY_BATCH], owner[SK__QUERY_BATCH];
    float px[SK__QUERY_BATCH], py[SK__QUERY_BATCH], jac[SK__QUERY_BATCH][4];
    int warped[SK__QUERY_BATCH]; /* first level whose unwarp moved the point (else L) */
    for (int j = 0; j < n; j++) {
        sk_skin_sample *o = &out[j];
        o->height_mm = 0.0f;
        o->normal = sk_v3f(0, 0, 1);
        double wx = sk__wrap(x[j], skin->period[0]), wy = sk__wrap(y[j], skin->period[1]);
        if (!isfinite(x[j]) || !isfinite(y[j]) ||
            !locate_level1(skin, wx, wy, hint, &u[m], &px[m], &py[m])) {
            for (int k = 0; k < L; k++) o->cell[k] = SK__SKIN_NONE, o->furrow_mm[k] = 0.0f;
            continue;
        }
        for (int k = walked; k < L; k++) o->cell[k] = SK__SKIN_NONE, o->furrow_mm[k] = 0.0f;
        jac[m][0] = 1, jac[m][1] = 0, jac[m][2] = 0, jac[m][3] = 1;
        warped[m] = L;
        idx[m++] = j;
    }
    /* Down the levels, the points side by side: the cell (each level's point comes from
       the level above) and the unwarp. Item i = k * m + p holds point p at level k. */
    enum { ITEMS = SK__QUERY_BATCH * SK_SKIN_MAX_LEVELS };
    uint32_t cell[ITEMS];
    float lx[ITEMS], ly[ITEMS], lj[ITEMS][4];
    for (int k = 0; k < walked; k++) {
        const sk__level *lv = &skin->levels[k];
        for (int p = 0; p < m; p++) {
            if (k > 0) u[p] = locate_child(skin, k, owner[p], px[p], py[p], hint);
            const sk__fan *fan = &lv->fans[u[p]];
            float pre_x = px[p], pre_y = py[p];
            uint32_t c = fan->cell;
            if (fan->edge != SK__SKIN_NONE &&
                !(fan->gx * (px[p] - fan->sx) + fan->gy * (py[p] - fan->sy) < fan->gcut)) {
                float J[2][2] = {{jac[p][0], jac[p][1]}, {jac[p][2], jac[p][3]}};
                c = sk__unwarp(lv, fan, &px[p], &py[p], J, &pre_x, &pre_y);
                jac[p][0] = J[0][0], jac[p][1] = J[0][1], jac[p][2] = J[1][0], jac[p][3] = J[1][1];
                if (warped[p] == L) warped[p] = k;
            }
            owner[p] = c;
            sk_skin_sample *o = &out[idx[p]];
            o->cell[k] = c;
            o->furrow_mm[k] = furrow >> k & 1u ? sk__furrow_distance(lv, c, pre_x, pre_y) : 0.0f;
            int i = k * m + p;
            cell[i] = c, lx[i] = px[p], ly[i] = py[p];
            if (warped[p] <= k)
                for (int q = 0; q < 4; q++) lj[i][q] = jac[p][q];
        }
    }
    if (!relief) return;
    /* The profiles of every item at once (independent of one another). */
    float z[ITEMS], g[ITEMS][2];
    sk__profile_eval(skin, L, m, cell, lx, ly, hint->sector, z, g);
    for (int p = 0; p < m; p++) {
        float h = 0, gx = 0, gy = 0;
        /* gradient in the world = jac^T g (jac = I above the first unwarp) */
        for (int k = 0; k < warped[p]; k++) {
            int i = k * m + p;
            h += z[i], gx += g[i][0], gy += g[i][1];
        }
        for (int k = warped[p]; k < L; k++) {
            int i = k * m + p;
            h += z[i];
            gx += lj[i][0] * g[i][0] + lj[i][2] * g[i][1];
            gy += lj[i][1] * g[i][0] + lj[i][3] * g[i][1];
        }
        int j = idx[p];
        if (skin->pores.count) {
            float pg[2] = {0, 0}, ph = 0;
            sk__pores_eval(skin, x[j], y[j], &ph, pg);
            h += ph, gx += pg[0], gy += pg[1];
        }
        out[j].height_mm = h;
        float inv = 1.0f / sqrtf(gx * gx + gy * gy + 1.0f);
        out[j].normal = sk_v3f(-gx * inv, -gy * inv, inv);
    }
}

void sk_skin_query(const sk_skin *skin, double x, double y, unsigned flags, sk_skin_sample *out)
{
    for (int k = 0; k < SK_SKIN_MAX_LEVELS; k++)
        out->cell[k] = SK__SKIN_NONE, out->furrow_mm[k] = 0;
    sk__query(skin, 1, &x, &y, flags, out, NULL);
}

void sk_skin_eval(const sk_skin *skin, double x_mm, double y_mm, float *height_mm, sk_vec3f *normal)
{
    sk_skin_sample s;
    sk__query(skin, 1, &x_mm, &y_mm, 0, &s, NULL);
    if (height_mm) *height_mm = s.height_mm;
    if (normal) *normal = s.normal;
}
