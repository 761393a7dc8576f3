/* Noise maps: tileable fBm textures rendered in parallel from the core gradient noise,
 * and their preset schema. */
#include <math.h>
#include <stddef.h>

#include "base/loop_progress.h"
#include "shitsukan/noise_map.h"
#include "base/fbm_fields.h"

sk_noise_map_desc sk_noise_map_desc_resolved(const sk_noise_map_desc *desc)
{
    sk_noise_map_desc d = *desc;
    sk_schema_apply_defaults(&sk_noise_map_schema, &d);
    if (d.height == 0) d.height = d.width;
    return d;
}

sk_result sk_noise_map_desc_validate(const sk_noise_map_desc *d, sk_error *err)
{
    /* the map's own keys, then its fBm under "fbm" as the C struct names it */
    static const char *const own[] = {"width", "height", "cells"};
    for (int i = 0; i < 3; i++) {
        sk_result r =
            sk_schema_check_field(sk_schema_find(&sk_noise_map_schema, own[i]), d, own[i], err);
        if (r != SK_OK) return r;
    }
    return sk_fbm_desc_validate(&d->fbm, "fbm", err);
}

sk_result sk_noise_map_render(const sk_noise_map_desc *desc, const int region[4], sk_image *out,
                              sk_error *err)
{
    sk_noise_map_desc d = sk_noise_map_desc_resolved(desc);
    sk_result r = sk_noise_map_desc_validate(&d, err);
    if (r != SK_OK) return r;
    int rx = 0, ry = 0, rw = d.width, rh = d.height;
    if (region) {
        rx = region[0];
        ry = region[1];
        rw = region[2];
        rh = region[3];
        if (rx < 0 || ry < 0 || rw < 1 || rh < 1 || rx > d.width - rw || ry > d.height - rh)
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "region %d,%d,%d,%d lies outside the %dx%d map", rx, ry, rw, rh, d.width,
                           d.height);
    }
    if (!out || !out->data || out->width != rw || out->height != rh || out->channels != 1)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "output image must be 1 channel of %dx%d",
                       rw, rh);
    /* lattice units per pixel; seamless maps round the periods to whole cells */
    int period_x = 1, period_y = 1;
    double sx = d.cells / d.width, sy = sx;
    if (d.seamless) {
        period_x = (int)lround(d.cells) < 1 ? 1 : (int)lround(d.cells);
        period_y = (int)lround(d.cells * d.height / d.width);
        if (period_y < 1) period_y = 1;
        sx = (double)period_x / d.width;
        sy = (double)period_y / d.height;
    }
    sk__loop_progress lp;
    sk__loop_progress_init(&lp, &d.progress, rh);
#pragma omp parallel for schedule(dynamic, 4)
    for (int j = 0; j < rh; j++) {
        float *row = out->data + (size_t)j * (size_t)rw;
        float y = (float)((ry + j + 0.5) * sy);
        for (int i = 0; i < rw; i++) {
            float x = (float)((rx + i + 0.5) * sx);
            float n = d.seamless ? sk_fbm2_periodic(d.seed, x, y, period_x, period_y, &d.fbm)
                                 : sk_fbm2(d.seed, x, y, &d.fbm);
            row[i] = 0.5f + 0.5f * n;
        }
        sk__loop_progress_tick(&lp);
    }
    return SK_OK;
}

static const sk_schema_field k_fields[] = {
    SK_SCHEMA_SEED(sk_noise_map_desc, seed, "seed", .doc = "random seed"),
    SK_SCHEMA_INT(sk_noise_map_desc, width, "width", 1, SK_IMAGE_MAX_DIMENSION, .def = 512,
                  .doc = "map width in pixels"),
    SK_SCHEMA_INT(sk_noise_map_desc, height, "height", 1, SK_IMAGE_MAX_DIMENSION,
                  .def_text = "width", .doc = "map height in pixels"),
    SK_SCHEMA_FLOAT(sk_noise_map_desc, cells, "cells", 1e-3, 4096, .def = 8,
                    .doc = "noise cells across the width (base frequency)"),
    SK__FBM_FIELDS(sk_noise_map_desc, fbm.octaves, fbm.lacunarity, fbm.gain),
    SK_SCHEMA_BOOL(sk_noise_map_desc, seamless, "seamless",
                   .doc = "tileable map (whole-cell periods)"),
};

const sk_schema sk_noise_map_schema = SK_SCHEMA_OF("noise", sk_noise_map_desc, k_fields);
