/* Strokes: single line segments with round, butt or square caps, and polylines whose
 * segments are combined in a coverage mask (max per pixel) and composited once. */
#include <stdlib.h>

#include "products/draw/draw_internal.h"

void sk_draw_line_capped(sk_image *img, float x0, float y0, float x1, float y1, float width,
                         sk_line_cap cap, sk_color c)
{
    sk__paint paint;
    if (!isfinite(x0) || !isfinite(y0) || !isfinite(x1) || !isfinite(y1) || !isfinite(width))
        return;
    if (!(width > 0.0f) || (int)cap < 0 || cap > SK_CAP_SQUARE) return;
    if (!sk__paint_init(&paint, img, c)) return;
    sk__path path;
    sk__path_init(&path);
    if (sk__path_stroke_segment(&path, x0, y0, x1, y1, width, cap))
        sk__fill_path(&paint, &path, SK_FILL_NONZERO, sk__clip_image(img));
    sk__path_free(&path);
}

void sk_draw_line(sk_image *img, float x0, float y0, float x1, float y1, float width, sk_color c)
{
    sk_draw_line_capped(img, x0, y0, x1, y1, width, SK_CAP_ROUND, c);
}

static bool point_finite(sk_vec2f p) { return isfinite(p.x) && isfinite(p.y); }

/* Rasterizes one round-capped segment into `emit`. */
static void stroke_into(double x0, double y0, double x1, double y1, double width, sk__clip clip,
                        sk__span_fn emit, void *user)
{
    sk__path path;
    sk__path_init(&path);
    if (sk__path_stroke_segment(&path, x0, y0, x1, y1, width, SK_CAP_ROUND))
        sk__raster_fill(&path, SK_FILL_NONZERO, clip, emit, user);
    sk__path_free(&path);
}

/* Rasterizes every segment of the polyline (and dots for isolated points) into `emit`. */
static void stroke_all(const sk_vec2f *pts, int n, bool closed, double width, sk__clip bounds,
                       sk__span_fn emit, void *user)
{
    int segments = closed && n > 2 ? n : n - 1;
    for (int i = 0; i < segments; i++) {
        sk_vec2f a = pts[i], b = pts[(i + 1) % n];
        /* A segment touching a non-finite point is left out (the line breaks there). */
        if (!point_finite(a) || !point_finite(b)) continue;
        stroke_into(a.x, a.y, b.x, b.y, width, bounds, emit, user);
    }
    /* A finite point without finite neighbours (or a single point) shows as a dot. */
    for (int i = 0; i < n; i++) {
        if (!point_finite(pts[i])) continue;
        bool prev = (i > 0 || closed) && n > 1 && point_finite(pts[(i + n - 1) % n]);
        bool next = (i + 1 < n || closed) && n > 1 && point_finite(pts[(i + 1) % n]);
        if (!prev && !next)
            stroke_into(pts[i].x, pts[i].y, pts[i].x, pts[i].y, width, bounds, emit, user);
    }
}

void sk__draw_polyline_clip(sk_image *img, sk__clip clip, const sk_vec2f *pts, int n, bool closed,
                            float width, sk_color c)
{
    sk__paint paint;
    if (!pts || n <= 0 || !isfinite(width) || !(width > 0.0f)) return;
    if (!sk__paint_init(&paint, img, c)) return;
    clip = sk__clip_bounds(sk__clip_image(img), clip.x0, clip.y0, clip.x1, clip.y1);
    double min_x = INFINITY, min_y = INFINITY, max_x = -INFINITY, max_y = -INFINITY;
    for (int i = 0; i < n; i++) {
        if (!point_finite(pts[i])) continue;
        min_x = fmin(min_x, pts[i].x);
        max_x = fmax(max_x, pts[i].x);
        min_y = fmin(min_y, pts[i].y);
        max_y = fmax(max_y, pts[i].y);
    }
    if (!(min_x <= max_x)) return; /* no finite point */
    double h = 0.5 * (double)width + 1.0;
    sk__clip bounds = sk__clip_bounds(clip, min_x - h, min_y - h, max_x + h, max_y + h);
    if (sk__clip_empty(bounds)) return;

    /* Two or more pieces combine in a mask and composite once. Should the mask run out
       of memory, the stroke is drawn piece by piece instead (complete, though joins then
       blend twice). */
    sk__mask mask;
    if (n > 2 && sk__mask_init(&mask, bounds)) {
        stroke_all(pts, n, closed, width, bounds, sk__mask_span_fn, &mask);
        bool complete = !mask.failed;
        if (complete) sk__mask_paint(&mask, &paint);
        sk__mask_free(&mask);
        if (complete) return;
    }
    stroke_all(pts, n, closed, width, bounds, sk__paint_span_fn, &paint);
}

void sk_draw_polyline(sk_image *img, const sk_vec2f *pts, int n, bool closed, float width,
                      sk_color c)
{
    if (!sk__image_valid(img)) return;
    sk__draw_polyline_clip(img, sk__clip_image(img), pts, n, closed, width, c);
}
