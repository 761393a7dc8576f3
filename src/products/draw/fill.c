/* Whole-image fill and clear, and axis-aligned rectangles (exact separable coverage). */
#include "products/draw/draw_internal.h"

/* Images at least this large are filled by several threads. */
#define SK__FILL_PARALLEL_PIXELS (1 << 18)

/* Sets (or composites, if `blend`) the colour value v with alpha a over every pixel. */
static void whole_image(sk_image *img, const float v[4], float a, bool blend)
{
    size_t pixels = (size_t)img->width * (size_t)img->height;
    long long rows = img->height;
    int ch = img->channels;
#pragma omp parallel for schedule(static) if (pixels >= SK__FILL_PARALLEL_PIXELS)
    for (long long y = 0; y < rows; y++) {
        float *px = sk_image_pixel(img, 0, (int)y);
        for (int x = 0; x < img->width; x++, px += ch) {
            if (blend)
                sk__composite_over(px, ch, v, a);
            else
                for (int k = 0; k < ch; k++) px[k] = v[k];
        }
    }
}

void sk_draw_fill(sk_image *img, sk_color c)
{
    sk__paint paint;
    if (sk__paint_init(&paint, img, c)) whole_image(img, paint.value, paint.alpha, true);
}

void sk_draw_clear(sk_image *img, sk_color c)
{
    if (!sk__image_valid(img) || !sk__color_finite(c)) return;
    float v[4];
    sk__color_to_layout(c, img->channels, v);
    whole_image(img, v, v[3], false);
}

/* Length of [p, p + 1) inside [lo, hi). */
static inline float overlap(int p, double lo, double hi)
{
    double a = (double)p > lo ? (double)p : lo;
    double b = (double)(p + 1) < hi ? (double)(p + 1) : hi;
    return b > a ? (float)(b - a) : 0.0f;
}

void sk_draw_rect(sk_image *img, float x, float y, float w, float h, sk_color c)
{
    sk__paint paint;
    if (!isfinite(x) || !isfinite(y) || !isfinite(w) || !isfinite(h)) return;
    if (!sk__paint_init(&paint, img, c)) return;
    double x0 = x, x1 = (double)x + (double)w, y0 = y, y1 = (double)y + (double)h;
    if (x1 < x0) {
        double t = x0;
        x0 = x1;
        x1 = t;
    }
    if (y1 < y0) {
        double t = y0;
        y0 = y1;
        y1 = t;
    }
    if (!(x1 > x0) || !(y1 > y0)) return;
    sk__clip box = sk__clip_bounds(sk__clip_image(img), x0, y0, x1, y1);
    if (sk__clip_empty(box)) return;
    enum { CHUNK = 256 };
    float cov[CHUNK];
    for (int py = box.y0; py < box.y1; py++) {
        float cy = overlap(py, y0, y1);
        for (int px = box.x0; px < box.x1; px += CHUNK) {
            int n = box.x1 - px < CHUNK ? box.x1 - px : CHUNK;
            for (int i = 0; i < n; i++) cov[i] = cy * overlap(px + i, x0, x1);
            sk__paint_span(&paint, px, py, n, cov);
        }
    }
}
