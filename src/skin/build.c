/* Building a skin (paper Fig. 11, sec. 4.1): centre points, Voronoi division,
 * perturbation and stretch for level 1, then recursively for every deeper level inside
 * its parents; then the lookup grid, the pores and the shading constants. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "skin/skin_internal.h"

static void level_setup(sk_skin *skin, int k)
{
    const sk_skin_level *d = &skin->desc.levels[k];
    sk__level *lv = &skin->levels[k];
    sk__stretch_matrices(d, lv->m, lv->minv);
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 2; j++) lv->minvf[i][j] = (float)lv->minv[i][j];
    lv->depth = d->perturb_depth;
    for (int n = 1; n <= lv->depth; n++)
        lv->amp[n] = d->perturb_rate * exp2(-n * (double)d->perturb_decay);
    lv->perturbed = d->perturb_rate > 0.0f;
    lv->roundness = d->roundness;
    lv->spacing = d->spacing_mm;
    /* profile z is in tenths of the nominal cell radius (spacing / 2) */
    lv->z_scale = d->spacing_mm / 20.0f;
    sk__profile *p = &lv->profile;
    p->segment_count = d->segment_count;
    p->z_min = INFINITY, p->z_max = -INFINITY;
    for (int s = 0; s < d->segment_count; s++)
        for (int i = 0; i < 4; i++) {
            p->x[s][i] = d->segments[s].points[i][0];
            p->z[s][i] = d->segments[s].points[i][1];
            p->z_min = fminf(p->z_min, p->z[s][i]);
            p->z_max = fmaxf(p->z_max, p->z[s][i]);
        }
    p->g_min = 1.0f - d->roundness;
    sk__profile_prepare(p);
}

static void shading_setup(sk_skin *skin)
{
    const sk_skin_shading *sh = &skin->desc.shading;
    double el = sh->light_elevation, az = sh->light_azimuth;
    /* azimuth 0 = light from +y (top of the image), counter-clockwise */
    double lx = -sin(az) * cos(el), ly = cos(az) * cos(el), lz = sin(el);
    skin->light[0] = (float)lx, skin->light[1] = (float)ly, skin->light[2] = (float)lz;
    double hx = lx, hy = ly, hz = lz + 1.0, hl = sqrt(hx * hx + hy * hy + hz * hz);
    skin->half[0] = (float)(hx / hl), skin->half[1] = (float)(hy / hl),
    skin->half[2] = (float)(hz / hl);
    for (int i = 0; i < 3; i++) skin->albedo[i] = sh->albedo[i];
    skin->sun = sh->sun_fraction;
    skin->sky = 1.0f - sh->sun_fraction;
    skin->spec = sh->no_specular ? 0.0f : sh->specular;
    skin->shininess = sh->shininess;
    skin->shininess_int = sh->shininess == floorf(sh->shininess) ? (int)sh->shininess : 0;
}

static void height_range(sk_skin *skin)
{
    float lo = 0, hi = 0;
    for (int k = 0; k < skin->level_count; k++) {
        const sk__level *lv = &skin->levels[k];
        lo += lv->profile.z_min * lv->z_scale;
        hi += lv->profile.z_max * lv->z_scale;
    }
    /* the profiles stay within their control points' z (a Bezier curve lies in their
       hull); pores dig below, deeper where they overlap */
    lo -= sk__pores_deepest(skin);
    skin->height_min = lo;
    skin->height_max = hi > lo ? hi : lo + 1e-6f;
}

sk_result sk_skin_create(sk_skin **out, const sk_skin_desc *desc, sk_error *err)
{
    if (!out) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "sk_skin_create: out is NULL");
    *out = NULL;
    sk_result r = sk_skin_desc_validate(desc, err);
    if (r != SK_OK) return r;
    sk_skin *skin = calloc(1, sizeof *skin);
    if (!skin) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for the skin");
    skin->desc = sk_skin_desc_resolved(desc);
    r = sk_skin_desc_validate(&skin->desc, err);
    if (r != SK_OK) goto fail;
    skin->level_count = skin->desc.level_count;
    const sk_progress *progress = &desc->progress;
    skin->tile[0] = skin->desc.size_mm[0];
    skin->tile[1] = skin->desc.size_mm[1];
    skin->period[0] = skin->tile[0];
    skin->period[1] = skin->tile[1];
    for (int k = 0; k < skin->level_count; k++) level_setup(skin, k);
    if (skin->desc.aperiodic) {
        /* room for two stretched level-1 cells beyond the tile, so nothing wraps into it */
        const sk_skin_level *l1 = &skin->desc.levels[0];
        const double(*m)[2] = (const double(*)[2])skin->levels[0].m;
        double reach = 4.0 * l1->spacing_mm * (1.0 + 2.0 * l1->jitter_rate);
        skin->period[0] += reach * hypot(m[0][0], m[0][1]);
        skin->period[1] += reach * hypot(m[1][0], m[1][1]);
    }
    /* Refuse absurd sizes before building anything (cells per level ~ area / cell area). */
    double estimate = 0;
    for (int k = 0; k < skin->level_count; k++) {
        const sk_skin_level *lv = &skin->desc.levels[k];
        double cell = lv->spacing_mm * (double)lv->spacing_mm * lv->stretch[0] * lv->stretch[1] *
                      (lv->layout == SK_SKIN_LAYOUT_SQUARE ? 1.0 : 0.8660254);
        estimate += skin->period[0] * skin->period[1] / cell;
        if (estimate > 1.05 * SK_SKIN_MAX_CELLS) {
            r = sk_fail(err, SK_ERROR_LIMIT,
                        "levels[%d].spacing_mm = %g makes about %.3g cells on a %g x %g mm "
                        "tile; at most %d are supported",
                        k, lv->spacing_mm, estimate, skin->period[0], skin->period[1],
                        SK_SKIN_MAX_CELLS);
            goto fail;
        }
        if (desc->max_memory > 0 && estimate * SK_SKIN_BYTES_PER_CELL > desc->max_memory) {
            r = sk_fail(err, SK_ERROR_LIMIT,
                        "levels[%d].spacing_mm = %g on a %g x %g mm tile (size_mm) makes about "
                        "%.3g cells needing about %.1f GiB, more than the memory cap of %.1f GiB",
                        k, lv->spacing_mm, skin->period[0], skin->period[1], estimate,
                        estimate * SK_SKIN_BYTES_PER_CELL / 1073741824.0,
                        desc->max_memory / 1073741824.0);
            goto fail;
        }
    }

    size_t total = 0;
    for (int k = 0; k < skin->level_count; k++) {
        double *xy = NULL;
        uint32_t count = 0;
        r = sk__layout_points(skin, k, &xy, &count, err);
        if (r != SK_OK) goto fail;
        if (total + count > SK_SKIN_MAX_CELLS) {
            free(xy);
            r = sk_fail(err, SK_ERROR_LIMIT,
                        "level %d would bring the skin to %zu cells; at most %d are supported "
                        "(raise levels[%d].spacing_mm or reduce size_mm)",
                        k + 1, total + count, SK_SKIN_MAX_CELLS, k);
            goto fail;
        }
        if (k == 0)
            r = sk__build_level1(skin, xy, count, err);
        else
            r = sk__build_children(skin, k, xy, count, err);
        free(xy);
        if (r != SK_OK) goto fail;
        r = sk__build_query_records(&skin->levels[k], err);
        if (r != SK_OK) goto fail;
        if (k == 0) {
            r = sk__build_grid(skin, err);
            if (r != SK_OK) goto fail;
        }
        total += skin->levels[k].cell_count;
        sk_progress_report(progress, (double)(k + 1) / (skin->level_count + 1));
    }
    r = sk__build_pores(skin, err);
    if (r != SK_OK) goto fail;
    height_range(skin);
    shading_setup(skin);
    sk_progress_report(progress, 1.0);
    *out = skin;
    return SK_OK;
fail:
    sk_skin_destroy(skin);
    return r;
}

void sk_skin_destroy(sk_skin *skin)
{
    if (!skin) return;
    for (int k = 0; k < SK_SKIN_MAX_LEVELS; k++) {
        sk__level *lv = &skin->levels[k];
        free(lv->cells);
        free(lv->uses);
        free(lv->edges);
        free(lv->vxy);
        free(lv->f);
        free(lv->fans);
        free(lv->sectors);
    }
    free(skin->grid.start);
    free(skin->grid.cell);
    free(skin->grid.shift);
    free(skin->origin);
    free(skin->pores.start);
    free(skin->pores.near);
    free(skin);
}

const sk_skin_desc *sk_skin_get_desc(const sk_skin *skin) { return &skin->desc; }

void sk_skin_tile_size(const sk_skin *skin, double *width_mm, double *height_mm)
{
    if (width_mm) *width_mm = skin->tile[0];
    if (height_mm) *height_mm = skin->tile[1];
}

void sk_skin_height_range(const sk_skin *skin, float *min_mm, float *max_mm)
{
    if (min_mm) *min_mm = skin->height_min;
    if (max_mm) *max_mm = skin->height_max;
}

uint32_t sk_skin_cell_count(const sk_skin *skin, int level)
{
    if (!skin || level < 1 || level > skin->level_count) return 0;
    return skin->levels[level - 1].cell_count;
}
