/* Line-plot layout: input checks, axis ranges (auto ranges rounded out to round tick
 * values) and the margins that keep every tick label, axis label and the title inside
 * the image. */
#include <stdio.h>
#include <string.h>

#include "products/draw/draw_internal.h"

#define SK__PLOT_MAX_SERIES 1024
#define SK__PLOT_MAX_POINTS 100000000
#define SK__PLOT_MIN_SIZE 64
#define SK__PLOT_MAX_SIZE 16384
#define SK__PLOT_MIN_AREA 32 /* smallest plot area side, pixels */
#define SK__PLOT_MAX_TEXT_SCALE 16
#define SK__PLOT_Y_MARGIN 0.03 /* auto y range: data range plus 3% on each side */

sk_plot_desc sk_plot_desc_resolved(const sk_plot_desc *desc)
{
    sk_plot_desc d = {0};
    if (desc) d = *desc;
    if (d.width == 0) d.width = 800;
    if (d.height == 0) d.height = 500;
    if (d.text_scale == 0) d.text_scale = 2;
    if (d.channels == 0) d.channels = 3;
    if (d.legend == SK_LEGEND_DEFAULT) d.legend = SK_LEGEND_AUTO;
    return d;
}

static sk_result check_size(sk_error *err, const char *name, int v, int def)
{
    if (v == 0) return SK_OK;
    if (v > SK__PLOT_MAX_SIZE)
        return sk_fail(err, SK_ERROR_LIMIT, "%s = %d is out of range [%d, %d] (0 = %d)", name, v,
                       SK__PLOT_MIN_SIZE, SK__PLOT_MAX_SIZE, def);
    if (v < SK__PLOT_MIN_SIZE)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "%s = %d is out of range [%d, %d] (0 = %d)",
                       name, v, SK__PLOT_MIN_SIZE, SK__PLOT_MAX_SIZE, def);
    return SK_OK;
}

static sk_result check_axis(sk_error *err, const char *axis, float lo, float hi)
{
    char name[16];
    sk_result r;
    snprintf(name, sizeof name, "%s_min", axis);
    if ((r = sk_check_finite(err, name, lo)) != SK_OK) return r;
    snprintf(name, sizeof name, "%s_max", axis);
    if ((r = sk_check_finite(err, name, hi)) != SK_OK) return r;
    if (!(hi > lo))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "%s_min = %g must be less than %s_max = %g",
                       axis, (double)lo, axis, (double)hi);
    return SK_OK;
}

static sk_result validate(const sk_plot_series *series, int count, const sk_plot_desc *d,
                          sk_error *err)
{
    sk_result r;
    if ((r = check_size(err, "width", d->width, 800)) != SK_OK) return r;
    if ((r = check_size(err, "height", d->height, 500)) != SK_OK) return r;
    if ((r = sk_check_range_i(err, "text_scale", d->text_scale, 0, SK__PLOT_MAX_TEXT_SCALE)) !=
        SK_OK)
        return r;
    if ((r = sk_check_range_i(err, "channels", d->channels, 0, 4)) != SK_OK) return r;
    if ((r = sk_check_range_i(err, "legend", (int)d->legend, 0, SK_LEGEND_BOTTOM_LEFT)) != SK_OK)
        return r;
    if (d->fixed_x && (r = check_axis(err, "x", d->x_min, d->x_max)) != SK_OK) return r;
    if (d->fixed_y && (r = check_axis(err, "y", d->y_min, d->y_max)) != SK_OK) return r;
    if ((r = sk_check_range_i(err, "series_count", count, 0, SK__PLOT_MAX_SERIES)) != SK_OK)
        return r;
    if (count > 0 && !series) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "series is NULL");
    for (int i = 0; i < count; i++) {
        const sk_plot_series *s = &series[i];
        char name[48];
        snprintf(name, sizeof name, "series[%d].count", i);
        if ((r = sk_check_range_i(err, name, s->count, 0, SK__PLOT_MAX_POINTS)) != SK_OK) return r;
        if (s->count > 0 && !s->y)
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "series[%d].y is NULL", i);
        snprintf(name, sizeof name, "series[%d].width", i);
        if ((r = sk_check_range_f(err, name, s->width, 0.0, 64.0)) != SK_OK) return r;
        if (!sk__color_finite(s->color))
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "series[%d].color has a component that is not a finite number", i);
    }
    return SK_OK;
}

/* Range of the finite data along one axis; false if there is none. */
static bool data_range(const sk_plot_series *series, int count, bool want_x, double *lo, double *hi)
{
    *lo = INFINITY;
    *hi = -INFINITY;
    for (int s = 0; s < count; s++) {
        for (int i = 0; i < series[s].count; i++) {
            double x = sk__series_x(&series[s], i), y = series[s].y[i];
            if (!isfinite(x) || !isfinite(y)) continue;
            double v = want_x ? x : y;
            *lo = fmin(*lo, v);
            *hi = fmax(*hi, v);
        }
    }
    if (!(*lo <= *hi)) {
        *lo = 0.0;
        *hi = 1.0;
        return false;
    }
    if (*hi == *lo) {
        /* A flat range: open it up around the value. */
        double d = *lo != 0.0 ? 0.1 * fabs(*lo) : 1.0;
        *lo -= d;
        *hi += d;
    }
    return true;
}

/* Ticks with a given step inside [lo, hi]. */
static sk_ticks ticks_with_step(double lo, double hi, sk_ticks t)
{
    double a = ceil(lo / t.step - 1e-9), b = floor(hi / t.step + 1e-9);
    if (!(fabs(a) < 1e15 && fabs(b) < 1e15) || b < a) {
        t.count = 0;
        return t;
    }
    t.first_index = (long long)a;
    t.count = (int)(b - a + 1.0);
    return t;
}

/* Rounds [lo, hi] out to multiples of `unit`. */
static void round_out(double *lo, double *hi, double unit)
{
    double a = floor(*lo / unit + 1e-9) * unit, b = ceil(*hi / unit - 1e-9) * unit;
    if (isfinite(a) && isfinite(b) && b > a) {
        *lo = a;
        *hi = b;
    }
}

static int widest_label(const sk_ticks *t, int scale)
{
    int w = 0;
    char buf[64];
    for (int i = 0; i < t->count; i++) {
        sk_ticks_format(t, i, buf, sizeof buf);
        int lw = sk_draw_text_width(buf, scale);
        if (lw > w) w = lw;
    }
    return w;
}

static int label_width(const sk_ticks *t, int i, int scale)
{
    char buf[64];
    sk_ticks_format(t, i, buf, sizeof buf);
    return sk_draw_text_width(buf, scale);
}

/* The y axis: its ticks are spaced at least 2.5 text heights apart. */
static void y_axis(const sk_plot_series *series, int count, const sk_plot_desc *d, int span_px,
                   int text_h, sk_plot_layout *l)
{
    int max_ticks = (int)(span_px / (2.5 * text_h)) + 1;
    if (max_ticks < 2) max_ticks = 2;
    if (d->fixed_y) {
        l->y_min = d->y_min;
        l->y_max = d->y_max;
        l->y_ticks = sk_nice_ticks(l->y_min, l->y_max, max_ticks);
        return;
    }
    double lo, hi;
    data_range(series, count, false, &lo, &hi);
    double m = SK__PLOT_Y_MARGIN * (hi - lo);
    lo -= m;
    hi += m;
    sk_ticks t = sk_nice_ticks(lo, hi, max_ticks);
    if (t.count > 0) round_out(&lo, &hi, 0.5 * t.step);
    l->y_min = lo;
    l->y_max = hi;
    l->y_ticks = t.count > 0 ? ticks_with_step(lo, hi, t) : t;
}

/* The x axis: the finest round step whose labels keep two glyphs of space between them. */
static void x_axis(const sk_plot_series *series, int count, const sk_plot_desc *d, int span_px,
                   int scale, sk_plot_layout *l)
{
    double lo, hi;
    if (d->fixed_x) {
        lo = d->x_min;
        hi = d->x_max;
    } else {
        data_range(series, count, true, &lo, &hi);
    }
    int char_w = SK__GLYPH_ADVANCE * scale;
    int max_ticks = span_px / (2 * char_w) + 1;
    if (max_ticks > 20) max_ticks = 20;
    for (int mc = max_ticks; mc >= 2; mc--) {
        sk_ticks t = sk_nice_ticks(lo, hi, mc);
        double a = lo, b = hi;
        if (t.count > 0 && !d->fixed_x) {
            round_out(&a, &b, t.step);
            t = ticks_with_step(a, b, t);
        }
        l->x_min = a;
        l->x_max = b;
        l->x_ticks = t;
        if (t.count == 0) return;
        double spacing = t.step / (b - a) * span_px;
        if (mc == 2 || spacing >= widest_label(&t, scale) + 2 * char_w) return;
    }
}

sk_result sk__plot_frame_compute(const sk_plot_series *series, int series_count,
                                 const sk_plot_desc *desc, sk__plot_frame *frame, sk_error *err)
{
    sk_plot_desc raw = {0};
    if (desc) raw = *desc;
    sk_result r = validate(series, series_count, &raw, err);
    if (r != SK_OK) return r;
    sk_plot_desc d = sk_plot_desc_resolved(&raw);
    int s = d.text_scale;
    memset(frame, 0, sizeof *frame);
    frame->desc = d;
    frame->text_h = sk_draw_text_height(s);
    frame->char_w = SK__GLYPH_ADVANCE * s;
    frame->pad = 5 * s;
    frame->gap = 2 * s;
    frame->tick_len = 2 * s + 1;
    int pad = frame->pad, gap = frame->gap, th = frame->text_h;
    sk_plot_layout *l = &frame->layout;
    l->width = d.width;
    l->height = d.height;

    /* Vertical margins do not depend on the ticks. A y tick label is centred on its
       tick, so half a capital (3.5 rows) may stick out above the frame. */
    bool titled = d.title && d.title[0];
    int top = pad + (titled ? sk_draw_text_height(s + 1) + pad : 0) + (7 * s + 1) / 2;
    int bottom = frame->tick_len + gap + th + (d.x_label && d.x_label[0] ? 2 * gap + th : 0) + pad;
    int frame_h = d.height - top - bottom;
    y_axis(series, series_count, &d, frame_h, th, l);

    int left = pad + (d.y_label && d.y_label[0] ? th + 2 * gap : 0) + widest_label(&l->y_ticks, s) +
               gap + frame->tick_len;
    int right = pad;
    /* Two passes: the first ticks tell how far the last x label reaches past the frame. */
    for (int pass = 0; pass < 2; pass++) {
        int frame_w = d.width - left - right;
        if (frame_w < SK__PLOT_MIN_AREA) break;
        x_axis(series, series_count, &d, frame_w, s, l);
        const sk_ticks *t = &l->x_ticks;
        if (t->count > 0) {
            double last = sk_ticks_value(t, t->count - 1);
            double px = (last - l->x_min) / (l->x_max - l->x_min) * frame_w;
            int overhang = (int)ceil(px + label_width(t, t->count - 1, s) / 2.0 - frame_w);
            if (pad + overhang > right) right = pad + overhang;
            double first = sk_ticks_value(t, 0);
            double px0 = (first - l->x_min) / (l->x_max - l->x_min) * frame_w;
            int under = (int)ceil(label_width(t, 0, s) / 2.0 - px0);
            if (pad + under > left) left = pad + under;
        }
    }
    int frame_w = d.width - left - right;
    if (frame_w < SK__PLOT_MIN_AREA || frame_h < SK__PLOT_MIN_AREA)
        return sk_fail(err, SK_ERROR_LIMIT,
                       "the plot area would be %d x %d pixels (at least %d x %d needed): increase "
                       "width (%d) or height (%d), or reduce text_scale (%d)",
                       frame_w, frame_h, SK__PLOT_MIN_AREA, SK__PLOT_MIN_AREA, d.width, d.height,
                       s);
    /* The frame lines run along pixel centres; data bounds map onto them. */
    l->frame_x0 = (float)left + 0.5f;
    l->frame_x1 = (float)(d.width - right) - 0.5f;
    l->frame_y0 = (float)top + 0.5f;
    l->frame_y1 = (float)(d.height - bottom) - 0.5f;
    return SK_OK;
}

sk_result sk_plot_compute_layout(const sk_plot_series *series, int series_count,
                                 const sk_plot_desc *desc, sk_plot_layout *layout, sk_error *err)
{
    if (!layout) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "layout is NULL");
    sk__plot_frame frame;
    sk_result r = sk__plot_frame_compute(series, series_count, desc, &frame, err);
    if (r == SK_OK) *layout = frame.layout;
    return r;
}
