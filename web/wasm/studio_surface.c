/* The hand panel's skin surface (thesis 4.1: about 8000 triangles bound to the
 * skeleton): built once on the panel's skeleton, then deformed with the solved link
 * frames at every pose (rigid as the thesis, linear blend or dual quaternion skinning).
 * Built only when the library has the hand surface (SK_STUDIO_HAND_SURFACE). */
#include "shitsukan/hand.h"
#include "studio.h"

#ifdef SK_STUDIO_HAND_SURFACE

STUDIO_API sk_hand_surface *studio_surface_create(const studio_hand *h, int triangles, sk_error *err)
{
    sk_hand_surface_desc d = {0};
    d.triangles = triangles;
    sk_hand_surface *s = NULL;
    if (sk_hand_surface_create(&s, studio_hand_skeleton(h), &d, err) != SK_OK) return NULL;
    return s;
}

STUDIO_API void studio_surface_destroy(sk_hand_surface *s) { sk_hand_surface_destroy(s); }
STUDIO_API int studio_surface_vertex_count(const sk_hand_surface *s) { return (int)sk_hand_surface_mesh(s)->vertex_count; }
STUDIO_API int studio_surface_triangle_count(const sk_hand_surface *s) { return (int)sk_hand_surface_mesh(s)->triangle_count; }
STUDIO_API const uint32_t *studio_surface_indices(const sk_hand_surface *s) { return sk_hand_surface_mesh(s)->indices; }

/* Positions and normals (vertex count x 3 each, mm) of the surface on the hand's last
 * pose; method 1 rigid, 2 linear blend, 3 dual quaternion (0 = the library's default). */
STUDIO_API void studio_surface_deform(const sk_hand_surface *s, const studio_hand *h, int method, float *positions,
                                      float *normals)
{
    sk_hand_surface_deform(s, studio_hand_frames(h), (sk_hand_skinning)method, positions, normals);
}

#endif
