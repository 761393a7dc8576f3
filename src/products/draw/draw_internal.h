/* Private pieces shared by the draw module: clip rectangles, colour compositing, outline
 * paths, the coverage rasterizer, the tiled coverage mask, text and image allocation. */
#ifndef SK_DRAW_INTERNAL_H
#define SK_DRAW_INTERNAL_H

#include <math.h>
#include <stdbool.h>
#include <stddef.h>

#include "shitsukan/draw.h"

/* ------------------------------------------------------------------ clipping */
/* A half-open pixel rectangle [x0, x1) x [y0, y1). */
typedef struct sk__clip {
    int x0, y0, x1, y1;
} sk__clip;

/* True if img can be drawn into (non-NULL data, 1-4 channels, positive size). */
bool sk__image_valid(const sk_image *img);
/* The whole image as a clip rectangle. */
sk__clip sk__clip_image(const sk_image *img);
static inline bool sk__clip_empty(sk__clip c) { return c.x0 >= c.x1 || c.y0 >= c.y1; }
/* The clip rectangle intersected with the pixels touched by [x0, x1] x [y0, y1]
 * (double coordinates, possibly huge). */
sk__clip sk__clip_bounds(sk__clip clip, double x0, double y0, double x1, double y1);

static inline bool sk__color_finite(sk_color c)
{
    return isfinite(c.r) && isfinite(c.g) && isfinite(c.b) && isfinite(c.a);
}
static inline bool sk__color_is_zero(sk_color c)
{
    return c.r == 0.0f && c.g == 0.0f && c.b == 0.0f && c.a == 0.0f;
}
static inline float sk__luminance(sk_color c)
{
    /* Rec. 709 / sRGB primaries, applied to linear values. */
    return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b;
}

/* ---------------------------------------------------------------- compositing */
/* A colour prepared for one image's channel layout. */
typedef struct sk__paint {
    sk_image *img;
    int channels;
    float value[4]; /* the colour in the image's layout (sk__color_to_layout) */
    float alpha;    /* the colour's alpha, clamped to [0, 1] */
} sk__paint;

/* The colour in a channel layout: v[0..2] = grey, alpha, 0 (1-2 channels) or r, g, b
 * (3-4 channels); v[3] = alpha clamped to [0, 1]. A 2-channel pixel is v[0], v[1]. */
void sk__color_to_layout(sk_color c, int channels, float v[4]);
/* False (and nothing to draw) if the colour is not finite, fully transparent or the
 * image is invalid. */
bool sk__paint_init(sk__paint *paint, sk_image *img, sk_color c);
/* Composites the paint over pixels (x .. x+n-1, y) weighted by coverage[i] in [0, 1];
 * zero coverage leaves a pixel untouched. */
void sk__paint_span(const sk__paint *paint, int x, int y, int n, const float *coverage);
/* "Over" (Porter & Duff 1984) of a straight-alpha source value with alpha `a` into one
 * pixel of `channels` channels whose last channel is alpha if channels is 2 or 4:
 * alpha_out = a + alpha_dst (1 - a), colour_out = (c a + c_dst alpha_dst (1 - a)) / alpha_out. */
static inline void sk__composite_over(float *px, int channels, const float *src, float a)
{
    if (channels == 1 || channels == 3) {
        float keep = 1.0f - a;
        for (int k = 0; k < channels; k++) px[k] = src[k] * a + px[k] * keep;
        return;
    }
    int colors = channels - 1;
    float dst_w = px[colors] * (1.0f - a);
    float out_a = a + dst_w;
    if (out_a <= 0.0f) return;
    float inv = 1.0f / out_a;
    for (int k = 0; k < colors; k++) px[k] = (src[k] * a + px[k] * dst_w) * inv;
    px[colors] = out_a;
}

/* Receiver of rasterized coverage rows. */
typedef void (*sk__span_fn)(void *user, int x, int y, int n, const float *coverage);
/* An sk__span_fn that forwards to sk__paint_span (user = const sk__paint *). */
void sk__paint_span_fn(void *user, int x, int y, int n, const float *coverage);

/* ---------------------------------------------------------------------- paths */
/* A directed outline edge; double so that huge coordinates clip exactly. */
typedef struct sk__edge {
    double x0, y0, x1, y1;
} sk__edge;

/* A growing list of edges with a small inline store (no allocation for strokes and
 * small shapes). `failed` is set if growing it ran out of memory. */
#define SK__PATH_INLINE_EDGES 160
typedef struct sk__path {
    sk__edge *edges;
    int count, capacity;
    bool failed;
    double min_x, min_y, max_x, max_y;
    double start_x, start_y, last_x, last_y; /* current contour */
    bool open;
    sk__edge inline_edges[SK__PATH_INLINE_EDGES];
} sk__path;

void sk__path_init(sk__path *path);
void sk__path_free(sk__path *path);
/* Starts a new contour at (x, y) (closing the previous one). */
void sk__path_move_to(sk__path *path, double x, double y);
void sk__path_line_to(sk__path *path, double x, double y);
/* Closes the current contour back to its first point. */
void sk__path_close(sk__path *path);

/* Number of polygon vertices for a full circle of `radius` so that the polygon deviates
 * from the circle by at most 0.01 px (a multiple of 4 in 8..4096). */
int sk__circle_segments(double radius);
/* Radius of a regular n-gon with the same area as a circle of `radius`: flattened curves
 * keep the curve's exact area. */
double sk__area_preserving_radius(double radius, int segments);
/* Appends a closed circle contour; `clockwise` on screen (y down) or counter-clockwise. */
void sk__path_circle(sk__path *path, double cx, double cy, double radius, bool clockwise);
/* Appends the outline of a stroked segment (a closed convex contour). Returns false if
 * there is nothing to draw (zero length with butt caps). */
bool sk__path_stroke_segment(sk__path *path, double x0, double y0, double x1, double y1,
                             double width, sk_line_cap cap);

/* ----------------------------------------------------------------- rasterizer */
/* Rasterizes the path's closed contours with exact area coverage, restricted to clip,
 * and hands each covered row to `emit` (coverage already mapped by the fill rule to
 * [0, 1]). Rows are emitted top to bottom within column tiles. */
void sk__raster_fill(const sk__path *path, sk_fill_rule rule, sk__clip clip, sk__span_fn emit,
                     void *user);
/* Fills the path with the paint, clipped to clip. */
void sk__fill_path(const sk__paint *paint, const sk__path *path, sk_fill_rule rule, sk__clip clip);

/* sk_draw_polyline restricted to a clip rectangle (the plot area, for example). */
void sk__draw_polyline_clip(sk_image *img, sk__clip clip, const sk_vec2f *pts, int n, bool closed,
                            float width, sk_color c);

/* ---------------------------------------------------------- coverage mask */
/* A sparse coverage mask over a clip rectangle, stored in lazily allocated 32 x 32
 * tiles that remember the part of them written to. Shapes rasterized into it combine by
 * max, so overlapping pieces of one stroke are composited once. */
typedef struct sk__mask_tile {
    float *coverage;      /* NULL until written */
    short x0, y0, x1, y1; /* written part, half-open, tile-local */
} sk__mask_tile;

typedef struct sk__mask {
    sk__clip bounds;
    int tiles_x, tiles_y;
    sk__mask_tile *tiles;
    bool failed; /* an allocation failed: the mask is incomplete */
} sk__mask;

/* False if the tile directory cannot be allocated. */
bool sk__mask_init(sk__mask *mask, sk__clip bounds);
/* An sk__span_fn taking the max of the mask and the coverage (user = sk__mask *). */
void sk__mask_span_fn(void *user, int x, int y, int n, const float *coverage);
/* Composites the paint weighted by the mask's coverage. */
void sk__mask_paint(const sk__mask *mask, const sk__paint *paint);
void sk__mask_free(sk__mask *mask);

/* ----------------------------------------------------------------------- text */
#define SK__GLYPH_WIDTH 5
#define SK__GLYPH_HEIGHT 9
#define SK__GLYPH_ADVANCE 6
#define SK__MAX_TEXT_SCALE 64

/* The character code starting at *text (-1 for a byte outside ASCII: a UTF-8 sequence
 * counts as one character), advancing *text past it. *text must not be at the NUL. */
int sk__glyph_code_next(const char **text);
/* The 9 rows of the glyph of `code`, bit (4 - col) of row r set where it has ink;
 * codes outside 32..126 give the replacement glyph (a hollow box). */
void sk__glyph_rows(int code, unsigned char rows[SK__GLYPH_HEIGHT]);
/* Number of glyphs the text draws (0 for NULL). */
long long sk__text_glyph_count(const char *text);

/* Text direction for sk__draw_text_dir. */
typedef enum sk__text_dir {
    SK__TEXT_RIGHT = 0, /* normal, left to right */
    SK__TEXT_UP         /* rotated a quarter turn counter-clockwise: reads bottom to top;
                           (x, y) is still the top-left of the (rotated) box */
} sk__text_dir;

/* sk_draw_text with a direction and a clip rectangle. */
int sk__draw_text_dir(sk_image *img, sk__clip clip, float x, float y, const char *text, int scale,
                      sk__text_dir dir, sk_color c);
/* Copies text into buf, shortened with "..." if needed so that it is at most max_width
 * pixels wide at `scale`. Returns buf. */
const char *sk__text_fit(const char *text, int scale, int max_width, char *buf, size_t size);

/* ----------------------------------------------------------------------- plots */
/* A plot's layout with the resolved desc and the spacing it was built with. */
typedef struct sk__plot_frame {
    sk_plot_layout layout;
    sk_plot_desc desc; /* resolved */
    int pad;           /* outer margin */
    int gap;           /* between a tick and its label, between text lines */
    int tick_len;
    int text_h, char_w; /* text box height and glyph advance at desc.text_scale */
} sk__plot_frame;

/* Validates the inputs and computes the layout (sk_plot_compute_layout's work). */
sk_result sk__plot_frame_compute(const sk_plot_series *series, int series_count,
                                 const sk_plot_desc *desc, sk__plot_frame *frame, sk_error *err);
/* Data point i of a series (x = i when the series has no x array). */
static inline double sk__series_x(const sk_plot_series *s, int i)
{
    return s->x ? (double)s->x[i] : (double)i;
}

/* ---------------------------------------------------------- image allocation */
/* Allocates a zero-filled width x height x channels image with malloc (caps
 * SK_IMAGE_MAX_DIMENSION / SK_IMAGE_MAX_BYTES checked overflow-safely); `what` names the
 * output in error messages. */
sk_result sk__image_alloc(sk_image *img, int width, int height, int channels, const char *what,
                          sk_error *err);
/* Checks an input image (non-NULL data, 1..4 channels, size within the caps). */
sk_result sk__image_check(const sk_image *img, const char *name, sk_error *err);

#endif /* SK_DRAW_INTERNAL_H */
