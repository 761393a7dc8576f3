/* Tests of the skin model (Ishii et al. 1991): cells tile every level, perturbed edges are
 * shared, children lie in their parents, the section profile's end values, normals as the
 * derivative of height, roundness, seamless wrap, regions, thread independence, errors. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "shitsukan/image.h"
#include "shitsukan/preset.h"
#include "shitsukan/skin.h"
#include "models/skin/skin_internal.h"
#include "test_support.h"

static bool sanitized(void) { return getenv("SK_TEST_SANITIZED") != NULL; }

/* Fig. 19a-like skin on a small tile, 3 levels, perturbed. */
static sk_skin_desc desc_19a(float size_mm)
{
    sk_skin_desc d = {0};
    d.seed = 7;
    d.size_mm[0] = size_mm;
    d.size_mm[1] = size_mm * 0.8f;
    d.level_count = 3;
    static const float prof[3][4][2] = {{{0, 4}, {5, 4}, {9, 3}, {10, 0}},
                                        {{0, 2}, {5, 2}, {9, 1.5f}, {10, 0}},
                                        {{0, 0.8f}, {5, 0.8f}, {9, 0.4f}, {10, 0}}};
    float spacing[3] = {0.8f, 0.32f, 0.13f};
    for (int k = 0; k < 3; k++) {
        sk_skin_level *lv = &d.levels[k];
        lv->jitter_rate = 0.5f;
        lv->spacing_mm = spacing[k];
        lv->perturb_rate = 0.1f;
        lv->perturb_decay = 1.0f;
        lv->segment_count = 1;
        memcpy(lv->segments[0].points, prof[k], sizeof prof[k]);
        lv->roundness = 0.2f;
    }
    return d;
}

static sk_skin *make(const sk_skin_desc *d)
{
    sk_skin *skin = NULL;
    sk_error err = {0};
    sk_result r = sk_skin_create(&skin, d, &err);
    if (r != SK_OK) fail_msg("sk_skin_create: %s", err.message);
    return skin;
}

static double polygon_area(const sk_vec2d *p, size_t n)
{
    double a = 0;
    for (size_t i = 0; i < n; i++) {
        size_t j = (i + 1) % n;
        a += p[i].x * p[j].y - p[j].x * p[i].y;
    }
    return 0.5 * a;
}

/* Winding number of the closed polyline around q. */
static int winding(const sk_vec2d *p, size_t n, double qx, double qy)
{
    int w = 0;
    for (size_t i = 0; i < n; i++) {
        const sk_vec2d *a = &p[i], *b = &p[(i + 1) % n];
        double c = (b->x - a->x) * (qy - a->y) - (qx - a->x) * (b->y - a->y);
        if (a->y <= qy) {
            if (b->y > qy && c > 0) w++;
        } else if (b->y <= qy && c < 0) {
            w--;
        }
    }
    return w;
}

static double polyline_distance(const sk_vec2d *p, size_t n, double qx, double qy)
{
    double best = INFINITY;
    for (size_t i = 0; i < n; i++) {
        const sk_vec2d *a = &p[i], *b = &p[(i + 1) % n];
        double ex = b->x - a->x, ey = b->y - a->y, wx = qx - a->x, wy = qy - a->y;
        double l2 = ex * ex + ey * ey, t = l2 > 0 ? (wx * ex + wy * ey) / l2 : 0;
        t = t < 0 ? 0 : (t > 1 ? 1 : t);
        double dx = wx - t * ex, dy = wy - t * ey;
        best = fmin(best, sqrt(dx * dx + dy * dy));
    }
    return best;
}

typedef struct outlines {
    uint32_t count;
    size_t *start, *len;
    sk_vec2d *pts;
} outlines;

static outlines get_outlines(const sk_skin *skin, int level, int subdivide)
{
    outlines o;
    o.count = sk_skin_cell_count(skin, level);
    o.start = malloc(sizeof(size_t) * o.count);
    o.len = malloc(sizeof(size_t) * o.count);
    size_t total = 0;
    for (uint32_t c = 0; c < o.count; c++) {
        o.len[c] = sk_skin_cell_outline(skin, level, c, subdivide, NULL, 0);
        o.start[c] = total;
        total += o.len[c];
    }
    o.pts = malloc(sizeof(sk_vec2d) * (total ? total : 1));
    for (uint32_t c = 0; c < o.count; c++)
        assert_int_equal(
            sk_skin_cell_outline(skin, level, c, subdivide, o.pts + o.start[c], o.len[c]),
            o.len[c]);
    return o;
}

static void free_outlines(outlines *o)
{
    free(o->start);
    free(o->len);
    free(o->pts);
}

/* Cells of every level tile the tile: areas sum to its area, every cell is positively
 * oriented, and each sample point lies in exactly one cell (the one the query reports). */
static void test_cells_tile(void **state)
{
    (void)state;
    sk_skin_desc d = desc_19a(3.2f);
    sk_skin *skin = make(&d);
    double w, h;
    sk_skin_tile_size(skin, &w, &h);
    int samples = sanitized() ? 40 : 150;
    for (int level = 1; level <= 3; level++) {
        outlines o = get_outlines(skin, level, 2);
        double sum = 0;
        for (uint32_t c = 0; c < o.count; c++) {
            double a = polygon_area(o.pts + o.start[c], o.len[c]);
            if (!(a > 0)) fail_msg("level %d cell %u has area %g", level, c, a);
            sum += a;
        }
        if (fabs(sum - w * h) > 1e-6 * w * h)
            fail_msg("level %d: cell areas sum to %.9f, the tile is %.9f", level, sum, w * h);
        sk_rng rng = sk_rng_make(11, (uint64_t)level, 0, 0);
        int tested = 0;
        for (int s = 0; s < samples; s++) {
            double x = sk_rng_uniform(&rng) * w, y = sk_rng_uniform(&rng) * h;
            int hits = 0;
            uint32_t hit = UINT32_MAX;
            bool near = false;
            for (uint32_t c = 0; c < o.count && !near; c++)
                for (int my = -1; my <= 1; my++)
                    for (int mx = -1; mx <= 1; mx++) {
                        double qx = x + mx * w, qy = y + my * h;
                        const sk_vec2d *p = o.pts + o.start[c];
                        if (polyline_distance(p, o.len[c], qx, qy) < 1e-6) near = true;
                        if (winding(p, o.len[c], qx, qy) != 0) hits++, hit = c;
                    }
            if (near) continue;
            tested++;
            if (hits != 1) fail_msg("level %d: point (%g, %g) lies in %d cells", level, x, y, hits);
            sk_skin_sample smp;
            sk_skin_query(skin, x, y, 0, &smp);
            if (smp.cell[level - 1] != hit)
                fail_msg("level %d: query says cell %u, geometry says %u at (%g, %g)", level,
                         smp.cell[level - 1], hit, x, y);
        }
        assert_true(tested > samples / 2);
        free_outlines(&o);
    }
    sk_skin_destroy(skin);
}

/* Without perturbation or stretch the containing cell is the nearest centre point (among
 * all points at level 1, among the siblings below). */
static void test_nearest_centre(void **state)
{
    (void)state;
    sk_skin_desc d = desc_19a(3.2f);
    for (int k = 0; k < 3; k++) d.levels[k].perturb_rate = 0;
    sk_skin *skin = make(&d);
    double w, h;
    sk_skin_tile_size(skin, &w, &h);
    sk_rng rng = sk_rng_make(5, 0, 0, 0);
    for (int s = 0; s < 400; s++) {
        double x = sk_rng_uniform(&rng) * w, y = sk_rng_uniform(&rng) * h;
        sk_skin_sample smp;
        sk_skin_query(skin, x, y, 0, &smp);
        for (int level = 1; level <= 3; level++) {
            uint32_t first = 0, count = sk_skin_cell_count(skin, level);
            if (level > 1) {
                sk_skin_cell_info pi;
                assert_int_equal(
                    sk_skin_cell_info_get(skin, level - 1, smp.cell[level - 2], &pi, NULL), SK_OK);
                first = pi.first_child, count = pi.child_count;
            }
            double best = INFINITY, second = INFINITY;
            uint32_t arg = UINT32_MAX;
            for (uint32_t c = first; c < first + count; c++) {
                sk_skin_cell_info ci;
                sk_skin_cell_info_get(skin, level, c, &ci, NULL);
                for (int my = -1; my <= 1; my++)
                    for (int mx = -1; mx <= 1; mx++) {
                        double dx = ci.site.x + mx * w - x, dy = ci.site.y + my * h - y;
                        double d2 = dx * dx + dy * dy;
                        if (d2 < best)
                            second = best, best = d2, arg = c;
                        else if (d2 < second)
                            second = d2;
                    }
            }
            if (sqrt(second) - sqrt(best) < 1e-6) continue; /* on a bisector */
            if (arg != smp.cell[level - 1])
                fail_msg("level %d at (%g, %g): cell %u, nearest centre %u", level, x, y,
                         smp.cell[level - 1], arg);
        }
    }
    sk_skin_destroy(skin);
}

/* Every perturbed edge is the same chain of points seen from both of its cells. */
static void test_shared_edges(void **state)
{
    (void)state;
    sk_skin_desc d = desc_19a(3.2f);
    sk_skin *skin = make(&d);
    sk_vec2d a[4096], b[4096];
    int compared = 0;
    for (int level = 1; level <= 3; level++) {
        uint32_t n = sk_skin_cell_count(skin, level);
        for (uint32_t c = 0; c < n; c += (level == 3 ? 7 : 1)) {
            sk_skin_cell_info ci;
            sk_skin_cell_info_get(skin, level, c, &ci, NULL);
            for (uint32_t e = 0; e < ci.edge_count; e++) {
                uint32_t nb;
                size_t na = sk_skin_cell_edge(skin, level, c, e, 2, &nb, a, 4096);
                if (nb == UINT32_MAX) continue;
                sk_skin_cell_info ni;
                sk_skin_cell_info_get(skin, level, nb, &ni, NULL);
                bool found = false;
                for (uint32_t f = 0; f < ni.edge_count && !found; f++) {
                    uint32_t back;
                    size_t nbp = sk_skin_cell_edge(skin, level, nb, f, 2, &back, b, 4096);
                    if (back != c || nbp != na) continue;
                    /* b runs the other way: a[i] == b[na - i] (b[na] = next edge start) */
                    double dx = 0, dy = 0;
                    /* compare after removing the tile shift between the two frames */
                    double ox = a[1].x - b[na - 1].x, oy = a[1].y - b[na - 1].y;
                    ox = round(ox / d.size_mm[0]) * d.size_mm[0];
                    oy = round(oy / d.size_mm[1]) * d.size_mm[1];
                    double worst = 0;
                    for (size_t i = 1; i < na; i++) {
                        dx = a[i].x - b[na - i].x - ox, dy = a[i].y - b[na - i].y - oy;
                        worst = fmax(worst, hypot(dx, dy));
                    }
                    if (worst < 1e-5) found = true;
                }
                if (!found)
                    fail_msg("level %d: edge %u of cell %u differs from cell %u's", level, e, c,
                             nb);
                compared++;
            }
        }
    }
    if (compared < 500) fail_msg("only %d edges compared", compared);
    sk_skin_destroy(skin);
}

/* Every child lies in its parent (its perturbed outline, carried by the parent's
 * perturbation, stays inside or on the parent's outline). */
static void test_children_in_parent(void **state)
{
    (void)state;
    sk_skin_desc d = desc_19a(3.2f);
    sk_skin *skin = make(&d);
    int checked = 0;
    for (int level = 2; level <= 3; level++) {
        outlines parents = get_outlines(skin, level - 1, 8);
        outlines kids = get_outlines(skin, level, 2);
        for (uint32_t c = 0; c < kids.count; c += (level == 3 ? 5 : 1)) {
            sk_skin_cell_info ci;
            sk_skin_cell_info_get(skin, level, c, &ci, NULL);
            const sk_vec2d *pp = parents.pts + parents.start[ci.parent];
            size_t pn = parents.len[ci.parent];
            for (size_t i = 0; i < kids.len[c]; i++) {
                const sk_vec2d *q = kids.pts + kids.start[c] + i;
                if (winding(pp, pn, q->x, q->y) == 0 &&
                    polyline_distance(pp, pn, q->x, q->y) > 1e-5)
                    fail_msg("level %d cell %u point (%g, %g) is %g mm outside parent %u", level, c,
                             q->x, q->y, polyline_distance(pp, pn, q->x, q->y), ci.parent);
                checked++;
            }
        }
        free_outlines(&parents);
        free_outlines(&kids);
    }
    assert_true(checked > 1000);
    sk_skin_destroy(skin);
}

/* Height is the first control point's at the centre and the last one's on the boundary. */
static void test_profile_ends(void **state)
{
    (void)state;
    for (int perturbed = 0; perturbed <= 1; perturbed++) {
        sk_skin_desc d = desc_19a(3.2f);
        d.level_count = 1;
        d.levels[0].perturb_rate = perturbed ? 0.15f : 0.0f;
        static const float prof[2][4][2] = {{{0, 3}, {2, 3}, {4, 3}, {7, 3}},
                                            {{7, 3}, {8, 3}, {9, 2.5f}, {10, -1.0f}}};
        d.levels[0].segment_count = 2;
        memcpy(d.levels[0].segments, prof, sizeof prof);
        sk_skin *skin = make(&d);
        float scale = d.levels[0].spacing_mm / 20.0f;
        sk_vec2d pts[4096];
        for (uint32_t c = 0; c < sk_skin_cell_count(skin, 1); c++) {
            sk_skin_cell_info ci;
            sk_skin_cell_info_get(skin, 1, c, &ci, NULL);
            float hgt;
            sk_skin_eval(skin, ci.centre.x, ci.centre.y, &hgt, NULL);
            assert_float_equal(hgt, 3.0f * scale, 1e-5);
            size_t n = sk_skin_cell_outline(skin, 1, c, 3, pts, 4096);
            for (size_t i = 0; i < n; i++) {
                sk_skin_eval(skin, pts[i].x, pts[i].y, &hgt, NULL);
                if (fabsf(hgt - (-1.0f * scale)) > 2e-4f * scale)
                    fail_msg("cell %u boundary point %zu: height %g, expected %g", c, i, hgt,
                             -scale);
            }
        }
        sk_skin_destroy(skin);
    }
}

/* The normal is the normal of the height field: compare with finite differences. */
static void test_normal_is_gradient(void **state)
{
    (void)state;
    sk_skin_desc d = desc_19a(3.2f);
    d.pores.hair.depth_mm = 0.02f;
    d.pores.sweat.depth_mm = 0.01f;
    sk_skin *skin = make(&d);
    double w, h;
    sk_skin_tile_size(skin, &w, &h);
    sk_rng rng = sk_rng_make(3, 0, 0, 0);
    int n = 2000, good = 0;
    double step = 2e-5;
    for (int s = 0; s < n; s++) {
        double x = sk_rng_uniform(&rng) * w, y = sk_rng_uniform(&rng) * h;
        float h0, hx1, hx0, hy1, hy0;
        sk_vec3f nrm;
        sk_skin_eval(skin, x, y, &h0, &nrm);
        sk_skin_eval(skin, x + step, y, &hx1, NULL);
        sk_skin_eval(skin, x - step, y, &hx0, NULL);
        sk_skin_eval(skin, x, y + step, &hy1, NULL);
        sk_skin_eval(skin, x, y - step, &hy0, NULL);
        double gx = (hx1 - hx0) / (2 * step), gy = (hy1 - hy0) / (2 * step);
        double inv = 1.0 / sqrt(gx * gx + gy * gy + 1);
        double ex = -gx * inv - nrm.x, ey = -gy * inv - nrm.y, ez = inv - nrm.z;
        if (sqrt(ex * ex + ey * ey + ez * ez) < 0.01) good++;
    }
    /* kinks (furrow lines, polyline corners) are a set of measure zero; float steps leave
       a little noise */
    if (good < n * 97 / 100)
        fail_msg("normal matches the height's gradient at %d of %d points", good, n);
    sk_skin_destroy(skin);
}

/* normal_model profile (the paper's Fig. 7): each level's slope is its profile's along the
 * ray from the cell centre, so the normal leans along that ray, by the derivative of the
 * height along it. */
static void test_profile_normal(void **state)
{
    (void)state;
    sk_skin_desc d = desc_19a(3.2f);
    d.level_count = 1;
    d.levels[0].perturb_rate = 0;
    d.normal_model = SK_SKIN_NORMAL_PROFILE;
    sk_skin *skin = make(&d);
    double w, h;
    sk_skin_tile_size(skin, &w, &h);
    sk_rng rng = sk_rng_make(5, 0, 0, 0);
    int n = 1000, good = 0, leaning = 0;
    double step = 2e-5;
    for (int s = 0; s < n; s++) {
        double x = sk_rng_uniform(&rng) * w, y = sk_rng_uniform(&rng) * h;
        sk_skin_sample smp;
        sk_skin_query(skin, x, y, 0, &smp);
        sk_skin_cell_info ci;
        assert_int_equal(sk_skin_cell_info_get(skin, 1, smp.cell[0], &ci, NULL), SK_OK);
        double rx = x - ci.centre.x, ry = y - ci.centre.y;
        rx -= w * round(rx / w), ry -= h * round(ry / h);
        double r = sqrt(rx * rx + ry * ry);
        if (r < 1e-3) continue;
        double ux = rx / r, uy = ry / r;
        float h1, h0;
        sk_skin_eval(skin, x + step * ux, y + step * uy, &h1, NULL);
        sk_skin_eval(skin, x - step * ux, y - step * uy, &h0, NULL);
        double slope = (h1 - h0) / (2 * step);
        /* the horizontal part of N = (-g, 1) / |.| with g = slope * u */
        double gx = -smp.normal.x / smp.normal.z, gy = -smp.normal.y / smp.normal.z;
        double across = fabs(gx * uy - gy * ux), along = gx * ux + gy * uy;
        if (across < 1e-4 && fabs(along - slope) < 1e-3 * (1 + fabs(slope))) good++;
        leaning += along < -0.01; /* downhill away from the centre on the slopes */
    }
    if (good < n * 97 / 100) fail_msg("profile normal along the ray at %d of %d points", good, n);
    assert_true(leaning > n / 10);
    /* a stretched level takes the ray before the stretch: the slope along the stretched
       ray is still the height's, the normal leans across it towards the long sides */
    sk_skin_desc ds = d;
    ds.levels[0].stretch[0] = 3, ds.levels[0].stretch[1] = 1;
    ds.size_mm[0] = 9.6f;
    sk_skin *st = make(&ds);
    int along_ok = 0, across = 0, tried = 0;
    for (int s = 0; s < 400; s++) {
        double x = sk_rng_uniform(&rng) * 9.6, y = sk_rng_uniform(&rng) * h;
        sk_skin_sample smp;
        sk_skin_query(st, x, y, 0, &smp);
        sk_skin_cell_info ci;
        sk_skin_cell_info_get(st, 1, smp.cell[0], &ci, NULL);
        double rx = x - ci.centre.x, ry = y - ci.centre.y;
        rx -= 9.6 * round(rx / 9.6), ry -= h * round(ry / h);
        double r = sqrt(rx * rx + ry * ry);
        if (r < 1e-3) continue;
        double ux = rx / r, uy = ry / r;
        float h1, h0;
        sk_skin_eval(st, x + step * ux, y + step * uy, &h1, NULL);
        sk_skin_eval(st, x - step * ux, y - step * uy, &h0, NULL);
        double slope = (h1 - h0) / (2 * step);
        double gx = -smp.normal.x / smp.normal.z, gy = -smp.normal.y / smp.normal.z;
        tried++;
        /* float heights leave the finite difference a few 1e-3 of noise */
        along_ok += fabs(gx * ux + gy * uy - slope) < 5e-3 * (1 + fabs(slope));
        across += fabs(gx * uy - gy * ux) > 1e-3;
    }
    if (along_ok < tried * 97 / 100)
        fail_msg("stretched: slope along the ray right at %d of %d points", along_ok, tried);
    assert_true(across > tried / 10);
    sk_skin_destroy(st);
    /* the gradient model differs from it where D(phi) changes with the angle */
    d.normal_model = SK_SKIN_NORMAL_GRADIENT;
    sk_skin *grad = make(&d);
    int differ = 0;
    for (int s = 0; s < 200; s++) {
        double x = sk_rng_uniform(&rng) * w, y = sk_rng_uniform(&rng) * h;
        sk_vec3f a, b;
        sk_skin_eval(skin, x, y, NULL, &a);
        sk_skin_eval(grad, x, y, NULL, &b);
        differ += fabsf(a.x - b.x) + fabsf(a.y - b.y) > 1e-3f;
    }
    assert_true(differ > 20);
    sk_skin_destroy(grad);
    sk_skin_destroy(skin);
}

/* Spread of the radius of the contour through the middle of the slope, around a centre. */
static double contour_spread(const sk_skin *skin, uint32_t cell)
{
    sk_skin_cell_info ci;
    sk_skin_cell_info_get(skin, 1, cell, &ci, NULL);
    float top, target;
    sk_skin_eval(skin, ci.centre.x, ci.centre.y, &top, NULL);
    target = 0.75f * top; /* inside the first segment, which roundness scales */
    double rmin = INFINITY, rmax = 0;
    for (int a = 0; a < 180; a++) {
        double th = 2 * SK_PI * a / 180, lo = 0, hi = 0;
        /* march out to the first point below the target, then bisect */
        for (double r = 0.005; r < 1.0; r += 0.005) {
            float v;
            sk_skin_eval(skin, ci.centre.x + r * cos(th), ci.centre.y + r * sin(th), &v, NULL);
            if (v < target) {
                hi = r;
                break;
            }
            lo = r;
        }
        for (int it = 0; it < 30; it++) {
            double mid = 0.5 * (lo + hi);
            float v;
            sk_skin_eval(skin, ci.centre.x + mid * cos(th), ci.centre.y + mid * sin(th), &v, NULL);
            if (v < target)
                hi = mid;
            else
                lo = mid;
        }
        rmin = fmin(rmin, lo), rmax = fmax(rmax, lo);
    }
    return (rmax - rmin) / (0.5 * (rmax + rmin));
}

static void test_roundness(void **state)
{
    (void)state;
    double spread[2];
    for (int i = 0; i < 2; i++) {
        sk_skin_desc d = {0};
        /* a tile that holds whole rows of a regular triangular lattice */
        d.size_mm[0] = 4.0f;
        d.size_mm[1] = 6 * 0.8f * 0.8660254f;
        d.level_count = 1;
        d.levels[0].spacing_mm = 0.8f;
        d.levels[0].roundness = (float)i;
        static const float prof[2][4][2] = {{{0, 4}, {2, 4}, {4, 3}, {7, 2}},
                                            {{7, 2}, {8, 2}, {9, 1.5f}, {10, 0}}};
        d.levels[0].segment_count = 2;
        memcpy(d.levels[0].segments, prof, sizeof prof);
        sk_skin *skin = make(&d);
        spread[i] = contour_spread(skin, 3);
        sk_skin_destroy(skin);
    }
    /* a regular hexagon's similar contour spreads by 1 - cos 30 deg = 0.134 */
    if (!(spread[0] > 0.10))
        fail_msg("roundness 0: contour spread %g, expected about 0.13", spread[0]);
    if (!(spread[1] < 0.02)) fail_msg("roundness 1: contour spread %g, expected < 0.02", spread[1]);
}

static void render_all(const sk_skin *skin, int w, int h, const int region[4], float *height,
                       float *normal, float *furrow, uint32_t *ids, float *preview)
{
    sk_skin_render_desc r = {0};
    r.width = w, r.height = h;
    if (region) memcpy(r.region, region, sizeof r.region);
    r.height_mm = height, r.normal = normal, r.furrow = furrow, r.cell_id = ids,
    r.preview = preview;
    sk_error err = {0};
    if (sk_skin_render(skin, &r, &err) != SK_OK) fail_msg("render: %s", err.message);
}

/* The map tiles: the skin repeats with the tile, and the step across the wrap is no
 * larger than the steps inside. */
static void test_seamless(void **state)
{
    (void)state;
    sk_skin_desc d = desc_19a(3.2f);
    sk_skin *skin = make(&d);
    double w, h;
    sk_skin_tile_size(skin, &w, &h);
    sk_rng rng = sk_rng_make(9, 0, 0, 0);
    for (int s = 0; s < 300; s++) {
        double x = sk_rng_uniform(&rng) * w, y = sk_rng_uniform(&rng) * h;
        float a, b, c;
        sk_skin_eval(skin, x, y, &a, NULL);
        sk_skin_eval(skin, x + w, y - 2 * h, &b, NULL);
        sk_skin_eval(skin, x - 3 * w, y + h, &c, NULL);
        assert_float_equal(a, b, 1e-5);
        assert_float_equal(a, c, 1e-5);
    }
    int W = 128, H = 96;
    float *hm = malloc(sizeof(float) * W * H);
    render_all(skin, W, H, NULL, hm, NULL, NULL, NULL, NULL);
    double inner = 0, wrap = 0;
    for (int y = 0; y < H; y++) {
        for (int x = 0; x + 1 < W; x++) inner += fabs(hm[y * W + x + 1] - hm[y * W + x]);
        wrap += fabs(hm[y * W] - hm[y * W + W - 1]);
    }
    inner /= (W - 1);
    /* the wrap column pair is one more pair of neighbours: about the mean step */
    if (!(wrap < 2.0 * inner)) fail_msg("step across the wrap %g vs %g inside", wrap, inner);
    double innery = 0, wrapy = 0;
    for (int x = 0; x < W; x++) {
        for (int y = 0; y + 1 < H; y++) innery += fabs(hm[(y + 1) * W + x] - hm[y * W + x]);
        wrapy += fabs(hm[x] - hm[(H - 1) * W + x]);
    }
    innery /= (H - 1);
    if (!(wrapy < 2.0 * innery))
        fail_msg("vertical step across the wrap %g vs %g inside", wrapy, innery);
    free(hm);
    sk_skin_destroy(skin);
}

/* An aperiodic skin does not wrap inside its tile: the far edge is new ground. */
static void test_aperiodic(void **state)
{
    (void)state;
    sk_skin_desc d = desc_19a(3.2f);
    d.aperiodic = true;
    sk_skin *skin = make(&d);
    double w, h;
    sk_skin_tile_size(skin, &w, &h);
    assert_float_equal(w, 3.2, 1e-6);
    int differ = 0;
    for (int i = 0; i < 50; i++) {
        double y = (i + 0.5) * h / 50;
        sk_skin_sample a, b;
        sk_skin_query(skin, 0.05, y, 0, &a);
        sk_skin_query(skin, w + 0.05, y, 0, &b);
        differ += a.cell[0] != b.cell[0];
    }
    assert_true(differ > 40);
    sk_skin_destroy(skin);
}

/* A region renders the same bytes as the same pixels of the whole map, and any thread
 * count gives the same bytes. */
static void test_region_and_threads(void **state)
{
    (void)state;
    sk_skin_desc d = desc_19a(3.2f);
    d.pores.hair.depth_mm = 0.01f;
    sk_skin *skin = make(&d);
    int W = 96, H = 80, reg[4] = {13, 9, 40, 50};
    size_t n = (size_t)W * H, rn = (size_t)reg[2] * reg[3];
    float *h1 = malloc(sizeof(float) * n), *n1 = malloc(sizeof(float) * 3 * n),
          *f1 = malloc(sizeof(float) * n), *p1 = malloc(sizeof(float) * 3 * n);
    uint32_t *i1 = malloc(sizeof(uint32_t) * n);
    float *h2 = malloc(sizeof(float) * n), *n2 = malloc(sizeof(float) * 3 * n),
          *f2 = malloc(sizeof(float) * n), *p2 = malloc(sizeof(float) * 3 * n);
    uint32_t *i2 = malloc(sizeof(uint32_t) * n);
    sk_threads_set(1);
    render_all(skin, W, H, NULL, h1, n1, f1, i1, p1);
    sk_threads_set(2);
    render_all(skin, W, H, NULL, h2, n2, f2, i2, p2);
    assert_memory_equal(h1, h2, sizeof(float) * n);
    assert_memory_equal(n1, n2, sizeof(float) * 3 * n);
    assert_memory_equal(f1, f2, sizeof(float) * n);
    assert_memory_equal(i1, i2, sizeof(uint32_t) * n);
    assert_memory_equal(p1, p2, sizeof(float) * 3 * n);
    render_all(skin, W, H, reg, h2, n2, f2, i2, p2);
    for (int y = 0; y < reg[3]; y++) {
        size_t full = (size_t)(reg[1] + y) * W + reg[0], part = (size_t)y * reg[2];
        assert_memory_equal(h1 + full, h2 + part, sizeof(float) * reg[2]);
        assert_memory_equal(n1 + 3 * full, n2 + 3 * part, sizeof(float) * 3 * reg[2]);
        assert_memory_equal(f1 + full, f2 + part, sizeof(float) * reg[2]);
        assert_memory_equal(i1 + full, i2 + part, sizeof(uint32_t) * reg[2]);
        assert_memory_equal(p1 + 3 * full, p2 + 3 * part, sizeof(float) * 3 * reg[2]);
    }
    (void)rn;
    sk_threads_set(0);
    free(h1), free(n1), free(f1), free(p1), free(i1);
    free(h2), free(n2), free(f2), free(p2), free(i2);
    sk_skin_destroy(skin);
}

/* A render of only cell ids and furrow distances walks down only to the deepest level
 * they name and evaluates no relief: its values are those of a render of every map, for
 * each level asked of (and the other outputs untouched). */
static void test_cells_and_furrows_only(void **state)
{
    (void)state;
    sk_skin_desc d = desc_19a(3.2f);
    d.pores.hair.depth_mm = 0.01f;
    sk_skin *skin = make(&d);
    enum { W = 64, H = 52, N = W * H };
    static float height[N], normal[3 * N], furrow[N], furrow_only[N];
    static uint32_t ids[N], ids_only[N];
    sk_error err = {0};
    for (int furrow_level = 1; furrow_level <= 3; furrow_level++)
        for (int id_level = 1; id_level <= 3; id_level++) {
            sk_skin_render_desc all = {.width = W,
                                       .height = H,
                                       .height_mm = height,
                                       .normal = normal,
                                       .furrow = furrow,
                                       .cell_id = ids,
                                       .furrow_level = furrow_level,
                                       .id_level = id_level};
            assert_int_equal(sk_skin_render(skin, &all, &err), SK_OK);
            sk_skin_render_desc some = {.width = W,
                                        .height = H,
                                        .furrow = furrow_only,
                                        .cell_id = ids_only,
                                        .furrow_level = furrow_level,
                                        .id_level = id_level};
            assert_int_equal(sk_skin_render(skin, &some, &err), SK_OK);
            assert_memory_equal(furrow, furrow_only, sizeof furrow);
            assert_memory_equal(ids, ids_only, sizeof ids);
            /* one output alone too */
            memset(ids_only, 0, sizeof ids_only);
            sk_skin_render_desc one = {
                .width = W, .height = H, .cell_id = ids_only, .id_level = id_level};
            assert_int_equal(sk_skin_render(skin, &one, &err), SK_OK);
            assert_memory_equal(ids, ids_only, sizeof ids);
        }
    /* the level-1 cells differ from pixel to pixel: not a flat answer */
    int changes = 0;
    for (int i = 1; i < N; i++) changes += ids[i] != ids[i - 1];
    assert_true(changes > 20);
    sk_skin_destroy(skin);
}

/* Level-1 furrow distance is the true distance to the cell's perturbed outline. */
static void test_furrow_distance(void **state)
{
    (void)state;
    sk_skin_desc d = desc_19a(3.2f);
    sk_skin *skin = make(&d);
    double w, h;
    sk_skin_tile_size(skin, &w, &h);
    outlines o = get_outlines(skin, 1, 1);
    sk_rng rng = sk_rng_make(21, 0, 0, 0);
    for (int s = 0; s < 300; s++) {
        double x = sk_rng_uniform(&rng) * w, y = sk_rng_uniform(&rng) * h;
        sk_skin_sample smp;
        sk_skin_query(skin, x, y, SK_SKIN_QUERY_FURROW, &smp);
        uint32_t c = smp.cell[0];
        double best = INFINITY;
        for (int my = -1; my <= 1; my++)
            for (int mx = -1; mx <= 1; mx++)
                best = fmin(
                    best, polyline_distance(o.pts + o.start[c], o.len[c], x + mx * w, y + my * h));
        assert_float_equal(smp.furrow_mm[0], best, 1e-5);
    }
    free_outlines(&o);
    sk_skin_destroy(skin);
}

static void expect_error(const sk_skin_desc *d, const char *needle)
{
    sk_error err = {0};
    sk_skin *skin = NULL;
    sk_result r = sk_skin_create(&skin, d, &err);
    assert_int_equal(r, SK_ERROR_INVALID_ARGUMENT);
    assert_null(skin);
    if (!strstr(err.message, needle)) fail_msg("message \"%s\" lacks \"%s\"", err.message, needle);
}

static void test_bad_parameters(void **state)
{
    (void)state;
    sk_skin_desc d = desc_19a(3.2f);
    d.level_count = -1;
    expect_error(&d, "level_count = -1 is out of range [0, 6]");
    d = desc_19a(3.2f);
    d.levels[1].spacing_mm = -0.5f;
    expect_error(&d, "levels[1].spacing_mm = -0.5 is out of range [0, 1000]");
    d = desc_19a(3.2f);
    d.levels[0].segments[0].points[2][0] = 3.0f;
    expect_error(&d,
                 "levels[0].profile[0].points[2][0] = 3 is less than the previous point's x = 5");
    d = desc_19a(3.2f);
    d.levels[2].jitter_rate = NAN;
    expect_error(&d, "levels[2].jitter_rate is not a finite number");
    d = desc_19a(3.2f);
    d.levels[0].segments[0].points[3][0] = 9.0f;
    expect_error(&d, "must end at x = 10");
    d = desc_19a(3.2f);
    d.size_mm[0] = 2000;
    expect_error(&d, "size_mm[0] = 2000 is out of range");
    /* too many cells: a clear limit error, nothing allocated at absurd sizes */
    d = desc_19a(3.2f);
    d.size_mm[0] = d.size_mm[1] = 1000;
    d.levels[2].spacing_mm = 0.001f;
    sk_error err = {0};
    sk_skin *skin = NULL;
    assert_int_equal(sk_skin_create(&skin, &d, &err), SK_ERROR_LIMIT);
    assert_non_null(strstr(err.message, "spacing_mm"));
}

/* The all-zero desc is the documented default skin. */
static void test_defaults(void **state)
{
    (void)state;
    sk_skin_desc zero = {0};
    sk_skin_desc r = sk_skin_desc_resolved(&zero);
    assert_int_equal(r.level_count, 3);
    assert_float_equal(r.size_mm[0], 10.0f, 0);
    assert_float_equal(r.levels[0].spacing_mm, 0.8f, 1e-6);
    assert_float_equal(r.levels[1].spacing_mm, 0.32f, 1e-6);
    assert_int_equal(r.levels[0].layout, SK_SKIN_LAYOUT_TRIANGULAR);
    assert_int_equal(r.levels[0].perturb_depth, 4);
    assert_int_equal(sk_skin_desc_validate(&r, NULL), SK_OK);
    sk_skin *skin = make(&zero);
    /* about 12 level-1 cells across 10 mm (spacing 0.8 mm) */
    uint32_t n1 = sk_skin_cell_count(skin, 1);
    assert_true(n1 > 120 && n1 < 220);
    assert_true(sk_skin_cell_count(skin, 2) > 4 * n1);
    float lo, hi;
    sk_skin_height_range(skin, &lo, &hi);
    assert_float_equal(lo, 0.0f, 1e-6);
    assert_float_equal(hi, (4.0f * 0.8f + 2.0f * 0.32f + 0.8f * 0.128f) / 20.0f, 1e-6);
    sk_skin_destroy(skin);
}

/* ------------------------------------------------------------ command line */
static void test_cli_help_and_errors(void **state)
{
    (void)state;
    sk_test_run run;
    assert_int_equal(sk_test_cli(&run, "skin --help"), 0);
    assert_non_null(strstr(run.out, "shitsukan skin"));
    assert_int_equal(sk_test_cli(&run, "skin maps --help"), 0);
    assert_non_null(strstr(run.out, "--directx"));
    const char *out = sk_test_path("bad.png");
    struct {
        const char *set, *message;
    } bad[] = {
        {"levels=[]", "levels: array length 0 is out of range [1, 6]"},
        {"levels[0].spacing_mm=-1", "levels[0].spacing_mm = -1 is out of range [0, 1000]"},
        {"levels[0].profile[0].points[2][0]=2",
         "levels[0].profile[0].points[2][0] = 2 is less than"},
        {"levels[1].jitter_rate=nan", "levels[1].jitter_rate is not a finite number"},
        {"levels[0].layout=hexagonal", "levels[0].layout"},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        int status = sk_test_cli(&run, "skin --preset fig19a --set '%s' -o '%s'", bad[i].set, out);
        assert_int_equal(status, 2);
        if (!strstr(run.err, bad[i].message)) fail_msg("'%s': stderr \"%s\"", bad[i].set, run.err);
        assert_int_equal(sk_test_count_lines(run.err), 1);
        assert_false(sk_test_file_exists(out));
    }
    assert_int_equal(sk_test_cli(&run, "skin --preset no-such-figure -o '%s'", out), 2);
    assert_int_equal(sk_test_cli(&run, "skin --preset fig19a --size 0 -o '%s'", out), 2);
    assert_int_equal(sk_test_cli(&run, "skin maps --preset fig19a --furrow-level 4 -o '%s'",
                                 sk_test_path("badmaps")),
                     2);
    assert_false(sk_test_file_exists(out));
}

/* Every shipped preset loads, validates and builds (Table 1 and the real regions). */
/* Sign of the turn a -> b -> c. */
static int turn(sk_vec2d a, sk_vec2d b, sk_vec2d c)
{
    double v = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    return (v > 0) - (v < 0);
}

typedef struct segment {
    double x0, x1;
    size_t i;
} segment;

static int by_x0(const void *a, const void *b)
{
    double u = ((const segment *)a)->x0, v = ((const segment *)b)->x0;
    return (u > v) - (u < v);
}

/* True if two segments of the closed polyline p that are not neighbours cross or touch
 * (a sweep over x). */
static bool self_intersects(const sk_vec2d *p, size_t n)
{
    segment *s = malloc(sizeof(segment) * n);
    for (size_t i = 0; i < n; i++) {
        sk_vec2d a = p[i], b = p[(i + 1) % n];
        s[i] = (segment){fmin(a.x, b.x), fmax(a.x, b.x), i};
    }
    qsort(s, n, sizeof s[0], by_x0);
    bool found = false;
    for (size_t u = 0; u < n && !found; u++)
        for (size_t v = u + 1; v < n && s[v].x0 <= s[u].x1 && !found; v++) {
            size_t i = s[u].i, j = s[v].i;
            if ((i + 1) % n == j || (j + 1) % n == i) continue;
            sk_vec2d a = p[i], b = p[(i + 1) % n], c = p[j], d = p[(j + 1) % n];
            if (fmax(fmin(a.y, b.y), fmin(c.y, d.y)) > fmin(fmax(a.y, b.y), fmax(c.y, d.y)))
                continue;
            int t1 = turn(a, b, c), t2 = turn(a, b, d), t3 = turn(c, d, a), t4 = turn(c, d, b);
            if (t1 * t2 <= 0 && t3 * t4 <= 0) found = true;
        }
    free(s);
    return found;
}

/* The geometry of a shipped preset's cells: no cell is wider than half the tile along
 * either axis (so the tile holds whole cells along any stretch and no cell meets itself
 * across the wrap), and no cell's perturbed polygon crosses itself (in the frame where
 * its level is built; the levels above carry it by homeomorphisms, whose tiling
 * test_cells_tile checks). Every level-1 cell and up to about 400 cells of each deeper
 * level are checked. */
static void check_cell_geometry(const char *name, const sk_skin *skin)
{
    double tw, th;
    sk_skin_tile_size(skin, &tw, &th);
    int levels = sk_skin_get_desc(skin)->level_count;
    size_t cap = 4096;
    sk_vec2d *pts = malloc(sizeof(sk_vec2d) * cap);
    for (int level = 1; level <= levels; level++) {
        uint32_t count = sk_skin_cell_count(skin, level);
        uint32_t step = level == 1 || count < 400 ? 1 : count / 400;
        for (uint32_t c = 0; c < count; c += step) {
            size_t n = sk_skin_cell_outline(skin, level, c, 2, pts, cap);
            if (n > cap) {
                cap = n;
                pts = realloc(pts, sizeof(sk_vec2d) * cap);
                n = sk_skin_cell_outline(skin, level, c, 2, pts, cap);
            }
            double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
            for (size_t i = 0; i < n; i++) {
                x0 = fmin(x0, pts[i].x), x1 = fmax(x1, pts[i].x);
                y0 = fmin(y0, pts[i].y), y1 = fmax(y1, pts[i].y);
            }
            if (x1 - x0 > 0.5 * tw || y1 - y0 > 0.5 * th)
                fail_msg("%s: level-%d cell %u is %.3g x %.3g mm, more than half the %g x %g mm "
                         "tile",
                         name, level, c, x1 - x0, y1 - y0, tw, th);
            n = sk__cell_polygon(skin, level, c, pts, cap);
            if (n > cap) {
                cap = n;
                pts = realloc(pts, sizeof(sk_vec2d) * cap);
                n = sk__cell_polygon(skin, level, c, pts, cap);
            }
            if (self_intersects(pts, n))
                fail_msg("%s: the outline of level-%d cell %u crosses itself", name, level, c);
        }
    }
    free(pts);
}

static void test_presets_build(void **state)
{
    (void)state;
    const char *names[] = {"fig13a", "fig13b", "fig13c", "fig14a", "fig14b", "fig14c",
                           "fig15a", "fig15b", "fig15c", "fig16a", "fig16b", "fig17a",
                           "fig17b", "fig17c", "fig18a", "fig18b", "fig18c", "fig19a",
                           "fig19b", "fig19c", "fig19d", "fig19e", "fig19f", "back-of-hand",
                           "wrist",  "forearm"};
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++) {
        char path[1024];
        snprintf(path, sizeof path, "%s/skin/%s.json", SK_TEST_PRESET_DIR, names[i]);
        sk_preset *p = NULL;
        sk_error err = {0};
        if (sk_preset_load_file(&p, path, &err) != SK_OK) fail_msg("%s: %s", names[i], err.message);
        sk_skin_desc d = {0};
        if (sk_preset_bind(p, &sk_skin_schema, &d, &err) != SK_OK)
            fail_msg("%s: %s", names[i], err.message);
        assert_non_null(sk_preset_get_string(p, "source"));
        sk_preset_free(p);
        sk_skin *skin = make(&d);
        assert_true(sk_skin_cell_count(skin, 1) > 0);
        check_cell_geometry(names[i], skin);
        sk_skin_destroy(skin);
    }
}

static sk_image read_png(const char *path, sk_image_metadata *meta, int *bits)
{
    sk_image im = {0};
    sk_error err = {0};
    sk_png_read_desc rd = {.encoding = SK_PNG_ENCODING_LINEAR};
    if (sk_image_read_png(&im, path, &rd, meta, bits, &err) != SK_OK)
        fail_msg("%s: %s", path, err.message);
    return im;
}

/* The height range bounds every height, pores included where they overlap: in the library
 * (crowded pores) and in the files skin maps writes (the metadata against height.exr). */
static void test_height_range(void **state)
{
    (void)state;
    sk_skin_desc d = desc_19a(2.0f);
    d.pores.hair = (sk_skin_pore_kind){.depth_mm = 0.05f, .radius_mm = 0.3f, .density = 1};
    d.pores.sweat = (sk_skin_pore_kind){.depth_mm = 0.02f, .radius_mm = 0.1f, .density = 1};
    d.pores.sweat_level = 2;
    sk_skin *skin = make(&d);
    float lo, hi, seen_lo = INFINITY, seen_hi = -INFINITY;
    sk_skin_height_range(skin, &lo, &hi);
    int n = 256;
    float *height = malloc(sizeof(float) * n * n);
    sk_skin_render_desc rd = {.width = n, .height = n, .height_mm = height};
    assert_int_equal(sk_skin_render(skin, &rd, NULL), SK_OK);
    for (int i = 0; i < n * n; i++)
        seen_lo = fminf(seen_lo, height[i]), seen_hi = fmaxf(seen_hi, height[i]);
    free(height);
    if (!(lo <= seen_lo && seen_hi <= hi))
        fail_msg("heights %g .. %g outside the range %g .. %g", seen_lo, seen_hi, lo, hi);
    /* overlapping pits reach below the deepest single pore (its depth varies by +-20 %),
       and the bound is not far below them */
    assert_true(seen_lo < -1.2f * 0.05f);
    assert_true(lo > 5.0f * seen_lo);
    sk_skin_destroy(skin);

    sk_test_run run;
    const char *dir = sk_test_path("maps-range");
    assert_int_equal(
        sk_test_cli(&run, "skin maps --preset back-of-hand --size 512 -q -o '%s'", dir), 0);
    char path[1024];
    snprintf(path, sizeof path, "%s/height.exr", dir);
    sk_image ex = {0};
    sk_image_metadata meta = {0};
    assert_int_equal(sk_image_read_exr(&ex, path, &meta, NULL), SK_OK);
    seen_lo = INFINITY, seen_hi = -INFINITY;
    for (int i = 0; i < ex.width * ex.height; i++)
        seen_lo = fminf(seen_lo, ex.data[i]), seen_hi = fmaxf(seen_hi, ex.data[i]);
    sk_image_free(&ex);
    snprintf(path, sizeof path, "%s/height.png", dir);
    sk_image_metadata pmeta = {0};
    sk_image png = read_png(path, &pmeta, NULL);
    for (int k = 0; k < 2; k++) {
        const sk_image_metadata *m = k ? &pmeta : &meta;
        lo = strtof(sk_image_metadata_get(m, "shitsukan:height_min_mm"), NULL);
        hi = strtof(sk_image_metadata_get(m, "shitsukan:height_max_mm"), NULL);
        if (!(lo <= seen_lo && seen_hi <= hi))
            fail_msg("height.exr spans %g .. %g mm, its metadata says %g .. %g", seen_lo, seen_hi,
                     lo, hi);
    }
    /* no code of height.png is clipped: each decodes to its height.exr value */
    snprintf(path, sizeof path, "%s/height.exr", dir);
    assert_int_equal(sk_image_read_exr(&ex, path, NULL, NULL), SK_OK);
    for (int i = 0; i < ex.width * ex.height; i++)
        assert_true(fabsf(lo + png.data[i] * (hi - lo) - ex.data[i]) <= (hi - lo) / 65535.0f);
    sk_image_free(&ex);
    sk_image_free(&png);
}

/* skin maps writes every map; --region gives the same pixels; threads do not matter. */
static void test_cli_maps(void **state)
{
    (void)state;
    sk_test_run run;
    const char *full = sk_test_path("maps-full"), *part = sk_test_path("maps-part");
    assert_int_equal(
        sk_test_cli(&run, "skin maps --preset fig19a --size 96x64 --threads 1 --edges -q -o '%s'",
                    full),
        0);
    assert_int_equal(
        sk_test_cli(
            &run,
            "skin maps --preset fig19a --size 96x64 --threads 2 --region 20,10,30,40 -q -o '%s'",
            part),
        0);
    const char *maps[] = {"height.png", "normal.png", "furrow.png", "cells.png", "preview.png"};
    for (size_t m = 0; m < sizeof maps / sizeof maps[0]; m++) {
        char a[1024], b[1024];
        snprintf(a, sizeof a, "%s/%s", full, maps[m]);
        snprintf(b, sizeof b, "%s/%s", part, maps[m]);
        sk_image_metadata meta = {0};
        int bits = 0;
        sk_image fa = read_png(a, &meta, &bits), fb = read_png(b, NULL, NULL);
        assert_int_equal(fa.width, 96);
        assert_int_equal(fb.width, 30);
        assert_int_equal(fb.height, 40);
        if (m == 0) {
            assert_int_equal(bits, 16);
            assert_non_null(sk_image_metadata_get(&meta, "shitsukan:height_max_mm"));
            assert_non_null(sk_image_metadata_get(&meta, SK_IMAGE_KEY_MM_PER_PIXEL));
        }
        for (int y = 0; y < 40; y++)
            assert_memory_equal(sk_image_pixel(&fa, 20, 10 + y), sk_image_pixel(&fb, 0, y),
                                sizeof(float) * fa.channels * 30);
        sk_image_free(&fa);
        sk_image_free(&fb);
    }
    char path[1024];
    snprintf(path, sizeof path, "%s/height.exr", full);
    sk_image ex = {0};
    sk_image_metadata meta = {0};
    assert_int_equal(sk_image_read_exr(&ex, path, &meta, NULL), SK_OK);
    assert_string_equal(sk_image_metadata_get(&meta, "shitsukan:units"), "mm");
    float lo = INFINITY, hi = -INFINITY;
    for (int i = 0; i < ex.width * ex.height; i++)
        lo = fminf(lo, ex.data[i]), hi = fmaxf(hi, ex.data[i]);
    /* Fig. 19a: heights from the furrow floor (0) towards 4, 2, 0.8 tenths of each radius */
    assert_true(lo >= 0.0f && hi > 0.1f && hi < 0.2f);
    sk_image_free(&ex);
    snprintf(path, sizeof path, "%s/edges.png", full);
    assert_true(sk_test_file_exists(path));
    /* preview: same bytes for 1 and 2 threads */
    const char *p1 = sk_test_path("t1.png"), *p2 = sk_test_path("t2.png");
    assert_int_equal(
        sk_test_cli(&run, "skin --preset back-of-hand --size 80 --threads 1 -q -o '%s'", p1), 0);
    assert_int_equal(
        sk_test_cli(&run, "skin --preset back-of-hand --size 80 --threads 2 -q -o '%s'", p2), 0);
    sk_image a = read_png(p1, NULL, NULL), b = read_png(p2, NULL, NULL);
    assert_memory_equal(a.data, b.data, sizeof(float) * 3 * 80 * 80);
    sk_image_free(&a);
    sk_image_free(&b);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_defaults),
        cmocka_unit_test(test_cells_tile),
        cmocka_unit_test(test_nearest_centre),
        cmocka_unit_test(test_shared_edges),
        cmocka_unit_test(test_children_in_parent),
        cmocka_unit_test(test_profile_ends),
        cmocka_unit_test(test_normal_is_gradient),
        cmocka_unit_test(test_profile_normal),
        cmocka_unit_test(test_roundness),
        cmocka_unit_test(test_seamless),
        cmocka_unit_test(test_aperiodic),
        cmocka_unit_test(test_region_and_threads),
        cmocka_unit_test(test_furrow_distance),
        cmocka_unit_test(test_cells_and_furrows_only),
        cmocka_unit_test(test_bad_parameters),
        cmocka_unit_test(test_presets_build),
        cmocka_unit_test(test_cli_help_and_errors),
        cmocka_unit_test(test_cli_maps),
        cmocka_unit_test(test_height_range),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
