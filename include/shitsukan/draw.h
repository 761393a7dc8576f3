/* shitsukan draw: anti-aliased 2D raster drawing on float images (rects, lines,
 * polylines, circles, polygons, bitmap text), blits and resizing, and two figure
 * builders: contact sheets (tiles + labels in a grid) and line plots with axes.
 *
 * Conventions shared by every function here:
 * - Colours are linear RGBA floats with straight (not premultiplied) alpha. Drawing
 *   composites "over" the image: the colour's alpha times the pixel coverage is the
 *   blend weight. Images hold straight alpha too (as PNG does).
 * - Channel layouts (sk_image): 1 = grey (the colour's luminance
 *   0.2126 R + 0.7152 G + 0.0722 B is drawn), 2 = grey + alpha, 3 = RGB, 4 = RGBA; an
 *   alpha channel is composited too (alpha_out = a + alpha_dst (1 - a)).
 * - Coordinates are pixels: pixel (x, y) covers [x, x+1) x [y, y+1), so its centre is at
 *   (x + 0.5, y + 0.5); y grows downwards (top row first).
 * - Anti-aliasing is exact area coverage (a box filter over each pixel), computed
 *   analytically from the shape's outline; curves are flattened to polygons with at most
 *   0.01 px deviation (for radii up to 30000 px) and with the exact area of the curve.
 *   Where one outline overlaps itself the coverage is clamped (see sk_draw_polygon).
 *   Results are deterministic.
 * - Everything clips to the image; work is bounded by the primitive's clipped bounding
 *   box. A primitive with a NaN or infinite coordinate, size or colour component is
 *   skipped, as is an image with a NULL pointer or invalid size.
 *
 * Thread-safety: every function is thread-safe on distinct images (no shared state). */
#ifndef SHITSUKAN_DRAW_H
#define SHITSUKAN_DRAW_H

#include "shitsukan/core.h"
#include "shitsukan/image.h"
#include "shitsukan/vecmath.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ------------------------------------------------------------------ colours */
typedef struct sk_color {
    float r, g, b, a;
} sk_color;

static inline sk_color sk_rgba(float r, float g, float b, float a)
{
    sk_color c = {r, g, b, a};
    return c;
}
static inline sk_color sk_rgb(float r, float g, float b) { return sk_rgba(r, g, b, 1.0f); }

/* A qualitative palette of 8 colour-blind-safe colours (Okabe & Ito 2008, "Color
 * Universal Design"), ordered for line plots on white: blue, vermillion, bluish green,
 * reddish purple, orange, sky blue, black, yellow. Linear RGB, opaque. The index wraps
 * (negative indices too). */
sk_color sk_palette(int index);
#define SK_PALETTE_SIZE 8

/* --------------------------------------------------------------- primitives */

/* Composites `c` over every pixel (with c.a = 1 this sets the image to c). */
void sk_draw_fill(sk_image *img, sk_color c);
/* Sets every pixel to `c` (no blending; the alpha channel, if any, becomes c.a). */
void sk_draw_clear(sk_image *img, sk_color c);

/* Filled axis-aligned rectangle [x, x+w) x [y, y+h); edge pixels get their exact
 * fractional coverage. Negative w or h extend left / up from (x, y). */
void sk_draw_rect(sk_image *img, float x, float y, float w, float h, sk_color c);

typedef enum sk_line_cap {
    SK_CAP_DEFAULT = 0, /* = SK_CAP_ROUND */
    SK_CAP_ROUND,       /* a half disc of diameter `width` beyond each end */
    SK_CAP_BUTT,        /* the stroke ends exactly at the end points */
    SK_CAP_SQUARE       /* the stroke extends width/2 beyond each end */
} sk_line_cap;

/* A straight stroke of `width` pixels centred on the segment, with ROUND caps (so
 * segments drawn one by one join seamlessly). A zero-length line with round caps is a
 * disc of diameter `width`. width <= 0 draws nothing. */
void sk_draw_line(sk_image *img, float x0, float y0, float x1, float y1, float width, sk_color c);
void sk_draw_line_capped(sk_image *img, float x0, float y0, float x1, float y1, float width,
                         sk_line_cap cap, sk_color c);

/* A stroke through n points with round joins and (if open) round caps. The whole stroke
 * is composited once: where its segments overlap (at joins, or where it crosses itself)
 * each pixel takes the largest coverage of any segment, never the sum, so a translucent
 * polyline has no darker knots. `closed` joins the last point back to the first.
 * A single point draws a disc of diameter `width`. A point with a NaN or infinite
 * coordinate breaks the line (its segments are left out; a finite point left without
 * neighbours shows as a disc). */
void sk_draw_polyline(sk_image *img, const sk_vec2f *pts, int n, bool closed, float width,
                      sk_color c);

/* A ring of stroke `width` centred on the circle of `radius` (inner radius
 * radius - width/2, outer radius + width/2; a disc if the inner radius is <= 0). */
void sk_draw_circle(sk_image *img, float cx, float cy, float radius, float width, sk_color c);
/* A filled disc; radius <= 0 draws nothing. */
void sk_draw_disc(sk_image *img, float cx, float cy, float radius, sk_color c);

typedef enum sk_fill_rule {
    SK_FILL_DEFAULT = 0, /* = SK_FILL_NONZERO */
    SK_FILL_NONZERO,     /* inside where the winding number is not 0 */
    SK_FILL_EVEN_ODD     /* inside where the winding number is odd */
} sk_fill_rule;

/* A filled polygon (closed automatically), any orientation, convex or concave, with the
 * NON-ZERO winding rule. Coverage is exact where the outline does not cross itself; in
 * pixels where two self-crossing parts of the outline meet, the coverage of the
 * overlapping parts is clamped (a close approximation). */
void sk_draw_polygon(sk_image *img, const sk_vec2f *pts, int n, sk_color c);
/* Several closed contours filled together by `rule` (holes: a contour inside another,
 * with opposite orientation for NONZERO or any orientation for EVEN_ODD).
 * counts[i] points of contour i follow each other in pts. */
void sk_draw_contours(sk_image *img, const sk_vec2f *pts, const int *counts, int contour_count,
                      sk_fill_rule rule, sk_color c);

/* --------------------------------------------------------------------- text */
/* Text in a built-in bitmap font: each printable ASCII character (32-126) is a 5 x 9 grid
 * (capitals and digits 7 high, descenders 2 below) in a 6-pixel-wide cell, scaled by the
 * integer `scale` (clamped to [1, 64]). (x, y) is the top-left corner of the text's box,
 * which is sk_draw_text_width(text, scale) wide and sk_draw_text_height(scale) high: the
 * tops of capitals touch its top edge, descenders its bottom edge, and no ink falls
 * outside it. Any other byte (a UTF-8 sequence counts as one) draws a hollow box.
 * Fractional positions are anti-aliased. Returns the width of the box (0 for NULL or "");
 * text that continues on the same line starts one gap later, at x + width + scale. */
int sk_draw_text(sk_image *img, float x, float y, const char *text, int scale, sk_color c);
/* Width of the text's box: 6 * scale per character minus the trailing 1 * scale gap. */
int sk_draw_text_width(const char *text, int scale);
/* Height of the text's box: 9 * scale. A comfortable line pitch is 12 * scale. */
int sk_draw_text_height(int scale);

/* ---------------------------------------------------------- blit and resize */
typedef enum sk_blit_mode {
    SK_BLIT_DEFAULT = 0, /* OVER if src has an alpha channel (2 or 4 channels), else COPY */
    SK_BLIT_COPY,        /* dst pixels become src pixels (alpha copied, or 1 if src has none) */
    SK_BLIT_OVER         /* src composited over dst with src's alpha */
} sk_blit_mode;

/* Copies src into dst with its top-left at (x, y), clipped to dst, converting channels:
 * grey -> RGB repeats the grey, RGB -> grey takes the luminance, a missing source alpha
 * is 1, a missing destination alpha is dropped (after compositing). */
void sk_draw_blit(sk_image *dst, const sk_image *src, int x, int y);
void sk_draw_blit_mode(sk_image *dst, const sk_image *src, int x, int y, sk_blit_mode mode);

typedef enum sk_resize_filter {
    SK_RESIZE_DEFAULT = 0, /* per axis: BOX when shrinking, BILINEAR when enlarging */
    SK_RESIZE_NEAREST,     /* the source pixel whose centre is nearest */
    SK_RESIZE_BILINEAR,    /* linear interpolation between pixel centres, edges clamped */
    SK_RESIZE_BOX          /* the exact area average of the source pixels covered */
} sk_resize_filter;

/* Resizes src into a newly allocated image of width x height with src's channel count
 * (free it with free(out->data) or sk_image_free). Fails with SK_ERROR_INVALID_ARGUMENT
 * for a bad source or size < 1, SK_ERROR_LIMIT beyond SK_IMAGE_MAX_DIMENSION or
 * SK_IMAGE_MAX_BYTES. Alpha is not premultiplied: colour and alpha are filtered alike. */
sk_result sk_image_resize(const sk_image *src, int width, int height, sk_image *out, sk_error *err);
sk_result sk_image_resize_filter(const sk_image *src, int width, int height,
                                 sk_resize_filter filter, sk_image *out, sk_error *err);

/* ----------------------------------------------------------- contact sheet */
typedef enum sk_label_position {
    SK_LABEL_DEFAULT = 0, /* = SK_LABEL_BELOW */
    SK_LABEL_BELOW,
    SK_LABEL_ABOVE
} sk_label_position;

typedef struct sk_contact_sheet_desc {
    int columns;         /* 0 = ceil(sqrt(count)); range 0..4096 (at most count are used) */
    int tile_size;       /* 0 = each tile at its own size, cells sized to the largest tile;
                            > 0 = each tile scaled (aspect kept) to fit tile_size x tile_size;
                            range 0..16384 */
    int padding;         /* pixels around and between cells; 0 = 8; range 0..1024 */
    int text_scale;      /* label text scale; 0 = 2; range 0..64 */
    int title_scale;     /* title text scale; 0 = text_scale + 1; range 0..64 */
    const char *title;   /* NULL or "" = no title line */
    sk_color background; /* all zero = white {1, 1, 1, 1}; for a transparent sheet use a
                            tiny alpha such as {0, 0, 0, 1e-9f} with channels = 4 */
    sk_color text_color; /* all zero = black {0, 0, 0, 1} */
    int channels;        /* output channels 1..4; 0 = 3 */
    sk_label_position label_position; /* 0 = labels below the tiles */
    int tile_border;              /* width in pixels of a thin frame drawn around each tile (in the
                                     padding, half-transparent text_color), so pale tiles stand out
                                     from the background; 0 = none; range 0..64 */
    sk_resize_filter tile_filter; /* how tiles are scaled to tile_size; 0 = box when
                                     shrinking, bilinear when enlarging; NEAREST keeps
                                     hard pixels (masks, cell maps) */
} sk_contact_sheet_desc;

/* The desc with every zero field replaced by its default (columns needs `count`). */
sk_contact_sheet_desc sk_contact_sheet_desc_resolved(const sk_contact_sheet_desc *desc, int count);

/* Lays out `count` tiles (any sizes and channel counts; alpha is composited over the
 * background) in a grid of `columns`, row by row. Every cell has the same tile area,
 * tile_w x tile_h = the largest shown tile width and height (tiles are centred in it),
 * and the same width cell_w = max(tile_w, widest label + 6 * text_scale), so no label is
 * ever cut. Labels are centred under (or over) their tiles, the optional title is
 * centred above the grid. The sheet is
 *   width  = max(padding + columns * (cell_w + padding), title_width + 2 * padding)
 *   height = padding + [title_height + padding]
 *            + rows * (tile_h + [text_height + ceil(padding / 2)] + padding)
 * where the label band [..] is there only if some label is given and the grid is
 * centred horizontally. `labels` may be NULL, and any label may be NULL. The output is
 * allocated (free with free(out->data) or sk_image_free).
 * Errors name the field: count 1..65536, a NULL or invalid tile, desc fields out of
 * range (SK_ERROR_INVALID_ARGUMENT), a sheet over SK_IMAGE_MAX_DIMENSION or
 * SK_IMAGE_MAX_BYTES (SK_ERROR_LIMIT). `desc` may be NULL. */
sk_result sk_contact_sheet(const sk_image *const *tiles, const char *const *labels, int count,
                           const sk_contact_sheet_desc *desc, sk_image *out, sk_error *err);

/* ----------------------------------------------------------------- plots */
/* Round tick values for an axis: value(i) = (first_index + i) * step for i < count, with
 * step = 1, 2 or 5 x 10^k. */
typedef struct sk_ticks {
    double step;
    long long first_index;
    int count;
    int decimals; /* digits after the point that print every tick value exactly */
} sk_ticks;

/* The ticks inside [lo, hi] with the smallest round step giving at most max_count ticks
 * (max_count >= 2; lo < hi, both finite; otherwise count = 0). */
sk_ticks sk_nice_ticks(double lo, double hi, int max_count);
static inline double sk_ticks_value(const sk_ticks *t, int i)
{
    return (double)(t->first_index + i) * t->step;
}
/* Formats tick value i into buf with `decimals` digits ("-0" never appears); axes with
 * values of 1e7 or more, or steps below 1e-6, share one exponent: "1.5e7", "2.0e7". */
void sk_ticks_format(const sk_ticks *t, int i, char *buf, size_t size);

/* One data series. x may be NULL (x = 0, 1, 2, ...). A NaN (or infinite) x or y breaks
 * the line there. color all zero = sk_palette(series index); width 0 = 2 px. */
typedef struct sk_plot_series {
    const char *label; /* NULL or "" = not in the legend */
    const float *x;
    const float *y;
    int count;
    sk_color color;
    float width; /* pixels, 0 = 2; range 0..64 */
} sk_plot_series;

typedef enum sk_legend_position {
    SK_LEGEND_DEFAULT = 0, /* = SK_LEGEND_AUTO */
    SK_LEGEND_AUTO,        /* the inside corner covering the fewest data points */
    SK_LEGEND_NONE,
    SK_LEGEND_TOP_RIGHT,
    SK_LEGEND_TOP_LEFT,
    SK_LEGEND_BOTTOM_RIGHT,
    SK_LEGEND_BOTTOM_LEFT
} sk_legend_position;

typedef struct sk_plot_desc {
    int width, height;                     /* 0 = 800 x 500; range 0 or 64..16384 */
    const char *title, *x_label, *y_label; /* NULL = none */
    bool fixed_x, fixed_y;            /* false = auto range from the data: x spans the data rounded
                                         out to ticks; y spans the data plus a 3% margin on each
                                         side, rounded out to half ticks; true = [min, max] below */
    float x_min, x_max, y_min, y_max; /* used when fixed; finite, min < max */
    int text_scale;                   /* 0 = 2; range 0..16 (the title is drawn one scale larger) */
    int channels;                     /* output channels 1..4; 0 = 3 */
    bool hide_grid;                   /* false = light grid lines at the ticks */
    sk_legend_position legend;        /* 0 = auto corner (only if some series has a label) */
} sk_plot_desc;

/* The desc with zero fields replaced by their defaults. */
sk_plot_desc sk_plot_desc_resolved(const sk_plot_desc *desc);

/* Where a plot puts things: the frame (plot area border) in pixel coordinates and the
 * axes. Data (x_min, y_min) maps to (frame_x0, frame_y1), (x_max, y_max) to
 * (frame_x1, frame_y0); the frame lines run along those pixel centres. */
typedef struct sk_plot_layout {
    int width, height;
    float frame_x0, frame_y0, frame_x1, frame_y1;
    double x_min, x_max, y_min, y_max;
    sk_ticks x_ticks, y_ticks;
} sk_plot_layout;

static inline sk_vec2f sk_plot_map(const sk_plot_layout *l, double x, double y)
{
    double u = (x - l->x_min) / (l->x_max - l->x_min);
    double v = (y - l->y_min) / (l->y_max - l->y_min);
    return sk_v2f((float)(l->frame_x0 + u * (l->frame_x1 - l->frame_x0)),
                  (float)(l->frame_y1 - v * (l->frame_y1 - l->frame_y0)));
}

/* Computes the layout sk_plot_lines would use (to place annotations on a plot). */
sk_result sk_plot_compute_layout(const sk_plot_series *series, int series_count,
                                 const sk_plot_desc *desc, sk_plot_layout *layout, sk_error *err);

/* Draws the series as anti-aliased lines on shared axes with round ticks, tick labels,
 * axis labels, a title, a legend and a grid, into a newly allocated image (free with
 * free(out->data) or sk_image_free). series_count may be 0 (empty axes). Errors name the
 * field and range (e.g. "series[2].count = -1 is out of range [0, 100000000]");
 * SK_ERROR_LIMIT if the text leaves no room for the plot area. `desc` may be NULL. */
sk_result sk_plot_lines(const sk_plot_series *series, int series_count, const sk_plot_desc *desc,
                        sk_image *out, sk_error *err);

#ifdef __cplusplus
}
#endif

#endif /* SHITSUKAN_DRAW_H */
