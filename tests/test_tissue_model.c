/* Tests of the tissue character and its generated skin (Shigemori & Kawai secs. 3-4):
 * the muscle law keeps volume and X:Y ratio, the skin is closed and manifold with every
 * vertex on a grid point, the points are classified as the paper says, and character
 * files are checked with key paths. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "shitsukan/preset.h"
#include "test_result.h"
#include "test_support.h"
#include "models/tissue/tissue_internal.h"
#include "tissue_fixture.h"

/* ------------------------------------------------------------ muscles */
static void test_muscle_keeps_volume_and_ratio(void **state)
{
    (void)state;
    sk_tissue_model *m = sk_test_rod_model(6.0);
    const sk__muscle *mu = &m->muscles[0];
    double v0 = mu->a0 * mu->b0 * mu->c0, r0 = mu->a0 / mu->b0;
    double worst_v = 0, worst_r = 0, shortest = 1e9, longest = 0;
    sk_rng rng = sk_rng_make(7, 0, 0, 0);
    for (int i = 0; i < 500; i++) {
        sk_quatd local[SK_TISSUE_MAX_JOINTS];
        for (int j = 0; j < 3; j++)
            local[j] = sk_qd_normalize(sk_qd(1.0, sk_rng_range(&rng, -0.8, 0.8),
                                             sk_rng_range(&rng, -0.8, 0.8),
                                             sk_rng_range(&rng, -0.8, 0.8)));
        sk_tissue_pose pose;
        sk__skeleton_pose(&m->skeleton, local, sk_v3d(sk_rng_range(&rng, -100, 100), 0, 0), &pose);
        sk__ellipsoid e;
        sk__muscle_shape(mu, &pose, &e);
        worst_v = fmax(worst_v, fabs(e.radii.x * e.radii.y * e.radii.z / v0 - 1.0));
        worst_r = fmax(worst_r, fabs((e.radii.x / e.radii.y) / r0 - 1.0));
        shortest = fmin(shortest, e.radii.z / mu->c0);
        longest = fmax(longest, e.radii.z / mu->c0);
        /* the axes stay orthonormal */
        assert_true(fabs(sk_m3d_det(e.axes) - 1.0) < 1e-12);
    }
    assert_true(worst_v < 1e-9);
    assert_true(worst_r < 1e-9);
    /* the motion did stretch and shorten it */
    assert_true(shortest < 0.8 && longest > 1.01);
    /* the law itself: a stretch of 4 halves the thickness */
    double a, b, c;
    sk_tissue_muscle_axes(10, 20, 30, 100, 400, &a, &b, &c);
    assert_true(fabs(a - 5) < 1e-12 && fabs(b - 10) < 1e-12 && fabs(c - 120) < 1e-12);
    sk_tissue_model_destroy(m);
}

/* ------------------------------------------------------------ skin */
typedef struct edge {
    uint32_t a, b;
} edge;

static int compare_edge(const void *x, const void *y)
{
    const edge *p = x, *q = y;
    if (p->a != q->a) return p->a < q->a ? -1 : 1;
    return (p->b > q->b) - (p->b < q->b);
}

/* Every undirected edge is used once in each direction (closed, consistently wound, no
 * edge shared by more than two triangles), and every vertex's triangles form one fan. */
static void check_closed_manifold(const sk_mesh *mesh)
{
    size_t nt = mesh->triangle_count, ne = 3 * nt;
    edge *e = malloc(ne * sizeof *e);
    assert_non_null(e);
    for (size_t t = 0; t < nt; t++)
        for (int k = 0; k < 3; k++)
            e[3 * t + (size_t)k] = (edge){mesh->indices[3 * t + (size_t)k],
                                          mesh->indices[3 * t + (size_t)(k + 1) % 3]};
    qsort(e, ne, sizeof *e, compare_edge);
    for (size_t i = 0; i + 1 < ne; i++)
        if (e[i].a == e[i + 1].a && e[i].b == e[i + 1].b)
            fail_msg("directed edge %u-%u used twice", e[i].a, e[i].b);
    for (size_t i = 0; i < ne; i++) {
        edge back = {e[i].b, e[i].a};
        if (!bsearch(&back, e, ne, sizeof *e, compare_edge))
            fail_msg("edge %u-%u has no twin: the skin is open", e[i].a, e[i].b);
    }
    /* one fan per vertex: following "next edge around" from one triangle visits all */
    size_t nv = mesh->vertex_count;
    int *incident = calloc(nv, sizeof *incident);
    for (size_t i = 0; i < 3 * nt; i++) incident[mesh->indices[i]]++;
    for (size_t v = 0; v < nv; v++) {
        if (incident[v] == 0) fail_msg("vertex %zu is on no triangle", v);
        /* start at the first outgoing edge of v, walk: from edge v->a take the triangle
           with edge a->v... counted by the sorted directed edges */
        const edge *first = NULL;
        edge key = {(uint32_t)v, 0};
        size_t lo = 0, hi = ne;
        while (lo < hi) {
            size_t mid = (lo + hi) / 2;
            if (compare_edge(&e[mid], &key) < 0)
                lo = mid + 1;
            else
                hi = mid;
        }
        first = &e[lo];
        assert_int_equal(first->a, v);
        int steps = 0;
        uint32_t cur = first->b;
        do {
            /* the triangle with directed edge cur -> v: its third corner is the next */
            uint32_t next = UINT32_MAX;
            for (size_t t = 0; t < nt && next == UINT32_MAX; t++)
                for (int k = 0; k < 3; k++)
                    if (mesh->indices[3 * t + (size_t)k] == cur &&
                        mesh->indices[3 * t + (size_t)(k + 1) % 3] == v)
                        next = mesh->indices[3 * t + (size_t)(k + 2) % 3];
            assert_true(next != UINT32_MAX);
            cur = next;
            steps++;
        } while (cur != first->b && steps <= incident[v]);
        if (steps != incident[v])
            fail_msg("vertex %zu: %d of its %d triangles in one fan (not manifold)", v, steps,
                     incident[v]);
    }
    free(incident);
    free(e);
}

static void test_skin_is_closed_manifold_on_grid_points(void **state)
{
    (void)state;
    sk_tissue_model *m = sk_test_rod_model(5.0);
    sk_mesh skin;
    SK_ASSERT_OK(sk_tissue_model_rest_skin(m, &skin, &e_));
    assert_true(skin.triangle_count > 500);
    check_closed_manifold(&skin);
    const sk__grid *g = &m->grid;
    for (size_t v = 0; v < skin.vertex_count; v++) {
        double c[3] = {(skin.positions[3 * v] - g->origin.x) / g->spacing,
                       (skin.positions[3 * v + 1] - g->origin.y) / g->spacing,
                       (skin.positions[3 * v + 2] - g->origin.z) / g->spacing};
        for (int k = 0; k < 3; k++)
            if (fabs(c[k] - round(c[k])) > 1e-3)
                fail_msg("skin vertex %zu is not on a grid point", v);
    }
    /* the skin encloses the tissue: its signed volume is that of a body, not zero */
    double volume = 0.0;
    for (size_t t = 0; t < skin.triangle_count; t++) {
        const float *a = skin.positions + 3 * skin.indices[3 * t],
                    *b = skin.positions + 3 * skin.indices[3 * t + 1],
                    *c = skin.positions + 3 * skin.indices[3 * t + 2];
        volume += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                   a[2] * (b[0] * c[1] - b[1] * c[0])) /
                  6.0;
    }
    assert_true(volume > 220.0 * SK_PI * 12 * 12); /* more than the bones, outward normals */
    sk_mesh_free(&skin);

    /* smoothing keeps it closed and manifold, and outside the tissue */
    sk_tissue_character_desc *d = sk_test_rod_desc(5.0);
    d->skin.smooth_iterations = 8;
    sk_tissue_model *smooth = NULL;
    SK_ASSERT_OK(sk_tissue_model_build(d, NULL, &smooth, &e_));
    SK_ASSERT_OK(sk_tissue_model_rest_skin(smooth, &skin, &e_));
    check_closed_manifold(&skin);
    size_t moved = 0;
    for (size_t v = 0; v < skin.vertex_count; v++) {
        sk_vec3d p =
            sk_v3d(skin.positions[3 * v], skin.positions[3 * v + 1], skin.positions[3 * v + 2]);
        moved += sk_v3d_length(sk_v3d_sub(p, m->rest[v])) > 1e-3;
        for (int b = 0; b < 2; b++)
            for (int k = 0; k < 3; k++) {
                sk__ellipsoid e =
                    sk__ellipsoid_transform(&smooth->bones[b].part[k], sk_m3d_identity(),
                                            smooth->skeleton.rest[smooth->bones[b].joint]);
                assert_true(sk__ellipsoid_level(&e, p) > 1.0);
            }
    }
    assert_true(moved > skin.vertex_count / 2);
    sk_mesh_free(&skin);
    sk_tissue_model_destroy(smooth);
    free(d);
    sk_tissue_model_destroy(m);
}

/* Whether p is inside the closed mesh: crossings of a ray along +x (slightly tilted so it
 * meets no edge). */
static bool inside_mesh(const sk_mesh *mesh, sk_vec3d p)
{
    const double dy = 1e-4, dz = 2.3e-4;
    int crossings = 0;
    for (size_t t = 0; t < mesh->triangle_count; t++) {
        double v[3][3];
        for (int k = 0; k < 3; k++)
            for (int c = 0; c < 3; c++)
                v[k][c] = mesh->positions[3 * mesh->indices[3 * t + (size_t)k] + (size_t)c];
        /* ray p + s (1, dy, dz): project onto the plane perpendicular to x */
        double a[3][2];
        bool left = true, right = true;
        for (int k = 0; k < 3; k++) {
            a[k][0] = (v[k][1] - p.y) - dy * (v[k][0] - p.x);
            a[k][1] = (v[k][2] - p.z) - dz * (v[k][0] - p.x);
            left &= v[k][0] < p.x;
            right &= v[k][0] >= p.x;
        }
        if (left) continue;
        double w[3];
        for (int k = 0; k < 3; k++)
            w[k] = a[(k + 1) % 3][0] * a[(k + 2) % 3][1] - a[(k + 2) % 3][0] * a[(k + 1) % 3][1];
        bool in = (w[0] > 0 && w[1] > 0 && w[2] > 0) || (w[0] < 0 && w[1] < 0 && w[2] < 0);
        if (!in) continue;
        if (!right) {
            /* the crossing's x by barycentric weights */
            double sum = w[0] + w[1] + w[2],
                   x = (w[0] * v[0][0] + w[1] * v[1][0] + w[2] * v[2][0]) / sum;
            if (x < p.x) continue;
        }
        crossings++;
    }
    return crossings & 1;
}

static void test_classification(void **state)
{
    (void)state;
    sk_tissue_model *m = sk_test_rod_model(5.0);
    sk__tissue_shapes *t = malloc(sizeof *t);
    sk_tissue_pose rest;
    sk_quatd local[SK_TISSUE_MAX_JOINTS];
    for (int j = 0; j < 3; j++) local[j] = sk_qd_identity();
    sk__skeleton_pose(&m->skeleton, local, sk_v3d(0, 0, 0), &rest);
    t->bone_count = 2;
    t->muscle_count = 1;
    for (int b = 0; b < 2; b++)
        for (int k = 0; k < 3; k++)
            t->bone[b][k] = sk__ellipsoid_transform(&m->bones[b].part[k], sk_m3d_identity(),
                                                    m->skeleton.rest[m->bones[b].joint]);
    sk__muscle_shape(&m->muscles[0], &rest, &t->muscle[0]);
    sk_mesh skin;
    SK_ASSERT_OK(sk_tissue_model_rest_skin(m, &skin, &e_));
    assert_true(m->fat_count > 100 && m->muscle_count > 10 && m->bone_count > 10);
    /* fat points: outside every bone and muscle, inside the skin */
    for (size_t p = m->skin_count; p < m->skin_count + m->fat_count; p += 3) {
        assert_int_equal(sk__tissue_label_at(t, m->rest[p]), SK__LABEL_NONE);
        if (!inside_mesh(&skin, m->rest[p])) fail_msg("fat point %zu is outside the skin", p);
    }
    /* skin points with no fat point among their 26 neighbours (the skin on the tissue) */
    size_t nfree = m->skin_count + m->fat_count;
    int *skin_fat = calloc(m->skin_count, sizeof *skin_fat);
    for (size_t s = 0; s < m->spring_count; s++)
        if (m->spring_class[s] == SK__SPRING_SKIN_FAT) {
            size_t a = m->spring_i[s] < m->skin_count ? m->spring_i[s] : m->spring_j[s];
            skin_fat[a]++;
        }
    /* muscle and bone points: in their tissue, beside a fat point (or a skin point on the
       tissue) */
    int dirs[13][3], all[13][3];
    int nd = sk__lattice_directions(m->neighbourhood, dirs), na = sk__lattice_directions(26, all);
    for (size_t p = m->skin_count + m->fat_count; p < m->point_count; p++) {
        bool muscle = p < m->skin_count + m->fat_count + m->muscle_count;
        sk__label l = sk__tissue_label_at(t, m->rest[p]);
        assert_true(muscle ? l >= SK__LABEL_MUSCLE0
                           : (l != SK__LABEL_NONE && l < SK__LABEL_MUSCLE0));
        int c[3];
        sk__grid_coords(&m->grid, m->grid_of[p], c);
        bool touches = false;
        for (size_t f = 0; f < nfree && !touches; f++) {
            if (f < m->skin_count && skin_fat[f]) continue;
            int q[3];
            sk__grid_coords(&m->grid, m->grid_of[f], q);
            int d[3] = {q[0] - c[0], q[1] - c[1], q[2] - c[2]};
            touches = sk__lattice_direction_index(f < m->skin_count ? all : dirs,
                                                  f < m->skin_count ? na : nd, d) >= 0;
        }
        if (!touches) fail_msg("%s point %zu touches no fat point", muscle ? "muscle" : "bone", p);
    }
    /* springs join only the classes the paper joins (and the skin to the tissue only where
       no fat point is beside it); every skin point is held by something below it */
    for (size_t s = 0; s < m->spring_count; s++) {
        size_t i = m->spring_i[s], j = m->spring_j[s];
        bool si = i < m->skin_count, sj = j < m->skin_count, fi = i < nfree, fj = j < nfree;
        switch (m->spring_class[s]) {
        case SK__SPRING_SKIN:
            assert_true(si && sj);
            break;
        case SK__SPRING_SKIN_FAT:
            assert_true((si && fj && !sj) || (sj && fi && !si));
            break;
        case SK__SPRING_FAT:
            assert_true(fi && fj && !si && !sj);
            break;
        case SK__SPRING_ANCHOR:
            assert_true(fi != fj);
            if (si) assert_int_equal(skin_fat[i], 0);
            if (sj) assert_int_equal(skin_fat[j], 0);
            break;
        default:
            fail();
        }
    }
    int *held = calloc(m->skin_count, sizeof *held);
    for (size_t s = 0; s < m->spring_count; s++) {
        if (m->spring_class[s] == SK__SPRING_SKIN) continue;
        if (m->spring_i[s] < m->skin_count) held[m->spring_i[s]]++;
        if (m->spring_j[s] < m->skin_count) held[m->spring_j[s]]++;
    }
    /* a skin point whose cells are one cell thick (all their corners on the skin, at thin
       tips) has only skin springs (and its tether): a few per cent at most */
    size_t loose = 0;
    for (size_t p = 0; p < m->skin_count; p++) loose += !held[p];
    assert_true(loose * 25 < m->skin_count);
    free(held);
    free(skin_fat);
    sk_mesh_free(&skin);
    free(t);
    sk_tissue_model_destroy(m);
}

/* The shipped characters build, and their tracked points lie where they say. */
static void test_shipped_characters(void **state)
{
    (void)state;
    static const char *const names[] = {"arm", "body"};
    for (int i = 0; i < 2; i++) {
        char path[1024];
        snprintf(path, sizeof path, "%s/tissue/%s.json", SK_TEST_PRESET_DIR, names[i]);
        sk_tissue_character_desc *d = malloc(sizeof *d);
        SK_ASSERT_OK(sk_tissue_character_load(path, d, &e_));
        d->skin.spacing_mm = i == 0 ? 8.0f : 20.0f; /* coarse: the structure is what is tested */
        d->skin.dilation_radius_mm = 1.5f * d->skin.spacing_mm;
        sk_tissue_model *m = NULL;
        SK_ASSERT_OK(sk_tissue_model_build(d, NULL, &m, &e_));
        sk_tissue_model_stats s = sk_tissue_model_get_stats(m);
        assert_true(s.skin_points > 100 && s.fat_points > 100 && s.springs > s.fat_points);
        for (int k = 0; k < d->tracked_count; k++) assert_true(m->tracked_point[k] >= 0);
        sk_tissue_model_destroy(m);
        free(d);
    }
}

static void expect_character_error(const char *json, const char *needle)
{
    sk_preset *p = NULL;
    sk_error err = {0};
    SK_ASSERT_OK(sk_preset_parse(&p, json, strlen(json), "c.json", &e_));
    sk_tissue_character_desc *d = malloc(sizeof *d);
    sk_result r = sk_tissue_character_bind(p, d, &err);
    if (r == SK_OK || !strstr(err.message, needle))
        fail_msg("%s: got \"%s\", want \"%s\"", json, err.message, needle);
    sk_preset_free(p);
    free(d);
}

static void test_character_errors_name_the_key(void **state)
{
    (void)state;
    const char *j = "{\"joints\": [{\"name\": \"A\"}, {\"name\": \"B\", \"parent\": \"A\", "
                    "\"offset_mm\": [0, -100, 0]}]";
    char buf[1024];
#define CASE(extra, needle)                                                                        \
    do {                                                                                           \
        snprintf(buf, sizeof buf, "%s, %s}", j, extra);                                            \
        expect_character_error(buf, needle);                                                       \
    } while (0)
    CASE("\"bones\": [{\"name\": \"b\", \"joint\": \"C\", \"end\": \"B\", \"radius_mm\": 10}]",
         "bones[0].joint = \"C\" is not a joint (joints: A, B)");
    CASE("\"bones\": [{\"name\": \"b\", \"joint\": \"A\", \"end\": \"B\"}]",
         "bones[0].radius_mm = 0 is out of range (0, 1000] (required)");
    CASE("\"bones\": [{\"name\": \"b\", \"joint\": \"A\", \"end\": \"B\", \"radius_mm\": 2000}]",
         "bones[0].radius_mm = 2000 is out of range");
    CASE("\"bones\": [{\"name\": \"b\", \"joint\": \"A\", \"end\": \"B\", \"radius_mm\": 10}], "
         "\"muscles\": [{\"name\": \"m\", "
         "\"origin\": {\"bone\": \"x\"}, \"insertion\": {\"bone\": \"b\"}, \"thickness_mm\": 5}]",
         "muscles[0].origin.bone = \"x\" is not a bone (bones: b)");
    CASE("\"bones\": [{\"name\": \"b\", \"joint\": \"A\", \"end\": \"B\", \"radius_mm\": 10}], "
         "\"skin\": {\"threshold\": 0.9999}",
         "skin.threshold = 0.9999 is out of range");
    CASE("\"bones\": [{\"name\": \"b\", \"joint\": \"A\", \"end\": \"B\", \"radius_mm\": 10}], "
         "\"skin\": {\"neighbourhood\": 6}",
         "skin.neighbourhood = 6 must be 18 or 26");
    CASE("\"bones\": [{\"name\": \"b\", \"joint\": \"A\", \"end\": \"B\", \"radius_mm\": 10}], "
         "\"material\": {\"fat_stifness\": 3}",
         "fat_stifness");
    CASE("\"bones\": [{\"name\": \"b\", \"joint\": \"A\", \"end\": \"B\", \"radius_mm\": 10}], "
         "\"fat\": [{\"around\": \"q\", "
         "\"thickness_mm\": 5}]",
         "fat[0].around = \"q\" is not a bone (bones: b)");
    CASE("\"bones\": [{\"name\": \"b\", \"joint\": \"A\", \"end\": \"B\", \"radius_mm\": 10}], "
         "\"joint_map\": [{\"motion\": "
         "\"x\", \"joint\": \"Z\"}]",
         "joint_map[0].joint = \"Z\" is not a joint");
    CASE("\"bones\": [{\"name\": \"b\", \"joint\": \"A\", \"end\": \"B\", \"radius_mm\": 10}], "
         "\"simulation\": {\"step_hz\": 30}",
         "simulation.step_hz = 30 is out of range [60, 20000]");
#undef CASE
    expect_character_error(
        "{\"joints\": [{\"name\": \"A\", \"parent\": \"B\"}, {\"name\": \"B\", \"parent\": "
        "\"A\"}], "
        "\"bones\": [{\"name\": \"b\", \"joint\": \"A\", \"end\": \"B\", \"radius_mm\": 10}]}",
        "joints: no root");
    expect_character_error(
        "{\"joints\": [{\"name\": \"A\"}, {\"name\": \"A\", \"parent\": \"A\"}]}",
        "joints[1].name = \"A\" is also joints[0]'s");
    /* a build that cannot make a skin says why */
    sk_tissue_character_desc *d = sk_test_rod_desc(5.0);
    d->skin.spacing_mm = 0.5f;
    d->skin.dilation_radius_mm = 0.75f;
    d->joints[2].offset_mm[1] = -20000;
    sk_tissue_model *m = NULL;
    sk_error err = {0};
    sk_test_expect_failure(sk_tissue_model_build(d, NULL, &m, &err), &err, SK_ERROR_LIMIT,
                           "more than 2^28");
    free(d);
}

/* The build does not depend on the thread count. */
static void test_build_is_deterministic(void **state)
{
    (void)state;
    sk_threads_set(1);
    sk_tissue_model *a = sk_test_rod_model(5.0);
    sk_threads_set(0);
    sk_tissue_model *b = sk_test_rod_model(5.0);
    assert_int_equal(a->point_count, b->point_count);
    assert_int_equal(a->spring_count, b->spring_count);
    assert_memory_equal(a->rest, b->rest, a->point_count * sizeof *a->rest);
    assert_memory_equal(a->spring_i, b->spring_i, a->spring_count * sizeof *a->spring_i);
    assert_memory_equal(a->triangles, b->triangles, 3 * a->triangle_count * sizeof *a->triangles);
    sk_tissue_model_destroy(a);
    sk_tissue_model_destroy(b);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_muscle_keeps_volume_and_ratio),
        cmocka_unit_test(test_skin_is_closed_manifold_on_grid_points),
        cmocka_unit_test(test_classification),
        cmocka_unit_test(test_shipped_characters),
        cmocka_unit_test(test_character_errors_name_the_key),
        cmocka_unit_test(test_build_is_deterministic),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
