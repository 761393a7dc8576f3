/* Renderer benchmark: the Fig. 20 wrist scene (skin bump-mapped around a capsule) at
 * 1280 x 720 with 16 samples per pixel, the target being at most 10 s wall on 2
 * cores. Prints wall time, camera rays per second, the split between Embree queries and
 * shading (from a second, instrumented run), and, as a baseline measured in the same run,
 * the scene with its materials made plain (no skin evaluation).
 * Usage: bench_render [SCENE.json [WIDTHxHEIGHT [SPP]]] */
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "shitsukan/render.h"

static double load_average(void)
{
    double load = -1;
    FILE *fp = fopen("/proc/loadavg", "r");
    if (fp) {
        if (fscanf(fp, "%lf", &load) != 1) load = -1;
        fclose(fp);
    }
    return load;
}

static int render_once(const sk_render_scene_desc *desc, bool timing, sk_render_stats *stats,
                       double *setup)
{
    sk_error err = {0};
    sk_render_scene *scene = NULL;
    double t0 = sk_time_seconds();
    if (sk_render_scene_create(desc, &scene, &err) != SK_OK) {
        fprintf(stderr, "bench_render: %s\n", err.message);
        return 1;
    }
    *setup = sk_time_seconds() - t0;
    sk_render_options options = {.timing = timing};
    sk_image image = {0};
    sk_result r = sk_render_scene_render(scene, &options, &image, stats, &err);
    if (r != SK_OK) fprintf(stderr, "bench_render: %s\n", err.message);
    sk_image_free(&image);
    sk_render_scene_destroy(scene);
    return r == SK_OK ? 0 : 1;
}

int main(int argc, char **argv)
{
    const char *path = argc > 1 ? argv[1] : SK_BENCH_PRESET_DIR "/scenes/wrist.json";
    int width = 1280, height = 720, spp = 16;
    if (argc > 2 && sscanf(argv[2], "%dx%d", &width, &height) != 2) return 2;
    if (argc > 3) spp = atoi(argv[3]);
    sk_render_scene_desc *desc = calloc(1, sizeof *desc);
    if (!desc) return 1;
    sk_error err = {0};
    if (sk_render_scene_desc_load(path, desc, &err) != SK_OK) {
        fprintf(stderr, "bench_render: %s\n", err.message);
        free(desc);
        return 1;
    }
    desc->image.width = width;
    desc->image.height = height;
    desc->image.samples = spp;
    double load = load_average();
    sk_render_stats full, timed, plain;
    double setup, setup_timed, setup_plain;
    if (render_once(desc, false, &full, &setup) || render_once(desc, true, &timed, &setup_timed)) {
        free(desc);
        return 1;
    }
    for (int i = 0; i < desc->material_count; i++)
        desc->materials[i].type = SK_RENDER_MATERIAL_STANDARD;
    if (render_once(desc, false, &plain, &setup_plain)) {
        free(desc);
        return 1;
    }
    double busy = timed.intersect_seconds + timed.shade_seconds;
    printf("render %s: %dx%d, %d spp, %d threads (load average %.2f before the run)\n", path, width,
           height, spp, omp_get_max_threads(), load);
    printf("  scene setup      %8.3f s (meshes, materials, Embree BVH)\n", setup);
    printf("  render           %8.3f s wall  (target <= 10 s on 2 cores)\n", full.seconds);
    printf("  camera rays      %8.2f M/s  (%lld rays)\n", full.camera_rays_per_second / 1e6,
           full.camera_rays);
    printf("  shadow rays      %8.2f M/s  (%lld rays)\n", full.shadow_rays / full.seconds / 1e6,
           full.shadow_rays);
    printf("  time split       %8.0f %% intersection (Embree), %.0f %% shading, of %.2f thread-s "
           "(instrumented run: %.3f s wall)\n",
           busy > 0 ? 100 * timed.intersect_seconds / busy : 0,
           busy > 0 ? 100 * timed.shade_seconds / busy : 0, busy, timed.seconds);
    printf("  baseline         %8.3f s wall with every material standard (no skin/wood "
           "evaluation): x%.2f\n",
           plain.seconds, full.seconds / plain.seconds);
    free(desc);
    return 0;
}
