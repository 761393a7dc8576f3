/* Bar charts of a held-out evaluation (the model of thesis 3.2 against the mean, linear
 * regression and a PCA prior): one panel per pin set, a group of bars per unpinned joint
 * and one for all joints, drawn with the raster primitives of draw.h. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "models/hand/hand_internal.h"
#include "shitsukan/hand.h"

#define METHODS 4

/* "I.DIP.flex" -> "I.DIP" (flexion is the default DOF of a joint). */
static void short_name(int dof, char *buf, size_t size)
{
    const char *name = sk_hand_dof(dof)->name;
    size_t n = strlen(name);
    if (n > 5 && strcmp(name + n - 5, ".flex") == 0) n -= 5;
    snprintf(buf, size, "%.*s", (int)n, name);
}

static void draw_panel(sk_image *img, int x0, int y0, int w, int h, const sk_hand_pin_result *res,
                       const char *const *method_names, double y_max, int ts)
{
    const sk_color ink = sk_rgb(0.1f, 0.1f, 0.1f), grid = sk_rgb(0.85f, 0.85f, 0.85f);
    char title[256];
    int used = snprintf(title, sizeof title, "pins ");
    for (int k = 0; k < res->pins.count && used < (int)sizeof title; k++)
        used += snprintf(title + used, sizeof title - (size_t)used, "%s%s", k ? " + " : "",
                         sk_hand_dof(res->pins.dof[k])->name);
    snprintf(title + used, sizeof title - (size_t)used, ": held-out RMS error (deg)");
    sk_draw_text(img, (float)(x0 + 10 * ts), (float)(y0 + 4 * ts), title, ts, ink);
    /* plot area */
    int left = x0 + 40 * ts, right = x0 + w - 8 * ts, top = y0 + 30 * ts, bottom = y0 + h - 20 * ts;
    sk_ticks ticks = sk_nice_ticks(0.0, y_max, 6);
    double y_top = ticks.count > 0 ? fmax(y_max, sk_ticks_value(&ticks, ticks.count - 1)) : y_max;
    for (int i = 0; i < ticks.count; i++) {
        double v = sk_ticks_value(&ticks, i);
        float y = (float)(bottom - (bottom - top) * v / y_top);
        sk_draw_line_capped(img, (float)left, y, (float)right, y, 1.0f, SK_CAP_BUTT, grid);
        char label[32];
        sk_ticks_format(&ticks, i, label, sizeof label);
        int lw = sk_draw_text_width(label, ts);
        sk_draw_text(img, (float)(left - lw - 4 * ts), y - 4.5f * ts, label, ts, ink);
    }
    sk_draw_line_capped(img, (float)left, (float)bottom, (float)right, (float)bottom, 1.0f,
                        SK_CAP_BUTT, ink);
    sk_draw_line_capped(img, (float)left, (float)top, (float)left, (float)bottom, 1.0f, SK_CAP_BUTT,
                        ink);
    /* groups: each joint, then all */
    int groups = res->joint_count + 1;
    double gw = (double)(right - left) / groups;
    double bw = gw * 0.8 / METHODS;
    int label_scale = sk_draw_text_width("I.DIP", ts) < gw - 2 ? ts : 1;
    for (int g = 0; g < groups; g++) {
        double v[METHODS];
        char label[32];
        if (g < res->joint_count) {
            v[0] = res->model[g];
            v[1] = res->mean[g];
            v[2] = res->linear[g];
            v[3] = res->pca[g];
            short_name(res->joint[g], label, sizeof label);
        } else {
            v[0] = res->model_all;
            v[1] = res->mean_all;
            v[2] = res->linear_all;
            v[3] = res->pca_all;
            snprintf(label, sizeof label, "all");
        }
        double gx = left + g * gw + gw * 0.1;
        for (int m = 0; m < METHODS; m++) {
            double hv = v[m] * SK_RAD_TO_DEG / y_top * (bottom - top);
            sk_draw_rect(img, (float)(gx + m * bw), (float)(bottom - hv), (float)(bw * 0.9),
                         (float)hv, sk_palette(m));
        }
        int lw = sk_draw_text_width(label, label_scale);
        sk_draw_text(img, (float)(left + g * gw + gw / 2 - lw / 2.0), (float)(bottom + 5 * ts),
                     label, label_scale, g < res->joint_count ? ink : sk_rgb(0, 0, 0));
    }
    /* legend along the top right */
    float lx = (float)right;
    for (int m = METHODS - 1; m >= 0; m--) {
        int lw = sk_draw_text_width(method_names[m], ts);
        lx -= (float)(lw + 16 * ts);
        sk_draw_rect(img, lx, (float)(y0 + 17 * ts), 8.0f * ts, 8.0f * ts, sk_palette(m));
        sk_draw_text(img, lx + 10.0f * ts, (float)(y0 + 17 * ts), method_names[m], ts, ink);
    }
}

sk_result sk_hand_plot_evaluation(const sk_hand_evaluation *eval, const char *model_name,
                                  const sk_plot_desc *plot, sk_image *out, sk_error *err)
{
    memset(out, 0, sizeof *out);
    if (eval->pin_set_count < 1)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "the evaluation has no pin sets");
    int w = plot && plot->width ? plot->width : 900, ph = plot && plot->height ? plot->height : 300;
    sk_result r = sk_check_range_i(err, "width", w, 320, 8192);
    if (r == SK_OK) r = sk_check_range_i(err, "height", ph, 160, 4096);
    if (r != SK_OK) return r;
    int ts = ph >= 260 && w >= 700 ? 2 : 1;
    const char *title = plot && plot->title ? plot->title : NULL;
    int title_h = title ? 16 * ts : 0;
    int h = title_h + eval->pin_set_count * ph;
    r = sk_image_create(out, w, h, 3, err);
    if (r != SK_OK) return r;
    sk_draw_clear(out, sk_rgb(1, 1, 1));
    if (title) sk_draw_text(out, (float)(10 * ts), (float)(4 * ts), title, ts, sk_rgb(0, 0, 0));
    char pca_name[32];
    snprintf(pca_name, sizeof pca_name, "PCA %d", eval->pca_k);
    const char *names[METHODS] = {model_name ? model_name : "model", "mean", "linear", pca_name};
    double y_max = 0.0;
    for (int p = 0; p < eval->pin_set_count; p++) {
        const sk_hand_pin_result *res = &eval->result[p];
        for (int j = 0; j < res->joint_count; j++)
            y_max = fmax(
                y_max, fmax(fmax(res->model[j], res->mean[j]), fmax(res->linear[j], res->pca[j])));
    }
    y_max = fmax(y_max * SK_RAD_TO_DEG * 1.05, 1.0);
    for (int p = 0; p < eval->pin_set_count; p++)
        draw_panel(out, 0, title_h + p * ph, w, ph, &eval->result[p], names, y_max, ts);
    return SK_OK;
}
