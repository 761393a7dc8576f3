/* Environment light: uniform radiance, a lat-long HDR map read from EXR, or a procedural
 * sky (a gradient from the ground through the horizon to the zenith plus a sun disc)
 * tabulated once into the same lat-long form. Maps and sky are importance sampled by a
 * 2D piecewise-constant distribution of their radiance times sin(theta), turned into a
 * solid-angle density by dividing by 2 pi^2 sin(theta) (Pharr, Jakob & Humphreys, PBRT
 * 3rd ed. sec. 14.2.4 "Infinite Area Lights"). Radiance is constant over each texel, the
 * same function the sampler follows. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "render/render_internal.h"

#define SKY_WIDTH 1024
#define SKY_HEIGHT 512

/* Map frame direction (rotated by -rotate about +y) <-> lat-long (u, v) in [0, 1)^2. */
static sk_vec3f to_map(const sk__environment *e, sk_vec3f d)
{
    return sk_v3f(e->cos_rot * d.x - e->sin_rot * d.z, d.y, e->sin_rot * d.x + e->cos_rot * d.z);
}

static sk_vec3f from_map(const sk__environment *e, sk_vec3f d)
{
    return sk_v3f(e->cos_rot * d.x + e->sin_rot * d.z, d.y, -e->sin_rot * d.x + e->cos_rot * d.z);
}

static sk_vec2f lat_long(sk_vec3f d)
{
    float u = 0.5f + atan2f(d.x, -d.z) / (2.0f * SK_PI_F);
    float v = acosf(fminf(1.0f, fmaxf(-1.0f, d.y))) / SK_PI_F;
    return sk_v2f(u - floorf(u), v);
}

static sk_vec3f lat_long_direction(sk_vec2f uv, float *sin_theta)
{
    float phi = (uv.x - 0.5f) * 2.0f * SK_PI_F, theta = uv.y * SK_PI_F;
    float s = sinf(theta);
    *sin_theta = s;
    return sk_v3f(s * sinf(phi), cosf(theta), -s * cosf(phi));
}

/* The procedural sky in the scene frame, without the sun. */
static sk_vec3f sky_gradient(const sk_render_environment_desc *e, sk_vec3f d)
{
    if (d.y < 0) return sk_v3f_load(e->ground);
    float t = sqrtf(d.y);
    sk_vec3f h = sk_v3f_load(e->horizon), z = sk_v3f_load(e->zenith);
    return sk_v3f_add(h, sk_v3f_scale(sk_v3f_sub(z, h), t));
}

/* Fills env->rgb with the sky: the gradient, and the sun's texels at the radiance that
 * gives exactly sun_irradiance over the solid angle the tabulated disc covers. */
static void tabulate_sky(sk__environment *env, const sk_render_environment_desc *e)
{
    sk_vec3f sun = sk_v3f_normalize(sk_v3f_load(e->sun_direction));
    float cos_sun = cosf(0.5f * e->sun_size);
    double sun_solid_angle = 0;
    float texel = 2.0f * SK_PI_F * SK_PI_F / (float)(SKY_WIDTH * SKY_HEIGHT);
    for (int pass = 0; pass < 2; pass++) {
        float sun_radiance = pass ? (float)(e->sun_irradiance / sun_solid_angle) : 0.0f;
        for (int y = 0; y < SKY_HEIGHT; y++)
            for (int x = 0; x < SKY_WIDTH; x++) {
                float s;
                sk_vec2f uv = sk_v2f(((float)x + 0.5f) / SKY_WIDTH, ((float)y + 0.5f) / SKY_HEIGHT);
                sk_vec3f d = from_map(env, lat_long_direction(uv, &s));
                bool in_sun = sk_v3f_dot(d, sun) >= cos_sun;
                if (!pass) {
                    if (in_sun) sun_solid_angle += texel * s;
                    continue;
                }
                sk_vec3f L = sky_gradient(e, d);
                if (in_sun) L = sk_v3f_add(L, sk_v3f(sun_radiance, sun_radiance, sun_radiance));
                float *px = env->rgb + 3 * ((size_t)y * SKY_WIDTH + x);
                px[0] = L.x, px[1] = L.y, px[2] = L.z;
            }
        if (!(sun_solid_angle > 0)) sun_solid_angle = 1; /* no texel in the disc: no sun */
    }
}

/* Reads the map into env->rgb (RGB; grey replicated from one channel). */
static sk_result load_map(sk__environment *env, const char *base, const char *name, sk_error *err)
{
    char path[2 * SK_RENDER_PATH_SIZE];
    sk__join_path(base, name, path, sizeof path);
    sk_image img = {0};
    sk_result r = sk_image_read_exr(&img, path, NULL, err);
    if (r != SK_OK) return sk_error_prefix(err, r, "environment.map = \"%s\"", name);
    env->width = img.width, env->height = img.height;
    env->rgb = malloc((size_t)img.width * (size_t)img.height * 3 * sizeof *env->rgb);
    if (!env->rgb) {
        sk_image_free(&img);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "environment.map = \"%s\": out of memory",
                       name);
    }
    size_t n = (size_t)img.width * (size_t)img.height;
    for (size_t i = 0; i < n; i++)
        for (int c = 0; c < 3; c++) {
            float v = img.data[i * (size_t)img.channels + (img.channels >= 3 ? c : 0)];
            env->rgb[3 * i + c] = isfinite(v) && v > 0 ? v : 0.0f;
        }
    sk_image_free(&img);
    return SK_OK;
}

/* Scales by strength, and builds the sampling distribution and the mean radiance. */
static sk_result finish_table(sk__environment *env, float strength, sk_error *err)
{
    size_t n = (size_t)env->width * (size_t)env->height;
    float *func = malloc(n * sizeof *func);
    if (!func) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for the environment");
    double mean[3] = {0, 0, 0}, texel = 2.0 * SK_PI * SK_PI / (double)n;
    for (int y = 0; y < env->height; y++) {
        float s = sinf(((float)y + 0.5f) / (float)env->height * SK_PI_F);
        for (int x = 0; x < env->width; x++) {
            size_t i = (size_t)y * env->width + x;
            float *px = env->rgb + 3 * i;
            for (int c = 0; c < 3; c++) {
                px[c] *= strength;
                mean[c] += px[c] * s * texel / (4.0 * SK_PI);
            }
            func[i] = (px[0] + px[1] + px[2]) * s;
        }
    }
    env->uniform = sk_v3f((float)mean[0], (float)mean[1], (float)mean[2]);
    sk_result r = sk__distribution2d_build(&env->distribution, func, env->width, env->height, err);
    free(func);
    return r;
}

sk_result sk__environment_build(sk_render_scene *scene, sk_error *err)
{
    const sk_render_environment_desc *e = &scene->desc.environment;
    sk__environment *env = &scene->env;
    memset(env, 0, sizeof *env);
    env->type = e->type;
    env->uniform = sk_v3f_load(e->radiance);
    env->cos_rot = cosf(e->rotate), env->sin_rot = sinf(e->rotate);
    if (e->type == SK_RENDER_ENVIRONMENT_UNIFORM) return SK_OK;
    if (e->type == SK_RENDER_ENVIRONMENT_MAP) {
        sk_result r = load_map(env, scene->desc.base_dir, e->map, err);
        if (r != SK_OK) return r;
    } else {
        env->width = SKY_WIDTH, env->height = SKY_HEIGHT;
        env->rgb = malloc((size_t)SKY_WIDTH * SKY_HEIGHT * 3 * sizeof *env->rgb);
        if (!env->rgb) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for the sky");
        tabulate_sky(env, e);
    }
    return finish_table(env, e->strength, err);
}

void sk__environment_destroy(sk_render_scene *scene)
{
    free(scene->env.rgb);
    sk__distribution2d_free(&scene->env.distribution);
    memset(&scene->env, 0, sizeof scene->env);
}

bool sk__environment_is_black(const sk__environment *env)
{
    return env->uniform.x == 0 && env->uniform.y == 0 && env->uniform.z == 0;
}

sk_vec3f sk__environment_eval(const sk__environment *env, sk_vec3f d)
{
    if (env->type == SK_RENDER_ENVIRONMENT_UNIFORM) return env->uniform;
    sk_vec2f uv = lat_long(to_map(env, d));
    int x = (int)(uv.x * (float)env->width), y = (int)(uv.y * (float)env->height);
    x = x < 0 ? 0 : x >= env->width ? env->width - 1 : x;
    y = y < 0 ? 0 : y >= env->height ? env->height - 1 : y;
    const float *px = env->rgb + 3 * ((size_t)y * env->width + x);
    return sk_v3f(px[0], px[1], px[2]);
}

float sk__environment_pdf(const sk__environment *env, sk_vec3f d)
{
    if (env->type == SK_RENDER_ENVIRONMENT_UNIFORM) return 1.0f / (4.0f * SK_PI_F);
    sk_vec3f m = to_map(env, d);
    float sin_theta = sqrtf(fmaxf(0.0f, 1.0f - m.y * m.y));
    if (!(sin_theta > 0)) return 0.0f;
    return sk__distribution2d_pdf(&env->distribution, lat_long(m)) /
           (2.0f * SK_PI_F * SK_PI_F * sin_theta);
}

sk_vec3f sk__environment_sample(const sk__environment *env, sk_vec2f u, float *pdf)
{
    if (env->type == SK_RENDER_ENVIRONMENT_UNIFORM) {
        float z = 1.0f - 2.0f * u.x, r = sqrtf(fmaxf(0.0f, 1.0f - z * z));
        float phi = 2.0f * SK_PI_F * u.y;
        *pdf = 1.0f / (4.0f * SK_PI_F);
        return sk_v3f(r * cosf(phi), z, r * sinf(phi));
    }
    float pdf_uv, sin_theta;
    sk_vec2f uv = sk__distribution2d_sample(&env->distribution, u, &pdf_uv);
    sk_vec3f d = from_map(env, lat_long_direction(uv, &sin_theta));
    *pdf = sin_theta > 0 ? pdf_uv / (2.0f * SK_PI_F * SK_PI_F * sin_theta) : 0.0f;
    return d;
}
