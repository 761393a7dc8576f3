/* Line plots: series drawn as anti-aliased polylines clipped to the plot area, with a
 * frame, grid, round ticks and their labels, axis labels, a title and a legend placed in
 * the emptiest corner. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "products/draw/draw_internal.h"

#define SK__PLOT_DEFAULT_WIDTH 2.0f

static const sk_color plot_text = {0.0f, 0.0f, 0.0f, 1.0f};
static const sk_color plot_frame = {0.05f, 0.05f, 0.05f, 1.0f};
static const sk_color plot_grid = {0.78f, 0.78f, 0.78f, 1.0f};
static const sk_color plot_legend_fill = {1.0f, 1.0f, 1.0f, 0.88f};
static const sk_color plot_legend_border = {0.55f, 0.55f, 0.55f, 1.0f};

static sk_color series_color(const sk_plot_series *s, int i)
{
    return sk__color_is_zero(s->color) ? sk_palette(i) : s->color;
}

static float series_width(const sk_plot_series *s)
{
    return s->width > 0.0f ? s->width : SK__PLOT_DEFAULT_WIDTH;
}

/* Data to pixel coordinates in double (sk_plot_map rounds to float). */
static void map_point(const sk_plot_layout *l, double x, double y, double *px, double *py)
{
    *px = l->frame_x0 + (x - l->x_min) / (l->x_max - l->x_min) * (l->frame_x1 - l->frame_x0);
    *py = l->frame_y1 - (y - l->y_min) / (l->y_max - l->y_min) * (l->frame_y1 - l->frame_y0);
}

/* Clips the segment a + t (b - a), t in [0, 1], to a rectangle (Liang & Barsky 1984). */
static bool clip_segment(double ax, double ay, double bx, double by, double x0, double y0,
                         double x1, double y1, double *t0, double *t1)
{
    double dx = bx - ax, dy = by - ay;
    double p[4] = {-dx, dx, -dy, dy};
    double q[4] = {ax - x0, x1 - ax, ay - y0, y1 - ay};
    double lo = 0.0, hi = 1.0;
    for (int k = 0; k < 4; k++) {
        if (p[k] == 0.0) {
            if (q[k] < 0.0) return false;
            continue;
        }
        double r = q[k] / p[k];
        if (p[k] < 0.0) {
            if (r > hi) return false;
            if (r > lo) lo = r;
        } else {
            if (r < lo) return false;
            if (r < hi) hi = r;
        }
    }
    *t0 = lo;
    *t1 = hi;
    return true;
}

typedef struct series_run {
    sk_vec2f *pts;
    int n;
} series_run;

static void run_flush(series_run *run, sk_image *img, sk__clip clip, float width, sk_color c)
{
    if (run->n > 0) sk__draw_polyline_clip(img, clip, run->pts, run->n, false, width, c);
    run->n = 0;
}

/* Draws one series as polylines broken at non-finite points, pre-clipped (in double) to
 * a rectangle a little larger than the plot area so that far-away points stay exact. */
static void draw_series(sk_image *img, sk__clip clip, const sk_plot_layout *l,
                        const sk_plot_series *s, sk_color c, float width, sk_vec2f *buf)
{
    double m = (double)width + 4.0;
    double ex0 = clip.x0 - m, ey0 = clip.y0 - m, ex1 = clip.x1 + m, ey1 = clip.y1 + m;
    series_run run = {buf, 0};
    bool have_prev = false;
    double qx = 0.0, qy = 0.0;
    for (int i = 0; i < s->count; i++) {
        double x = sk__series_x(s, i), y = s->y[i];
        double px, py;
        map_point(l, x, y, &px, &py);
        if (!isfinite(x) || !isfinite(y) || !isfinite(px) || !isfinite(py)) {
            run_flush(&run, img, clip, width, c);
            have_prev = false;
            continue;
        }
        if (!have_prev) {
            run_flush(&run, img, clip, width, c);
            if (px >= ex0 && px <= ex1 && py >= ey0 && py <= ey1)
                run.pts[run.n++] = sk_v2f((float)px, (float)py);
        } else {
            double t0, t1;
            if (!clip_segment(qx, qy, px, py, ex0, ey0, ex1, ey1, &t0, &t1)) {
                run_flush(&run, img, clip, width, c);
            } else {
                if (run.n == 0 || t0 > 0.0) {
                    run_flush(&run, img, clip, width, c);
                    run.pts[run.n++] =
                        sk_v2f((float)(qx + t0 * (px - qx)), (float)(qy + t0 * (py - qy)));
                }
                run.pts[run.n++] =
                    sk_v2f((float)(qx + t1 * (px - qx)), (float)(qy + t1 * (py - qy)));
                if (t1 < 1.0) run_flush(&run, img, clip, width, c);
            }
        }
        have_prev = true;
        qx = px;
        qy = py;
    }
    run_flush(&run, img, clip, width, c);
}

/* Pixel-centre snapping keeps 1 px grid lines and ticks crisp. */
static float snap(double v) { return (float)(floor(v) + 0.5); }

static void hline(sk_image *img, double x0, double x1, double y, sk_color c)
{
    sk_draw_rect(img, (float)floor(x0), (float)(floor(y)), (float)(floor(x1) - floor(x0) + 1.0),
                 1.0f, c);
}

static void vline(sk_image *img, double x, double y0, double y1, sk_color c)
{
    sk_draw_rect(img, (float)floor(x), (float)floor(y0), 1.0f, (float)(floor(y1) - floor(y0) + 1.0),
                 c);
}

static void draw_axes(sk_image *img, const sk__plot_frame *f)
{
    const sk_plot_layout *l = &f->layout;
    int s = f->desc.text_scale;
    char buf[64];
    for (int i = 0; i < l->x_ticks.count; i++) {
        double v = sk_ticks_value(&l->x_ticks, i), px, py;
        map_point(l, v, l->y_min, &px, &py);
        px = snap(px);
        bool at_frame = fabs(px - l->frame_x0) < 0.5 || fabs(px - l->frame_x1) < 0.5;
        if (!f->desc.hide_grid && !at_frame)
            vline(img, px, l->frame_y0 + 1.0, l->frame_y1 - 1.0, plot_grid);
        vline(img, px, l->frame_y1 + 1.0, l->frame_y1 + f->tick_len, plot_frame);
        sk_ticks_format(&l->x_ticks, i, buf, sizeof buf);
        int w = sk_draw_text_width(buf, s);
        sk_draw_text(img, (float)floor(px - w / 2.0 + 0.5),
                     (float)floor(l->frame_y1 + 0.5) + f->tick_len + f->gap, buf, s, plot_text);
    }
    for (int i = 0; i < l->y_ticks.count; i++) {
        double v = sk_ticks_value(&l->y_ticks, i), px, py;
        map_point(l, l->x_min, v, &px, &py);
        py = snap(py);
        bool at_frame = fabs(py - l->frame_y0) < 0.5 || fabs(py - l->frame_y1) < 0.5;
        if (!f->desc.hide_grid && !at_frame)
            hline(img, l->frame_x0 + 1.0, l->frame_x1 - 1.0, py, plot_grid);
        hline(img, l->frame_x0 - f->tick_len, l->frame_x0 - 1.0, py, plot_frame);
        sk_ticks_format(&l->y_ticks, i, buf, sizeof buf);
        int w = sk_draw_text_width(buf, s);
        /* Centred on the tick by the middle of a capital (rows 0-6 of the glyph). */
        sk_draw_text(img, (float)(floor(l->frame_x0) - f->tick_len - f->gap - w),
                     (float)floor(py - 3.5 * s + 0.5), buf, s, plot_text);
    }
}

static void draw_frame(sk_image *img, const sk_plot_layout *l)
{
    hline(img, l->frame_x0, l->frame_x1, l->frame_y0, plot_frame);
    hline(img, l->frame_x0, l->frame_x1, l->frame_y1, plot_frame);
    vline(img, l->frame_x0, l->frame_y0, l->frame_y1, plot_frame);
    vline(img, l->frame_x1, l->frame_y0, l->frame_y1, plot_frame);
}

static void draw_labels(sk_image *img, const sk__plot_frame *f)
{
    const sk_plot_desc *d = &f->desc;
    const sk_plot_layout *l = &f->layout;
    int s = d->text_scale;
    char buf[512];
    double mid_x = 0.5 * (l->frame_x0 + l->frame_x1), mid_y = 0.5 * (l->frame_y0 + l->frame_y1);
    if (d->title && d->title[0]) {
        sk__text_fit(d->title, s + 1, l->width - 2 * f->pad, buf, sizeof buf);
        int w = sk_draw_text_width(buf, s + 1);
        double x = fmin(fmax(mid_x - w / 2.0, f->pad), l->width - f->pad - w);
        sk_draw_text(img, (float)floor(x + 0.5), (float)f->pad, buf, s + 1, plot_text);
    }
    if (d->x_label && d->x_label[0]) {
        sk__text_fit(d->x_label, s, (int)(l->frame_x1 - l->frame_x0), buf, sizeof buf);
        int w = sk_draw_text_width(buf, s);
        sk_draw_text(img, (float)floor(mid_x - w / 2.0 + 0.5),
                     (float)(l->height - f->pad - f->text_h), buf, s, plot_text);
    }
    if (d->y_label && d->y_label[0]) {
        sk__text_fit(d->y_label, s, (int)(l->frame_y1 - l->frame_y0), buf, sizeof buf);
        int w = sk_draw_text_width(buf, s);
        sk__draw_text_dir(img, sk__clip_image(img), (float)f->pad,
                          (float)floor(mid_y - w / 2.0 + 0.5), buf, s, SK__TEXT_UP, plot_text);
    }
}

/* How much of the data a legend box at (x0, y0, x1, y1) would hide: segments crossing it. */
static long long legend_overlap(const sk_plot_series *series, int count, const sk_plot_layout *l,
                                double x0, double y0, double x1, double y1)
{
    long long hits = 0;
    for (int k = 0; k < count; k++) {
        const sk_plot_series *s = &series[k];
        double qx = 0.0, qy = 0.0;
        bool have = false;
        for (int i = 0; i < s->count; i++) {
            double px, py;
            map_point(l, sk__series_x(s, i), s->y[i], &px, &py);
            if (!isfinite(px) || !isfinite(py)) {
                have = false;
                continue;
            }
            double t0, t1;
            if (have ? clip_segment(qx, qy, px, py, x0, y0, x1, y1, &t0, &t1)
                     : (px >= x0 && px <= x1 && py >= y0 && py <= y1))
                hits++;
            qx = px;
            qy = py;
            have = true;
        }
    }
    return hits;
}

static void draw_legend(sk_image *img, const sk__plot_frame *f, const sk_plot_series *series,
                        int count)
{
    const sk_plot_desc *d = &f->desc;
    const sk_plot_layout *l = &f->layout;
    if (d->legend == SK_LEGEND_NONE) return;
    int s = d->text_scale, th = f->text_h;
    int entries = 0, label_w = 0;
    int max_label = (int)((l->frame_x1 - l->frame_x0) / 2.0);
    char buf[512];
    for (int i = 0; i < count; i++) {
        if (!series[i].label || !series[i].label[0]) continue;
        entries++;
        int w = sk_draw_text_width(sk__text_fit(series[i].label, s, max_label, buf, sizeof buf), s);
        if (w > label_w) label_w = w;
    }
    if (entries == 0) return;
    int inner = 3 * s + 2, pitch = th + 3 * s, sample = 4 * f->char_w;
    double box_w = 2.0 * inner + sample + f->char_w + label_w;
    double box_h = 2.0 * inner + entries * pitch - 3 * s;
    double margin = 3 * s + 4;
    double fx0 = floor(l->frame_x0) + 1.0 + margin, fx1 = floor(l->frame_x1) - margin;
    double fy0 = floor(l->frame_y0) + 1.0 + margin, fy1 = floor(l->frame_y1) - margin;
    if (box_w > fx1 - fx0 || box_h > fy1 - fy0) return; /* no room inside the frame */
    /* Corners in order of preference: top right, top left, bottom right, bottom left. */
    double cx[4] = {fx1 - box_w, fx0, fx1 - box_w, fx0};
    double cy[4] = {fy0, fy0, fy1 - box_h, fy1 - box_h};
    int corner = 0;
    switch (d->legend) {
    case SK_LEGEND_TOP_LEFT:
        corner = 1;
        break;
    case SK_LEGEND_BOTTOM_RIGHT:
        corner = 2;
        break;
    case SK_LEGEND_BOTTOM_LEFT:
        corner = 3;
        break;
    case SK_LEGEND_TOP_RIGHT:
        corner = 0;
        break;
    default: {
        long long best = -1;
        for (int k = 0; k < 4; k++) {
            long long hits =
                legend_overlap(series, count, l, cx[k], cy[k], cx[k] + box_w, cy[k] + box_h);
            if (best < 0 || hits < best) {
                best = hits;
                corner = k;
            }
        }
    }
    }
    double x = cx[corner], y = cy[corner];
    sk_draw_rect(img, (float)x, (float)y, (float)box_w, (float)box_h, plot_legend_fill);
    hline(img, x, x + box_w - 1.0, y, plot_legend_border);
    hline(img, x, x + box_w - 1.0, y + box_h - 1.0, plot_legend_border);
    vline(img, x, y, y + box_h - 1.0, plot_legend_border);
    vline(img, x + box_w - 1.0, y, y + box_h - 1.0, plot_legend_border);
    double row_y = y + inner;
    for (int i = 0; i < count; i++) {
        if (!series[i].label || !series[i].label[0]) continue;
        double mid = row_y + 3.5 * s; /* the middle of a capital */
        sk_draw_line_capped(img, (float)(x + inner), (float)mid, (float)(x + inner + sample),
                            (float)mid, series_width(&series[i]), SK_CAP_BUTT,
                            series_color(&series[i], i));
        sk_draw_text(img, (float)(x + inner + sample + f->char_w), (float)row_y,
                     sk__text_fit(series[i].label, s, max_label, buf, sizeof buf), s, plot_text);
        row_y += pitch;
    }
}

sk_result sk_plot_lines(const sk_plot_series *series, int series_count, const sk_plot_desc *desc,
                        sk_image *out, sk_error *err)
{
    if (!out) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "plot: out is NULL");
    sk__plot_frame f;
    sk_result r = sk__plot_frame_compute(series, series_count, desc, &f, err);
    if (r != SK_OK) return r;
    const sk_plot_layout *l = &f.layout;
    int longest = 0;
    for (int i = 0; i < series_count; i++)
        if (series[i].count > longest) longest = series[i].count;
    /* A run gains at most one extra point per clipped segment. */
    sk_vec2f *buf = longest > 0 ? malloc(((size_t)longest * 2 + 2) * sizeof *buf) : NULL;
    if (longest > 0 && !buf)
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "plot: cannot allocate %d points", longest);
    sk_image img = {0};
    r = sk__image_alloc(&img, l->width, l->height, f.desc.channels, "plot", err);
    if (r != SK_OK) {
        free(buf);
        return r;
    }
    sk_draw_clear(&img, sk_rgba(1.0f, 1.0f, 1.0f, 1.0f));
    draw_axes(&img, &f);
    /* Series are clipped to the frame's pixels (the frame is drawn over their edges). */
    sk__clip area = {(int)floor(l->frame_x0), (int)floor(l->frame_y0), (int)floor(l->frame_x1) + 1,
                     (int)floor(l->frame_y1) + 1};
    for (int i = 0; i < series_count; i++)
        draw_series(&img, area, l, &series[i], series_color(&series[i], i),
                    series_width(&series[i]), buf);
    draw_frame(&img, l);
    draw_labels(&img, &f);
    draw_legend(&img, &f, series, series_count);
    free(buf);
    *out = img;
    return SK_OK;
}
