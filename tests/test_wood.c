/* Tests of the wood solid texture (Kawai 2000): the grain's phase against its closed
 * forms (eqs. 2, 3), T as the inverse of R (sec. 4.4), the vessel index against a scan of
 * every vessel (sec. 5), ring-porous counts, the fibre direction (sec. 4.1), eq. (4),
 * determinism over threads and regions, the errors of bad parameters, the shipped
 * presets and the `wood` commands. */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "shitsukan/image.h"
#include "shitsukan/io.h"
#include "shitsukan/wood.h"
#include "test_support.h"
#include "models/wood/wood_internal.h"

static bool sanitized(void) { return getenv("SK_TEST_SANITIZED") != NULL; }

static sk_wood *make_wood(const sk_wood_desc *desc)
{
    sk_wood *wood = NULL;
    sk_error err;
    sk_result r = sk_wood_create(desc, &wood, &err);
    if (r != SK_OK) fprintf(stderr, "sk_wood_create: %s\n", err.message);
    assert_int_equal(r, SK_OK);
    return wood;
}

/* A deterministic point in a box around the tree axis: |x|, |z| <= half, y in [0, len). */
static sk_vec3f random_point(uint64_t i, float half, float len)
{
    sk_rng rng = sk_rng_make(99, i, 0, 0);
    float x = (float)sk_rng_range(&rng, -half, half);
    float y = (float)sk_rng_range(&rng, 0.0, len);
    float z = (float)sk_rng_range(&rng, -half, half);
    return sk_v3f(x, y, z);
}

static double radius_of(sk_vec3f p) { return sqrt((double)p.x * p.x + (double)p.z * p.z); }

/* ------------------------------------------------------------------ phase */

static void test_straight_grain_has_zero_phase(void **state)
{
    (void)state;
    sk_wood_desc d = {0};
    d.rings.fluctuation = 0.4f; /* rings may wander; straight fibres still do not turn */
    d.rings.width_variation = 0.3f;
    sk_wood *w = make_wood(&d);
    for (int i = 0; i < 2000; i++) {
        sk_wood_sample s;
        sk_wood_eval(w, random_point(i, 120, 800), sk_v3f(0, 0, 1), &s);
        assert_true(s.phase == 0.0f);
        /* and the fibre is the tree axis */
        assert_true(fabsf(s.fibre.y - 1.0f) < 1e-6f);
    }
    sk_wood_destroy(w);
}

static void test_spiral_phase_is_analytic(void **state)
{
    (void)state;
    sk_wood_desc d = {0};
    d.grain.spiral_slope = 0.12f;
    sk_wood *w = make_wood(&d);
    for (int i = 0; i < 2000; i++) {
        sk_vec3f p = random_point(i, 100, 1000);
        double r = radius_of(p);
        if (r < 1.0) continue;
        sk_wood_sample s;
        sk_wood_eval(w, p, sk_v3f(1, 0, 0), &s);
        double expect = 0.12 * p.y / r; /* phi = g1 y / r */
        assert_true(fabs(s.phase - expect) <= 1e-5 * fabs(expect) + 1e-6);
    }
    sk_wood_destroy(w);
}

static void test_wavy_phase_is_closed_form(void **state)
{
    (void)state;
    sk_wood_desc d = {0};
    d.grain.wavy_amplitude = 0.2f;
    d.grain.wavy_wavelength_mm = 40.0f;
    sk_wood *w = make_wood(&d);
    for (int i = 0; i < 2000; i++) {
        sk_vec3f p = random_point(i, 100, 1000);
        double r = radius_of(p);
        if (r < 1.0) continue;
        sk_wood_sample s;
        sk_wood_eval(w, p, sk_v3f(1, 0, 0), &s);
        /* integral of A sin(y / lambda) / r from 0 to y */
        double expect = 0.2 * 40.0 * (1.0 - cos(p.y / 40.0)) / r;
        assert_true(fabs(s.phase - expect) <= 1e-5 * fabs(expect) + 1e-6);
    }
    sk_wood_destroy(w);
}

static void test_interlocked_and_table_phase(void **state)
{
    (void)state;
    sk_wood_desc d = {0};
    d.rings.width_mm = 2.0f;
    d.grain.interlocked_slope = 0.1f;
    d.grain.interlocked_period_years = 12.0f;
    /* g(y): 0 at y = 0, 0.05 at 100, -0.05 at 300, constant beyond */
    d.grain.table_count = 3;
    d.grain.table[0] = (sk_wood_grain_point){0.0f, 0.0f};
    d.grain.table[1] = (sk_wood_grain_point){100.0f, 0.05f};
    d.grain.table[2] = (sk_wood_grain_point){300.0f, -0.05f};
    sk_wood *w = make_wood(&d);
    for (int i = 0; i < 500; i++) {
        sk_vec3f p = random_point(i, 60, 500);
        double r = radius_of(p);
        if (r < 1.0) continue;
        sk_wood_sample s;
        sk_wood_eval(w, p, sk_v3f(1, 0, 0), &s);
        double t = r / 2.0; /* round rings of 2 mm */
        double y = p.y, table;
        if (y <= 100.0)
            table = 0.05 * y * y / 200.0;
        else if (y <= 300.0)
            table = 2.5 + 0.05 * (y - 100.0) - 0.1 * (y - 100.0) * (y - 100.0) / 400.0;
        else
            table = 2.5 + 0.0 - 0.05 * (y - 300.0);
        double expect = (0.1 * sin(2.0 * SK_PI * t / 12.0) * y + table) / r;
        assert_true(fabs(s.t - t) < 1e-4);
        assert_true(fabs(s.phase - expect) <= 1e-4 * fabs(expect) + 1e-5);
    }
    sk_wood_destroy(w);
}

/* The fractal dg stays within its bound, reaches it, and the phase table's derivative
 * along y is the slope the fibre direction uses. */
static void test_fluctuation_bound_and_phase_derivative(void **state)
{
    (void)state;
    sk_wood_desc d = {0};
    d.grain.spiral_slope = 0.12f;
    d.grain.fluctuation = 0.02f;
    d.log.radius_mm = 60.0f;
    sk_wood *w = make_wood(&d);
    const sk__grain *g = &w->grain;
    double peak = 0.0;
    for (int i = 0; i < 20000; i++) {
        sk_rng rng = sk_rng_make(5, i, 0, 0);
        double t = sk_rng_range(&rng, 0.0, 19.0), y = sk_rng_range(&rng, -2000.0, 2000.0);
        double G = sk__grain_slope(g, t, y);
        double dg = G - 0.12;
        assert_true(fabs(dg) <= 0.02 + 1e-6);
        peak = fmax(peak, fabs(dg));
        double h = 1e-3;
        double dPhi =
            (sk__phase_eval(g, t, y + h, NULL) - sk__phase_eval(g, t, y - h, NULL)) / (2 * h);
        assert_true(fabs(dPhi - G) < 1e-4);
    }
    assert_true(peak > 0.015); /* "dg up to 0.02" is reached, not just bounded */
    /* dg has zero mean along y, so the phase repeats after log.length_mm */
    double L = g->period;
    assert_true(fabs(sk__phase_eval(g, 7.3, 123.0 + L, NULL) - sk__phase_eval(g, 7.3, 123.0, NULL) -
                     0.12 * L) < 1e-6 * L);
    sk_wood_destroy(w);
}

/* ------------------------------------------------------------------ rings */

static void test_T_inverts_R(void **state)
{
    (void)state;
    sk_wood_desc d = {0};
    d.seed = 3;
    d.rings.width_mm = 2.5f;
    d.rings.width_variation = 0.4f;
    d.rings.fluctuation = 0.6f;
    d.rings.fluctuation_lobes = 6.0f;
    sk_wood *w = make_wood(&d);
    const sk__rings *rg = &w->rings;
    for (int i = 0; i < 20000; i++) {
        sk_rng rng = sk_rng_make(11, i, 0, 0);
        double t = sk_rng_range(&rng, 0.0, rg->t_max * 1.2); /* beyond the table too */
        double theta = sk_rng_range(&rng, -10.0, 10.0);
        double r = sk__rings_R(rg, t, theta);
        double back = sk__rings_T(rg, r, theta, NULL, NULL);
        assert_true(fabs(back - t) < 1e-6);
        /* rings never cross: R increases with t */
        assert_true(sk__rings_R(rg, t + 0.01, theta) > r);
    }
    /* the tables reach the log's radius in every direction */
    for (int j = 0; j < 360; j++)
        assert_true(sk__rings_R(rg, rg->t_max, j * SK_PI / 180.0) >= d.log.radius_mm ||
                    d.log.radius_mm == 0.0f);
    sk_wood_destroy(w);
}

static void test_round_rings_have_width_d(void **state)
{
    (void)state;
    sk_wood_desc d = {0};
    d.rings.width_mm = 4.0f;
    sk_wood *w = make_wood(&d);
    for (int i = 0; i < 1000; i++) {
        sk_vec3f p = random_point(i, 140, 100);
        sk_wood_sample s;
        sk_wood_eval(w, p, sk_v3f(0, 1, 0), &s);
        assert_true(fabs(s.t - radius_of(p) / 4.0) < 1e-5);
    }
    sk_wood_destroy(w);
}

/* The latewood profile: earlywood, a linear rise over `transition`, latewood; the
 * filtered value is the box average of point values. */
static void test_latewood_profile_and_filter(void **state)
{
    (void)state;
    sk_wood_desc d = {0};
    d.rings.latewood_fraction = 0.25f;
    d.rings.transition = 0.2f;
    sk_wood *w = make_wood(&d);
    const sk__attributes *a = &w->attr;
    assert_true(sk__attributes_latewood(a, 7.30, 0.0) == 0.0);
    assert_true(fabs(sk__attributes_latewood(a, 7.65, 0.0) - 0.5) < 1e-6);
    assert_true(sk__attributes_latewood(a, 7.80, 0.0) == 1.0);
    for (int i = 0; i < 200; i++) {
        double t = 3.0 + i * 0.037, half = 0.05 + 0.001 * i, sum = 0.0;
        int n = 4000;
        for (int k = 0; k < n; k++)
            sum += sk__attributes_latewood(a, t - half + (k + 0.5) * 2 * half / n, 0.0);
        assert_true(fabs(sum / n - sk__attributes_latewood(a, t, half)) < 2e-3);
    }
    sk_wood_destroy(w);
}

/* ------------------------------------------------------------------ vessels */

static double brute_force_coverage(const sk_wood *w, double x0, double z0, double fw, double extent,
                                   int rings)
{
    const sk__vessels *v = &w->vessels;
    double best = 0.0;
    sk__vessel vs;
    if (v->diffuse.on) {
        int64_t n = (int64_t)ceil(extent * v->diffuse.inv_cell);
        for (int64_t cx = -n; cx <= n; cx++)
            for (int64_t cz = -n; cz <= n; cz++) {
                assert_true(sk__diffuse_cell_vessel(v, cx, cz, &vs));
                double dx = vs.x - x0, dz = vs.z - z0;
                double c = sk__vessel_cover(sqrt(dx * dx + dz * dz), vs.radius, fw);
                best = fmax(best, c);
            }
    }
    for (int j = 1; j <= rings; j++) {
        int n = sk__ring_vessel_count(&v->ring, &w->rings, j);
        for (int row = 0; row < v->ring.rows; row++)
            for (int k = 0; k < n; k++) {
                sk__ring_vessel(v, &w->rings, j, row, k, &vs);
                double dx = vs.x - x0, dz = vs.z - z0;
                double c = sk__vessel_cover(sqrt(dx * dx + dz * dz), vs.radius, fw);
                best = fmax(best, c);
            }
    }
    return best;
}

/* Random end-grain points, and points placed near vessels so that hits are common; each
 * point alone and in batches (the index tests a batch's points together). */
static void check_index_against_scan(const sk_wood *w, double extent, int rings, double fw,
                                     int count)
{
    int hits = 0;
    sk__rings_at at[SK__WOOD_BATCH];
    double x[SK__WOOD_BATCH], z[SK__WOOD_BATCH], r[SK__WOOD_BATCH], theta[SK__WOOD_BATCH];
    double t[SK__WOOD_BATCH], cover[SK__WOOD_BATCH], scanned[SK__WOOD_BATCH];
    for (int i0 = 0; i0 < count; i0 += SK__WOOD_BATCH) {
        int n = count - i0 < SK__WOOD_BATCH ? count - i0 : SK__WOOD_BATCH;
        for (int k = 0; k < n; k++) {
            int i = i0 + k;
            sk_rng rng = sk_rng_make(17, i, 0, 0);
            x[k] = sk_rng_range(&rng, -extent * 0.8, extent * 0.8);
            z[k] = sk_rng_range(&rng, -extent * 0.8, extent * 0.8);
            r[k] = hypot(x[k], z[k]);
            theta[k] = atan2(z[k], x[k]);
            t[k] = sk__rings_T(&w->rings, r[k], theta[k], NULL, NULL);
            at[k] = sk__rings_at_angle(&w->rings, theta[k]);
            double indexed =
                sk__vessels_coverage(&w->vessels, &w->rings, x[k], z[k], r[k], theta[k], t[k], fw);
            scanned[k] = brute_force_coverage(w, x[k], z[k], fw, extent, rings);
            if (indexed != scanned[k])
                fprintf(stderr, "point %d (%g, %g): index %.17g, scan %.17g\n", i, x[k], z[k],
                        indexed, scanned[k]);
            assert_true(indexed == scanned[k]);
            if (indexed > 0.0) hits++;
        }
        sk__vessels_coverage_batch(&w->vessels, &w->rings, n, at, x, z, r, theta, t, fw, cover);
        for (int k = 0; k < n; k++) assert_true(cover[k] == scanned[k]);
    }
    assert_true(hits > count / 30); /* the comparison saw vessels, not only empty wood */
}

static void test_diffuse_index_matches_scan(void **state)
{
    (void)state;
    sk_wood_desc d = {0};
    d.log.radius_mm = 6.0f;
    d.rings.width_mm = 1.0f;
    d.vessels.diffuse.density_per_mm2 = 20.0f;
    d.vessels.diffuse.radius_mm = 0.06f;
    d.vessels.diffuse.radius_sd_mm = 0.02f;
    sk_wood *w = make_wood(&d);
    int n = sanitized() ? 150 : 600;
    check_index_against_scan(w, 4.0, 0, 0.0, n);
    check_index_against_scan(w, 4.0, 0, 0.05, n / 3); /* soft outlines reach further */
    sk_wood_destroy(w);
    /* small pores against their spacing: the query needs only a 2 x 2 block of cells */
    d.vessels.diffuse.density_per_mm2 = 60.0f;
    d.vessels.diffuse.radius_mm = 0.035f;
    d.vessels.diffuse.radius_sd_mm = 0.004f;
    w = make_wood(&d);
    assert_true(sk__vessel_reach(w->vessels.diffuse.size.hi, 0.02) <=
                0.5 * w->vessels.diffuse.cell);
    check_index_against_scan(w, 3.0, 0, 0.0, n);
    check_index_against_scan(w, 3.0, 0, 0.02, n / 3);
    sk_wood_destroy(w);
}

static void test_ring_index_matches_scan(void **state)
{
    (void)state;
    sk_wood_desc d = {0};
    d.seed = 21;
    d.log.radius_mm = 12.0f;
    d.rings.width_mm = 1.5f;
    d.rings.fluctuation = 0.5f;
    d.rings.width_variation = 0.3f;
    d.vessels.ring.linear_density = 8.0f;
    d.vessels.ring.radius_mm = 0.12f;
    d.vessels.ring.radius_sd_mm = 0.03f;
    d.vessels.ring.rows = 2;
    d.vessels.ring.jitter = 0.8f;
    d.vessels.diffuse.density_per_mm2 = 2.0f; /* latewood pores as well */
    d.vessels.diffuse.radius_mm = 0.03f;
    sk_wood *w = make_wood(&d);
    int n = sanitized() ? 100 : 400;
    check_index_against_scan(w, 9.0, 14, 0.0, n);
    check_index_against_scan(w, 9.0, 14, 0.08, n / 4);
    sk_wood_destroy(w);
}

/* Sec. 5.4: ring j (radius j d) holds P j d vessels at theta_k = 2 pi k / (P j d). */
static void test_ring_porous_counts(void **state)
{
    (void)state;
    sk_wood_desc d = {0};
    d.rings.width_mm = 2.0f;
    d.vessels.ring.linear_density = 3.0f;
    d.vessels.ring.radius_mm = 0.2f;
    sk_wood *w = make_wood(&d);
    for (int j = 1; j <= 60; j++) {
        int n = sk__ring_vessel_count(&w->vessels.ring, &w->rings, j);
        assert_int_equal(n, 3 * j * 2);
        for (int k = 0; k < n; k += 7) {
            sk__vessel v;
            sk__ring_vessel(&w->vessels, &w->rings, j, 0, k, &v);
            double theta = atan2(v.z, v.x);
            double expect = 2.0 * SK_PI * k / n;
            double diff = fmod(theta - expect + 3.0 * SK_PI, 2.0 * SK_PI) - SK_PI;
            assert_true(fabs(diff) < 1e-9);
            /* the vessel sits just past the ring boundary r = j d, clear of the ring before */
            double rv = hypot(v.x, v.z);
            assert_true(rv - v.radius >= j * 2.0 - 1e-9 && rv < j * 2.0 + 2.0);
        }
    }
    sk_wood_destroy(w);
}

/* Sec. 5.3: n = rho x area vessels in a region. */
static void test_diffuse_density(void **state)
{
    (void)state;
    sk_wood_desc d = {0};
    d.vessels.diffuse.density_per_mm2 = 38.0f;
    sk_wood *w = make_wood(&d);
    const double side = 10.0;
    int64_t n = (int64_t)ceil(side * w->vessels.diffuse.inv_cell) + 1, count = 0;
    for (int64_t cx = -n; cx <= n; cx++)
        for (int64_t cz = -n; cz <= n; cz++) {
            sk__vessel v;
            sk__diffuse_cell_vessel(&w->vessels, cx, cz, &v);
            if (fabs(v.x) < side / 2 && fabs(v.z) < side / 2) count++;
        }
    assert_true(fabs(count - 38.0 * side * side) <= 0.03 * 38.0 * side * side);
    sk_wood_destroy(w);
}

/* ------------------------------------------------------------------ fibres */

static void test_fibre_direction_on_cylinder(void **state)
{
    (void)state;
    sk_wood_desc d = {0};
    d.grain.spiral_slope = 0.1f;
    d.grain.wavy_amplitude = 0.2f;
    d.grain.wavy_wavelength_mm = 30.0f;
    d.grain.fluctuation = 0.03f;
    d.log.radius_mm = 80.0f;
    sk_wood *w = make_wood(&d);
    for (int i = 0; i < 3000; i++) {
        sk_vec3f p = random_point(i, 70, 900);
        double r = radius_of(p);
        if (r < 0.5) continue;
        sk_wood_sample s;
        sk_wood_eval(w, p, sk_v3f(0, 0, 1), &s);
        sk_vec3d f = sk_v3f_to_d(s.fibre);
        assert_true(fabs(sk_v3d_length(f) - 1.0) < 1e-6);
        sk_vec3d er = sk_v3d(p.x / r, 0, p.z / r), et = sk_v3d(-p.z / r, 0, p.x / r);
        assert_true(fabs(sk_v3d_dot(f, er)) < 1e-6); /* on its cylinder */
        double G = sk__grain_slope(&w->grain, s.t, p.y);
        assert_true(fabs(sk_v3d_dot(f, et) / f.y - G) < 1e-5); /* r dtheta/dy = G */
        assert_true(f.y > 0.0);                                /* up the tree */
    }
    sk_wood_destroy(w);
}

/* With fluctuating rings the fibre stays on its ring surface t = const: f . grad T = 0. */
static void test_fibre_direction_on_ring_surface(void **state)
{
    (void)state;
    sk_wood_desc d = {0};
    d.rings.fluctuation = 0.5f;
    d.grain.spiral_slope = 0.3f;
    d.log.radius_mm = 80.0f;
    sk_wood *w = make_wood(&d);
    double worst = 0.0;
    for (int i = 0; i < 2000; i++) {
        sk_vec3f p = random_point(i, 60, 100);
        if (radius_of(p) < 5.0) continue;
        sk_wood_sample s;
        sk_wood_eval(w, p, sk_v3f(0, 0, 1), &s);
        const double h = 1e-3;
        double grad[3];
        for (int a = 0; a < 3; a++) {
            sk_vec3f q1 = p, q0 = p;
            (&q1.x)[a] += (float)h;
            (&q0.x)[a] -= (float)h;
            double t1 = sk__rings_T(&w->rings, radius_of(q1), atan2(q1.z, q1.x), NULL, NULL);
            double t0 = sk__rings_T(&w->rings, radius_of(q0), atan2(q0.z, q0.x), NULL, NULL);
            grad[a] = (t1 - t0) / (((&q1.x)[a] - (&q0.x)[a]));
        }
        double gl = sqrt(grad[0] * grad[0] + grad[1] * grad[1] + grad[2] * grad[2]);
        double dot = (s.fibre.x * grad[0] + s.fibre.y * grad[1] + s.fibre.z * grad[2]) / gl;
        worst = fmax(worst, fabs(dot));
    }
    /* finite differences across the tables' kinks: a few thousandths at most */
    assert_true(worst < 0.01);
    sk_wood_destroy(w);
}

/* The dive angle's sign (sec. 7.3): positive where the fibre goes into the wood upwards. */
static void test_dive_angle_sign(void **state)
{
    (void)state;
    sk_wood_desc d = {0};
    d.grain.spiral_slope = 0.2f; /* fibres lean towards +theta going up */
    sk_wood *w = make_wood(&d);
    /* quarter-sawn face z = 0 at x = 50, seen from +z: there e_theta = +z, so the fibre
       leaves the surface going up and dives when going down: alpha = -atan(0.2) */
    sk_wood_sample s;
    sk_wood_eval(w, sk_v3f(50, 10, 0), sk_v3f(0, 0, 1), &s);
    assert_true(fabs(s.dive - (-atan(0.2))) < 1e-6);
    sk_wood_eval(w, sk_v3f(50, 10, 0), sk_v3f(0, 0, -1), &s);
    assert_true(fabs(s.dive - atan(0.2)) < 1e-6);
    /* the sample's up is the tree top projected on the surface */
    assert_true(fabs(s.up.y - 1.0f) < 1e-6f);
    sk_wood_destroy(w);
}

/* ------------------------------------------------------------------ shading */

static void test_shading_equals_eq4(void **state)
{
    (void)state;
    sk_wood_desc d = {0};
    d.shading.specular = 0.3f;
    d.shading.exponent = 50.0f;
    sk_wood *w = make_wood(&d);
    const double angles[][2] = {{7.2, 5.0},    {0.0, 5.0},    {-7.2, 5.0},
                                {20.0, -10.0}, {-30.0, 12.0}, {45.0, 0.0}};
    for (size_t i = 0; i < sizeof angles / sizeof angles[0]; i++) {
        double delta = angles[i][0] * SK_DEG_TO_RAD, alpha = angles[i][1] * SK_DEG_TO_RAD;
        sk_wood_sample s = {0};
        s.albedo = sk_v3f(0.5f, 0.4f, 0.25f);
        s.up = sk_v3f(0, 1, 0);
        /* a fibre diving by alpha into the surface z = 0 as it rises */
        s.fibre = sk_v3f(0, (float)cos(alpha), (float)-sin(alpha));
        s.dive = (float)alpha;
        sk_vec3f n = sk_v3f(0, 0, 1);
        sk_vec3f l = sk_v3f(0, (float)sin(delta), (float)cos(delta));
        sk_vec3f out = sk_wood_shade(w, &s, n, l, n);
        double spec = 0.3 * pow(cos(delta - alpha), 50.0);
        assert_true(fabs(out.x - (0.5 * 0.7 * cos(delta) + spec)) < 1e-5);
        assert_true(fabs(out.z - (0.25 * 0.7 * cos(delta) + spec)) < 1e-5);
        /* an open vessel has no walls to reflect */
        s.vessel = 1.0f;
        s.albedo = sk_v3f(0.1f, 0.1f, 0.1f);
        out = sk_wood_shade(w, &s, n, l, n);
        assert_true(fabs(out.y - 0.1 * 0.7 * cos(delta)) < 1e-5);
    }
    /* light from behind the surface */
    sk_wood_sample s = {0};
    s.up = sk_v3f(0, 1, 0);
    s.fibre = sk_v3f(0, 1, 0);
    sk_vec3f out = sk_wood_shade(w, &s, sk_v3f(0, 0, 1), sk_v3f(0, 0.2f, -0.98f), sk_v3f(0, 0, 1));
    assert_true(out.x == 0.0f && out.y == 0.0f && out.z == 0.0f);
    sk_wood_destroy(w);
}

/* The fibre highlight lies on the cone around the fibre: with the fibre in the surface,
 * light and view mirrored about the plane normal to the fibre give the peak. */
static void test_fibre_highlight_cone(void **state)
{
    (void)state;
    sk_wood_desc d = {0};
    d.shading.model = SK_WOOD_SHADING_FIBRE;
    d.shading.finish_exponent = 100000.0f; /* keep the finish highlight out of the way */
    sk_wood *w = make_wood(&d);
    sk_wood_sample s = {0};
    s.albedo = sk_v3f(0, 0, 0);
    s.fibre = sk_v3f(0, 1, 0);
    s.up = sk_v3f(0, 1, 0);
    sk_vec3f n = sk_v3f(0, 0, 1);
    sk_vec3f l = sk_v3f_normalize(sk_v3f(0.3f, 0.4f, 0.8f));
    double on = sk_wood_shade(w, &s, n, l, sk_v3f_normalize(sk_v3f(-0.5f, -0.4f, 0.7f))).x;
    double off = sk_wood_shade(w, &s, n, l, sk_v3f_normalize(sk_v3f(-0.5f, 0.4f, 0.7f))).x;
    double rotated = sk_wood_shade(w, &s, n, l, sk_v3f_normalize(sk_v3f(0.5f, -0.4f, 0.7f))).x;
    assert_true(on > 5.0 * off);
    /* rotating the view about the fibre axis keeps it on the cone (psi_r unchanged) */
    assert_true(fabs(on - rotated) < 0.05 * on);
    /* Fresnel reflectance: 4 % at normal incidence for eta 1.5 */
    assert_true(fabs(sk__fresnel_dielectric(1.0, 1.5) - 0.04) < 1e-9);
    sk_wood_destroy(w);
}

/* ------------------------------------------------------------------ cuts */

static sk_wood_desc busy_desc(void)
{
    sk_wood_desc d = {0};
    d.seed = 42;
    d.log.radius_mm = 80.0f;
    d.rings.fluctuation = 0.3f;
    d.rings.width_variation = 0.3f;
    d.grain.wavy_amplitude = 0.15f;
    d.grain.wavy_wavelength_mm = 20.0f;
    d.grain.fluctuation = 0.02f;
    d.vessels.diffuse.density_per_mm2 = 5.0f;
    d.vessels.diffuse.radius_mm = 0.08f;
    d.vessels.ring.linear_density = 2.0f;
    d.vessels.ring.jitter = 0.5f;
    d.fibre.brightness_shift = 0.4f;
    d.shading.specular = 0.3f;
    d.view.width_mm = 40.0f;
    d.view.tilt = 0.1f;
    d.view.light_incidence = 0.1f;
    return d;
}

static void test_cut_same_bytes_for_threads_and_regions(void **state)
{
    (void)state;
    sk_wood_desc d = busy_desc();
    sk_wood *w = make_wood(&d);
    const int W = 96, H = 80;
    size_t n = (size_t)W * H;
    float *a = malloc(n * 3 * sizeof(float)), *b = malloc(n * 3 * sizeof(float));
    float *fa = malloc(n * 3 * sizeof(float)), *va = malloc(n * sizeof(float));
    sk_wood_cut_desc c = {0};
    sk_wood_view_cut(w, &sk_wood_get_desc(w)->view, &c);
    c.width = W;
    c.height = H;
    c.samples = 2;
    c.shaded = a;
    c.fibre = fa;
    c.vessel = va;
    int threads = sk_threads_max();
    sk_threads_set(1);
    assert_int_equal(sk_wood_cut(w, &c, NULL), SK_OK);
    sk_threads_set(2);
    c.shaded = b;
    assert_int_equal(sk_wood_cut(w, &c, NULL), SK_OK);
    sk_threads_set(threads);
    assert_memory_equal(a, b, n * 3 * sizeof(float));
    /* every fibre texel decodes to a unit vector */
    for (size_t i = 0; i < n; i++) {
        double fx = 2 * fa[3 * i] - 1, fy = 2 * fa[3 * i + 1] - 1, fz = 2 * fa[3 * i + 2] - 1;
        assert_true(fabs(sqrt(fx * fx + fy * fy + fz * fz) - 1.0) < 1e-5);
        assert_true(va[i] >= 0.0f && va[i] <= 1.0f);
    }
    /* a region holds exactly the full image's pixels */
    const int rx = 17, ry = 9, rw = 40, rh = 33;
    float *r = malloc((size_t)rw * rh * 3 * sizeof(float));
    c.region[0] = rx;
    c.region[1] = ry;
    c.region[2] = rw;
    c.region[3] = rh;
    c.shaded = r;
    c.fibre = NULL;
    c.vessel = NULL;
    assert_int_equal(sk_wood_cut(w, &c, NULL), SK_OK);
    for (int y = 0; y < rh; y++)
        assert_memory_equal(r + (size_t)y * rw * 3, a + ((size_t)(ry + y) * W + rx) * 3,
                            (size_t)rw * 3 * sizeof(float));
    /* the same seed gives the same tree, another seed another */
    sk_wood *w2 = make_wood(&d);
    c.shaded = b;
    memset(c.region, 0, sizeof c.region);
    assert_int_equal(sk_wood_cut(w2, &c, NULL), SK_OK);
    assert_memory_equal(a, b, n * 3 * sizeof(float));
    sk_wood_destroy(w2);
    d.seed = 43;
    w2 = make_wood(&d);
    assert_int_equal(sk_wood_cut(w2, &c, NULL), SK_OK);
    assert_true(memcmp(a, b, n * 3 * sizeof(float)) != 0);
    sk_wood_destroy(w2);
    free(a);
    free(b);
    free(fa);
    free(va);
    free(r);
    sk_wood_destroy(w);
}

/* Every pixel of a cut is sk_wood_eval_filtered at its samples' points with their
 * footprint, shaded by sk_wood_shade and averaged in the cut's order, to the bit: the
 * cut's vectorized batches (and, on flat and quarter faces, its shared per-column stage)
 * give what a single point gives. */
static void check_cut_equals_eval(const sk_wood *w, int W, int H, int S)
{
    size_t np = (size_t)W * H;
    float *shaded = malloc(np * 3 * sizeof(float)), *albedo = malloc(np * 3 * sizeof(float));
    float *vessel = malloc(np * sizeof(float)), *dive = malloc(np * sizeof(float));
    sk_wood_cut_desc c = {0};
    sk_wood_view_cut(w, &sk_wood_get_desc(w)->view, &c);
    c.width = W;
    c.height = H;
    c.samples = S;
    c.shaded = shaded;
    c.albedo = albedo;
    c.vessel = vessel;
    c.dive = dive;
    assert_int_equal(sk_wood_cut(w, &c, NULL), SK_OK);
    /* the cut's frame and light, as sk_wood_cut sets them up */
    sk_vec3f n = sk_v3f_scale(c.normal, 1.0f / sk_v3f_length(c.normal));
    sk_vec3f a = sk_v3f_sub(c.axis, sk_v3f_scale(n, sk_v3f_dot(c.axis, n)));
    a = sk_v3f_scale(a, 1.0f / sk_v3f_length(a));
    sk_vec3f up = sk_v3f_cross(n, a);
    sk_vec3f dir = sk_v3f_add(sk_v3f_scale(up, (float)cos(c.light_azimuth)),
                              sk_v3f_scale(a, (float)sin(c.light_azimuth)));
    sk_vec3f light = sk_v3f_normalize(sk_v3f_add(sk_v3f_scale(n, (float)cos(c.light_incidence)),
                                                 sk_v3f_scale(dir, (float)sin(c.light_incidence))));
    sk_vec3f view = sk_v3f_normalize(sk_v3f_add(sk_v3f_scale(n, (float)cos(c.view_incidence)),
                                                sk_v3f_scale(up, (float)sin(c.view_incidence))));
    double width_mm = c.width_mm, height_mm = width_mm * H / W;
    float footprint = (float)(width_mm / W / S), inv = 1.0f / (float)(S * S);
    int vessels = 0;
    for (int Y = 0; Y < H; Y++)
        for (int X = 0; X < W; X++) {
            float sum[3] = {0, 0, 0}, alb[3] = {0, 0, 0}, ves = 0.0f, dv = 0.0f;
            for (int sy = 0; sy < S; sy++) {
                double fy = 0.5 - (Y + (sy + 0.5) / S) * (1.0 / H);
                sk_vec3f row = sk_v3f_add(c.point, sk_v3f_scale(up, (float)(fy * height_mm)));
                for (int sx = 0; sx < S; sx++) {
                    double fx = ((double)X + (sx + 0.5) / S) * (1.0 / W) - 0.5;
                    sk_vec3f p = sk_v3f_add(row, sk_v3f_scale(a, (float)(fx * width_mm)));
                    sk_wood_sample s;
                    sk_wood_eval_filtered(w, p, n, footprint, &s);
                    sk_vec3f col = sk_wood_shade(w, &s, n, light, view);
                    if (S == 1) { /* the cut stores 0 + value */
                        sum[0] = col.x, sum[1] = col.y, sum[2] = col.z;
                        alb[0] = s.albedo.x, alb[1] = s.albedo.y, alb[2] = s.albedo.z;
                        ves = s.vessel, dv = s.dive;
                    } else {
                        sum[0] += col.x, sum[1] += col.y, sum[2] += col.z;
                        alb[0] += s.albedo.x, alb[1] += s.albedo.y, alb[2] += s.albedo.z;
                        ves += s.vessel, dv += s.dive;
                    }
                    vessels += s.vessel > 0.0f;
                }
            }
            if (S > 1) {
                for (int k = 0; k < 3; k++) sum[k] *= inv, alb[k] *= inv;
                ves *= inv, dv *= inv;
            }
            size_t i = (size_t)Y * W + X;
            assert_memory_equal(&albedo[3 * i], alb, 3 * sizeof(float));
            assert_memory_equal(&shaded[3 * i], sum, 3 * sizeof(float));
            assert_memory_equal(&vessel[i], &ves, sizeof(float));
            assert_memory_equal(&dive[i], &dv, sizeof(float));
        }
    assert_true(vessels > 0); /* the comparison took the vessel paths too */
    free(shaded);
    free(albedo);
    free(vessel);
    free(dive);
}

static void test_cut_equals_eval(void **state)
{
    (void)state;
    /* ring-porous and sparse diffuse vessels, fluctuating rings, wavy grain with dg */
    sk_wood_desc d = busy_desc();
    sk_wood *w = make_wood(&d);
    check_cut_equals_eval(w, 77, 9, 1);
    check_cut_equals_eval(w, 31, 5, 2);
    sk_wood_destroy(w);
    /* the same on an untilted flat-sawn face and a quarter-sawn one, whose columns share
       their cross-section stage */
    d.view.tilt = 0.0f;
    w = make_wood(&d);
    check_cut_equals_eval(w, 77, 9, 1);
    check_cut_equals_eval(w, 31, 5, 2);
    sk_wood_destroy(w);
    d.view.plane = SK_WOOD_PLANE_QUARTER;
    d.view.distance_mm = 30.0f;
    w = make_wood(&d);
    check_cut_equals_eval(w, 61, 7, 2);
    sk_wood_destroy(w);
    /* dense diffuse vessels, round rings, a rotated tree, fibre highlight shading */
    d = busy_desc();
    d.rings.fluctuation = 0.0f;
    d.vessels.ring.linear_density = 0.0f;
    d.vessels.diffuse.density_per_mm2 = 40.0f;
    d.vessels.diffuse.radius_mm = 0.03f;
    d.vessels.diffuse.radius_sd_mm = 0.004f;
    d.transform.rotate[0] = 0.2f;
    d.transform.translate_mm[2] = 3.0f;
    d.shading.model = SK_WOOD_SHADING_FIBRE;
    d.view.width_mm = 6.0f;
    w = make_wood(&d);
    check_cut_equals_eval(w, 77, 9, 1);
    sk_wood_destroy(w);
    /* knots (sound and dead, whorls 25 mm apart) and broad rays on both kinds of cut */
    d = busy_desc();
    d.rays.spacing_mm = 1.0f;
    d.rays.width_mm = 0.3f;
    d.rays.height_mm = 4.0f;
    d.rays.jitter = 0.8f;
    d.knots.whorl_spacing_mm = 25.0f;
    d.knots.per_whorl = 6;
    d.knots.rise = 0.3f;
    d.knots.dead_after_years = 8.0f;
    d.knots.jitter = 0.7f;
    w = make_wood(&d);
    check_cut_equals_eval(w, 77, 9, 1);
    sk_wood_destroy(w);
    d.view.tilt = 0.0f;
    w = make_wood(&d);
    check_cut_equals_eval(w, 31, 5, 2);
    sk_wood_destroy(w);
    /* round rings seen quarter-sawn (the figure of Fig. 9) */
    d = busy_desc();
    d.rings.fluctuation = 0.0f;
    d.view.tilt = 0.0f;
    d.view.plane = SK_WOOD_PLANE_QUARTER;
    w = make_wood(&d);
    check_cut_equals_eval(w, 40, 6, 2);
    sk_wood_destroy(w);
}

/* ------------------------------------------------------------------ knots */

/* One branch a whorl, no jitter: the branch of whorl k leaves the pith at height
 * (k + phase) spacing towards the whorl's rotation. */
static sk_wood_desc knot_desc(float dead_years)
{
    sk_wood_desc d = {0};
    d.seed = 5;
    d.log.radius_mm = 100.0f;
    d.rings.width_mm = 3.0f;
    d.knots.whorl_spacing_mm = 400.0f;
    d.knots.per_whorl = 1;
    d.knots.growth = 0.2f;
    d.knots.dead_after_years = dead_years;
    d.knots.stub_mm = 30.0f;
    return d;
}

/* The tree of knot_desc and where its branch of whorl 0 leaves the pith. */
static sk_wood *knot_wood(float dead_years, double *y0, double *theta)
{
    sk_wood_desc d = knot_desc(dead_years);
    sk_wood *w = make_wood(&d);
    const sk__knots *k = &w->knots;
    uint64_t h = sk__wood_hash(k->seed, 0, 0, 0);
    *y0 = k->phase * k->spacing;
    *theta = 2.0 * SK_PI * (double)((h >> 16) & 0xffffu) / 65536.0;
    return w;
}

/* The point at radius r on the branch's side, `across` mm round the tree from its axis
 * and `up` mm above it. */
static sk_vec3f knot_point(double y0, double theta, double r, double across, double up)
{
    double a = theta + across / r;
    return sk_v3f((float)(r * cos(a)), (float)(y0 + up), (float)(r * sin(a)));
}

/* A live branch is a cone from the pith: its wood's half width is growth x r at every r
 * (the branch's rings grow 0.2 of the stem's a year), its fibres run along the branch,
 * its end grain is darker by the darkening. */
static void test_knot_is_a_cone_from_the_pith(void **state)
{
    (void)state;
    double y0, theta;
    sk_wood *w = knot_wood(0.0f, &y0, &theta);
    sk_vec3f axis = sk_v3f((float)cos(theta), 0.0f, (float)sin(theta)), n = sk_v3f(0, 1, 0);
    for (int k = 1; k <= 3; k++) {
        double r = 20.0 * k;
        sk_wood_sample in, out;
        sk_wood_eval(w, knot_point(y0, theta, r, 0.0, 0.0), n, &in);
        assert_true(fabs(sk_v3f_dot(in.fibre, axis)) > 0.999);
        /* the edge: knot fibres inside, the stem's (up the tree) outside */
        double lo = 0.0, hi = 0.6 * r;
        for (int it = 0; it < 40; it++) {
            double mid = 0.5 * (lo + hi);
            sk_wood_eval(w, knot_point(y0, theta, r, mid, 0.0), n, &out);
            if (fabs(sk_v3f_dot(out.fibre, axis)) > 0.5)
                lo = mid;
            else
                hi = mid;
        }
        double half_width = lo;
        if (fabs(half_width / r - 0.2) > 0.01)
            fail_msg("r = %g: knot half width %.3f mm, want %.3f", r, half_width, 0.2 * r);
        /* darker: the knot's ring colour times 1 - 0.4 */
        sk_wood_eval(w, knot_point(y0, theta, r, 3.0 * half_width, 0.0), n, &out);
        double ew = sk_linear_from_srgb(0.64f), lwc = sk_linear_from_srgb(0.42f);
        assert_true(in.albedo.y <= 0.6 * fmax(ew, lwc) + 1e-6);
        assert_true(in.albedo.y >= 0.6 * fmin(ew, lwc) - 1e-6);
    }
    sk_wood_destroy(w);
}

/* The grain's deflection round a knot is a smooth map: no jumps along lines past the
 * knot, nothing beyond its reach; and the fibre follows the deflected grain (moving
 * along the fibre keeps the end-grain point the stem is looked up at). */
static void test_knot_deflection_is_smooth_and_follows_the_fibre(void **state)
{
    (void)state;
    double y0, theta;
    sk_wood *w = knot_wood(0.0f, &y0, &theta);
    const sk__knots *k = &w->knots;
    double r = 50.0, t_stem = r / 3.0, a = 0.2 * r; /* the knot's radius there */
    sk__knot_hit h;
    for (int line = 0; line < 3; line++) {
        double across = (0.3 + 0.8 * line) * a; /* through the knot, its edge, its side */
        double prev = NAN;
        for (int i = -400; i <= 400; i++) {
            double up = i * 0.0125 * a; /* +-5 knot radii along the axis */
            double th = theta + across / r, shift = 0.0;
            if (sk__knots_hit(k, &w->rings, r, th, y0 + up, t_stem, 0.0, &h)) shift = h.theta_shift;
            if (fabs(up) > k->reach * a * 1.01) assert_true(shift == 0.0); /* out of reach */
            if (!isnan(prev) && across > a) assert_true(fabs(shift - prev) * r < 0.08 * a);
            prev = shift;
        }
    }
    /* along the fibre the lookup stays: theta + shift constant to second order */
    int checked = 0;
    for (int i = 0; i < 200; i++) {
        double across = a * (1.05 + 1.5 * sk_rand_uniform(1, (uint64_t)i, 0, 0)) * (i % 2 ? 1 : -1);
        double up = a * (3.0 * sk_rand_uniform(2, (uint64_t)i, 0, 0) - 1.5);
        if (across * across + up * up < 1.1 * a * a) continue;
        double th = theta + across / r, eps = 1e-3;
        if (!sk__knots_hit(k, &w->rings, r, th, y0 + up, t_stem, 0.0, &h)) continue;
        double look = th + h.theta_shift, slope = -h.psi_y / h.psi_u; /* du / dy, G = 0 */
        sk__knot_hit h2, h3;
        double straight = 0.0, along;
        assert_true(
            sk__knots_hit(k, &w->rings, r, th + slope * eps / r, y0 + up + eps, t_stem, 0.0, &h2));
        along = fabs(th + slope * eps / r + h2.theta_shift - look);
        if (sk__knots_hit(k, &w->rings, r, th, y0 + up + eps, t_stem, 0.0, &h3))
            straight = fabs(th + h3.theta_shift - look);
        if (straight < 1e-9) continue;
        if (!(along < 0.02 * straight + 1e-8))
            fail_msg("across %g up %g (a %g): along %g straight %g psi_u %g psi_y %g", across, up,
                     a, along, straight, h.psi_u, h.psi_y);
        checked++;
    }
    assert_true(checked > 50);
    sk_wood_destroy(w);
}

/* A branch that died after 12 years is a dead knot further out: the radius it had then,
 * a ring of bark, and nothing past its stub. */
static void test_dead_knot(void **state)
{
    (void)state;
    double y0, theta;
    sk_wood *w = knot_wood(12.0f, &y0, &theta);
    sk_vec3f n = sk_v3f(0, 1, 0), axis = sk_v3f((float)cos(theta), 0.0f, (float)sin(theta));
    double a = 0.2 * 3.0 * 12.0; /* 7.2 mm */
    sk_vec3f bark =
        sk_v3f(sk_linear_from_srgb(0.24f), sk_linear_from_srgb(0.15f), sk_linear_from_srgb(0.09f));
    for (double r = 45.0; r <= 60.0; r += 5.0) { /* past 36 mm, the stem when it died */
        sk_wood_sample s;
        sk_wood_eval(w, knot_point(y0, theta, r, 0.5 * a, 0.0), n, &s);
        assert_true(fabs(sk_v3f_dot(s.fibre, axis)) > 0.999);
        sk_wood_eval(w, knot_point(y0, theta, r, a - 0.3, 0.0), n, &s); /* in the bark ring */
        assert_true(fabs(s.albedo.x - bark.x) < 1e-3 && fabs(s.albedo.z - bark.z) < 1e-3);
        sk_wood_eval(w, knot_point(y0, theta, r, a + 0.3, 0.0), n, &s); /* the stem beside it */
        assert_true(fabs(sk_v3f_dot(s.fibre, axis)) < 0.5);
    }
    sk_wood_sample s;
    sk_wood_eval(w, knot_point(y0, theta, 36.0 + 30.0 + 2.0, 0.0, 0.0), n, &s); /* overgrown */
    assert_true(fabs(sk_v3f_dot(s.fibre, axis)) < 0.5);
    sk_wood_destroy(w);
}

/* ------------------------------------------------------------------ rays */

/* How radial the fibre is at an end-grain point: 1 inside a ray, whose cells run out from
 * the pith. */
static double radial_part(const sk_wood *w, double r, double theta, double y)
{
    sk_wood_sample s;
    sk_wood_eval(w, sk_v3f((float)(r * cos(theta)), (float)y, (float)(r * sin(theta))),
                 sk_v3f(0, 1, 0), &s);
    return fabs(s.fibre.x * cos(theta) + s.fibre.z * sin(theta));
}

/* Broad rays are radial ribbons: a point in one stays in it a couple of millimetres
 * further out, leaves it a width away round the tree, and holds no pores; they cover a
 * fair share of the wood. */
static void test_rays_are_radial_ribbons(void **state)
{
    (void)state;
    sk_wood_desc d = {0};
    d.seed = 3;
    d.log.radius_mm = 100.0f;
    d.rings.width_mm = 4.0f;
    d.vessels.diffuse.density_per_mm2 = 20.0f;
    d.vessels.diffuse.radius_mm = 0.05f;
    d.rays.spacing_mm = 1.5f;
    d.rays.width_mm = 0.45f;
    d.rays.height_mm = 15.0f;
    d.rays.length_mm = 40.0f;
    sk_wood *w = make_wood(&d);
    int in = 0, stays = 0, leaves = 0, total = 4000;
    for (int i = 0; i < total; i++) {
        double r = 30.0 + 40.0 * sk_rand_uniform(7, (uint64_t)i, 0, 0);
        double theta = 2.0 * SK_PI * sk_rand_uniform(7, (uint64_t)i, 1, 0);
        double y = 50.0 * sk_rand_uniform(7, (uint64_t)i, 2, 0);
        if (radial_part(w, r, theta, y) < 0.99) continue;
        in++;
        sk_wood_sample s;
        sk_wood_eval(w, sk_v3f((float)(r * cos(theta)), (float)y, (float)(r * sin(theta))),
                     sk_v3f(0, 1, 0), &s);
        assert_true(s.vessel == 0.0f);
        stays += radial_part(w, r + 2.0, theta, y) > 0.99;
        leaves += radial_part(w, r, theta + 1.0 / r, y) < 0.5; /* 1 mm round the tree */
    }
    /* the lenses fill about a tenth of the wood (two sets of one per 3 mm x 24 mm) */
    assert_true(in > total / 40 && in < total / 4);
    assert_true(stays > 0.8 * in);
    assert_true(leaves > 0.9 * in);
    sk_wood_destroy(w);
}

/* A tree moved by a rigid transform is the same wood at the moved points. */
static void test_transform_moves_the_tree(void **state)
{
    (void)state;
    sk_wood_desc d = busy_desc();
    sk_wood *w0 = make_wood(&d);
    d.transform.translate_mm[0] = 100.0f;
    d.transform.translate_mm[1] = -20.0f;
    d.transform.rotate[0] = 0.5f;
    d.transform.rotate[2] = -1.1f;
    sk_wood *w1 = make_wood(&d);
    sk__wood_frame frame;
    sk__wood_frame_init(&frame, &d.transform);
    for (int i = 0; i < 500; i++) {
        sk_vec3f p = random_point(i, 60, 300);
        sk_vec3f n = sk_v3f_normalize(random_point(i + 1000, 1, 1));
        sk_wood_sample a, b;
        sk_wood_eval(w0, p, n, &a);
        sk_wood_eval(w1, sk__wood_frame_point_to_scene(&frame, p),
                     sk__wood_frame_dir_to_scene(&frame, n), &b);
        assert_true(fabsf(a.t - b.t) < 1e-3f);
        assert_true(fabsf(a.dive - b.dive) < 1e-3f);
        sk_vec3f fa = sk__wood_frame_dir_to_scene(&frame, a.fibre);
        assert_true(sk_v3f_dot(fa, b.fibre) > 0.99999f);
    }
    sk_wood_destroy(w0);
    sk_wood_destroy(w1);
}

/* ------------------------------------------------------------------ errors */

static void expect_error(const sk_wood_desc *d, sk_result result, const char *a, const char *b)
{
    sk_error err;
    assert_int_equal(sk_wood_desc_validate(d, &err), result);
    if (!strstr(err.message, a) || (b && !strstr(err.message, b)))
        fprintf(stderr, "unexpected message: %s\n", err.message);
    assert_non_null(strstr(err.message, a));
    if (b) assert_non_null(strstr(err.message, b));
    sk_wood *w = (sk_wood *)1;
    assert_int_equal(sk_wood_create(d, &w, &err), result);
    assert_null(w);
}

static void test_bad_parameters(void **state)
{
    (void)state;
    sk_wood_desc d = {0};
    d.rings.width_mm = -2.0f;
    expect_error(&d, SK_ERROR_INVALID_ARGUMENT, "rings.width_mm = -2 is out of range", "0.05");

    d = (sk_wood_desc){0};
    d.grain.spiral_slope = NAN;
    expect_error(&d, SK_ERROR_INVALID_ARGUMENT, "grain.spiral_slope is not a finite number", NULL);

    d = (sk_wood_desc){0};
    d.rings.width_mm = 1.0f;
    d.vessels.ring.linear_density = 2.0f;
    d.vessels.ring.radius_mm = 0.45f;
    d.vessels.ring.radius_sd_mm = 0.05f;
    expect_error(&d, SK_ERROR_INVALID_ARGUMENT, "vessels.ring.radius_mm = 0.45 is too large",
                 "rings.width_mm = 1");

    d = (sk_wood_desc){0};
    d.rings.width_mm = 0.5f;
    d.vessels.diffuse.density_per_mm2 = 10.0f;
    d.vessels.diffuse.radius_mm = 0.3f;
    expect_error(&d, SK_ERROR_INVALID_ARGUMENT, "vessels.diffuse.radius_mm = 0.3 is too large",
                 NULL);

    d = (sk_wood_desc){0};
    d.grain.wavy_amplitude = 0.2f;
    expect_error(&d, SK_ERROR_INVALID_ARGUMENT, "grain.wavy_wavelength_mm = 0 must be", NULL);

    d = (sk_wood_desc){0};
    d.knots.whorl_spacing_mm = 5.0f;
    expect_error(&d, SK_ERROR_INVALID_ARGUMENT, "knots.whorl_spacing_mm = 5 is out of range", "20");

    d = (sk_wood_desc){0};
    d.knots.whorl_spacing_mm = 300.0f;
    d.knots.rise = (float)(85.0 * SK_DEG_TO_RAD);
    expect_error(&d, SK_ERROR_INVALID_ARGUMENT, "knots.rise_deg = 85 is out of range", NULL);

    /* the steepest branches, jittered, stay finite */
    d = (sk_wood_desc){0};
    d.knots.whorl_spacing_mm = 20.0f;
    d.knots.rise = (float)(80.0 * SK_DEG_TO_RAD);
    d.knots.jitter = 1.0f;
    sk_wood *steep = make_wood(&d);
    for (int i = 0; i < 2000; i++) {
        sk_wood_sample s;
        sk_wood_eval(steep, random_point((uint64_t)i, 60.0f, 200.0f), sk_v3f(0, 0, 1), &s);
        assert_true(isfinite(s.albedo.x) && isfinite(s.fibre.x) && isfinite(s.t));
    }
    sk_wood_destroy(steep);

    d = (sk_wood_desc){0};
    d.fibre.shift_mode = (sk_wood_shift_mode)7;
    expect_error(&d, SK_ERROR_INVALID_ARGUMENT, "fibre.shift_mode = 7 is out of range", NULL);

    d = (sk_wood_desc){0};
    d.grain.interlocked_slope = 0.1f;
    expect_error(&d, SK_ERROR_INVALID_ARGUMENT, "grain.interlocked_period_years = 0", NULL);

    d = (sk_wood_desc){0};
    d.grain.table_count = 2;
    d.grain.table[0] = (sk_wood_grain_point){10.0f, 0.0f};
    d.grain.table[1] = (sk_wood_grain_point){10.0f, 0.1f};
    expect_error(&d, SK_ERROR_INVALID_ARGUMENT, "grain.table[1][0] = 10 must be greater", NULL);

    d = (sk_wood_desc){0};
    d.view.tilt = (float)(100.0 * SK_DEG_TO_RAD);
    expect_error(&d, SK_ERROR_INVALID_ARGUMENT, "view.tilt_deg = 100 is out of range", NULL);

    d = (sk_wood_desc){0};
    d.rings.earlywood_srgb[1] = 1.5f;
    expect_error(&d, SK_ERROR_INVALID_ARGUMENT, "rings.earlywood_srgb[1] = 1.5", NULL);

    d = (sk_wood_desc){0};
    d.log.radius_mm = 2000.0f;
    d.rings.width_mm = 0.05f;
    expect_error(&d, SK_ERROR_LIMIT, "needs more than 4096 rings", NULL);
}

static void test_bad_cut(void **state)
{
    (void)state;
    sk_wood *w = make_wood(NULL);
    float px[3];
    sk_wood_cut_desc c = {0};
    c.normal = sk_v3f(0, 0, 1);
    c.axis = sk_v3f(0, 0, 2); /* along the normal */
    c.width = c.height = 1;
    c.width_mm = 10;
    c.shaded = px;
    sk_error err;
    assert_int_equal(sk_wood_cut(w, &c, &err), SK_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(err.message, "axis"));
    c.axis = sk_v3f(1, 0, 0);
    c.region[0] = 1;
    c.region[2] = 1;
    c.region[3] = 1;
    assert_int_equal(sk_wood_cut(w, &c, &err), SK_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(err.message, "region"));
    memset(c.region, 0, sizeof c.region);
    c.width_mm = NAN;
    assert_int_equal(sk_wood_cut(w, &c, &err), SK_ERROR_INVALID_ARGUMENT);
    c.width_mm = 10;
    assert_int_equal(sk_wood_cut(w, &c, &err), SK_OK);
    sk_wood_destroy(w);
}

/* The all-zero desc is the documented defaults and builds a tree. */
static void test_defaults(void **state)
{
    (void)state;
    sk_wood_desc r = sk_wood_desc_resolved(NULL);
    assert_true(r.log.radius_mm == 150.0f && r.rings.width_mm == 3.0f);
    assert_true(r.rings.latewood_fraction == 0.3f && r.fibre.cell_mm == 0.08f);
    assert_int_equal(r.shading.model, SK_WOOD_SHADING_FIGURE);
    assert_true(r.shading.diffuse == 1.0f && r.shading.exponent == 64.0f);
    assert_int_equal(r.view.plane, SK_WOOD_PLANE_FLAT);
    assert_true(r.view.distance_mm == 75.0f);
    assert_int_equal(sk_wood_desc_validate(&r, NULL), SK_OK);
    sk_wood *w = make_wood(NULL);
    sk_wood_stats st;
    sk_wood_get_stats(w, &st);
    assert_true(st.memory_bytes > 0 && st.ring_count >= 50);
    sk_wood_destroy(w);
}

/* ------------------------------------------------------------------ presets */

/* Every shipped preset binds, validates, builds a tree and says where its values are from. */
static void test_presets_bind_and_build(void **state)
{
    (void)state;
    char dir[1024];
    snprintf(dir, sizeof dir, "%s/wood", SK_TEST_PRESET_DIR);
    DIR *d = opendir(dir);
    assert_non_null(d);
    int count = 0, species = 0;
    struct dirent *e;
    while ((e = readdir(d)) != NULL) {
        size_t len = strlen(e->d_name);
        if (len < 6 || strcmp(e->d_name + len - 5, ".json") != 0) continue;
        char path[2048];
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        sk_preset *preset = NULL;
        sk_error err = {0};
        if (sk_preset_load_file(&preset, path, &err) != SK_OK) fprintf(stderr, "%s\n", err.message);
        assert_non_null(preset);
        sk_wood_desc desc;
        memset(&desc, 0, sizeof desc);
        sk_result r = sk_preset_bind(preset, &sk_wood_schema, &desc, &err);
        if (r != SK_OK) fprintf(stderr, "%s: %s\n", e->d_name, err.message);
        assert_int_equal(r, SK_OK);
        assert_non_null(sk_preset_get_string(preset, "description"));
        sk_preset_free(preset);
        char *text = NULL;
        size_t size = 0;
        assert_int_equal(sk_read_file(path, 0, &text, &size, NULL), SK_OK);
        assert_non_null(strstr(text, "\"source\""));
        if (strncmp(e->d_name, "fig", 3) != 0) species++;
        free(text);
        /* every vessel a preset can draw lies within the 20-400 um diameters of Kawai 2000
           sec. 3.2 (radius ~ Normal cut at 3 sd, at least a tenth of the mean) */
        sk_wood_desc rd = sk_wood_desc_resolved(&desc);
        const float *sizes[2][2] = {
            {&rd.vessels.diffuse.radius_mm, &rd.vessels.diffuse.radius_sd_mm},
            {&rd.vessels.ring.radius_mm, &rd.vessels.ring.radius_sd_mm}};
        bool on[2] = {rd.vessels.diffuse.density_per_mm2 > 0.0f,
                      rd.vessels.ring.linear_density > 0.0f};
        for (int k = 0; k < 2; k++) {
            if (!on[k]) continue;
            double mean = *sizes[k][0], sd = *sizes[k][1];
            double lo = fmax(mean - 3.0 * sd, 0.1 * mean), hi = mean + 3.0 * sd;
            if (2.0 * lo < 0.020 - 1e-6 || 2.0 * hi > 0.400 + 1e-6)
                fail_msg("%s: %s vessels %.0f-%.0f um across, outside 20-400 um", e->d_name,
                         k ? "ring" : "diffuse", 2000.0 * lo, 2000.0 * hi);
        }
        desc.log.radius_mm = desc.log.radius_mm > 0.0f ? fminf(desc.log.radius_mm, 40.0f) : 40.0f;
        sk_wood *w = make_wood(&desc);
        sk_wood_sample s;
        sk_wood_eval(w, sk_v3f(20, 5, 3), sk_v3f(0, 0, 1), &s);
        assert_true(s.albedo.x >= 0.0f && s.albedo.x <= 1.0f);
        sk_wood_destroy(w);
        count++;
    }
    closedir(d);
    assert_true(count >= 15);  /* Figs. 5a-c, 6a-c, 7, 9, the ring fluctuation and the species */
    assert_true(species >= 6); /* oak, ash, maple, birch, cherry and a conifer */
}

/* The paper's figure parameters are in the presets as the paper states them. */
static void test_figure_presets_hold_the_paper_values(void **state)
{
    (void)state;
    static const struct {
        const char *name;
        float spiral, amplitude, wavelength, fluctuation, shift, specular;
        bool ring_fluctuation; /* the figure shows R(t, theta) fluctuating (sec. 4.4) */
    } figs[] = {
        {"fig5a", 0, 0, 0, 0, 0, 0, false},         {"fig5b", 0.12f, 0, 0, 0.02f, 0, 0, false},
        {"fig5c", 0, 0.2f, 40, 0.02f, 0, 0, false}, {"fig6b", 0.12f, 0, 0, 0.02f, 0, 0, false},
        {"fig6c", 0, 0.2f, 40, 0.02f, 0, 0, false}, {"fig7", 0, 0.15f, 15, 0, 0.4f, 0, true},
        {"fig9", 0, 0.15f, 20, 0, 0, 0.3f, false},
    };
    for (size_t i = 0; i < sizeof figs / sizeof figs[0]; i++) {
        char path[1024];
        snprintf(path, sizeof path, "%s/wood/%s.json", SK_TEST_PRESET_DIR, figs[i].name);
        sk_preset *preset = NULL;
        assert_int_equal(sk_preset_load_file(&preset, path, NULL), SK_OK);
        sk_wood_desc d;
        memset(&d, 0, sizeof d);
        assert_int_equal(sk_preset_bind(preset, &sk_wood_schema, &d, NULL), SK_OK);
        sk_preset_free(preset);
        assert_true(d.grain.spiral_slope == figs[i].spiral);
        assert_true(d.grain.wavy_amplitude == figs[i].amplitude);
        assert_true(d.grain.wavy_wavelength_mm == figs[i].wavelength);
        assert_true(d.grain.fluctuation == figs[i].fluctuation);
        assert_true(d.fibre.brightness_shift == figs[i].shift);
        assert_true(d.shading.specular == figs[i].specular);
        assert_true((d.rings.fluctuation > 0.0f) == figs[i].ring_fluctuation);
        /* the paper adds the brightness shift (sec. 6.3) */
        assert_true(sk_wood_desc_resolved(&d).fibre.shift_mode == SK_WOOD_SHIFT_ADD);
    }
}

/* The ring-fluctuation preset shows R(t, theta) at work: its rings' radii vary by more
 * than a quarter around the tree yet grow with t at every angle (rings never cross), and
 * T inverts R there. */
static void test_ring_fluctuation_preset(void **state)
{
    (void)state;
    char path[1024];
    snprintf(path, sizeof path, "%s/wood/ring-fluctuation.json", SK_TEST_PRESET_DIR);
    sk_preset *preset = NULL;
    assert_int_equal(sk_preset_load_file(&preset, path, NULL), SK_OK);
    sk_wood_desc d;
    memset(&d, 0, sizeof d);
    assert_int_equal(sk_preset_bind(preset, &sk_wood_schema, &d, NULL), SK_OK);
    sk_preset_free(preset);
    sk_wood *w = make_wood(&d);
    const sk__rings *rg = &w->rings;
    double widest = 0.0;
    for (int year = 2; year <= 20; year++) {
        double lo = INFINITY, hi = 0.0;
        for (int k = 0; k < 360; k++) {
            double theta = k * SK_PI / 180.0, R = sk__rings_R(rg, year, theta);
            lo = fmin(lo, R);
            hi = fmax(hi, R);
            assert_true(sk__rings_R(rg, year + 0.5, theta) > R);
            double back = sk__rings_T(rg, R, theta, NULL, NULL);
            assert_true(fabs(back - year) < 1e-4);
        }
        widest = fmax(widest, (hi - lo) / (0.5 * (hi + lo)));
    }
    assert_true(widest > 0.25);
    assert_true(w->vessels.ring.on); /* pores placed through R(t, theta) */
    sk_wood_destroy(w);
}

/* The brightness shift is added to the cell's brightness (its sRGB value) as the paper
 * adds it: centred on the ring's colour, spread over the whole range; the old form
 * multiplies by 1 - shift u and only darkens. */
static void test_brightness_shift_modes(void **state)
{
    (void)state;
    for (int mode = SK_WOOD_SHIFT_ADD; mode <= SK_WOOD_SHIFT_MULTIPLY; mode++) {
        sk_wood_desc d = {0};
        d.rings.latewood_fraction = 0.02f; /* earlywood almost everywhere */
        d.fibre.brightness_shift = 0.4f;
        d.fibre.cell_mm = 0.05f;
        d.fibre.shift_mode = (sk_wood_shift_mode)mode;
        sk_wood *w = make_wood(&d);
        double ew = d.rings.earlywood_srgb[1] ? d.rings.earlywood_srgb[1] : 0.64;
        double lo = INFINITY, hi = -INFINITY, sum = 0.0;
        int n = 0;
        for (int i = 0; i < 4000; i++) {
            /* end grain, mid-ring (t = k + 0.5): the ring profile is earlywood */
            double r = 3.0 * (5 + i % 20) + 1.5, theta = i * 0.7;
            sk_wood_sample s;
            sk_wood_eval(w, sk_v3f((float)(r * cos(theta)), 0.0f, (float)(r * sin(theta))),
                         sk_v3f(0, 1, 0), &s);
            double v = mode == SK_WOOD_SHIFT_ADD ? sk_srgb_from_linear(s.albedo.y) - ew
                                                 : s.albedo.y / sk_linear_from_srgb((float)ew);
            lo = fmin(lo, v);
            hi = fmax(hi, v);
            sum += v;
            n++;
        }
        if (mode == SK_WOOD_SHIFT_ADD) {
            assert_true(lo >= -0.2 - 1e-3 && hi <= 0.2 + 1e-3); /* within 40 % of each other */
            assert_true(lo < -0.18 && hi > 0.18);               /* and filling that range */
            assert_true(fabs(sum / n) < 0.01); /* centred: the ring keeps its mean */
        } else {
            assert_true(lo >= 0.6 - 1e-5 && hi <= 1.0 + 1e-6);
            assert_true(lo < 0.62);
        }
        sk_wood_destroy(w);
    }
}

/* ------------------------------------------------------------------ commands */

static sk_test_run g_run;

static void test_cli_cut_and_region(void **state)
{
    (void)state;
    const char *full = sk_test_path("wood/full.png"), *part = sk_test_path("wood/part.png");
    const char *maps = sk_test_path("wood/maps/x");
    assert_int_equal(sk_test_cli(&g_run,
                                 "wood cut --preset oak --size 48x40 --samples 1 -q "
                                 "--maps '%s' -o '%s'",
                                 maps, full),
                     0);
    assert_int_equal(sk_test_cli(&g_run,
                                 "wood cut --preset oak --size 48x40 --samples 1 -q "
                                 "--region 7,5,20,11 -o '%s'",
                                 part),
                     0);
    sk_image a = {0}, b = {0};
    assert_int_equal(sk_image_read_png(&a, full, NULL, NULL, NULL, NULL), SK_OK);
    assert_int_equal(sk_image_read_png(&b, part, NULL, NULL, NULL, NULL), SK_OK);
    assert_int_equal(b.width, 20);
    assert_int_equal(b.height, 11);
    for (int y = 0; y < 11; y++)
        assert_memory_equal(sk_image_pixel(&b, 0, y), sk_image_pixel(&a, 7, 5 + y),
                            20 * 3 * sizeof(float));
    sk_image_free(&a);
    sk_image_free(&b);
    /* the maps: albedo, fibre directions (unit after decoding), pores */
    char path[1200];
    snprintf(path, sizeof path, "%s/fibre.png", maps);
    sk_png_read_desc linear = {.encoding = SK_PNG_ENCODING_LINEAR};
    int bits = 0;
    assert_int_equal(sk_image_read_png(&a, path, &linear, NULL, &bits, NULL), SK_OK);
    assert_int_equal(bits, 16);
    int up = 0;
    for (int i = 0; i < a.width * a.height; i++) {
        const float *f = a.data + 3 * i;
        double x = 2 * f[0] - 1, y = 2 * f[1] - 1, z = 2 * f[2] - 1;
        assert_true(fabs(sqrt(x * x + y * y + z * z) - 1.0) < 1e-3);
        /* a flat-sawn face: fibres run up the image, but for the broad rays' cells, which
           run out of it (towards the bark, towards the viewer) */
        assert_true(y > -1e-3 && z > -0.2);
        up += y > 0.9;
    }
    assert_true(up > a.width * a.height * 3 / 4);
    sk_image_free(&a);
    snprintf(path, sizeof path, "%s/albedo.png", maps);
    assert_true(sk_test_file_exists(path));
    snprintf(path, sizeof path, "%s/pores.png", maps);
    assert_true(sk_test_file_exists(path));
    /* the picture inside a maps folder that does not exist yet (as make demo writes it) */
    const char *fresh = sk_test_path("wood/maps/fresh");
    char inside[1200];
    snprintf(inside, sizeof inside, "%s/shaded.png", fresh);
    char clear[1300];
    snprintf(clear, sizeof clear, "rm -rf '%s'", fresh);
    assert_int_equal(system(clear), 0);
    assert_int_equal(sk_test_cli(&g_run,
                                 "wood cut --preset oak --size 24 --samples 1 -q "
                                 "--maps '%s' -o '%s'",
                                 fresh, inside),
                     0);
    assert_true(sk_test_file_exists(inside));
    snprintf(path, sizeof path, "%s/albedo.png", fresh);
    assert_true(sk_test_file_exists(path));
}

static void expect_cli_error(const char *args, const char *needle)
{
    const char *out = sk_test_path("wood/never.png");
    remove(out);
    int status = sk_test_cli(&g_run, "%s -q -o '%s'", args, out);
    if (status != 2 || !strstr(g_run.err, needle))
        fprintf(stderr, "%s -> %d: %s", args, status, g_run.err);
    assert_int_equal(status, 2);
    assert_non_null(strstr(g_run.err, needle));
    assert_int_equal(sk_test_count_lines(g_run.err), 1);
    assert_false(sk_test_file_exists(out));
}

static void test_cli_errors(void **state)
{
    (void)state;
    expect_cli_error("wood cut --size 8 --set rings.width_mm=-1", "rings.width_mm");
    expect_cli_error("wood cut --size 8 --set grain.wavy_amplitude=0.2",
                     "grain.wavy_wavelength_mm");
    expect_cli_error("wood cut --size 8 --set vessels.ring.linear_density=3 "
                     "--set vessels.ring.radius_mm=1.9",
                     "too large");
    expect_cli_error("wood cut --size 8 --set rings.fluctuation=nan", "rings.fluctuation");
    expect_cli_error("wood cut --size 8 --plane diagonal", "--plane");
    expect_cli_error("wood cut --size 8 --tilt 120", "tilt");
    expect_cli_error("wood cut --size 8 --point 1,2,3", "--normal");
    expect_cli_error("wood cut --size 8 --point 0,0,0 --normal 0,0,1 --axis 0,0,3", "axis");
    expect_cli_error("wood cut --size 8 --region 4,4,8,8", "--region");
    expect_cli_error("wood sweep --size 8 --frames 1", "frames");
    expect_cli_error("wood cut --preset no-such-wood", "no-such-wood");
    assert_int_equal(sk_test_cli(&g_run, "wood cut --help"), 0);
    assert_non_null(strstr(g_run.out, "--maps"));
    assert_int_equal(sk_test_cli(&g_run, "wood sweep --help"), 0);
    assert_non_null(strstr(g_run.out, "--frames"));
}

static void test_cli_sweep_and_sheet(void **state)
{
    (void)state;
    const char *dir = sk_test_path("wood/sweep/x");
    assert_int_equal(sk_test_cli(&g_run,
                                 "wood sweep --preset fig9 --size 24 --samples 1 --frames 3 "
                                 "-q -o '%s'",
                                 dir),
                     0);
    char a[1200], b[1200], c[1200];
    snprintf(a, sizeof a, "%s/frame_0001.png", dir);
    snprintf(b, sizeof b, "%s/frame_0002.png", dir);
    snprintf(c, sizeof c, "%s/frame_0003.png", dir);
    assert_true(sk_test_file_exists(a) && sk_test_file_exists(b) && sk_test_file_exists(c));
    /* the sheen moves: the first and last frames differ */
    sk_image i1 = {0}, i3 = {0};
    assert_int_equal(sk_image_read_png(&i1, a, NULL, NULL, NULL, NULL), SK_OK);
    assert_int_equal(sk_image_read_png(&i3, c, NULL, NULL, NULL, NULL), SK_OK);
    assert_true(memcmp(i1.data, i3.data, (size_t)24 * 24 * 3 * sizeof(float)) != 0);
    sk_image_free(&i1);
    sk_image_free(&i3);
    const char *sheet = sk_test_path("wood/sheet.png");
    assert_int_equal(sk_test_cli(&g_run,
                                 "sheet '%s' '%s' '%s' --label a --label b --columns 3 "
                                 "--title T -o '%s'",
                                 a, b, c, sheet),
                     0);
    assert_int_equal(sk_image_read_png(&i1, sheet, NULL, NULL, NULL, NULL), SK_OK);
    assert_true(i1.width >= 3 * 24 && i1.height > 24);
    sk_image_free(&i1);
    assert_int_equal(sk_test_cli(&g_run, "sheet '%s' --label a --label b -o '%s'", a, sheet), 2);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_straight_grain_has_zero_phase),
        cmocka_unit_test(test_spiral_phase_is_analytic),
        cmocka_unit_test(test_wavy_phase_is_closed_form),
        cmocka_unit_test(test_interlocked_and_table_phase),
        cmocka_unit_test(test_fluctuation_bound_and_phase_derivative),
        cmocka_unit_test(test_T_inverts_R),
        cmocka_unit_test(test_round_rings_have_width_d),
        cmocka_unit_test(test_latewood_profile_and_filter),
        cmocka_unit_test(test_diffuse_index_matches_scan),
        cmocka_unit_test(test_ring_index_matches_scan),
        cmocka_unit_test(test_ring_porous_counts),
        cmocka_unit_test(test_diffuse_density),
        cmocka_unit_test(test_fibre_direction_on_cylinder),
        cmocka_unit_test(test_fibre_direction_on_ring_surface),
        cmocka_unit_test(test_dive_angle_sign),
        cmocka_unit_test(test_shading_equals_eq4),
        cmocka_unit_test(test_fibre_highlight_cone),
        cmocka_unit_test(test_cut_same_bytes_for_threads_and_regions),
        cmocka_unit_test(test_cut_equals_eval),
        cmocka_unit_test(test_transform_moves_the_tree),
        cmocka_unit_test(test_bad_parameters),
        cmocka_unit_test(test_bad_cut),
        cmocka_unit_test(test_defaults),
        cmocka_unit_test(test_presets_bind_and_build),
        cmocka_unit_test(test_figure_presets_hold_the_paper_values),
        cmocka_unit_test(test_ring_fluctuation_preset),
        cmocka_unit_test(test_knot_is_a_cone_from_the_pith),
        cmocka_unit_test(test_knot_deflection_is_smooth_and_follows_the_fibre),
        cmocka_unit_test(test_dead_knot),
        cmocka_unit_test(test_rays_are_radial_ribbons),
        cmocka_unit_test(test_brightness_shift_modes),
        cmocka_unit_test(test_cli_cut_and_region),
        cmocka_unit_test(test_cli_errors),
        cmocka_unit_test(test_cli_sweep_and_sheet),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
