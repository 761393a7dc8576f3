/* Benchmark of the wood solid texture (Kawai 2000): tree set-up (ring, phase tables and
 * vessel index) time and memory, and a 2048 x 2048 shaded planar cut with vessels,
 * fluctuating rings and wavy grain, on all threads and on one thread, for a
 * diffuse-porous (maple-like) and a ring-porous (oak-like) tree. */
#include <stdio.h>
#include <stdlib.h>

#include "shitsukan/wood.h"

/* A maple-like tree (Richter & Dallwitz vessel figures) with the paper's Fig. 9 wavy
 * grain, ring fluctuation, fractal dg, brightness shift and the figure sheen; with
 * `ring_porous`, oak-like vessels instead (two rows of 0.29 mm earlywood pores and small
 * latewood pores). */
static sk_wood_desc bench_desc(bool ring_porous)
{
    sk_wood_desc d = {0};
    d.seed = 7;
    d.log.radius_mm = 200.0f;
    d.rings.width_mm = 3.0f;
    d.rings.width_variation = 0.3f;
    d.rings.fluctuation = 0.3f;
    d.grain.wavy_amplitude = 0.15f;
    d.grain.wavy_wavelength_mm = 20.0f;
    d.grain.fluctuation = 0.02f;
    d.vessels.diffuse.density_per_mm2 = 38.0f;
    d.vessels.diffuse.radius_mm = 0.033f;
    d.vessels.diffuse.radius_sd_mm = 0.004f;
    d.fibre.brightness_shift = 0.3f;
    d.shading.specular = 0.3f;
    d.shading.exponent = 100.0f;
    d.view.plane = SK_WOOD_PLANE_FLAT;
    d.view.distance_mm = 80.0f;
    d.view.width_mm = 200.0f;
    d.view.tilt = 0.05f;
    d.view.light_incidence = 0.13f;
    if (ring_porous) {
        d.rings.width_mm = 4.0f;
        d.vessels.diffuse.density_per_mm2 = 4.0f;
        d.vessels.diffuse.radius_mm = 0.02f;
        d.vessels.ring.linear_density = 14.0f;
        d.vessels.ring.radius_mm = 0.145f;
        d.vessels.ring.radius_sd_mm = 0.025f;
        d.vessels.ring.rows = 2;
        d.vessels.ring.jitter = 0.7f;
    }
    return d;
}

static double best_cut(const sk_wood *wood, sk_wood_cut_desc *cut, int runs)
{
    double best = 1e30;
    for (int r = 0; r < runs; r++) {
        double t0 = sk_time_seconds();
        sk_error err;
        if (sk_wood_cut(wood, cut, &err) != SK_OK) {
            fprintf(stderr, "bench_wood: %s\n", err.message);
            exit(1);
        }
        double dt = sk_time_seconds() - t0;
        if (dt < best) best = dt;
    }
    return best;
}

static int run(bool ring_porous)
{
    sk_wood_desc desc = bench_desc(ring_porous);
    sk_error err;
    sk_wood *wood = NULL;
    double setup_best = 1e30;
    for (int r = 0; r < 5; r++) {
        sk_wood_destroy(wood);
        if (sk_wood_create(&desc, &wood, &err) != SK_OK) {
            fprintf(stderr, "bench_wood: %s\n", err.message);
            return 1;
        }
        sk_wood_stats st;
        sk_wood_get_stats(wood, &st);
        if (st.setup_seconds < setup_best) setup_best = st.setup_seconds;
    }
    sk_wood_stats st;
    sk_wood_get_stats(wood, &st);
    printf("%s tree: set-up %.1f ms (best of 5; target <= 100 ms), memory %.2f MiB,\n"
           "  %d rings, R(t, theta) table %d x %d, Phi(t, y) table %d x %d\n",
           ring_porous ? "ring-porous (oak-like)" : "diffuse-porous (maple-like, 38 vessels/mm^2)",
           setup_best * 1e3, st.memory_bytes / (1024.0 * 1024.0), st.ring_count,
           st.ring_table_size[0], st.ring_table_size[1], st.phase_table_size[0],
           st.phase_table_size[1]);

    const int size = 2048;
    float *shaded = malloc((size_t)size * size * 3 * sizeof(float));
    if (!shaded) return 1;
    sk_wood_cut_desc cut = {0};
    sk_wood_view_cut(wood, &sk_wood_get_desc(wood)->view, &cut);
    cut.width = cut.height = size;
    cut.shaded = shaded;
    int threads = sk_threads_max();
    double all = best_cut(wood, &cut, 3);
    sk_threads_set(1);
    double one = best_cut(wood, &cut, 2);
    sk_threads_set(threads);
    double samples = (double)size * size;
    printf("  shaded %dx%d flat-sawn cut, 1 sample/pixel (fluctuating rings, wavy grain + dg):\n"
           "  %d threads: %.3f s wall (target <= 0.3 s on 2 cores), %.1f M samples/s\n"
           "  1 thread:   %.3f s wall, %.1f M samples/s, %.0f ns/sample (speed-up %.2f)\n",
           size, size, threads, all, samples / all * 1e-6, one, samples / one * 1e-6,
           one / samples * 1e9, one / all);
    free(shaded);
    sk_wood_destroy(wood);
    return 0;
}

int main(void)
{
    int status = run(false);
    if (status == 0) status = run(true);
    return status;
}
