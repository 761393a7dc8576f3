/* The plot of the tracked skin points (e.g. a belly and an upper-arm point) over a run:
 * their height with the fat layer (the simulation) and without it (the skin carried by the
 * bones, as in Wilhelms' model the paper extends), and the difference, the jiggle the fat
 * adds (Shigemori & Kawai sec. 5). Two plots one above the other. */
#include <stdio.h>
#include <stdlib.h>

#include "shitsukan/draw.h"
#include "products/tissue/tissue_draw_internal.h"

sk_result sk__plot_tracked(const sk__tracked_series *t, const char *png_path, sk_error *err)
{
    if (t->count < 1 || t->samples < 2)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "nothing tracked to plot");
    int n = t->count;
    sk_plot_series *height = calloc((size_t)(2 * n), sizeof *height),
                   *jiggle = calloc((size_t)n, sizeof *jiggle);
    float *diff = malloc((size_t)n * (size_t)t->samples * sizeof *diff);
    char(*labels)[96] = calloc((size_t)(3 * n), sizeof *labels);
    sk_image plots[2] = {{0}}, sheet = {0};
    sk_result r = SK_OK;
    if (!height || !jiggle || !diff || !labels)
        r = sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for the plot");
    for (int k = 0; r == SK_OK && k < n; k++) {
        const float *with = t->with_fat + (size_t)k * (size_t)t->samples;
        const float *without = t->without_fat + (size_t)k * (size_t)t->samples;
        for (int i = 0; i < t->samples; i++)
            diff[(size_t)k * (size_t)t->samples + (size_t)i] = with[i] - without[i];
        snprintf(labels[3 * k], sizeof labels[0], "%s, with fat", t->name[k]);
        snprintf(labels[3 * k + 1], sizeof labels[0], "%s, without fat", t->name[k]);
        snprintf(labels[3 * k + 2], sizeof labels[0], "%s", t->name[k]);
        sk_color c = sk_palette(k);
        height[2 * k] = (sk_plot_series){labels[3 * k], t->time, with, t->samples, c, 2.0f};
        sk_color light = sk_rgba(c.r, c.g, c.b, 0.45f);
        height[2 * k + 1] =
            (sk_plot_series){labels[3 * k + 1], t->time, without, t->samples, light, 4.0f};
        jiggle[k] = (sk_plot_series){
            labels[3 * k + 2], t->time, diff + (size_t)k * (size_t)t->samples, t->samples, c, 2.0f};
    }
    if (r == SK_OK) {
        sk_plot_desc d = {0};
        d.width = 900;
        d.height = 380;
        d.title = "Tracked skin points: height with and without fat";
        d.x_label = "time (s)";
        d.y_label = "height (mm)";
        r = sk_plot_lines(height, 2 * n, &d, &plots[0], err);
        if (r == SK_OK) {
            d.title = "The jiggle: with fat minus without";
            d.y_label = "height difference (mm)";
            r = sk_plot_lines(jiggle, n, &d, &plots[1], err);
        }
    }
    if (r == SK_OK) {
        const sk_image *tiles[2] = {&plots[0], &plots[1]};
        sk_contact_sheet_desc cs = {0};
        cs.columns = 1;
        cs.padding = 4;
        r = sk_contact_sheet(tiles, NULL, 2, &cs, &sheet, err);
    }
    if (r == SK_OK) r = sk_image_write_png(&sheet, png_path, NULL, err);
    sk_image_free(&plots[0]);
    sk_image_free(&plots[1]);
    sk_image_free(&sheet);
    free(height);
    free(jiggle);
    free(diff);
    free(labels);
    return r;
}
