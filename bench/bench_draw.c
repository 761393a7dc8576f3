/* Benchmark of the draw module: anti-aliased segments on a 4096 x 4096 RGB image (the
 * skin edge-overlay case), polylines, discs, text, resizing, a plot and a contact sheet.
 * Baseline: filling each segment's bounding box with sk_draw_rect (the memory traffic a
 * primitive cannot avoid). */
#include <stdio.h>
#include <stdlib.h>

#include "shitsukan/draw.h"

#define SIZE 4096
#define SEGMENTS 100000

typedef struct segment {
    float x0, y0, x1, y1;
} segment;

/* Random positions and directions, lengths 5-30 px: the worst case for the caches. */
static void random_segments(segment *s, int n, uint64_t seed)
{
    for (int i = 0; i < n; i++) {
        sk_rng r = sk_rng_make(seed, (uint64_t)i, 0, 0);
        float x = (float)sk_rng_range(&r, 0, SIZE), y = (float)sk_rng_range(&r, 0, SIZE);
        float a = (float)sk_rng_range(&r, 0, 2 * SK_PI), len = (float)sk_rng_range(&r, 5, 30);
        s[i] = (segment){x, y, x + len * cosf(a), y + len * sinf(a)};
    }
}

/* Cell outlines in scanline order of the cells (the order an edge overlay of a cell map
 * draws in): heptagons of radius 12-16 px on a jittered grid, one segment per side. */
static void cell_segments(segment *s, int n, uint64_t seed)
{
    int per_row = (int)sqrt((double)n / 7.0) + 1;
    double cell = (double)SIZE / per_row;
    for (int i = 0; i < n; i++) {
        int c = i / 7, k = i % 7;
        sk_rng r = sk_rng_make(seed, (uint64_t)c, 0, 0);
        double cx = (c % per_row + 0.5) * cell + sk_rng_range(&r, -4, 4);
        double cy = (c / per_row + 0.5) * cell + sk_rng_range(&r, -4, 4);
        double rad = sk_rng_range(&r, 12, 16), a0 = 2 * SK_PI * k / 7, a1 = 2 * SK_PI * (k + 1) / 7;
        s[i] = (segment){(float)(cx + rad * cos(a0)), (float)(cy + rad * sin(a0)),
                         (float)(cx + rad * cos(a1)), (float)(cy + rad * sin(a1))};
    }
}

int main(void)
{
    sk_image img = {SIZE, SIZE, 3, calloc((size_t)SIZE * SIZE * 3, sizeof(float))};
    segment *seg = malloc(sizeof(segment) * SEGMENTS);
    if (!img.data || !seg) return 1;
    random_segments(seg, SEGMENTS, 1);
    sk_color c = sk_rgba(0.9f, 0.2f, 0.1f, 0.8f);
    sk_draw_clear(&img, sk_rgb(1.0f, 1.0f, 1.0f)); /* touch every page before timing */

    double t0 = sk_time_seconds();
    for (int i = 0; i < SEGMENTS; i++) {
        float x0 = fminf(seg[i].x0, seg[i].x1) - 1, y0 = fminf(seg[i].y0, seg[i].y1) - 1;
        float x1 = fmaxf(seg[i].x0, seg[i].x1) + 1, y1 = fmaxf(seg[i].y0, seg[i].y1) + 1;
        sk_draw_rect(&img, x0, y0, x1 - x0, y1 - y0, c);
    }
    double base = sk_time_seconds() - t0;
    printf("baseline: %d bounding-box rects on %dx%d RGB: %.3f s (%.0f ns each)\n", SEGMENTS, SIZE,
           SIZE, base, base / SEGMENTS * 1e9);

    const float widths[] = {0.5f, 1.5f, 3.0f, 10.0f};
    for (int k = 0; k < 4; k++) {
        t0 = sk_time_seconds();
        for (int i = 0; i < SEGMENTS; i++)
            sk_draw_line(&img, seg[i].x0, seg[i].y0, seg[i].x1, seg[i].y1, widths[k], c);
        double t = sk_time_seconds() - t0;
        printf("random lines, width %4.1f: %d segments (5-30 px) in %.3f s (%.0f ns each, "
               "%.2fx baseline)\n",
               widths[k], SEGMENTS, t, t / SEGMENTS * 1e9, t / base);
    }
    segment *cells = malloc(sizeof(segment) * SEGMENTS);
    if (!cells) return 1;
    cell_segments(cells, SEGMENTS, 3);
    for (int k = 0; k < 4; k++) {
        t0 = sk_time_seconds();
        for (int i = 0; i < SEGMENTS; i++)
            sk_draw_line(&img, cells[i].x0, cells[i].y0, cells[i].x1, cells[i].y1, widths[k], c);
        double t = sk_time_seconds() - t0;
        printf("cell-edge overlay, width %4.1f: %d segments (~11 px) in %.3f s (%.0f ns each)\n",
               widths[k], SEGMENTS, t, t / SEGMENTS * 1e9);
    }
    free(cells);

    /* 10k closed cell outlines of 8 points each, composited once per polyline. */
    enum { CELLS = 10000, CORNERS = 8 };
    sk_vec2f pts[CORNERS];
    t0 = sk_time_seconds();
    for (int i = 0; i < CELLS; i++) {
        sk_rng r = sk_rng_make(2, (uint64_t)i, 0, 0);
        float cx = (float)sk_rng_range(&r, 0, SIZE), cy = (float)sk_rng_range(&r, 0, SIZE);
        for (int k = 0; k < CORNERS; k++) {
            float a = 2 * SK_PI_F * (float)k / CORNERS, rr = (float)sk_rng_range(&r, 10, 20);
            pts[k] = sk_v2f(cx + rr * cosf(a), cy + rr * sinf(a));
        }
        sk_draw_polyline(&img, pts, CORNERS, true, 1.5f, c);
    }
    double t = sk_time_seconds() - t0;
    printf("polylines: %d closed outlines of %d points, width 1.5, in %.3f s (%.1f us each)\n",
           CELLS, CORNERS, t, t / CELLS * 1e6);

    t0 = sk_time_seconds();
    for (int i = 0; i < SEGMENTS; i++) sk_draw_disc(&img, seg[i].x0, seg[i].y0, 3.0f, c);
    t = sk_time_seconds() - t0;
    printf("discs: %d of radius 3 in %.3f s (%.0f ns each)\n", SEGMENTS, t, t / SEGMENTS * 1e9);

    for (int frac = 0; frac < 2; frac++) {
        t0 = sk_time_seconds();
        for (int i = 0; i < 10000; i++) {
            float x = frac ? seg[i].x0 : floorf(seg[i].x0),
                  y = frac ? seg[i].y0 : floorf(seg[i].y0);
            sk_draw_text(&img, x, y, "(a) jitter 0.25", 2, c);
        }
        t = sk_time_seconds() - t0;
        printf("text: 10000 labels of 15 characters at scale 2, %s positions, in %.3f s (%.1f us "
               "each)\n",
               frac ? "fractional" : "integer", t, t / 10000 * 1e6);
    }

    sk_image small;
    t0 = sk_time_seconds();
    if (sk_image_resize(&img, 1024, 1024, &small, NULL) != SK_OK) return 1;
    t = sk_time_seconds() - t0;
    printf("resize: %dx%d RGB box-filtered to 1024x1024 in %.3f s (%d threads)\n", SIZE, SIZE, t,
           sk_threads_max());

    enum { N = 2000 };
    float xs[N], ys[4][N];
    for (int i = 0; i < N; i++) {
        xs[i] = (float)i * 0.01f;
        for (int k = 0; k < 4; k++) ys[k][i] = 40.0f * sinf(xs[i] * (float)(k + 1)) + 20.0f * k;
    }
    sk_plot_series series[4] = {{"a", xs, ys[0], N, {0, 0, 0, 0}, 0},
                                {"b", xs, ys[1], N, {0, 0, 0, 0}, 0},
                                {"c", xs, ys[2], N, {0, 0, 0, 0}, 0},
                                {"d", xs, ys[3], N, {0, 0, 0, 0}, 0}};
    sk_image plot;
    t0 = sk_time_seconds();
    if (sk_plot_lines(series, 4, NULL, &plot, NULL) != SK_OK) return 1;
    t = sk_time_seconds() - t0;
    printf("plot: 4 series x %d points, 800x500, in %.1f ms\n", N, t * 1e3);

    const sk_image *tiles[9];
    const char *labels[9] = {"(a)", "(b)", "(c)", "(d)", "(e)", "(f)", "(g)", "(h)", "(i)"};
    for (int i = 0; i < 9; i++) tiles[i] = &small;
    sk_contact_sheet_desc cd = {0};
    cd.tile_size = 256;
    cd.title = "Contact sheet";
    sk_image sheet;
    t0 = sk_time_seconds();
    if (sk_contact_sheet(tiles, labels, 9, &cd, &sheet, NULL) != SK_OK) return 1;
    t = sk_time_seconds() - t0;
    printf("contact sheet: 9 tiles of 1024x1024 scaled to 256, in %.1f ms\n", t * 1e3);

    free(sheet.data);
    free(plot.data);
    free(small.data);
    free(seg);
    free(img.data);
    return 0;
}
