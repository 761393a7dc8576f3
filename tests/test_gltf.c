/* Tests of the glTF writer and reader: round trips of every attribute, node transforms,
 * skins (inverse bind matrices against the inverses of the joints' world transforms),
 * morph targets and animation keys; deterministic bytes; the writer's refusals (bad
 * indices, NaN, weights not summing to 1, non-increasing times, ...); and the reader's
 * strictness on damaged files (chunk layout, bounds, indices, sparse accessors, caps). */
#define _POSIX_C_SOURCE 200809L
#include "test_result.h"
#include "test_support.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cjson/cJSON.h>

#include "gltf_read_back.h"
#include "gltf_samples.h"
#include "shitsukan/gltf.h"
#include "shitsukan/image.h"
#include "shitsukan/io.h"
#include "shitsukan/render.h"

/* ------------------------------------------------------------------ helpers */

/* A 3 x 3 vertex grid (8 triangles) in the xz plane with normals, uvs and colours. */
static void make_grid(sk_mesh *m)
{
    SK_ASSERT_OK(sk_mesh_create(m, 9, 8, SK_MESH_NORMALS | SK_MESH_UVS | SK_MESH_COLORS, &e_));
    for (int y = 0; y < 3; y++)
        for (int x = 0; x < 3; x++) {
            size_t v = (size_t)(3 * y + x);
            m->positions[3 * v] = 0.25f * (float)x - 0.1f;
            m->positions[3 * v + 1] = 0.01f * (float)(x * y);
            m->positions[3 * v + 2] = -0.3f * (float)y;
            m->normals[3 * v + 1] = 1.0f;
            m->uvs[2 * v] = 0.5f * (float)x;
            m->uvs[2 * v + 1] = 0.25f * (float)y;
            m->colors[3 * v] = (float)x / 2.0f;
            m->colors[3 * v + 1] = (float)y / 2.0f;
            m->colors[3 * v + 2] = 0.125f;
        }
    for (int y = 0; y < 2; y++)
        for (int x = 0; x < 2; x++) {
            uint32_t a = (uint32_t)(3 * y + x), b = a + 1, c = a + 3, d = c + 1;
            uint32_t *t = m->indices + 6 * (2 * y + x);
            t[0] = a, t[1] = c, t[2] = b, t[3] = b, t[4] = c, t[5] = d;
        }
}

static void assert_floats_equal(const float *a, const float *b, size_t n)
{
    for (size_t i = 0; i < n; i++)
        if (a[i] != b[i]) fail_msg("element %zu: %.9g != %.9g", i, (double)a[i], (double)b[i]);
}

/* Column-major 4x4 of T R S in double (the test's own derivation, not the library's). */
static void trs(const double t[3], const double q[4], const double s[3], double m[16])
{
    double x = q[0], y = q[1], z = q[2], w = q[3];
    double r[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
                      {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
                      {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}};
    memset(m, 0, 16 * sizeof(double));
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 3; j++) m[4 * j + i] = r[i][j] * s[j];
        m[12 + i] = t[i];
    }
    m[15] = 1;
}

static void mul(const double a[16], const double b[16], double out[16])
{
    double t[16];
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            double s = 0;
            for (int k = 0; k < 4; k++) s += a[4 * k + i] * b[4 * j + k];
            t[4 * j + i] = s;
        }
    memcpy(out, t, sizeof t);
}

/* Re-packs a GLB after `edit` changed its JSON (for damaged-file tests). */
typedef void (*json_edit)(cJSON *root);

static void repack(const uint8_t *glb, size_t size, json_edit edit, uint8_t **out, size_t *out_size)
{
    uint32_t json_len;
    memcpy(&json_len, glb + 12, 4);
    cJSON *root = cJSON_ParseWithLength((const char *)glb + 20, json_len);
    assert_non_null(root);
    edit(root);
    char *text = cJSON_PrintUnformatted(root);
    cJSON_Delete(root);
    size_t tl = strlen(text), tp = (tl + 3) & ~(size_t)3;
    size_t bin_at = 20 + json_len, bin_bytes = size - bin_at;
    size_t total = 20 + tp + bin_bytes;
    uint8_t *p = malloc(total);
    assert_non_null(p);
    memcpy(p, glb, 20);
    memcpy(p + 20, text, tl);
    memset(p + 20 + tl, ' ', tp - tl);
    memcpy(p + 20 + tp, glb + bin_at, bin_bytes);
    uint32_t t32 = (uint32_t)total, j32 = (uint32_t)tp;
    memcpy(p + 8, &t32, 4);
    memcpy(p + 12, &j32, 4);
    free(text);
    *out = p;
    *out_size = total;
}

static void expect_bad_glb(const uint8_t *data, size_t size, sk_result want, const char *needle)
{
    sk_gltf_doc *doc = (sk_gltf_doc *)1;
    sk_error err = {0};
    sk_test_expect_failure(sk_gltf_read_glb_memory(&doc, data, size, NULL, &err), &err, want,
                           needle);
    assert_null(doc);
}

static void expect_bad_edit(const uint8_t *glb, size_t size, json_edit edit, sk_result want,
                            const char *needle)
{
    uint8_t *p;
    size_t n;
    repack(glb, size, edit, &p, &n);
    expect_bad_glb(p, n, want, needle);
    free(p);
}

static cJSON *item(cJSON *root, const char *array, int index)
{
    cJSON *a = cJSON_GetObjectItem(root, array);
    assert_non_null(a);
    cJSON *o = cJSON_GetArrayItem(a, index);
    assert_non_null(o);
    return o;
}

static bool has_text(const uint8_t *bytes, size_t size, const char *text)
{
    size_t n = strlen(text);
    for (size_t i = 0; i + n <= size; i++)
        if (memcmp(bytes + i, text, n) == 0) return true;
    return false;
}

static void set_number(cJSON *obj, const char *key, double v)
{
    cJSON_DeleteItemFromObject(obj, key);
    cJSON_AddNumberToObject(obj, key, v);
}

/* ------------------------------------------------------------------ static meshes */

static void test_static_roundtrip(void **state)
{
    (void)state;
    sk_mesh grid;
    make_grid(&grid);
    SK_ASSERT_OK(sk_mesh_compute_tangents(&grid, &e_));
    sk_image colour, normal;
    SK_ASSERT_OK(sk_image_create(&colour, 4, 4, 4, &e_));
    SK_ASSERT_OK(sk_image_create(&normal, 4, 4, 3, &e_));
    for (int i = 0; i < 16; i++) {
        colour.data[4 * i] = 0.5f, colour.data[4 * i + 3] = i == 5 ? 0.5f : 1.0f;
        normal.data[3 * i + 2] = 1.0f;
    }
    sk_gltf *g;
    SK_ASSERT_OK(sk_gltf_create(&g, &e_));
    int mat, mesh, parent, child;
    sk_gltf_material_desc md = {
        .name = "m", .base_color_texture = &colour, .normal_texture = &normal};
    SK_ASSERT_OK(sk_gltf_add_material(g, &md, &mat, &e_));
    sk_gltf_mesh_desc d = {
        .name = "grid", .mesh = &grid, .uv_origin_bottom_left = true, .material = mat};
    SK_ASSERT_OK(sk_gltf_add_mesh(g, &d, &mesh, &e_));
    sk_gltf_node_desc n = sk_gltf_node_desc_default();
    n.name = "parent";
    n.translation[0] = 1.5, n.translation[2] = -2;
    n.rotation[0] = sin(0.2), n.rotation[3] = cos(0.2);
    n.scale[1] = 2, n.scale[0] = n.scale[2] = 0.5;
    SK_ASSERT_OK(sk_gltf_add_node(g, &n, &parent, &e_));
    n = sk_gltf_node_desc_default();
    n.name = "child";
    n.parent = parent;
    n.mesh = mesh;
    SK_ASSERT_OK(sk_gltf_add_node(g, &n, &child, &e_));

    uint8_t *bytes, *again, *file_bytes;
    size_t size, again_size, file_size;
    sk_gltf_doc *doc = sk_test_gltf_read_back(g, &bytes, &size);
    /* deterministic: the same document gives the same bytes, in memory and in a file */
    SK_ASSERT_OK(sk_gltf_write_glb_memory(g, NULL, &again, &again_size, &e_));
    assert_int_equal(size, again_size);
    assert_memory_equal(bytes, again, size);
    const char *path = sk_test_path("gltf/static.glb");
    SK_ASSERT_OK(sk_gltf_write_glb(g, path, NULL, &e_));
    SK_ASSERT_OK(sk_read_file(path, 0, (char **)&file_bytes, &file_size, &e_));
    assert_int_equal(file_size, size);
    assert_memory_equal(file_bytes, bytes, size);
    assert_int_equal(size % 4, 0);

    sk_gltf_doc_counts c = sk_gltf_doc_count(doc);
    assert_int_equal(c.nodes, 2);
    assert_int_equal(c.meshes, 1);
    assert_int_equal(c.materials, 1);
    assert_int_equal(c.images, 2);
    assert_int_equal(c.skins, 0);
    sk_gltf_doc_node dn;
    SK_ASSERT_OK(sk_gltf_doc_get_node(doc, parent, &dn, &e_));
    assert_string_equal(dn.name, "parent");
    assert_int_equal(dn.parent, SK_GLTF_NONE);
    assert_int_equal(dn.mesh, SK_GLTF_NONE);
    assert_true(dn.translation[0] == 1.5 && dn.translation[1] == 0 && dn.translation[2] == -2);
    assert_true(fabs(dn.rotation[0] - sin(0.2)) < 1e-15 && fabs(dn.rotation[3] - cos(0.2)) < 1e-15);
    assert_true(dn.scale[0] == 0.5 && dn.scale[1] == 2 && dn.scale[2] == 0.5);
    SK_ASSERT_OK(sk_gltf_doc_get_node(doc, child, &dn, &e_));
    assert_int_equal(dn.parent, parent);
    assert_int_equal(dn.mesh, mesh);
    assert_true(dn.rotation[3] == 1 && dn.scale[0] == 1);

    float *p = sk_test_gltf_accessor(doc, sk_gltf_doc_mesh_accessor(doc, mesh, "POSITION"), 9, 3);
    assert_floats_equal(p, grid.positions, 27);
    float *nn = sk_test_gltf_accessor(doc, sk_gltf_doc_mesh_accessor(doc, mesh, "NORMAL"), 9, 3);
    assert_floats_equal(nn, grid.normals, 27);
    float *col = sk_test_gltf_accessor(doc, sk_gltf_doc_mesh_accessor(doc, mesh, "COLOR_0"), 9, 3);
    assert_floats_equal(col, grid.colors, 27);
    float *uv =
        sk_test_gltf_accessor(doc, sk_gltf_doc_mesh_accessor(doc, mesh, "TEXCOORD_0"), 9, 2);
    for (int v = 0; v < 9; v++) {
        assert_true(uv[2 * v] == grid.uvs[2 * v]);
        assert_true(uv[2 * v + 1] == 1.0f - grid.uvs[2 * v + 1]); /* glTF's top-left origin */
    }
    float *tan = sk_test_gltf_accessor(doc, sk_gltf_doc_mesh_accessor(doc, mesh, "TANGENT"), 9, 4);
    for (int v = 0; v < 9; v++) {
        assert_true(fabsf(tan[4 * v + 3]) == 1.0f);
        float len = sqrtf(tan[4 * v] * tan[4 * v] + tan[4 * v + 1] * tan[4 * v + 1] +
                          tan[4 * v + 2] * tan[4 * v + 2]);
        assert_true(fabsf(len - 1.0f) < 1e-6f);
    }
    float *ix = sk_test_gltf_accessor(doc, sk_gltf_doc_mesh_accessor(doc, mesh, "indices"), 24, 1);
    for (int i = 0; i < 24; i++) assert_true(ix[i] == (float)grid.indices[i]);
    assert_int_equal(sk_gltf_doc_mesh_accessor(doc, mesh, "JOINTS_0"), -1);
    assert_int_equal(sk_gltf_doc_mesh_target_count(doc, mesh), 0);
    /* the texture with some alpha below 1 makes the material blend */
    assert_true(has_text(bytes, size, "\"alphaMode\":\"BLEND\""));
    assert_true(has_text(bytes, size, "\"mimeType\":\"image/png\""));
    free(p), free(nn), free(col), free(uv), free(tan), free(ix);
    free(bytes), free(again), free(file_bytes);
    sk_gltf_doc_free(doc);
    sk_gltf_destroy(g);
    sk_mesh_free(&grid);
    sk_image_free(&colour);
    sk_image_free(&normal);
}

/* The in-memory PNG the writer embeds holds the bytes of the PNG file writer. */
static void test_png_memory_matches_file(void **state)
{
    (void)state;
    sk_image im;
    SK_ASSERT_OK(sk_image_create(&im, 7, 5, 3, &e_));
    for (size_t i = 0; i < 7 * 5 * 3; i++) im.data[i] = (float)(i % 11) / 10.0f;
    uint8_t *mem;
    size_t mem_size;
    char *file;
    size_t file_size;
    SK_ASSERT_OK(sk_image_write_png_memory(&im, NULL, &mem, &mem_size, &e_));
    const char *path = sk_test_path("gltf/memory.png");
    SK_ASSERT_OK(sk_image_write_png(&im, path, NULL, &e_));
    SK_ASSERT_OK(sk_read_file(path, 0, &file, &file_size, &e_));
    assert_int_equal(mem_size, file_size);
    assert_memory_equal(mem, file, mem_size);
    sk_error err = {0};
    sk_png_write_desc bad = {.bit_depth = 12};
    uint8_t *none = (uint8_t *)1;
    size_t none_size = 1;
    sk_test_expect_failure(sk_image_write_png_memory(&im, &bad, &none, &none_size, &err), &err,
                           SK_ERROR_INVALID_ARGUMENT, "bit_depth");
    assert_null(none);
    assert_int_equal(none_size, 0);
    free(mem);
    free(file);
    sk_image_free(&im);
}

/* ------------------------------------------------------------------ skins and animation */

typedef struct chain {
    sk_gltf *g;
    int joints[3], mesh, skin, body, anim;
    sk_mesh mesh_data;
    uint16_t j[4 * 9];
    float w[4 * 9];
} chain;

/* A grid skinned to a 3-joint chain with rotations and scales, so that every joint's world
 * transform is non-trivial. */
static void make_chain(chain *c, const float *inverse_bind)
{
    memset(c, 0, sizeof *c);
    make_grid(&c->mesh_data);
    SK_ASSERT_OK(sk_gltf_create(&c->g, &e_));
    for (int v = 0; v < 9; v++) {
        uint16_t *j = c->j + 4 * v;
        float *w = c->w + 4 * v;
        j[0] = (uint16_t)(v % 3), j[1] = (uint16_t)((v + 1) % 3), j[2] = 2,
        j[3] = (uint16_t)((v + 2) % 3);
        /* not normalised to float exactness: the writer must do that */
        w[0] = 0.7f, w[1] = 0.2f, w[2] = 0.0f, w[3] = 0.1f;
        if (v == 4) w[0] = 1.0f, w[1] = w[3] = 0.0f;
        if (v == 5) j[0] = 2, j[1] = 0, j[3] = 1; /* joint 2 in slot 2 has weight 0: fine */
    }
    static const double t[3][3] = {{0.1, -0.2, 0.3}, {0, 0.5, 0}, {0.05, 0.4, -0.1}};
    static const double s[3][3] = {{1, 1, 1}, {1.5, 1.5, 1.5}, {1, 2, 0.5}};
    for (int k = 0; k < 3; k++) {
        sk_gltf_node_desc n = sk_gltf_node_desc_default();
        n.parent = k ? c->joints[k - 1] : SK_GLTF_NONE;
        memcpy(n.translation, t[k], sizeof n.translation);
        memcpy(n.scale, s[k], sizeof n.scale);
        double a = 0.3 * (k + 1);
        n.rotation[k] = sin(a / 2), n.rotation[3] = cos(a / 2);
        SK_ASSERT_OK(sk_gltf_add_node(c->g, &n, &c->joints[k], &e_));
    }
    sk_gltf_mesh_desc d = {
        .mesh = &c->mesh_data, .material = SK_GLTF_NONE, .joints = c->j, .weights = c->w};
    SK_ASSERT_OK(sk_gltf_add_mesh(c->g, &d, &c->mesh, &e_));
    SK_ASSERT_OK(sk_gltf_add_skin(c->g, NULL, c->joints, 3, inverse_bind, &c->skin, &e_));
    sk_gltf_node_desc n = sk_gltf_node_desc_default();
    n.mesh = c->mesh;
    n.skin = c->skin;
    SK_ASSERT_OK(sk_gltf_add_node(c->g, &n, &c->body, &e_));
    SK_ASSERT_OK(sk_gltf_add_animation(c->g, "wave", &c->anim, &e_));
}

static void test_skin_roundtrip(void **state)
{
    (void)state;
    chain c;
    make_chain(&c, NULL);
    float times[3] = {0.0f, 0.5f, 1.25f}, other_times[2] = {0.0f, 2.0f};
    float rot[12] = {0, 0, 0, 1, 0, 0.6f, 0, 0.8f, 0.6f, 0, 0, 0.8f};
    float move[9] = {0, 0, 0, 1, 2, 3, -1, 0.5f, 0};
    float grow[6] = {1, 1, 1, 2, 2, 2};
    SK_ASSERT_OK(sk_gltf_add_channel(c.g, c.anim, c.joints[1], SK_GLTF_PATH_ROTATION,
                                     SK_GLTF_INTERPOLATION_DEFAULT, times, 3, rot, &e_));
    SK_ASSERT_OK(sk_gltf_add_channel(c.g, c.anim, c.joints[0], SK_GLTF_PATH_TRANSLATION,
                                     SK_GLTF_INTERPOLATION_STEP, times, 3, move, &e_));
    SK_ASSERT_OK(sk_gltf_add_channel(c.g, c.anim, c.joints[2], SK_GLTF_PATH_SCALE,
                                     SK_GLTF_INTERPOLATION_LINEAR, other_times, 2, grow, &e_));
    sk_gltf_doc *doc = sk_test_gltf_read_back(c.g, NULL, NULL);
    assert_int_equal(sk_gltf_doc_count(doc).skins, 1);
    const int *joints;
    int joint_count, ibm;
    SK_ASSERT_OK(sk_gltf_doc_get_skin(doc, 0, &joints, &joint_count, &ibm, &e_));
    assert_int_equal(joint_count, 3);
    for (int k = 0; k < 3; k++) assert_int_equal(joints[k], c.joints[k]);
    float *m = sk_test_gltf_accessor(doc, ibm, 3, 16);
    /* inverse bind matrix x world transform of the joint (composed here from the read
       nodes' TRS) is the identity */
    for (int k = 0; k < 3; k++) {
        double world[16], local[16], prod[16], ib[16];
        sk_gltf_doc_node dn;
        SK_ASSERT_OK(sk_gltf_doc_get_node(doc, joints[k], &dn, &e_));
        trs(dn.translation, dn.rotation, dn.scale, world);
        for (int p = dn.parent; p != SK_GLTF_NONE;) {
            SK_ASSERT_OK(sk_gltf_doc_get_node(doc, p, &dn, &e_));
            trs(dn.translation, dn.rotation, dn.scale, local);
            mul(local, world, world);
            p = dn.parent;
        }
        for (int i = 0; i < 16; i++) ib[i] = m[16 * k + i];
        mul(ib, world, prod);
        for (int i = 0; i < 16; i++) assert_true(fabs(prod[i] - (i % 5 == 0 ? 1.0 : 0.0)) < 1e-6);
        /* the validator wants the last row exactly (0, 0, 0, 1) */
        assert_true(m[16 * k + 3] == 0 && m[16 * k + 7] == 0 && m[16 * k + 11] == 0 &&
                    m[16 * k + 15] == 1);
    }
    sk_gltf_doc_node body;
    SK_ASSERT_OK(sk_gltf_doc_get_node(doc, c.body, &body, &e_));
    assert_int_equal(body.skin, 0);
    assert_int_equal(body.mesh, c.mesh);
    float *jw =
        sk_test_gltf_accessor(doc, sk_gltf_doc_mesh_accessor(doc, c.mesh, "JOINTS_0"), 9, 4);
    float *ww =
        sk_test_gltf_accessor(doc, sk_gltf_doc_mesh_accessor(doc, c.mesh, "WEIGHTS_0"), 9, 4);
    for (int v = 0; v < 9; v++) {
        float sum = 0.0f; /* summed in float, in slot order, as the validator does */
        for (int k = 0; k < 4; k++) {
            float w = ww[4 * v + k];
            if (w != 0) sum += w;
            if (w == 0)
                assert_true(jw[4 * v + k] == 0.0f); /* weight 0 names joint 0 */
            else
                assert_true(jw[4 * v + k] == (float)c.j[4 * v + k]);
            double want = c.w[4 * v + k] /
                          (c.w[4 * v] + c.w[4 * v + 1] + c.w[4 * v + 2] + (double)c.w[4 * v + 3]);
            assert_true(fabs(w - want) < 1e-6);
        }
        assert_true(fabsf(sum - 1.0f) <= 2e-7f);
    }
    assert_int_equal(sk_gltf_doc_count(doc).animations, 1);
    assert_int_equal(sk_gltf_doc_channel_count(doc, 0), 3);
    sk_gltf_doc_channel ch[3];
    for (int k = 0; k < 3; k++) SK_ASSERT_OK(sk_gltf_doc_get_channel(doc, 0, k, &ch[k], &e_));
    assert_int_equal(ch[0].node, c.joints[1]);
    assert_int_equal(ch[0].path, SK_GLTF_PATH_ROTATION);
    assert_int_equal(ch[0].interpolation, SK_GLTF_INTERPOLATION_LINEAR);
    assert_int_equal(ch[1].path, SK_GLTF_PATH_TRANSLATION);
    assert_int_equal(ch[1].interpolation, SK_GLTF_INTERPOLATION_STEP);
    assert_int_equal(ch[2].path, SK_GLTF_PATH_SCALE);
    /* identical key times share one accessor */
    assert_int_equal(ch[0].input_accessor, ch[1].input_accessor);
    assert_true(ch[2].input_accessor != ch[0].input_accessor);
    float *tt = sk_test_gltf_accessor(doc, ch[0].input_accessor, 3, 1);
    assert_floats_equal(tt, times, 3);
    float *rv = sk_test_gltf_accessor(doc, ch[0].output_accessor, 3, 4);
    assert_floats_equal(rv, rot, 12);
    float *mv = sk_test_gltf_accessor(doc, ch[1].output_accessor, 3, 3);
    assert_floats_equal(mv, move, 9);
    float *gv = sk_test_gltf_accessor(doc, ch[2].output_accessor, 2, 3);
    assert_floats_equal(gv, grow, 6);
    free(m), free(jw), free(ww), free(tt), free(rv), free(mv), free(gv);
    sk_gltf_doc_free(doc);
    sk_gltf_destroy(c.g);

    /* given inverse bind matrices are written as given */
    float given[48];
    for (int i = 0; i < 48; i++) given[i] = (i % 16) % 5 == 0 ? 1.0f : 0.0f;
    given[12] = 0.25f, given[16 + 13] = -3.0f;
    chain d;
    make_chain(&d, given);
    SK_ASSERT_OK(sk_gltf_add_channel(d.g, d.anim, d.joints[0], SK_GLTF_PATH_ROTATION, 0, times, 1,
                                     rot, &e_));
    doc = sk_test_gltf_read_back(d.g, NULL, NULL);
    SK_ASSERT_OK(sk_gltf_doc_get_skin(doc, 0, &joints, &joint_count, &ibm, &e_));
    m = sk_test_gltf_accessor(doc, ibm, 3, 16);
    assert_floats_equal(m, given, 48);
    free(m);
    sk_gltf_doc_free(doc);
    sk_gltf_destroy(d.g);
    sk_mesh_free(&d.mesh_data);
    sk_mesh_free(&c.mesh_data);
}

/* ------------------------------------------------------------------ morph targets */

static void test_morph_roundtrip(void **state)
{
    (void)state;
    sk_mesh grid;
    make_grid(&grid);
    float targets[2 * 27], normals[2 * 27], defaults[2] = {0.5f, 0.0f};
    for (int i = 0; i < 54; i++)
        targets[i] = 0.01f * (float)(i % 7) - 0.02f, normals[i] = 0.001f * (float)i;
    const char *names[2] = {"smile", "frown"};
    sk_gltf *g;
    SK_ASSERT_OK(sk_gltf_create(&g, &e_));
    int mesh, node, linear, step;
    sk_gltf_mesh_desc d = {.mesh = &grid,
                           .material = SK_GLTF_NONE,
                           .target_count = 2,
                           .target_positions = targets,
                           .target_normals = normals,
                           .default_weights = defaults,
                           .target_names = names};
    SK_ASSERT_OK(sk_gltf_add_mesh(g, &d, &mesh, &e_));
    sk_gltf_node_desc n = sk_gltf_node_desc_default();
    n.mesh = mesh;
    SK_ASSERT_OK(sk_gltf_add_node(g, &n, &node, &e_));
    float times[3] = {0.0f, 1.0f, 2.0f}, w[6] = {0, 1, 1, 0, 0.25f, 0.75f};
    SK_ASSERT_OK(sk_gltf_add_animation(g, "linear", &linear, &e_));
    SK_ASSERT_OK(sk_gltf_add_channel(g, linear, node, SK_GLTF_PATH_WEIGHTS,
                                     SK_GLTF_INTERPOLATION_LINEAR, times, 3, w, &e_));
    SK_ASSERT_OK(sk_gltf_add_animation(g, "step", &step, &e_));
    SK_ASSERT_OK(sk_gltf_add_channel(g, step, node, SK_GLTF_PATH_WEIGHTS,
                                     SK_GLTF_INTERPOLATION_STEP, times, 3, w, &e_));
    uint8_t *bytes;
    size_t size;
    sk_gltf_doc *doc = sk_test_gltf_read_back(g, &bytes, &size);
    assert_int_equal(sk_gltf_doc_mesh_target_count(doc, mesh), 2);
    for (int t = 0; t < 2; t++) {
        float *tp = sk_test_gltf_accessor(
            doc, sk_gltf_doc_mesh_target_accessor(doc, mesh, t, "POSITION"), 9, 3);
        float *tn = sk_test_gltf_accessor(
            doc, sk_gltf_doc_mesh_target_accessor(doc, mesh, t, "NORMAL"), 9, 3);
        assert_floats_equal(tp, targets + 27 * t, 27);
        assert_floats_equal(tn, normals + 27 * t, 27);
        free(tp), free(tn);
    }
    assert_int_equal(sk_gltf_doc_mesh_target_accessor(doc, mesh, 2, "POSITION"), -1);
    assert_int_equal(sk_gltf_doc_mesh_target_accessor(doc, mesh, 0, "TANGENT"), -1);
    for (int a = 0; a < 2; a++) {
        sk_gltf_doc_channel ch;
        SK_ASSERT_OK(sk_gltf_doc_get_channel(doc, a, 0, &ch, &e_));
        assert_int_equal(ch.path, SK_GLTF_PATH_WEIGHTS);
        assert_int_equal(ch.node, node);
        assert_int_equal(ch.interpolation,
                         a == 0 ? SK_GLTF_INTERPOLATION_LINEAR : SK_GLTF_INTERPOLATION_STEP);
        float *wv = sk_test_gltf_accessor(doc, ch.output_accessor, 6,
                                          1); /* one scalar per target per key */
        assert_floats_equal(wv, w, 6);
        free(wv);
    }
    assert_true(has_text(bytes, size, "\"targetNames\":[\"smile\",\"frown\"]"));
    assert_true(has_text(bytes, size, "\"weights\":[0.5,0]"));
    free(bytes);
    sk_gltf_doc_free(doc);
    sk_gltf_destroy(g);
    sk_mesh_free(&grid);
}

/* The samples checked by the validator and Blender read back with their counts. */
static void test_samples_read_back(void **state)
{
    (void)state;
    for (int k = 0; k < SK_TEST_GLTF_KIND_COUNT; k++) {
        sk_test_gltf_sample s;
        SK_ASSERT_OK(sk_test_gltf_sample_make((sk_test_gltf_kind)k, &s, &e_));
        sk_gltf_doc *doc = sk_test_gltf_read_back(s.gltf, NULL, NULL);
        sk_gltf_doc_counts c = sk_gltf_doc_count(doc);
        assert_int_equal(c.meshes, s.meshes);
        assert_int_equal(c.animations, s.animations);
        if (s.joints) {
            const int *joints;
            int count, ibm;
            SK_ASSERT_OK(sk_gltf_doc_get_skin(doc, 0, &joints, &count, &ibm, &e_));
            assert_int_equal(count, s.joints);
        }
        assert_int_equal(s.shape_keys ? sk_gltf_doc_mesh_target_count(doc, 0) : 0, s.shape_keys);
        sk_gltf_doc_free(doc);
        sk_gltf_destroy(s.gltf);
    }
}

/* ------------------------------------------------------------------ writer errors */

static sk_result add_grid_mesh(sk_gltf *g, sk_mesh *m, const uint16_t *j, const float *w,
                               sk_error *err)
{
    int index;
    sk_gltf_mesh_desc d = {.mesh = m, .material = SK_GLTF_NONE, .joints = j, .weights = w};
    return sk_gltf_add_mesh(g, &d, &index, err);
}

/* What the writer's refusals build on, one step after another: the document, the grid
   (and a copy without uvs), its joints and weights, a texture, and the nodes the
   animations refer to. */
typedef struct refusals {
    sk_gltf *g;
    sk_mesh m, bare;
    uint16_t j[36];
    float w[36];
    sk_image tex;
    int root, skinned_node, node_plain;
} refusals;

/* Meshes: bad indices, NaN, colours and normals; weights and joints; morph targets. */
static void refuse_bad_meshes(refusals *t)
{
    sk_gltf *g = t->g;
    sk_mesh *m = &t->m;
    uint16_t *j = t->j;
    float *w = t->w;
    sk_error err = {0};
    int index = 0;

    m->indices[4] = 9; /* bad index */
    sk_test_expect_failure(add_grid_mesh(g, m, NULL, NULL, &err), &err, SK_ERROR_INVALID_ARGUMENT,
                           "meshes[0]");
    m->indices[4] = 3;
    m->positions[7] = NAN;
    sk_test_expect_failure(add_grid_mesh(g, m, NULL, NULL, &err), &err, SK_ERROR_INVALID_ARGUMENT,
                           "meshes[0]");
    m->positions[7] = 0.0f;
    m->colors[5] = 1.5f;
    sk_test_expect_failure(add_grid_mesh(g, m, NULL, NULL, &err), &err, SK_ERROR_INVALID_ARGUMENT,
                           "colors[1]");
    m->colors[5] = 0.5f;
    m->normals[4] = 0.0f; /* a zero normal */
    sk_test_expect_failure(add_grid_mesh(g, m, NULL, NULL, &err), &err, SK_ERROR_INVALID_ARGUMENT,
                           "normals[1]");
    m->normals[4] = 1.0f;

    memset(t->j, 0, sizeof t->j);
    memset(t->w, 0, sizeof t->w);
    for (int v = 0; v < 9; v++)
        j[4 * v] = 0, j[4 * v + 1] = 1, w[4 * v] = 0.5f, w[4 * v + 1] = 0.5f;
    w[4 * 3 + 1] = 0.4f; /* sums to 0.9 */
    sk_test_expect_failure(add_grid_mesh(g, m, j, w, &err), &err, SK_ERROR_INVALID_ARGUMENT,
                           "weights[3] sum to 0.9");
    w[4 * 3 + 1] = 0.5f;
    w[4 * 2 + 2] = -0.1f;
    sk_test_expect_failure(add_grid_mesh(g, m, j, w, &err), &err, SK_ERROR_INVALID_ARGUMENT,
                           "weights[2][2]");
    w[4 * 2 + 2] = 0.0f;
    j[4 * 6 + 1] = 0; /* joint 0 twice with weight */
    sk_test_expect_failure(add_grid_mesh(g, m, j, w, &err), &err, SK_ERROR_INVALID_ARGUMENT,
                           "joints[6]");
    j[4 * 6 + 1] = 1;
    sk_gltf_mesh_desc half = {.mesh = m, .material = SK_GLTF_NONE, .joints = j};
    sk_test_expect_failure(sk_gltf_add_mesh(g, &half, &index, &err), &err,
                           SK_ERROR_INVALID_ARGUMENT, "together");
    float tp[27] = {0};
    sk_gltf_mesh_desc morph = {
        .mesh = m, .material = SK_GLTF_NONE, .target_count = 1, .target_positions = tp};
    tp[5] = INFINITY;
    sk_test_expect_failure(sk_gltf_add_mesh(g, &morph, &index, &err), &err,
                           SK_ERROR_INVALID_ARGUMENT, "target_positions[5]");
    tp[5] = 0;
    const char *dup[2] = {"a", "a"};
    float tp2[54] = {0};
    sk_gltf_mesh_desc morph2 = {.mesh = m,
                                .material = SK_GLTF_NONE,
                                .target_count = 2,
                                .target_positions = tp2,
                                .target_names = dup};
    sk_test_expect_failure(sk_gltf_add_mesh(g, &morph2, &index, &err), &err,
                           SK_ERROR_INVALID_ARGUMENT, "target_names[1]");
}

/* materials and textures, and the meshes that use them */
static void refuse_bad_materials(refusals *t)
{
    sk_gltf *g = t->g;
    sk_mesh *m = &t->m, *bare = &t->bare;
    sk_image *tex = &t->tex;
    sk_error err = {0};
    int index = 0;

    sk_gltf_material_desc md = {.roughness = 1.5f};
    sk_test_expect_failure(sk_gltf_add_material(g, &md, &index, &err), &err,
                           SK_ERROR_INVALID_ARGUMENT, "roughness");
    md.roughness = 0.5f;
    md.base_color[1] = NAN;
    sk_test_expect_failure(sk_gltf_add_material(g, &md, &index, &err), &err,
                           SK_ERROR_INVALID_ARGUMENT, "base_color[1]");
    md.base_color[1] = 0.0f;
    SK_ASSERT_OK(sk_image_create(tex, 2, 2, 3, &e_));
    tex->data[4] = 2.0f;
    md.base_color_texture = tex;
    sk_test_expect_failure(sk_gltf_add_material(g, &md, &index, &err), &err,
                           SK_ERROR_INVALID_ARGUMENT, "base_color_texture: pixel (1, 0)");
    tex->data[4] = 0.5f;
    int textured;
    SK_ASSERT_OK(sk_gltf_add_material(g, &md, &textured, &e_));
    make_grid(bare);
    free(bare->uvs);
    bare->uvs = NULL;
    sk_gltf_mesh_desc needs_uv = {.mesh = bare, .material = textured};
    sk_test_expect_failure(sk_gltf_add_mesh(g, &needs_uv, &index, &err), &err,
                           SK_ERROR_INVALID_ARGUMENT, "needs uvs");
    sk_gltf_material_desc nd = {.normal_texture = tex};
    int normal_mat;
    SK_ASSERT_OK(sk_gltf_add_material(g, &nd, &normal_mat, &e_));
    sk_gltf_mesh_desc needs_tangents = {.mesh = m, .material = normal_mat};
    sk_test_expect_failure(sk_gltf_add_mesh(g, &needs_tangents, &index, &err), &err,
                           SK_ERROR_INVALID_ARGUMENT, "tangent");
    sk_gltf_material_desc glow = {.emissive_texture = tex};
    sk_test_expect_failure(sk_gltf_add_material(g, &glow, &index, &err), &err,
                           SK_ERROR_INVALID_ARGUMENT,
                           "emissive_texture without an emissive factor");
    glow.emissive[2] = 1.5f;
    sk_test_expect_failure(sk_gltf_add_material(g, &glow, &index, &err), &err,
                           SK_ERROR_INVALID_ARGUMENT, "emissive[2]");
    glow.emissive[2] = 0.5f;
    int glow_mat;
    SK_ASSERT_OK(sk_gltf_add_material(g, &glow, &glow_mat, &e_));
    sk_gltf_mesh_desc glow_needs_uv = {.mesh = bare, .material = glow_mat};
    sk_test_expect_failure(sk_gltf_add_mesh(g, &glow_needs_uv, &index, &err), &err,
                           SK_ERROR_INVALID_ARGUMENT, "needs uvs");
    sk_gltf_mesh_desc no_material = {.mesh = m, .material = 7};
    sk_test_expect_failure(sk_gltf_add_mesh(g, &no_material, &index, &err), &err,
                           SK_ERROR_INVALID_ARGUMENT, "material = 7");
}

/* nodes and skins: parents, transforms, skinned meshes and their joints */
static void refuse_bad_nodes(refusals *t)
{
    sk_gltf *g = t->g;
    sk_mesh *m = &t->m;
    const uint16_t *j = t->j;
    const float *w = t->w;
    sk_error err = {0};
    int index = 0;

    sk_gltf_node_desc n = sk_gltf_node_desc_default();
    n.parent = 0;
    sk_test_expect_failure(sk_gltf_add_node(g, &n, &index, &err), &err, SK_ERROR_INVALID_ARGUMENT,
                           "nodes[0].parent");
    n = sk_gltf_node_desc_default();
    n.rotation[0] = 0.5;
    sk_test_expect_failure(sk_gltf_add_node(g, &n, &index, &err), &err, SK_ERROR_INVALID_ARGUMENT,
                           "rotation");
    n.rotation[0] = 0;
    n.translation[2] = NAN;
    sk_test_expect_failure(sk_gltf_add_node(g, &n, &index, &err), &err, SK_ERROR_INVALID_ARGUMENT,
                           "translation[2]");
    n.translation[2] = 0;
    int root, plain_mesh, skinned_mesh, node_plain;
    SK_ASSERT_OK(sk_gltf_add_node(g, &n, &root, &e_));
    sk_gltf_mesh_desc pd = {.mesh = m, .material = SK_GLTF_NONE};
    SK_ASSERT_OK(sk_gltf_add_mesh(g, &pd, &plain_mesh, &e_));
    sk_gltf_mesh_desc sd = {.mesh = m, .material = SK_GLTF_NONE, .joints = j, .weights = w};
    SK_ASSERT_OK(sk_gltf_add_mesh(g, &sd, &skinned_mesh, &e_));
    n.mesh = skinned_mesh;
    sk_test_expect_failure(sk_gltf_add_node(g, &n, &index, &err), &err, SK_ERROR_INVALID_ARGUMENT,
                           "needs a skin");
    int joint_list[2] = {root, root};
    sk_test_expect_failure(sk_gltf_add_skin(g, NULL, joint_list, 2, NULL, &index, &err), &err,
                           SK_ERROR_INVALID_ARGUMENT, "joints[1] = 0 repeats");
    int one_joint, skin1;
    SK_ASSERT_OK(sk_gltf_add_skin(g, NULL, &root, 1, NULL, &one_joint, &e_));
    (void)one_joint;
    n.skin = 0;
    sk_test_expect_failure(sk_gltf_add_node(g, &n, &index, &err), &err, SK_ERROR_INVALID_ARGUMENT,
                           "uses joint 1");
    int second;
    n = sk_gltf_node_desc_default();
    n.parent = root;
    SK_ASSERT_OK(sk_gltf_add_node(g, &n, &second, &e_));
    joint_list[1] = second;
    SK_ASSERT_OK(sk_gltf_add_skin(g, NULL, joint_list, 2, NULL, &skin1, &e_));
    n = sk_gltf_node_desc_default();
    n.mesh = skinned_mesh;
    n.skin = skin1;
    n.translation[0] = 1;
    sk_test_expect_failure(sk_gltf_add_node(g, &n, &index, &err), &err, SK_ERROR_INVALID_ARGUMENT,
                           "root without");
    n.translation[0] = 0;
    int skinned_node;
    SK_ASSERT_OK(sk_gltf_add_node(g, &n, &skinned_node, &e_));
    n = sk_gltf_node_desc_default();
    n.mesh = plain_mesh;
    n.skin = skin1;
    sk_test_expect_failure(sk_gltf_add_node(g, &n, &index, &err), &err, SK_ERROR_INVALID_ARGUMENT,
                           "needs a mesh with joints");
    n.skin = SK_GLTF_NONE;
    SK_ASSERT_OK(sk_gltf_add_node(g, &n, &node_plain, &e_));
    float ibm_bad[16] = {1, 0, 0, 0.5f, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    sk_test_expect_failure(sk_gltf_add_skin(g, NULL, &root, 1, ibm_bad, &index, &err), &err,
                           SK_ERROR_INVALID_ARGUMENT, "inverse_bind[0][3]");
    t->root = root, t->skinned_node = skinned_node, t->node_plain = node_plain;
}

/* animations: no channels, times, keys, values, targets, paths, repeats */
static void refuse_bad_animations(refusals *t)
{
    sk_gltf *g = t->g;
    int root = t->root, skinned_node = t->skinned_node, node_plain = t->node_plain;
    sk_error err = {0};

    int anim;
    SK_ASSERT_OK(sk_gltf_add_animation(g, NULL, &anim, &e_));
    uint8_t *data = (uint8_t *)1;
    size_t size = 1;
    sk_test_expect_failure(sk_gltf_write_glb_memory(g, NULL, &data, &size, &err), &err,
                           SK_ERROR_INVALID_ARGUMENT,
                           "animations[0] (\"animation0\") has no channels");
    assert_null(data);
    float times[3] = {0.0f, 0.5f, 0.5f}, values[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    sk_test_expect_failure(
        sk_gltf_add_channel(g, anim, root, SK_GLTF_PATH_ROTATION, 0, times, 3, values, &err), &err,
        SK_ERROR_INVALID_ARGUMENT, "times[2] = 0.5 is not after times[1]");
    times[2] = 1.0f;
    times[0] = -1.0f;
    sk_test_expect_failure(
        sk_gltf_add_channel(g, anim, root, SK_GLTF_PATH_ROTATION, 0, times, 3, values, &err), &err,
        SK_ERROR_INVALID_ARGUMENT, "times[0]");
    times[0] = 0.0f;
    values[4] = 2.0f;
    sk_test_expect_failure(
        sk_gltf_add_channel(g, anim, root, SK_GLTF_PATH_ROTATION, 0, times, 3, values, &err), &err,
        SK_ERROR_INVALID_ARGUMENT, "key 1");
    values[4] = 0.0f;
    values[0] = NAN;
    sk_test_expect_failure(
        sk_gltf_add_channel(g, anim, root, SK_GLTF_PATH_TRANSLATION, 0, times, 3, values, &err),
        &err, SK_ERROR_INVALID_ARGUMENT, "values[0]");
    values[0] = 0.0f;
    sk_test_expect_failure(
        sk_gltf_add_channel(g, anim, node_plain, SK_GLTF_PATH_WEIGHTS, 0, times, 3, values, &err),
        &err, SK_ERROR_INVALID_ARGUMENT, "morph targets");
    sk_test_expect_failure(sk_gltf_add_channel(g, anim, skinned_node, SK_GLTF_PATH_TRANSLATION, 0,
                                               times, 3, values, &err),
                           &err, SK_ERROR_INVALID_ARGUMENT, "skinned mesh");
    sk_test_expect_failure(
        sk_gltf_add_channel(g, anim, 99, SK_GLTF_PATH_SCALE, 0, times, 3, values, &err), &err,
        SK_ERROR_INVALID_ARGUMENT, "node = 99");
    sk_test_expect_failure(
        sk_gltf_add_channel(g, anim, root, (sk_gltf_path)7, 0, times, 3, values, &err), &err,
        SK_ERROR_INVALID_ARGUMENT, "path = 7");
    SK_ASSERT_OK(
        sk_gltf_add_channel(g, anim, root, SK_GLTF_PATH_ROTATION, 0, times, 3, values, &e_));
    sk_test_expect_failure(
        sk_gltf_add_channel(g, anim, root, SK_GLTF_PATH_ROTATION, 0, times, 3, values, &err), &err,
        SK_ERROR_INVALID_ARGUMENT, "already animated");
    sk_test_expect_failure(
        sk_gltf_add_channel(g, 5, root, SK_GLTF_PATH_SCALE, 0, times, 3, values, &err), &err,
        SK_ERROR_INVALID_ARGUMENT, "animation = 5");
}

/* nothing a refused call tried to add was kept: the document still validates; and a file
   below a plain file is refused */
static void check_nothing_kept(refusals *t)
{
    sk_gltf *g = t->g;
    sk_error err = {0};
    uint8_t *data;
    size_t size;
    SK_ASSERT_OK(sk_gltf_write_glb_memory(g, NULL, &data, &size, &e_));
    sk_gltf_doc *doc;
    SK_ASSERT_OK(sk_gltf_read_glb_memory(&doc, data, size, NULL, &e_));
    assert_int_equal(sk_gltf_doc_count(doc).meshes, 2);
    assert_int_equal(sk_gltf_doc_count(doc).images,
                     3); /* the textured, the normal and the emissive material's */
    sk_gltf_doc_free(doc);
    free(data);
    const char *not_a_folder = sk_test_path("gltf/plain-file");
    sk_test_write_file(not_a_folder, "x", 1);
    char below[1100];
    snprintf(below, sizeof below, "%s/x.glb", not_a_folder);
    sk_test_expect_failure(sk_gltf_write_glb(g, below, NULL, &err), &err, SK_ERROR_IO, "x.glb");
}

static void test_writer_refuses_bad_input(void **state)
{
    (void)state;
    refusals t;
    SK_ASSERT_OK(sk_gltf_create(&t.g, &e_));
    make_grid(&t.m);
    refuse_bad_meshes(&t);
    refuse_bad_materials(&t);
    refuse_bad_nodes(&t);
    refuse_bad_animations(&t);
    check_nothing_kept(&t);
    sk_image_free(&t.tex);
    sk_mesh_free(&t.bare);
    sk_mesh_free(&t.m);
    sk_gltf_destroy(t.g);
}

/* ------------------------------------------------------------------ reader errors */

static uint8_t *good_glb(sk_test_gltf_kind kind, size_t *size)
{
    sk_test_gltf_sample s;
    SK_ASSERT_OK(sk_test_gltf_sample_make(kind, &s, &e_));
    uint8_t *data;
    SK_ASSERT_OK(sk_gltf_write_glb_memory(s.gltf, NULL, &data, size, &e_));
    sk_gltf_destroy(s.gltf);
    return data;
}

static void edit_count(cJSON *root) { set_number(item(root, "accessors", 3), "count", 1e6); }
static void edit_sparse(cJSON *root)
{
    cJSON_AddObjectToObject(item(root, "accessors", 2), "sparse");
}
static void edit_view(cJSON *root) { set_number(item(root, "bufferViews", 1), "byteOffset", 1e7); }
static void edit_component(cJSON *root)
{
    set_number(item(root, "accessors", 0), "componentType", 5124);
}
static void edit_alignment(cJSON *root) { set_number(item(root, "accessors", 0), "byteOffset", 2); }
static void edit_cubic(cJSON *root)
{
    cJSON *sampler =
        cJSON_GetArrayItem(cJSON_GetObjectItem(item(root, "animations", 0), "samplers"), 0);
    cJSON_DeleteItemFromObject(sampler, "interpolation");
    cJSON_AddStringToObject(sampler, "interpolation", "CUBICSPLINE");
}
static void edit_required(cJSON *root)
{
    cJSON *a = cJSON_AddArrayToObject(root, "extensionsRequired");
    cJSON_AddItemToArray(a, cJSON_CreateString("KHR_draco_mesh_compression"));
}
static void edit_loop(cJSON *root)
{
    cJSON *tip = item(root, "nodes", 2);
    cJSON *children = cJSON_AddArrayToObject(tip, "children");
    cJSON_AddItemToArray(children, cJSON_CreateNumber(1)); /* 1 is already 0's child */
}
static void edit_cycle(cJSON *root)
{
    cJSON *children = cJSON_AddArrayToObject(item(root, "nodes", 2), "children");
    cJSON_AddItemToArray(children, cJSON_CreateNumber(0)); /* 0 -> 1 -> 2 -> 0 */
}
static void edit_animated_matrix(cJSON *root)
{
    cJSON *node = item(root, "nodes", 0); /* its translation is animated */
    cJSON_DeleteItemFromObject(node, "translation");
    double m[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0.5, 0, 1};
    cJSON_AddItemToObject(node, "matrix", cJSON_CreateDoubleArray(m, 16));
}
static void edit_times(cJSON *root)
{
    cJSON *sampler =
        cJSON_GetArrayItem(cJSON_GetObjectItem(item(root, "animations", 0), "samplers"), 2);
    cJSON *output = cJSON_GetObjectItem(sampler, "output");
    cJSON_SetNumberValue(cJSON_GetObjectItem(sampler, "input"), output->valuedouble);
}
static void edit_version(cJSON *root)
{
    cJSON *asset = cJSON_GetObjectItem(root, "asset");
    cJSON_DeleteItemFromObject(asset, "version");
    cJSON_AddStringToObject(asset, "version", "1.0");
}
static void edit_attribute(cJSON *root)
{
    cJSON *attrs = cJSON_GetObjectItem(
        cJSON_GetArrayItem(cJSON_GetObjectItem(item(root, "meshes", 0), "primitives"), 0),
        "attributes");
    cJSON_AddNumberToObject(attrs, "COLOUR", 0);
}
static void edit_uri(cJSON *root)
{
    cJSON_AddStringToObject(item(root, "buffers", 0), "uri", "data.bin");
}
static void edit_skin_joint(cJSON *root)
{
    cJSON *joints = cJSON_GetObjectItem(item(root, "skins", 0), "joints");
    cJSON_DeleteItemFromArray(joints, 2); /* the mesh uses joint 2 */
}

/* Sets the first index of the mesh to vertex_count (out of range) in the BIN chunk. */
static void break_index(uint8_t *glb, size_t size)
{
    uint32_t json_len;
    memcpy(&json_len, glb + 12, 4);
    cJSON *root = cJSON_ParseWithLength((const char *)glb + 20, json_len);
    cJSON *prim = cJSON_GetArrayItem(cJSON_GetObjectItem(item(root, "meshes", 0), "primitives"), 0);
    int acc = cJSON_GetObjectItem(prim, "indices")->valueint;
    int pos = cJSON_GetObjectItem(cJSON_GetObjectItem(prim, "attributes"), "POSITION")->valueint;
    int vertices = cJSON_GetObjectItem(item(root, "accessors", pos), "count")->valueint;
    cJSON *view = item(root, "bufferViews",
                       cJSON_GetObjectItem(item(root, "accessors", acc), "bufferView")->valueint);
    size_t at = 20 + json_len + 8 + (size_t)cJSON_GetObjectItem(view, "byteOffset")->valueint;
    assert_true(at + 2 <= size);
    glb[at] = (uint8_t)vertices, glb[at + 1] = (uint8_t)(vertices >> 8); /* unsigned shorts */
    cJSON_Delete(root);
}

/* Makes the second key time of the first sampler equal to the first in the BIN chunk. */
static void break_times(uint8_t *glb, size_t size)
{
    uint32_t json_len;
    memcpy(&json_len, glb + 12, 4);
    cJSON *root = cJSON_ParseWithLength((const char *)glb + 20, json_len);
    cJSON *sampler =
        cJSON_GetArrayItem(cJSON_GetObjectItem(item(root, "animations", 0), "samplers"), 0);
    int acc = cJSON_GetObjectItem(sampler, "input")->valueint;
    cJSON *view = item(root, "bufferViews",
                       cJSON_GetObjectItem(item(root, "accessors", acc), "bufferView")->valueint);
    size_t at = 20 + json_len + 8 + (size_t)cJSON_GetObjectItem(view, "byteOffset")->valueint;
    assert_true(at + 8 <= size);
    memcpy(glb + at + 4, glb + at, 4);
    cJSON_Delete(root);
}

static void test_reader_refuses_damage(void **state)
{
    (void)state;
    size_t size;
    uint8_t *glb = good_glb(SK_TEST_GLTF_SKINNED, &size);
    sk_gltf_doc *doc;
    SK_ASSERT_OK(sk_gltf_read_glb_memory(&doc, glb, size, NULL, &e_));
    sk_gltf_doc_free(doc);
    uint8_t *copy = malloc(size + 8);
    assert_non_null(copy);

    /* container */
    expect_bad_glb(glb, 11, SK_ERROR_PARSE, "GLB header");
    expect_bad_glb(glb, size - 4, SK_ERROR_PARSE, "does not match");
    memcpy(copy, glb, size);
    copy[0] = 'X';
    expect_bad_glb(copy, size, SK_ERROR_PARSE, "magic");
    memcpy(copy, glb, size);
    copy[4] = 1;
    expect_bad_glb(copy, size, SK_ERROR_UNSUPPORTED, "version 1");
    memcpy(copy, glb, size);
    copy[12] += 1; /* JSON chunk length not a multiple of 4 */
    expect_bad_glb(copy, size, SK_ERROR_PARSE, "chunk 0: length");
    memcpy(copy, glb, size);
    copy[16] = 'B'; /* first chunk not JSON */
    expect_bad_glb(copy, size, SK_ERROR_PARSE, "first chunk must be JSON");
    memcpy(copy, glb, size);
    memcpy(copy + size, "\0\0\0\0", 4); /* a truncated chunk header after the BIN chunk */
    uint32_t longer = (uint32_t)size + 4;
    memcpy(copy + 8, &longer, 4);
    expect_bad_glb(copy, size + 4, SK_ERROR_PARSE, "truncated chunk header");
    memcpy(copy, glb, size);
    copy[21] = '#'; /* inside the JSON */
    expect_bad_glb(copy, size, SK_ERROR_PARSE, "invalid JSON");
    /* an unknown chunk after BIN is skipped */
    memcpy(copy, glb, size);
    memcpy(copy + size, "\0\0\0\0XYZW", 8);
    longer = (uint32_t)size + 8;
    memcpy(copy + 8, &longer, 4);
    SK_ASSERT_OK(sk_gltf_read_glb_memory(&doc, copy, size + 8, NULL, &e_));
    sk_gltf_doc_free(doc);

    /* JSON structure, each failure naming its JSON path */
    expect_bad_edit(glb, size, edit_count, SK_ERROR_PARSE, "accessors[3].count");
    expect_bad_edit(glb, size, edit_sparse, SK_ERROR_UNSUPPORTED, "accessors[2].sparse");
    expect_bad_edit(glb, size, edit_view, SK_ERROR_PARSE, "bufferViews[1]");
    expect_bad_edit(glb, size, edit_component, SK_ERROR_PARSE, "accessors[0].componentType = 5124");
    expect_bad_edit(glb, size, edit_alignment, SK_ERROR_PARSE, "accessors[0].byteOffset = 2");
    expect_bad_edit(glb, size, edit_cubic, SK_ERROR_UNSUPPORTED,
                    "animations[0].samplers[0].interpolation");
    expect_bad_edit(glb, size, edit_required, SK_ERROR_UNSUPPORTED, "KHR_draco_mesh_compression");
    expect_bad_edit(glb, size, edit_loop, SK_ERROR_PARSE,
                    "nodes[2].children[0] = 1: already a child of nodes[0]");
    expect_bad_edit(glb, size, edit_cycle, SK_ERROR_PARSE, "loop of children");
    expect_bad_edit(glb, size, edit_animated_matrix, SK_ERROR_PARSE, "matrix");
    expect_bad_edit(glb, size, edit_times, SK_ERROR_PARSE, "samplers[2].input");
    expect_bad_edit(glb, size, edit_version, SK_ERROR_UNSUPPORTED, "asset.version");
    expect_bad_edit(glb, size, edit_attribute, SK_ERROR_PARSE, "attributes.COLOUR");
    expect_bad_edit(glb, size, edit_uri, SK_ERROR_UNSUPPORTED, "buffers[0].uri");
    expect_bad_edit(glb, size, edit_skin_joint, SK_ERROR_PARSE, "uses joint 2");

    /* an index out of range in the binary chunk */
    memcpy(copy, glb, size);
    break_index(copy, size);
    expect_bad_glb(copy, size, SK_ERROR_PARSE, ".indices: accessors[");

    memcpy(copy, glb, size);
    break_times(copy, size);
    expect_bad_glb(copy, size, SK_ERROR_PARSE, "samplers[0].input: key time 1 = 0 is not after 0");

    /* the cap */
    sk_gltf_read_desc small = {.max_bytes = size - 1};
    sk_error err = {0};
    doc = (sk_gltf_doc *)1;
    sk_test_expect_failure(sk_gltf_read_glb_memory(&doc, glb, size, &small, &err), &err,
                           SK_ERROR_LIMIT, "cap");
    assert_null(doc);
    small.max_bytes = size + 1000; /* the file fits, its JSON tree does not */
    sk_test_expect_failure(sk_gltf_read_glb_memory(&doc, glb, size, &small, &err), &err,
                           SK_ERROR_LIMIT, "JSON chunk");

    /* files, and queries out of range */
    const char *path = sk_test_path("gltf/good.glb");
    sk_test_write_file(path, glb, size);
    SK_ASSERT_OK(sk_gltf_read_glb(&doc, path, NULL, &e_));
    sk_gltf_doc_node node;
    sk_test_expect_failure(sk_gltf_doc_get_node(doc, 99, &node, &err), &err,
                           SK_ERROR_INVALID_ARGUMENT, "node = 99");
    float *v;
    size_t count;
    int components;
    sk_test_expect_failure(sk_gltf_doc_read_accessor(doc, -1, &v, &count, &components, &err), &err,
                           SK_ERROR_INVALID_ARGUMENT, "accessor = -1");
    assert_int_equal(sk_gltf_doc_mesh_accessor(doc, 5, "POSITION"), -1);
    assert_int_equal(sk_gltf_doc_mesh_accessor(doc, 0, "TEXCOORD_3"), -1);
    assert_int_equal(sk_gltf_doc_channel_count(doc, 3), 0);
    sk_gltf_doc_free(doc);
    path = sk_test_path("gltf/missing.glb");
    sk_test_expect_failure(sk_gltf_read_glb(&doc, path, NULL, &err), &err, SK_ERROR_NOT_FOUND,
                           "missing.glb");
    free(copy);
    free(glb);
}

/* A node given as a matrix reads back as its translation, rotation and scale. */
static void edit_matrix(cJSON *root)
{
    cJSON *node = item(root, "nodes", 1);
    cJSON_DeleteItemFromObject(node, "translation");
    cJSON_DeleteItemFromObject(node, "rotation");
    cJSON_DeleteItemFromObject(node, "scale");
    /* rotation of 90 degrees about z, scale (2, 3, 4), translation (1, 2, 3), column-major */
    double m[16] = {0, 2, 0, 0, -3, 0, 0, 0, 0, 0, 4, 0, 1, 2, 3, 1};
    cJSON_AddItemToObject(node, "matrix", cJSON_CreateDoubleArray(m, 16));
}

static void test_reader_matrix_nodes(void **state)
{
    (void)state;
    size_t size, n;
    uint8_t *glb = good_glb(SK_TEST_GLTF_STATIC, &size), *p;
    repack(glb, size, edit_matrix, &p, &n);
    sk_gltf_doc *doc;
    SK_ASSERT_OK(sk_gltf_read_glb_memory(&doc, p, n, NULL, &e_));
    sk_gltf_doc_node node;
    SK_ASSERT_OK(sk_gltf_doc_get_node(doc, 1, &node, &e_));
    double want_r[4] = {0, 0, sqrt(0.5), sqrt(0.5)}, want_s[3] = {2, 3, 4}, want_t[3] = {1, 2, 3};
    for (int i = 0; i < 4; i++) assert_true(fabs(node.rotation[i] - want_r[i]) < 1e-12);
    for (int i = 0; i < 3; i++) {
        assert_true(fabs(node.scale[i] - want_s[i]) < 1e-12);
        assert_true(node.translation[i] == want_t[i]);
    }
    sk_gltf_doc_free(doc);
    free(p);
    free(glb);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_static_roundtrip),
        cmocka_unit_test(test_png_memory_matches_file),
        cmocka_unit_test(test_skin_roundtrip),
        cmocka_unit_test(test_morph_roundtrip),
        cmocka_unit_test(test_samples_read_back),
        cmocka_unit_test(test_writer_refuses_bad_input),
        cmocka_unit_test(test_reader_refuses_damage),
        cmocka_unit_test(test_reader_matrix_nodes),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
