/* Joint-angle plots of an animation (the angle profiles behind the thesis's Figs. 4.19 and
 * 4.20): the driven DOFs and the DOFs that follow them through the natural coupling. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "models/hand/hand_internal.h"
#include "shitsukan/hand.h"

int sk_hand_moving_dofs(const double *dofs, int frame_count, const bool driven[SK_HAND_DOF_COUNT],
                        double min_range, int *out, int max_count)
{
    int n = 0;
    for (int d = 0; d < SK_HAND_DOF_COUNT && n < max_count; d++)
        if (driven && driven[d]) out[n++] = d;
    double range[SK_HAND_DOF_COUNT];
    int others[SK_HAND_DOF_COUNT], m = 0;
    for (int d = 0; d < SK_HAND_DOF_COUNT; d++) {
        if ((driven && driven[d]) || sk_hand_dof(d)->translation) continue;
        double lo = INFINITY, hi = -INFINITY;
        for (int f = 0; f < frame_count; f++) {
            double v = dofs[(size_t)f * SK_HAND_DOF_COUNT + d];
            lo = fmin(lo, v);
            hi = fmax(hi, v);
        }
        range[d] = hi - lo;
        if (frame_count > 0 && range[d] >= min_range) others[m++] = d;
    }
    /* largest range first (insertion sort; ties keep DOF order) */
    for (int i = 1; i < m; i++) {
        int d = others[i], j = i;
        for (; j > 0 && range[others[j - 1]] < range[d]; j--) others[j] = others[j - 1];
        others[j] = d;
    }
    for (int i = 0; i < m && n < max_count; i++) out[n++] = others[i];
    return n;
}

/* The legend box of sk_plot_lines (rows of 12 text units, a line sample of 4 characters,
 * padding of 3 units + 2 px, 3 units + 4 px from the frame) in pixels. */
static void legend_size(const sk_plot_series *series, int count, int s, double *w, double *h)
{
    int label_w = 0;
    for (int i = 0; i < count; i++) {
        int lw = sk_draw_text_width(series[i].label, s);
        if (lw > label_w) label_w = lw;
    }
    *w = 2.0 * (3 * s + 2) + 5.0 * 6 * s + label_w;
    *h = 2.0 * (3 * s + 2) + count * 12.0 * s - 3 * s;
}

/* Whether some data point (or segment midpoint) falls in the pixel box. */
static bool box_hits_data(const sk_plot_series *series, int count, const sk_plot_layout *l,
                          double x0, double y0, double x1, double y1)
{
    for (int i = 0; i < count; i++)
        for (int k = 0; k < series[i].count; k++) {
            for (int half = 0; half < 2 && (half == 0 || k + 1 < series[i].count); half++) {
                double x = half ? k + 0.5 : k;
                double y = half ? 0.5 * (series[i].y[k] + series[i].y[k + 1]) : series[i].y[k];
                sk_vec2f p = sk_plot_map(l, x, y);
                if (p.x >= x0 && p.x <= x1 && p.y >= y0 && p.y <= y1) return true;
            }
        }
    return false;
}

/* When every inside corner of the plot would put the legend over a line, the y range
 * grows upward by the legend's share of the plot area (rounded out to half ticks) and
 * the legend goes top right, above the data. */
static void make_legend_room(const sk_plot_series *series, int count, sk_plot_desc *pd)
{
    sk_plot_layout l;
    if (count == 0 || sk_plot_compute_layout(series, count, pd, &l, NULL) != SK_OK) return;
    int s = sk_plot_desc_resolved(pd).text_scale;
    double w, h, margin = 3 * s + 4;
    legend_size(series, count, s, &w, &h);
    double fx0 = l.frame_x0 + margin, fx1 = l.frame_x1 - margin;
    double fy0 = l.frame_y0 + margin, fy1 = l.frame_y1 - margin;
    double cx[4] = {fx1 - w, fx0, fx1 - w, fx0}, cy[4] = {fy0, fy0, fy1 - h, fy1 - h};
    for (int k = 0; k < 4; k++)
        if (!box_hits_data(series, count, &l, cx[k], cy[k], cx[k] + w, cy[k] + h)) return;
    double share = (h + 2.0 * margin) / (l.frame_y1 - l.frame_y0);
    if (share > 0.6) return; /* too many lines for room above them */
    double lo = INFINITY, hi = -INFINITY;
    for (int i = 0; i < count; i++)
        for (int k = 0; k < series[i].count; k++) {
            lo = fmin(lo, series[i].y[k]);
            hi = fmax(hi, series[i].y[k]);
        }
    double pad = fmax(0.03 * (hi - lo), 0.5);
    double y_min = lo - pad, y_max = y_min + (hi + pad - y_min) / (1.0 - share);
    sk_ticks t = sk_nice_ticks(y_min, y_max, 8);
    if (t.count > 0) { /* the bottom on a tick, the top on a half tick */
        y_min = floor(y_min / t.step) * t.step;
        y_max = ceil(y_max / (0.5 * t.step)) * 0.5 * t.step;
    }
    pd->fixed_y = true;
    pd->y_min = (float)y_min;
    pd->y_max = (float)y_max;
    pd->legend = SK_LEGEND_TOP_RIGHT;
}

sk_result sk_hand_plot_angles(const double *dofs, int frame_count, const int *dof_list,
                              int dof_count, const bool driven[SK_HAND_DOF_COUNT],
                              const sk_plot_desc *plot, sk_image *out, sk_error *err)
{
    sk_result r = sk_check_range_i(err, "frame_count", frame_count, 1, 100000000);
    if (r == SK_OK) r = sk_check_range_i(err, "dof_count", dof_count, 0, SK_HAND_DOF_COUNT);
    for (int i = 0; r == SK_OK && i < dof_count; i++)
        if (dof_list[i] < 0 || dof_list[i] >= SK_HAND_DOF_COUNT)
            r = sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "dof_list[%d] = %d is out of range [0, %d]",
                        i, dof_list[i], SK_HAND_DOF_COUNT - 1);
    if (r != SK_OK) return r;
    float *y = malloc(sizeof *y * (size_t)frame_count * (size_t)(dof_count > 0 ? dof_count : 1));
    if (!y) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for %d frames", frame_count);
    sk_plot_series series[SK_HAND_DOF_COUNT];
    char labels[SK_HAND_DOF_COUNT][48];
    bool any_translation = false, any_rotation = false;
    for (int i = 0; i < dof_count; i++) {
        int d = dof_list[i];
        const sk_hand_dof_info *info = sk_hand_dof(d);
        bool is_driven = driven && driven[d];
        float *col = y + (size_t)i * (size_t)frame_count;
        for (int f = 0; f < frame_count; f++)
            col[f] = (float)sk__hand_to_file_units(d, dofs[(size_t)f * SK_HAND_DOF_COUNT + d]);
        snprintf(labels[i], sizeof labels[i], "%s%s", info->name, is_driven ? " (driven)" : "");
        any_translation |= info->translation;
        any_rotation |= !info->translation;
        series[i] = (sk_plot_series){
            .label = labels[i], .y = col, .count = frame_count, .width = is_driven ? 4.0f : 2.0f};
    }
    sk_plot_desc pd = {0};
    if (plot) pd = *plot;
    if (!pd.x_label) pd.x_label = "frame";
    if (!pd.y_label)
        pd.y_label = any_translation
                         ? (any_rotation ? "angle (deg), translation (mm)" : "translation (mm)")
                         : "angle (deg)";
    if (!pd.fixed_y && (pd.legend == SK_LEGEND_DEFAULT || pd.legend == SK_LEGEND_AUTO))
        make_legend_room(series, dof_count, &pd);
    r = sk_plot_lines(series, dof_count, &pd, out, err);
    free(y);
    return r;
}
