/* The banded render of a skin map set: the region in bands of SK_SKIN_MAPS_BAND_ROWS rows
 * shared out between the threads in one parallel loop. Each thread renders a band on its
 * own (sk_skin_render's loop inside runs on that thread) into its own float normal and
 * furrow buffers and stores it at once in the set's encodings, so threads wait for one
 * another only at the end. */
#include <stdlib.h>

#include "products/maps/maps_internal.h"

/* Sets of fewer pixel-levels (pixels x levels x samples^2) render on one thread, as the
   skin's own render loop does: starting a second costs more than it saves. */
#define SK__MAPS_PARALLEL_WORK 32768

/* Renders the parts `parts` of band b (rows from b x SK_SKIN_MAPS_BAND_ROWS) into the
 * store, through the thread's normal and furrow buffers (the other parts go straight
 * into the store). */
static sk_result render_band(sk_skin_maps *m, unsigned parts, int b, float *normal, float *furrow,
                             sk_error *err)
{
    const sk_skin_maps_desc *d = &m->desc;
    int rw = d->region[2], y0 = b * SK_SKIN_MAPS_BAND_ROWS;
    int rows =
        d->region[3] - y0 < SK_SKIN_MAPS_BAND_ROWS ? d->region[3] - y0 : SK_SKIN_MAPS_BAND_ROWS;
    size_t off = (size_t)y0 * (size_t)rw;
    sk_skin_render_desc rd = {
        .width = d->width,
        .height = d->height,
        .region = {d->region[0], d->region[1] + y0, rw, rows},
        .height_mm = parts & SK__STORE_HEIGHT ? m->height.data + off : NULL,
        .normal = parts & SK__STORE_NORMAL ? normal : NULL,
        .furrow = parts & SK__STORE_FURROW ? furrow : NULL,
        .cell_id = parts & SK__STORE_IDS ? m->ids + off : NULL,
        .preview = parts & SK__STORE_PREVIEW ? m->preview.data + 3 * off : NULL,
        .edges = parts & SK__STORE_EDGES ? m->edges.data + 3 * off : NULL,
        .furrow_level = d->furrow_level,
        .id_level = d->id_level,
        .samples = d->samples,
    };
    sk_result r = sk_skin_render(m->skin, &rd, err);
    if (r != SK_OK) return r;
    for (size_t i = 0; i < (size_t)rows * (size_t)rw; i++) {
        size_t o = off + i;
        if (rd.normal) sk_skin_maps_store_normal(normal + 3 * i, m->normal + 2 * o);
        if (rd.furrow) m->furrow[o] = sk_skin_maps_furrow_code(furrow[i], m->furrow_span);
    }
    return SK_OK;
}

/* The parallel loop over the bands; the first failure is reported. */
static sk_result render_bands(sk_skin_maps *m, unsigned parts, sk_error *err)
{
    const sk_skin_maps_desc *d = &m->desc;
    int rh = d->region[3], bands = (rh + SK_SKIN_MAPS_BAND_ROWS - 1) / SK_SKIN_MAPS_BAND_ROWS;
    double work = (double)d->region[2] * rh * sk_skin_get_desc(m->skin)->level_count * d->samples *
                  d->samples;
    sk_result result = SK_OK;
    bool failed = false;
    long rows_done = 0;
#pragma omp parallel if (work >= SK__MAPS_PARALLEL_WORK && bands > 1)
    {
        size_t band_px = (size_t)d->region[2] * SK_SKIN_MAPS_BAND_ROWS;
        float *normal = parts & SK__STORE_NORMAL ? malloc(sizeof(float) * 3 * band_px) : NULL;
        float *furrow = parts & SK__STORE_FURROW ? malloc(sizeof(float) * band_px) : NULL;
        bool ready =
            (normal || !(parts & SK__STORE_NORMAL)) && (furrow || !(parts & SK__STORE_FURROW));
#pragma omp for schedule(dynamic, 1)
        for (int b = 0; b < bands; b++) {
            bool stop;
#pragma omp atomic read
            stop = failed;
            if (stop) continue;
            sk_error band_err = {0};
            sk_result r = ready ? render_band(m, parts, b, normal, furrow, &band_err)
                                : sk_fail(&band_err, SK_ERROR_OUT_OF_MEMORY,
                                          "out of memory for a band of the maps");
#pragma omp critical(sk_skin_maps_progress)
            {
                if (r != SK_OK && !failed) {
                    result = r;
                    if (err) *err = band_err;
#pragma omp atomic write
                    failed = true;
                }
                rows_done += r == SK_OK ? SK_SKIN_MAPS_BAND_ROWS : 0;
                if (r == SK_OK)
                    sk_progress_report(&d->progress,
                                       (double)(rows_done < rh ? rows_done : rh) / rh);
            }
        }
        free(normal), free(furrow);
    }
    return result;
}

sk_result sk_skin_maps_render(sk_skin_maps *maps, unsigned which, sk_error *err)
{
    if (!maps) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "maps must not be NULL");
    if (which == 0) which = maps->desc.maps;
    if (which & ~maps->desc.maps)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "maps 0x%x are asked for, the set holds 0x%x", which, maps->desc.maps);
    unsigned parts = 0;
    for (int k = 0; k < SK_SKIN_MAP_COUNT; k++)
        if (which & SK_SKIN_MAP_BIT(k))
            parts |= sk__skin_map_parts((sk_skin_map)k, maps->desc.samples);
    if (parts & ~maps->parts)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "the maps 0x%x were released: make a new set to render them", which);
    sk_result r = render_bands(maps, parts, err);
    /* a failed render leaves what it rendered unreadable */
    maps->rendered = r == SK_OK ? maps->rendered | parts : maps->rendered & ~parts;
    return r;
}
