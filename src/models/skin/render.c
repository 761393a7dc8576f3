/* Map rendering: height, tangent-space normal, furrow distance, cell id, shaded preview
 * (paper sec. 5: 400 x 400 bump-mapped images) and a furrow overlay, for any
 * sub-rectangle of the map. Every pixel is a pure function of its global position, so a
 * region renders the same bytes as the whole map, and rows run in parallel with the same
 * result for any thread count. */
#include <math.h>

#include "base/loop_progress.h"
#include "models/skin/skin_internal.h"

static const float level_colour[4][3] = {
    {0.95f, 0.10f, 0.10f}, {0.10f, 0.80f, 0.15f}, {0.15f, 0.35f, 1.00f}, {0.95f, 0.85f, 0.10f}};

/* Shaded colours of pixels gx0 .. gx0 + n - 1 (n <= SK__QUERY_BATCH) of image row gy, each
 * the mean over samples x samples points: every sub-row of points is queried in batches
 * with its own hint, and each pixel sums its points row by row, as one at a time would. */
static void supersample(const sk_skin *skin, int gx0, int n, int gy, int samples, double mm_x,
                        double mm_y, double top, sk__hint *hints, sk_vec3f *c)
{
    for (int b = 0; b < n; b++) c[b] = sk_v3f(0, 0, 0);
    int total = n * samples;
    for (int sy = 0; sy < samples; sy++) {
        double y = top - (gy + (sy + 0.5) / samples) * mm_y;
        for (int q0 = 0; q0 < total; q0 += SK__QUERY_BATCH) {
            int m = total - q0 < SK__QUERY_BATCH ? total - q0 : SK__QUERY_BATCH;
            double xs[SK__QUERY_BATCH], ys[SK__QUERY_BATCH];
            sk_skin_sample smp[SK__QUERY_BATCH];
            for (int q = 0; q < m; q++) {
                int b = (q0 + q) / samples, sx = (q0 + q) % samples;
                xs[q] = ((gx0 + b) + (sx + 0.5) / samples) * mm_x, ys[q] = y;
            }
            sk__query(skin, m, xs, ys, 0, smp, &hints[sy]);
            for (int q = 0; q < m; q++) {
                int b = (q0 + q) / samples;
                c[b] = sk_v3f_add(c[b], sk_skin_shade(skin, smp[q].normal));
            }
        }
    }
    for (int b = 0; b < n; b++) c[b] = sk_v3f_scale(c[b], 1.0f / (float)(samples * samples));
}

sk_result sk_skin_render(const sk_skin *skin, const sk_skin_render_desc *desc, sk_error *err)
{
    if (!skin || !desc)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "skin and desc must not be NULL");
    sk_result r;
    if ((r = sk_check_range_i(err, "width", desc->width, 1, 65536)) != SK_OK) return r;
    if ((r = sk_check_range_i(err, "height", desc->height, 1, 65536)) != SK_OK) return r;
    int rx = desc->region[0], ry = desc->region[1], rw = desc->region[2], rh = desc->region[3];
    if (rw == 0 && rh == 0) rx = 0, ry = 0, rw = desc->width, rh = desc->height;
    if (rx < 0 || ry < 0 || rw < 1 || rh < 1 || rx > desc->width - rw || ry > desc->height - rh)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "region %d,%d,%d,%d is not inside the %d x %d map", rx, ry, rw, rh,
                       desc->width, desc->height);
    int L = skin->level_count;
    int furrow_level = desc->furrow_level ? desc->furrow_level : 1;
    int id_level = desc->id_level ? desc->id_level : 1;
    int samples = desc->samples ? desc->samples : 1;
    if ((r = sk_check_range_i(err, "furrow_level", furrow_level, 1, L)) != SK_OK) return r;
    if ((r = sk_check_range_i(err, "id_level", id_level, 1, L)) != SK_OK) return r;
    if ((r = sk_check_range_i(err, "samples", samples, 1, 8)) != SK_OK) return r;

    double mm_x = skin->tile[0] / desc->width, mm_y = skin->tile[1] / desc->height;
    double top = skin->tile[1];
    bool want_furrow = desc->furrow || desc->edges;
    /* furrow distances: every level for the overlay, else only the one asked for */
    unsigned flags = desc->edges   ? SK_SKIN_QUERY_FURROW
                     : want_furrow ? 1u << (SK__FURROW_LEVEL_SHIFT + furrow_level - 1)
                                   : 0u;
    /* only cell ids and furrow distances: down to the deepest level they name, with no
       profiles or pores */
    int walked = L;
    if (!desc->height_mm && !desc->normal && !desc->preview && !desc->edges) {
        walked = desc->cell_id ? id_level : 1;
        if (desc->furrow && furrow_level > walked) walked = furrow_level;
        flags |= SK__QUERY_DEPTH(walked);
    }
    float line_mm = (float)(0.75 * fmax(mm_x, mm_y));
    sk__loop_progress lp;
    sk__loop_progress_init(&lp, &desc->progress, rh);

    /* under about a millisecond of work one thread is faster than two */
    double work = (double)rw * rh * walked * samples * samples;
#pragma omp parallel for schedule(dynamic, 1) if (work >= SK__PARALLEL_PIXELS)
    for (int j = 0; j < rh; j++) {
        int gy = ry + j;
        sk__hint hint, sub_hints[8];
        sk__hint_reset(&hint);
        for (int s = 0; s < samples; s++) sk__hint_reset(&sub_hints[s]);
        bool shade = desc->preview || desc->edges;
        for (int i0 = 0; i0 < rw; i0 += SK__QUERY_BATCH) {
            int n = rw - i0 < SK__QUERY_BATCH ? rw - i0 : SK__QUERY_BATCH;
            double xs[SK__QUERY_BATCH], ys[SK__QUERY_BATCH];
            sk_skin_sample batch[SK__QUERY_BATCH];
            for (int b = 0; b < n; b++)
                xs[b] = (rx + i0 + b + 0.5) * mm_x, ys[b] = top - (gy + 0.5) * mm_y;
            sk__query(skin, n, xs, ys, flags, batch, &hint);
            sk_vec3f colours[SK__QUERY_BATCH];
            if (shade && samples > 1)
                supersample(skin, rx + i0, n, gy, samples, mm_x, mm_y, top, sub_hints, colours);
            for (int b = 0; b < n; b++) {
                int i = i0 + b;
                size_t o = (size_t)j * (size_t)rw + (size_t)i;
                const sk_skin_sample *sp = &batch[b];
                if (desc->height_mm) desc->height_mm[o] = sp->height_mm;
                if (desc->normal) {
                    desc->normal[3 * o] = sp->normal.x;
                    desc->normal[3 * o + 1] = sp->normal.y;
                    desc->normal[3 * o + 2] = sp->normal.z;
                }
                if (desc->furrow) desc->furrow[o] = sp->furrow_mm[furrow_level - 1];
                if (desc->cell_id) desc->cell_id[o] = sp->cell[id_level - 1];
                if (!shade) continue;
                sk_vec3f c = samples > 1 ? colours[b] : sk_skin_shade(skin, sp->normal);
                if (desc->preview) {
                    desc->preview[3 * o] = c.x;
                    desc->preview[3 * o + 1] = c.y;
                    desc->preview[3 * o + 2] = c.z;
                }
                if (desc->edges) {
                    float e[3] = {c.x, c.y, c.z};
                    for (int k = L - 1; k >= 0; k--) {
                        float d = sp->furrow_mm[k];
                        if (d >= line_mm) continue;
                        float a = 1.0f - d / line_mm;
                        const float *lc = level_colour[k < 3 ? k : 3];
                        for (int q = 0; q < 3; q++) e[q] += (lc[q] - e[q]) * a;
                    }
                    desc->edges[3 * o] = e[0];
                    desc->edges[3 * o + 1] = e[1];
                    desc->edges[3 * o + 2] = e[2];
                }
            }
        }
        sk__loop_progress_tick(&lp);
    }
    sk_progress_report(&desc->progress, 1.0);
    return SK_OK;
}
