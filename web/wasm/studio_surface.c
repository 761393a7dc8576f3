/* The hand panel's skin surface (thesis 4.1: about 8000 triangles bound to the
 * skeleton): built once on the panel's skeleton, then deformed with the solved link
 * frames at every pose (rigid as the thesis, linear blend or dual quaternion skinning).
 * Its atlas (the UVs of the exported mesh, whose vertices along the seam are split) and
 * the baked skin texture put the skin module's microrelief on the hand. */
#include <stdlib.h>
#include <string.h>

#include "shitsukan/hand.h"
#include "shitsukan/skin.h"
#include "studio.h"

STUDIO_API sk_hand_surface *studio_surface_create(const studio_hand *h, int triangles,
                                                  sk_error *err)
{
    sk_hand_surface_desc d = {0};
    d.triangles = triangles;
    sk_hand_surface *s = NULL;
    if (sk_hand_surface_create(&s, studio_hand_skeleton(h), &d, err) != SK_OK) return NULL;
    return s;
}

STUDIO_API void studio_surface_destroy(sk_hand_surface *s) { sk_hand_surface_destroy(s); }
STUDIO_API int studio_surface_vertex_count(const sk_hand_surface *s)
{
    return (int)sk_hand_surface_mesh(s)->vertex_count;
}
STUDIO_API int studio_surface_triangle_count(const sk_hand_surface *s)
{
    return (int)sk_hand_surface_mesh(s)->triangle_count;
}
STUDIO_API const uint32_t *studio_surface_indices(const sk_hand_surface *s)
{
    return sk_hand_surface_mesh(s)->indices;
}

/* Positions and normals (vertex count x 3 each, mm) of the surface on the hand's last
 * pose; method 1 rigid, 2 linear blend, 3 dual quaternion (0 = the library's default). */
STUDIO_API void studio_surface_deform(const sk_hand_surface *s, const studio_hand *h, int method,
                                      float *positions, float *normals)
{
    sk_hand_surface_deform(s, studio_hand_frames(h), (sk_hand_skinning)method, positions, normals);
}

/* The atlas mesh of the relaxed surface (sk_hand_surface_export_mesh): vertex count, its
 * UVs (2 floats each, v up as in OBJ and glTF's flipped images) and triangles; each
 * vertex's surface vertex from studio_surface_export_map. */
STUDIO_API sk_mesh *studio_surface_atlas(const sk_hand_surface *s, sk_error *err)
{
    sk_mesh *m = calloc(1, sizeof *m);
    if (!m) {
        sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
        return NULL;
    }
    if (sk_hand_surface_export_mesh(s, NULL, NULL, false, m, err) != SK_OK) {
        free(m);
        return NULL;
    }
    return m;
}

STUDIO_API int studio_mesh_vertex_count(const sk_mesh *m) { return (int)m->vertex_count; }
STUDIO_API const float *studio_mesh_uvs(const sk_mesh *m) { return m->uvs; }
STUDIO_API const uint32_t *studio_mesh_indices(const sk_mesh *m) { return m->indices; }

STUDIO_API void studio_mesh_destroy(sk_mesh *m)
{
    if (!m) return;
    sk_mesh_free(m);
    free(m);
}

STUDIO_API const uint32_t *studio_surface_export_map(const sk_hand_surface *s)
{
    return sk_hand_surface_export_map(s, NULL);
}

static sk_result skin_of(const char *json, sk_skin **out, sk_error *err)
{
    *out = NULL;
    if (!json || !*json) return SK_OK;
    sk_skin_desc d;
    memset(&d, 0, sizeof d);
    sk_result r = studio_bind_json(json, &sk_skin_schema, &d, err);
    return r == SK_OK ? sk_skin_create(out, &d, err) : r;
}

/* Bakes the atlas's texture at size x size (sk_hand_texture_bake): the albedo (linear
 * RGB) and the normal map (0.5 n + 0.5) into `albedo` and `normal` (size x size x 3
 * floats each, top row first), with the microrelief of the skin presets `back_json` on
 * the back and `palm_json` on the palm (NULL or "" for none). */
STUDIO_API int studio_surface_texture(const sk_hand_surface *s, int size, const char *back_json,
                                      const char *palm_json, float *albedo, float *normal,
                                      sk_error *err)
{
    sk_skin *back, *palm = NULL;
    sk_result r = skin_of(back_json, &back, err);
    if (r == SK_OK) r = skin_of(palm_json, &palm, err);
    sk_image a = {0}, n = {0};
    if (r == SK_OK) {
        sk_hand_texture_desc d = {.size = size, .back_skin = back, .palm_skin = palm};
        r = sk_hand_texture_bake(s, &d, &a, &n, err);
    }
    if (r == SK_OK) {
        size_t floats = (size_t)size * (size_t)size * 3;
        memcpy(albedo, a.data, floats * sizeof(float));
        memcpy(normal, n.data, floats * sizeof(float));
    }
    sk_image_free(&a);
    sk_image_free(&n);
    sk_skin_destroy(back);
    sk_skin_destroy(palm);
    return (int)r;
}
