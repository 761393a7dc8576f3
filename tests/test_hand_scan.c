/* Tests of the thesis's scan pipeline (sec. 4.1.1-4.1.3) on analytic surfaces meshed here
 * (spheres, capsules): the ray hierarchy against brute force, the simulated scanner's
 * visibility and noise against their definitions, marker location, rigid registration
 * within the noise, slices and resampled tubes that are closed manifolds, the
 * neighbouring-slice resampling against the wrinkles of the thesis's, and the whole
 * pipeline on a hand of capsules (deterministic for any thread count). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "shitsukan/hand.h"
#include "test_support.h"

/* ------------------------------------------------------------ shapes */

/* A closed capsule mesh from a to b (its axis), radius r, appended to `m` (grown).
 * rings: latitude steps per hemisphere; sides: around. */
static void add_capsule(sk_mesh *m, sk_vec3d a, sk_vec3d b, double r, int sides, int rings,
                        int body)
{
    sk_vec3d axis = sk_v3d_normalize(sk_v3d_sub(b, a));
    sk_vec3d t = fabs(axis.x) < 0.9 ? sk_v3d(1, 0, 0) : sk_v3d(0, 1, 0);
    sk_vec3d e1 = sk_v3d_normalize(sk_v3d_cross(axis, t)), e2 = sk_v3d_cross(axis, e1);
    /* latitude rows: south pole cap (rings), body (body + 1 rows), north cap (rings) */
    int rows = 2 * rings + body + 1; /* rows of vertices between the two poles */
    size_t v0 = m->vertex_count, nv = (size_t)rows * sides + 2,
           nt = (size_t)(rows - 1) * sides * 2 + 2 * sides;
    m->positions = realloc(m->positions, sizeof(float) * 3 * (v0 + nv));
    m->indices = realloc(m->indices, sizeof(uint32_t) * 3 * (m->triangle_count + nt));
    float *P = m->positions;
    size_t v = v0;
    for (int row = 0; row < rows; row++) {
        sk_vec3d c;
        double lat; /* angle from the equator, -pi/2 .. pi/2 */
        if (row < rings) {
            lat = -SK_PI / 2 + SK_PI / 2 * (row + 1) / (rings + 1.0);
            c = a;
        } else if (row >= rings + body + 1) {
            lat = SK_PI / 2 * (row - rings - body) / (rings + 1.0);
            c = b;
        } else {
            lat = 0;
            c = sk_v3d_add(a, sk_v3d_scale(sk_v3d_sub(b, a), (double)(row - rings) / body));
        }
        for (int s = 0; s < sides; s++) {
            double phi = 2 * SK_PI * s / sides;
            sk_vec3d dir = sk_v3d_add(
                sk_v3d_scale(sk_v3d_add(sk_v3d_scale(e1, cos(phi)), sk_v3d_scale(e2, sin(phi))),
                             cos(lat)),
                sk_v3d_scale(axis, sin(lat)));
            sk_vec3d p = sk_v3d_add(c, sk_v3d_scale(dir, r));
            P[3 * v] = (float)p.x, P[3 * v + 1] = (float)p.y, P[3 * v + 2] = (float)p.z;
            v++;
        }
    }
    sk_vec3d south = sk_v3d_sub(a, sk_v3d_scale(axis, r)),
             north = sk_v3d_add(b, sk_v3d_scale(axis, r));
    size_t vs = v++, vn = v++;
    P[3 * vs] = (float)south.x, P[3 * vs + 1] = (float)south.y, P[3 * vs + 2] = (float)south.z;
    P[3 * vn] = (float)north.x, P[3 * vn + 1] = (float)north.y, P[3 * vn + 2] = (float)north.z;
    uint32_t *I = m->indices + 3 * m->triangle_count;
    size_t t_ = 0;
#define VID(row, s) ((uint32_t)(v0 + (size_t)(row)*sides + (size_t)(((s) % sides + sides) % sides)))
    for (int row = 0; row + 1 < rows; row++)
        for (int s = 0; s < sides; s++) {
            uint32_t q00 = VID(row, s), q01 = VID(row, s + 1), q10 = VID(row + 1, s),
                     q11 = VID(row + 1, s + 1);
            I[3 * t_] = q00, I[3 * t_ + 1] = q01, I[3 * t_ + 2] = q11, t_++;
            I[3 * t_] = q00, I[3 * t_ + 1] = q11, I[3 * t_ + 2] = q10, t_++;
        }
    for (int s = 0; s < sides; s++) {
        I[3 * t_] = (uint32_t)vs, I[3 * t_ + 1] = VID(0, s + 1), I[3 * t_ + 2] = VID(0, s), t_++;
        I[3 * t_] = (uint32_t)vn, I[3 * t_ + 1] = VID(rows - 1, s),
              I[3 * t_ + 2] = VID(rows - 1, s + 1), t_++;
    }
#undef VID
    m->vertex_count = v0 + nv;
    m->triangle_count += nt;
}

static sk_mesh sphere_mesh(sk_vec3d c, double r)
{
    sk_mesh m;
    memset(&m, 0, sizeof m);
    add_capsule(&m, c, sk_v3d_add(c, sk_v3d(0, 1e-9, 0)), r, 96, 48, 1);
    return m;
}

typedef struct sphere_sdf {
    sk_vec3d c;
    double r;
} sphere_sdf;

static double sdf_sphere(void *user, sk_vec3d p, sk_vec3d *g)
{
    const sphere_sdf *s = user;
    sk_vec3d d = sk_v3d_sub(p, s->c);
    double len = sk_v3d_length(d);
    if (g) *g = len > 0 ? sk_v3d_scale(d, 1.0 / len) : sk_v3d(0, 0, 1);
    return len - s->r;
}

static void free_mesh(sk_mesh *m)
{
    free(m->positions);
    free(m->indices);
    memset(m, 0, sizeof *m);
}

/* ------------------------------------------------------------ ray hierarchy */

static void test_ray_hierarchy_matches_brute_force(void **state)
{
    (void)state;
    sk_mesh m = sphere_mesh(sk_v3d(1, 2, 3), 10.0);
    sk_hand_scan_target_desc td = {.mesh = &m};
    sk_hand_scan_target *t;
    sk_error err;
    assert_int_equal(sk_hand_scan_target_create(&t, &td, &err), SK_OK);
    for (int k = 0; k < 300; k++) {
        sk_vec3d o =
            sk_v3d(sk_rand_uniform(1, k, 0, 0) * 40 - 20, sk_rand_uniform(1, k, 1, 0) * 40 - 20,
                   sk_rand_uniform(1, k, 2, 0) * 40 - 20);
        sk_vec3d d = sk_v3d_normalize(sk_v3d(sk_rand_normal(1, k, 3, 0), sk_rand_normal(1, k, 4, 0),
                                             sk_rand_normal(1, k, 5, 0)));
        if (k % 7 == 0) d = sk_v3d(0, 0, -1); /* axis-aligned rays, as the scanner's */
        /* brute force over every triangle (Moller-Trumbore written out again) */
        double best = INFINITY;
        for (size_t i = 0; i < m.triangle_count; i++) {
            sk_vec3d v[3];
            for (int c = 0; c < 3; c++) {
                const float *p = m.positions + 3 * m.indices[3 * i + c];
                v[c] = sk_v3d(p[0], p[1], p[2]);
            }
            sk_vec3d e1 = sk_v3d_sub(v[1], v[0]), e2 = sk_v3d_sub(v[2], v[0]),
                     pv = sk_v3d_cross(d, e2);
            double det = sk_v3d_dot(e1, pv);
            if (fabs(det) < 1e-15) continue;
            sk_vec3d s = sk_v3d_sub(o, v[0]);
            double u = sk_v3d_dot(s, pv) / det;
            sk_vec3d q = sk_v3d_cross(s, e1);
            double w = sk_v3d_dot(d, q) / det, tt = sk_v3d_dot(e2, q) / det;
            if (u >= 0 && w >= 0 && u + w <= 1 && tt > 0 && tt < best) best = tt;
        }
        double th;
        sk_vec3d n;
        bool hit = sk_hand_scan_target_raycast(t, o, d, 0.0, 1e9, &th, &n);
        assert_int_equal(hit, isfinite(best));
        if (hit) {
            assert_true(fabs(th - best) < 1e-9);
            assert_true(sk_v3d_dot(n, d) <= 0.0); /* facing the ray */
        }
        /* nearest point: the sphere mesh is within its facets' sag of the sphere */
        double dist = sk_hand_scan_target_distance(t, o);
        double exact = fabs(sk_v3d_length(sk_v3d_sub(o, sk_v3d(1, 2, 3))) - 10.0);
        assert_true(fabs(dist - exact) < 0.02);
    }
    sk_hand_scan_target_destroy(t);
    sk_mesh bad = m;
    bad.triangle_count = 0;
    td.mesh = &bad;
    assert_int_equal(sk_hand_scan_target_create(&t, &td, &err), SK_ERROR_INVALID_ARGUMENT);
    assert_null(t);
    free_mesh(&m);
}

/* ------------------------------------------------------------ registration */

static sk_hand_rigid some_transform(void)
{
    sk_hand_rigid t;
    t.rotation =
        sk_m3d_mul(sk_m3d_rot_z(0.07), sk_m3d_mul(sk_m3d_rot_x(SK_PI), sk_m3d_rot_y(-0.03)));
    t.translation = sk_v3d(12.0, 180.0, 41.0);
    return t;
}

/* 9 points spread like the markers: around the hand's outline, nearly in one plane. */
static void marker_like_points(sk_vec3d *p)
{
    static const double xy[9][2] = {{-30, 0},  {35, 5},   {50, 40},  {60, 80},  {42, 100},
                                    {45, 140}, {-40, 30}, {-42, 90}, {-48, 120}};
    for (int i = 0; i < 9; i++) p[i] = sk_v3d(xy[i][0], xy[i][1], 2.0 * sin(i * 1.3));
}

static void test_registration_recovers_a_known_transform(void **state)
{
    (void)state;
    sk_vec3d a[9], b[9];
    marker_like_points(a);
    sk_hand_rigid truth = some_transform(), est;
    for (int i = 0; i < 9; i++) b[i] = sk_hand_rigid_apply(&truth, a[i]);
    double res[9];
    sk_error err;
    assert_int_equal(sk_hand_register_rigid(a, b, 9, &est, res, &err), SK_OK);
    double angle, shift;
    sk_hand_rigid_difference(&est, &truth, &angle, &shift);
    assert_true(angle < 1e-9 && shift < 1e-9);
    for (int i = 0; i < 9; i++) assert_true(res[i] < 1e-9);
    assert_true(fabs(sk_m3d_det(est.rotation) - 1.0) < 1e-12);
    /* with noise of sigma per coordinate on both sets, the fitted transform misses the
       true one at the points by about sigma * sqrt(2) * sqrt(6 / (3 n)) (6 parameters
       from 3n coordinates): within the noise, not beyond it */
    const double sigma = 0.05;
    double err_sum = 0.0, res_sum = 0.0;
    const int trials = 200;
    for (int k = 0; k < trials; k++) {
        sk_vec3d na[9], nb[9];
        for (int i = 0; i < 9; i++) {
            na[i] = sk_v3d_add(a[i], sk_v3d(sigma * sk_rand_normal(5, k, i, 0),
                                            sigma * sk_rand_normal(5, k, i, 1),
                                            sigma * sk_rand_normal(5, k, i, 2)));
            nb[i] = sk_v3d_add(b[i], sk_v3d(sigma * sk_rand_normal(5, k, i, 3),
                                            sigma * sk_rand_normal(5, k, i, 4),
                                            sigma * sk_rand_normal(5, k, i, 5)));
        }
        assert_int_equal(sk_hand_register_rigid(na, nb, 9, &est, res, &err), SK_OK);
        double e2 = 0.0;
        for (int i = 0; i < 9; i++) {
            e2 += pow(sk_v3d_length(sk_v3d_sub(sk_hand_rigid_apply(&est, a[i]), b[i])), 2);
            res_sum += res[i] * res[i];
        }
        err_sum += e2 / 9;
    }
    double point_noise = sigma * sqrt(2.0) * sqrt(3.0); /* 3D noise of a difference */
    double rms_error = sqrt(err_sum / trials), rms_res = sqrt(res_sum / (9.0 * trials));
    double expected_error = point_noise * sqrt(6.0 / 27.0);
    assert_true(rms_error > 0.6 * expected_error && rms_error < 1.4 * expected_error);
    /* residuals: the noise less what the 6 parameters absorb */
    double expected_res = point_noise * sqrt(21.0 / 27.0);
    assert_true(rms_res > 0.85 * expected_res && rms_res < 1.15 * expected_res);
    /* points in one plane still give a rotation, not a reflection */
    for (int i = 0; i < 9; i++) a[i].z = 0, b[i] = sk_hand_rigid_apply(&truth, a[i]);
    assert_int_equal(sk_hand_register_rigid(a, b, 9, &est, NULL, &err), SK_OK);
    assert_true(fabs(sk_m3d_det(est.rotation) - 1.0) < 1e-12);
    sk_hand_rigid_difference(&est, &truth, &angle, &shift);
    assert_true(angle < 1e-9 && shift < 1e-9);
    /* points on a line leave the rotation about it open */
    for (int i = 0; i < 9; i++)
        a[i] = sk_v3d(i, 2 * i, 0), b[i] = sk_hand_rigid_apply(&truth, a[i]);
    assert_int_equal(sk_hand_register_rigid(a, b, 9, &est, NULL, &err), SK_ERROR_INVALID_ARGUMENT);
    assert_int_equal(sk_hand_register_rigid(a, b, 2, &est, NULL, &err), SK_ERROR_INVALID_ARGUMENT);
}

/* ------------------------------------------------------------ scanner */

static void test_scanner_sees_what_is_visible_with_the_stated_noise(void **state)
{
    (void)state;
    const double radius = 30.0;
    sk_vec3d c = {0, 0, 0};
    sk_mesh m = sphere_mesh(c, radius);
    sphere_sdf sd = {c, radius};
    sk_hand_scan_target_desc td = {.mesh = &m, .sdf = sdf_sphere, .sdf_user = &sd};
    sk_hand_scan_target *t;
    sk_error err;
    assert_int_equal(sk_hand_scan_target_create(&t, &td, &err), SK_OK);
    sk_hand_scanner_desc d = {
        .lines = 160, .points = 128, .size_x_mm = 100, .size_y_mm = 80, .size_z_mm = 100};
    sk_hand_rigid place[2];
    assert_int_equal(sk_hand_scan_placements(t, &d, place, &err), SK_OK);
    /* resting on the table, centred */
    sk_vec3d centre = sk_hand_rigid_apply(&place[0], c);
    assert_true(fabs(centre.z - radius) < 0.05 && fabs(centre.x - 50) < 0.05 &&
                fabs(centre.y - 40) < 0.05);
    sk_hand_range_scan scan;
    assert_int_equal(
        sk_hand_scan_simulate(t, NULL, SK_HAND_SCAN_PALM, &place[0], &d, 9, &scan, &err), SK_OK);
    sk_hand_scanner_desc r = sk_hand_scanner_desc_resolved(&d);
    double a = r.triangulation_deg * SK_DEG_TO_RAD, cg = cos(r.grazing_deg * SK_DEG_TO_RAD);
    sk_vec3d cam = {sin(a), 0, cos(a)};
    int surface = 0, mismatches = 0, shadow = 0, shadow_predicted = 0;
    double sum = 0, sum2 = 0;
    for (int i = 0; i < scan.lines; i++)
        for (int j = 0; j < scan.points; j++) {
            size_t k = (size_t)i * scan.points + j;
            sk_vec3d p = sk_hand_range_scan_point(&scan, i, j, 0);
            double dx = p.x - centre.x, dy = p.y - centre.y;
            bool on_sphere = dx * dx + dy * dy < radius * radius;
            if (on_sphere) {
                double dz = sqrt(radius * radius - dx * dx - dy * dy);
                sk_vec3d n = {dx / radius, dy / radius, dz / radius};
                bool seen = n.z >= cg && sk_v3d_dot(n, cam) >= cg;
                bool measured = scan.kind[k] == SK_HAND_SAMPLE_SURFACE;
                surface++;
                mismatches += seen != measured;
                if (measured) {
                    assert_true(fabs(scan.true_depth[k] - (centre.z + dz)) <
                                1e-4); /* float storage */
                    double e = scan.depth[k] - scan.true_depth[k];
                    sum += e, sum2 += e * e;
                    /* quantised to the depth step */
                    double q = scan.depth[k] / r.depth_step_mm;
                    assert_true(fabs(q - nearbyint(q)) < 1e-3);
                }
            } else {
                /* the table is shadowed where the way up to the camera passes the sphere */
                sk_vec3d o = {p.x - centre.x, p.y - centre.y, -centre.z};
                double b = sk_v3d_dot(o, cam), cc = sk_v3d_dot(o, o) - radius * radius;
                bool shadowed = b * b - cc > 0 && -b > 0;
                shadow_predicted += shadowed;
                shadow += scan.kind[k] == SK_HAND_SAMPLE_NONE;
                if (!shadowed && scan.kind[k] != SK_HAND_SAMPLE_NONE) {
                    assert_int_equal(scan.kind[k], SK_HAND_SAMPLE_TABLE);
                    assert_true(scan.depth[k] < r.table_threshold_mm);
                }
            }
        }
    /* only the silhouette's few samples may differ (mesh against sphere) */
    assert_true(mismatches < surface / 100 + 4);
    assert_true(shadow_predicted > 100 &&
                abs(shadow - shadow_predicted) < shadow_predicted / 50 + 4);
    int measured = 0;
    for (size_t k = 0; k < (size_t)scan.lines * scan.points; k++)
        measured += scan.kind[k] == SK_HAND_SAMPLE_SURFACE;
    double mean = sum / measured, sd_ = sqrt(sum2 / measured - mean * mean);
    /* noise 0.05 / cos (>= 0.05) and quantisation 0.2 (sd 0.058) */
    assert_true(fabs(mean) < 0.01);
    assert_true(sd_ > 0.07 && sd_ < 0.12);
    /* the back placement is the cast turned over: its z axis points down in the hand frame */
    assert_true(place[1].rotation.m[2][2] < -0.99);
    /* same seed, same scan; another seed, another noise */
    sk_hand_range_scan again;
    assert_int_equal(
        sk_hand_scan_simulate(t, NULL, SK_HAND_SCAN_PALM, &place[0], &d, 9, &again, &err), SK_OK);
    assert_memory_equal(scan.depth, again.depth, sizeof(float) * scan.lines * scan.points);
    sk_hand_range_scan_free(&again);
    assert_int_equal(
        sk_hand_scan_simulate(t, NULL, SK_HAND_SCAN_PALM, &place[0], &d, 10, &again, &err), SK_OK);
    assert_true(memcmp(scan.depth, again.depth, sizeof(float) * scan.lines * scan.points) != 0);
    sk_hand_range_scan_free(&again);
    sk_hand_range_scan_free(&scan);
    /* a surface larger than the volume is refused, naming the axis */
    sk_hand_scanner_desc small = {.size_x_mm = 40};
    assert_int_equal(sk_hand_scan_placements(t, &small, place, &err), SK_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(err.message, "size_x_mm"));
    sk_hand_scanner_desc bad = {.lines = 3};
    assert_int_equal(
        sk_hand_scan_simulate(t, NULL, SK_HAND_SCAN_PALM, &place[0], &bad, 9, &scan, &err),
        SK_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(err.message, "scanner.lines"));
    sk_hand_scan_target_destroy(t);
    free_mesh(&m);
}

static void test_markers_are_found_where_they_are(void **state)
{
    (void)state;
    /* a flat ellipsoid-like lump (a wide capsule) with 9 bumps around its rim */
    sk_mesh m;
    memset(&m, 0, sizeof m);
    add_capsule(&m, sk_v3d(0, -40, 0), sk_v3d(0, 40, 0), 20.0, 96, 24, 40);
    sk_hand_scan_target_desc td = {.mesh = &m};
    sk_hand_scan_target *t;
    sk_error err;
    assert_int_equal(sk_hand_scan_target_create(&t, &td, &err), SK_OK);
    sk_hand_markers mk = {.count = 9, .radius_mm = 2.5};
    for (int k = 0; k < 9; k++) snprintf(mk.name[k], sizeof mk.name[k], "m%d", k);
    for (int k = 0; k < 9; k++) mk.centre[k] = sk_v3d((k % 2 ? 1 : -1) * 20.75, -36 + 9.0 * k, 0);
    sk_hand_scanner_desc d = {
        .lines = 300, .points = 256, .size_x_mm = 150, .size_y_mm = 100, .size_z_mm = 80};
    sk_hand_rigid place[2];
    assert_int_equal(sk_hand_scan_placements(t, &d, place, &err), SK_OK);
    for (int side = 0; side < 2; side++) {
        sk_hand_range_scan scan;
        assert_int_equal(sk_hand_scan_simulate(t, &mk, (sk_hand_scan_side)side, &place[side], &d, 4,
                                               &scan, &err),
                         SK_OK);
        sk_vec3d found[9];
        int used[9];
        assert_int_equal(sk_hand_markers_locate(&scan, &mk, found, used, &err), SK_OK);
        for (int k = 0; k < 9; k++) {
            assert_true(scan.marker_points[k] >= 10);
            sk_vec3d truth = sk_hand_rigid_apply(&place[side], mk.centre[k]);
            assert_true(sk_v3d_length(sk_v3d_sub(found[k], truth)) < 0.08);
            assert_true(used[k] >= 6);
        }
        sk_hand_range_scan_free(&scan);
    }
    sk_hand_scan_target_destroy(t);
    free_mesh(&m);
}

/* ------------------------------------------------------------ slices and polygons */

/* A link geometry with one phalanx (link 5, the index proximal) from a to b, the other
 * links far away. */
static sk_hand_link_geometry single_link(sk_vec3d a, sk_vec3d b)
{
    sk_hand_link_geometry g;
    for (int l = 0; l < SK_HAND_LINK_COUNT; l++) {
        g.a[l] = sk_v3d(1000.0 + 10 * l, 0, 0);
        g.b[l] = sk_v3d(1000.0 + 10 * l, 1, 0);
        g.frame[l] = sk_m3d_identity();
    }
    g.a[5] = a;
    g.b[5] = b;
    return g;
}

/* Points on a capsule's cylinder (radius r about the y axis, y in [0, len]) seen as a
 * scanner would: rows every 0.5 mm, 0.4 mm apart around, a gap on one side (where
 * neither scan saw it), noise of `noise` mm on the radius. */
static void cylinder_cloud(double r, double len, double noise, double gap_deg, sk_hand_cloud *c)
{
    int rows = (int)(len / 0.5), around = (int)(2 * SK_PI * r / 0.4);
    sk_error err;
    assert_int_equal(sk_hand_cloud_alloc(c, (size_t)rows * around, false, &err), SK_OK);
    size_t n = 0;
    for (int i = 0; i < rows; i++)
        for (int j = 0; j < around; j++) {
            double th = 2 * SK_PI * (j + 0.5 * sk_rand_uniform(3, i, j, 0)) / around - SK_PI;
            if (fabs(th) < 0.5 * gap_deg * SK_DEG_TO_RAD) continue;
            double rr = r + noise * sk_rand_normal(3, i, j, 1);
            c->position[n] = sk_v3d(rr * cos(th), (i + 0.5) * 0.5, rr * sin(th));
            c->side[n] = sin(th) > 0 ? SK_HAND_SCAN_PALM : SK_HAND_SCAN_BACK;
            n++;
        }
    c->count = n;
}

typedef struct edge_count {
    uint32_t a, b;
    int forward, backward;
} edge_count;

/* Counts how often each undirected edge occurs in each direction. */
static edge_count *count_edges(const sk_mesh *m, size_t *count)
{
    edge_count *e = calloc(3 * m->triangle_count, sizeof *e);
    size_t n = 0;
    for (size_t t = 0; t < m->triangle_count; t++)
        for (int k = 0; k < 3; k++) {
            uint32_t a = m->indices[3 * t + k], b = m->indices[3 * t + (k + 1) % 3];
            uint32_t lo = a < b ? a : b, hi = a < b ? b : a;
            size_t i = 0;
            while (i < n && !(e[i].a == lo && e[i].b == hi)) i++;
            if (i == n) e[n++] = (edge_count){lo, hi, 0, 0};
            if (a == lo)
                e[i].forward++;
            else
                e[i].backward++;
        }
    *count = n;
    return e;
}

/* Every triangle of a tube about the y axis faces away from the axis. */
static void assert_faces_away_from_the_y_axis(const sk_mesh *m)
{
    for (size_t t = 0; t < m->triangle_count; t++) {
        const float *p0 = m->positions + 3 * m->indices[3 * t],
                    *p1 = m->positions + 3 * m->indices[3 * t + 1];
        const float *p2 = m->positions + 3 * m->indices[3 * t + 2];
        sk_vec3d a = sk_v3d(p0[0], p0[1], p0[2]), b = sk_v3d(p1[0], p1[1], p1[2]),
                 c = sk_v3d(p2[0], p2[1], p2[2]);
        sk_vec3d n = sk_v3d_cross(sk_v3d_sub(b, a), sk_v3d_sub(c, a));
        sk_vec3d centre = sk_v3d_scale(sk_v3d_add(sk_v3d_add(a, b), c), 1.0 / 3);
        assert_true(n.x * centre.x + n.z * centre.z > 0);
    }
}

static void test_resampled_tube_is_a_closed_manifold(void **state)
{
    (void)state;
    sk_hand_cloud c;
    cylinder_cloud(8.0, 30.0, 0.0, 60.0, &c);
    sk_hand_link_geometry g = single_link(sk_v3d(0, -5, 0), sk_v3d(0, 35, 0));
    sk_hand_slices_desc sd = {.count = 12};
    sk_hand_slices sl;
    sk_error err;
    assert_int_equal(sk_hand_slices_build(&c, &g, &sd, &sl, &err), SK_OK);
    assert_int_equal(sl.count, 12);
    for (size_t k = 0; k < sl.first[sl.count]; k++) {
        assert_int_equal(sl.points[k].link, 5);
        assert_true(fabs(sl.points[k].r - 8.0) < 1e-5);
    }
    for (int mode = SK_HAND_RESAMPLE_NEIGHBOURS; mode <= SK_HAND_RESAMPLE_THESIS; mode++) {
        sk_hand_resample_desc rd = {.mode = (sk_hand_resample_mode)mode};
        sk_mesh m;
        sk_hand_resample_stats st;
        assert_int_equal(sk_hand_resample(&sl, &g, &rd, &m, &st, &err), SK_OK);
        /* 12 rings of 10, 11 bands of 20 triangles */
        assert_int_equal(st.rings, 12);
        assert_int_equal(st.arcs, 0);
        assert_int_equal(m.vertex_count, 120);
        assert_int_equal(m.triangle_count, 220);
        size_t ne;
        edge_count *e = count_edges(&m, &ne);
        int boundary = 0;
        for (size_t i = 0; i < ne; i++) {
            /* every edge used once each way (interior) or once (the two end rings) */
            assert_true(e[i].forward <= 1 && e[i].backward <= 1);
            boundary += e[i].forward + e[i].backward == 1;
        }
        assert_int_equal(boundary, 20);
        /* a cylinder: V - E + F = 0 */
        assert_int_equal((long)m.vertex_count - (long)ne + (long)m.triangle_count, 0);
        free(e);
        /* outward faces, vertices on the surface (eq. 4.2 interpolates across the gap on
           the chord, hence the tolerance there) */
        assert_faces_away_from_the_y_axis(&m);
        for (size_t v = 0; v < m.vertex_count; v++) {
            double rr = hypot(m.positions[3 * v], m.positions[3 * v + 2]);
            assert_true(rr < 8.0 + 1e-4 && rr > 8.0 * cos(SK_PI / 6) - 1e-4);
        }
        assert_non_null(sk_mesh_find_attribute(&m, "link"));
        sk_mesh_free(&m);
    }
    sk_hand_slices_free(&sl);
    sk_hand_cloud_free(&c);
}

/* Folds of the resampled tube of a patchy scan of a finger, each mode. */
static void tube_folds(double noise, sk_hand_resample_stats st[2])
{
    sk_hand_cloud c;
    cylinder_cloud(8.0, 60.0, noise, 50.0, &c);
    /* drop points at random so that the angular extent of each slice's data differs */
    size_t n = 0;
    for (size_t i = 0; i < c.count; i++) {
        if (sk_rand_uniform(11, i, 0, 0) < 0.3) continue;
        c.position[n] = c.position[i];
        c.side[n++] = c.side[i];
    }
    c.count = n;
    sk_hand_link_geometry g = single_link(sk_v3d(0, -5, 0), sk_v3d(0, 65, 0));
    sk_hand_slices sl;
    sk_error err;
    sk_hand_slices_desc sd = {.count = 30};
    assert_int_equal(sk_hand_slices_build(&c, &g, &sd, &sl, &err), SK_OK);
    for (int k = 0; k < 2; k++) {
        sk_hand_resample_desc rd = {.mode =
                                        k ? SK_HAND_RESAMPLE_THESIS : SK_HAND_RESAMPLE_NEIGHBOURS};
        sk_mesh m;
        assert_int_equal(sk_hand_resample(&sl, &g, &rd, &m, &st[k], &err), SK_OK);
        assert_int_equal(st[k].rings, 30);
        sk_mesh_free(&m);
    }
    sk_hand_slices_free(&sl);
    sk_hand_cloud_free(&c);
}

/* Slices the cloud (10 slices) over its link geometry, resamples it with the neighbouring
 * slices and checks what both joins below must give: 5 rings and 10 arcs, a manifold (no
 * edge twice in one direction), every face outward, and triangles that cross y = 20 (no
 * gap where the two kinds of section meet). Frees the cloud. */
static void assert_joined_at_y20(sk_hand_cloud *cloud, const sk_hand_link_geometry *geometry)
{
    sk_hand_cloud c = *cloud;
    sk_hand_link_geometry g = *geometry;
    sk_hand_slices_desc sd = {.count = 10};
    sk_hand_slices sl;
    sk_error err;
    assert_int_equal(sk_hand_slices_build(&c, &g, &sd, &sl, &err), SK_OK);
    sk_mesh m;
    sk_hand_resample_stats st;
    assert_int_equal(sk_hand_resample(&sl, &g, NULL, &m, &st, &err), SK_OK);
    assert_int_equal(st.rings, 5);
    assert_int_equal(st.arcs, 10);
    size_t ne;
    edge_count *e = count_edges(&m, &ne);
    for (size_t i = 0; i < ne; i++) assert_true(e[i].forward <= 1 && e[i].backward <= 1);
    free(e);
    bool joined = false;
    for (size_t t = 0; t < m.triangle_count; t++) {
        float y0 = m.positions[3 * m.indices[3 * t] + 1],
              y1 = m.positions[3 * m.indices[3 * t + 1] + 1];
        joined = joined || (y0 < 20.0f && y1 > 20.0f) || (y0 > 20.0f && y1 < 20.0f);
    }
    assert_true(joined);
    sk_mesh_free(&m);
    sk_hand_slices_free(&sl);
    sk_hand_cloud_free(&c);
}

/* Drops the cloud's points in two side bands (within 0.6 rad of the +x and -x directions
 * about the y axis) beyond y = 20 (`above`) or below it. */
static void drop_side_bands(sk_hand_cloud *c, bool above)
{
    size_t n = 0;
    for (size_t i = 0; i < c->count; i++) {
        sk_vec3d p = c->position[i];
        double th = atan2(p.z, p.x);
        if ((above ? p.y > 20.0 : p.y < 20.0) && (fabs(th) < 0.6 || fabs(th) > SK_PI - 0.6))
            continue;
        c->position[n] = p;
        c->side[n++] = c->side[i];
    }
    c->count = n;
}

/* A palm link (the carpus) whose points surround it on some slices and lie on two sides
 * on others: rings joined to arcs, still a manifold with every face outward. */
static void test_rings_join_arcs_as_a_manifold(void **state)
{
    (void)state;
    sk_hand_cloud c;
    cylinder_cloud(15.0, 40.0, 0.0, 0.0, &c);
    /* the far half loses two side bands (as where the metacarpals' points take over) */
    drop_side_bands(&c, true);
    sk_hand_link_geometry g = single_link(sk_v3d(1000, 0, 0), sk_v3d(1000, 1, 0));
    g.a[0] = sk_v3d(0, -5, 0), g.b[0] = sk_v3d(0, 45, 0);
    assert_joined_at_y20(&c, &g);
}

/* Where a finger's metacarpal strips end and its phalanx's tube begins, the two join: one
 * surface from the palm into the finger, still a manifold facing outward. */
static void test_finger_joins_its_metacarpal(void **state)
{
    (void)state;
    sk_hand_cloud c;
    cylinder_cloud(10.0, 40.0, 0.0, 0.0, &c);
    /* below y = 20 (the metacarpal) the sides are unseen, as between the palm's strips */
    drop_side_bands(&c, false);
    sk_hand_link_geometry g =
        single_link(sk_v3d(0, 20, 0), sk_v3d(0, 45, 0));  /* link 5: index proximal */
    g.a[4] = sk_v3d(0, -5, 0), g.b[4] = sk_v3d(0, 20, 0); /* link 4: its metacarpal */
    assert_joined_at_y20(&c, &g);
}

/* Two metacarpals side by side under one flat section: each link's points are an arc, and
 * where the arcs meet the strips are bridged, so the palm is one tube (V - E + F = 0, the
 * only boundary the two end sections), not two strips with gaps. */
static void test_palm_strips_are_bridged(void **state)
{
    (void)state;
    int rows = 80, around = 240;
    sk_hand_cloud c;
    sk_error err;
    assert_int_equal(sk_hand_cloud_alloc(&c, (size_t)rows * around, false, &err), SK_OK);
    for (int i = 0; i < rows; i++)
        for (int j = 0; j < around; j++) {
            double th = 2 * SK_PI * (j + 0.5) / around;
            c.position[i * around + j] = sk_v3d(24 * cos(th), (i + 0.5) * 0.5, 8 * sin(th));
            c.side[i * around + j] = sin(th) > 0 ? SK_HAND_SCAN_PALM : SK_HAND_SCAN_BACK;
        }
    c.count = (size_t)rows * around;
    sk_hand_link_geometry g = single_link(sk_v3d(1000, 0, 0), sk_v3d(1000, 1, 0));
    g.a[4] = sk_v3d(10, -5, 0), g.b[4] = sk_v3d(10, 45, 0);   /* the index metacarpal */
    g.a[8] = sk_v3d(-10, -5, 0), g.b[8] = sk_v3d(-10, 45, 0); /* the middle metacarpal */
    sk_hand_slices_desc sd = {.count = 8};
    sk_hand_slices sl;
    assert_int_equal(sk_hand_slices_build(&c, &g, &sd, &sl, &err), SK_OK);
    sk_mesh m;
    sk_hand_resample_stats st;
    assert_int_equal(sk_hand_resample(&sl, &g, NULL, &m, &st, &err), SK_OK);
    assert_int_equal(st.rings, 0);
    assert_int_equal(st.arcs, 16);
    size_t ne;
    edge_count *e = count_edges(&m, &ne);
    int boundary = 0;
    for (size_t i = 0; i < ne; i++) {
        assert_true(e[i].forward <= 1 && e[i].backward <= 1);
        boundary += e[i].forward + e[i].backward == 1;
    }
    free(e);
    assert_int_equal(boundary,
                     2 * 20); /* the first and the last section: 2 arcs of 9 edges, 2 bridges */
    assert_int_equal((long)m.vertex_count - (long)ne + (long)m.triangle_count, 0);
    assert_faces_away_from_the_y_axis(&m);
    sk_mesh_free(&m);
    sk_hand_slices_free(&sl);
    sk_hand_cloud_free(&c);
}

static void test_neighbouring_slices_remove_the_wrinkles(void **state)
{
    (void)state;
    sk_hand_resample_stats st[2];
    /* without noise the tube's quads are flat unless the rings twist against each other,
       as the thesis's do when theta_min wanders from slice to slice */
    tube_folds(0.0, st);
    assert_true(st[0].fold_max_deg < 0.5);
    assert_true(st[1].fold_mean_deg > 2.0 && st[1].fold_max_deg > 10.0);
    /* with the scanner's noise the twist still dominates the worst folds */
    tube_folds(0.08, st);
    assert_true(st[0].fold_mean_deg < st[1].fold_mean_deg);
    assert_true(st[0].fold_max_deg < 0.6 * st[1].fold_max_deg);
}

/* ------------------------------------------------------------ the whole pipeline */

/* A stand-in hand for the pipeline's tests: a capsule around every link of the skeleton
 * (wide ones over the metacarpals so that they merge into a palm), the union meshed as
 * overlapping closed capsules, with its exact signed distance. */
typedef struct capsule_hand {
    int count;
    sk_vec3d a[SK_HAND_LINK_COUNT], b[SK_HAND_LINK_COUNT];
    double r[SK_HAND_LINK_COUNT];
} capsule_hand;

static double sdf_capsules(void *user, sk_vec3d p, sk_vec3d *g)
{
    const capsule_hand *h = user;
    double best = INFINITY;
    for (int k = 0; k < h->count; k++) {
        sk_vec3d ab = sk_v3d_sub(h->b[k], h->a[k]);
        double t = sk_v3d_dot(sk_v3d_sub(p, h->a[k]), ab) / sk_v3d_dot(ab, ab);
        t = t < 0 ? 0 : (t > 1 ? 1 : t);
        sk_vec3d q = sk_v3d_sub(p, sk_v3d_add(h->a[k], sk_v3d_scale(ab, t)));
        double len = sk_v3d_length(q), d = len - h->r[k];
        if (d < best) {
            best = d;
            if (g) *g = len > 0 ? sk_v3d_scale(q, 1.0 / len) : sk_v3d(0, 0, 1);
        }
    }
    return best;
}

static void make_capsule_hand(const sk_hand_skeleton *skel, const double *dofs, capsule_hand *h,
                              sk_mesh *m)
{
    sk_hand_frames f;
    sk_hand_forward(skel, dofs, &f);
    sk_hand_link_geometry g;
    sk_hand_link_geometry_from_frames(&f, &g);
    memset(m, 0, sizeof *m);
    h->count = SK_HAND_LINK_COUNT;
    static const double radius[SK_HAND_LINK_COUNT] = {22, 13, 10, 9,   12,  9,   8,  7, 12, 9,
                                                      8,  7,  12, 8.5, 7.5, 6.5, 11, 8, 7,  6};
    for (int l = 0; l < SK_HAND_LINK_COUNT; l++) {
        sk_vec3d a = g.a[l], b = g.b[l];
        if (l == 0) a = sk_v3d_sub(a, sk_v3d(0, 20, 0)); /* the wrist stump */
        h->a[l] = a, h->b[l] = b, h->r[l] = radius[l];
        if (l == 0) { /* a flat, wide carpus: two capsules side by side would be better; one
                         is enough here */
        }
        add_capsule(m, a, b, radius[l], 40, 8, 12);
    }
}

static void run_capsule_pipeline(int threads, sk_hand_scan_result *res)
{
    sk_hand_skeleton skel;
    sk_hand_skeleton_desc sd = {0};
    sk_error err;
    assert_int_equal(sk_hand_skeleton_init(&skel, &sd, &err), SK_OK);
    double q[SK_HAND_DOF_COUNT];
    sk_hand_scan_cast_pose(&skel, q);
    static capsule_hand h;
    sk_mesh m;
    make_capsule_hand(&skel, q, &h, &m);
    sk_hand_scan_target_desc td = {.mesh = &m, .sdf = sdf_capsules, .sdf_user = &h};
    sk_hand_scan_target *t;
    assert_int_equal(sk_hand_scan_target_create(&t, &td, &err), SK_OK);
    /* a coarser scan under the sanitizers keeps the test within seconds there */
    bool sanitized = getenv("SK_TEST_SANITIZED") != NULL;
    sk_hand_scan_desc d = {
        .scanner = {.lines = sanitized ? 200 : 320, .points = sanitized ? 160 : 256}, .seed = 5};
    sk_hand_scan_input in = {.target = t, .skeleton = &skel, .dofs = q};
    sk_threads_set(threads);
    sk_result r = sk_hand_scan_run(&in, &d, res, (sk_progress){0}, &err);
    sk_threads_set(0);
    if (r != SK_OK) fprintf(stderr, "%s\n", err.message);
    assert_int_equal(r, SK_OK);
    sk_hand_scan_target_destroy(t);
    free_mesh(&m);
}

static void test_pipeline_on_a_hand_of_capsules(void **state)
{
    (void)state;
    sk_hand_scan_result a, b;
    run_capsule_pipeline(1, &a);
    const sk_hand_registration *reg = &a.registration;
    /* registration: within the scanner's noise */
    assert_true(reg->rms_mm < 0.1);
    assert_true(reg->rotation_error_deg < 0.05 && reg->translation_error_mm < 0.1);
    for (int k = 0; k < 9; k++) assert_true(reg->palm_used[k] >= 6 && reg->back_used[k] >= 6);
    /* the merged cloud lies on the true surface (registration error + noise) */
    assert_true(a.cloud.count > 10000);
    /* patches: nearly all regions have data; errors of the thesis's order */
    assert_true(a.table.patches_fitted[0] >= 40 && a.table.patches_fitted[1] >= 40);
    assert_true(a.table.has_truth);
    for (int side = 0; side < 2; side++) {
        assert_true(a.table.scan[side].mean_mm > 0.01 && a.table.scan[side].mean_mm < 0.15);
        assert_true(a.table.truth[side].mean_mm < 0.15);
    }
    assert_true(a.polygons.vertex_count > 1000 && a.polygons.triangle_count > 1500);
    assert_true(a.polygons_stats.fold_mean_deg < a.polygons_thesis_stats.fold_mean_deg);
    /* the same for two threads, bit for bit */
    run_capsule_pipeline(2, &b);
    assert_int_equal(a.cloud.count, b.cloud.count);
    assert_memory_equal(a.cloud.position, b.cloud.position,
                        sizeof *a.cloud.position * a.cloud.count);
    assert_memory_equal(a.patches->patch, b.patches->patch, sizeof a.patches->patch);
    assert_memory_equal(&a.table, &b.table, sizeof a.table);
    assert_int_equal(a.polygons.vertex_count, b.polygons.vertex_count);
    assert_memory_equal(a.polygons.positions, b.polygons.positions,
                        sizeof(float) * 3 * a.polygons.vertex_count);
    sk_hand_scan_result_free(&a);
    sk_hand_scan_result_free(&b);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_ray_hierarchy_matches_brute_force),
        cmocka_unit_test(test_registration_recovers_a_known_transform),
        cmocka_unit_test(test_scanner_sees_what_is_visible_with_the_stated_noise),
        cmocka_unit_test(test_markers_are_found_where_they_are),
        cmocka_unit_test(test_resampled_tube_is_a_closed_manifold),
        cmocka_unit_test(test_rings_join_arcs_as_a_manifold),
        cmocka_unit_test(test_finger_joins_its_metacarpal),
        cmocka_unit_test(test_palm_strips_are_bridged),
        cmocka_unit_test(test_neighbouring_slices_remove_the_wrinkles),
        cmocka_unit_test(test_pipeline_on_a_hand_of_capsules),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
