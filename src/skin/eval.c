/* Point query (paper sec. 3.2.3 (2), Fig. 10): walk down the levels, find the cell at each
 * level, evaluate its section profile, and sum heights over levels; normals combine as
 * gradients add (each level's normal scaled to z = 1, x and y parts summed), carried
 * through the perturbation maps by the chain rule so the normal is the exact normal of
 * the height field. Allocation-free and thread-safe. */
#include <math.h>

#include "skin/skin_internal.h"

void sk_skin_query(const sk_skin *skin, double x, double y, unsigned flags, sk_skin_sample *out)
{
    for (int k = 0; k < SK_SKIN_MAX_LEVELS; k++) out->cell[k] = SK__SKIN_NONE, out->furrow_mm[k] = 0;
    out->height_mm = 0.0f;
    out->normal = sk_v3f(0, 0, 1);
    if (!isfinite(x) || !isfinite(y)) return;
    float px, py;
    uint32_t c = sk__locate_level1(skin, x, y, &px, &py);
    if (c == SK__SKIN_NONE) return;
    float jac[2][2] = {{1, 0}, {0, 1}};
    float h = 0, gx = 0, gy = 0;
    for (int k = 0; k < skin->level_count; k++) {
        const sk__level *lv = &skin->levels[k];
        if (k > 0) {
            const sk__cell *pc = &skin->levels[k - 1].cells[c];
            c = sk__locate_child(lv, pc->first_child, pc->child_count, px, py);
        }
        uint32_t u = sk__fan_use(lv, c, px, py);
        float pre_x, pre_y;
        c = sk__unwarp(lv, c, u, &px, &py, jac, &pre_x, &pre_y);
        out->cell[k] = c;
        if (flags & SK_SKIN_QUERY_FURROW) out->furrow_mm[k] = sk__furrow_distance(lv, c, pre_x, pre_y);
        float g[2];
        h += sk__profile_eval(lv, c, px, py, g);
        /* gradient in world = jac^T g */
        gx += jac[0][0] * g[0] + jac[1][0] * g[1];
        gy += jac[0][1] * g[0] + jac[1][1] * g[1];
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

void sk_skin_eval(const sk_skin *skin, double x_mm, double y_mm, float *height_mm,
                  sk_vec3f *normal)
{
    sk_skin_sample s;
    sk_skin_query(skin, x_mm, y_mm, 0, &s);
    if (height_mm) *height_mm = s.height_mm;
    if (normal) *normal = s.normal;
}
