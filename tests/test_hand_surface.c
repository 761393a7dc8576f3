/* Tests of the hand surface (thesis 4.1 on a surface built from the skeleton): the flesh
 * data file, the mesh's topology (closed, manifold, genus 0, outward, no
 * self-intersection), the mirror image, the implicit field's distance, skin weights,
 * rigid / LBS / DQS deformation (rigidity, candy-wrapper), the defect measure, levels of
 * detail, the atlas and determinism across thread counts. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "shitsukan/hand.h"
#include "shitsukan/io.h"
#include "test_support.h"

typedef struct fixture {
    sk_hand_skeleton right, left;
    sk_hand_surface *surface, *small, *mirror;
} fixture;

static fixture *fx;

static int setup(void **state)
{
    (void)state;
    fx = calloc(1, sizeof *fx);
    sk_hand_skeleton_desc d = {0};
    sk_error err = {0};
    if (sk_hand_skeleton_init(&fx->right, &d, &err) != SK_OK) return -1;
    d.side = SK_HAND_SIDE_LEFT;
    if (sk_hand_skeleton_init(&fx->left, &d, &err) != SK_OK) return -1;
    if (sk_hand_surface_create(&fx->surface, &fx->right, NULL, &err) != SK_OK) {
        fprintf(stderr, "%s\n", err.message);
        return -1;
    }
    /* the mirror test compares a smaller right and left pair (the same desc) */
    sk_hand_surface_desc small = {.triangles = 2000, .cell_mm = 3.0};
    if (sk_hand_surface_create(&fx->small, &fx->right, &small, &err) != SK_OK) return -1;
    if (sk_hand_surface_create(&fx->mirror, &fx->left, &small, &err) != SK_OK) return -1;
    return 0;
}

static int teardown(void **state)
{
    (void)state;
    sk_hand_surface_destroy(fx->surface);
    sk_hand_surface_destroy(fx->small);
    sk_hand_surface_destroy(fx->mirror);
    free(fx);
    return 0;
}

/* ------------------------------------------------------------ flesh file */
static void test_flesh_file_matches_builtin(void **state)
{
    (void)state;
    char path[512];
    snprintf(path, sizeof path, "%s/hand/flesh.json", SK_TEST_PRESET_DIR);
    sk_hand_flesh file, builtin;
    sk_error err = {0};
    sk_result r = sk_hand_flesh_load_file(path, &file, &err);
    if (r != SK_OK) fprintf(stderr, "%s\n", err.message);
    assert_int_equal(r, SK_OK);
    /* the parser starts from the built-in values: change them to see that every
       value is in the file */
    sk_hand_flesh_default(&builtin);
    assert_memory_equal(&file, &builtin, sizeof file);
}

static void test_flesh_errors(void **state)
{
    (void)state;
    sk_hand_flesh f;
    sk_error err = {0};
    const char *bad[] = {
        "{\"fingers\": {\"X\": {}}}",
        "{\"fingers\": {\"I\": {\"breadth_mm\": [20, 20, 20]}}}",
        "{\"fingers\": {\"I\": {\"breadth_mm\": [20, 20, 20, 200]}}}",
        "{\"wrist\": {\"breadth_mm\": -3}}",
        "{\"webs\": {\"reach\": 0.9}}",
        "{\"nails\": {\"colour\": 1}}",
        "{\"blend\": {\"joint_mm\": \"x\"}}",
        "{\"thenar\": {\"radius_mm\": [1, 2]}}",
        "[1, 2]",
        "{\"reference_breadth_mm\": 1e400}",
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        sk_result r = sk_hand_flesh_parse(bad[i], strlen(bad[i]), "t.json", &f, &err);
        assert_int_not_equal(r, SK_OK);
        assert_non_null(strstr(err.message, "t.json"));
    }
    sk_hand_flesh_parse("{\"fingers\": {\"I\": {\"breadth_mm\": [20, 20, 20, 200]}}}", 50, "t.json",
                        &f, &err);
    const char *ok =
        "{\"fingers\": {\"M\": {\"thickness_mm\": [21, 19, 16, 13]}}, \"blend\": {\"root_mm\": 4}}";
    assert_int_equal(sk_hand_flesh_parse(ok, strlen(ok), "t.json", &f, &err), SK_OK);
    assert_true(f.finger[SK_HAND_MIDDLE].thickness_mm[1] == 19 && f.blend_root_mm == 4);
}

/* ------------------------------------------------------------ topology */
typedef struct edge {
    uint32_t a, b, c; /* directed edge a -> b of triangle (a, b, c) */
} edge;
static int edge_cmp(const void *x, const void *y)
{
    const edge *p = x, *q = y;
    if (p->a != q->a) return p->a < q->a ? -1 : 1;
    return p->b < q->b ? -1 : (p->b > q->b);
}

/* Closed oriented 2-manifold: every directed edge once, with its reverse; every vertex's
 * triangles one fan (a disc, not two fans touching at the vertex). Returns the Euler
 * characteristic. */
static long check_manifold(const sk_mesh *m)
{
    size_t T = m->triangle_count, V = m->vertex_count;
    edge *e = malloc(3 * T * sizeof *e);
    for (size_t t = 0; t < T; t++)
        for (int k = 0; k < 3; k++) {
            e[3 * t + k].a = m->indices[3 * t + k];
            e[3 * t + k].b = m->indices[3 * t + (k + 1) % 3];
            e[3 * t + k].c = m->indices[3 * t + (k + 2) % 3];
            assert_int_not_equal(e[3 * t + k].a, e[3 * t + k].b);
        }
    qsort(e, 3 * T, sizeof *e, edge_cmp);
    for (size_t i = 0; i + 1 < 3 * T; i++)
        assert_false(e[i].a == e[i + 1].a && e[i].b == e[i + 1].b);
    for (size_t i = 0; i < 3 * T; i++) {
        edge rev = {e[i].b, e[i].a, 0};
        assert_non_null(bsearch(&rev, e, 3 * T, sizeof *e, edge_cmp));
    }
    /* around v, triangle (v, w, x) leads from neighbour w to x: from one outgoing edge
       the walk must visit all of v's triangles before it comes back */
    size_t lo = 0;
    for (size_t v = 0; v < V; v++) {
        assert_true(lo < 3 * T && e[lo].a == v); /* every vertex is used */
        size_t hi = lo;
        while (hi < 3 * T && e[hi].a == v) hi++;
        assert_true(hi - lo >= 3);
        uint32_t w = e[lo].b;
        size_t steps = 0;
        do {
            edge key = {(uint32_t)v, w, 0};
            const edge *d = bsearch(&key, e + lo, hi - lo, sizeof *e, edge_cmp);
            assert_non_null(d);
            w = d->c;
            steps++;
        } while (w != e[lo].b && steps <= hi - lo);
        assert_int_equal(steps, hi - lo);
        lo = hi;
    }
    free(e);
    return (long)V - (long)(3 * T / 2) + (long)T;
}

static double signed_volume(const sk_mesh *m)
{
    double vol = 0;
    for (size_t t = 0; t < m->triangle_count; t++) {
        const float *a = m->positions + 3 * m->indices[3 * t],
                    *b = m->positions + 3 * m->indices[3 * t + 1],
                    *c = m->positions + 3 * m->indices[3 * t + 2];
        vol += a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
               a[2] * (b[0] * c[1] - b[1] * c[0]);
    }
    return vol / 6.0;
}

static void test_mesh_closed_manifold_genus0(void **state)
{
    (void)state;
    const sk_mesh *m = sk_hand_surface_mesh(fx->surface);
    assert_true(m->triangle_count >= 7900 && m->triangle_count <= 8000);
    assert_int_equal(check_manifold(m), 2);
    assert_true(signed_volume(m) > 2e5); /* outward: a hand is a few hundred cm^3 */
    assert_true(signed_volume(m) < 8e5);
    assert_int_equal(sk_mesh_validate(m, NULL), SK_OK);
}

/* Segment pq crosses triangle abc strictly inside (Moller-Trumbore). */
static bool segment_hits(const double *p, const double *q, const double *a, const double *b,
                         const double *c)
{
    double d[3], e1[3], e2[3], h[3], s[3], qv[3];
    for (int k = 0; k < 3; k++) d[k] = q[k] - p[k], e1[k] = b[k] - a[k], e2[k] = c[k] - a[k];
    h[0] = d[1] * e2[2] - d[2] * e2[1], h[1] = d[2] * e2[0] - d[0] * e2[2],
    h[2] = d[0] * e2[1] - d[1] * e2[0];
    double det = e1[0] * h[0] + e1[1] * h[1] + e1[2] * h[2];
    if (fabs(det) < 1e-12) return false;
    double inv = 1.0 / det;
    for (int k = 0; k < 3; k++) s[k] = p[k] - a[k];
    double u = inv * (s[0] * h[0] + s[1] * h[1] + s[2] * h[2]);
    if (u <= 1e-9 || u >= 1 - 1e-9) return false;
    qv[0] = s[1] * e1[2] - s[2] * e1[1], qv[1] = s[2] * e1[0] - s[0] * e1[2],
    qv[2] = s[0] * e1[1] - s[1] * e1[0];
    double v = inv * (d[0] * qv[0] + d[1] * qv[1] + d[2] * qv[2]);
    if (v <= 1e-9 || u + v >= 1 - 1e-9) return false;
    double t = inv * (e2[0] * qv[0] + e2[1] * qv[1] + e2[2] * qv[2]);
    return t > 1e-9 && t < 1 - 1e-9;
}

/* Pairs of triangles without a shared vertex that cross (uniform grid of bounds). */
static int count_self_intersections(const sk_mesh *m)
{
    size_t T = m->triangle_count;
    sk_vec3f lo, hi;
    sk_mesh_bounds(m, &lo, &hi);
    const double cell = 6.0;
    int nx = (int)((hi.x - lo.x) / cell) + 1, ny = (int)((hi.y - lo.y) / cell) + 1,
        nz = (int)((hi.z - lo.z) / cell) + 1;
    size_t cells = (size_t)nx * ny * nz;
    int *head = malloc(cells * sizeof *head), *next = malloc(T * sizeof *next);
    for (size_t i = 0; i < cells; i++) head[i] = -1;
    /* each triangle in the cell of its centroid (triangles are smaller than a cell) */
    for (size_t t = 0; t < T; t++) {
        double c[3] = {0, 0, 0};
        for (int k = 0; k < 3; k++)
            for (int j = 0; j < 3; j++) c[j] += m->positions[3 * m->indices[3 * t + k] + j] / 3.0;
        int ix = (int)((c[0] - lo.x) / cell), iy = (int)((c[1] - lo.y) / cell),
            iz = (int)((c[2] - lo.z) / cell);
        size_t id = ((size_t)iz * ny + iy) * nx + ix;
        next[t] = head[id];
        head[id] = (int)t;
    }
    int hits = 0;
    for (size_t t = 0; t < T; t++) {
        const uint32_t *A = m->indices + 3 * t;
        double pa[3][3];
        double c[3] = {0, 0, 0};
        for (int k = 0; k < 3; k++)
            for (int j = 0; j < 3; j++)
                pa[k][j] = m->positions[3 * A[k] + j], c[j] += pa[k][j] / 3.0;
        int ix = (int)((c[0] - lo.x) / cell), iy = (int)((c[1] - lo.y) / cell),
            iz = (int)((c[2] - lo.z) / cell);
        for (int dz = -1; dz <= 1; dz++)
            for (int dy = -1; dy <= 1; dy++)
                for (int dx = -1; dx <= 1; dx++) {
                    int x = ix + dx, y = iy + dy, z = iz + dz;
                    if (x < 0 || y < 0 || z < 0 || x >= nx || y >= ny || z >= nz) continue;
                    for (int u = head[((size_t)z * ny + y) * nx + x]; u >= 0; u = next[u]) {
                        if ((size_t)u <= t) continue;
                        const uint32_t *B = m->indices + 3 * (size_t)u;
                        bool shares = false;
                        for (int i = 0; i < 3; i++)
                            for (int j = 0; j < 3; j++) shares |= A[i] == B[j];
                        if (shares) continue;
                        double pb[3][3];
                        for (int k = 0; k < 3; k++)
                            for (int j = 0; j < 3; j++) pb[k][j] = m->positions[3 * B[k] + j];
                        bool hit = false;
                        for (int k = 0; k < 3 && !hit; k++) {
                            hit = segment_hits(pa[k], pa[(k + 1) % 3], pb[0], pb[1], pb[2]) ||
                                  segment_hits(pb[k], pb[(k + 1) % 3], pa[0], pa[1], pa[2]);
                        }
                        hits += hit;
                    }
                }
    }
    free(head);
    free(next);
    return hits;
}

static void test_mesh_no_self_intersection(void **state)
{
    (void)state;
    assert_int_equal(count_self_intersections(sk_hand_surface_mesh(fx->surface)), 0);
}

/* The test can fail: two crossing triangles are found. */
static void test_self_intersection_check_finds_crossing(void **state)
{
    (void)state;
    sk_mesh m;
    assert_int_equal(sk_mesh_create(&m, 6, 2, 0, NULL), SK_OK);
    float p[18] = {0, 0, 0, 2, 0, 0, 0, 2, 0, 0.5, 0.5, -1, 0.5, 0.5, 1, 1.5, 1.5, 0};
    memcpy(m.positions, p, sizeof p);
    uint32_t idx[6] = {0, 1, 2, 3, 4, 5};
    memcpy(m.indices, idx, sizeof idx);
    assert_int_equal(count_self_intersections(&m), 1);
    sk_mesh_free(&m);
}

static void test_left_is_exact_mirror(void **state)
{
    (void)state;
    const sk_mesh *r = sk_hand_surface_mesh(fx->small), *l = sk_hand_surface_mesh(fx->mirror);
    assert_int_equal(r->vertex_count, l->vertex_count);
    assert_int_equal(r->triangle_count, l->triangle_count);
    for (size_t v = 0; v < r->vertex_count; v++) {
        assert_true(l->positions[3 * v] == -r->positions[3 * v]);
        assert_true(l->positions[3 * v + 1] == r->positions[3 * v + 1]);
        assert_true(l->positions[3 * v + 2] == r->positions[3 * v + 2]);
        assert_true(l->normals[3 * v] == -r->normals[3 * v]);
    }
    for (size_t t = 0; t < r->triangle_count; t++) {
        assert_int_equal(l->indices[3 * t], r->indices[3 * t]);
        assert_int_equal(l->indices[3 * t + 1], r->indices[3 * t + 2]);
        assert_int_equal(l->indices[3 * t + 2], r->indices[3 * t + 1]);
    }
    assert_true(signed_volume(l) > 0);
    /* posed: the same DOF values give the mirror image */
    double q[SK_HAND_DOF_COUNT];
    sk_hand_relaxed(&fx->right, q);
    q[sk_hand_dof_find("I.PIP.flex")] = 1.2;
    q[sk_hand_dof_find("wrist.dev")] = 0.3;
    sk_mesh pr, pl;
    assert_int_equal(sk_hand_surface_pose(fx->small, q, SK_HAND_SKINNING_DQS, &pr, NULL), SK_OK);
    assert_int_equal(sk_hand_surface_pose(fx->mirror, q, SK_HAND_SKINNING_DQS, &pl, NULL), SK_OK);
    for (size_t v = 0; v < pr.vertex_count; v++) {
        assert_float_equal(pl.positions[3 * v], -pr.positions[3 * v], 1e-4);
        assert_float_equal(pl.positions[3 * v + 1], pr.positions[3 * v + 1], 1e-4);
    }
    sk_mesh_free(&pr);
    sk_mesh_free(&pl);
}

/* ------------------------------------------------------------ the field */
static void test_field_and_distance(void **state)
{
    (void)state;
    const sk_hand_skeleton *s = &fx->right;
    sk_hand_frames fr;
    double q[SK_HAND_DOF_COUNT];
    sk_hand_relaxed(s, q);
    sk_hand_forward(s, q, &fr);
    /* inside the middle finger's proximal phalanx, outside far away */
    sk_vec3d mid = sk_v3d_scale(
        sk_v3d_add(fr.point[sk_hand_link_point(13)], fr.point[sk_hand_link_point(14)]), 0.5);
    assert_true(sk_hand_surface_field(fx->surface, mid) < -5.0);
    assert_true(sk_hand_surface_field(fx->surface, sk_v3d(0, 100, 200)) > 50.0);
    /* mesh vertices lie on the surface; stepping along the normal gives that distance */
    const sk_mesh *m = sk_hand_surface_mesh(fx->surface);
    size_t off = 0;
    double worst = 0;
    for (size_t v = 0; v < m->vertex_count; v++) {
        double f = fabs(
            sk_hand_surface_field(fx->surface, sk_v3d(m->positions[3 * v], m->positions[3 * v + 1],
                                                      m->positions[3 * v + 2])));
        off += f > 0.05;
        worst = fmax(worst, f);
    }
    assert_true(off * 100 <= m->vertex_count); /* all but the few smoothed out of a fold */
    assert_true(worst < 0.5);
    for (size_t v = 0; v < m->vertex_count; v += 97) {
        sk_vec3d p = sk_v3d(m->positions[3 * v], m->positions[3 * v + 1], m->positions[3 * v + 2]);
        sk_vec3d n = sk_v3d(m->normals[3 * v], m->normals[3 * v + 1], m->normals[3 * v + 2]);
        if (fabs(sk_hand_surface_distance(fx->surface, p, NULL)) > 0.05) continue;
        sk_vec3d c;
        double d = sk_hand_surface_distance(fx->surface, sk_v3d_add(p, sk_v3d_scale(n, 0.4)), &c);
        assert_float_equal(d, 0.4, 0.05);
        assert_true(fabs(sk_hand_surface_field(fx->surface, c)) < 1e-5);
        /* the left hand's field is the mirror */
        sk_vec3d pm = sk_v3d(-p.x, p.y, p.z);
        assert_float_equal(sk_hand_surface_field(fx->mirror, pm),
                           sk_hand_surface_field(fx->small, p), 1e-12);
    }
}

/* ------------------------------------------------------------ weights, skinning */
static void test_weights(void **state)
{
    (void)state;
    const sk_mesh *m = sk_hand_surface_mesh(fx->surface);
    const uint16_t *ln, *ls;
    const float *wn, *ws;
    sk_hand_surface_weights(fx->surface, SK_HAND_WEIGHTS_NEAREST, &ln, &wn);
    sk_hand_surface_weights(fx->surface, SK_HAND_WEIGHTS_SMOOTH, &ls, &ws);
    int blended = 0, used[SK_HAND_LINK_COUNT] = {0};
    for (size_t v = 0; v < m->vertex_count; v++) {
        assert_true(wn[4 * v] == 1.0f && wn[4 * v + 1] == 0.0f);
        used[ln[4 * v]]++;
        float sum = 0;
        for (int k = 0; k < 4; k++) {
            assert_true(ws[4 * v + k] >= 0.0f);
            assert_true(ls[4 * v + k] < SK_HAND_LINK_COUNT);
            if (k) assert_true(ws[4 * v + k] <= ws[4 * v + k - 1]);
            sum += ws[4 * v + k];
        }
        assert_float_equal(sum, 1.0, 1e-6);
        assert_int_equal(ls[4 * v], ln[4 * v]); /* the largest is the nearest link */
        blended += ws[4 * v + 1] > 0.0f;
    }
    for (int j = 0; j < SK_HAND_LINK_COUNT; j++) assert_true(used[j] >= 5);
    assert_true(blended > (int)m->vertex_count / 10);
    assert_true(blended < (int)m->vertex_count * 9 / 10);
}

static void test_rigid_skinning_moves_with_link(void **state)
{
    (void)state;
    const sk_hand_surface *s = fx->surface;
    const sk_mesh *m = sk_hand_surface_mesh(s);
    double q0[SK_HAND_DOF_COUNT], q[SK_HAND_DOF_COUNT];
    sk_hand_relaxed(&fx->right, q0);
    memcpy(q, q0, sizeof q);
    q[sk_hand_dof_find("M.MCP.flex")] = 1.3;
    q[sk_hand_dof_find("M.PIP.flex")] = 1.0;
    q[sk_hand_dof_find("wrist.roll")] = 0.5;
    q[sk_hand_dof_find("wrist.tx")] = 10;
    sk_hand_frames f0, f1;
    sk_hand_forward(&fx->right, q0, &f0);
    sk_hand_forward(&fx->right, q, &f1);
    float *pos = malloc(3 * m->vertex_count * sizeof *pos),
          *nrm = malloc(3 * m->vertex_count * sizeof *nrm);
    const uint16_t *ln, *ls;
    const float *ws;
    sk_hand_surface_weights(s, SK_HAND_WEIGHTS_NEAREST, &ln, NULL);
    sk_hand_surface_weights(s, SK_HAND_WEIGHTS_SMOOTH, &ls, &ws);
    for (int method = SK_HAND_SKINNING_RIGID; method <= SK_HAND_SKINNING_DQS; method++) {
        sk_hand_surface_deform(s, &f1, (sk_hand_skinning)method, pos, nrm);
        int checked = 0;
        for (size_t v = 0; v < m->vertex_count; v++) {
            /* all weight on one link: the link's rigid motion */
            bool single = method == SK_HAND_SKINNING_RIGID || ws[4 * v + 1] == 0.0f;
            if (!single) continue;
            int j = method == SK_HAND_SKINNING_RIGID ? ln[4 * v] : ls[4 * v];
            sk_vec3d p =
                sk_v3d(m->positions[3 * v], m->positions[3 * v + 1], m->positions[3 * v + 2]);
            sk_vec3d local = sk_m3d_apply(sk_m3d_transpose(f0.rotation[j]),
                                          sk_v3d_sub(p, f0.point[sk_hand_link_point(j)]));
            sk_vec3d want =
                sk_v3d_add(f1.point[sk_hand_link_point(j)], sk_m3d_apply(f1.rotation[j], local));
            assert_float_equal(pos[3 * v], want.x, 2e-3);
            assert_float_equal(pos[3 * v + 1], want.y, 2e-3);
            assert_float_equal(pos[3 * v + 2], want.z, 2e-3);
            float nl = sqrtf(nrm[3 * v] * nrm[3 * v] + nrm[3 * v + 1] * nrm[3 * v + 1] +
                             nrm[3 * v + 2] * nrm[3 * v + 2]);
            assert_float_equal(nl, 1.0, 1e-4);
            checked++;
        }
        assert_true(checked > 1000);
    }
    free(pos);
    free(nrm);
}

/* Linear blend skinning against its definition in double precision: every vertex at
 * sum_k w_k (R_k p + t_k) with R_k, t_k taking link k's relaxed frame to its posed one,
 * its normal sum_k w_k R_k n renormalised (a vertex with one link keeps it as turned). */
static void test_lbs_matches_definition(void **state)
{
    (void)state;
    const sk_hand_surface *s = fx->surface;
    const sk_mesh *m = sk_hand_surface_mesh(s);
    double q[SK_HAND_DOF_COUNT];
    sk_hand_relaxed(&fx->right, q);
    sk_hand_frames f0, f1;
    sk_hand_forward(&fx->right, q, &f0);
    q[sk_hand_dof_find("wrist.roll")] = 0.7;
    q[sk_hand_dof_find("I.MCP.flex")] = 1.2;
    q[sk_hand_dof_find("M.PIP.flex")] = 1.5;
    q[sk_hand_dof_find("T.CMC.abd")] = 0.9;
    q[sk_hand_dof_find("L.MCP.abd")] = -0.3;
    q[1] = 12.0;
    sk_hand_forward(&fx->right, q, &f1);
    float *pos = malloc(3 * m->vertex_count * sizeof *pos),
          *nrm = malloc(3 * m->vertex_count * sizeof *nrm);
    sk_hand_surface_deform(s, &f1, SK_HAND_SKINNING_LBS, pos, nrm);
    const uint16_t *ls;
    const float *ws;
    sk_hand_surface_weights(s, SK_HAND_WEIGHTS_SMOOTH, &ls, &ws);
    for (size_t v = 0; v < m->vertex_count; v++) {
        sk_vec3d p = sk_v3d(m->positions[3 * v], m->positions[3 * v + 1], m->positions[3 * v + 2]);
        sk_vec3d n = sk_v3d(m->normals[3 * v], m->normals[3 * v + 1], m->normals[3 * v + 2]);
        sk_vec3d want = sk_v3d(0, 0, 0), wn = sk_v3d(0, 0, 0);
        for (int k = 0; k < 4 && ws[4 * v + k] > 0; k++) {
            int j = ls[4 * v + k];
            sk_mat3d r = sk_m3d_mul(f1.rotation[j], sk_m3d_transpose(f0.rotation[j]));
            sk_vec3d t = sk_v3d_sub(f1.point[sk_hand_link_point(j)],
                                    sk_m3d_apply(r, f0.point[sk_hand_link_point(j)]));
            want = sk_v3d_add(want, sk_v3d_scale(sk_v3d_add(sk_m3d_apply(r, p), t), ws[4 * v + k]));
            wn = sk_v3d_add(wn, sk_v3d_scale(sk_m3d_apply(r, n), ws[4 * v + k]));
        }
        wn = sk_v3d_normalize(wn);
        assert_float_equal(pos[3 * v], want.x, 1e-3);
        assert_float_equal(pos[3 * v + 1], want.y, 1e-3);
        assert_float_equal(pos[3 * v + 2], want.z, 1e-3);
        assert_float_equal(nrm[3 * v], wn.x, 1e-4);
        assert_float_equal(nrm[3 * v + 1], wn.y, 1e-4);
        assert_float_equal(nrm[3 * v + 2], wn.z, 1e-4);
    }
    free(pos);
    free(nrm);
}

/* Candy wrapper: turn a finger about its own axis (not a DOF of the hand, so the frames
 * are built by hand): linear blending pulls the blended vertices toward the axis, dual
 * quaternions keep their distance. */
static void test_dqs_keeps_radius_under_twist(void **state)
{
    (void)state;
    const sk_hand_surface *s = fx->surface;
    const sk_mesh *m = sk_hand_surface_mesh(s);
    double q[SK_HAND_DOF_COUNT];
    sk_hand_relaxed(&fx->right, q);
    sk_hand_frames rest, tw;
    sk_hand_forward(&fx->right, q, &rest);
    tw = rest;
    int link = 14; /* the middle finger's middle phalanx */
    sk_vec3d axis = sk_v3d(rest.rotation[link].m[0][1], rest.rotation[link].m[1][1],
                           rest.rotation[link].m[2][1]);
    sk_vec3d base = rest.point[sk_hand_link_point(link)];
    sk_mat3d twist = sk_qd_to_m3d(sk_qd_axis_angle(axis, 0.5 * SK_PI));
    for (int j = link; j <= link + 1; j++) {
        tw.rotation[j] = sk_m3d_mul(twist, rest.rotation[j]);
        tw.point[sk_hand_link_point(j)] = sk_v3d_add(
            base, sk_m3d_apply(twist, sk_v3d_sub(rest.point[sk_hand_link_point(j)], base)));
    }
    const uint16_t *ls;
    const float *ws;
    sk_hand_surface_weights(s, SK_HAND_WEIGHTS_SMOOTH, &ls, &ws);
    float *pos = malloc(3 * m->vertex_count * sizeof *pos),
          *nrm = malloc(3 * m->vertex_count * sizeof *nrm);
    double radius[3] = {0, 0, 0};
    int n = 0;
    for (int pass = 0; pass < 3; pass++) {
        if (pass)
            sk_hand_surface_deform(s, &tw, pass == 1 ? SK_HAND_SKINNING_LBS : SK_HAND_SKINNING_DQS,
                                   pos, nrm);
        n = 0;
        for (size_t v = 0; v < m->vertex_count; v++) {
            /* blended about equally between the twisted phalanx and the proximal one */
            bool pair = (ls[4 * v] == link && ls[4 * v + 1] == link - 1) ||
                        (ls[4 * v] == link - 1 && ls[4 * v + 1] == link);
            if (!pair || ws[4 * v + 1] < 0.3f) continue;
            const float *p = pass ? pos + 3 * v : m->positions + 3 * v;
            sk_vec3d d = sk_v3d_sub(sk_v3d(p[0], p[1], p[2]), base);
            d = sk_v3d_sub(d, sk_v3d_scale(axis, sk_v3d_dot(d, axis)));
            radius[pass] += sk_v3d_length(d);
            n++;
        }
    }
    assert_true(n >= 4);
    for (int i = 0; i < 3; i++) radius[i] /= n;
    assert_true(radius[1] < 0.9 * radius[0]);                   /* LBS shrinks */
    assert_float_equal(radius[2], radius[0], 0.03 * radius[0]); /* DQS keeps */
    free(pos);
    free(nrm);
}

static void test_defect_measure(void **state)
{
    (void)state;
    double q[SK_HAND_DOF_COUNT];
    sk_hand_relaxed(&fx->right, q);
    sk_hand_defect d;
    /* in the relaxed pose nothing moves */
    assert_int_equal(
        sk_hand_surface_defect(fx->surface, q, SK_HAND_SKINNING_RIGID, SK_HAND_INDEX, &d, NULL),
        SK_OK);
    assert_float_equal(d.volume_lost_mm3, 0.0, 1e-6 * d.rest_volume_mm3);
    assert_int_equal(d.inside_count, 0);
    assert_true(d.vertex_count > 200);
    /* fully flexed index: the rigid links overlap on the flexion side */
    q[sk_hand_dof_find("I.MCP.flex")] = 90 * SK_DEG_TO_RAD;
    q[sk_hand_dof_find("I.PIP.flex")] = 100 * SK_DEG_TO_RAD;
    q[sk_hand_dof_find("I.DIP.flex")] = 80 * SK_DEG_TO_RAD;
    sk_hand_defect rigid, dqs;
    assert_int_equal(
        sk_hand_surface_defect(fx->surface, q, SK_HAND_SKINNING_RIGID, SK_HAND_INDEX, &rigid, NULL),
        SK_OK);
    assert_int_equal(
        sk_hand_surface_defect(fx->surface, q, SK_HAND_SKINNING_DQS, SK_HAND_INDEX, &dqs, NULL),
        SK_OK);
    assert_true(rigid.inside_count > 0);
    assert_true(isfinite(dqs.volume_lost_mm3));
    assert_int_not_equal(
        sk_hand_surface_defect(fx->surface, q, SK_HAND_SKINNING_DQS, (sk_hand_finger)7, &d, NULL),
        SK_OK);
}

/* ------------------------------------------------------------ desc, threads */
static void test_desc_errors_and_threads(void **state)
{
    (void)state;
    sk_hand_surface *s = NULL;
    sk_error err = {0};
    sk_hand_surface_desc d = {.triangles = 10};
    assert_int_equal(sk_hand_surface_create(&s, &fx->right, &d, &err), SK_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(err.message, "triangles"));
    d = (sk_hand_surface_desc){.cell_mm = NAN};
    assert_int_equal(sk_hand_surface_create(&s, &fx->right, &d, &err), SK_ERROR_INVALID_ARGUMENT);
    assert_null(s);
    /* identical for any thread count */
    d = (sk_hand_surface_desc){.triangles = 2000, .cell_mm = 3.0};
    sk_hand_surface *a;
    sk_threads_set(1);
    assert_int_equal(sk_hand_surface_create(&a, &fx->right, &d, NULL), SK_OK);
    sk_threads_set(0);
    const sk_mesh *ma = sk_hand_surface_mesh(a),
                  *mb = sk_hand_surface_mesh(fx->small); /* all threads */
    assert_int_equal(ma->vertex_count, mb->vertex_count);
    assert_memory_equal(ma->positions, mb->positions, 3 * ma->vertex_count * sizeof(float));
    assert_memory_equal(ma->indices, mb->indices, 3 * ma->triangle_count * sizeof(uint32_t));
    assert_int_equal(check_manifold(ma), 2);
    sk_hand_surface_destroy(a);
}

/* ------------------------------------------------------------ LOD, atlas, files */
static void test_levels_of_detail(void **state)
{
    (void)state;
    const sk_mesh *base = sk_hand_surface_mesh(fx->surface);
    const uint16_t *bl;
    const float *bw;
    sk_hand_surface_weights(fx->surface, SK_HAND_WEIGHTS_SMOOTH, &bl, &bw);
    for (int l = 1; l < SK_HAND_LOD_COUNT; l++) {
        sk_hand_surface *c;
        assert_int_equal(sk_hand_surface_simplify(&c, fx->surface, sk_hand_lod_triangles[l], NULL),
                         SK_OK);
        const sk_mesh *m = sk_hand_surface_mesh(c);
        /* one closed surface of genus 0 at every level, as the full mesh */
        assert_int_equal(check_manifold(m), 2);
        assert_true(m->triangle_count <= (size_t)sk_hand_lod_triangles[l]);
        assert_true(m->triangle_count >= (size_t)sk_hand_lod_triangles[l] * 9 / 10);
        assert_true(signed_volume(m) > 0.8 * signed_volume(base));
        /* every kept vertex is a vertex of the full mesh with the same weights */
        const uint16_t *cl;
        const float *cw;
        sk_hand_surface_weights(c, SK_HAND_WEIGHTS_SMOOTH, &cl, &cw);
        size_t j = 0;
        for (size_t v = 0; v < m->vertex_count; v++) {
            while (j < base->vertex_count &&
                   memcmp(base->positions + 3 * j, m->positions + 3 * v, 3 * sizeof(float)) != 0)
                j++;
            assert_true(j < base->vertex_count);
            assert_memory_equal(cw + 4 * v, bw + 4 * j, 4 * sizeof(float));
            assert_memory_equal(cl + 4 * v, bl + 4 * j, 4 * sizeof(uint16_t));
        }
        /* the atlas keeps the full surface's bounds: a kept vertex has its uv in each
           chart, so one texture serves every level */
        sk_mesh ce, be;
        assert_int_equal(sk_hand_surface_export_mesh(c, NULL, NULL, false, &ce, NULL), SK_OK);
        assert_int_equal(sk_hand_surface_export_mesh(fx->surface, NULL, NULL, false, &be, NULL),
                         SK_OK);
        size_t matched = 0;
        for (size_t v = 0; v < ce.vertex_count; v += 7)
            for (size_t k = 0; k < be.vertex_count; k++)
                if (memcmp(be.positions + 3 * k, ce.positions + 3 * v, 3 * sizeof(float)) == 0 &&
                    (be.uvs[2 * k] < 0.5f) == (ce.uvs[2 * v] < 0.5f)) {
                    assert_memory_equal(be.uvs + 2 * k, ce.uvs + 2 * v, 2 * sizeof(float));
                    matched++;
                }
        assert_true(matched > ce.vertex_count / 7 / 2);
        sk_mesh_free(&ce);
        sk_mesh_free(&be);
        sk_hand_surface_destroy(c);
    }
    /* the left hand's levels too */
    sk_hand_surface *c;
    assert_int_equal(sk_hand_surface_simplify(&c, fx->mirror, 500, NULL), SK_OK);
    assert_int_equal(check_manifold(sk_hand_surface_mesh(c)), 2);
    sk_hand_surface_destroy(c);
}

static void test_atlas_export(void **state)
{
    (void)state;
    const sk_mesh *m = sk_hand_surface_mesh(fx->surface);
    sk_mesh e;
    assert_int_equal(sk_hand_surface_export_mesh(fx->surface, NULL, NULL, true, &e, NULL), SK_OK);
    assert_int_equal(e.triangle_count, m->triangle_count);
    assert_true(e.vertex_count > m->vertex_count &&
                e.vertex_count < m->vertex_count * 3 / 2); /* the seam only */
    size_t n;
    const uint32_t *map = sk_hand_surface_export_map(fx->surface, &n);
    assert_int_equal(n, e.vertex_count);
    int back = 0, palm = 0;
    for (size_t v = 0; v < e.vertex_count; v++) {
        float u = e.uvs[2 * v], w = e.uvs[2 * v + 1];
        assert_true(u > 0 && u < 1 && w > 0 && w < 1);
        assert_memory_equal(e.positions + 3 * v, m->positions + 3 * map[v], 3 * sizeof(float));
        /* the back chart on the left faces -z (dorsal), the palm chart +z */
        if (u < 0.5f)
            back += m->normals[3 * map[v] + 2] < 0;
        else
            palm += m->normals[3 * map[v] + 2] > 0;
    }
    assert_true(back + palm > (int)e.vertex_count * 8 / 10);
    /* each triangle lies in one chart */
    for (size_t t = 0; t < e.triangle_count; t++) {
        const uint32_t *tv = e.indices + 3 * t;
        bool left = e.uvs[2 * tv[0]] < 0.5f;
        assert_true((e.uvs[2 * tv[1]] < 0.5f) == left && (e.uvs[2 * tv[2]] < 0.5f) == left);
        for (int k = 0; k < 3; k++) assert_int_equal(map[tv[k]], m->indices[3 * t + k]);
    }
    const sk_mesh_attribute *j = sk_mesh_find_attribute(&e, "joints"),
                            *w = sk_mesh_find_attribute(&e, "weights");
    assert_non_null(j);
    assert_non_null(w);
    assert_non_null(sk_mesh_find_attribute(&e, "nail"));
    sk_mesh_free(&e);
    /* nails: on the dorsal side of the distal phalanges only */
    const sk_mesh_attribute *nail = sk_mesh_find_attribute(m, "nail");
    const uint16_t *ln;
    sk_hand_surface_weights(fx->surface, SK_HAND_WEIGHTS_NEAREST, &ln, NULL);
    int nails = 0;
    for (size_t v = 0; v < m->vertex_count; v++) {
        if (nail->data[v] == 0) continue;
        nails++;
        int link = ln[4 * v];
        assert_true(link == 3 || link == 7 || link == 11 || link == 15 || link == 19);
    }
    assert_true(nails > 50);
}

static void test_texture_bake(void **state)
{
    (void)state;
    sk_hand_texture_desc d = {.size = 128};
    sk_image albedo, normal;
    assert_int_equal(sk_hand_texture_bake(fx->surface, &d, &albedo, &normal, NULL), SK_OK);
    assert_int_equal(albedo.width, 128);
    /* the centre of each chart is skin, the corners empty */
    const float *back = sk_image_pixel(&albedo, 32, 90), *palm = sk_image_pixel(&albedo, 96, 90);
    assert_true(back[0] > back[1] && back[1] > back[2] && back[2] > 0.1f);
    assert_true(palm[0] > back[0]); /* the palm is lighter */
    assert_true(sk_image_pixel(&albedo, 0, 0)[0] == 0.0f);
    /* normal map: unit normals */
    for (int i = 0; i < 128 * 128; i += 37) {
        const float *n = normal.data + 3 * i;
        double x = 2 * n[0] - 1, y = 2 * n[1] - 1, z = 2 * n[2] - 1;
        assert_float_equal(x * x + y * y + z * z, 1.0, 1e-3);
    }
    sk_image_free(&albedo);
    sk_image_free(&normal);
    d.size = 10;
    assert_int_equal(sk_hand_texture_bake(fx->surface, &d, &albedo, &normal, NULL),
                     SK_ERROR_INVALID_ARGUMENT);
}

static void test_landmarks_and_pose_file(void **state)
{
    (void)state;
    assert_string_equal(sk_hand_landmark_name(0), "wrist");
    assert_string_equal(sk_hand_point_name(sk_hand_landmark_point(4)), "T.tip");
    assert_string_equal(sk_hand_point_name(sk_hand_landmark_point(5)), "I.MCP");
    assert_string_equal(sk_hand_point_name(sk_hand_landmark_point(12)), "M.tip");
    assert_string_equal(sk_hand_point_name(sk_hand_landmark_point(17)), "L.MCP");
    assert_string_equal(sk_hand_landmark_name(20), "little_tip");
    assert_null(sk_hand_landmark_name(21));
    double q[2 * SK_HAND_DOF_COUNT];
    const char *text = "{\"dofs\": {\"I.PIP.flex\": 90, \"wrist.tx\": 5}, \"side\": \"right\"}";
    assert_int_equal(sk_hand_pose_parse(text, strlen(text), "p.json", &fx->right, q, NULL), SK_OK);
    assert_float_equal(q[sk_hand_dof_find("I.PIP.flex")], 0.5 * SK_PI, 1e-12);
    assert_float_equal(q[0], 5.0, 1e-12);
    assert_float_equal(q[sk_hand_dof_find("M.PIP.flex")],
                       fx->right.dof[sk_hand_dof_find("M.PIP.flex")].relaxed, 1e-12);
    sk_error err = {0};
    const char *bad = "{\"dofs\": {\"I.PIP.flx\": 90}}";
    assert_int_not_equal(sk_hand_pose_parse(bad, strlen(bad), "p.json", &fx->right, q, &err),
                         SK_OK);
    assert_non_null(strstr(err.message, "I.PIP.flx"));
    /* two frames of landmarks as CSV: 21 rows each, the tip where the skeleton says */
    memcpy(q + SK_HAND_DOF_COUNT, q, sizeof(double) * SK_HAND_DOF_COUNT);
    const char *path = sk_test_path("landmarks.csv");
    assert_int_equal(sk_hand_landmarks_write(&fx->right, q, 2, SK_HAND_POSITIONS_CSV, path, NULL),
                     SK_OK);
    char *csv;
    size_t size;
    assert_int_equal(sk_read_file(path, 0, &csv, &size, NULL), SK_OK);
    assert_int_equal(sk_test_count_lines(csv), 1 + 2 * 21);
    assert_non_null(strstr(csv, "1,20,little_tip,"));
    free(csv);
}

/* ------------------------------------------------------------ the commands */
static void test_cli_hand_mesh(void **state)
{
    (void)state;
    sk_test_run run;
    assert_int_equal(sk_test_cli(&run, "hand mesh --help"), 0);
    assert_non_null(strstr(run.out, "--skinning"));
    const char *ply = sk_test_path("cli/hand.ply");
    assert_int_equal(
        sk_test_cli(&run, "hand mesh -q --pin I.PIP.flex=90 --skinning lbs --lod 2 --left -o %s",
                    ply),
        0);
    sk_mesh m;
    assert_int_equal(sk_mesh_read_ply(&m, ply, NULL, NULL), SK_OK);
    assert_true(m.triangle_count <= 500 && m.uvs != NULL);
    assert_non_null(sk_mesh_find_attribute(&m, "weights"));
    sk_vec3f lo, hi;
    sk_mesh_bounds(&m, &lo, &hi);
    assert_true(hi.x + lo.x < 0); /* the thumb of a left hand is on -x */
    sk_mesh_free(&m);
    /* bad input: one line, exit 2, no file */
    const char *none = sk_test_path("cli/none.obj");
    assert_int_equal(sk_test_cli(&run, "hand mesh --skinning cubic -o %s", none), 2);
    assert_int_equal(sk_test_cli(&run, "hand mesh --lod 3 -o %s", none), 2);
    assert_int_equal(sk_test_cli(&run, "hand mesh --pin X.Y=3 -o %s", none), 2);
    assert_int_equal(sk_test_cli(&run, "hand mesh -o %s.stl", none), 2);
    assert_int_equal(sk_test_cli(&run, "hand mesh --pose /nonexistent.json -o %s", none), 2);
    assert_int_equal(sk_test_count_lines(run.err), 1);
    assert_false(sk_test_file_exists(none));
    const char *dir = sk_test_path("cli/frames");
    assert_int_equal(sk_test_cli(&run,
                                 "hand animate -q %s/hand/little-mcp.json --meshes-dir %s "
                                 "--mesh-frames 0,24 --landmarks %s",
                                 SK_TEST_PRESET_DIR, dir, sk_test_path("cli/lm.json")),
                     0);
    char p[600];
    snprintf(p, sizeof p, "%s/frame_0024.obj", dir);
    assert_int_equal(sk_mesh_read_obj(&m, p, NULL, NULL), SK_OK);
    assert_true(m.triangle_count >= 7900 && m.uvs != NULL);
    sk_mesh_free(&m);
    snprintf(p, sizeof p, "%s/frame_0001.obj", dir);
    assert_false(sk_test_file_exists(p));
    assert_int_equal(
        sk_test_cli(&run,
                    "hand animate -q %s/hand/little-mcp.json --meshes-dir %s --mesh-frames 0,99",
                    SK_TEST_PRESET_DIR, dir),
        2);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_flesh_file_matches_builtin),
        cmocka_unit_test(test_flesh_errors),
        cmocka_unit_test(test_mesh_closed_manifold_genus0),
        cmocka_unit_test(test_mesh_no_self_intersection),
        cmocka_unit_test(test_self_intersection_check_finds_crossing),
        cmocka_unit_test(test_left_is_exact_mirror),
        cmocka_unit_test(test_field_and_distance),
        cmocka_unit_test(test_weights),
        cmocka_unit_test(test_rigid_skinning_moves_with_link),
        cmocka_unit_test(test_lbs_matches_definition),
        cmocka_unit_test(test_dqs_keeps_radius_under_twist),
        cmocka_unit_test(test_defect_measure),
        cmocka_unit_test(test_desc_errors_and_threads),
        cmocka_unit_test(test_levels_of_detail),
        cmocka_unit_test(test_atlas_export),
        cmocka_unit_test(test_texture_bake),
        cmocka_unit_test(test_landmarks_and_pose_file),
        cmocka_unit_test(test_cli_hand_mesh),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
