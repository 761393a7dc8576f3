/* Tests of the `shitsukan tissue` commands: help, the files they write (rest skin, layers,
 * point cache, OBJ frames, statistics), one-line errors with exit code 2 and no partial
 * output, and the shipped motions being what the generator makes. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "shitsukan/gltf.h"
#include "shitsukan/io.h"
#include "shitsukan/mesh.h"
#include "shitsukan/pointcache.h"
#include "shitsukan/preset.h"
#include "test_result.h"
#include "test_support.h"

/* A coarse arm, quick to build. */
#define COARSE "--set skin.spacing_mm=10 --set skin.dilation_radius_mm=15"

static void test_help(void **state)
{
    (void)state;
    sk_test_run *run = malloc(sizeof *run);
    assert_int_equal(sk_test_cli(run, "tissue --help"), 0);
    assert_non_null(strstr(run->out, "tissue skin"));
    assert_non_null(strstr(run->out, "tissue run"));
    assert_int_equal(sk_test_cli(run, "tissue"), 2);
    assert_int_equal(sk_test_cli(run, "tissue skin --help"), 0);
    assert_non_null(strstr(run->out, "--character"));
    assert_int_equal(sk_test_cli(run, "tissue run --help"), 0);
    assert_non_null(strstr(run->out, "--frames A:B"));
    assert_int_equal(sk_test_cli(run, "tissue skin --help-keys"), 0);
    assert_non_null(strstr(run->out, "material.fat_stiffness"));
    assert_int_equal(sk_test_cli(run, "tissue nothing"), 2);
    assert_non_null(strstr(run->err, "unknown command 'tissue nothing'"));
    free(run);
}

static void test_skin_and_layers(void **state)
{
    (void)state;
    sk_test_run *run = malloc(sizeof *run);
    const char *obj = sk_test_path("tissue-cli/arm.obj"),
               *layers = sk_test_path("tissue-cli/layers");
    assert_int_equal(sk_test_cli(run,
                                 "tissue skin --character arm " COARSE " -q -o '%s' --layers '%s'",
                                 obj, layers),
                     0);
    sk_mesh mesh;
    SK_ASSERT_OK(sk_mesh_read_obj(&mesh, obj, NULL, &e_));
    assert_true(mesh.triangle_count > 100);
    sk_mesh_free(&mesh);
    static const char *const files[] = {"skin.ply",  "fat.ply",     "muscle.ply", "bone.ply",
                                        "bones.obj", "muscles.obj", "rest.obj",   "layers.png"};
    char path[1024];
    for (size_t i = 0; i < sizeof files / sizeof files[0]; i++) {
        snprintf(path, sizeof path, "%s/%s", layers, files[i]);
        if (!sk_test_file_exists(path)) fail_msg("%s was not written", path);
    }
    snprintf(path, sizeof path, "%s/fat.ply", layers);
    SK_ASSERT_OK(sk_mesh_read_ply(&mesh, path, NULL, &e_));
    assert_true(mesh.vertex_count > 10 && mesh.triangle_count == 0);
    assert_non_null(sk_mesh_find_attribute(&mesh, "owner"));
    sk_mesh_free(&mesh);
    free(run);
}

static void test_run_writes_its_files(void **state)
{
    (void)state;
    sk_test_run *run = malloc(sizeof *run);
    const char *dir = sk_test_path("tissue-cli/curl"),
               *plot = sk_test_path("tissue-cli/curl-plot.png");
    assert_int_equal(sk_test_cli(run,
                                 "tissue run --character arm --motion curl " COARSE
                                 " --fps 10 --frames 5:15 --obj-frames --plot '%s' -o '%s'",
                                 plot, dir),
                     0);
    assert_non_null(strstr(run->out, "11 frames at 10 fps"));
    char path[1024];
    snprintf(path, sizeof path, "%s/skin.pc2", dir);
    sk_pc2 pc;
    SK_ASSERT_OK(sk_pc2_read(path, 0, &pc, &e_));
    assert_int_equal(pc.samples, 11);
    assert_true(pc.start_frame == 5.0f && pc.sample_rate == 1.0f);
    /* the cache and the OBJ frames hold the same positions (the v lines, in file order) */
    snprintf(path, sizeof path, "%s/frames/0009.obj", dir);
    char *obj;
    size_t obj_size;
    SK_ASSERT_OK(sk_read_file(path, 0, &obj, &obj_size, &e_));
    int v = 0;
    for (char *line = strtok(obj, "\n"); line; line = strtok(NULL, "\n")) {
        if (strncmp(line, "v ", 2) != 0) continue;
        float x, y, z;
        assert_int_equal(sscanf(line + 2, "%f %f %f", &x, &y, &z), 3);
        const float *want = pc.xyz + (4 * (size_t)pc.points + (size_t)v) * 3;
        if (x != want[0] || y != want[1] || z != want[2])
            fail_msg("vertex %d: OBJ frame and point cache differ", v);
        v++;
    }
    assert_int_equal(v, pc.points);
    free(obj);
    /* skin.glb: the rest mesh plus morph target k is frame k */
    snprintf(path, sizeof path, "%s/skin.glb", dir);
    sk_gltf_doc *doc = NULL;
    SK_ASSERT_OK(sk_gltf_read_glb(&doc, path, NULL, &e_));
    assert_int_equal(sk_gltf_doc_mesh_target_count(doc, 0), 11);
    float *rest = NULL, *target = NULL;
    size_t count;
    int components;
    SK_ASSERT_OK(sk_gltf_doc_read_accessor(doc, sk_gltf_doc_mesh_accessor(doc, 0, "POSITION"),
                                           &rest, &count, &components, &e_));
    assert_int_equal((int)count, pc.points);
    SK_ASSERT_OK(sk_gltf_doc_read_accessor(doc,
                                           sk_gltf_doc_mesh_target_accessor(doc, 0, 4, "POSITION"),
                                           &target, &count, &components, &e_));
    for (size_t i = 0; i < 3 * count; i++)
        assert_true(fabsf(rest[i] + target[i] - pc.xyz[4 * 3 * (size_t)pc.points + i]) < 1e-3f);
    free(rest);
    free(target);
    sk_gltf_doc_free(doc);
    sk_pc2_free(&pc);
    assert_false(sk_test_file_exists(sk_test_path("tissue-cli/curl/frames/0004.obj")));
    assert_true(sk_test_file_exists(plot));
    snprintf(path, sizeof path, "%s/stats.json", dir);
    sk_preset *stats = NULL;
    SK_ASSERT_OK(sk_preset_load_file(&stats, path, &e_));
    sk_preset_free(stats);
    char *text;
    size_t size;
    SK_ASSERT_OK(sk_read_file(path, 0, &text, &size, &e_));
    assert_non_null(strstr(text, "\"simulated_frames_per_second\""));
    assert_non_null(strstr(text, "\"max_displacement_mm\""));
    assert_non_null(strstr(text, "\"springs\""));
    free(text);
    sk_mesh mesh;
    snprintf(path, sizeof path, "%s/rest.obj", dir);
    SK_ASSERT_OK(sk_mesh_read_obj(&mesh, path, NULL, &e_));
    assert_true(mesh.triangle_count > 100);
    sk_mesh_free(&mesh);
    free(run);
}

static void test_errors_are_one_line_with_status_2(void **state)
{
    (void)state;
    sk_test_run *run = malloc(sizeof *run);
    const char *dir = sk_test_path("tissue-cli/bad/x");
    char folder[1024];
    snprintf(folder, sizeof folder, "%s", dir);
    *strrchr(folder, '/') = '\0';
    assert_int_equal(sk_test_cli(run, "tissue skin --character nobody -o '%s/x.obj'", folder), 2);
    assert_non_null(strstr(run->err, "nobody"));
    assert_int_equal(sk_test_count_lines(run->err), 1);
    assert_int_equal(sk_test_cli(run,
                                 "tissue skin --character arm --set skin.threshold=2 -o '%s/x.obj'",
                                 folder),
                     2);
    assert_non_null(strstr(run->err, "skin.threshold"));
    assert_false(sk_test_file_exists(sk_test_path("tissue-cli/bad/x.obj")));
    /* a broken motion: the line and the reason, and nothing written */
    const char *bvh = sk_test_path("tissue-cli/bad/broken.bvh");
    const char *broken = "HIERARCHY\nROOT RightArm\n{\n\tOFFSET 0 0 0\n\tCHANNELS 3 Zrotation "
                         "Qrotation Xrotation\n}\n";
    sk_test_write_file(bvh, broken, strlen(broken));
    assert_int_equal(sk_test_cli(run,
                                 "tissue run --character arm " COARSE " --motion '%s' -o '%s/run'",
                                 bvh, folder),
                     2);
    assert_non_null(strstr(run->err, "line 5: unknown channel \"Qrotation\""));
    assert_false(sk_test_file_exists(sk_test_path("tissue-cli/bad/run/skin.pc2")));
    assert_int_equal(
        sk_test_cli(run, "tissue run --character arm --motion curl --frames 5:2 -o '%s/run'",
                    folder),
        2);
    assert_non_null(strstr(run->err, "--frames '5:2'"));
    assert_int_equal(
        sk_test_cli(run, "tissue run --character arm --motion dance -o '%s/run'", folder), 2);
    assert_non_null(strstr(run->err, "no such file or shipped motion"));
    const char *junk = sk_test_path("tissue-cli/bad/junk.state");
    sk_test_write_file(junk, "not a state", 11);
    assert_int_equal(sk_test_cli(run,
                                 "tissue run --character arm " COARSE
                                 " --motion curl --resume '%s' -o '%s/run'",
                                 junk, folder),
                     2);
    assert_non_null(strstr(run->err, "not a tissue simulation state"));
    assert_false(sk_test_file_exists(sk_test_path("tissue-cli/bad/run/skin.pc2")));
    assert_int_equal(sk_test_cli(run, "tissue motion twirl -o '%s/m.bvh'", folder), 2);
    free(run);
}

/* The shipped motions are exactly what `tissue motion` makes (so they can be made again). */
static void test_shipped_motions_are_generated(void **state)
{
    (void)state;
    sk_test_run *run = malloc(sizeof *run);
    static const char *const kinds[] = {"curl", "jump", "walk"};
    for (int i = 0; i < 3; i++) {
        char name[64];
        snprintf(name, sizeof name, "%s.bvh", kinds[i]);
        const char *made = sk_test_path(name);
        char shipped[1024];
        snprintf(shipped, sizeof shipped, "%s/tissue/%s.bvh", SK_TEST_PRESET_DIR, kinds[i]);
        assert_int_equal(sk_test_cli(run, "tissue motion %s -o '%s'", kinds[i], made), 0);
        if (!sk_test_same_file(made, shipped))
            fail_msg("presets/tissue/%s.bvh differs from 'shitsukan tissue motion %s'", kinds[i],
                     kinds[i]);
    }
    free(run);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_help),
        cmocka_unit_test(test_skin_and_layers),
        cmocka_unit_test(test_run_writes_its_files),
        cmocka_unit_test(test_errors_are_one_line_with_status_2),
        cmocka_unit_test(test_shipped_motions_are_generated),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
