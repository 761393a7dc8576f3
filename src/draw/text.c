/* Text in the built-in bitmap font: glyph cells scaled by an integer factor, each pixel
 * covered by the exact area of the scaled glyph cells under it (crisp at integer
 * positions, anti-aliased at fractional ones), horizontal or rotated a quarter turn. */
#include <limits.h>
#include <string.h>

#include "draw/draw_internal.h"

static int clamp_scale(int scale)
{
    return scale < 1 ? 1 : (scale > SK__MAX_TEXT_SCALE ? SK__MAX_TEXT_SCALE : scale);
}

static long long text_width_ll(const char *text, int scale)
{
    long long n = sk__text_glyph_count(text);
    if (n == 0) return 0;
    return n * SK__GLYPH_ADVANCE * scale - scale;
}

int sk_draw_text_width(const char *text, int scale)
{
    long long w = text_width_ll(text, clamp_scale(scale));
    return w > INT_MAX ? INT_MAX : (int)w;
}

int sk_draw_text_height(int scale) { return SK__GLYPH_HEIGHT * clamp_scale(scale); }

/* Length of [a, a + 1) inside [lo, hi). */
static inline double overlap(double a, double lo, double hi)
{
    double l = a > lo ? a : lo;
    double h = a + 1.0 < hi ? a + 1.0 : hi;
    return h > l ? h - l : 0.0;
}

/* Ink area of the glyph under a 1 x 1 footprint whose glyph-space corner is (u, v):
 * u runs along the text, v down the glyph, in pixels of the scaled glyph. */
static float glyph_coverage(const unsigned char rows[SK__GLYPH_HEIGHT], int scale, double u,
                            double v)
{
    double s = (double)scale;
    int j0 = (int)floor(u / s), j1 = (int)floor((u + 1.0) / s);
    int k0 = (int)floor(v / s), k1 = (int)floor((v + 1.0) / s);
    if (j0 < 0) j0 = 0;
    if (k0 < 0) k0 = 0;
    if (j1 > SK__GLYPH_WIDTH - 1) j1 = SK__GLYPH_WIDTH - 1;
    if (k1 > SK__GLYPH_HEIGHT - 1) k1 = SK__GLYPH_HEIGHT - 1;
    double sum = 0.0;
    for (int k = k0; k <= k1; k++) {
        if (!rows[k]) continue;
        double oy = overlap(v, k * s, (k + 1) * s);
        if (oy <= 0.0) continue;
        for (int j = j0; j <= j1; j++)
            if (rows[k] & (1u << (SK__GLYPH_WIDTH - 1 - j)))
                sum += oy * overlap(u, j * s, (j + 1) * s);
    }
    return (float)sum;
}

int sk__draw_text_dir(sk_image *img, sk__clip clip, float x, float y, const char *text, int scale,
                      sk__text_dir dir, sk_color c)
{
    scale = clamp_scale(scale);
    long long width = text_width_ll(text, scale);
    int result = width > INT_MAX ? INT_MAX : (int)width;
    sk__paint paint;
    if (width == 0 || !isfinite(x) || !isfinite(y) || !sk__paint_init(&paint, img, c))
        return result;
    double s = (double)scale;
    double glyph_w = SK__GLYPH_WIDTH * s, glyph_h = SK__GLYPH_HEIGHT * s;
    double u0 = 0.0;
    unsigned char rows[SK__GLYPH_HEIGHT];
    while (*text) {
        sk__glyph_rows(sk__glyph_code_next(&text), rows);
        double gx0, gy0, gx1, gy1; /* the glyph's box on screen */
        if (dir == SK__TEXT_UP) {
            gx0 = x;
            gx1 = x + glyph_h;
            gy1 = y + (double)width - u0;
            gy0 = gy1 - glyph_w;
        } else {
            gx0 = x + u0;
            gx1 = gx0 + glyph_w;
            gy0 = y;
            gy1 = y + glyph_h;
        }
        u0 += SK__GLYPH_ADVANCE * s;
        if (dir == SK__TEXT_UP ? gy1 <= clip.y0 : gx0 >= clip.x1) break;
        sk__clip box = sk__clip_bounds(clip, gx0, gy0, gx1, gy1);
        for (int py = box.y0; py < box.y1; py++) {
            for (int px = box.x0; px < box.x1; px++) {
                double u, v;
                if (dir == SK__TEXT_UP) {
                    u = gy1 - (double)py - 1.0;
                    v = (double)px - gx0;
                } else {
                    u = (double)px - gx0;
                    v = (double)py - gy0;
                }
                float w = glyph_coverage(rows, scale, u, v);
                if (w > 0.0f) sk__paint_pixel(&paint, px, py, w);
            }
        }
    }
    return result;
}

int sk_draw_text(sk_image *img, float x, float y, const char *text, int scale, sk_color c)
{
    if (!sk__image_valid(img)) return sk_draw_text_width(text, scale);
    return sk__draw_text_dir(img, sk__clip_image(img), x, y, text, scale, SK__TEXT_RIGHT, c);
}

const char *sk__text_fit(const char *text, int scale, int max_width, char *buf, size_t size)
{
    if (size == 0) return buf;
    buf[0] = '\0';
    if (!text) return buf;
    scale = clamp_scale(scale);
    size_t len = strlen(text);
    if (text_width_ll(text, scale) <= max_width && len < size) {
        memcpy(buf, text, len + 1);
        return buf;
    }
    /* m glyphs are m * 6 s - s wide. */
    long long fit = ((long long)max_width + scale) / (SK__GLYPH_ADVANCE * scale);
    if (fit < 3) {
        size_t dots = fit > 0 ? (size_t)fit : 0;
        if (dots > size - 1) dots = size - 1;
        memset(buf, '.', dots);
        buf[dots] = '\0';
        return buf;
    }
    const char *p = text;
    for (long long kept = 0; kept < fit - 3 && *p; kept++) {
        const char *next = p;
        sk__glyph_code_next(&next);
        if ((size_t)(next - text) + 4 > size) break;
        p = next;
    }
    size_t n = (size_t)(p - text);
    memcpy(buf, text, n);
    memcpy(buf + n, "...", 4);
    return buf;
}
