/* Point query (paper sec. 3.2.3 (2), Fig. 10): walk down the levels, find the cell at each
 * level, evaluate its section profile, and sum heights over levels; normals combine as
 * gradients add (each level's normal scaled to z = 1, x and y parts summed), carried
 * through the perturbation maps by the chain rule, so the normal is the exact normal of
 * the height field. Allocation-free and thread-safe. */
#include <math.h>

#include "skin/skin_internal.h"

void sk__hint_reset(sk__hint *hint)
{
    for (int k = 0; k < SK_SKIN_MAX_LEVELS; k++)
        hint->cell[k] = SK__SKIN_NONE, hint->fan[k] = UINT32_MAX, hint->sector[k] = UINT32_MAX;
    hint->shift[0] = hint->shift[1] = 0.0;
}

void sk__query(const sk_skin *skin, double x, double y, unsigned flags, sk_skin_sample *out,
               sk__hint *hint)
{
    int L = skin->level_count;
    out->height_mm = 0.0f;
    out->normal = sk_v3f(0, 0, 1);
    if (!isfinite(x) || !isfinite(y)) {
        for (int k = 0; k < L; k++) out->cell[k] = SK__SKIN_NONE, out->furrow_mm[k] = 0.0f;
        return;
    }
    sk__hint local;
    if (!hint) {
        sk__hint_reset(&local);
        hint = &local;
    }
    const sk__level *l1 = &skin->levels[0];
    float px = 0, py = 0;
    uint32_t c = SK__SKIN_NONE, u = 0;
    double wx = sk__wrap(x, skin->period[0]), wy = sk__wrap(y, skin->period[1]);
    /* Level 1: the previous point's fan triangle, else the grid. */
    if (hint->cell[0] != SK__SKIN_NONE) {
        float lx = (float)(wx - hint->shift[0]), ly = (float)(wy - hint->shift[1]);
        if (sk__in_fan(l1, hint->cell[0], hint->fan[0], lx, ly)) {
            c = hint->cell[0], px = lx, py = ly;
            u = l1->cells[c].first_use + hint->fan[0];
        }
    }
    if (c == SK__SKIN_NONE) {
        double shift[2];
        c = sk__locate_level1(skin, wx, wy, &px, &py, &u, shift);
        if (c == SK__SKIN_NONE) {
            for (int k = 0; k < L; k++) out->cell[k] = SK__SKIN_NONE, out->furrow_mm[k] = 0.0f;
            return;
        }
        hint->cell[0] = c, hint->shift[0] = shift[0], hint->shift[1] = shift[1];
        hint->fan[0] = u - l1->cells[c].first_use;
    }
    /* First the cells of every level (each level's point comes from the level above),
       then the profiles, which are independent of one another: their long arithmetic
       chains can overlap in the processor. */
    float jac[2][2] = {{1, 0}, {0, 1}};
    float lx[SK_SKIN_MAX_LEVELS], ly[SK_SKIN_MAX_LEVELS], lj[SK_SKIN_MAX_LEVELS][4];
    uint32_t same[SK_SKIN_MAX_LEVELS];
    for (int k = 0; k < L; k++) {
        const sk__level *lv = &skin->levels[k];
        if (k > 0) {
            uint32_t parent = c, hc = hint->cell[k];
            c = SK__SKIN_NONE;
            if (hc != SK__SKIN_NONE && lv->cells[hc].parent == parent &&
                sk__in_fan(lv, hc, hint->fan[k], px, py)) {
                c = hc;
                u = lv->cells[c].first_use + hint->fan[k];
            } else {
                const sk__cell *pc = &skin->levels[k - 1].cells[parent];
                c = sk__locate_child(lv, pc->first_child, pc->child_count, px, py);
                u = sk__fan_use(lv, c, px, py);
                hint->cell[k] = c;
                hint->fan[k] = u - lv->cells[c].first_use;
            }
        }
        float pre_x = px, pre_y = py;
        uint32_t owner = c;
        if (lv->perturbed) owner = sk__unwarp(lv, c, u, &px, &py, jac, &pre_x, &pre_y);
        out->cell[k] = owner;
        out->furrow_mm[k] =
            (flags & (SK_SKIN_QUERY_FURROW | (1u << (SK__FURROW_LEVEL_SHIFT + k))))
                ? sk__furrow_distance(lv, owner, pre_x, pre_y)
                : 0.0f;
        same[k] = owner == c;
        lx[k] = px, ly[k] = py;
        lj[k][0] = jac[0][0], lj[k][1] = jac[0][1], lj[k][2] = jac[1][0], lj[k][3] = jac[1][1];
        c = owner;
    }
    float h = 0, gx = 0, gy = 0;
    for (int k = 0; k < L; k++) {
        float g[2];
        uint32_t sector = same[k] ? hint->sector[k] : UINT32_MAX;
        h += sk__profile_eval(&skin->levels[k], out->cell[k], lx[k], ly[k], g, &sector);
        if (same[k]) hint->sector[k] = sector;
        /* gradient in the world = jac^T g */
        gx += lj[k][0] * g[0] + lj[k][2] * g[1];
        gy += lj[k][1] * g[0] + lj[k][3] * g[1];
    }
    if (skin->pores.count) {
        float pg[2] = {0, 0}, ph = 0;
        sk__pores_eval(skin, x, y, &ph, pg);
        h += ph, gx += pg[0], gy += pg[1];
    }
    out->height_mm = h;
    float inv = 1.0f / sqrtf(gx * gx + gy * gy + 1.0f);
    out->normal = sk_v3f(-gx * inv, -gy * inv, inv);
}

void sk_skin_query(const sk_skin *skin, double x, double y, unsigned flags, sk_skin_sample *out)
{
    for (int k = 0; k < SK_SKIN_MAX_LEVELS; k++)
        out->cell[k] = SK__SKIN_NONE, out->furrow_mm[k] = 0;
    sk__query(skin, x, y, flags, out, NULL);
}

void sk_skin_eval(const sk_skin *skin, double x_mm, double y_mm, float *height_mm, sk_vec3f *normal)
{
    sk_skin_sample s;
    sk__query(skin, x_mm, y_mm, 0, &s, NULL);
    if (height_mm) *height_mm = s.height_mm;
    if (normal) *normal = s.normal;
}
