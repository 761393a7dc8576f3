/* Private pieces of the scan pipeline's pictures: an orthographic view with a depth
 * buffer that rasterises flat-shaded triangles and point splats (supersampled, then
 * reduced), and a colour per index. */
#ifndef SK_HAND_DRAW_SCAN_INTERNAL_H
#define SK_HAND_DRAW_SCAN_INTERNAL_H

#include "shitsukan/draw.h"
#include "shitsukan/hand.h"

#define SK_HAND__VIEW_SUPERSAMPLE 2

typedef struct sk__hand_view {
    sk_image image; /* RGB, supersampled */
    float *depth;   /* nearness (dot with `toward`); -inf = empty */
    sk_vec3d right, up, toward;
    double scale, ox, oy; /* pixel = (ox + scale * p.right, oy - scale * p.up) */
} sk__hand_view;

/* A view of width x height final pixels framing the box [lo, hi] (world) seen along
 * -toward with `up` up, with a margin of `margin` final pixels; background `bg`. */
sk_result sk__hand_view_create(sk__hand_view *v, int width, int height, sk_vec3d right, sk_vec3d up,
                               sk_vec3d lo, sk_vec3d hi, int margin, sk_color bg, sk_error *err);
void sk__hand_view_free(sk__hand_view *v);
/* A flat-shaded triangle (light from the viewer's upper left, both sides lit). */
void sk__hand_view_triangle(sk__hand_view *v, sk_vec3d a, sk_vec3d b, sk_vec3d c, sk_color color);
/* A square splat of `radius` final pixels. */
void sk__hand_view_point(sk__hand_view *v, sk_vec3d p, float radius, sk_color color);
/* Final-pixel position of a world point. */
sk_vec2f sk__hand_view_project(const sk__hand_view *v, sk_vec3d p);
/* Reduces the supersampled image into `out` (allocated). */
sk_result sk__hand_view_finish(sk__hand_view *v, sk_image *out, sk_error *err);

/* Bounds of a mesh's vertices (false if empty). */
bool sk__hand_mesh_bounds(const sk_mesh *m, sk_vec3d *lo, sk_vec3d *hi);
/* A distinct colour for index k (golden-ratio hues). */
sk_color sk__hand_index_color(int k);
/* The colour of a link: its finger's colour, lighter toward the tip. */
sk_color sk__hand_link_color(int link);
/* Stacks images side by side on a white ground with a title line above. */
sk_result sk__hand_panels(const sk_image *const *panels, int count, const char *title,
                          sk_image *out, sk_error *err);

#endif /* SK_HAND_DRAW_SCAN_INTERNAL_H */
