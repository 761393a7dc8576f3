/* Exact-area coverage rasterizer. For each pixel row an edge adds the second difference
 * of its "ramp integral" to an accumulation row, so a running sum along the row yields,
 * for every pixel, the winding-weighted area of the pixel inside the outline (a box
 * filter, computed analytically). Work is bounded by the clipped bounding box, which is
 * processed in tiles that fit a fixed stack buffer (no allocation). */
#include <limits.h>
#include <string.h>

#include "products/draw/draw_internal.h"

#define SK__RASTER_FLOATS 8192
#define SK__RASTER_MAX_TILE_WIDTH 1022

/* Coverage is snapped to 0 or 1 within this distance (float round-off of the sums). */
#define SK__COVERAGE_SNAP 1e-6f

/* One tile of the accumulation buffer: w columns (+2 for pieces touching the right
 * edge) by h rows, with the range of columns each row's edges touched, so that rows are
 * resolved only where something happens. */
typedef struct raster_tile {
    float *acc;
    int stride, w, h;
    short *touch_lo, *touch_hi;
} raster_tile;

/* The ramp integral of an edge piece whose x is spread uniformly over [lo, hi] (x is
 * linear in y): G(u) = mean over the piece of max(0, u - x). The area of pixel column c
 * to the right of the piece is dy (G(c + 1) - G(c)); the accumulation row stores the
 * difference of that between neighbouring columns, dy (G(c+1) - 2 G(c) + G(c-1)). */
static inline double ramp_integral(double u, double lo, double hi, double inv_width)
{
    if (u <= lo) return 0.0;
    if (u >= hi) return u - 0.5 * (lo + hi);
    double t = u - lo;
    return 0.5 * t * t * inv_width;
}

/* Adds row r's share of an edge piece: winding-weighted height k, x in [lo, hi] within
 * [0, w]. */
static void add_row_piece(raster_tile *t, int r, double k, double lo, double hi)
{
    float *row = t->acc + (size_t)r * (size_t)t->stride;
    int c0 = (int)floor(lo);
    double f = lo - (double)c0;
    int c1;
    if (hi - lo < 1e-9) {
        /* Vertical: G is the plain ramp max(0, u - lo). */
        row[c0] += (float)(k * (1.0 - f));
        row[c0 + 1] += (float)(k * f);
        c1 = c0 + 1;
    } else {
        c1 = (int)floor(hi) + 1;
        double l = f, h = hi - (double)c0; /* relative to c0 for precision */
        double inv = 1.0 / (h - l);
        double g_prev = 0.0, g_cur = 0.0; /* G(c0 - 1) = G(c0) = 0 since c0 <= lo */
        for (int c = c0; c <= c1; c++) {
            double g_next = ramp_integral((double)(c + 1 - c0), l, h, inv);
            row[c] += (float)(k * (g_next - 2.0 * g_cur + g_prev));
            g_prev = g_cur;
            g_cur = g_next;
        }
    }
    if (c0 < t->touch_lo[r]) t->touch_lo[r] = (short)c0;
    if (c1 > t->touch_hi[r]) t->touch_hi[r] = (short)c1;
}

/* Plain comparisons (fmin/fmax are library calls in the hot loop). NaN maps to lo. */
static inline double min2(double a, double b) { return a < b ? a : b; }
static inline double max2(double a, double b) { return a > b ? a : b; }
static inline double clampd(double v, double lo, double hi)
{
    return v > lo ? (v < hi ? v : hi) : lo;
}

/* A piece with ya < yb inside [0, h] and x inside [0, w], split into pixel rows. */
static void accumulate_piece(raster_tile *t, double ya, double xa, double yb, double xb, double dir)
{
    int w = t->w, h = t->h;
    double slope = (xb - xa) / (yb - ya);
    int r0 = (int)floor(ya);
    int r1 = (int)ceil(yb);
    if (r1 > h) r1 = h;
    for (int r = r0; r < r1; r++) {
        double top = ya > (double)r ? ya : (double)r;
        double bottom = yb < (double)(r + 1) ? yb : (double)(r + 1);
        if (!(bottom > top)) continue;
        double xt = top == ya ? xa : xa + (top - ya) * slope;
        double xbt = bottom == yb ? xb : xa + (bottom - ya) * slope;
        xt = clampd(xt, 0.0, (double)w);
        xbt = clampd(xbt, 0.0, (double)w);
        add_row_piece(t, r, dir * (bottom - top), min2(xt, xbt), max2(xt, xbt));
    }
}

/* One edge in tile coordinates. Parts left of the tile act as a vertical edge at x = 0
 * (they cover every pixel to their right), parts right of it cannot reach the tile. */
static void accumulate_edge(raster_tile *tile, double x0, double y0, double x1, double y1)
{
    int w = tile->w, h = tile->h;
    double dir = 1.0;
    if (y0 > y1) {
        double t = x0;
        x0 = x1;
        x1 = t;
        t = y0;
        y0 = y1;
        y1 = t;
        dir = -1.0;
    }
    double slope = (x1 - x0) / (y1 - y0);
    double ya = y0, xa = x0, yb = y1, xb = x1;
    if (ya < 0.0) {
        ya = 0.0;
        xa = x0 + (0.0 - y0) * slope;
    }
    if (yb > (double)h) {
        yb = (double)h;
        xb = x0 + ((double)h - y0) * slope;
    }
    if (!(yb > ya)) return;

    /* Break points where the piece crosses x = 0 and x = w (at most two). */
    double ys[4], xs[4];
    int n = 0;
    ys[n] = ya;
    xs[n++] = xa;
    double bounds[2] = {0.0, (double)w};
    double cross_y[2], cross_x[2];
    int crossings = 0;
    for (int i = 0; i < 2; i++) {
        double b = bounds[i];
        if ((xa < b && xb > b) || (xa > b && xb < b)) {
            double y = ya + (b - xa) / (xb - xa) * (yb - ya);
            if (y > ya && y < yb) {
                cross_y[crossings] = y;
                cross_x[crossings++] = b;
            }
        }
    }
    if (crossings == 2 && cross_y[1] < cross_y[0]) {
        double t = cross_y[0];
        cross_y[0] = cross_y[1];
        cross_y[1] = t;
        t = cross_x[0];
        cross_x[0] = cross_x[1];
        cross_x[1] = t;
    }
    for (int i = 0; i < crossings; i++) {
        ys[n] = cross_y[i];
        xs[n++] = cross_x[i];
    }
    ys[n] = yb;
    xs[n++] = xb;

    for (int i = 0; i + 1 < n; i++) {
        double pt = ys[i], pb = ys[i + 1];
        if (!(pb > pt)) continue;
        double xt = xs[i], xbt = xs[i + 1];
        double mid = 0.5 * (xt + xbt);
        if (mid >= (double)w) continue;
        if (mid <= 0.0) {
            xt = xbt = 0.0;
        } else {
            xt = clampd(xt, 0.0, (double)w);
            xbt = clampd(xbt, 0.0, (double)w);
        }
        accumulate_piece(tile, pt, xt, pb, xbt, dir);
    }
}

static inline float apply_rule(double sum, sk_fill_rule rule)
{
    float v = (float)fabs(sum);
    if (rule == SK_FILL_EVEN_ODD) {
        v = fmodf(v, 2.0f);
        if (v > 1.0f) v = 2.0f - v;
    } else if (v > 1.0f) {
        v = 1.0f;
    }
    if (v < SK__COVERAGE_SNAP) return 0.0f;
    return v > 1.0f - SK__COVERAGE_SNAP ? 1.0f : v;
}

/* Turns row r of the accumulation buffer into coverage in place (the touched columns,
 * then the constant value the running sum keeps up to the tile's right edge); returns
 * the nonzero range. */
static bool resolve_row(const raster_tile *t, int r, sk_fill_rule rule, int *first, int *last)
{
    float *row = t->acc + (size_t)r * (size_t)t->stride;
    int c0 = t->touch_lo[r], c1 = t->touch_hi[r] < t->w - 1 ? t->touch_hi[r] : t->w - 1;
    if (c0 > c1) return false;
    double sum = 0.0;
    int lo = -1, hi = -1;
    for (int c = c0; c <= c1; c++) {
        sum += (double)row[c];
        float v = apply_rule(sum, rule);
        row[c] = v;
        if (v > 0.0f) {
            if (lo < 0) lo = c;
            hi = c;
        }
    }
    float tail = apply_rule(sum, rule);
    if (tail > 0.0f && c1 + 1 < t->w) {
        for (int c = c1 + 1; c < t->w; c++) row[c] = tail;
        if (lo < 0) lo = c1 + 1;
        hi = t->w - 1;
    }
    *first = lo;
    *last = hi;
    return lo >= 0;
}

void sk__raster_fill(const sk__path *path, sk_fill_rule rule, sk__clip clip, sk__span_fn emit,
                     void *user)
{
    if (path->failed || path->count == 0) return;
    sk__clip box = sk__clip_bounds(clip, path->min_x, path->min_y, path->max_x, path->max_y);
    if (sk__clip_empty(box)) return;
    if (rule == SK_FILL_DEFAULT) rule = SK_FILL_NONZERO;

    float acc[SK__RASTER_FLOATS];
    short touch_lo[SK__RASTER_FLOATS / 3], touch_hi[SK__RASTER_FLOATS / 3];
    raster_tile t = {acc, 0, 0, 0, touch_lo, touch_hi};
    int total_w = box.x1 - box.x0;
    int tile_w = total_w < SK__RASTER_MAX_TILE_WIDTH ? total_w : SK__RASTER_MAX_TILE_WIDTH;
    for (int tx = box.x0; tx < box.x1; tx += tile_w) {
        t.w = box.x1 - tx < tile_w ? box.x1 - tx : tile_w;
        t.stride = t.w + 2;
        int band_h = SK__RASTER_FLOATS / t.stride;
        for (int ty = box.y0; ty < box.y1; ty += band_h) {
            t.h = box.y1 - ty < band_h ? box.y1 - ty : band_h;
            memset(acc, 0, sizeof(float) * (size_t)t.stride * (size_t)t.h);
            for (int r = 0; r < t.h; r++) {
                touch_lo[r] = SHRT_MAX;
                touch_hi[r] = -1;
            }
            bool touched = false;
            for (int i = 0; i < path->count; i++) {
                const sk__edge *e = &path->edges[i];
                double ey0 = e->y0 - (double)ty, ey1 = e->y1 - (double)ty;
                if (max2(ey0, ey1) <= 0.0 || min2(ey0, ey1) >= (double)t.h) continue;
                double ex0 = e->x0 - (double)tx, ex1 = e->x1 - (double)tx;
                if (min2(ex0, ex1) >= (double)t.w) continue;
                accumulate_edge(&t, ex0, ey0, ex1, ey1);
                touched = true;
            }
            if (!touched) continue;
            for (int r = 0; r < t.h; r++) {
                int first, last;
                if (resolve_row(&t, r, rule, &first, &last))
                    emit(user, tx + first, ty + r, last - first + 1,
                         acc + (size_t)r * (size_t)t.stride + first);
            }
        }
    }
}

void sk__fill_path(const sk__paint *paint, const sk__path *path, sk_fill_rule rule, sk__clip clip)
{
    sk__raster_fill(path, rule, clip, sk__paint_span_fn, (void *)paint);
}
