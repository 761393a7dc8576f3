/* Tests of the mesh module: allocation caps, attributes, validation, normals, polygon
 * triangulation, OBJ and PLY round trips, hand-written and malformed files. */
#define _POSIX_C_SOURCE 200809L
#include "test_result.h"
#include "test_support.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/polygon_triangulate.h"
#include "shitsukan/image.h"
#include "shitsukan/io.h"
#include "shitsukan/mesh.h"

/* ------------------------------------------------------------------ helpers */

static const char *write_text(const char *name, const char *text)
{
    const char *path = sk_test_path(name);
    sk_test_write_file(path, text, strlen(text));
    return path;
}

/* Reads `text` as a file named `name` and expects failure `want` with `needle`. */
static void expect_bad_obj(const char *name, const char *text, sk_result want, const char *needle)
{
    sk_mesh m;
    sk_error err = {0};
    sk_test_expect_failure(sk_mesh_read_obj(&m, write_text(name, text), NULL, &err), &err, want,
                           needle);
    assert_int_equal(m.vertex_count, 0);
    assert_null(m.positions);
}

static void expect_bad_ply(const char *name, const void *data, size_t size, sk_result want,
                           const char *needle)
{
    const char *path = sk_test_path(name);
    sk_test_write_file(path, data, size);
    sk_mesh m;
    sk_error err = {0};
    sk_test_expect_failure(sk_mesh_read_ply(&m, path, NULL, &err), &err, want, needle);
    assert_null(m.positions);
}

static double tri_area(const float *a, const float *b, const float *c, double n_out[3])
{
    double e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    double e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                   e1[0] * e2[1] - e1[1] * e2[0]};
    if (n_out) memcpy(n_out, n, sizeof n);
    return 0.5 * sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
}

/* Sum of triangle areas, and whether every triangle faces along `normal`. */
static double mesh_area(const sk_mesh *m, const double normal[3], bool *all_facing)
{
    double total = 0.0;
    *all_facing = true;
    for (size_t t = 0; t < m->triangle_count; t++) {
        const uint32_t *tri = m->indices + 3 * t;
        double n[3];
        total += tri_area(m->positions + 3 * tri[0], m->positions + 3 * tri[1],
                          m->positions + 3 * tri[2], n);
        if (normal && n[0] * normal[0] + n[1] * normal[1] + n[2] * normal[2] <= 0.0)
            *all_facing = false;
    }
    return total;
}

/* A test mesh: a 3 x 2 grid of quads split into triangles, with every optional array. */
static void make_grid(sk_mesh *m, bool attributes)
{
    SK_ASSERT_OK(sk_mesh_create(m, 12, 12, SK_MESH_NORMALS | SK_MESH_UVS | SK_MESH_COLORS, &e_));
    for (int y = 0; y < 3; y++)
        for (int x = 0; x < 4; x++) {
            size_t i = (size_t)(y * 4 + x);
            m->positions[3 * i] = (float)x * 0.1f + 0.0123f;
            m->positions[3 * i + 1] = (float)y / 3.0f;
            m->positions[3 * i + 2] = sinf((float)i);
            m->normals[3 * i] = 0.6f;
            m->normals[3 * i + 1] = 0.0f;
            m->normals[3 * i + 2] = 0.8f;
            m->uvs[2 * i] = (float)x / 3.0f;
            m->uvs[2 * i + 1] = 1.0f - (float)y / 2.0f;
            m->colors[3 * i] = (float)x / 3.0f;
            m->colors[3 * i + 1] = (float)y / 2.0f;
            m->colors[3 * i + 2] = 0.25f;
        }
    size_t t = 0;
    for (int y = 0; y < 2; y++)
        for (int x = 0; x < 3; x++) {
            uint32_t a = (uint32_t)(y * 4 + x), b = a + 1, c = a + 5, d = a + 4;
            uint32_t q[6] = {a, b, c, a, c, d};
            memcpy(m->indices + 3 * t, q, sizeof q);
            t += 2;
        }
    if (!attributes) return;
    float *w, *dir;
    SK_ASSERT_OK(sk_mesh_add_attribute(m, "weight", 1, &w, &e_));
    SK_ASSERT_OK(sk_mesh_add_attribute(m, "direction", 3, &dir, &e_));
    for (size_t i = 0; i < 12; i++) {
        w[i] = (float)i * 0.37f - 1.0f;
        for (int k = 0; k < 3; k++) dir[3 * i + (size_t)k] = (float)(i * 3 + (size_t)k) / 7.0f;
    }
}

/* Colours pass through the sRGB curve in files: OBJ's decimal values come back within
 * float rounding, PLY's 8-bit codes within half a code, which is up to 2.28 times as much
 * in linear terms (the curve's steepest inverse slope, at 1). */
#define OBJ_COLOR_TOL 1e-6
#define PLY_COLOR_TOL (2.28 * 0.5 / 255.0)

/* Compares two meshes corner by corner (vertex order may differ). */
static void assert_same_triangles(const sk_mesh *a, const sk_mesh *b, double color_tol)
{
    assert_int_equal(a->triangle_count, b->triangle_count);
    assert_int_equal(a->normals != NULL, b->normals != NULL);
    assert_int_equal(a->uvs != NULL, b->uvs != NULL);
    assert_int_equal(a->colors != NULL, b->colors != NULL);
    for (size_t k = 0; k < 3 * a->triangle_count; k++) {
        size_t i = a->indices[k], j = b->indices[k];
        assert_true(j < b->vertex_count);
        assert_memory_equal(a->positions + 3 * i, b->positions + 3 * j, 3 * sizeof(float));
        for (int c = 0; a->normals && c < 3; c++)
            assert_float_equal(a->normals[3 * i + (size_t)c], b->normals[3 * j + (size_t)c], 1e-6);
        if (a->uvs) assert_memory_equal(a->uvs + 2 * i, b->uvs + 2 * j, 2 * sizeof(float));
        for (int c = 0; a->colors && c < 3; c++)
            assert_float_equal(a->colors[3 * i + (size_t)c], b->colors[3 * j + (size_t)c],
                               color_tol);
    }
}

/* ------------------------------------------------------------------ core */

static void test_mesh_create_and_attributes(void **state)
{
    (void)state;
    sk_mesh m;
    sk_error err = {0};
    sk_test_expect_failure(sk_mesh_create(&m, (size_t)1 << 40, 0, 0, &err), &err, SK_ERROR_LIMIT,
                           "cap");
    assert_null(m.positions);
    sk_test_expect_failure(sk_mesh_create(&m, 3, 1, 1 << 7, &err), &err, SK_ERROR_INVALID_ARGUMENT,
                           "flags");
    SK_ASSERT_OK(sk_mesh_create(&m, 4, 2, SK_MESH_UVS, &e_));
    assert_non_null(m.positions);
    assert_non_null(m.uvs);
    assert_null(m.normals);
    assert_null(m.colors);
    assert_int_equal(m.indices[5], 0);
    float *data;
    SK_ASSERT_OK(sk_mesh_add_attribute(&m, "curvature", 2, &data, &e_));
    assert_ptr_equal(sk_mesh_find_attribute(&m, "curvature")->data, data);
    assert_null(sk_mesh_find_attribute(&m, "missing"));
    sk_test_expect_failure(sk_mesh_add_attribute(&m, "curvature", 1, NULL, &err), &err,
                           SK_ERROR_INVALID_ARGUMENT, "exists");
    sk_test_expect_failure(sk_mesh_add_attribute(&m, "c5", 5, NULL, &err), &err,
                           SK_ERROR_INVALID_ARGUMENT, "components");
    for (int i = 1; i < SK_MESH_MAX_ATTRIBUTES; i++) {
        char name[16];
        snprintf(name, sizeof name, "a%d", i);
        SK_ASSERT_OK(sk_mesh_add_attribute(&m, name, 1, NULL, &e_));
    }
    sk_test_expect_failure(sk_mesh_add_attribute(&m, "one_more", 1, NULL, &err), &err,
                           SK_ERROR_LIMIT, "slots");
    sk_mesh_free(&m);
    assert_null(m.positions);
    assert_int_equal(m.attribute_count, 0);
}

static void test_mesh_validate_and_bounds(void **state)
{
    (void)state;
    sk_mesh m;
    sk_error err = {0};
    make_grid(&m, false);
    SK_ASSERT_OK(sk_mesh_validate(&m, &e_));
    sk_vec3f lo, hi;
    assert_true(sk_mesh_bounds(&m, &lo, &hi));
    assert_float_equal(lo.x, 0.0123f, 1e-7);
    assert_float_equal(hi.x, 0.3123f, 1e-6);
    assert_float_equal(hi.y, 2.0f / 3.0f, 1e-7);
    m.indices[7] = 12;
    sk_test_expect_failure(sk_mesh_validate(&m, &err), &err, SK_ERROR_INVALID_ARGUMENT,
                           "triangle 2");
    m.indices[7] = 0;
    m.uvs[5] = NAN;
    sk_test_expect_failure(sk_mesh_validate(&m, &err), &err, SK_ERROR_INVALID_ARGUMENT,
                           "uv of vertex 2");
    sk_mesh_free(&m);
    sk_mesh empty = {0};
    assert_false(sk_mesh_bounds(&empty, &lo, &hi));
}

/* A unit cube centred on the origin, 8 shared corners, outward winding. */
static void make_cube(sk_mesh *m)
{
    SK_ASSERT_OK(sk_mesh_create(m, 8, 12, 0, &e_));
    for (int i = 0; i < 8; i++) {
        m->positions[3 * i] = (i & 1) ? 0.5f : -0.5f;
        m->positions[3 * i + 1] = (i & 2) ? 0.5f : -0.5f;
        m->positions[3 * i + 2] = (i & 4) ? 0.5f : -0.5f;
    }
    static const uint32_t faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                         {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (int f = 0; f < 6; f++) {
        const uint32_t *q = faces[f];
        uint32_t tris[6] = {q[0], q[1], q[2], q[0], q[2], q[3]};
        memcpy(m->indices + 6 * f, tris, sizeof tris);
    }
}

static void test_compute_normals_cube(void **state)
{
    (void)state;
    sk_mesh m;
    make_cube(&m);
    bool facing;
    double none[3] = {0, 0, 0};
    assert_float_equal(mesh_area(&m, none, &facing), 6.0, 1e-9);
    SK_ASSERT_OK(sk_mesh_compute_normals(&m, &e_));
    assert_non_null(m.normals);
    for (int i = 0; i < 8; i++) {
        const float *n = m.normals + 3 * i, *p = m.positions + 3 * i;
        assert_float_equal(n[0] * n[0] + n[1] * n[1] + n[2] * n[2], 1.0, 1e-6);
        /* Outward: every component has the sign of the corner's position. */
        for (int k = 0; k < 3; k++) assert_true(n[k] * p[k] > 0.0f);
    }
    /* Corner 0 touches two triangles of each of its three faces: weights are equal. */
    float s = 1.0f / sqrtf(3.0f);
    assert_float_equal(m.normals[0], -s, 1e-6);
    assert_float_equal(m.normals[1], -s, 1e-6);
    assert_float_equal(m.normals[2], -s, 1e-6);
    sk_mesh_free(&m);
}

static void test_compute_normals_sphere(void **state)
{
    (void)state;
    enum { SLICES = 48, STACKS = 24 };
    sk_mesh m;
    size_t vcount = (size_t)SLICES * (STACKS - 1) + 2;
    size_t tcount = (size_t)SLICES * 2 * (STACKS - 1);
    SK_ASSERT_OK(sk_mesh_create(&m, vcount, tcount, 0, &e_));
    float *p = m.positions;
    for (int j = 1; j < STACKS; j++)
        for (int i = 0; i < SLICES; i++) {
            double th = SK_PI * j / STACKS, ph = 2 * SK_PI * i / SLICES;
            *p++ = (float)(sin(th) * cos(ph));
            *p++ = (float)(sin(th) * sin(ph));
            *p++ = (float)cos(th);
        }
    uint32_t top = (uint32_t)(vcount - 2), bottom = (uint32_t)(vcount - 1);
    m.positions[3 * top + 2] = 1.0f;
    m.positions[3 * bottom + 2] = -1.0f;
    uint32_t *t = m.indices;
    for (int i = 0; i < SLICES; i++) {
        uint32_t i1 = (uint32_t)((i + 1) % SLICES);
        *t++ = top, *t++ = (uint32_t)i, *t++ = i1;
        uint32_t base = (uint32_t)(SLICES * (STACKS - 2));
        *t++ = bottom, *t++ = base + i1, *t++ = base + (uint32_t)i;
        for (int j = 0; j < STACKS - 2; j++) {
            uint32_t a = (uint32_t)(j * SLICES + i), b = (uint32_t)(j * SLICES) + i1;
            uint32_t c = b + SLICES, d = a + SLICES;
            *t++ = a, *t++ = d, *t++ = c;
            *t++ = a, *t++ = c, *t++ = b;
        }
    }
    assert_int_equal((size_t)(t - m.indices), 3 * tcount);
    SK_ASSERT_OK(sk_mesh_compute_normals(&m, &e_));
    for (size_t v = 0; v < vcount; v++) {
        const float *n = m.normals + 3 * v, *q = m.positions + 3 * v;
        double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        assert_float_equal(len, 1.0, 1e-6);
        double dot = n[0] * q[0] + n[1] * q[1] + n[2] * q[2];
        if (dot < 0.999) fail_msg("vertex %zu: normal . position = %f", v, dot);
    }
    sk_mesh_free(&m);
}

/* ------------------------------------------------------------------ triangulation */

/* The L-shaped hexagon (area 3) starting at a corner from which a fan would overlap
 * itself, placed in a tilted plane. */
static void l_shape(float out[6][3], double normal[3])
{
    static const float l2[6][2] = {{2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}, {0, 0}};
    /* Plane basis: u = (1, 1, 0)/sqrt2, v = (-1, 1, 2)/sqrt6, normal u x v. */
    const double u[3] = {1 / sqrt(2.0), 1 / sqrt(2.0), 0};
    const double v[3] = {-1 / sqrt(6.0), 1 / sqrt(6.0), 2 / sqrt(6.0)};
    normal[0] = u[1] * v[2] - u[2] * v[1];
    normal[1] = u[2] * v[0] - u[0] * v[2];
    normal[2] = u[0] * v[1] - u[1] * v[0];
    for (int i = 0; i < 6; i++)
        for (int k = 0; k < 3; k++)
            out[i][k] = (float)(l2[i][0] * u[k] + l2[i][1] * v[k] + 0.5 * k);
}

static void test_triangulate_concave_and_degenerate(void **state)
{
    (void)state;
    float pts[6][3];
    double normal[3];
    l_shape(pts, normal);
    sk__triangulator t = {0};
    uint32_t corners[6] = {0, 1, 2, 3, 4, 5}, out[12];
    SK_ASSERT_OK(sk__triangulate(&t, &pts[0][0], corners, 6, out));
    double area = 0.0;
    for (int k = 0; k < 4; k++) {
        double n[3];
        area += tri_area(pts[out[3 * k]], pts[out[3 * k + 1]], pts[out[3 * k + 2]], n);
        assert_true(n[0] * normal[0] + n[1] * normal[1] + n[2] * normal[2] > 0.0);
    }
    assert_float_equal(area, 3.0, 1e-5);

    /* Collinear corners and a repeated corner still give n - 2 triangles. */
    float line[5][3] = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {1, 0, 0}};
    uint32_t c5[5] = {0, 1, 2, 3, 4}, out5[9];
    SK_ASSERT_OK(sk__triangulate(&t, &line[0][0], c5, 5, out5));
    for (int k = 0; k < 9; k++) assert_true(out5[k] < 5);
    float dup[5][3] = {{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    SK_ASSERT_OK(sk__triangulate(&t, &dup[0][0], c5, 5, out5));
    double dup_area = 0.0;
    for (int k = 0; k < 3; k++)
        dup_area += tri_area(dup[out5[3 * k]], dup[out5[3 * k + 1]], dup[out5[3 * k + 2]], NULL);
    assert_float_equal(dup_area, 1.0, 1e-6);
    sk__triangulator_free(&t);
}

/* ------------------------------------------------------------------ OBJ */

static void test_obj_roundtrip(void **state)
{
    (void)state;
    sk_mesh m, back;
    make_grid(&m, true);
    const char *path = sk_test_path("mesh/grid.obj");
    SK_ASSERT_OK(sk_mesh_write_obj(&m, path, NULL, &e_));
    SK_ASSERT_OK(sk_mesh_read_obj(&back, path, NULL, &e_));
    assert_int_equal(back.vertex_count, 12);
    assert_int_equal(back.attribute_count, 0);       /* OBJ has no attributes */
    assert_same_triangles(&m, &back, OBJ_COLOR_TOL); /* %.9g: bit-exact floats */
    sk_mesh_free(&back);

    /* Without normals and uvs the faces use the plain form. */
    free(m.normals);
    free(m.uvs);
    m.normals = m.uvs = NULL;
    SK_ASSERT_OK(sk_mesh_write_obj(&m, path, NULL, &e_));
    SK_ASSERT_OK(sk_mesh_read_obj(&back, path, NULL, &e_));
    assert_same_triangles(&m, &back, OBJ_COLOR_TOL);
    sk_mesh_free(&back);

    /* A point cloud keeps every vertex in order. */
    sk_mesh cloud;
    SK_ASSERT_OK(sk_mesh_create(&cloud, 5, 0, SK_MESH_COLORS, &e_));
    for (int i = 0; i < 15; i++) {
        cloud.positions[i] = (float)i * 1.5f - 3.0f;
        cloud.colors[i] = (float)i / 15.0f;
    }
    const char *cloud_path = sk_test_path("mesh/cloud.obj");
    SK_ASSERT_OK(sk_mesh_write_obj(&cloud, cloud_path, NULL, &e_));
    SK_ASSERT_OK(sk_mesh_read_obj(&back, cloud_path, NULL, &e_));
    assert_int_equal(back.vertex_count, 5);
    assert_int_equal(back.triangle_count, 0);
    assert_memory_equal(back.positions, cloud.positions, 15 * sizeof(float));
    for (int i = 0; i < 15; i++) assert_float_equal(back.colors[i], cloud.colors[i], OBJ_COLOR_TOL);
    sk_mesh_free(&back);
    sk_mesh_free(&cloud);
    sk_mesh_free(&m);
}

static void test_obj_forms_and_negative_indices(void **state)
{
    (void)state;
    const char *text = "\xef\xbb\xbf# corner forms\r\n"
                       "mtllib scene.mtl\r\n"
                       "o thing\n"
                       "v 0 0 0\n"
                       "v 1 0 0 1.0\n" /* w */
                       "v\t1 1 0\n"
                       "v 0 1 0   # trailing comment\n"
                       "vt 0 0\nvt 1 0\nvt 1 1 0\n"
                       "vn 0 0 2\n" /* not unit: normalised on read */
                       "g group\nusemtl m\ns off\n"
                       "\n"
                       "f 1/1/1 2/2/1 3/3/1\n"
                       "f -4/-3/-1 -2/-1/-1 -1/-3/-1\n" /* 1/1/1 3/3/1 4/1/1 */
                       "l 1 2\n";
    sk_mesh m;
    SK_ASSERT_OK(sk_mesh_read_obj(&m, write_text("mesh/forms.obj", text), NULL, &e_));
    assert_int_equal(m.triangle_count, 2);
    assert_int_equal(m.vertex_count, 4); /* 1/1/1, 2/2/1, 3/3/1, 4/1/1 */
    assert_non_null(m.uvs);
    assert_non_null(m.normals);
    assert_int_equal(m.indices[3], m.indices[0]); /* -4/-3/-1 is 1/1/1 */
    assert_int_equal(m.indices[4], m.indices[2]); /* -2/-1/-1 is 3/3/1 */
    const float *p = m.positions + 3 * m.indices[5];
    assert_float_equal(p[0], 0.0f, 0.0);
    assert_float_equal(p[1], 1.0f, 0.0);
    assert_float_equal(m.normals[3 * m.indices[0] + 2], 1.0f, 0.0);
    sk_mesh_free(&m);

    /* v//vn on some faces, plain v on others: the missing normals are computed. */
    const char *mixed = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvn 0 0 1\n"
                        "f 1//1 2//1 3//1\nf 2 4 3\n";
    SK_ASSERT_OK(sk_mesh_read_obj(&m, write_text("mesh/mixed.obj", mixed), NULL, &e_));
    assert_int_equal(m.vertex_count, 6);
    for (size_t v = 0; v < m.vertex_count; v++)
        assert_float_equal(m.normals[3 * v + 2], 1.0f, 1e-6);
    sk_mesh_free(&m);
}

static void test_obj_polygons(void **state)
{
    (void)state;
    float pts[6][3];
    double normal[3];
    l_shape(pts, normal);
    char text[1024];
    int n = 0;
    for (int i = 0; i < 6; i++)
        n += snprintf(text + n, sizeof text - (size_t)n, "v %.9g %.9g %.9g\n", pts[i][0], pts[i][1],
                      pts[i][2]);
    snprintf(text + n, sizeof text - (size_t)n,
             "v 10 0 0\nv 11 0 0\nv 11 1 0\nv 10 1 0\nf 1 2 3 4 5 6\nf 7 8 9 10\n");
    sk_mesh m;
    SK_ASSERT_OK(sk_mesh_read_obj(&m, write_text("mesh/polygons.obj", text), NULL, &e_));
    assert_int_equal(m.triangle_count, 4 + 2);
    bool facing;
    sk_mesh l = m;
    l.triangle_count = 4; /* the hexagon's triangles come first */
    assert_float_equal(mesh_area(&l, normal, &facing), 3.0, 1e-5);
    assert_true(facing);
    double up[3] = {0, 0, 1};
    l.indices = m.indices + 12;
    l.triangle_count = 2;
    assert_float_equal(mesh_area(&l, up, &facing), 1.0, 1e-6);
    assert_true(facing);
    sk_mesh_free(&m);

    /* A convex 600-gon is past the ear clipping limit: fanned, area still exact. */
    enum { N = 600 };
    size_t cap = (size_t)N * 48 + 8192;
    char *big = malloc(cap);
    n = 0;
    for (int i = 0; i < N; i++)
        n += snprintf(big + n, cap - (size_t)n, "v %.9g %.9g 0\n", cos(2 * SK_PI * i / N),
                      sin(2 * SK_PI * i / N));
    n += snprintf(big + n, cap - (size_t)n, "f");
    for (int i = 1; i <= N; i++) n += snprintf(big + n, cap - (size_t)n, " %d", i);
    snprintf(big + n, cap - (size_t)n, "\n");
    SK_ASSERT_OK(sk_mesh_read_obj(&m, write_text("mesh/circle.obj", big), NULL, &e_));
    free(big);
    assert_int_equal(m.triangle_count, N - 2);
    assert_float_equal(mesh_area(&m, up, &facing), 0.5 * N * sin(2 * SK_PI / N), 1e-4);
    assert_true(facing);
    sk_mesh_free(&m);
}

static void test_obj_malformed(void **state)
{
    (void)state;
    const char *tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    char text[256];
    snprintf(text, sizeof text, "%sf 1 2 4\n", tri);
    expect_bad_obj("mesh/bad_range.obj", text, SK_ERROR_PARSE, "bad_range.obj:4: vertex index 4");
    snprintf(text, sizeof text, "%sf 0 1 2\n", tri);
    expect_bad_obj("mesh/bad_zero.obj", text, SK_ERROR_PARSE, "bad_zero.obj:4: vertex index 0");
    snprintf(text, sizeof text, "%sf -4 1 2\n", tri);
    expect_bad_obj("mesh/bad_negative.obj", text, SK_ERROR_PARSE, ":4: vertex index -4");
    expect_bad_obj("mesh/bad_nan.obj", "v 0 0 0\nv nan 0 0\n", SK_ERROR_PARSE, "bad_nan.obj:2:");
    expect_bad_obj("mesh/bad_inf.obj", "v 1e999 0 0\n", SK_ERROR_PARSE, ":1: coordinate");
    expect_bad_obj("mesh/bad_short.obj", "v 1 2\n", SK_ERROR_PARSE, ":1: v needs 3");
    expect_bad_obj("mesh/bad_token.obj", "v 1 2 3x\n", SK_ERROR_PARSE, "\"3x\"");
    snprintf(text, sizeof text, "%sf 1 2\n", tri);
    expect_bad_obj("mesh/bad_two.obj", text, SK_ERROR_PARSE, ":4: a face needs at least 3");
    snprintf(text, sizeof text, "%sf 1/1/1/1 2 3\n", tri);
    expect_bad_obj("mesh/bad_slashes.obj", text, SK_ERROR_PARSE, ":4: face corner");
    snprintf(text, sizeof text, "%sf 1/1 2/1 3/1\n", tri);
    expect_bad_obj("mesh/bad_vt.obj", text, SK_ERROR_PARSE, "texture coordinate index 1");
    expect_bad_obj("mesh/bad_keyword.obj", "v 0 0 0\nvx 1 2 3\n", SK_ERROR_PARSE,
                   ":2: unknown statement \"vx\"");
    expect_bad_obj("mesh/bad_vn.obj", "vn 0 0\n", SK_ERROR_PARSE, ":1: vn needs 3");

    /* A cap smaller than what the file needs. */
    sk_mesh m;
    sk_error err = {0};
    sk_mesh_read_desc small = {.max_bytes = 64};
    snprintf(text, sizeof text, "%sf 1 2 3\n", tri);
    sk_test_expect_failure(sk_mesh_read_obj(&m, write_text("mesh/capped.obj", text), &small, &err),
                           &err, SK_ERROR_LIMIT, NULL);
    sk_test_expect_failure(sk_mesh_read_obj(&m, sk_test_path("mesh/none.obj"), NULL, &err), &err,
                           SK_ERROR_NOT_FOUND, "none.obj");
}

static void test_obj_material(void **state)
{
    (void)state;
    sk_mesh m;
    make_grid(&m, false);
    const char *path = sk_test_path("mesh/textured.obj");
    const char *mtl = sk_test_path("mesh/textured.mtl");
    sk_obj_write_desc desc = {.texture_path = "textures/skin albedo.png", .material_name = "skin"};
    SK_ASSERT_OK(sk_mesh_write_obj(&m, path, &desc, &e_));
    char *text;
    SK_ASSERT_OK(sk_read_file(path, 0, &text, NULL, &e_));
    assert_non_null(strstr(text, "mtllib textured.mtl\nusemtl skin\n"));
    free(text);
    SK_ASSERT_OK(sk_read_file(mtl, 0, &text, NULL, &e_));
    assert_non_null(strstr(text, "newmtl skin\n"));
    assert_non_null(strstr(text, "map_Kd textures/skin albedo.png\n"));
    free(text);
    sk_error err = {0};
    sk_obj_write_desc bad = {.texture_path = "t.png", .material_name = "two words"};
    sk_test_expect_failure(sk_mesh_write_obj(&m, sk_test_path("mesh/bad_mtl.obj"), &bad, &err),
                           &err, SK_ERROR_INVALID_ARGUMENT, "material_name");
    assert_false(sk_test_file_exists(sk_test_path("mesh/bad_mtl.obj")));
    sk_mesh_free(&m);
}

/* Files hold vertex colours sRGB-encoded, as Blender and MeshLab read them: a linear 0.5
 * is 0.735356987 in an OBJ and code 188 in a PLY (written linearly, Blender showed 0.21), and
 * both read back as 0.5. */
static void test_vertex_colors_are_srgb_in_files(void **state)
{
    (void)state;
    sk_mesh m, back;
    SK_ASSERT_OK(sk_mesh_create(&m, 3, 1, SK_MESH_COLORS, &e_));
    for (int i = 0; i < 9; i++) m.positions[i] = (float)(i % 4);
    m.indices[0] = 0, m.indices[1] = 1, m.indices[2] = 2;
    const float linear[3] = {0.5f, 0.0031308f * 0.5f, 1.0f};
    for (int v = 0; v < 3; v++)
        for (int c = 0; c < 3; c++) m.colors[3 * v + c] = linear[c];
    const char *obj = sk_test_path("mesh/srgb.obj"), *ply = sk_test_path("mesh/srgb.ply");
    SK_ASSERT_OK(sk_mesh_write_obj(&m, obj, NULL, &e_));
    char *text;
    size_t size;
    SK_ASSERT_OK(sk_read_file(obj, 0, &text, &size, &e_));
    assert_non_null(strstr(text, " 0.735356987 0.020224968 1\n"));
    free(text);
    SK_ASSERT_OK(sk_mesh_read_obj(&back, obj, NULL, &e_));
    for (int c = 0; c < 3; c++) assert_float_equal(back.colors[c], linear[c], OBJ_COLOR_TOL);
    sk_mesh_free(&back);
    SK_ASSERT_OK(sk_mesh_write_ply(&m, ply, &e_));
    SK_ASSERT_OK(sk_read_file(ply, 0, &text, &size, &e_));
    /* the first vertex record follows the header: x y z floats, then r g b bytes */
    const char *body = strstr(text, "end_header\n") + 11;
    const unsigned char *rgb = (const unsigned char *)body + 12;
    assert_int_equal(rgb[0], 188);
    assert_int_equal(rgb[1], 5); /* 255 * 12.92 * 0.00157 = 5.2 */
    assert_int_equal(rgb[2], 255);
    free(text);
    SK_ASSERT_OK(sk_mesh_read_ply(&back, ply, NULL, &e_));
    for (int c = 0; c < 3; c++) assert_float_equal(back.colors[c], linear[c], PLY_COLOR_TOL);
    assert_float_equal(back.colors[0], sk_linear_from_srgb(188.0f / 255.0f), 1e-7);
    sk_mesh_free(&back);
    sk_mesh_free(&m);
}

/* Several objects with their own materials in one OBJ and its MTL. */
static void test_obj_objects_and_materials(void **state)
{
    (void)state;
    sk_mesh m, back;
    make_grid(&m, false);
    const sk_obj_material mats[2] = {{"oak", {0.5f, 0.25f, 0.125f}, "oak.png"},
                                     {"paint", {1, 0, 0}, NULL}};
    const sk_obj_group groups[3] = {{"lid", 4, 0}, {"side", 6, 1}, {"base", 2, -1}};
    sk_obj_write_desc desc = {
        .materials = mats, .material_count = 2, .groups = groups, .group_count = 3};
    const char *path = sk_test_path("mesh/objects.obj");
    SK_ASSERT_OK(sk_mesh_write_obj(&m, path, &desc, &e_));
    char *text;
    SK_ASSERT_OK(sk_read_file(path, 0, &text, NULL, &e_));
    assert_non_null(strstr(text, "mtllib objects.mtl\n"));
    assert_non_null(strstr(text, "\no lid\nusemtl oak\nf "));
    assert_non_null(strstr(text, "\no side\nusemtl paint\nf "));
    assert_non_null(strstr(text, "\no base\nf "));
    assert_int_equal(sk_test_count_lines(strstr(text, "\no side\n") + 1), 1 + 1 + 6 + 1 + 2);
    free(text);
    SK_ASSERT_OK(sk_read_file(sk_test_path("mesh/objects.mtl"), 0, &text, NULL, &e_));
    assert_non_null(strstr(text, "newmtl oak\nKa 0 0 0\nKd 0.5 0.25 0.125\n"));
    assert_non_null(strstr(text, "map_Kd oak.png\n"));
    assert_non_null(strstr(text, "newmtl paint\nKa 0 0 0\nKd 1 0 0\n"));
    free(text);
    SK_ASSERT_OK(sk_mesh_read_obj(&back, path, NULL, &e_));
    assert_same_triangles(&m, &back, OBJ_COLOR_TOL);
    sk_mesh_free(&back);
    sk_error err = {0};
    const sk_obj_group short_groups[1] = {{"lid", 4, 0}};
    desc.groups = short_groups;
    desc.group_count = 1;
    sk_test_expect_failure(sk_mesh_write_obj(&m, sk_test_path("mesh/bad_groups.obj"), &desc, &err),
                           &err, SK_ERROR_INVALID_ARGUMENT,
                           "the groups hold 4 triangles, the mesh has 12");
    const sk_obj_group bad_material[1] = {{"all", 12, 2}};
    desc.groups = bad_material;
    sk_test_expect_failure(sk_mesh_write_obj(&m, sk_test_path("mesh/bad_groups.obj"), &desc, &err),
                           &err, SK_ERROR_INVALID_ARGUMENT, "groups[0].material = 2");
    const sk_obj_material bad_kd[1] = {{"x", {2, 0, 0}, NULL}};
    sk_obj_write_desc kd = {.materials = bad_kd, .material_count = 1};
    sk_test_expect_failure(sk_mesh_write_obj(&m, sk_test_path("mesh/bad_groups.obj"), &kd, &err),
                           &err, SK_ERROR_INVALID_ARGUMENT, "materials[0].diffuse[0]");
    assert_false(sk_test_file_exists(sk_test_path("mesh/bad_groups.obj")));
    sk_mesh_free(&m);
}

/* ------------------------------------------------------------------ PLY */

static void test_ply_roundtrip(void **state)
{
    (void)state;
    sk_mesh m, back;
    make_grid(&m, true);
    const char *path = sk_test_path("mesh/grid.ply");
    SK_ASSERT_OK(sk_mesh_write_ply(&m, path, &e_));
    SK_ASSERT_OK(sk_mesh_read_ply(&back, path, NULL, &e_));
    assert_int_equal(back.vertex_count, 12);
    assert_memory_equal(back.indices, m.indices, 36 * sizeof(uint32_t));
    assert_same_triangles(&m, &back, PLY_COLOR_TOL);
    assert_int_equal(back.attribute_count, 2);
    for (int a = 0; a < 2; a++) {
        const sk_mesh_attribute *want = &m.attributes[a];
        const sk_mesh_attribute *got = sk_mesh_find_attribute(&back, want->name);
        assert_non_null(got);
        assert_int_equal(got->components, want->components);
        assert_memory_equal(got->data, want->data, 12 * sizeof(float) * (size_t)want->components);
    }
    sk_mesh_free(&back);
    /* Writing through sk_mesh_write by extension gives the same file content. */
    const char *upper = sk_test_path("mesh/grid_upper.PLY");
    SK_ASSERT_OK(sk_mesh_write(&m, upper, &e_));
    SK_ASSERT_OK(sk_mesh_read(&back, upper, NULL, &e_));
    assert_same_triangles(&m, &back, PLY_COLOR_TOL);
    sk_mesh_free(&back);
    sk_mesh_free(&m);
}

static void test_ply_ascii(void **state)
{
    (void)state;
    const char *text = "ply\r\n"
                       "format ascii 1.0\n"
                       "comment hand written\n"
                       "obj_info test\n"
                       "element vertex 5\n"
                       "property float x\nproperty float y\nproperty float z\n"
                       "property float nx\nproperty float ny\nproperty float nz\n"
                       "property float u\nproperty float v\n"
                       "property uchar red\nproperty uchar green\nproperty uchar blue\n"
                       "property float quality\n"
                       "element face 2\n"
                       "property list uchar int vertex_indices\n"
                       "property uchar flags\n"
                       "element edge 1\n"
                       "property list uchar int vertex_pair\n"
                       "end_header\n"
                       "0 0 0 0 0 1 0 0 255 0 0 0.5\n"
                       "1 0 0 0 0 2 1 0 0 255 0 1.5\n"
                       "1 1 0 0 0 1 1 1 0 0 255 2.5\n"
                       "0 1 0 0 0 1 0 1 51 102 153 3.5\n"
                       "\n"
                       "2 2 0 0 0 1 0.5 0.5 0 0 0 -1e-3\n"
                       "4 0 1 2 3 7\n"
                       "3 1 4 2 0\n"
                       "2 0 1\n";
    sk_mesh m;
    SK_ASSERT_OK(sk_mesh_read_ply(&m, write_text("mesh/ascii.ply", text), NULL, &e_));
    assert_int_equal(m.vertex_count, 5);
    assert_int_equal(m.triangle_count, 3);
    assert_non_null(m.normals);
    assert_non_null(m.uvs);
    assert_non_null(m.colors);
    assert_float_equal(m.normals[5], 1.0f, 0.0); /* (0, 0, 2) normalised */
    assert_float_equal(m.uvs[2 * 2 + 1], 1.0f, 0.0);
    assert_float_equal(m.colors[3 * 3 + 1], sk_linear_from_srgb(0.4f), 1e-7); /* 102 / 255, sRGB */
    const sk_mesh_attribute *q = sk_mesh_find_attribute(&m, "quality");
    assert_non_null(q);
    assert_float_equal(q->data[4], -1e-3f, 0.0);
    bool facing;
    double up[3] = {0, 0, 1};
    /* The quad (area 1) and the triangle 1-4-2 (area 0.5). */
    assert_float_equal(mesh_area(&m, up, &facing), 1.5, 1e-6);
    assert_true(facing);
    sk_mesh_free(&m);
}

/* A byte writer for hand-made binary PLY bodies. */
typedef struct bytes {
    unsigned char data[4096];
    size_t n;
    bool big;
} bytes;

static void put(bytes *b, const void *src, size_t size)
{
    const unsigned char *s = src;
    for (size_t i = 0; i < size; i++) b->data[b->n + i] = s[b->big ? size - 1 - i : i];
    b->n += size;
}
static void put_text(bytes *b, const char *s)
{
    memcpy(b->data + b->n, s, strlen(s));
    b->n += strlen(s);
}
static void put_f32(bytes *b, float v) { put(b, &v, 4); }
static void put_f64(bytes *b, double v) { put(b, &v, 8); }
static void put_u8(bytes *b, uint8_t v) { put(b, &v, 1); }
static void put_i16(bytes *b, int16_t v) { put(b, &v, 2); }
static void put_u16(bytes *b, uint16_t v) { put(b, &v, 2); }
static void put_i32(bytes *b, int32_t v) { put(b, &v, 4); }
static void put_u32(bytes *b, uint32_t v) { put(b, &v, 4); }

/* The test machine is little-endian; `put` reverses bytes for big-endian files. */
static void make_binary(bytes *b, bool big, uint64_t vertex_count)
{
    memset(b, 0, sizeof *b);
    b->big = big;
    char header[512];
    snprintf(header, sizeof header,
             "ply\nformat %s 1.0\n"
             "element vertex %llu\n"
             "property double x\nproperty float y\nproperty short z\n"
             "property uchar red\nproperty uchar green\nproperty uchar blue\n"
             "property char c\nproperty ushort us\nproperty int i\nproperty uint ui\n"
             "property list uchar float skipped_list\n"
             "element face 2\n"
             "property int material\n"
             "property list ushort uint vertex_index\n"
             "end_header\n",
             big ? "binary_big_endian" : "binary_little_endian", (unsigned long long)vertex_count);
    put_text(b, header);
    for (int v = 0; v < 4; v++) {
        put_f64(b, (v & 1) ? 1.0 : 0.0);
        put_f32(b, (v & 2) ? 1.0f : 0.0f);
        put_i16(b, (int16_t)(-v));
        put_u8(b, (uint8_t)(v * 60));
        put_u8(b, 0);
        put_u8(b, 255);
        put_u8(b, (uint8_t)(int8_t)(-v));
        put_u16(b, (uint16_t)(60000 + v));
        put_i32(b, -100000 * v);
        put_u32(b, 4000000000u + (uint32_t)v);
        put_u8(b, (uint8_t)v); /* v floats in the skipped list */
        for (int k = 0; k < v; k++) put_f32(b, 9.0f);
    }
    /* Face 0: triangle 0 1 3; face 1: triangle 0 3 2. */
    static const uint32_t faces[2][3] = {{0, 1, 3}, {0, 3, 2}};
    for (int f = 0; f < 2; f++) {
        put_i32(b, 42);
        put_u16(b, 3);
        for (int k = 0; k < 3; k++) put_u32(b, faces[f][k]);
    }
}

static void test_ply_binary_both_endians(void **state)
{
    (void)state;
    for (int big = 0; big < 2; big++) {
        bytes b;
        make_binary(&b, big, 4);
        const char *path = sk_test_path(big ? "mesh/be.ply" : "mesh/le.ply");
        sk_test_write_file(path, b.data, b.n);
        sk_mesh m;
        SK_ASSERT_OK(sk_mesh_read_ply(&m, path, NULL, &e_));
        assert_int_equal(m.vertex_count, 4);
        assert_int_equal(m.triangle_count, 2);
        assert_float_equal(m.positions[3 * 3], 1.0f, 0.0);
        assert_float_equal(m.positions[3 * 3 + 1], 1.0f, 0.0);
        assert_float_equal(m.positions[3 * 3 + 2], -3.0f, 0.0);
        assert_float_equal(m.colors[3 * 2], sk_linear_from_srgb(120.0f / 255.0f), 1e-7);
        assert_float_equal(m.colors[3 * 2 + 2], 1.0f, 0.0);
        static const char *const names[4] = {"c", "us", "i", "ui"};
        const double want[4] = {-3, 60003, -300000, 4000000003.0};
        assert_int_equal(m.attribute_count, 4);
        for (int a = 0; a < 4; a++) {
            const sk_mesh_attribute *attr = sk_mesh_find_attribute(&m, names[a]);
            assert_non_null(attr);
            assert_float_equal(attr->data[3], (float)want[a], 0.0);
        }
        assert_int_equal(m.indices[4], 3);
        assert_int_equal(m.indices[5], 2);
        sk_mesh_free(&m);
    }
}

static void test_ply_point_cloud(void **state)
{
    (void)state;
    const char *text = "ply\nformat ascii 1.0\nelement vertex 3\n"
                       "property float x\nproperty float y\nproperty float z\n"
                       "property float f_dc_0\nproperty float f_dc_1\nproperty float f_dc_2\n"
                       "property float opacity\nend_header\n"
                       "1 2 3 0.1 0.2 0.3 1\n4 5 6 0 0 0 0\n7 8 9 1 1 1 0.5\n";
    sk_mesh m;
    SK_ASSERT_OK(sk_mesh_read_ply(&m, write_text("mesh/cloud.ply", text), NULL, &e_));
    assert_int_equal(m.vertex_count, 3);
    assert_int_equal(m.triangle_count, 0);
    assert_null(m.indices);
    assert_float_equal(m.positions[8], 9.0f, 0.0);
    /* f_dc_0..2 is one 3-component attribute. */
    const sk_mesh_attribute *dc = sk_mesh_find_attribute(&m, "f_dc");
    assert_non_null(dc);
    assert_int_equal(dc->components, 3);
    assert_float_equal(dc->data[2], 0.3f, 0.0);
    assert_non_null(sk_mesh_find_attribute(&m, "opacity"));
    sk_mesh_free(&m);
}

static void test_ply_malformed(void **state)
{
    (void)state;
    const char *head = "ply\nformat ascii 1.0\nelement vertex 3\n"
                       "property float x\nproperty float y\nproperty float z\n"
                       "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
    const char *verts = "0 0 0\n1 0 0\n0 1 0\n";
    char text[1024];
    snprintf(text, sizeof text, "%s%s3 0 1 3\n", head, verts);
    expect_bad_ply("mesh/p_range.ply", text, strlen(text), SK_ERROR_PARSE,
                   "face 0: vertex index 3 is out of range");
    snprintf(text, sizeof text, "%s%s2 0 1\n", head, verts);
    expect_bad_ply("mesh/p_two.ply", text, strlen(text), SK_ERROR_PARSE,
                   "face 0: face has 2 vertices");
    snprintf(text, sizeof text, "%s0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n", head);
    expect_bad_ply("mesh/p_nan.ply", text, strlen(text), SK_ERROR_PARSE,
                   "p_nan.ply:11: vertex 1: x is not a finite number");
    snprintf(text, sizeof text, "%s%s3 0 1 2\nextra\n", head, verts);
    expect_bad_ply("mesh/p_trailing.ply", text, strlen(text), SK_ERROR_PARSE, "trailing");
    snprintf(text, sizeof text, "%s0 0 0 7\n1 0 0\n0 1 0\n3 0 1 2\n", head);
    expect_bad_ply("mesh/p_extra.ply", text, strlen(text), SK_ERROR_PARSE,
                   "p_extra.ply:10: vertex 0: line has more values");
    snprintf(text, sizeof text, "%s0 0\n1 0 0\n0 1 0\n3 0 1 2\n", head);
    expect_bad_ply("mesh/p_few.ply", text, strlen(text), SK_ERROR_PARSE,
                   "p_few.ply:10: vertex 0: line has fewer values");
    const char *no_end = "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n";
    expect_bad_ply("mesh/p_noend.ply", no_end, strlen(no_end), SK_ERROR_PARSE, "end_header");
    const char *bad_format = "ply\nformat binary_middle_endian 1.0\nend_header\n";
    expect_bad_ply("mesh/p_format.ply", bad_format, strlen(bad_format), SK_ERROR_PARSE,
                   "p_format.ply:2: unknown format");
    const char *version = "ply\nformat ascii 2.0\nend_header\n";
    expect_bad_ply("mesh/p_version.ply", version, strlen(version), SK_ERROR_UNSUPPORTED, "2.0");
    expect_bad_ply("mesh/p_notply.ply", "solid cube\n", 11, SK_ERROR_PARSE, "not a PLY file");

    /* Binary: truncated body, NaN coordinate, a header claiming 2^40 vertices. */
    bytes b;
    make_binary(&b, false, 4);
    expect_bad_ply("mesh/p_truncated.ply", b.data, b.n - 5, SK_ERROR_PARSE,
                   "face 1: file is truncated");
    size_t header_len = (size_t)(strstr((char *)b.data, "end_header\n") - (char *)b.data) + 11;
    double nan_value = NAN;
    memcpy(b.data + header_len, &nan_value, 8); /* x of vertex 0 */
    expect_bad_ply("mesh/p_bin_nan.ply", b.data, b.n, SK_ERROR_PARSE,
                   "vertex 0: x is not a finite number");
    make_binary(&b, false, (uint64_t)1 << 40);
    assert_true(b.n < 4096);
    const char *huge = sk_test_path("mesh/p_huge.ply");
    sk_test_write_file(huge, b.data, 200 + 300); /* the header and a little data */
    sk_mesh m;
    sk_error err = {0};
    sk_result r = sk_mesh_read_ply(&m, huge, NULL, &err);
    if (r != SK_ERROR_PARSE && r != SK_ERROR_LIMIT) fail_msg("got %s", sk_result_string(r));
    if (!strstr(err.message, "1099511627776")) fail_msg("message: %s", err.message);
    if (getenv("SK_TEST_VERBOSE")) print_message("%s\n", err.message);
    assert_null(m.positions);
    /* Binary trailing data. */
    make_binary(&b, false, 4);
    b.data[b.n++] = 0;
    expect_bad_ply("mesh/p_bin_trailing.ply", b.data, b.n, SK_ERROR_PARSE, "1 bytes of trailing");
}

static void test_mesh_dispatch_and_writer_checks(void **state)
{
    (void)state;
    sk_mesh m;
    sk_error err = {0};
    make_grid(&m, false);
    sk_test_expect_failure(sk_mesh_write(&m, sk_test_path("mesh/x.stl"), &err), &err,
                           SK_ERROR_UNSUPPORTED, ".obj, .ply");
    sk_mesh back;
    sk_test_expect_failure(sk_mesh_read(&back, sk_test_path("mesh/x.stl"), NULL, &err), &err,
                           SK_ERROR_UNSUPPORTED, ".obj, .ply");
    const char *obj = sk_test_path("mesh/upper.OBJ");
    SK_ASSERT_OK(sk_mesh_write(&m, obj, &e_));
    SK_ASSERT_OK(sk_mesh_read(&back, obj, NULL, &e_));
    assert_same_triangles(&m, &back, OBJ_COLOR_TOL);
    sk_mesh_free(&back);
    /* Attribute names must survive as PLY property names. */
    SK_ASSERT_OK(sk_mesh_add_attribute(&m, "red", 1, NULL, &e_));
    sk_test_expect_failure(sk_mesh_write_ply(&m, sk_test_path("mesh/red.ply"), &err), &err,
                           SK_ERROR_INVALID_ARGUMENT, "red");
    /* An invalid mesh is refused and no file is made. */
    m.attribute_count = 0;
    free(m.attributes[0].data);
    m.attributes[0].data = NULL;
    m.positions[4] = INFINITY;
    const char *bad = sk_test_path("mesh/invalid.ply");
    sk_test_expect_failure(sk_mesh_write_ply(&m, bad, &err), &err, SK_ERROR_INVALID_ARGUMENT,
                           "vertex 1");
    assert_false(sk_test_file_exists(bad));
    sk_mesh_free(&m);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_mesh_create_and_attributes),
        cmocka_unit_test(test_mesh_validate_and_bounds),
        cmocka_unit_test(test_compute_normals_cube),
        cmocka_unit_test(test_compute_normals_sphere),
        cmocka_unit_test(test_triangulate_concave_and_degenerate),
        cmocka_unit_test(test_obj_roundtrip),
        cmocka_unit_test(test_obj_forms_and_negative_indices),
        cmocka_unit_test(test_obj_polygons),
        cmocka_unit_test(test_obj_malformed),
        cmocka_unit_test(test_obj_material),
        cmocka_unit_test(test_obj_objects_and_materials),
        cmocka_unit_test(test_vertex_colors_are_srgb_in_files),
        cmocka_unit_test(test_ply_roundtrip),
        cmocka_unit_test(test_ply_ascii),
        cmocka_unit_test(test_ply_binary_both_endians),
        cmocka_unit_test(test_ply_point_cloud),
        cmocka_unit_test(test_ply_malformed),
        cmocka_unit_test(test_mesh_dispatch_and_writer_checks),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
