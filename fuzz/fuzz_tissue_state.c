/* Fuzz harness: the tissue simulation's saved-state reader (sk_tissue_sim_load_state) on a
 * small character. A state that loads must leave every point finite and the simulation
 * able to step on. */
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "shitsukan/tissue.h"

static const char k_rod[] =
    "{\"joints\": [{\"name\": \"A\"}, {\"name\": \"B\", \"parent\": \"A\", \"offset_mm\": [0, -60, "
    "0]}],"
    " \"bones\": [{\"name\": \"b\", \"joint\": \"A\", \"end\": \"B\", \"radius_mm\": 8}],"
    " \"skin\": {\"spacing_mm\": 6, \"dilations\": 2, \"dilation_radius_mm\": 12}}";

static void still(void *user, double t, sk_quatd *local, sk_vec3d *root)
{
    (void)user;
    local[1] = sk_qd_axis_angle(sk_v3d(1, 0, 0), -0.5 * sin(t));
    *root = sk_v3d(0, 0, 0);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    /* the harness's own fixture, built once per process */
    static sk_tissue_model *model;
    if (!model) {
        sk_preset *p = NULL;
        sk_tissue_character_desc *d = malloc(sizeof *d);
        if (!d || sk_preset_parse(&p, k_rod, sizeof k_rod - 1, "rod", NULL) != SK_OK ||
            sk_tissue_character_bind(p, d, NULL) != SK_OK ||
            sk_tissue_model_build(d, NULL, &model, NULL) != SK_OK)
            abort();
        sk_preset_free(p);
        free(d);
    }
    sk_tissue_motion motion = {still, NULL, 1.0};
    sk_tissue_sim *sim = NULL;
    if (sk_tissue_sim_create(model, &motion, &sim, NULL) != SK_OK) abort();
    if (sk_tissue_sim_load_state(sim, data, size, NULL) == SK_OK) {
        double t = sk_tissue_sim_time(sim);
        if (!(t >= 0) || sk_tissue_sim_advance(sim, t + 0.01, NULL) != SK_OK) abort();
        size_t n = sk_tissue_model_get_stats(model).skin_points;
        float *xyz = malloc(3 * n * sizeof *xyz);
        if (!xyz || sk_tissue_sim_skin(sim, sk_tissue_sim_time(sim), xyz, NULL) != SK_OK) abort();
        free(xyz);
    }
    sk_tissue_sim_destroy(sim);
    return 0;
}
