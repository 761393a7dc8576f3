/* The jiggle as an image sequence (Shigemori & Kawai sec. 5: the skin's natural sway with
 * the motion): every output frame's skin through the renderer, seen by one fixed camera
 * that frames the whole motion. */
#include <math.h>
#include <stdio.h>

#include "products/tissue/tissue_draw_internal.h"

sk__view sk__jiggle_view(sk_vec3d lo, sk_vec3d hi, double *aspect)
{
    /* a hanging limb is seen from its side, a body from the front and a little right */
    bool limb = hi.y - lo.y > 2.5 * (hi.x - lo.x) && hi.z - lo.z < 2.0 * (hi.y - lo.y);
    sk_vec3d dir = limb ? sk_v3d(1.0, 0.15, 0.35) : sk_v3d(0.55, 0.2, 1.0);
    sk_vec3d d = sk_v3d_normalize(dir);
    sk_vec3d right = sk_v3d_normalize(sk_v3d_cross(sk_v3d(0, 1, 0), d));
    double w = 0.0, h = hi.y - lo.y;
    for (int c = 0; c < 8; c++) {
        sk_vec3d p = sk_v3d((c & 1) ? hi.x : lo.x, 0.0, (c & 4) ? hi.z : lo.z);
        w = fmax(w, 2.0 * fabs(sk_v3d_dot(
                              sk_v3d_sub(p, sk_v3d(0.5 * (lo.x + hi.x), 0, 0.5 * (lo.z + hi.z))),
                              right)));
    }
    *aspect = sk_clampd(w / h, 0.5, 2.0);
    return sk__view_framing(lo, hi, dir, sk_v3d(0, 1, 0), 30.0, *aspect);
}

sk_result sk__render_skin(const sk_mesh *skin, const sk__view *view, int width, int height,
                          const char *png_path, sk_error *err)
{
    sk__render_item item = {skin, {0.80f, 0.56f, 0.46f}, 0.08f};
    /* many frames: direct light only, two samples a pixel */
    return sk__render_items(&item, 1, view, width, height, 2, false, png_path, err);
}
