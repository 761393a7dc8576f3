/* The scene export (render --export): the glTF read back (nodes with the objects' transforms
 * under a root scaling to metres, meshes as the renderer tessellates them, materials and
 * textures), the wood atlas (uvs inside the image, charts at one density and not
 * overlapping, baked texels equal to the wood at their points), the OBJ (vertices moved
 * and in metres, one object per scene object, MTL and PNG beside it), deterministic bytes
 * for any thread count, and the errors. */
#define _POSIX_C_SOURCE 200809L
#include "test_result.h"
#include "test_support.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "render/export_internal.h"
#include "shitsukan/gltf.h"
#include "shitsukan/io.h"
#include "shitsukan/render.h"

static const char *scene_path(void) { return SK_TEST_DATA_DIR "/export/primitives.json"; }

/* The test scene; with `shrink`, the wood crate at a tenth of its size (so that a small
 * atlas has texels finer than SUPERSAMPLE_MM and bakes one sample per texel). */
static sk_render_scene *load_scene_scaled(sk_render_scene_desc **out_desc, bool shrink)
{
    sk_render_scene_desc *d = calloc(1, sizeof *d);
    assert_non_null(d);
    SK_ASSERT_OK(sk_render_scene_desc_load(scene_path(), d, &e_));
    if (shrink)
        for (int k = 0; k < 3; k++) d->objects[1].transform.scale[k] *= 0.1f;
    sk_render_scene *s = NULL;
    SK_ASSERT_OK(sk_render_scene_create(d, &s, &e_));
    *out_desc = d;
    return s;
}

/* The unchanged test scene, built once for the tests that only read it. */
static sk_render_scene *g_scene;
static sk_render_scene_desc *g_desc;

static int setup(void **state)
{
    (void)state;
    g_scene = load_scene_scaled(&g_desc, false);
    return 0;
}

static int teardown(void **state)
{
    (void)state;
    sk_render_scene_destroy(g_scene);
    free(g_desc);
    return 0;
}

static sk_render_scene *load_scene(sk_render_scene_desc **out_desc)
{
    *out_desc = g_desc;
    return g_scene;
}

static uint8_t *read_bytes(const char *path, size_t *size)
{
    char *data;
    SK_ASSERT_OK(sk_read_file(path, 0, &data, size, &e_));
    return (uint8_t *)data;
}

static float *accessor(const sk_gltf_doc *doc, int index, size_t *count, int components)
{
    float *v;
    int c;
    SK_ASSERT_OK(sk_gltf_doc_read_accessor(doc, index, &v, count, &c, &e_));
    assert_int_equal(c, components);
    return v;
}

/* The glTF of the test scene: what each object became. */
static void test_glb_structure(void **state)
{
    (void)state;
    sk_render_scene_desc *d;
    sk_render_scene *scene = load_scene(&d);
    const char *path = sk_test_path("export/primitives.glb");
    sk_render_export_desc ed = {.texture_size = 128};
    SK_ASSERT_OK(sk_render_scene_export(scene, path, &ed, &e_));
    sk_gltf_doc *doc;
    SK_ASSERT_OK(sk_gltf_read_glb(&doc, path, NULL, &e_));
    sk_gltf_doc_counts c = sk_gltf_doc_count(doc);
    assert_int_equal(c.nodes, 1 + d->object_count);
    /* the cylinder and the floor share the tiles material; the wood crate has its own */
    assert_int_equal(c.materials, 4);
    assert_int_equal(c.meshes, 5);
    /* tiles: albedo and normal map; skin: its normal tile; oak: the baked albedo */
    assert_int_equal(c.images, 4);
    sk_gltf_doc_node root, node;
    SK_ASSERT_OK(sk_gltf_doc_get_node(doc, 0, &root, &e_));
    assert_string_equal(root.name, "scene");
    for (int k = 0; k < 3; k++) assert_true(fabs(root.scale[k] - 0.001) < 1e-15); /* mm -> m */
    for (int i = 0; i < d->object_count; i++) {
        const sk_render_object_desc *o = &d->objects[i];
        SK_ASSERT_OK(sk_gltf_doc_get_node(doc, 1 + i, &node, &e_));
        assert_string_equal(node.name, o->name);
        assert_int_equal(node.parent, 0);
        for (int k = 0; k < 3; k++) assert_true(node.translation[k] == o->transform.translate[k]);
        /* the rotation reproduces Rz Ry Rx of the Euler angles on a test vector */
        sk_quatd q = sk_qd(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
        sk_vec3d v = sk_v3d(0.3, -0.5, 0.8);
        sk_mat3d r = sk_m3d_mul(
            sk_m3d_rot_z(o->transform.rotate[2]),
            sk_m3d_mul(sk_m3d_rot_y(o->transform.rotate[1]), sk_m3d_rot_x(o->transform.rotate[0])));
        sk_vec3d a = sk_qd_rotate(q, v), b = sk_m3d_apply(r, v);
        assert_true(sk_v3d_length(sk_v3d_sub(a, b)) < 1e-6);
        bool unit =
            o->transform.scale[0] == 0 && o->transform.scale[1] == 0 && o->transform.scale[2] == 0;
        for (int k = 0; k < 3; k++)
            assert_true(node.scale[k] == (unit ? 1.0 : (double)o->transform.scale[k]));
        /* a mesh of the tessellation the renderer uses: the primitive's own vertices */
        sk_mesh prim;
        SK_ASSERT_OK(sk_render_make_primitive(o, &prim, &e_));
        size_t count;
        float *p = accessor(doc, sk_gltf_doc_mesh_accessor(doc, node.mesh, "POSITION"), &count, 3);
        if (strcmp(o->name, "crate") == 0) {
            /* the wood crate is unwelded onto its atlas: every corner, same triangles */
            assert_int_equal(count, 3 * prim.triangle_count);
            for (size_t t = 0; t < 3 * prim.triangle_count; t++)
                assert_memory_equal(p + 3 * t, prim.positions + 3 * prim.indices[t],
                                    3 * sizeof(float));
        } else {
            assert_int_equal(count, prim.vertex_count);
            assert_memory_equal(p, prim.positions, 3 * count * sizeof(float));
        }
        free(p);
        sk_mesh_free(&prim);
    }
    /* the tiled meshes carry tangents for the normal map; the plain pill none */
    SK_ASSERT_OK(sk_gltf_doc_get_node(doc, 4, &node, &e_));
    assert_true(sk_gltf_doc_mesh_accessor(doc, node.mesh, "TANGENT") >= 0);
    SK_ASSERT_OK(sk_gltf_doc_get_node(doc, 5, &node, &e_));
    assert_int_equal(sk_gltf_doc_mesh_accessor(doc, node.mesh, "TANGENT"), -1);
    /* the pillar's uvs are st = uv * uv_scale, in glTF's top-left origin */
    SK_ASSERT_OK(sk_gltf_doc_get_node(doc, 4, &node, &e_));
    size_t count;
    float *uv = accessor(doc, sk_gltf_doc_mesh_accessor(doc, node.mesh, "TEXCOORD_0"), &count, 2);
    sk_mesh prim;
    SK_ASSERT_OK(sk_render_make_primitive(&d->objects[3], &prim, &e_));
    for (size_t v = 0; v < count; v++) {
        assert_true(fabsf(uv[2 * v] - 0.05f * prim.uvs[2 * v]) < 1e-6f);
        assert_true(fabsf(uv[2 * v + 1] - (1.0f - 0.05f * prim.uvs[2 * v + 1])) < 1e-5f);
    }
    free(uv);
    sk_mesh_free(&prim);
    sk_gltf_doc_free(doc);
}

/* Signed area of a uv triangle and its 3D area. */
static double uv_area(const float *a, const float *b, const float *c)
{
    return 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
}

static double tri_area(const float *a, const float *b, const float *c, const float scale[3])
{
    double e1[3], e2[3];
    for (int k = 0; k < 3; k++) e1[k] = (b[k] - a[k]) * scale[k], e2[k] = (c[k] - a[k]) * scale[k];
    double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                   e1[0] * e2[1] - e1[1] * e2[0]};
    return 0.5 * sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
}

/* The atlas of the wood crate: uvs in the image, every triangle at the same texels per
 * mm^2 (isometric charts), no two triangles on the same texels, and each texel the wood
 * at its point. */
static void test_wood_atlas(void **state)
{
    (void)state;
    sk_render_scene_desc *d;
    sk_render_scene *scene = load_scene_scaled(&d, true);
    const int crate = 1, size = 256;
    sk_mesh mesh;
    sk_image albedo;
    SK_ASSERT_OK(sk__export_bake_wood(scene, crate, size, &mesh, &albedo, &e_));
    const float *scale = d->objects[crate].transform.scale;
    const sk_wood *wood = scene->materials[scene->instances[crate].material].wood;
    double density = -1, diff_sum = 0;
    int diff_count = 0;
    unsigned char *owner = calloc((size_t)size * size, 1);
    assert_non_null(owner);
    for (size_t t = 0; t < mesh.triangle_count; t++) {
        const float *uv[3], *p[3];
        for (int k = 0; k < 3; k++) {
            uv[k] = mesh.uvs + 2 * (3 * t + (size_t)k);
            p[k] = mesh.positions + 3 * (3 * t + (size_t)k);
            assert_true(uv[k][0] > 0 && uv[k][0] < 1 && uv[k][1] > 0 && uv[k][1] < 1);
        }
        double ratio = fabs(uv_area(uv[0], uv[1], uv[2])) / tri_area(p[0], p[1], p[2], scale);
        if (density < 0) density = ratio;
        assert_true(fabs(ratio / density - 1) < 1e-3);
        /* texel centres strictly inside the triangle belong to it alone */
        for (int y = 0; y < size; y++)
            for (int x = 0; x < size; x++) {
                float q[2] = {(x + 0.5f) / size, 1.0f - (y + 0.5f) / size};
                double a0 = uv_area(q, uv[1], uv[2]), a1 = uv_area(uv[0], q, uv[2]),
                       a2 = uv_area(uv[0], uv[1], q);
                bool inside = (a0 > 1e-9 && a1 > 1e-9 && a2 > 1e-9) ||
                              (a0 < -1e-9 && a1 < -1e-9 && a2 < -1e-9);
                if (!inside) continue;
                assert_int_equal(owner[y * size + x], 0);
                owner[y * size + x] = 1;
                if ((x + y) % 5 != 0) continue;
                /* the baked texel against the wood at its point (object frame, scale kept,
                   mm) filtered over the texel */
                double total = a0 + a1 + a2, w[3] = {a0 / total, a1 / total, a2 / total};
                sk_vec3f point = sk_v3f(0, 0, 0);
                for (int k = 0; k < 3; k++)
                    point = sk_v3f_add(point, sk_v3f((float)(w[k] * p[k][0] * scale[0]),
                                                     (float)(w[k] * p[k][1] * scale[1]),
                                                     (float)(w[k] * p[k][2] * scale[2])));
                const float *n = mesh.normals + 3 * (3 * t);
                sk_vec3f normal =
                    sk_v3f_normalize(sk_v3f(n[0] / scale[0], n[1] / scale[1], n[2] / scale[2]));
                sk_wood_sample ws;
                sk_wood_eval_filtered(wood, point, normal,
                                      (float)(1.0 / sqrt(density * size * size)), &ws);
                const float *px = sk_image_pixel(&albedo, x, y);
                diff_sum += fabs(px[0] - ws.albedo.x) + fabs(px[1] - ws.albedo.y) +
                            fabs(px[2] - ws.albedo.z);
                diff_count += 3;
            }
    }
    assert_true(diff_count > 1000);
    if (diff_sum / diff_count > 1e-3)
        fail_msg("baked texels differ from the wood by %g on average", diff_sum / diff_count);
    /* charts cover a good part of the image (isometric charts of a box pack well) */
    size_t covered = 0;
    for (int i = 0; i < size * size; i++) covered += owner[i];
    assert_true(covered > (size_t)(0.4 * size * size));
    free(owner);
    sk_mesh_free(&mesh);
    sk_image_free(&albedo);
    sk_render_scene_destroy(scene);
    free(d);
}

static void test_obj_export(void **state)
{
    (void)state;
    sk_render_scene_desc *d;
    sk_render_scene *scene = load_scene(&d);
    const char *path = sk_test_path("export/obj/scene.obj");
    sk_render_export_desc ed = {.texture_size = 64};
    SK_ASSERT_OK(sk_render_scene_export(scene, path, &ed, &e_));
    assert_true(sk_test_file_exists(sk_test_path("export/obj/scene.mtl")));
    assert_true(sk_test_file_exists(sk_test_path("export/obj/scene-tiles.png")));
    assert_true(sk_test_file_exists(sk_test_path("export/obj/scene-oak-crate.png")));
    char *mtl;
    SK_ASSERT_OK(sk_read_file(sk_test_path("export/obj/scene.mtl"), 0, &mtl, NULL, &e_));
    assert_non_null(strstr(mtl, "newmtl paint\nKa 0 0 0\nKd 0.56000")); /* (1 - 0.3) albedo */
    assert_non_null(strstr(mtl, "map_Kd scene-tiles.png\n"));
    free(mtl);
    sk_mesh m;
    SK_ASSERT_OK(sk_mesh_read_obj(&m, path, NULL, &e_));
    /* the ball: sphere of radius 35 mm at (0, 35, 40) mm, so in metres every vertex of the
       object lies 0.035 from (0, 0.035, 0.04); find them by that distance */
    size_t on_ball = 0;
    for (size_t v = 0; v < m.vertex_count; v++) {
        double dx = m.positions[3 * v], dy = m.positions[3 * v + 1] - 0.035,
               dz = m.positions[3 * v + 2] - 0.04;
        if (fabs(sqrt(dx * dx + dy * dy + dz * dz) - 0.035) < 1e-6) on_ball++;
    }
    sk_mesh sphere;
    SK_ASSERT_OK(sk_render_make_primitive(&d->objects[2], &sphere, &e_));
    assert_true(on_ball >= sphere.vertex_count);
    size_t triangles = 0;
    for (int i = 0; i < d->object_count; i++) {
        sk_mesh prim;
        SK_ASSERT_OK(sk_render_make_primitive(&d->objects[i], &prim, &e_));
        triangles += prim.triangle_count;
        sk_mesh_free(&prim);
    }
    assert_int_equal(m.triangle_count, triangles);
    char *text;
    SK_ASSERT_OK(sk_read_file(path, 0, &text, NULL, &e_));
    assert_non_null(strstr(text, "\no crate\nusemtl oak-crate\n"));
    assert_non_null(strstr(text, "\no floor\nusemtl tiles\n"));
    free(text);
    sk_mesh_free(&sphere);
    sk_mesh_free(&m);
}

/* The same scene gives the same bytes, on one thread or two, without textures too. */
static void test_deterministic(void **state)
{
    (void)state;
    sk_render_scene_desc *d;
    sk_render_scene *scene = load_scene(&d);
    sk_render_export_desc ed = {.texture_size = 64};
    const char *a = sk_test_path("export/one.glb"), *b = sk_test_path("export/two.glb");
    sk_threads_set(1);
    SK_ASSERT_OK(sk_render_scene_export(scene, a, &ed, &e_));
    sk_threads_set(2);
    SK_ASSERT_OK(sk_render_scene_export(scene, b, &ed, &e_));
    sk_threads_set(0);
    assert_true(sk_test_same_file(a, b));
    ed.no_textures = true;
    const char *plain = sk_test_path("export/plain.glb");
    SK_ASSERT_OK(sk_render_scene_export(scene, plain, &ed, &e_));
    sk_gltf_doc *doc;
    SK_ASSERT_OK(sk_gltf_read_glb(&doc, plain, NULL, &e_));
    assert_int_equal(sk_gltf_doc_count(doc).images, 0);
    /* without a bake the crate keeps the primitive's welded vertices */
    sk_gltf_doc_node node;
    SK_ASSERT_OK(sk_gltf_doc_get_node(doc, 2, &node, &e_));
    size_t count;
    float *p = accessor(doc, sk_gltf_doc_mesh_accessor(doc, node.mesh, "POSITION"), &count, 3);
    assert_int_equal(count, 24);
    free(p);
    sk_gltf_doc_free(doc);
    size_t size;
    uint8_t *bytes = read_bytes(plain, &size);
    /* its base colour is the mean oak colour, not white */
    assert_non_null(strstr((const char *)bytes + 20,
                           "\"name\":\"oak-crate\",\"pbrMetallicRoughness\":{\"baseColorFactor\""));
    free(bytes);
}

static void test_errors_and_cli(void **state)
{
    (void)state;
    sk_render_scene_desc *d;
    sk_render_scene *scene = load_scene(&d);
    sk_error err = {0};
    sk_test_expect_failure(sk_render_scene_export(scene, sk_test_path("export/x.fbx"), NULL, &err),
                           &err, SK_ERROR_INVALID_ARGUMENT, ".glb or .obj");
    sk_render_export_desc bad = {.texture_size = 9};
    sk_test_expect_failure(
        sk_render_scene_export(scene, sk_test_path("export/bad.glb"), &bad, &err), &err,
        SK_ERROR_INVALID_ARGUMENT, "texture_size = 9");
    assert_false(sk_test_file_exists(sk_test_path("export/bad.glb")));
    (void)d;

    sk_test_run run;
    const char *glb = sk_test_path("export/cli.glb");
    assert_int_equal(
        sk_test_cli(&run, "render '%s' --export '%s' --texture-size 64 -q", scene_path(), glb), 0);
    assert_true(sk_test_file_exists(glb));
    /* with --export and no -o nothing is rendered */
    assert_false(sk_test_file_exists("primitives.png"));
    assert_int_equal(sk_test_cli(&run, "render '%s' --export '%s' -q", scene_path(),
                                 sk_test_path("export/x.stl")),
                     2);
    assert_non_null(strstr(run.err, ".glb, .obj"));
    assert_int_equal(
        sk_test_cli(&run, "render '%s' --export '%s' --texture-size 5 -q", scene_path(), glb), 2);
    assert_non_null(strstr(run.err, "texture-size"));
    assert_int_equal(sk_test_cli(&run, "render --help"), 0);
    assert_non_null(strstr(run.out, "--export"));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_glb_structure),  cmocka_unit_test(test_wood_atlas),
        cmocka_unit_test(test_obj_export),     cmocka_unit_test(test_deterministic),
        cmocka_unit_test(test_errors_and_cli),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
