/* Tests of `shitsukan sheet`: labelled grids and the --repeat tiling check. */
#include <string.h>

#include "shitsukan/image.h"
#include "test_support.h"

static sk_test_run g_run;

static const char *write_test_png(const char *name, int w, int h, float base)
{
    sk_image img = {0};
    assert_int_equal(sk_image_create(&img, w, h, 3, NULL), SK_OK);
    for (int i = 0; i < w * h * 3; i++) img.data[i] = base + 0.5f * (float)((i / 3) % w) / (float)w;
    const char *path = sk_test_path(name);
    assert_int_equal(sk_image_write_png(&img, path, NULL, NULL), SK_OK);
    sk_image_free(&img);
    return path;
}

static void test_grid_and_repeat(void **state)
{
    (void)state;
    const char *a = write_test_png("sheet/a.png", 60, 30, 0.1f);
    const char *b = write_test_png("sheet/b.png", 20, 30, 0.4f);
    const char *out = sk_test_path("sheet/out.png");
    assert_int_equal(sk_test_cli(&g_run,
                                 "sheet --columns 2 --label '(a)' '%s' --label '(b)' '%s' -o '%s'",
                                 a, b, out),
                     0);
    sk_image sheet = {0};
    assert_int_equal(sk_image_read_png(&sheet, out, NULL, NULL, NULL, NULL), SK_OK);
    /* two cells of the widest tile (60, wider than the labels) plus padding 8 */
    assert_int_equal(sheet.width, 8 + 2 * (60 + 8));
    assert_true(sheet.height > 30 + 16);
    sk_image_free(&sheet);

    const char *rep = sk_test_path("sheet/rep.png");
    assert_int_equal(sk_test_cli(&g_run, "sheet --repeat 3x2 '%s' -o '%s'", a, rep), 0);
    sk_image tiled = {0}, src = {0};
    assert_int_equal(sk_image_read_png(&tiled, rep, NULL, NULL, NULL, NULL), SK_OK);
    assert_int_equal(sk_image_read_png(&src, a, NULL, NULL, NULL, NULL), SK_OK);
    assert_int_equal(tiled.width, 180);
    assert_int_equal(tiled.height, 60);
    for (int y = 0; y < 60; y++)
        for (int x = 0; x < 180; x++)
            assert_true(sk_image_pixel(&tiled, x, y)[0] == sk_image_pixel(&src, x % 60, y % 30)[0]);
    sk_image_free(&tiled);
    sk_image_free(&src);
}

static void test_bad_input(void **state)
{
    (void)state;
    const char *a = write_test_png("sheet/c.png", 8, 8, 0.2f);
    const char *out = sk_test_path("sheet/bad.png");
    sk_test_cli(&g_run, "sheet --label x --label y '%s' -o '%s'", a, out);
    assert_int_equal(g_run.status, 2);
    assert_non_null(strstr(g_run.err, "2 labels for 1 images"));
    sk_test_cli(&g_run, "sheet '%s' '%s' --repeat 2x2 -o '%s'", a, a, out);
    assert_int_equal(g_run.status, 2);
    sk_test_cli(&g_run, "sheet '%s/none.png' -o '%s'", SK_TEST_TMP_DIR, out);
    assert_int_equal(g_run.status, 2);
    assert_int_equal(sk_test_count_lines(g_run.err), 1);
    sk_test_cli(&g_run, "sheet '%s'", a);
    assert_int_equal(g_run.status, 2);
    assert_false(sk_test_file_exists(out));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_grid_and_repeat),
        cmocka_unit_test(test_bad_input),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
