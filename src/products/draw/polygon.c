/* Filled polygons and multi-contour shapes (non-zero or even-odd winding). */
#include "products/draw/draw_internal.h"

void sk_draw_contours(sk_image *img, const sk_vec2f *pts, const int *counts, int contour_count,
                      sk_fill_rule rule, sk_color c)
{
    sk__paint paint;
    if (!pts || !counts || contour_count <= 0) return;
    if ((int)rule < 0 || rule > SK_FILL_EVEN_ODD) return;
    long long total = 0;
    for (int k = 0; k < contour_count; k++) {
        if (counts[k] < 0) return;
        total += counts[k];
    }
    for (long long i = 0; i < total; i++)
        if (!isfinite(pts[i].x) || !isfinite(pts[i].y)) return;
    if (!sk__paint_init(&paint, img, c)) return;
    sk__path path;
    sk__path_init(&path);
    const sk_vec2f *p = pts;
    for (int k = 0; k < contour_count; k++) {
        if (counts[k] >= 3) {
            sk__path_move_to(&path, p[0].x, p[0].y);
            for (int i = 1; i < counts[k]; i++) sk__path_line_to(&path, p[i].x, p[i].y);
            sk__path_close(&path);
        }
        p += counts[k];
    }
    sk__fill_path(&paint, &path, rule, sk__clip_image(img));
    sk__path_free(&path);
}

void sk_draw_polygon(sk_image *img, const sk_vec2f *pts, int n, sk_color c)
{
    sk_draw_contours(img, pts, &n, 1, SK_FILL_NONZERO, c);
}
