/* The image: OpenMP over 16 x 16 tiles; each pixel averages its stratified camera samples
 * (box filter) in a fixed order, so the bytes do not depend on the thread count. */
#include <math.h>
#include <omp.h>
#include <string.h>
#if defined(__SSE2__)
#include <xmmintrin.h>
#endif

#include "base/loop_progress.h"
#include "render/integrator.h"
#include "render/sequence.h"

#define TILE 16 /* default tile size */

/* Embree recommends flushing denormals to zero in rendering threads (a large speed-up
 * when they occur); every thread of the loop sets the same mode, so results stay equal. */
static unsigned fast_float_begin(void)
{
#if defined(__SSE2__)
    unsigned saved = _mm_getcsr();
    _mm_setcsr(saved | 0x8040u); /* FTZ (bit 15) and DAZ (bit 6) */
    return saved;
#else
    return 0;
#endif
}

static void fast_float_end(unsigned saved)
{
#if defined(__SSE2__)
    _mm_setcsr(saved);
#else
    (void)saved;
#endif
}

/* One pixel of the path integrator: its samples' positions are the first Sobol pair. */
static void path_pixel(const sk_render_scene *scene, sk__worker *w, uint64_t pixel, int x, int y,
                       double sum[4])
{
    const sk_render_scene_desc *d = &scene->desc;
    for (uint32_t s = 0; s < (uint32_t)d->image.samples; s++) {
        sk_vec2f u = sk__sobol_pair(d->seed, pixel, s, 0);
        sk_vec3f L;
        float alpha = sk__path_sample(scene, w, pixel, s, (float)x + u.x, (float)y + u.y, &L);
        sum[0] += L.x, sum[1] += L.y, sum[2] += L.z, sum[3] += alpha;
    }
}

static void render_tile(const sk_render_scene *scene, sk__worker *w, sk_image *image, int tile,
                        int ts)
{
    const sk_render_scene_desc *d = &scene->desc;
    int width = d->image.width, height = d->image.height;
    int tiles_x = (width + ts - 1) / ts;
    int x0 = (tile % tiles_x) * ts, y0 = (tile / tiles_x) * ts;
    int x1 = x0 + ts < width ? x0 + ts : width, y1 = y0 + ts < height ? y0 + ts : height;
    uint32_t spp = (uint32_t)d->image.samples;
    bool path = d->film.integrator != SK_RENDER_INTEGRATOR_PREVIEW;
    for (int y = y0; y < y1; y++) {
        for (int x = x0; x < x1; x++) {
            uint64_t pixel = (uint64_t)y * (uint64_t)width + (uint64_t)x;
            if (path) {
                double sum[4] = {0, 0, 0, 0};
                path_pixel(scene, w, pixel, x, y, sum);
                float *px = sk_image_pixel(image, x, y);
                for (int c = 0; c < 4; c++) px[c] = (float)(sum[c] / spp);
                continue;
            }
            sk__sample_id id;
            sk__sample_id_init(scene, pixel, &id);
            sk__pattern position = sk__pattern_make(d->seed, pixel, SK__SAMPLE_PIXEL, spp);
            double sum[4] = {0, 0, 0, 0};
            for (uint32_t s = 0; s < spp; s++) {
                id.sample = s;
                sk_vec2f u = sk__pattern_point(&position, s);
                sk_vec3f L;
                float alpha = sk__camera_sample(scene, w, &id, (float)x + u.x, (float)y + u.y, &L);
                sum[0] += L.x, sum[1] += L.y, sum[2] += L.z, sum[3] += alpha;
            }
            float *px = sk_image_pixel(image, x, y);
            for (int c = 0; c < 4; c++) px[c] = (float)(sum[c] / spp);
        }
    }
}

sk_result sk_render_scene_render(const sk_render_scene *scene, const sk_render_options *options,
                                 sk_image *image, sk_render_stats *stats, sk_error *err)
{
    const sk_render_scene_desc *d = &scene->desc;
    sk_result r = sk_image_create(image, d->image.width, d->image.height, 4, err);
    if (r != SK_OK) return r;
    sk_render_options opt = {0};
    if (options) opt = *options;
    int ts = opt.tile_size > 0 ? opt.tile_size : TILE;
    int tiles_x = (d->image.width + ts - 1) / ts, tiles_y = (d->image.height + ts - 1) / ts;
    int tiles = tiles_x * tiles_y;
    sk__loop_progress progress;
    sk__loop_progress_init(&progress, &opt.progress, tiles);
    long long shadow_rays = 0;
    double intersect_seconds = 0, busy_seconds = 0;
    double start = sk_time_seconds();
#pragma omp parallel reduction(+ : shadow_rays, intersect_seconds, busy_seconds)
    {
        unsigned saved = fast_float_begin();
        sk__worker w = {opt.timing, 0, 0};
        double t0 = opt.timing ? sk_time_seconds() : 0;
#pragma omp for schedule(dynamic, 1)
        for (int t = 0; t < tiles; t++) {
            render_tile(scene, &w, image, t, ts);
            sk__loop_progress_tick(&progress);
        }
        if (opt.timing) busy_seconds += sk_time_seconds() - t0;
        shadow_rays += w.shadow_rays;
        intersect_seconds += w.intersect_seconds;
        fast_float_end(saved);
    }
    sk_progress_report(&opt.progress, 1.0);
    if (stats) {
        memset(stats, 0, sizeof *stats);
        stats->seconds = sk_time_seconds() - start;
        stats->camera_rays = (long long)d->image.width * d->image.height * d->image.samples;
        stats->shadow_rays = shadow_rays;
        stats->camera_rays_per_second =
            stats->seconds > 0 ? stats->camera_rays / stats->seconds : 0;
        if (opt.timing) {
            stats->intersect_seconds = intersect_seconds;
            stats->shade_seconds = busy_seconds - intersect_seconds;
        }
    }
    return SK_OK;
}
