/* Private helpers of the tissue module's pictures (draw_*.c): fixed cameras, rendering
 * coloured meshes, cut-away meshes and points drawn as beads. */
#ifndef SK_TISSUE_DRAW_INTERNAL_H
#define SK_TISSUE_DRAW_INTERNAL_H

#include "shitsukan/mesh.h"
#include "models/tissue/tissue_internal.h"

typedef struct sk__view {
    sk_vec3d position, target, up;
    double fov_deg;
} sk__view;

typedef struct sk__render_item {
    const sk_mesh *mesh;
    float color[3]; /* linear albedo */
    float specular;
} sk__render_item;

/* A camera looking at the box [lo, hi] from `direction` (from the target towards the
 * eye), `up` up in the image, that shows all of it in an image of width / height = aspect. */
sk__view sk__view_framing(sk_vec3d lo, sk_vec3d hi, sk_vec3d direction, sk_vec3d up, double fov_deg,
                          double aspect);
/* Renders the meshes to a PNG (white ground, key and fill lights, a sky, with ambient
 * occlusion on request). */
sk_result sk__render_items(const sk__render_item *items, int count, const sk__view *view, int width,
                           int height, int samples, bool occlusion, const char *png_path,
                           sk_error *err);
/* A wedge cut out of a model: the points beyond both planes dot(p, n[k]) > offset[k]. */
typedef struct sk__wedge {
    sk_vec3d n[2];
    double offset[2];
} sk__wedge;
bool sk__in_wedge(const sk__wedge *w, const float *p);
/* The mesh without the triangles lying wholly in the wedge (into a new mesh). */
sk_result sk__mesh_cut(const sk_mesh *in, const sk__wedge *w, sk_mesh *out, sk_error *err);
/* Octahedra of `radius` at the cloud's points outside the wedge. */
sk_result sk__beads(const sk_mesh *cloud, double radius, const sk__wedge *w, sk_mesh *out,
                    sk_error *err);

/* The layers cut open, rendered to a PNG `width` pixels wide. */
sk_result sk__draw_layers(const sk_tissue_model *m, const char *png_path, int width, sk_error *err);

/* The tracked skin points over a run: their height (world Y, mm) with the fat layer and
 * carried by the bones alone, `samples` values each (point-major), at `time` (s). */
typedef struct sk__tracked_series {
    int count, samples;
    const char *name[SK_TISSUE_MAX_TRACKED];
    const float *time, *with_fat, *without_fat;
} sk__tracked_series;
sk_result sk__plot_tracked(const sk__tracked_series *t, const char *png_path, sk_error *err);

/* A fixed camera for a run whose skin stays inside [lo, hi]; writes the image aspect. */
sk__view sk__jiggle_view(sk_vec3d lo, sk_vec3d hi, double *aspect);
/* One frame of the skin, rendered. */
sk_result sk__render_skin(const sk_mesh *skin, const sk__view *view, int width, int height,
                          const char *png_path, sk_error *err);

#endif
