/* Tests of `shitsukan hand scan` and its files: the whole pipeline on the hand surface at
 * a small scanner resolution (every file and picture written, Table 4.1 beside the
 * thesis's figures, 96 patches of 16 control points, 9 marker residuals), a user's mesh
 * and point cloud as input, and bad input: one-line errors, exit status 2, no partial
 * files. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "shitsukan/hand.h"
#include "shitsukan/image.h"
#include "shitsukan/io.h"
#include "test_support.h"

static sk_test_run g_run;

/* Small scans keep the test fast (under sanitizers too). */
#define SMALL "--lines 160 --points 128 --slices 30 -q"

static int count_substrings(const char *text, const char *needle)
{
    int n = 0;
    size_t len = strlen(needle), at = 0;
    while (text[at]) {
        const char *hit = strstr(text + at, needle);
        if (!hit) break;
        n++;
        at = (size_t)(hit - text) + len;
    }
    return n;
}

/* The start of the value of the first "key" in a JSON text (NULL if absent). */
static const char *json_value(const char *text, const char *key)
{
    char quoted[64];
    snprintf(quoted, sizeof quoted, "\"%s\":", key);
    const char *p = strstr(text, quoted);
    if (!p) return NULL;
    p += strlen(quoted);
    while (*p == ' ' || *p == '\t' || *p == '\n') p++;
    return p;
}

/* The file's text in a buffer the caller frees. */
static void read_text(const char *path, char **text)
{
    size_t size;
    sk_error err;
    assert_int_equal(sk_read_file(path, 0, text, &size, &err), SK_OK);
}

static void test_help_and_bad_input(void **state)
{
    (void)state;
    assert_int_equal(sk_test_cli(&g_run, "hand scan --help"), 0);
    assert_non_null(strstr(g_run.out, "--input"));
    assert_non_null(strstr(g_run.out, "table-4.1"));
    assert_int_equal(sk_test_cli(&g_run, "--help"), 0);
    assert_non_null(strstr(g_run.out, "hand scan"));
    /* -o is required */
    assert_int_equal(sk_test_cli(&g_run, "hand scan"), 2);
    assert_non_null(strstr(g_run.err, "-o DIR"));
    assert_int_equal(sk_test_cli(&g_run, "hand scan --input '%s' -o '%s'",
                                 sk_test_path("scan/none.obj"), sk_test_path("scan/out-missing")),
                     2);
    assert_int_equal(sk_test_count_lines(g_run.err), 1);
    const char *bad = sk_test_path("scan/bad.obj");
    sk_test_write_file(bad, "v 1 2\nf 1 2 3\n", 14);
    const char *dir = sk_test_path("scan/out-bad");
    assert_int_equal(sk_test_cli(&g_run, "hand scan --input '%s' -o '%s'", bad, dir), 2);
    assert_int_equal(sk_test_count_lines(g_run.err), 1);
    assert_false(sk_test_file_exists(sk_test_path("scan/out-bad/table-4.1.json")));
    assert_int_equal(sk_test_cli(&g_run, "hand scan --lines 3 -o '%s'", dir), 2);
    assert_non_null(strstr(g_run.err, "--lines"));
    assert_int_equal(sk_test_cli(&g_run, "hand scan --pin X.MCP.flex=3 -o '%s'", dir), 2);
    assert_non_null(strstr(g_run.err, "unknown DOF"));
    assert_int_equal(sk_test_cli(&g_run, "hand scan --noise nan -o '%s'", dir), 2);
    /* a mesh far from the skeleton: the markers find no surface */
    const char *far = sk_test_path("scan/far.obj");
    const char *tri = "v 500 500 500\nv 501 500 500\nv 500 501 500\nf 1 2 3\n";
    sk_test_write_file(far, tri, strlen(tri));
    assert_int_equal(sk_test_cli(&g_run, "hand scan --input '%s' -o '%s' " SMALL, far, dir), 2);
    assert_non_null(strstr(g_run.err, "marker"));
    assert_int_equal(sk_test_count_lines(g_run.err), 1);
    assert_int_equal(sk_test_count_files_containing(dir, ".tmp"), 0);
}

static void test_the_whole_pipeline_on_the_hand_surface(void **state)
{
    (void)state;
    const char *dir = sk_test_path("scan/hand");
    assert_int_equal(
        sk_test_cli(&g_run, "hand scan -o '%s' --lines 160 --points 128 --slices 30", dir), 0);
    /* the summary: the registration per marker and Table 4.1 beside the thesis */
    assert_non_null(strstr(g_run.out, "registration"));
    assert_int_equal(count_substrings(g_run.out, " residual "), 9);
    assert_non_null(strstr(g_run.out, "Table 4.1"));
    static const char *const files[] = {"table-4.1.json",      "table-4.1.txt", "registration.json",
                                        "patches.json",        "patches.obj",   "polygons.obj",
                                        "polygons-thesis.obj", "scan-palm.png", "scan-back.png",
                                        "registered.png",      "slices.png",    "polygons.png",
                                        "polygons-thesis.png", "patches.png",   "patches-posed.png",
                                        "cloud.ply",           "cast.obj"};
    char path[1024];
    for (size_t k = 0; k < sizeof files / sizeof files[0]; k++) {
        snprintf(path, sizeof path, "%s/%s", dir, files[k]);
        assert_true(sk_test_file_exists(path));
    }
    snprintf(path, sizeof path, "%s/table-4.1.json", dir);
    char *table = NULL;
    read_text(path, &table);
    assert_non_null(strstr(table, "\"thesis\""));
    assert_true(json_value(table, "truth") && *json_value(table, "truth") == '{');
    assert_non_null(strstr(table, "0.03")); /* the thesis's palm mean */
    free(table);
    snprintf(path, sizeof path, "%s/patches.json", dir);
    char *patches = NULL;
    read_text(path, &patches);
    assert_int_equal(count_substrings(patches, "\"index\":"), SK_HAND_PATCH_COUNT);
    assert_true(count_substrings(patches, "\"control_points_mm\"") >= 80);
    free(patches);
    snprintf(path, sizeof path, "%s/registration.json", dir);
    char *reg = NULL;
    read_text(path, &reg);
    assert_int_equal(count_substrings(reg, "\"residual_mm\""), SK_HAND_MARKER_COUNT);
    free(reg);
    /* the scan picture: one pixel per sample, under a title */
    snprintf(path, sizeof path, "%s/scan-palm.png", dir);
    sk_image img;
    sk_error err;
    assert_int_equal(sk_image_read_png(&img, path, NULL, NULL, NULL, &err), SK_OK);
    assert_true(img.width >= 128 && img.height > 160);
    sk_image_free(&img);
    /* the patches as a mesh: 16 x 16 quads each */
    snprintf(path, sizeof path, "%s/patches.obj", dir);
    sk_mesh m;
    assert_int_equal(sk_mesh_read_obj(&m, path, NULL, &err), SK_OK);
    assert_int_equal(m.triangle_count % (2 * 16 * 16), 0);
    assert_true(m.triangle_count >= 80 * 2 * 16 * 16);
    sk_mesh_free(&m);
}

/* The cast and the registered cloud the first run wrote, as a user's mesh and point
 * cloud. */
static void test_a_users_mesh_and_point_cloud(void **state)
{
    (void)state;
    char obj[1024], ply[1024], path[1024];
    snprintf(obj, sizeof obj, "%s", sk_test_path("scan/hand/cast.obj"));
    snprintf(ply, sizeof ply, "%s", sk_test_path("scan/hand/cloud.ply"));
    assert_true(sk_test_file_exists(obj) && sk_test_file_exists(ply));
    const char *dir = sk_test_path("scan/user-mesh");
    assert_int_equal(
        sk_test_cli(&g_run, "hand scan --input '%s' -o '%s' --no-pictures " SMALL, obj, dir), 0);
    snprintf(path, sizeof path, "%s/table-4.1.json", dir);
    assert_true(sk_test_file_exists(path));
    snprintf(path, sizeof path, "%s/slices.png", dir);
    assert_false(sk_test_file_exists(path)); /* --no-pictures */
    snprintf(path, sizeof path, "%s/cast.obj", dir);
    assert_false(sk_test_file_exists(path)); /* only for the built-in surface */
    dir = sk_test_path("scan/user-cloud");
    assert_int_equal(sk_test_cli(&g_run, "hand scan --input '%s' -o '%s' " SMALL, ply, dir), 0);
    snprintf(path, sizeof path, "%s/table-4.1.json", dir);
    char *table = NULL;
    read_text(path, &table);
    assert_true(json_value(table, "truth") &&
                strncmp(json_value(table, "truth"), "null", 4) == 0); /* unknown */
    /* both sides kept from the cloud's "side" attribute */
    const char *fitted = json_value(table, "patches_fitted");
    assert_non_null(fitted);
    assert_true(json_value(fitted, "palm") && atoi(json_value(fitted, "palm")) >= 40);
    assert_true(json_value(fitted, "back") && atoi(json_value(fitted, "back")) >= 40);
    free(table);
    snprintf(path, sizeof path, "%s/registration.json", dir);
    assert_false(sk_test_file_exists(path)); /* nothing to register */
    snprintf(path, sizeof path, "%s/registered.png", dir);
    assert_true(sk_test_file_exists(path));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_help_and_bad_input),
        cmocka_unit_test(test_the_whole_pipeline_on_the_hand_surface),
        cmocka_unit_test(test_a_users_mesh_and_point_cloud),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
