/* Renderer scenes: JSON scene files bound and validated with key paths in every error (bad
 * material, missing or malformed mesh file, NaN, zero-size image), relative mesh paths,
 * and the `shitsukan render` command (outputs, exit codes, no partial files, thread count). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "test_support.h"
#include "shitsukan/io.h"
#include "shitsukan/render.h"

static sk_test_run g_run;

static void write_text(const char *path, const char *text)
{
    sk_test_write_file(path, text, strlen(text));
}

/* A unit cube OBJ (no normals: shaded flat) and a scene using it from the same folder. */
static const char *k_cube_obj =
    "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n"
    "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 4 8 7 3\nf 1 5 8 4\nf 2 3 7 6\n";

static const char *k_scene =
    "{\n"
    "  \"description\": \"test scene\",\n"
    "  \"image\": {\"width\": 24, \"height\": 16, \"samples\": 2},\n"
    "  \"camera\": {\"position\": [0, 0, 6], \"target\": [0, 0, 0], \"fov_deg\": 40},\n"
    "  \"materials\": [{\"name\": \"floor\", \"albedo\": [0.5, 0.5, 0.5], \"specular\": 0.2}],\n"
    "  \"objects\": [\n"
    "    {\"name\": \"cube\", \"file\": \"cube.obj\", \"material\": \"floor\",\n"
    "     \"transform\": {\"translate\": [0, 0, -1], \"rotate_deg\": [0, 0, 0], \"scale\": [0.5, "
    "0.5, 0.5]}},\n"
    "    {\"shape\": \"sphere\", \"radius\": 0.5, \"transform\": {\"translate\": [2, 0, 0]}}\n"
    "  ],\n"
    "  \"lights\": [{\"type\": \"directional\", \"direction\": [-1, -1, -1]}]\n"
    "}\n";

static const char *scene_file(const char *name, const char *text)
{
    static char path[1024];
    snprintf(path, sizeof path, "%s", sk_test_path(name));
    write_text(sk_test_path("cube.obj"), k_cube_obj);
    write_text(path, text);
    return path;
}

static void test_scene_file_with_relative_mesh(void **state)
{
    (void)state;
    const char *path = scene_file("scene.json", k_scene);
    sk_render_scene_desc *d = calloc(1, sizeof *d);
    sk_error err = {0};
    if (sk_render_scene_desc_load(path, d, &err) != SK_OK) fail_msg("%s", err.message);
    assert_int_equal(d->object_count, 2);
    assert_int_equal(d->objects[1].shape, SK_RENDER_SHAPE_SPHERE);
    sk_render_scene *s = NULL;
    if (sk_render_scene_create(d, &s, &err) != SK_OK) fail_msg("%s", err.message);
    /* the cube scaled to half size at z = -1: its front face is at z = -0.5 */
    sk_render_hit h;
    sk_render_scene_intersect(s, sk_v3f(0.1f, 0.2f, 6), sk_v3f(0, 0, -1), 0, &h);
    assert_true(h.hit);
    assert_int_equal(h.object, 0);
    assert_true(fabsf(h.distance - 6.5f) < 1e-5f);
    assert_true(fabsf(h.normal.z - 1) < 1e-6f); /* flat: the face normal */
    sk_render_scene_destroy(s);
    free(d);
}

/* A PLY mesh (written by the mesh writer) instanced twice, the second mirrored. */
static void test_ply_mesh_instances(void **state)
{
    (void)state;
    sk_render_object_desc box = {.shape = SK_RENDER_SHAPE_BOX, .size = {2, 2, 2}};
    sk_mesh m;
    sk_error err = {0};
    assert_int_equal(sk_render_make_primitive(&box, &m, &err), SK_OK);
    const char *ply = sk_test_path("ply/box.ply");
    assert_int_equal(sk_mesh_write(&m, ply, &err), SK_OK);
    sk_mesh_free(&m);
    const char *json =
        "{\"objects\": [{\"file\": \"box.ply\", \"transform\": {\"translate\": [-3, 0, 0]}},\n"
        "  {\"file\": \"box.ply\", \"transform\": {\"translate\": [3, 0, 0], \"scale\": [-1, 1, "
        "2]}}]}";
    const char *path = sk_test_path("ply/scene.json");
    write_text(path, json);
    sk_render_scene_desc *d = calloc(1, sizeof *d);
    if (sk_render_scene_desc_load(path, d, &err) != SK_OK) fail_msg("%s", err.message);
    sk_render_scene *s = NULL;
    if (sk_render_scene_create(d, &s, &err) != SK_OK) fail_msg("%s", err.message);
    sk_render_hit h;
    sk_render_scene_intersect(s, sk_v3f(-3, 0.5f, 10), sk_v3f(0, 0, -1), 0, &h);
    assert_int_equal(h.object, 0);
    assert_true(fabsf(h.distance - 9) < 1e-5f);
    assert_true(fabsf(h.normal.z - 1) < 1e-5f);
    /* mirrored in x and stretched in z: the front face at z = 2 still faces +z */
    sk_render_scene_intersect(s, sk_v3f(3.2f, 0.5f, 10), sk_v3f(0, 0, -1), 0, &h);
    assert_int_equal(h.object, 1);
    assert_true(fabsf(h.distance - 8) < 1e-5f);
    assert_true(fabsf(h.normal.z - 1) < 1e-5f);
    assert_true(fabsf(h.geometric_normal.z - 1) < 1e-5f);
    sk_render_scene_destroy(s);
    free(d);
}

/* Binds a scene text with one replacement of `from` by `to` and returns the message. */
static const char *bind_error(const char *from, const char *to)
{
    static char text[4096], message[SK_ERROR_MESSAGE_SIZE];
    const char *at = strstr(k_scene, from);
    assert_non_null(at);
    snprintf(text, sizeof text, "%.*s%s%s", (int)(at - k_scene), k_scene, to, at + strlen(from));
    const char *path = scene_file("bad.json", text);
    sk_render_scene_desc *d = calloc(1, sizeof *d);
    sk_error err = {0};
    sk_result r = sk_render_scene_desc_load(path, d, &err);
    if (r == SK_OK) {
        sk_render_scene *s = NULL;
        r = sk_render_scene_create(d, &s, &err);
        sk_render_scene_destroy(s);
    }
    free(d);
    assert_int_not_equal(r, SK_OK);
    snprintf(message, sizeof message, "%s", err.message);
    return message;
}

static void assert_starts(const char *text, const char *prefix)
{
    if (strncmp(text, prefix, strlen(prefix)) != 0)
        fail_msg("\"%s\" does not start with \"%s\"", text, prefix);
}

static void test_bad_scenes_name_the_key(void **state)
{
    (void)state;
    assert_string_equal(
        bind_error("\"material\": \"floor\"", "\"material\": \"flor\""),
        "objects[0].material = \"flor\" is not a material of the scene (materials: floor)");
    assert_starts(bind_error("cube.obj", "missing.obj"), "objects[0].file = \"missing.obj\": ");
    write_text(sk_test_path("nan.obj"), "v 0 0 0\nv 1 0 nan\nv 0 1 0\nf 1 2 3\n");
    const char *msg = bind_error("cube.obj", "nan.obj");
    assert_starts(msg, "objects[0].file = \"nan.obj\": ");
    assert_non_null(strstr(msg, "finite"));
    assert_string_equal(bind_error("\"width\": 24", "\"width\": 0"),
                        "image.width = 0 is out of range [1, 16384]");
    assert_string_equal(bind_error("\"radius\": 0.5", "\"radiuss\": 0.5"),
                        "objects[1].radiuss: unknown key (did you mean 'radius'?)");
    assert_string_equal(bind_error("\"shape\": \"sphere\"", "\"shape\": \"spere\""),
                        "objects[1].shape = \"spere\" is not one of: mesh, plane, box, sphere, "
                        "cylinder, capsule");
    assert_string_equal(
        bind_error("\"scale\": [0.5, 0.5, 0.5]", "\"scale\": [0.5, 0, 0.5]"),
        "objects[0].transform.scale[1] = 0: a scale must not be 0 (all three 0 mean 1)");
    assert_string_equal(
        bind_error("\"target\": [0, 0, 0]", "\"target\": [0, 0, 6]"),
        "camera.position = camera.target = [0, 0, 6]: the camera has no view direction");
    assert_string_equal(bind_error("\"name\": \"cube\", \"file\": \"cube.obj\"",
                                   "\"file\": \"cube.obj\", \"shape\": \"mesh\", \"file\": \"x\""),
                        "objects[0].file: key given twice");
    assert_string_equal(bind_error("\"samples\": 2", "\"samples\": 1e9"),
                        "image.samples = 1e+09 is out of range [1, 4096]");
}

/* The same rules for C callers: NaN and a NaN vertex in the caller's mesh. */
static void test_bad_desc_from_c(void **state)
{
    (void)state;
    sk_render_scene_desc *d = calloc(1, sizeof *d);
    sk_error err = {0};
    d->camera.fov = NAN;
    assert_int_equal(sk_render_scene_desc_validate(d, &err), SK_ERROR_INVALID_ARGUMENT);
    assert_string_equal(err.message,
                        "camera.fov_deg is not a finite number (got nan; accepted: [0.001, 179])");
    d->camera.fov = 0;
    d->light_count = 1;
    d->lights[0].type = SK_RENDER_LIGHT_RECT;
    d->lights[0].size[1] = -2;
    assert_int_equal(sk_render_scene_desc_validate(d, &err), SK_ERROR_INVALID_ARGUMENT);
    assert_string_equal(err.message, "lights[0].size[1] = -2 is out of range [0, 1e+09]");
    d->light_count = 0;
    sk_mesh m;
    assert_int_equal(sk_mesh_create(&m, 3, 1, 0, &err), SK_OK);
    const float p[9] = {0, 0, 0, 1, 0, 0, 0, NAN, 0};
    memcpy(m.positions, p, sizeof p);
    m.indices[0] = 0, m.indices[1] = 1, m.indices[2] = 2;
    d->object_count = 1;
    d->objects[0].mesh = &m;
    sk_render_scene *s = NULL;
    assert_int_not_equal(sk_render_scene_create(d, &s, &err), SK_OK);
    assert_null(s);
    assert_starts(err.message, "objects[0].mesh: ");
    /* the same mesh made finite renders */
    m.positions[7] = 1;
    assert_int_equal(sk_render_scene_create(d, &s, &err), SK_OK);
    sk_render_scene_destroy(s);
    sk_mesh_free(&m);
    free(d);
}

static void assert_one_line_error(const sk_test_run *run, const char *text)
{
    assert_int_equal(run->status, 2);
    assert_int_equal(sk_test_count_lines(run->err), 1);
    if (!strstr(run->err, text)) fail_msg("stderr \"%s\" lacks \"%s\"", run->err, text);
}

static void test_cli_render(void **state)
{
    (void)state;
    const char *scene = scene_file("cli.json", k_scene);
    char png[1024], exr[1024];
    snprintf(png, sizeof png, "%s", sk_test_path("cli/out.png"));
    snprintf(exr, sizeof exr, "%s", sk_test_path("cli/out.exr"));
    remove(png), remove(exr);
    assert_int_equal(sk_test_cli(&g_run, "render --help"), 0);
    assert_non_null(strstr(g_run.out, "usage: shitsukan render"));
    sk_test_cli(&g_run, "render '%s' -o '%s' --exr '%s' --size 20x12 --spp 3 --stats -q", scene,
                png, exr);
    assert_int_equal(g_run.status, 0);
    assert_non_null(strstr(g_run.err, "camera rays/s"));
    sk_image a, b;
    sk_error err = {0};
    assert_int_equal(sk_image_read_png(&a, png, NULL, NULL, NULL, &err), SK_OK);
    assert_int_equal(a.width, 20);
    assert_int_equal(a.height, 12);
    assert_int_equal(a.channels, 4);
    assert_int_equal(sk_image_read_exr(&b, exr, NULL, &err), SK_OK);
    assert_int_equal(b.channels, 4);
    /* the background is transparent; the cube in the middle is opaque */
    assert_true(sk_image_pixel(&b, 0, 0)[3] == 0);
    assert_true(sk_image_pixel(&b, 10, 6)[3] == 1);
    assert_true(sk_image_pixel(&b, 10, 6)[0] > 0);
    sk_image_free(&a);
    sk_image_free(&b);

    /* errors: one line, exit 2, the key path, and no output file */
    remove(png);
    sk_test_cli(&g_run, "render '%s' -o '%s' --set objects[0].material=wood", scene, png);
    assert_one_line_error(&g_run, "objects[0].material = \"wood\" is not a material of the scene");
    sk_test_cli(&g_run, "render '%s' -o '%s' --set image.height=0", scene, png);
    assert_one_line_error(&g_run, "image.height = 0 is out of range [1, 16384]");
    sk_test_cli(&g_run, "render '%s' -o '%s' --size 0x4", scene, png);
    assert_one_line_error(&g_run, "--size '0x4'");
    sk_test_cli(&g_run, "render");
    assert_one_line_error(&g_run, "no scene");
    sk_test_cli(&g_run, "render '%s' -o '%s.jpg'", scene, png);
    assert_one_line_error(&g_run, "unknown image type");
    assert_false(sk_test_file_exists(png));
    assert_int_equal(sk_test_count_files_containing(sk_test_path("cli"), ".tmp"), 0);
}

static void test_cli_same_bytes_any_thread_count(void **state)
{
    (void)state;
    const char *scene = scene_file("threads.json", k_scene);
    char one[1024], two[1024];
    snprintf(one, sizeof one, "%s", sk_test_path("threads1.exr"));
    snprintf(two, sizeof two, "%s", sk_test_path("threads2.exr"));
    assert_int_equal(
        sk_test_cli(&g_run,
                    "render '%s' -o '%s' --threads 1 -q --set environment.ambient_occlusion=true "
                    "--set environment.radiance=[1,1,1]",
                    scene, one),
        0);
    assert_int_equal(
        sk_test_cli(&g_run,
                    "render '%s' -o '%s' --threads 2 -q --set environment.ambient_occlusion=true "
                    "--set environment.radiance=[1,1,1]",
                    scene, two),
        0);
    assert_true(sk_test_same_file(one, two));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_scene_file_with_relative_mesh),
        cmocka_unit_test(test_ply_mesh_instances),
        cmocka_unit_test(test_bad_scenes_name_the_key),
        cmocka_unit_test(test_bad_desc_from_c),
        cmocka_unit_test(test_cli_render),
        cmocka_unit_test(test_cli_same_bytes_any_thread_count),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
