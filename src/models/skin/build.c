/* Building a skin (paper Fig. 11, sec. 4.1): centre points, Voronoi division,
 * perturbation and stretch for level 1, then recursively for every deeper level inside
 * its parents; then the lookup grid, the pores and the shading constants. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "models/skin/skin_internal.h"

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
    lv->spacing = d->spacing_mm;
    sk__level_profile_setup(skin, k);
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
    sk__height_range(skin);
    sk__shading_setup(skin);
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
