/* Tests of the thesis's Bezier patches (sec. 4.1.4): the basis of eq. (4.3) with the
 * corrected G, least-squares fitting (4.4, 4.5) that reproduces a bicubic surface exactly,
 * parameter correction (4.6, 4.7) that never increases the error and recovers the true
 * parameters, the facet-split error measure of Table 4.1 against brute force, and control
 * points moving with their links. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "shitsukan/hand.h"
#include "shitsukan/io.h"
#include "test_support.h"

/* A curved, non-planar patch (a saddle over a bent sheet), mm. */
static sk_hand_patch reference_patch(void)
{
    sk_hand_patch p;
    memset(&p, 0, sizeof p);
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            double x = 10.0 * i, y = 8.0 * j;
            double z = 3.0 * sin(0.9 * i) - 2.0 * cos(1.1 * j) + 0.5 * i * j;
            p.p[i][j] = sk_v3d(x + 0.7 * j, y - 0.4 * i, z);
        }
    return p;
}

static void test_basis_is_bernstein_and_corners_interpolate(void **state)
{
    (void)state;
    /* u^T G with G's last row [-1 3 -3 1] (the printed +1 is a misprint) */
    static const double g[4][4] = {{1, 0, 0, 0}, {-3, 3, 0, 0}, {3, -6, 3, 0}, {-1, 3, -3, 1}};
    for (int s = 0; s <= 10; s++) {
        double t = s / 10.0, mono[4] = {1, t, t * t, t * t * t}, b[4], sum = 0;
        sk_hand_bernstein3(t, b);
        for (int c = 0; c < 4; c++) {
            double expect = 0;
            for (int r = 0; r < 4; r++) expect += mono[r] * g[r][c];
            assert_true(fabs(b[c] - expect) < 1e-14);
            sum += b[c];
        }
        assert_true(fabs(sum - 1.0) < 1e-14); /* partition of unity */
    }
    sk_hand_patch p = reference_patch();
    sk_vec3d q = sk_hand_patch_eval(&p, 0, 0, NULL, NULL);
    assert_true(sk_v3d_length(sk_v3d_sub(q, p.p[0][0])) < 1e-12);
    q = sk_hand_patch_eval(&p, 1, 1, NULL, NULL);
    assert_true(sk_v3d_length(sk_v3d_sub(q, p.p[3][3])) < 1e-12);
    q = sk_hand_patch_eval(&p, 1, 0, NULL, NULL);
    assert_true(sk_v3d_length(sk_v3d_sub(q, p.p[3][0])) < 1e-12);
    /* derivatives against central differences */
    sk_vec3d du, dv;
    sk_hand_patch_eval(&p, 0.3, 0.6, &du, &dv);
    double h = 1e-6;
    sk_vec3d fu = sk_v3d_scale(sk_v3d_sub(sk_hand_patch_eval(&p, 0.3 + h, 0.6, NULL, NULL),
                                          sk_hand_patch_eval(&p, 0.3 - h, 0.6, NULL, NULL)),
                               0.5 / h);
    sk_vec3d fv = sk_v3d_scale(sk_v3d_sub(sk_hand_patch_eval(&p, 0.3, 0.6 + h, NULL, NULL),
                                          sk_hand_patch_eval(&p, 0.3, 0.6 - h, NULL, NULL)),
                               0.5 / h);
    assert_true(sk_v3d_length(sk_v3d_sub(du, fu)) < 1e-6);
    assert_true(sk_v3d_length(sk_v3d_sub(dv, fv)) < 1e-6);
}

/* n x n points of the reference patch at jittered parameters. */
static void sample_patch(const sk_hand_patch *p, int n, sk_vec3d *pts, double *u, double *v)
{
    for (int a = 0; a < n; a++)
        for (int b = 0; b < n; b++) {
            int k = a * n + b;
            double ju = (sk_rand_uniform(7, (uint64_t)a, (uint64_t)b, 0) - 0.5) * 0.5 / n;
            double jv = (sk_rand_uniform(7, (uint64_t)a, (uint64_t)b, 1) - 0.5) * 0.5 / n;
            u[k] = (a + 0.5) / n + ju;
            v[k] = (b + 0.5) / n + jv;
            pts[k] = sk_hand_patch_eval(p, u[k], v[k], NULL, NULL);
        }
}

static void test_fit_reproduces_a_bicubic_surface_exactly(void **state)
{
    (void)state;
    sk_hand_patch ref = reference_patch(), fit;
    memset(&fit, 0, sizeof fit);
    enum { N = 12 };
    sk_vec3d pts[N * N];
    double u[N * N], v[N * N];
    sample_patch(&ref, N, pts, u, v);
    sk_hand_patch_fit_desc d = {.no_correction = true};
    sk_hand_patch_fit_info info;
    sk_error err;
    assert_int_equal(sk_hand_patch_fit(pts, N * N, u, v, &d, &fit, &info, NULL, &err), SK_OK);
    assert_false(info.regularised);
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            assert_true(sk_v3d_length(sk_v3d_sub(fit.p[i][j], ref.p[i][j])) < 1e-9);
    assert_true(info.rms_final_mm < 1e-10);
}

static void test_parameter_correction_never_increases_the_error(void **state)
{
    (void)state;
    sk_hand_patch ref = reference_patch(), fit;
    memset(&fit, 0, sizeof fit);
    enum { N = 14 };
    sk_vec3d pts[N * N];
    double u[N * N], v[N * N], u_true[N * N], v_true[N * N];
    sample_patch(&ref, N, pts, u_true, v_true);
    /* start from chord-length parameters along rows of constant a (as 4.4) and v from
       the row index: not the true ones */
    for (int a = 0; a < N; a++) {
        sk_vec3d row[N];
        double ur[N];
        for (int b = 0; b < N; b++) row[b] = pts[a * N + b];
        sk_hand_chord_parameters(row, N, ur);
        assert_true(ur[0] == 0.0 && ur[N - 1] == 1.0);
        for (int b = 0; b < N; b++) {
            v[a * N + b] = ur[b]; /* along a row b varies: that is v here */
            u[a * N + b] = (double)a / (N - 1);
        }
    }
    double history[201];
    sk_hand_patch_fit_desc d = {.max_iterations = 200, .tolerance = 1e-9};
    sk_hand_patch_fit_info info;
    sk_error err;
    assert_int_equal(sk_hand_patch_fit(pts, N * N, u, v, &d, &fit, &info, history, &err), SK_OK);
    assert_true(info.iterations >= 2);
    for (int k = 1; k <= info.iterations; k++)
        assert_true(history[k] <= history[k - 1] * (1 + 1e-12) + 1e-15);
    /* the chord-length start is visibly off; the correction brings it to the surface */
    assert_true(info.rms_initial_mm > 1e-3);
    assert_true(info.rms_final_mm < 0.05 * info.rms_initial_mm);
    /* and a fit with correction is never worse than without */
    sk_hand_patch plain;
    memset(&plain, 0, sizeof plain);
    for (int a = 0; a < N; a++) {
        sk_vec3d row[N];
        double ur[N];
        for (int b = 0; b < N; b++) row[b] = pts[a * N + b];
        sk_hand_chord_parameters(row, N, ur);
        for (int b = 0; b < N; b++) v[a * N + b] = ur[b], u[a * N + b] = (double)a / (N - 1);
    }
    sk_hand_patch_fit_desc nd = {.no_correction = true};
    sk_hand_patch_fit_info pinfo;
    assert_int_equal(sk_hand_patch_fit(pts, N * N, u, v, &nd, &plain, &pinfo, NULL, &err), SK_OK);
    assert_true(info.rms_final_mm <= pinfo.rms_final_mm);
}

static void test_fit_rejects_bad_input(void **state)
{
    (void)state;
    sk_vec3d pts[20];
    double u[20], v[20];
    for (int k = 0; k < 20; k++) pts[k] = sk_v3d(k, k * k, 1), u[k] = k / 19.0, v[k] = 0.5;
    sk_hand_patch p;
    memset(&p, 0, sizeof p);
    sk_error err;
    assert_int_equal(sk_hand_patch_fit(pts, 10, u, v, NULL, &p, NULL, NULL, &err),
                     SK_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(err.message, "16 or more"));
    u[3] = 1.5;
    assert_int_equal(sk_hand_patch_fit(pts, 20, u, v, NULL, &p, NULL, NULL, &err),
                     SK_ERROR_INVALID_ARGUMENT);
    u[3] = 3 / 19.0;
    pts[4].x = NAN;
    assert_int_equal(sk_hand_patch_fit(pts, 20, u, v, NULL, &p, NULL, NULL, &err),
                     SK_ERROR_INVALID_ARGUMENT);
    pts[4].x = 4;
    sk_hand_patch_fit_desc d = {.max_iterations = -3};
    assert_int_equal(sk_hand_patch_fit(pts, 20, u, v, &d, &p, NULL, NULL, &err),
                     SK_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(err.message, "fit.max_iterations"));
    /* all points on one v line: singular normal equations, solved with a tiny ridge */
    sk_hand_patch_fit_info info;
    assert_int_equal(sk_hand_patch_fit(pts, 20, u, v, NULL, &p, &info, NULL, &err), SK_OK);
    assert_true(info.regularised);
}

static double segment_distance(sk_vec3d q, sk_vec3d a, sk_vec3d b)
{
    sk_vec3d ab = sk_v3d_sub(b, a);
    double t = sk_v3d_dot(sk_v3d_sub(q, a), ab) / sk_v3d_dot(ab, ab);
    t = t < 0 ? 0 : (t > 1 ? 1 : t);
    return sk_v3d_length(sk_v3d_sub(q, sk_v3d_add(a, sk_v3d_scale(ab, t))));
}

/* Distance to a triangle the plain way: the plane if the foot is inside (barycentric
 * coordinates), else the nearest edge. */
static double triangle_distance(sk_vec3d q, sk_vec3d a, sk_vec3d b, sk_vec3d c)
{
    sk_vec3d n = sk_v3d_cross(sk_v3d_sub(b, a), sk_v3d_sub(c, a));
    double area2 = sk_v3d_dot(n, n);
    double h = sk_v3d_dot(sk_v3d_sub(q, a), n) / area2;
    sk_vec3d f = sk_v3d_sub(q, sk_v3d_scale(n, h));
    double wa = sk_v3d_dot(sk_v3d_cross(sk_v3d_sub(b, f), sk_v3d_sub(c, f)), n) / area2;
    double wb = sk_v3d_dot(sk_v3d_cross(sk_v3d_sub(c, f), sk_v3d_sub(a, f)), n) / area2;
    double wc = 1.0 - wa - wb;
    if (wa >= 0 && wb >= 0 && wc >= 0) return fabs(h) * sqrt(area2);
    double d = segment_distance(q, a, b), e = segment_distance(q, b, c),
           g = segment_distance(q, c, a);
    return d < e ? (d < g ? d : g) : (e < g ? e : g);
}

/* Brute-force distance to the facets of a patch split n x n. */
static double brute_facet_distance(const sk_hand_patch *p, int n, sk_vec3d q)
{
    double best = INFINITY;
    for (int a = 0; a < n; a++)
        for (int b = 0; b < n; b++) {
            sk_vec3d v00 = sk_hand_patch_eval(p, (double)a / n, (double)b / n, NULL, NULL);
            sk_vec3d v10 = sk_hand_patch_eval(p, (double)(a + 1) / n, (double)b / n, NULL, NULL);
            sk_vec3d v11 =
                sk_hand_patch_eval(p, (double)(a + 1) / n, (double)(b + 1) / n, NULL, NULL);
            sk_vec3d v01 = sk_hand_patch_eval(p, (double)a / n, (double)(b + 1) / n, NULL, NULL);
            double d1 = triangle_distance(q, v00, v10, v11),
                   d2 = triangle_distance(q, v00, v11, v01);
            if (d1 < best) best = d1;
            if (d2 < best) best = d2;
        }
    return best;
}

static void test_facet_distance_is_the_nearest_facet(void **state)
{
    (void)state;
    sk_hand_patch p = reference_patch();
    enum { K = 40, SPLITS = 10 };
    sk_vec3d q[K];
    double u[K], v[K], d_hint[K], d_plain[K];
    for (int k = 0; k < K; k++) {
        u[k] = sk_rand_uniform(3, (uint64_t)k, 0, 0);
        v[k] = sk_rand_uniform(3, (uint64_t)k, 1, 0);
        sk_vec3d du, dv;
        sk_vec3d s = sk_hand_patch_eval(&p, u[k], v[k], &du, &dv);
        sk_vec3d n = sk_v3d_normalize(sk_v3d_cross(du, dv));
        double off = (sk_rand_uniform(3, (uint64_t)k, 2, 0) - 0.5) * (k < K / 2 ? 0.2 : 20.0);
        q[k] = sk_v3d_add(s, sk_v3d_scale(n, off));
        /* a hint that is wrong for some points: the search must not depend on it */
        if (k % 5 == 0) u[k] = 1.0 - u[k];
    }
    sk_error err;
    assert_int_equal(sk_hand_patch_facet_distances(&p, SPLITS, q, K, u, v, d_hint, &err), SK_OK);
    assert_int_equal(sk_hand_patch_facet_distances(&p, SPLITS, q, K, NULL, NULL, d_plain, &err),
                     SK_OK);
    for (int k = 0; k < K; k++) {
        double brute = brute_facet_distance(&p, SPLITS, q[k]);
        assert_true(d_hint[k] == d_plain[k]);
        assert_true(fabs(d_hint[k] - brute) < 1e-9);
    }
    /* points on the patch are within the facets' sag of it (100 x 100: tiny) */
    double on[K];
    for (int k = 0; k < K; k++) q[k] = sk_hand_patch_eval(&p, u[k], v[k], NULL, NULL);
    assert_int_equal(sk_hand_patch_facet_distances(&p, 100, q, K, u, v, on, &err), SK_OK);
    for (int k = 0; k < K; k++) assert_true(on[k] < 2e-3);
    assert_int_equal(sk_hand_patch_facet_distances(&p, 5000, q, K, u, v, on, &err),
                     SK_ERROR_INVALID_ARGUMENT);
}

/* ------------------------------------------------------------ with their links */

static void two_poses(sk_hand_frames *rest, sk_hand_frames *pose)
{
    sk_hand_skeleton skel;
    sk_hand_skeleton_desc sd = {0};
    sk_error err;
    assert_int_equal(sk_hand_skeleton_init(&skel, &sd, &err), SK_OK);
    double q[SK_HAND_DOF_COUNT];
    sk_hand_relaxed(&skel, q);
    sk_hand_forward(&skel, q, rest);
    q[sk_hand_dof_find("I.MCP.flex")] += 0.6;
    q[sk_hand_dof_find("I.PIP.flex")] += 0.9;
    q[sk_hand_dof_find("wrist.roll")] += 0.3;
    sk_hand_forward(&skel, q, pose);
}

static void test_control_points_move_with_their_links(void **state)
{
    (void)state;
    sk_hand_frames rest, pose;
    two_poses(&rest, &pose);
    sk_hand_patch p = reference_patch(), moved, same;
    p.link = 6; /* the index middle phalanx */
    sk_error err;
    /* at rest nothing moves */
    assert_int_equal(sk_hand_patches_pose(&p, 1, &rest, &rest, NULL, &same, &err), SK_OK);
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            assert_true(sk_v3d_length(sk_v3d_sub(same.p[i][j], p.p[i][j])) < 1e-9);
    /* rigidly: distances kept, and the link's base joint carries the patch along */
    assert_int_equal(sk_hand_patches_pose(&p, 1, &rest, &pose, NULL, &moved, &err), SK_OK);
    for (int a = 0; a < 16; a++)
        for (int b = 0; b < 16; b++) {
            double d0 = sk_v3d_length(sk_v3d_sub(p.p[a / 4][a % 4], p.p[b / 4][b % 4]));
            double d1 = sk_v3d_length(sk_v3d_sub(moved.p[a / 4][a % 4], moved.p[b / 4][b % 4]));
            assert_true(fabs(d0 - d1) < 1e-9);
        }
    int base = sk_hand_link_point(6);
    sk_vec3d rel0 = sk_v3d_sub(p.p[0][0], rest.point[base]),
             rel1 = sk_v3d_sub(moved.p[0][0], pose.point[base]);
    /* the same point in the link's own frame before and after */
    sk_vec3d l0 = sk_m3d_apply(sk_m3d_transpose(rest.rotation[6]), rel0);
    sk_vec3d l1 = sk_m3d_apply(sk_m3d_transpose(pose.rotation[6]), rel1);
    assert_true(sk_v3d_length(sk_v3d_sub(l0, l1)) < 1e-9);
    /* all weight on the patch's own link is the rigid motion; half on two links is the
       mean of the two rigid motions */
    sk_hand_patch_weights w[16];
    for (int c = 0; c < 16; c++) w[c] = (sk_hand_patch_weights){{6, -1, -1, -1}, {1, 0, 0, 0}};
    sk_hand_patch blend;
    assert_int_equal(sk_hand_patches_pose(&p, 1, &rest, &pose, w, &blend, &err), SK_OK);
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            assert_true(sk_v3d_length(sk_v3d_sub(blend.p[i][j], moved.p[i][j])) < 1e-9);
    sk_hand_patch other = p, moved_other;
    other.link = 5;
    assert_int_equal(sk_hand_patches_pose(&other, 1, &rest, &pose, NULL, &moved_other, &err),
                     SK_OK);
    for (int c = 0; c < 16; c++) w[c] = (sk_hand_patch_weights){{6, 5, -1, -1}, {0.5f, 0.5f, 0, 0}};
    assert_int_equal(sk_hand_patches_pose(&p, 1, &rest, &pose, w, &blend, &err), SK_OK);
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            sk_vec3d mean = sk_v3d_scale(sk_v3d_add(moved.p[i][j], moved_other.p[i][j]), 0.5);
            assert_true(sk_v3d_length(sk_v3d_sub(blend.p[i][j], mean)) < 1e-6);
        }
    /* bad weights and links are refused, naming the entry */
    w[3].weight[0] = -1.0f;
    assert_int_equal(sk_hand_patches_pose(&p, 1, &rest, &pose, w, &blend, &err),
                     SK_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(err.message, "weights[3]"));
    w[3] = (sk_hand_patch_weights){{-1, -1, -1, -1}, {0, 0, 0, 0}};
    assert_int_equal(sk_hand_patches_pose(&p, 1, &rest, &pose, w, &blend, &err),
                     SK_ERROR_INVALID_ARGUMENT);
    p.link = 40;
    assert_int_equal(sk_hand_patches_pose(&p, 1, &rest, &pose, NULL, &blend, &err),
                     SK_ERROR_INVALID_ARGUMENT);
}

static void test_tessellation_and_the_table(void **state)
{
    (void)state;
    sk_hand_patch p[2] = {reference_patch(), reference_patch()};
    sk_mesh m;
    sk_error err;
    assert_int_equal(sk_hand_patches_tessellate(p, 2, 8, &m, &err), SK_OK);
    assert_int_equal(m.vertex_count, 2 * 81);
    assert_int_equal(m.triangle_count, 2 * 2 * 64);
    /* vertices on the patch, no vertex shared between patches, normals along S_u x S_v */
    for (size_t v = 0; v < m.vertex_count; v++) {
        double u = m.uvs[2 * v], w = m.uvs[2 * v + 1];
        sk_vec3d du, dv;
        sk_vec3d q = sk_hand_patch_eval(&p[0], u, w, &du, &dv);
        assert_true(fabs(q.x - m.positions[3 * v]) < 1e-4 &&
                    fabs(q.z - m.positions[3 * v + 2]) < 1e-4);
        sk_vec3d n = sk_v3d_normalize(sk_v3d_cross(du, dv));
        assert_true(n.x * m.normals[3 * v] + n.y * m.normals[3 * v + 1] +
                        n.z * m.normals[3 * v + 2] >
                    0.999);
        assert_int_equal((int)m.attributes[0].data[v], (int)(v / 81));
    }
    for (size_t t = 0; t < m.triangle_count; t++) {
        /* a triangle's face normal agrees with its vertices' normals */
        const uint32_t *ix = m.indices + 3 * t;
        const float *a = m.positions + 3 * ix[0], *b = m.positions + 3 * ix[1],
                    *c = m.positions + 3 * ix[2];
        sk_vec3d fn = sk_v3d_cross(sk_v3d(b[0] - a[0], b[1] - a[1], b[2] - a[2]),
                                   sk_v3d(c[0] - a[0], c[1] - a[1], c[2] - a[2]));
        const float *vn = m.normals + 3 * ix[0];
        assert_true(fn.x * vn[0] + fn.y * vn[1] + fn.z * vn[2] > 0);
        assert_true(ix[0] / 81 == ix[1] / 81 && ix[1] / 81 == ix[2] / 81);
    }
    sk_mesh_free(&m);
    assert_int_equal(sk_hand_patches_tessellate(p, 2, 300, &m, &err), SK_ERROR_INVALID_ARGUMENT);
    /* Table 4.1 from per-point errors: means over (patch, point) pairs, per side */
    static sk_hand_patch_set set;
    memset(&set, 0, sizeof set);
    set.count = SK_HAND_PATCH_COUNT;
    double e0[3] = {0.1, 0.2, 0.3}, e1[2] = {0.5, 1.5};
    set.patch[0].side = SK_HAND_SCAN_PALM, set.fitted[0] = true, set.data[0].count = 3,
    set.error_scan[0] = e0;
    set.patch[50].side = SK_HAND_SCAN_BACK, set.fitted[50] = true, set.data[50].count = 2,
    set.error_scan[50] = e1;
    sk_hand_table41 t;
    sk_hand_table41_compute(&set, &t);
    assert_true(fabs(t.scan[0].mean_mm - 0.2) < 1e-12 && t.scan[0].max_mm == 0.3 &&
                t.scan[0].worst_patch == 0);
    assert_true(fabs(t.scan[1].mean_mm - 1.0) < 1e-12 && t.scan[1].max_mm == 1.5 &&
                t.scan[1].worst_patch == 50);
    assert_true(fabs(t.scan_all.mean_mm - 2.6 / 5) < 1e-12 && t.scan_all.points == 5);
    assert_false(t.has_truth);
    assert_int_equal(t.patches_fitted[0], 1);
    /* and its files beside the thesis's figures */
    const char *json = sk_test_path("table/table-4.1.json"),
               *txt = sk_test_path("table/table-4.1.txt");
    assert_int_equal(sk_hand_table41_write_json(&t, json, &err), SK_OK);
    assert_int_equal(sk_hand_table41_write_text(&t, txt, &err), SK_OK);
    char *text = NULL;
    size_t size;
    assert_int_equal(sk_read_file(txt, 0, &text, &size, &err), SK_OK);
    assert_non_null(strstr(text, "3.6"));  /* the thesis's palm maximum */
    assert_non_null(strstr(text, "0.43")); /* its back maximum */
    assert_non_null(strstr(text, "palm"));
    free(text);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_basis_is_bernstein_and_corners_interpolate),
        cmocka_unit_test(test_fit_reproduces_a_bicubic_surface_exactly),
        cmocka_unit_test(test_parameter_correction_never_increases_the_error),
        cmocka_unit_test(test_fit_rejects_bad_input),
        cmocka_unit_test(test_facet_distance_is_the_nearest_facet),
        cmocka_unit_test(test_control_points_move_with_their_links),
        cmocka_unit_test(test_tessellation_and_the_table),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
