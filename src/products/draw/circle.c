/* Discs and rings, flattened to polygons that keep the circle's exact area. */
#include "products/draw/draw_internal.h"

void sk_draw_disc(sk_image *img, float cx, float cy, float radius, sk_color c)
{
    sk__paint paint;
    if (!isfinite(cx) || !isfinite(cy) || !isfinite(radius) || !(radius > 0.0f)) return;
    if (!sk__paint_init(&paint, img, c)) return;
    sk__path path;
    sk__path_init(&path);
    sk__path_circle(&path, cx, cy, radius, true);
    sk__fill_path(&paint, &path, SK_FILL_NONZERO, sk__clip_image(img));
    sk__path_free(&path);
}

void sk_draw_circle(sk_image *img, float cx, float cy, float radius, float width, sk_color c)
{
    sk__paint paint;
    if (!isfinite(cx) || !isfinite(cy) || !isfinite(radius) || !isfinite(width)) return;
    if (radius < 0.0f || !(width > 0.0f)) return;
    if (!sk__paint_init(&paint, img, c)) return;
    double outer = (double)radius + 0.5 * (double)width;
    double inner = (double)radius - 0.5 * (double)width;
    sk__path path;
    sk__path_init(&path);
    /* Opposite orientations: the inner contour cancels the outer one's winding. */
    sk__path_circle(&path, cx, cy, outer, true);
    if (inner > 0.0) sk__path_circle(&path, cx, cy, inner, false);
    sk__fill_path(&paint, &path, SK_FILL_NONZERO, sk__clip_image(img));
    sk__path_free(&path);
}
