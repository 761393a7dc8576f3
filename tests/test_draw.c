/* Tests of the draw module: exact coverage of rects, lines, discs and polygons against
 * their areas, clipping and NaN robustness, font metrics and glyph set, blits, resizing,
 * contact sheet layout, plot mapping and tick generation. */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "test_support.h"

#include "products/draw/draw_internal.h"
#include "shitsukan/draw.h"

/* ------------------------------------------------------------------ helpers */

static sk_image img_new(int w, int h, int c)
{
    sk_image img = {w, h, c, calloc((size_t)w * (size_t)h * (size_t)c, sizeof(float))};
    assert_non_null(img.data);
    return img;
}

static void img_free(sk_image *img)
{
    free(img->data);
    img->data = NULL;
}

static double img_sum(const sk_image *img, int channel)
{
    double s = 0.0;
    for (int y = 0; y < img->height; y++)
        for (int x = 0; x < img->width; x++) s += sk_image_pixel(img, x, y)[channel];
    return s;
}

static float px(const sk_image *img, int x, int y, int c) { return sk_image_pixel(img, x, y)[c]; }

static const sk_color white = {1.0f, 1.0f, 1.0f, 1.0f};

static void assert_near(double actual, double expected, double tol, const char *what)
{
    if (fabs(actual - expected) > tol) {
        fprintf(stderr, "%s: got %.6f, expected %.6f (tolerance %.6f)\n", what, actual, expected,
                tol);
        fail();
    }
}

/* Shoelace area of a simple polygon. */
static double polygon_area(const sk_vec2f *p, int n)
{
    double a = 0.0;
    for (int i = 0; i < n; i++) {
        const sk_vec2f *q = &p[(i + 1) % n];
        a += (double)p[i].x * q->y - (double)q->x * p[i].y;
    }
    return fabs(0.5 * a);
}

/* ------------------------------------------------------------------- rects */

static void test_rect_integer_bounds_exact(void **state)
{
    (void)state;
    sk_image img = img_new(20, 16, 1);
    sk_draw_rect(&img, 3.0f, 4.0f, 5.0f, 6.0f, white);
    for (int y = 0; y < img.height; y++)
        for (int x = 0; x < img.width; x++) {
            bool inside = x >= 3 && x < 8 && y >= 4 && y < 10;
            assert_true(px(&img, x, y, 0) == (inside ? 1.0f : 0.0f));
        }
    img_free(&img);

    /* Full colour in RGB with an opaque colour, negative size extends left/up. */
    sk_image rgb = img_new(10, 10, 3);
    sk_draw_rect(&rgb, 6.0f, 6.0f, -3.0f, -2.0f, sk_rgb(0.25f, 0.5f, 0.75f));
    for (int y = 0; y < 10; y++)
        for (int x = 0; x < 10; x++) {
            bool inside = x >= 3 && x < 6 && y >= 4 && y < 6;
            assert_true(px(&rgb, x, y, 0) == (inside ? 0.25f : 0.0f));
            assert_true(px(&rgb, x, y, 2) == (inside ? 0.75f : 0.0f));
        }
    img_free(&rgb);
}

static void test_rect_half_pixel_edges(void **state)
{
    (void)state;
    sk_image img = img_new(12, 12, 1);
    sk_draw_rect(&img, 2.5f, 3.5f, 4.0f, 4.0f, white); /* [2.5, 6.5) x [3.5, 7.5) */
    for (int y = 0; y < 12; y++)
        for (int x = 0; x < 12; x++) {
            float cx = (x == 2 || x == 6) ? 0.5f : (x > 2 && x < 6 ? 1.0f : 0.0f);
            float cy = (y == 3 || y == 7) ? 0.5f : (y > 3 && y < 7 ? 1.0f : 0.0f);
            assert_near(px(&img, x, y, 0), cx * cy, 1e-6, "half-pixel rect coverage");
        }
    assert_near(img_sum(&img, 0), 16.0, 1e-5, "half-pixel rect area");
    img_free(&img);
}

/* ------------------------------------------------------------------- lines */

static void test_line_coverage_matches_area(void **state)
{
    (void)state;
    const float widths[] = {0.5f, 1.0f, 2.5f, 7.0f};
    for (size_t k = 0; k < sizeof widths / sizeof widths[0]; k++) {
        float w = widths[k];
        float x0 = 20.3f, y0 = 30.7f, x1 = 230.9f, y1 = 92.2f;
        double len = hypot((double)x1 - x0, (double)y1 - y0);
        sk_image img = img_new(256, 128, 1);
        sk_draw_line_capped(&img, x0, y0, x1, y1, w, SK_CAP_BUTT, white);
        assert_near(img_sum(&img, 0), w * len, 0.01 * w * len, "butt line coverage");
        /* Every pixel's coverage is a fraction of the pixel. */
        for (size_t i = 0; i < (size_t)img.width * img.height; i++)
            assert_true(img.data[i] <= 1.0f);
        memset(img.data, 0, sizeof(float) * (size_t)img.width * img.height);
        sk_draw_line(&img, x0, y0, x1, y1, w, white);
        double round = w * len + SK_PI * w * w / 4.0;
        assert_near(img_sum(&img, 0), round, 0.01 * round, "round-capped line coverage");
        memset(img.data, 0, sizeof(float) * (size_t)img.width * img.height);
        sk_draw_line_capped(&img, x0, y0, x1, y1, w, SK_CAP_SQUARE, white);
        assert_near(img_sum(&img, 0), w * (len + w), 0.01 * w * (len + w), "square-capped line");
        img_free(&img);
    }
}

static void test_line_cross_section_far_from_ends(void **state)
{
    (void)state;
    /* A horizontal line of width 3 centred on y = 10.5: rows 9-11 fully covered only,
       far from the ends; a width of 2 centred on y = 10 covers half of rows 8 and 11. */
    sk_image img = img_new(64, 20, 1);
    sk_draw_line(&img, 5.0f, 10.5f, 60.0f, 10.5f, 3.0f, white);
    for (int y = 0; y < 20; y++)
        assert_near(px(&img, 30, y, 0), (y >= 9 && y <= 11) ? 1.0 : 0.0, 1e-5, "row");
    memset(img.data, 0, sizeof(float) * 64 * 20);
    sk_draw_line(&img, 5.0f, 10.0f, 60.0f, 10.0f, 2.0f, white);
    for (int y = 0; y < 20; y++) {
        double e = (y == 9 || y == 10) ? 1.0 : 0.0;
        assert_near(px(&img, 30, y, 0), e, 1e-5, "row of even line");
    }
    memset(img.data, 0, sizeof(float) * 64 * 20);
    sk_draw_line(&img, 5.0f, 10.0f, 60.0f, 10.0f, 3.0f, white);
    for (int y = 0; y < 20; y++) {
        double e = (y == 9 || y == 10) ? 1.0 : ((y == 8 || y == 11) ? 0.5 : 0.0);
        assert_near(px(&img, 30, y, 0), e, 1e-5, "row of half-pixel line");
    }
    img_free(&img);
}

static void test_polyline_composites_once(void **state)
{
    (void)state;
    /* A zig-zag folding back over itself, translucent: no pixel may exceed the colour's
       alpha (drawing the segments one by one does, at the joins). */
    sk_vec2f pts[] = {{10, 10}, {50, 12}, {12, 14}, {52, 30}, {10, 30}, {30, 5}};
    int n = (int)(sizeof pts / sizeof pts[0]);
    sk_color half = sk_rgba(1.0f, 1.0f, 1.0f, 0.5f);
    sk_image img = img_new(64, 40, 1);
    sk_draw_polyline(&img, pts, n, false, 4.0f, half);
    float max = 0.0f;
    for (size_t i = 0; i < 64 * 40; i++) max = fmaxf(max, img.data[i]);
    assert_near(max, 0.5, 1e-5, "polyline maximum");
    memset(img.data, 0, sizeof(float) * 64 * 40);
    for (int i = 0; i + 1 < n; i++)
        sk_draw_line(&img, pts[i].x, pts[i].y, pts[i + 1].x, pts[i + 1].y, 4.0f, half);
    max = 0.0f;
    for (size_t i = 0; i < 64 * 40; i++) max = fmaxf(max, img.data[i]);
    assert_true(max > 0.7f); /* separate segments double-blend at the joins */

    /* Collinear segments of a straight polyline cover like one line of the same length. */
    sk_vec2f straight[9];
    for (int i = 0; i < 9; i++)
        straight[i] = sk_v2f(8.0f + 6.0f * (float)i, 20.3f + 1.5f * (float)i);
    memset(img.data, 0, sizeof(float) * 64 * 40);
    sk_draw_polyline(&img, straight, 9, false, 2.0f, white);
    double joined = img_sum(&img, 0);
    memset(img.data, 0, sizeof(float) * 64 * 40);
    sk_draw_line(&img, straight[0].x, straight[0].y, straight[8].x, straight[8].y, 2.0f, white);
    assert_near(joined, img_sum(&img, 0), 0.01 * img_sum(&img, 0), "polyline vs one line");

    /* A closed square polyline: its coverage is the square ring's area. */
    sk_vec2f square[] = {{10, 10}, {40, 10}, {40, 30}, {10, 30}};
    memset(img.data, 0, sizeof(float) * 64 * 40);
    sk_draw_polyline(&img, square, 4, true, 2.0f, white);
    /* Outer rounded rectangle (corner radius 1) minus the inner rectangle. */
    double ring = 32.0 * 22.0 - (4.0 - SK_PI) - 28.0 * 18.0;
    assert_near(img_sum(&img, 0), ring, 0.01 * ring, "closed polyline");
    img_free(&img);
}

/* ------------------------------------------------------------ discs, circles */

static void test_disc_and_ring_areas(void **state)
{
    (void)state;
    const float radii[] = {0.7f, 3.0f, 10.3f, 45.0f};
    for (size_t k = 0; k < sizeof radii / sizeof radii[0]; k++) {
        float r = radii[k];
        sk_image img = img_new(128, 128, 1);
        sk_draw_disc(&img, 63.3f, 64.6f, r, white);
        double area = SK_PI * r * r;
        assert_near(img_sum(&img, 0), area, 0.002 * area + 1e-3, "disc area");
        assert_near(px(&img, 63, 64, 0), r >= 1.0f ? 1.0 : px(&img, 63, 64, 0), 1e-6,
                    "disc centre");
        memset(img.data, 0, sizeof(float) * 128 * 128);
        sk_draw_circle(&img, 63.3f, 64.6f, r, 1.5f, white);
        double inner = r - 0.75 > 0 ? r - 0.75 : 0.0;
        double ring = SK_PI * ((r + 0.75) * (r + 0.75) - inner * inner);
        assert_near(img_sum(&img, 0), ring, 0.003 * ring, "ring area");
        img_free(&img);
    }
    /* A ring leaves its centre empty. */
    sk_image img = img_new(64, 64, 1);
    sk_draw_circle(&img, 32.0f, 32.0f, 20.0f, 2.0f, white);
    assert_true(px(&img, 31, 31, 0) == 0.0f);
    assert_near(px(&img, 51, 31, 0), 1.0, 2e-3, "ring pixel on the circle");
    img_free(&img);
}

/* ----------------------------------------------------------------- polygons */

static void test_polygon_areas(void **state)
{
    (void)state;
    /* Convex, concave (an arrow), both orientations. */
    sk_vec2f tri[] = {{5.2f, 7.1f}, {60.7f, 12.9f}, {22.4f, 55.3f}};
    sk_vec2f arrow[] = {{10, 30}, {40, 10}, {40, 22}, {70, 22.5f}, {70, 37.5f}, {40, 38}, {40, 50}};
    sk_vec2f arrow_cw[7];
    for (int i = 0; i < 7; i++) arrow_cw[i] = arrow[6 - i];
    struct {
        const sk_vec2f *p;
        int n;
    } cases[] = {{tri, 3}, {arrow, 7}, {arrow_cw, 7}};
    for (size_t k = 0; k < 3; k++) {
        sk_image img = img_new(80, 64, 1);
        sk_draw_polygon(&img, cases[k].p, cases[k].n, white);
        double area = polygon_area(cases[k].p, cases[k].n);
        assert_near(img_sum(&img, 0), area, 1e-4 * area, "polygon area");
        for (size_t i = 0; i < 80 * 64; i++)
            assert_true(img.data[i] >= 0.0f && img.data[i] <= 1.0f);
        img_free(&img);
    }
    /* A polygon wider than one rasterizer tile (1022 px). */
    sk_vec2f wide[] = {{3.5f, 2.0f}, {2500.2f, 9.0f}, {2490.0f, 30.5f}, {10.0f, 25.0f}};
    sk_image img = img_new(2600, 32, 1);
    sk_draw_polygon(&img, wide, 4, white);
    assert_near(img_sum(&img, 0), polygon_area(wide, 4), 1e-4 * polygon_area(wide, 4),
                "wide polygon");
    img_free(&img);
}

static void test_fill_rules_and_holes(void **state)
{
    (void)state;
    /* A pentagram: non-zero fills the centre, even-odd leaves it empty. */
    sk_vec2f star[5];
    for (int i = 0; i < 5; i++) {
        double a = -SK_PI / 2 + i * 4.0 * SK_PI / 5.0;
        star[i] = sk_v2f((float)(32.0 + 28.0 * cos(a)), (float)(32.0 + 28.0 * sin(a)));
    }
    int count = 5;
    sk_image img = img_new(64, 64, 1);
    sk_draw_contours(&img, star, &count, 1, SK_FILL_NONZERO, white);
    assert_near(px(&img, 32, 32, 0), 1.0, 1e-6, "non-zero centre");
    assert_near(px(&img, 32, 8, 0), 1.0, 1e-6, "non-zero point");
    memset(img.data, 0, sizeof(float) * 64 * 64);
    sk_draw_contours(&img, star, &count, 1, SK_FILL_EVEN_ODD, white);
    assert_near(px(&img, 32, 32, 0), 0.0, 1e-6, "even-odd centre");
    assert_near(px(&img, 32, 8, 0), 1.0, 1e-6, "even-odd point");

    /* A square with a hole (opposite orientation): area is the difference. */
    sk_vec2f pts[] = {{4, 4},         {60, 4},        {60, 60},       {4, 60},
                      {20.5f, 20.5f}, {20.5f, 40.5f}, {40.5f, 40.5f}, {40.5f, 20.5f}};
    int counts[] = {4, 4};
    memset(img.data, 0, sizeof(float) * 64 * 64);
    sk_draw_contours(&img, pts, counts, 2, SK_FILL_NONZERO, white);
    assert_near(img_sum(&img, 0), 56.0 * 56.0 - 20.0 * 20.0, 1e-3, "square with hole");
    assert_true(px(&img, 30, 30, 0) == 0.0f);
    img_free(&img);
}

/* ------------------------------------------------------ compositing, layouts */

static void test_alpha_compositing(void **state)
{
    (void)state;
    /* Over a transparent RGBA image, alpha becomes coverage x colour alpha and the colour
       stays the colour (straight alpha). */
    sk_image img = img_new(16, 16, 4);
    sk_draw_rect(&img, 2.5f, 2.0f, 4.0f, 4.0f, sk_rgba(0.2f, 0.4f, 0.6f, 0.8f));
    float *edge = sk_image_pixel(&img, 2, 3);
    assert_near(edge[3], 0.4, 1e-6, "edge alpha");
    assert_near(edge[0], 0.2, 1e-6, "edge red");
    float *in = sk_image_pixel(&img, 4, 3);
    assert_near(in[3], 0.8, 1e-6, "inside alpha");
    /* Again over it: a = 0.8 + 0.8 * 0.2. */
    sk_draw_rect(&img, 2.5f, 2.0f, 4.0f, 4.0f, sk_rgba(1.0f, 1.0f, 1.0f, 0.8f));
    assert_near(in[3], 0.96, 1e-6, "alpha over alpha");
    assert_near(in[0], (1.0 * 0.8 + 0.2 * 0.8 * 0.2) / 0.96, 1e-6, "colour over colour");
    img_free(&img);

    /* Grey images draw the luminance; fill and clear. */
    sk_image g = img_new(4, 4, 2);
    sk_draw_clear(&g, sk_rgba(0.0f, 1.0f, 0.0f, 0.5f));
    assert_near(px(&g, 1, 1, 0), 0.7152, 1e-6, "luminance");
    assert_near(px(&g, 1, 1, 1), 0.5, 1e-6, "cleared alpha");
    sk_draw_fill(&g, sk_rgba(1.0f, 1.0f, 1.0f, 1.0f));
    assert_near(px(&g, 3, 3, 0), 1.0, 1e-6, "fill");
    assert_near(px(&g, 3, 3, 1), 1.0, 1e-6, "fill alpha");
    img_free(&g);
}

/* Draws every primitive with the given coordinates into a 24 x 24 image stored inside a
 * larger buffer whose guard bands must stay untouched. Returns the image's sum. */
static double draw_all_guarded(float x0, float y0, float x1, float y1, float size, int channels)
{
    enum { W = 24, H = 24, GUARD = 4096 };
    size_t n = (size_t)W * H * channels;
    float *buf = malloc((n + 2 * GUARD) * sizeof(float));
    assert_non_null(buf);
    for (size_t i = 0; i < n + 2 * GUARD; i++)
        buf[i] = (i < GUARD || i >= GUARD + n) ? -7.0f : 0.0f;
    sk_image img = {W, H, channels, buf + GUARD};
    sk_color c = sk_rgba(1.0f, 0.5f, 0.25f, 1.0f);
    sk_vec2f pts[4] = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
    sk_draw_rect(&img, x0, y0, x1 - x0, y1 - y0, c);
    sk_draw_line(&img, x0, y0, x1, y1, size, c);
    sk_draw_line_capped(&img, x0, y1, x1, y0, size, SK_CAP_SQUARE, c);
    sk_draw_polyline(&img, pts, 4, true, size, c);
    sk_draw_circle(&img, x0, y0, size * 3.0f, size, c);
    sk_draw_disc(&img, x1, y1, size * 2.0f, c);
    sk_draw_polygon(&img, pts, 4, c);
    sk_draw_text(&img, x0, y0, "Clip Ag|", 3, c);
    sk_image src = {5, 5, 3, calloc(75, sizeof(float))};
    assert_non_null(src.data);
    if (isfinite(x0) && fabsf(x0) < 1e6f && isfinite(y0) && fabsf(y0) < 1e6f)
        sk_draw_blit(&img, &src, (int)x0, (int)y0);
    free(src.data);
    for (size_t i = 0; i < GUARD; i++) {
        assert_true(buf[i] == -7.0f);
        assert_true(buf[GUARD + n + i] == -7.0f);
    }
    double sum = 0.0;
    for (size_t i = 0; i < n; i++) {
        assert_false(isnan(img.data[i]));
        sum += img.data[i];
    }
    free(buf);
    return sum;
}

static void test_clipping_and_nan(void **state)
{
    (void)state;
    for (int ch = 1; ch <= 4; ch++) {
        /* Partly outside: draws something, writes nothing outside. */
        assert_true(draw_all_guarded(-10.5f, -7.25f, 30.5f, 40.0f, 3.0f, ch) > 0.0);
        assert_true(draw_all_guarded(20.0f, 20.0f, 50.0f, 45.0f, 2.0f, ch) > 0.0);
        /* Fully outside, huge or infinite: nothing drawn, no crash. */
        assert_true(draw_all_guarded(30.0f, 30.0f, 90.0f, 90.0f, 2.0f, ch) == 0.0);
        assert_true(draw_all_guarded(-90.0f, -1e30f, -30.0f, 1e30f, 2.0f, ch) == 0.0);
        draw_all_guarded(-FLT_MAX, -FLT_MAX, FLT_MAX, FLT_MAX, 1.0f, ch);
        draw_all_guarded(-1e30f, 5.0f, 1e30f, 6.0f, 1e20f, ch);
        /* NaN or infinite coordinates: the primitives are skipped. */
        assert_true(draw_all_guarded(NAN, NAN, NAN, NAN, 2.0f, ch) == 0.0);
        /* A NaN size: rect, polygon, text and blit (which take no size) still draw. */
        assert_true(draw_all_guarded(3.0f, 3.0f, 10.0f, 12.0f, NAN, ch) > 0.0);
        assert_true(draw_all_guarded(INFINITY, -INFINITY, -INFINITY, INFINITY, 2.0f, ch) == 0.0);
    }
    /* A NaN size alone skips the sized primitives. */
    sk_image img = img_new(16, 16, 1);
    sk_draw_line(&img, 1, 1, 10, 10, NAN, white);
    sk_draw_circle(&img, 8, 8, 4, NAN, white);
    sk_draw_disc(&img, 8, 8, NAN, white);
    sk_draw_rect(&img, 1, 1, NAN, 4, white);
    sk_draw_disc(&img, 8, 8, 4, sk_rgba(NAN, 1, 1, 1));
    sk_vec2f bad[3] = {{1, 1}, {NAN, 5}, {9, 9}};
    sk_draw_polygon(&img, bad, 3, white);
    assert_true(img_sum(&img, 0) == 0.0);
    /* A polyline breaks at a NaN point but keeps its finite segments. */
    sk_vec2f broken[4] = {{1, 2.5f}, {14, 2.5f}, {NAN, NAN}, {1.5f, 12.5f}};
    sk_draw_polyline(&img, broken, 4, false, 1.0f, white);
    assert_true(px(&img, 7, 2, 0) > 0.9f);
    assert_true(px(&img, 1, 12, 0) > 0.0f); /* the isolated point is a dot */
    assert_true(px(&img, 7, 8, 0) == 0.0f);
    /* Invalid images are ignored. */
    sk_image none = {0, 0, 3, NULL};
    sk_draw_line(&none, 0, 0, 5, 5, 1, white);
    sk_draw_fill(NULL, white);
    assert_int_equal(sk_draw_text(NULL, 0, 0, "abc", 1, white), 17);
    img_free(&img);
}

/* ---------------------------------------------------------------------- text */

static void ink_box(const sk_image *img, int *x0, int *y0, int *x1, int *y1)
{
    *x0 = *y0 = INT32_MAX;
    *x1 = *y1 = -1;
    for (int y = 0; y < img->height; y++)
        for (int x = 0; x < img->width; x++)
            if (px(img, x, y, 0) > 0.0f) {
                if (x < *x0) *x0 = x;
                if (y < *y0) *y0 = y;
                if (x > *x1) *x1 = x;
                if (y > *y1) *y1 = y;
            }
}

static void test_text_metrics_match_ink(void **state)
{
    (void)state;
    /* "M" touches the left and top, "g" and "_" the bottom, "W" the right of the box. */
    const char *text = "Mg_ x=1.5W";
    for (int scale = 1; scale <= 3; scale++) {
        sk_image img = img_new(240, 40, 1);
        int w = sk_draw_text(&img, 7.0f, 5.0f, text, scale, white);
        assert_int_equal(w, sk_draw_text_width(text, scale));
        assert_int_equal(w, (int)strlen(text) * 6 * scale - scale);
        int x0, y0, x1, y1;
        ink_box(&img, &x0, &y0, &x1, &y1);
        assert_int_equal(x0, 7);
        assert_int_equal(y0, 5);
        assert_int_equal(x1 - x0 + 1, w);
        assert_int_equal(y1 - y0 + 1, sk_draw_text_height(scale));
        /* Integer positions are crisp: only 0 or full colour. */
        for (size_t i = 0; i < (size_t)240 * 40; i++)
            assert_true(img.data[i] == 0.0f || img.data[i] == 1.0f);
        /* A fractional position spreads the same ink (area is conserved). */
        double ink = img_sum(&img, 0);
        memset(img.data, 0, sizeof(float) * 240 * 40);
        sk_draw_text(&img, 7.3f, 5.6f, text, scale, white);
        assert_near(img_sum(&img, 0), ink, 1e-3 * ink, "anti-aliased text ink");
        img_free(&img);
    }
    assert_int_equal(sk_draw_text_width("", 2), 0);
    assert_int_equal(sk_draw_text_width(NULL, 2), 0);
    assert_int_equal(sk_draw_text_height(2), 18);
    /* A UTF-8 sequence is one (replacement) glyph. */
    assert_int_equal(sk_draw_text_width("\xc3\xa9t\xc3\xa9", 1), sk_draw_text_width("ete", 1));
}

static void test_glyphs_present_and_distinct(void **state)
{
    (void)state;
    enum { N = 95, W = 5, H = 9 };
    static float glyphs[N][W * H];
    for (int i = 0; i < N; i++) {
        char s[2] = {(char)(32 + i), 0};
        sk_image img = img_new(W, H, 1);
        assert_int_equal(sk_draw_text(&img, 0, 0, s, 1, white), W);
        memcpy(glyphs[i], img.data, sizeof glyphs[i]);
        double ink = img_sum(&img, 0);
        if (i == 0)
            assert_true(ink == 0.0);
        else if (ink < 1.0) {
            fprintf(stderr, "glyph '%c' draws nothing\n", 32 + i);
            fail();
        }
        img_free(&img);
    }
    for (int i = 0; i < N; i++)
        for (int j = i + 1; j < N; j++)
            if (memcmp(glyphs[i], glyphs[j], sizeof glyphs[i]) == 0) {
                fprintf(stderr, "glyphs '%c' and '%c' are identical\n", 32 + i, 32 + j);
                fail();
            }
}

static void test_text_rotated_and_fit(void **state)
{
    (void)state;
    /* Rotated text occupies the transposed box. */
    sk_image img = img_new(40, 80, 1);
    const char *text = "Mg_W";
    sk__draw_text_dir(&img, sk__clip_image(&img), 3.0f, 4.0f, text, 2, SK__TEXT_UP, white);
    int x0, y0, x1, y1;
    ink_box(&img, &x0, &y0, &x1, &y1);
    assert_int_equal(x0, 3);
    assert_int_equal(y0, 4);
    assert_int_equal(x1 - x0 + 1, sk_draw_text_height(2));
    assert_int_equal(y1 - y0 + 1, sk_draw_text_width(text, 2));
    /* "M" is at the bottom: its left stem is the bottom row, drawn as a full row. */
    for (int x = 3; x < 3 + 14; x++) assert_true(px(&img, x, y1, 0) == 1.0f);
    img_free(&img);

    char buf[64];
    assert_string_equal(sk__text_fit("short", 1, 100, buf, sizeof buf), "short");
    const char *fit = sk__text_fit("a rather long label", 1, 59, buf, sizeof buf);
    assert_true(sk_draw_text_width(fit, 1) <= 59);
    assert_string_equal(fit, "a rathe...");
    assert_string_equal(sk__text_fit("abcdef", 1, 11, buf, sizeof buf), "..");
}

/* --------------------------------------------------------------------- blit */

static void test_blit_conversions(void **state)
{
    (void)state;
    sk_image grey = img_new(3, 2, 1);
    for (int i = 0; i < 6; i++) grey.data[i] = 0.1f * (float)(i + 1);
    sk_image rgba = img_new(6, 5, 4);
    sk_draw_blit(&rgba, &grey, 2, 1);
    for (int y = 0; y < 2; y++)
        for (int x = 0; x < 3; x++) {
            const float *p = sk_image_pixel(&rgba, x + 2, y + 1);
            float v = px(&grey, x, y, 0);
            assert_true(p[0] == v && p[1] == v && p[2] == v && p[3] == 1.0f);
        }
    assert_true(px(&rgba, 1, 1, 3) == 0.0f);

    /* RGB -> grey takes the luminance; negative offsets clip. */
    sk_image rgb = img_new(2, 2, 3);
    for (int i = 0; i < 4; i++) {
        rgb.data[3 * i] = 1.0f;
        rgb.data[3 * i + 1] = 0.5f;
        rgb.data[3 * i + 2] = 0.0f;
    }
    sk_image g2 = img_new(2, 2, 1);
    sk_draw_blit(&g2, &rgb, -1, -1);
    assert_near(px(&g2, 0, 0, 0), 0.2126 + 0.5 * 0.7152, 1e-6, "luminance blit");
    assert_true(px(&g2, 1, 0, 0) == 0.0f && px(&g2, 0, 1, 0) == 0.0f);

    /* RGBA over RGB composites with the source alpha; COPY into RGBA keeps it. */
    sk_image src = img_new(1, 1, 4);
    src.data[0] = 1.0f;
    src.data[3] = 0.25f;
    sk_image dst = img_new(2, 1, 3);
    dst.data[0] = dst.data[1] = dst.data[2] = 0.5f;
    sk_draw_blit(&dst, &src, 0, 0);
    assert_near(dst.data[0], 0.25 + 0.5 * 0.75, 1e-6, "over red");
    assert_near(dst.data[1], 0.5 * 0.75, 1e-6, "over green");
    sk_image dst4 = img_new(1, 1, 4);
    sk_draw_blit_mode(&dst4, &src, 0, 0, SK_BLIT_COPY);
    assert_true(dst4.data[0] == 1.0f && dst4.data[3] == 0.25f);
    /* Grey+alpha over grey. */
    sk_image ga = img_new(1, 1, 2);
    ga.data[0] = 1.0f;
    ga.data[1] = 0.5f;
    sk_image gd = img_new(1, 1, 1);
    sk_draw_blit(&gd, &ga, 0, 0);
    assert_near(gd.data[0], 0.5, 1e-6, "grey over");
    /* Far outside: nothing happens. */
    sk_draw_blit(&gd, &ga, 2000000000, -2000000000);
    assert_near(gd.data[0], 0.5, 1e-6, "blit far outside");
    img_free(&grey);
    img_free(&rgba);
    img_free(&rgb);
    img_free(&g2);
    img_free(&src);
    img_free(&dst);
    img_free(&dst4);
    img_free(&ga);
    img_free(&gd);
}

/* ------------------------------------------------------------------- resize */

static void test_resize_constant_and_box_mean(void **state)
{
    (void)state;
    sk_image c = img_new(37, 23, 3);
    for (size_t i = 0; i < 37 * 23 * 3; i++) c.data[i] = (float)(i % 3) * 0.3f + 0.1f;
    const sk_resize_filter filters[] = {SK_RESIZE_DEFAULT, SK_RESIZE_NEAREST, SK_RESIZE_BILINEAR,
                                        SK_RESIZE_BOX};
    const int sizes[][2] = {{11, 7}, {100, 61}, {37, 23}, {5, 90}, {1, 1}};
    for (size_t f = 0; f < 4; f++)
        for (size_t s = 0; s < 5; s++) {
            sk_image out;
            sk_error err;
            assert_int_equal(
                sk_image_resize_filter(&c, sizes[s][0], sizes[s][1], filters[f], &out, &err),
                SK_OK);
            assert_int_equal(out.width, sizes[s][0]);
            assert_int_equal(out.height, sizes[s][1]);
            assert_int_equal(out.channels, 3);
            for (size_t i = 0; i < (size_t)out.width * out.height * 3; i++)
                assert_near(out.data[i], (double)(i % 3) * 0.3 + 0.1, 2e-6, "constant resize");
            free(out.data);
        }
    img_free(&c);

    /* A checkerboard of 2x2 squares boxed down by 8 (and by a non-integer 64/6) gives
       its mean. */
    sk_image cb = img_new(64, 64, 1);
    for (int y = 0; y < 64; y++)
        for (int x = 0; x < 64; x++) cb.data[y * 64 + x] = ((x / 2 + y / 2) % 2) ? 1.0f : 0.0f;
    sk_image out;
    assert_int_equal(sk_image_resize(&cb, 8, 8, &out, NULL), SK_OK);
    for (int i = 0; i < 64; i++) assert_near(out.data[i], 0.5, 1e-6, "box mean");
    free(out.data);
    assert_int_equal(sk_image_resize_filter(&cb, 4, 4, SK_RESIZE_BOX, &out, NULL), SK_OK);
    for (int i = 0; i < 16; i++) assert_near(out.data[i], 0.5, 1e-6, "box mean 4");
    free(out.data);
    /* Non-integer ratio: the total is preserved (area average). */
    assert_int_equal(sk_image_resize_filter(&cb, 6, 6, SK_RESIZE_BOX, &out, NULL), SK_OK);
    assert_near(img_sum(&out, 0) / 36.0, 0.5, 0.02, "box mean 6");
    free(out.data);
    /* Nearest doubling repeats pixels; bilinear keeps a ramp a ramp inside. */
    assert_int_equal(sk_image_resize_filter(&cb, 128, 128, SK_RESIZE_NEAREST, &out, NULL), SK_OK);
    for (int y = 0; y < 128; y++)
        for (int x = 0; x < 128; x++)
            assert_true(out.data[y * 128 + x] == cb.data[(y / 2) * 64 + x / 2]);
    free(out.data);
    sk_image ramp = img_new(10, 1, 1);
    for (int x = 0; x < 10; x++) ramp.data[x] = (float)x;
    assert_int_equal(sk_image_resize_filter(&ramp, 20, 1, SK_RESIZE_BILINEAR, &out, NULL), SK_OK);
    for (int x = 1; x < 19; x++)
        assert_near(out.data[x], (x + 0.5) / 2.0 - 0.5, 1e-5, "bilinear ramp");
    free(out.data);
    img_free(&ramp);
    img_free(&cb);
}

static void test_resize_errors_and_threads(void **state)
{
    (void)state;
    sk_image src = img_new(8, 8, 2);
    for (int i = 0; i < 128; i++) src.data[i] = (float)((i * 37) % 11) / 10.0f;
    sk_image out = {0};
    sk_error err;
    assert_int_equal(sk_image_resize(&src, 0, 5, &out, &err), SK_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(err.message, "0 x 5"));
    assert_int_equal(sk_image_resize(&src, 70000, 5, &out, &err), SK_ERROR_LIMIT);
    assert_int_equal(sk_image_resize(NULL, 5, 5, &out, &err), SK_ERROR_INVALID_ARGUMENT);
    assert_int_equal(sk_image_resize_filter(&src, 5, 5, (sk_resize_filter)9, &out, &err),
                     SK_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(err.message, "filter"));
    sk_image bad = {8, 8, 5, src.data};
    assert_int_equal(sk_image_resize(&bad, 5, 5, &out, &err), SK_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(err.message, "channels"));
    assert_null(out.data);
    /* The same bytes for any thread count. */
    sk_image a, b;
    sk_threads_set(1);
    assert_int_equal(sk_image_resize(&src, 301, 203, &a, NULL), SK_OK);
    sk_threads_set(2);
    assert_int_equal(sk_image_resize(&src, 301, 203, &b, NULL), SK_OK);
    sk_threads_set(0);
    assert_memory_equal(a.data, b.data, sizeof(float) * 301 * 203 * 2);
    free(a.data);
    free(b.data);
    img_free(&src);
}

/* ------------------------------------------------------------ contact sheet */

static sk_image solid(int w, int h, int ch, float v)
{
    sk_image img = img_new(w, h, ch);
    for (size_t i = 0; i < (size_t)w * h * ch; i++) img.data[i] = v;
    if (ch == 2 || ch == 4)
        for (size_t i = 0; i < (size_t)w * h; i++) img.data[i * ch + ch - 1] = 1.0f;
    return img;
}

static void test_contact_sheet_layout(void **state)
{
    (void)state;
    sk_image t[5] = {solid(30, 20, 3, 0.1f), solid(10, 40, 1, 0.2f), solid(25, 25, 4, 0.3f),
                     solid(12, 12, 2, 0.4f), solid(40, 8, 3, 0.5f)};
    const sk_image *tiles[5] = {&t[0], &t[1], &t[2], &t[3], &t[4]};
    const char *labels[5] = {"(a)", NULL, "(c) long label", "", "(e)"};
    sk_contact_sheet_desc d = {0};
    d.columns = 2;
    d.padding = 6;
    d.text_scale = 1;
    d.background = sk_rgb(1.0f, 0.0f, 1.0f);
    sk_image sheet;
    sk_error err;
    assert_int_equal(sk_contact_sheet(tiles, labels, 5, &d, &sheet, &err), SK_OK);
    /* tile area 40 x 40; cell width = max(40, 14 * 6 - 1 + 6) = 89; label band 9 + 3 */
    int cell_w = 89, tile_h = 40, band = 9 + 3, pad = 6;
    assert_int_equal(sheet.width, pad + 2 * (cell_w + pad));
    assert_int_equal(sheet.height, pad + 3 * (tile_h + band + pad));
    assert_int_equal(sheet.channels, 3);
    for (int i = 0; i < 5; i++) {
        int cx = pad + (i % 2) * (cell_w + pad), cy = pad + (i / 2) * (tile_h + band + pad);
        int tx = cx + (cell_w - t[i].width) / 2, ty = cy + (tile_h - t[i].height) / 2;
        float expect = 0.1f * (float)(i + 1);
        const float *p = sk_image_pixel(&sheet, tx + t[i].width / 2, ty + t[i].height / 2);
        assert_near(p[0], expect, 1e-6, "tile centre");
        assert_near(p[2], expect, 1e-6, "tile centre blue");
        /* the first pixel of each tile and the background just outside it */
        assert_near(sk_image_pixel(&sheet, tx, ty)[1], expect, 1e-6, "tile corner");
        assert_near(sk_image_pixel(&sheet, tx - 1, ty)[1], 0.0, 1e-6, "background left of tile");
    }
    /* Some label ink (black) under tile 0, and none under tile 1 (no label). */
    int label_y = pad + tile_h + (pad + 1) / 2;
    bool ink0 = false, ink1 = false;
    for (int y = label_y; y < label_y + 9; y++)
        for (int x = 0; x < cell_w; x++) {
            if (sk_image_pixel(&sheet, pad + x, y)[0] == 0.0f) ink0 = true;
            if (sk_image_pixel(&sheet, 2 * pad + cell_w + x, y)[0] == 0.0f) ink1 = true;
        }
    assert_true(ink0);
    assert_false(ink1);
    free(sheet.data);

    /* Fixed tile size, title, labels above, defaults: scaled tiles fill their cells. */
    sk_contact_sheet_desc d2 = {0};
    d2.tile_size = 32;
    d2.title = "Title";
    d2.label_position = SK_LABEL_ABOVE;
    d2.channels = 4;
    assert_int_equal(sk_contact_sheet(tiles, NULL, 5, &d2, &sheet, &err), SK_OK);
    /* 3 columns (ceil sqrt 5), cells 32 x 32 (the largest scaled width and height),
       no label band, title band 27 + 8. */
    assert_int_equal(sheet.width, 8 + 3 * (32 + 8));
    assert_int_equal(sheet.height, 8 + 27 + 8 + 2 * (32 + 8));
    assert_int_equal(sheet.channels, 4);
    /* tile 1 (10 x 40) is shown 8 x 32 in the middle of cell 1 */
    const float *p = sk_image_pixel(&sheet, 8 + 40 + 16, 8 + 35 + 16);
    assert_near(p[0], 0.2, 1e-5, "scaled tile");
    assert_near(p[3], 1.0, 1e-6, "opaque");
    assert_near(sk_image_pixel(&sheet, 8 + 40 + 16 - 6, 8 + 35 + 16)[0], 1.0, 1e-6, "white beside");
    free(sheet.data);

    /* NEAREST scaling keeps hard pixels: a 2 x 2 checker tile shown 16 x 16. */
    sk_image checker = img_new(2, 2, 1);
    checker.data[0] = checker.data[3] = 1.0f;
    const sk_image *one[1] = {&checker};
    sk_contact_sheet_desc d3 = {0};
    d3.tile_size = 16;
    d3.tile_filter = SK_RESIZE_NEAREST;
    d3.padding = 4;
    assert_int_equal(sk_contact_sheet(one, NULL, 1, &d3, &sheet, &err), SK_OK);
    assert_int_equal(sheet.width, 24);
    for (int y = 0; y < 16; y++)
        for (int x = 0; x < 16; x++)
            assert_true(sk_image_pixel(&sheet, 4 + x, 4 + y)[0] ==
                        (((x < 8) == (y < 8)) ? 1.0f : 0.0f));
    free(sheet.data);
    img_free(&checker);
    for (int i = 0; i < 5; i++) img_free(&t[i]);
}

/* A tile border frames every tile in the padding (half-transparent text colour) and
 * leaves the tile's own pixels and the layout unchanged. */
static void test_contact_sheet_tile_border(void **state)
{
    (void)state;
    sk_image t = solid(20, 10, 3, 1.0f); /* a white tile on a white sheet */
    const sk_image *tiles[1] = {&t};
    sk_contact_sheet_desc plain = {0}, framed = {0};
    framed.tile_border = 2;
    sk_image a, b;
    sk_error err;
    assert_int_equal(sk_contact_sheet(tiles, NULL, 1, &plain, &a, &err), SK_OK);
    assert_int_equal(sk_contact_sheet(tiles, NULL, 1, &framed, &b, &err), SK_OK);
    assert_int_equal(a.width, b.width);
    assert_int_equal(a.height, b.height);
    /* tile at (8, 8): its pixels stay white, the 2 px around it are grey (0.5 black over white) */
    for (int y = 8; y < 18; y++)
        for (int x = 8; x < 28; x++) assert_true(sk_image_pixel(&b, x, y)[0] == 1.0f);
    assert_near(sk_image_pixel(&b, 7, 12)[0], 0.5, 1e-6, "left bar");
    assert_near(sk_image_pixel(&b, 6, 12)[0], 0.5, 1e-6, "left bar, outer pixel");
    assert_near(sk_image_pixel(&b, 5, 12)[0], 1.0, 1e-6, "beyond the bar");
    assert_near(sk_image_pixel(&b, 28, 12)[0], 0.5, 1e-6, "right bar");
    assert_near(sk_image_pixel(&b, 15, 7)[0], 0.5, 1e-6, "top bar");
    assert_near(sk_image_pixel(&b, 15, 18)[0], 0.5, 1e-6, "bottom bar");
    assert_near(sk_image_pixel(&a, 7, 12)[0], 1.0, 1e-6, "no frame without a border");
    framed.tile_border = 65;
    assert_int_equal(sk_contact_sheet(tiles, NULL, 1, &framed, &b, &err),
                     SK_ERROR_INVALID_ARGUMENT);
    free(a.data);
    free(b.data);
    img_free(&t);
}

static void test_contact_sheet_errors(void **state)
{
    (void)state;
    sk_image t = solid(4, 4, 3, 0.5f);
    const sk_image *tiles[2] = {&t, NULL};
    sk_image out = {0};
    sk_error err;
    sk_contact_sheet_desc d = {0};
    assert_int_equal(sk_contact_sheet(tiles, NULL, 0, NULL, &out, &err), SK_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(err.message, "count"));
    assert_int_equal(sk_contact_sheet(tiles, NULL, 2, NULL, &out, &err), SK_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(err.message, "tiles[1]"));
    d.padding = 5000;
    assert_int_equal(sk_contact_sheet(tiles, NULL, 1, &d, &out, &err), SK_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(err.message, "padding"));
    assert_non_null(strstr(err.message, "1024"));
    d.padding = 0;
    d.columns = -3;
    assert_int_equal(sk_contact_sheet(tiles, NULL, 1, &d, &out, &err), SK_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(err.message, "columns"));
    d.columns = 0;
    d.background = sk_rgba(NAN, 0, 0, 1);
    assert_int_equal(sk_contact_sheet(tiles, NULL, 1, &d, &out, &err), SK_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(err.message, "background"));
    d.background = sk_rgba(0, 0, 0, 0);
    d.tile_filter = (sk_resize_filter)7;
    assert_int_equal(sk_contact_sheet(tiles, NULL, 1, &d, &out, &err), SK_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(err.message, "tile_filter"));
    d.tile_filter = SK_RESIZE_DEFAULT;
    /* 8 columns of 16384-pixel tiles: far over the size limit. */
    const sk_image *many[8] = {&t, &t, &t, &t, &t, &t, &t, &t};
    d.tile_size = 16384;
    d.columns = 8;
    assert_int_equal(sk_contact_sheet(many, NULL, 8, &d, &out, &err), SK_ERROR_LIMIT);
    assert_non_null(strstr(err.message, "contact sheet"));
    assert_null(out.data);
    img_free(&t);
}

/* ---------------------------------------------------------------------- plot */

static void test_nice_ticks(void **state)
{
    (void)state;
    sk_rng rng = sk_rng_make(7, 0, 0, 0);
    for (int k = 0; k < 2000; k++) {
        double lo = sk_rng_range(&rng, -1000, 1000) * pow(10.0, sk_rng_range(&rng, -3, 3));
        double hi = lo + pow(10.0, sk_rng_range(&rng, -3, 7));
        int max_count = 2 + (int)sk_rng_below(&rng, 12);
        sk_ticks t = sk_nice_ticks(lo, hi, max_count);
        assert_true(t.count >= 1 && t.count <= max_count);
        /* step = m x 10^e with m in {1, 2, 5} */
        double e = floor(log10(t.step) + 1e-9);
        double m = t.step / pow(10.0, e);
        assert_true(fabs(m - 1.0) < 1e-6 || fabs(m - 2.0) < 1e-6 || fabs(m - 5.0) < 1e-6);
        for (int i = 0; i < t.count; i++) {
            double v = sk_ticks_value(&t, i);
            assert_true(v >= lo - 1e-9 * t.step && v <= hi + 1e-9 * t.step);
        }
        /* The next finer round step would give too many ticks (the step is the finest). */
        double finer = fabs(m - 1.0) < 1e-6 ? 0.5 * t.step
                                            : (fabs(m - 2.0) < 1e-6 ? 0.5 * t.step : 0.4 * t.step);
        double n_finer = floor(hi / finer + 1e-9) - ceil(lo / finer - 1e-9) + 1.0;
        assert_true(n_finer > max_count);
    }
    sk_ticks t = sk_nice_ticks(0.0, 100.0, 6);
    assert_true(t.step == 20.0 && t.first_index == 0 && t.count == 6);
    char buf[32];
    sk_ticks_format(&t, 5, buf, sizeof buf);
    assert_string_equal(buf, "100");
    t = sk_nice_ticks(-0.3, 0.3, 7);
    assert_true(fabs(t.step - 0.1) < 1e-12 && t.count == 7 && t.decimals == 1);
    sk_ticks_format(&t, 0, buf, sizeof buf);
    assert_string_equal(buf, "-0.3");
    sk_ticks_format(&t, 3, buf, sizeof buf);
    assert_string_equal(buf, "0.0");
    t = sk_nice_ticks(1.5e7, 2.5e7, 3);
    assert_true(t.count == 3 && t.step == 5e6);
    const char *expect[3] = {"1.5e7", "2.0e7", "2.5e7"};
    for (int i = 0; i < 3; i++) {
        sk_ticks_format(&t, i, buf, sizeof buf);
        assert_string_equal(buf, expect[i]);
    }
    t = sk_nice_ticks(-2e-7, 2e-7, 5);
    sk_ticks_format(&t, 0, buf, sizeof buf);
    assert_string_equal(buf, "-2e-7");
    assert_int_equal(sk_nice_ticks(1.0, 1.0, 5).count, 0);
    assert_int_equal(sk_nice_ticks(NAN, 1.0, 5).count, 0);
}

static void test_plot_maps_points(void **state)
{
    (void)state;
    float xs[] = {0.0f, 10.0f}, ys[] = {5.0f, 5.0f};
    float dx[] = {0.0f, 2.0f, 8.0f, 10.0f}, dy[] = {0.0f, 2.0f, 8.0f, 10.0f};
    sk_color red = sk_rgb(1.0f, 0.0f, 0.0f), blue = sk_rgb(0.0f, 0.0f, 1.0f);
    sk_plot_series s[2] = {{"flat", xs, ys, 2, red, 3.0f}, {"diagonal", dx, dy, 4, blue, 3.0f}};
    sk_plot_desc d = {0};
    d.width = 400;
    d.height = 300;
    d.fixed_x = d.fixed_y = true;
    d.x_min = 0.0f;
    d.x_max = 10.0f;
    d.y_min = 0.0f;
    d.y_max = 10.0f;
    d.title = "t";
    d.x_label = "x";
    d.y_label = "y";
    d.legend = SK_LEGEND_NONE;
    sk_plot_layout l;
    sk_error err;
    assert_int_equal(sk_plot_compute_layout(s, 2, &d, &l, &err), SK_OK);
    assert_true(l.x_min == 0.0 && l.x_max == 10.0 && l.y_min == 0.0 && l.y_max == 10.0);
    assert_true(l.frame_x0 > 0 && l.frame_x1 < 400 && l.frame_y0 > 0 && l.frame_y1 < 300);
    sk_vec2f p = sk_plot_map(&l, 3.0, 5.0);
    assert_near(p.y, 0.5 * (l.frame_y0 + l.frame_y1), 1e-3, "mapped y");
    assert_near(p.x, l.frame_x0 + 0.3 * (l.frame_x1 - l.frame_x0), 1e-3, "mapped x");
    sk_image img;
    assert_int_equal(sk_plot_lines(s, 2, &d, &img, &err), SK_OK);
    assert_int_equal(img.width, 400);
    assert_int_equal(img.height, 300);
    const float *c = sk_image_pixel(&img, (int)p.x, (int)p.y);
    assert_near(c[0], 1.0, 1e-3, "flat series red");
    assert_near(c[1], 0.0, 1e-3, "flat series green");
    /* Away from the line by 4 px: background or grid, not red. */
    c = sk_image_pixel(&img, (int)p.x, (int)p.y + 4);
    assert_true(c[1] > 0.5f);
    /* Diagonal series at data (2, 2) and (8, 8). */
    for (int k = 0; k < 2; k++) {
        double v = k ? 8.0 : 2.0;
        sk_vec2f q = sk_plot_map(&l, v, v);
        c = sk_image_pixel(&img, (int)q.x, (int)q.y);
        assert_near(c[2], 1.0, 1e-3, "diagonal series blue");
        assert_near(c[0], 0.0, 1e-3, "diagonal series red");
    }
    free(img.data);
}

static void test_plot_auto_range(void **state)
{
    (void)state;
    enum { N = 300 };
    float x[N], y[N], y2[N];
    for (int i = 0; i < N; i++) {
        x[i] = -3.7f + 0.05f * (float)i;
        y[i] = 17.0f * sinf(0.05f * (float)i) + 3.0f;
        y2[i] = (i == 10) ? NAN : 0.01f * (float)(i * i) - 40.0f;
    }
    sk_plot_series s[3] = {{"a", x, y, N, {0, 0, 0, 0}, 0},
                           {"b", x, y2, N, {0, 0, 0, 0}, 1.0f},
                           {NULL, NULL, y, 50, {0, 0, 0, 0}, 0}};
    sk_plot_layout l;
    assert_int_equal(sk_plot_compute_layout(s, 3, NULL, &l, NULL), SK_OK);
    double xmin = INFINITY, xmax = -INFINITY, ymin = INFINITY, ymax = -INFINITY;
    for (int i = 0; i < N; i++) {
        xmin = fmin(xmin, x[i]);
        xmax = fmax(xmax, fmax(x[i], 49.0));
        ymin = fmin(ymin, fmin(y[i], isnan(y2[i]) ? y[i] : y2[i]));
        ymax = fmax(ymax, fmax(y[i], isnan(y2[i]) ? y[i] : y2[i]));
    }
    assert_true(l.x_min <= xmin && l.x_max >= xmax);
    assert_true(l.y_min < ymin && l.y_max > ymax); /* with a margin */
    /* The auto bounds are round: multiples of the tick step (x) or half step (y). */
    assert_near(remainder(l.x_min, l.x_ticks.step), 0.0, 1e-9, "x bound round");
    assert_near(remainder(l.y_max, 0.5 * l.y_ticks.step), 0.0, 1e-9, "y bound round");
    assert_true(l.x_ticks.count >= 3 && l.y_ticks.count >= 3);
    assert_int_equal(l.width, 800);
    assert_int_equal(l.height, 500);
    sk_image img;
    assert_int_equal(sk_plot_lines(s, 3, NULL, &img, NULL), SK_OK);
    free(img.data);
    /* Empty plots and empty series are fine. */
    assert_int_equal(sk_plot_lines(NULL, 0, NULL, &img, NULL), SK_OK);
    free(img.data);
}

static void test_plot_errors(void **state)
{
    (void)state;
    float v[2] = {1, 2};
    sk_plot_series s = {"s", v, v, 2, {0, 0, 0, 0}, 0};
    sk_plot_desc d = {0};
    sk_image out = {0};
    sk_error err;
    d.width = 10;
    assert_int_equal(sk_plot_lines(&s, 1, &d, &out, &err), SK_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(err.message, "width = 10"));
    d.width = 100000;
    assert_int_equal(sk_plot_lines(&s, 1, &d, &out, &err), SK_ERROR_LIMIT);
    assert_non_null(strstr(err.message, "width"));
    d.width = 0;
    d.fixed_x = true;
    d.x_min = 3;
    d.x_max = 1;
    assert_int_equal(sk_plot_lines(&s, 1, &d, &out, &err), SK_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(err.message, "x_min"));
    d.x_max = NAN;
    assert_int_equal(sk_plot_lines(&s, 1, &d, &out, &err), SK_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(err.message, "x_max"));
    d.fixed_x = false;
    s.count = -1;
    assert_int_equal(sk_plot_lines(&s, 1, &d, &out, &err), SK_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(err.message, "series[0].count"));
    s.count = 2;
    s.width = NAN;
    assert_int_equal(sk_plot_lines(&s, 1, &d, &out, &err), SK_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(err.message, "series[0].width"));
    s.width = 0;
    d.text_scale = 16;
    d.width = 64;
    d.height = 64;
    assert_int_equal(sk_plot_lines(&s, 1, &d, &out, &err), SK_ERROR_LIMIT);
    assert_non_null(strstr(err.message, "text_scale"));
    assert_int_equal(sk_plot_lines(&s, -1, NULL, &out, &err), SK_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(err.message, "series_count"));
    assert_null(out.data);
}

static void test_palette(void **state)
{
    (void)state;
    for (int i = 0; i < SK_PALETTE_SIZE; i++) {
        sk_color a = sk_palette(i);
        assert_true(a.a == 1.0f);
        for (int j = i + 1; j < SK_PALETTE_SIZE; j++) {
            sk_color b = sk_palette(j);
            double d = fabs(a.r - b.r) + fabs(a.g - b.g) + fabs(a.b - b.b);
            assert_true(d > 0.2);
        }
    }
    sk_color w = sk_palette(-1), e = sk_palette(SK_PALETTE_SIZE - 1);
    assert_true(w.r == e.r && w.g == e.g && w.b == e.b);
    sk_color w2 = sk_palette(SK_PALETTE_SIZE + 2), e2 = sk_palette(2);
    assert_true(w2.r == e2.r && w2.g == e2.g && w2.b == e2.b);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_rect_integer_bounds_exact),
        cmocka_unit_test(test_rect_half_pixel_edges),
        cmocka_unit_test(test_line_coverage_matches_area),
        cmocka_unit_test(test_line_cross_section_far_from_ends),
        cmocka_unit_test(test_polyline_composites_once),
        cmocka_unit_test(test_disc_and_ring_areas),
        cmocka_unit_test(test_polygon_areas),
        cmocka_unit_test(test_fill_rules_and_holes),
        cmocka_unit_test(test_alpha_compositing),
        cmocka_unit_test(test_clipping_and_nan),
        cmocka_unit_test(test_text_metrics_match_ink),
        cmocka_unit_test(test_glyphs_present_and_distinct),
        cmocka_unit_test(test_text_rotated_and_fit),
        cmocka_unit_test(test_blit_conversions),
        cmocka_unit_test(test_resize_constant_and_box_mean),
        cmocka_unit_test(test_resize_errors_and_threads),
        cmocka_unit_test(test_contact_sheet_layout),
        cmocka_unit_test(test_contact_sheet_tile_border),
        cmocka_unit_test(test_contact_sheet_errors),
        cmocka_unit_test(test_nice_ticks),
        cmocka_unit_test(test_plot_maps_points),
        cmocka_unit_test(test_plot_auto_range),
        cmocka_unit_test(test_plot_errors),
        cmocka_unit_test(test_palette),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
