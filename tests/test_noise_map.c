/* Tests of noise maps and, through the `noise` command, of the command-line plumbing every
 * module shares: presets, --set with key-path errors, --region, --threads, exit codes. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "shitsukan/image.h"
#include "shitsukan/io.h"
#include "shitsukan/noise_map.h"
#include "test_support.h"

static sk_test_run g_run;

static sk_image render(const sk_noise_map_desc *d, const int region[4])
{
    sk_noise_map_desc r = sk_noise_map_desc_resolved(d);
    int w = region ? region[2] : r.width, h = region ? region[3] : r.height;
    sk_image img = {0};
    assert_int_equal(sk_image_create(&img, w, h, 1, NULL), SK_OK);
    assert_int_equal(sk_noise_map_render(d, region, &img, NULL), SK_OK);
    return img;
}

static void test_values_in_range_and_region_exact(void **state)
{
    (void)state;
    sk_noise_map_desc d = {.seed = 5, .width = 96, .height = 64, .cells = 6};
    sk_image full = render(&d, NULL);
    float lo = 1, hi = 0;
    for (int i = 0; i < 96 * 64; i++) {
        lo = fminf(lo, full.data[i]);
        hi = fmaxf(hi, full.data[i]);
    }
    assert_true(lo >= 0.0f && hi <= 1.0f);
    assert_true(hi - lo > 0.3f); /* not flat */
    int region[4] = {17, 9, 40, 30};
    sk_image part = render(&d, region);
    for (int y = 0; y < 30; y++)
        assert_memory_equal(part.data + y * 40, full.data + (y + 9) * 96 + 17, 40 * sizeof(float));
    sk_image_free(&part);
    sk_image_free(&full);
}

static void test_seamless_wraps(void **state)
{
    (void)state;
    sk_noise_map_desc d = {.seed = 2, .width = 128, .height = 80, .cells = 5.0f, .seamless = true};
    sk_image img = render(&d, NULL);
    /* across the wrap, neighbours differ as little as neighbours inside the map do */
    double inside = 0, across = 0;
    for (int y = 0; y < 80; y++) {
        inside += fabsf(img.data[y * 128 + 64] - img.data[y * 128 + 63]);
        across += fabsf(img.data[y * 128 + 0] - img.data[y * 128 + 127]);
    }
    assert_true(across < 2.0 * inside + 1e-3);
    double inside_y = 0, across_y = 0;
    for (int x = 0; x < 128; x++) {
        inside_y += fabsf(img.data[40 * 128 + x] - img.data[39 * 128 + x]);
        across_y += fabsf(img.data[0 * 128 + x] - img.data[79 * 128 + x]);
    }
    assert_true(across_y < 2.0 * inside_y + 1e-3);
    /* without seamless the same edge pair is clearly discontinuous */
    d.seamless = false;
    sk_image plain = render(&d, NULL);
    double plain_across = 0;
    for (int y = 0; y < 80; y++)
        plain_across += fabsf(plain.data[y * 128] - plain.data[y * 128 + 127]);
    assert_true(plain_across > 3.0 * inside);
    sk_image_free(&plain);
    sk_image_free(&img);
}

static void test_validation(void **state)
{
    (void)state;
    sk_error err = {0};
    sk_image img = {0};
    assert_int_equal(sk_image_create(&img, 8, 8, 1, NULL), SK_OK);
    sk_noise_map_desc d = {.width = 8, .cells = NAN};
    assert_int_equal(sk_noise_map_render(&d, NULL, &img, &err), SK_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(err.message, "cells is not a finite number"));
    d.cells = 4;
    d.fbm.octaves = 40;
    assert_int_equal(sk_noise_map_render(&d, NULL, &img, &err), SK_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(err.message, "fbm.octaves = 40 is out of range [1, 16]"));
    d.fbm.octaves = 2;
    int region[4] = {4, 4, 8, 8};
    assert_int_equal(sk_noise_map_render(&d, region, &img, &err), SK_ERROR_INVALID_ARGUMENT);
    d.width = 16;
    assert_int_equal(sk_noise_map_render(&d, region, &img, &err), SK_OK);
    sk_image_free(&img);
}

/* ------------------------------------------------------------ the command */

static sk_image read_png(const char *path)
{
    sk_image img = {0};
    sk_png_read_desc rd = {.encoding = SK_PNG_ENCODING_LINEAR};
    assert_int_equal(sk_image_read_png(&img, path, &rd, NULL, NULL, NULL), SK_OK);
    return img;
}

static void test_cli_writes_maps(void **state)
{
    (void)state;
    const char *a = sk_test_path("noise/a.png");
    assert_int_equal(sk_test_cli(&g_run, "noise --preset clouds --size 64 --quiet -o '%s'", a), 0);
    sk_image img = read_png(a);
    assert_int_equal(img.width, 64);
    assert_int_equal(img.height, 64);
    /* same bytes for 1 and 2 threads */
    const char *t1 = sk_test_path("noise/t1.png"), *t2 = sk_test_path("noise/t2.png");
    assert_int_equal(
        sk_test_cli(&g_run, "noise --preset grain --size 80x48 --threads 1 -o '%s'", t1), 0);
    assert_int_equal(
        sk_test_cli(&g_run, "noise --preset grain --size 80x48 --threads 2 -o '%s'", t2), 0);
    assert_true(sk_test_same_file(t1, t2));
    /* --region gives the full map's pixels */
    const char *r = sk_test_path("noise/r.png");
    assert_int_equal(
        sk_test_cli(&g_run, "noise --preset clouds --size 64 --region 10,20,30,12 -o '%s'", r), 0);
    sk_image part = read_png(r);
    assert_int_equal(part.width, 30);
    for (int y = 0; y < 12; y++)
        for (int x = 0; x < 30; x++)
            assert_true(part.data[y * 30 + x] == img.data[(y + 20) * 64 + x + 10]);
    sk_image_free(&part);
    sk_image_free(&img);
    /* EXR output and --seed */
    const char *e = sk_test_path("noise/e.exr");
    assert_int_equal(sk_test_cli(&g_run, "noise --size 32 --seed 9 -o '%s'", e), 0);
    sk_image_metadata meta = {0};
    sk_image ex = {0};
    assert_int_equal(sk_image_read_exr(&ex, e, &meta, NULL), SK_OK);
    assert_string_equal(sk_image_metadata_get(&meta, "shitsukan:seed"), "9");
    sk_image_free(&ex);
}

static void expect_bad(const char *args, int status, const char *message)
{
    sk_test_cli(&g_run, "%s", args);
    if (g_run.status != status || sk_test_count_lines(g_run.err) != 1 ||
        !strstr(g_run.err, "shitsukan: error: ") || !strstr(g_run.err, message))
        fail_msg("'%s': status %d, stderr '%s', expected %d and '%s'", args, g_run.status,
                 g_run.err, status, message);
}

static void test_cli_bad_input(void **state)
{
    (void)state;
    char args[2048];
    const char *out = sk_test_path("noise/bad.png");
    snprintf(args, sizeof args, "noise --set octaves=40 -o '%s'", out);
    expect_bad(args, 2, "octaves = 40 is out of range [1, 16]");
    snprintf(args, sizeof args, "noise --set cells=nan -o '%s'", out);
    expect_bad(args, 2, "cells is not a finite number");
    snprintf(args, sizeof args, "noise --set cels=3 -o '%s'", out);
    expect_bad(args, 2, "cels: unknown key (did you mean 'cells'?)");
    snprintf(args, sizeof args, "noise --preset no-such-preset -o '%s'", out);
    expect_bad(args, 2, "no such preset");
    snprintf(args, sizeof args, "noise --size 0 -o '%s'", out);
    expect_bad(args, 2, "--size '0' must be N or WxH");
    snprintf(args, sizeof args, "noise --size 64 --region 60,0,10,10 -o '%s'", out);
    expect_bad(args, 2, "--region '60,0,10,10' must lie inside");
    snprintf(args, sizeof args, "noise --seed -3 -o '%s'", out);
    expect_bad(args, 2, "--seed '-3' must be an integer");
    snprintf(args, sizeof args, "noise --threads x -o '%s'", out);
    expect_bad(args, 2, "--threads 'x'");
    expect_bad("noise", 2, "-o/--output is required");
    /* a malformed preset file names its line and column */
    const char *bad = sk_test_path("noise/broken.json");
    sk_test_write_file(bad, "{\n \"cells\": 3,\n \"octaves\": }\n", 29);
    snprintf(args, sizeof args, "noise --preset '%s' -o '%s'", bad, out);
    expect_bad(args, 2, "broken.json:3:");
    assert_false(sk_test_file_exists(out));
    /* a write that fails is a runtime error (1), and leaves no file */
    snprintf(args, sizeof args, "noise --size 8 -o '%s/missing-folder/x.png'", SK_TEST_TMP_DIR);
    expect_bad(args, 1, "cannot create");
    /* --help-keys lists every preset key with its range */
    assert_int_equal(sk_test_cli(&g_run, "noise --help-keys"), 0);
    assert_non_null(strstr(g_run.out, "octaves"));
    assert_non_null(strstr(g_run.out, "[1, 16]"));
}

/* Progress: a bar with percent and ETA on a terminal (a pseudo-terminal from script(1)),
 * nothing with --quiet or when stderr is not a terminal. */
static void test_cli_progress_bar_on_terminal(void **state)
{
    (void)state;
    if (system("command -v script >/dev/null 2>&1") != 0) skip();
    const char *out = sk_test_path("noise/progress.png");
    const char *log = sk_test_path("noise/progress.log");
    char cmd[4096];
    snprintf(cmd, sizeof cmd,
             "script -qfec \"'%s' noise --size 1500 -o '%s'\" /dev/null > '%s' 2>&1", SK_TEST_CLI,
             out, log);
    assert_int_equal(system(cmd), 0);
    char *text;
    assert_int_equal(sk_read_file(log, 0, &text, NULL, NULL), SK_OK);
    assert_non_null(strstr(text, "ETA"));
    assert_non_null(strstr(text, "100%"));
    free(text);
    snprintf(cmd, sizeof cmd,
             "script -qfec \"'%s' noise --quiet --size 1500 -o '%s'\" /dev/null > '%s' 2>&1",
             SK_TEST_CLI, out, log);
    assert_int_equal(system(cmd), 0);
    assert_int_equal(sk_read_file(log, 0, &text, NULL, NULL), SK_OK);
    assert_null(strstr(text, "ETA"));
    free(text);
    /* not a terminal: silent (the test runner captures stderr to a file) */
    assert_int_equal(sk_test_cli(&g_run, "noise --size 1500 -o '%s'", out), 0);
    assert_string_equal(g_run.err, "");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_values_in_range_and_region_exact),
        cmocka_unit_test(test_seamless_wraps),
        cmocka_unit_test(test_validation),
        cmocka_unit_test(test_cli_writes_maps),
        cmocka_unit_test(test_cli_bad_input),
        cmocka_unit_test(test_cli_progress_bar_on_terminal),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
