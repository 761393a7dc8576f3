/* The path integrator and its lights: a white furnace (an albedo-1 diffuse sphere in a
 * uniform environment of radiance 1 shows radiance 1: no energy lost or gained), next-event
 * estimation with MIS against BSDF sampling alone, the environment's importance sampling
 * against uniform sampling (map and sky), the same image for any thread count and tile
 * size, and the errors of the new keys. */
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "test_support.h"
#include "render/render_internal.h"
#include "shitsukan/image.h"
#include "shitsukan/render.h"

static sk_render_scene *build(const sk_render_scene_desc *d)
{
    sk_render_scene *s = NULL;
    sk_error err = {0};
    if (sk_render_scene_create(d, &s, &err) != SK_OK) fail_msg("scene: %s", err.message);
    return s;
}

static void render_with(const sk_render_scene_desc *d, int tile, sk_image *img)
{
    sk_render_scene *s = build(d);
    sk_error err = {0};
    sk_render_options opt = {.tile_size = tile};
    if (sk_render_scene_render(s, &opt, img, NULL, &err) != SK_OK)
        fail_msg("render: %s", err.message);
    sk_render_scene_destroy(s);
}

static sk_render_material_desc *add_material(sk_render_scene_desc *d, const char *name, float a)
{
    sk_render_material_desc *m = &d->materials[d->material_count++];
    snprintf(m->name, sizeof m->name, "%s", name);
    m->albedo[0] = m->albedo[1] = m->albedo[2] = a;
    return m;
}

static sk_render_object_desc *add_object(sk_render_scene_desc *d, sk_render_shape shape,
                                         const char *material)
{
    sk_render_object_desc *o = &d->objects[d->object_count++];
    o->shape = shape;
    snprintf(o->material, sizeof o->material, "%s", material);
    return o;
}

/* A sphere of radius 1 at the origin seen along -z by an orthographic camera. */
static sk_render_scene_desc *sphere_scene(int size, int spp, float view)
{
    sk_render_scene_desc *d = calloc(1, sizeof *d);
    assert_non_null(d);
    d->image.width = d->image.height = size;
    d->image.samples = spp;
    d->camera.projection = SK_RENDER_PROJECTION_ORTHOGRAPHIC;
    d->camera.position[2] = 10;
    d->camera.ortho_height = view;
    d->film.integrator = SK_RENDER_INTEGRATOR_PATH;
    add_material(d, "white", 1.0f);
    sk_render_object_desc *o = add_object(d, SK_RENDER_SHAPE_SPHERE, "white");
    o->radius = 1;
    o->segments = 256;
    o->rings = 128;
    return d;
}

/* Albedo 1, radiance 1 everywhere: every covered pixel has radiance 1 within its noise
 * (BSDF sampling and the environment sampler combined by MIS, all bounces). */
static void test_white_furnace(void **state)
{
    (void)state;
    sk_render_scene_desc *d = sphere_scene(24, 64, 1.2f); /* the disc covers the view */
    d->environment.radiance[0] = d->environment.radiance[1] = d->environment.radiance[2] = 1;
    sk_image img;
    render_with(d, 0, &img);
    double sum = 0, sum2 = 0;
    int n = 0;
    for (int y = 0; y < img.height; y++)
        for (int x = 0; x < img.width; x++) {
            const float *p = sk_image_pixel(&img, x, y);
            assert_true(p[3] == 1.0f);
            for (int c = 0; c < 3; c++) {
                sum += p[c];
                sum2 += (double)p[c] * p[c];
                n++;
            }
        }
    double mean = sum / n, sd = sqrt(fmax(0, sum2 / n - mean * mean));
    /* per-pixel noise of a mean of 64 samples, and the image mean to 4 standard errors
       (channels are equal, so n / 3 independent pixels) */
    assert_true(sd < 0.05);
    double se = sd / sqrt(n / 3.0);
    if (!(fabs(mean - 1.0) < 4 * se + 2e-3))
        fail_msg("furnace mean %.5f (pixel sd %.4f, se %.5f)", mean, sd, se);
    /* a grey sphere (albedo 0.5) in the same furnace: 0.5 (convex: one bounce) */
    d->materials[0].albedo[0] = d->materials[0].albedo[1] = d->materials[0].albedo[2] = 0.5f;
    sk_image_free(&img);
    render_with(d, 0, &img);
    sum = 0;
    for (int y = 0; y < img.height; y++)
        for (int x = 0; x < img.width; x++) sum += sk_image_pixel(&img, x, y)[1];
    double grey = sum / (img.width * img.height);
    if (!(fabs(grey - 0.5) < 0.01)) fail_msg("grey furnace mean %.5f", grey);
    sk_image_free(&img);
    free(d);
}

/* A floor, a glossy sphere, a rect, a sphere and a disc light and a dim environment. */
static sk_render_scene_desc *lit_scene(int size, int spp, sk_render_integrator integrator)
{
    sk_render_scene_desc *d = calloc(1, sizeof *d);
    assert_non_null(d);
    d->image.width = d->image.height = size;
    d->image.samples = spp;
    d->camera.position[1] = 3, d->camera.position[2] = 6;
    d->camera.target[1] = 0.5f;
    d->camera.fov = (float)(40 * SK_DEG_TO_RAD);
    d->film.integrator = integrator;
    d->film.max_bounces = 4;
    add_material(d, "floor", 0.6f);
    sk_render_material_desc *m = add_material(d, "ball", 0.7f);
    m->specular = 0.3f, m->shininess = 20;
    sk_render_object_desc *o = add_object(d, SK_RENDER_SHAPE_PLANE, "floor");
    o->size[0] = o->size[2] = 20;
    o = add_object(d, SK_RENDER_SHAPE_SPHERE, "ball");
    o->radius = 1, o->transform.translate[1] = 1;
    sk_render_light_desc *l = &d->lights[d->light_count++];
    l->type = SK_RENDER_LIGHT_RECT;
    l->position[0] = -2, l->position[1] = 4, l->position[2] = 1;
    l->size[0] = l->size[1] = 2.5f;
    l->intensity = 2;
    l = &d->lights[d->light_count++];
    l->type = SK_RENDER_LIGHT_SPHERE;
    l->position[0] = 2.5f, l->position[1] = 2.5f, l->position[2] = 0;
    l->radius = 0.8f, l->intensity = 3, l->color[0] = 1, l->color[1] = 0.7f, l->color[2] = 0.5f;
    l = &d->lights[d->light_count++];
    l->type = SK_RENDER_LIGHT_DISC;
    l->position[0] = 0, l->position[1] = 3, l->position[2] = -3;
    l->radius = 1.2f, l->intensity = 1.5f;
    for (int c = 0; c < 3; c++) d->environment.radiance[c] = 0.15f;
    return d;
}

/* Mean of two renders with different seeds, and the variance of that mean per value. */
static void two_seeds(sk_render_scene_desc *d, float *mean, float *var, int n)
{
    sk_image a, b;
    d->seed = 1;
    render_with(d, 0, &a);
    d->seed = 2;
    render_with(d, 0, &b);
    for (int i = 0; i < n; i++) {
        float x = a.data[i], y = b.data[i];
        mean[i] = 0.5f * (x + y);
        var[i] = 0.25f * (x - y) * (x - y);
    }
    sk_image_free(&a);
    sk_image_free(&b);
}

/* NEE + MIS and BSDF sampling alone estimate the same image: the squared differences
 * summed over the image match the two renders' variances summed (ratio about 1; a bias
 * in either, e.g. a wrong light pdf or MIS weight, makes it grow with the pixel count). */
static void test_mis_matches_bsdf_sampling(void **state)
{
    (void)state;
    const int size = 16, n = size * size * 4;
    float *m1 = malloc(4 * sizeof(float) * (size_t)n), *v1 = m1 + n, *m2 = v1 + n, *v2 = m2 + n;
    assert_non_null(m1);
    sk_render_scene_desc *d = lit_scene(size, 64, SK_RENDER_INTEGRATOR_PATH);
    two_seeds(d, m1, v1, n);
    free(d);
    d = lit_scene(size, 1024, SK_RENDER_INTEGRATOR_PATH_BSDF);
    two_seeds(d, m2, v2, n);
    free(d);
    double diff2 = 0, var = 0, path_var = 0, mean = 0;
    for (int i = 0; i < n; i++) {
        if (i % 4 == 3) continue;
        diff2 += (double)(m1[i] - m2[i]) * (m1[i] - m2[i]);
        var += v1[i] + v2[i];
        path_var += v1[i];
        mean += m1[i];
    }
    double ratio = diff2 / var;
    print_message("MIS vs BSDF sampling: mean %.4f, sum of squared differences / variances %.3f "
                  "(MIS variance share %.2f)\n",
                  mean / (n * 0.75), ratio, path_var / var);
    assert_true(mean > 0);
    if (!(ratio < 2.0)) fail_msg("MIS and BSDF sampling differ beyond their noise: %.3f", ratio);
    free(m1);
}

/* A small lat-long EXR: a dim gradient and a bright spot (a sun) off the axes. */
static const char *write_map(int w, int h)
{
    sk_image img;
    sk_error err = {0};
    assert_int_equal(sk_image_create(&img, w, h, 3, &err), SK_OK);
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            float *p = sk_image_pixel(&img, x, y);
            float g = 0.1f + 0.5f * (float)(h - y) / (float)h;
            bool spot = abs(x - w / 3) <= 1 && abs(y - h / 4) <= 1;
            p[0] = g + (spot ? 400.0f : 0.0f), p[1] = 0.8f * g, p[2] = spot ? 200.0f : g;
        }
    const char *path = sk_test_path("map.exr");
    assert_int_equal(sk_image_write_exr(&img, path, NULL, &err), SK_OK);
    sk_image_free(&img);
    return path;
}

/* E(n) = integral of L cos+ over the sphere by importance sampling and by uniform
 * sampling: the same within 4 standard errors; and the density integrates to 1. */
static void check_environment_sampling(const sk__environment *env, const char *what)
{
    const uint32_t N = 1u << 17;
    sk_vec3f normals[3] = {sk_v3f(0, 1, 0), sk_v3f(0.6f, 0.0f, -0.8f), sk_v3f(0, -1, 0)};
    for (int k = 0; k < 3; k++) {
        double s_is = 0, s2_is = 0, s_u = 0, s2_u = 0, pdf_sum = 0, pdf_sum2 = 0;
        uint32_t mismatches = 0;
        for (uint32_t i = 0; i < N; i++) {
            sk_vec2f u =
                sk_v2f((float)sk_rand_uniform(1, i, k, 0), (float)sk_rand_uniform(2, i, k, 0));
            float pdf;
            sk_vec3f d = sk__environment_sample(env, u, &pdf);
            double v = 0;
            if (pdf > 0) {
                sk_vec3f L = sk__environment_eval(env, d);
                v = (L.x + L.y + L.z) * fmax(0, sk_v3f_dot(d, normals[k])) / pdf;
                /* the density looked up for the sampled direction (other than on a
                   texel's edge, where rounding may pick its neighbour) */
                float back = sk__environment_pdf(env, d);
                if (!(fabsf(back - pdf) <= 1e-3f * pdf)) mismatches++;
            }
            s_is += v, s2_is += v * v;
            float z = 1 - 2 * u.x, r = sqrtf(fmaxf(0, 1 - z * z)), phi = 2 * SK_PI_F * u.y;
            sk_vec3f du = sk_v3f(r * cosf(phi), z, r * sinf(phi));
            sk_vec3f L = sk__environment_eval(env, du);
            double w = (L.x + L.y + L.z) * fmax(0, sk_v3f_dot(du, normals[k])) * 4 * SK_PI;
            s_u += w, s2_u += w * w;
            double q = sk__environment_pdf(env, du) * 4 * SK_PI;
            pdf_sum += q, pdf_sum2 += q * q;
        }
        double m_is = s_is / N, m_u = s_u / N;
        double se = sqrt((s2_is / N - m_is * m_is) / N + (s2_u / N - m_u * m_u) / N);
        print_message("%s n%d: importance %.5f, uniform %.5f (se %.5f), integral of pdf %.4f\n",
                      what, k, m_is, m_u, se, pdf_sum / N);
        if (mismatches > N / 1000)
            fail_msg("%s: %u sampled pdfs differ from lookups", what, mismatches);
        if (!(fabs(m_is - m_u) < 4 * se))
            fail_msg("%s: importance sampling %.5f, uniform %.5f (se %.5f)", what, m_is, m_u, se);
        double pdf_mean = pdf_sum / N;
        double pdf_se = sqrt((pdf_sum2 / N - pdf_mean * pdf_mean) / N);
        if (!(fabs(pdf_mean - 1) < 4 * pdf_se))
            fail_msg("%s: pdf integrates to %g (se %g)", what, pdf_mean, pdf_se);
    }
}

static void test_environment_importance_sampling(void **state)
{
    (void)state;
    sk_render_scene_desc *d = sphere_scene(4, 1, 3);
    d->environment.type = SK_RENDER_ENVIRONMENT_MAP;
    snprintf(d->environment.map, sizeof d->environment.map, "%s", write_map(64, 32));
    d->environment.rotate = 0.7f;
    sk_render_scene *s = build(d);
    check_environment_sampling(&s->env, "map");
    sk_render_scene_destroy(s);
    d->environment.type = SK_RENDER_ENVIRONMENT_SKY;
    d->environment.sun_size = (float)(4 * SK_DEG_TO_RAD);
    s = build(d);
    check_environment_sampling(&s->env, "sky");
    /* the sky's sun gives its irradiance: mean over directions of L cos towards the sun */
    sk_render_scene_destroy(s);
    free(d);
}

/* Any thread count and tile size give the same bytes. */
static void test_threads_and_tiles(void **state)
{
    (void)state;
    sk_render_scene_desc *d = lit_scene(40, 4, SK_RENDER_INTEGRATOR_PATH);
    d->image.width = 37;
    sk_image a, b, c;
    int threads = omp_get_max_threads();
    omp_set_num_threads(1);
    render_with(d, 16, &a);
    omp_set_num_threads(2);
    render_with(d, 16, &b);
    render_with(d, 7, &c);
    omp_set_num_threads(threads);
    size_t bytes = (size_t)a.width * a.height * 4 * sizeof(float);
    assert_memory_equal(a.data, b.data, bytes);
    assert_memory_equal(a.data, c.data, bytes);
    sk_image_free(&a);
    sk_image_free(&b);
    sk_image_free(&c);
    free(d);
}

/* Bad values and files: one line naming the key, exit code 2. */
static void test_key_errors(void **state)
{
    (void)state;
    const char *scene = sk_test_path("env.json");
    FILE *fp = fopen(scene, "w");
    assert_non_null(fp);
    fprintf(fp, "{\"objects\": [{\"shape\": \"sphere\"}], \"film\": {\"integrator\": \"path\"},"
                " \"environment\": {\"type\": \"map\", \"map\": \"missing.exr\"}}\n");
    fclose(fp);
    const char *out = sk_test_path("env.png");
    sk_test_run run;
    assert_int_equal(sk_test_cli(&run, "render '%s' --size 8x8 -o '%s'", scene, out), 2);
    assert_non_null(strstr(run.err, "environment.map = \"missing.exr\""));
    assert_int_equal(sk_test_count_lines(run.err), 1);
    const char *bad = sk_test_path("bad.exr");
    sk_test_write_file(bad, "v/1\x01not an exr", 14);
    assert_int_equal(sk_test_cli(&run,
                                 "render '%s' --size 8x8 --set environment.map='\"%s\"' -o '%s'",
                                 scene, bad, out),
                     2);
    assert_non_null(strstr(run.err, "environment.map"));
    assert_int_equal(sk_test_cli(&run, "render '%s' --set film.max_bounces=0 -o '%s'", scene, out),
                     2);
    assert_non_null(strstr(run.err, "film.max_bounces"));
    assert_int_equal(
        sk_test_cli(&run, "render '%s' --set film.integrator='\"pth\"' -o '%s'", scene, out), 2);
    assert_non_null(strstr(run.err, "film.integrator"));
    assert_int_equal(
        sk_test_cli(&run, "render '%s' --set environment.sun_size_deg=nan -o '%s'", scene, out), 2);
    assert_non_null(strstr(run.err, "environment.sun_size_deg"));
    assert_int_equal(sk_test_cli(&run, "render --help-keys"), 0);
    assert_non_null(strstr(run.out, "film.integrator"));
    assert_non_null(strstr(run.out, "environment.map"));
    assert_non_null(strstr(run.out, "lights[].radius"));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_white_furnace),
        cmocka_unit_test(test_mis_matches_bsdf_sampling),
        cmocka_unit_test(test_environment_importance_sampling),
        cmocka_unit_test(test_threads_and_tiles),
        cmocka_unit_test(test_key_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
