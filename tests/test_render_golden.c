/* Golden images: a 64 x 64 render of every shipped scene (presets/scenes/; hand-blend with
 * a synthetic texture in place of the skin photo the demo makes) matches its
 * reference in tests/data/render/<scene>.png, and is the same to the byte on 1 and 2
 * threads.
 *
 * Tolerance, in 8-bit sRGB codes of the tone-mapped image: the mean absolute difference
 * over all channels is at most 0.5 and at most 1 % of the channel values differ by more
 * than 4. That absorbs last-bit differences of other compilers or Embree's code paths on
 * other CPUs (a silhouette sample that flips changes a pixel by up to 1/16 of the edge's
 * contrast) while any change of the model, the light transport or a scene fails.
 *
 * After an intended change, regenerate the references with SK_UPDATE_GOLDEN=1 and look at
 * them before committing. */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "test_support.h"
#include "shitsukan/render.h"

#define SIZE 64

/* hand-blend.json blends a skin photo texture the demo makes first; the test gives it a
 * synthetic texture of its own instead. */
static const char *blend_texture(void)
{
    const char *path = sk_test_path("golden/blend-texture.png");
    sk_image tex;
    sk_error err = {0};
    assert_int_equal(sk_image_create(&tex, 32, 32, 3, &err), SK_OK);
    for (int y = 0; y < 32; y++)
        for (int x = 0; x < 32; x++) {
            float *p = sk_image_pixel(&tex, x, y);
            p[0] = 0.55f + 0.25f * sinf(0.4f * (float)x);
            p[1] = 0.35f + 0.15f * cosf(0.3f * (float)y);
            p[2] = 0.3f;
        }
    assert_int_equal(sk_image_write_png(&tex, path, NULL, &err), SK_OK);
    sk_image_free(&tex);
    return path;
}

static void render_scene(const char *name, int threads, sk_image *out, sk_render_film_desc *film)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/scenes/%s.json", SK_TEST_PRESET_DIR, name);
    sk_render_scene_desc *d = calloc(1, sizeof *d);
    assert_non_null(d);
    sk_error err = {0};
    if (sk_render_scene_desc_load(path, d, &err) != SK_OK) fail_msg("%s: %s", name, err.message);
    d->image.width = d->image.height = SIZE;
    if (strcmp(name, "hand-blend") == 0)
        snprintf(d->materials[0].albedo_texture, sizeof d->materials[0].albedo_texture, "%s",
                 blend_texture());
    sk_render_scene *s = NULL;
    if (sk_render_scene_create(d, &s, &err) != SK_OK) fail_msg("%s: %s", name, err.message);
    *film = d->film;
    sk_threads_set(threads);
    sk_result r = sk_render_scene_render(s, NULL, out, NULL, &err);
    sk_threads_set(0);
    if (r != SK_OK) fail_msg("%s: %s", name, err.message);
    sk_render_scene_destroy(s);
    free(d);
}

static int code(float linear_display, bool srgb)
{
    float v = srgb ? sk_srgb_from_linear(sk_clampf(linear_display, 0, 1)) : linear_display;
    return (int)lrintf(sk_clampf(v, 0, 1) * 255.0f);
}

static void check_scene(const char *name)
{
    sk_image one, two;
    sk_render_film_desc film;
    render_scene(name, 1, &one, &film);
    render_scene(name, 2, &two, &film);
    assert_memory_equal(one.data, two.data, (size_t)SIZE * SIZE * 4 * sizeof(float));

    char ref_path[1024];
    snprintf(ref_path, sizeof ref_path, "%s/render/%s.png", SK_TEST_DATA_DIR, name);
    sk_error err = {0};
    if (getenv("SK_UPDATE_GOLDEN")) {
        assert_int_equal(sk_render_write(&one, &film, ref_path, NULL, &err), SK_OK);
        print_message("wrote %s\n", ref_path);
    }
    sk_image display, ref;
    assert_int_equal(sk_render_tonemap(&one, &film, &display, &err), SK_OK);
    sk_png_read_desc linear = {.encoding = SK_PNG_ENCODING_LINEAR};
    if (sk_image_read_png(&ref, ref_path, &linear, NULL, NULL, &err) != SK_OK)
        fail_msg("%s: %s (SK_UPDATE_GOLDEN=1 writes the references)", name, err.message);
    assert_int_equal(ref.width, SIZE);
    assert_int_equal(ref.height, SIZE);
    assert_int_equal(ref.channels, display.channels);
    size_t n = (size_t)SIZE * SIZE * (size_t)display.channels;
    double sum = 0;
    size_t large = 0;
    for (size_t i = 0; i < n; i++) {
        bool alpha = display.channels == 4 && i % 4 == 3;
        int d = abs(code(display.data[i], !alpha) - code(ref.data[i], false));
        sum += d;
        if (d > 4) large++;
    }
    double mean = sum / (double)n;
    print_message("%s: mean difference %.3f codes, %zu of %zu values differ by more than 4\n", name,
                  mean, large, n);
    if (mean > 0.5 || (double)large > 0.01 * (double)n)
        fail_msg("%s differs from its reference (mean %.3f codes, %zu values > 4 codes)", name,
                 mean, large);
    sk_image_free(&one);
    sk_image_free(&two);
    sk_image_free(&display);
    sk_image_free(&ref);
}

static const char *const k_scenes[] = {"wrist",      "piano",      "wood-turntable",
                                       "fig9-board", "hand-blend", "path-lights"};
#define SCENE_COUNT ((int)(sizeof k_scenes / sizeof k_scenes[0]))

static void test_scene(void **state) { check_scene((const char *)*state); }

/* Every shipped scene has its golden test. */
static void test_every_scene_is_covered(void **state)
{
    (void)state;
    char folder[1024];
    snprintf(folder, sizeof folder, "%s/scenes", SK_TEST_PRESET_DIR);
    DIR *dir = opendir(folder);
    assert_non_null(dir);
    struct dirent *e;
    int count = 0;
    while ((e = readdir(dir)) != NULL) {
        size_t n = strlen(e->d_name);
        if (n < 6 || strcmp(e->d_name + n - 5, ".json") != 0) continue;
        bool found = false;
        for (int i = 0; i < SCENE_COUNT; i++)
            found |= strlen(k_scenes[i]) == n - 5 && strncmp(k_scenes[i], e->d_name, n - 5) == 0;
        if (!found) fail_msg("presets/scenes/%s has no golden test", e->d_name);
        count++;
    }
    closedir(dir);
    assert_int_equal(count, SCENE_COUNT);
}

int main(void)
{
    struct CMUnitTest tests[SCENE_COUNT + 1];
    for (int i = 0; i < SCENE_COUNT; i++)
        tests[i] = (struct CMUnitTest){k_scenes[i], test_scene, NULL, NULL,
                                       (void *)(uintptr_t)k_scenes[i]};
    tests[SCENE_COUNT] = (struct CMUnitTest)cmocka_unit_test(test_every_scene_is_covered);
    return cmocka_run_group_tests(tests, NULL, NULL);
}
