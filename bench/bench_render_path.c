/* Path integrator against the preview on the Fig. 20 wrist scene: for a few samples per
 * pixel, the render time and the noise, the RMS difference of two renders with different
 * seeds divided by sqrt(2) and by the mean radiance (linear RGB, all pixels): the
 * measure of issue 22. Then the whole command (`shitsukan render ...`) timed once.
 * Usage: bench_render_path [SCENE.json [WIDTHxHEIGHT [SPP ...]]] */
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "shitsukan/render.h"

static int render_seed(const sk_render_scene_desc *desc, uint64_t seed, sk_image *image,
                       double *seconds)
{
    sk_render_scene_desc *d = malloc(sizeof *d);
    if (!d) return 1;
    memcpy(d, desc, sizeof *d);
    d->seed = seed;
    sk_error err = {0};
    sk_render_scene *scene = NULL;
    int rc = 1;
    if (sk_render_scene_create(d, &scene, &err) == SK_OK) {
        sk_render_stats stats;
        if (sk_render_scene_render(scene, NULL, image, &stats, &err) == SK_OK) {
            *seconds = stats.seconds;
            rc = 0;
        }
    }
    if (rc) fprintf(stderr, "bench_render_path: %s\n", err.message);
    sk_render_scene_destroy(scene);
    free(d);
    return rc;
}

/* RMS(a - b) / sqrt(2) / mean((a + b) / 2) over the RGB values. */
static double noise(const sk_image *a, const sk_image *b)
{
    double d2 = 0, sum = 0;
    size_t n = 0;
    for (size_t i = 0; i < (size_t)a->width * a->height; i++)
        for (int c = 0; c < 3; c++) {
            double x = a->data[4 * i + c], y = b->data[4 * i + c];
            d2 += (x - y) * (x - y);
            sum += 0.5 * (x + y);
            n++;
        }
    return sum > 0 ? sqrt(d2 / n) / sqrt(2.0) / (sum / n) : 0;
}

static int measure(sk_render_scene_desc *desc, sk_render_integrator integrator, int spp)
{
    desc->film.integrator = integrator;
    desc->image.samples = spp;
    sk_image a = {0}, b = {0};
    double ta = 0, tb = 0;
    if (render_seed(desc, 1, &a, &ta) || render_seed(desc, 2, &b, &tb)) return 1;
    printf("  %-8s %5d spp  %8.3f s  noise %6.2f %%\n", sk_render_integrator_names[integrator], spp,
           0.5 * (ta + tb), 100 * noise(&a, &b));
    sk_image_free(&a);
    sk_image_free(&b);
    return 0;
}

int main(int argc, char **argv)
{
    const char *path = argc > 1 ? argv[1] : SK_BENCH_PRESET_DIR "/scenes/wrist.json";
    int width = 320, height = 180;
    if (argc > 2 && sscanf(argv[2], "%dx%d", &width, &height) != 2) return 2;
    int spps[8] = {4, 16, 64}, n_spp = 3;
    if (argc > 3) {
        n_spp = 0;
        for (int i = 3; i < argc && n_spp < 8; i++) spps[n_spp++] = atoi(argv[i]);
    }
    sk_render_scene_desc *desc = calloc(1, sizeof *desc);
    if (!desc) return 1;
    sk_error err = {0};
    if (sk_render_scene_desc_load(path, desc, &err) != SK_OK) {
        fprintf(stderr, "bench_render_path: %s\n", err.message);
        free(desc);
        return 1;
    }
    desc->image.width = width;
    desc->image.height = height;
    printf("render %s: %dx%d, %d threads; noise = RMS(seed 1 - seed 2) / sqrt(2) / mean\n", path,
           width, height, omp_get_max_threads());
    for (int k = 0; k < n_spp; k++)
        if (measure(desc, SK_RENDER_INTEGRATOR_PREVIEW, spps[k]) ||
            measure(desc, SK_RENDER_INTEGRATOR_PATH, spps[k])) {
            free(desc);
            return 1;
        }
    free(desc);
    char cmd[2048];
    snprintf(cmd, sizeof cmd,
             "'%s' render '%s' --size %dx%d --spp 16 --set film.integrator='\"path\"' -o "
             "'%s/bench_render_path.png'",
             SK_BENCH_CLI, path, width, height, SK_BENCH_TMP);
    double t0 = sk_time_seconds();
    int rc = system(cmd);
    printf("  command  `shitsukan render ... --spp 16 --set film.integrator=\"path\"`: %.3f s "
           "(exit %d)\n",
           sk_time_seconds() - t0, rc);
    return rc == 0 ? 0 : 1;
}
