/* Text in the built-in bitmap font: glyph cells scaled by an integer factor, each pixel
 * covered by the exact area of the scaled glyph cells under it (crisp at integer
 * positions, anti-aliased at fractional ones), horizontal or rotated a quarter turn. */
#include <limits.h>
#include <string.h>

#include "products/draw/draw_internal.h"

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

/* The glyph cells (at most two) under one pixel along one axis, with the length of the
 * pixel inside each. */
typedef struct cell_taps {
    int cell[2];
    float weight[2];
} cell_taps;

#define SK__MAX_GLYPH_EXTENT (SK__GLYPH_HEIGHT * SK__MAX_TEXT_SCALE + 2)

/* Taps for n pixels whose footprints start at glyph-space coordinate a0 + i * step
 * (step = +1 or -1), for cells of `scale` pixels numbered 0 .. cells - 1. */
static void build_taps(cell_taps *taps, int n, double a0, double step, int scale, int cells)
{
    double s = (double)scale;
    for (int i = 0; i < n; i++) {
        double a = a0 + step * (double)i;
        cell_taps *t = &taps[i];
        t->cell[0] = t->cell[1] = 0;
        t->weight[0] = t->weight[1] = 0.0f;
        int j = (int)floor(a / s);
        for (int k = 0; k < 2; k++, j++) {
            if (j < 0 || j >= cells) continue;
            double lo = a > j * s ? a : j * s;
            double hi = a + 1.0 < (j + 1) * s ? a + 1.0 : (j + 1) * s;
            if (hi > lo) {
                t->cell[k] = j;
                t->weight[k] = (float)(hi - lo);
            }
        }
    }
}

static inline int glyph_bit(const unsigned char rows[SK__GLYPH_HEIGHT], int row, int col)
{
    return (rows[row] >> (SK__GLYPH_WIDTH - 1 - col)) & 1;
}

/* Draws one glyph whose screen box is [gx0, gx0 + extent) x [gy0, ...), rotated or not. */
static void draw_glyph(const sk__paint *paint, sk__clip clip,
                       const unsigned char rows[SK__GLYPH_HEIGHT], double gx0, double gy0,
                       double gx1, double gy1, int scale, sk__text_dir dir)
{
    sk__clip box = sk__clip_bounds(clip, gx0, gy0, gx1, gy1);
    int nx = box.x1 - box.x0, ny = box.y1 - box.y0;
    if (nx <= 0 || ny <= 0) return;
    cell_taps tx[SK__MAX_GLYPH_EXTENT], ty[SK__MAX_GLYPH_EXTENT];
    float coverage[SK__MAX_GLYPH_EXTENT];
    bool up = dir == SK__TEXT_UP;
    /* Screen x runs along the text (u) normally, down the glyph (v) when rotated; screen
       y runs down the glyph, or backwards along the text. */
    if (up) {
        build_taps(tx, nx, (double)box.x0 - gx0, 1.0, scale, SK__GLYPH_HEIGHT);
        build_taps(ty, ny, gy1 - (double)box.y0 - 1.0, -1.0, scale, SK__GLYPH_WIDTH);
    } else {
        build_taps(tx, nx, (double)box.x0 - gx0, 1.0, scale, SK__GLYPH_WIDTH);
        build_taps(ty, ny, (double)box.y0 - gy0, 1.0, scale, SK__GLYPH_HEIGHT);
    }
    for (int j = 0; j < ny; j++) {
        /* This screen row's ink per glyph cell across x (columns normally, rows when
           rotated), so each pixel only mixes its two taps. */
        const cell_taps *b = &ty[j];
        float profile[SK__GLYPH_HEIGHT];
        int cells_x = up ? SK__GLYPH_HEIGHT : SK__GLYPH_WIDTH;
        bool any = false;
        for (int k = 0; k < cells_x; k++) {
            float w = 0.0f;
            for (int q = 0; q < 2; q++) {
                int bit = up ? glyph_bit(rows, k, b->cell[q]) : glyph_bit(rows, b->cell[q], k);
                w += bit ? b->weight[q] : 0.0f;
            }
            profile[k] = w;
            any |= w > 0.0f;
        }
        if (!any) continue;
        for (int i = 0; i < nx; i++)
            coverage[i] =
                tx[i].weight[0] * profile[tx[i].cell[0]] + tx[i].weight[1] * profile[tx[i].cell[1]];
        sk__paint_span(paint, box.x0, box.y0 + j, nx, coverage);
    }
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
        draw_glyph(&paint, clip, rows, gx0, gy0, gx1, gy1, scale, dir);
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
