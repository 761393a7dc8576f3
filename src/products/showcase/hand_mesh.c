/* The hand's skin surface in the showcase (Yasumuro 2000, sec. 4.1, through the hand
 * module): built or shared, its texture baked with the skin microrelief, the flesh's
 * radius around each link measured on it, and each frame's posed mesh (dual quaternion
 * skinning, the atlas UVs) placed in the scene. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "products/showcase/showcase_internal.h"

#define TIP_REACH_MM 12.0 /* the pad: flesh within this of the fingertip along the link */

sk_result sk__hand_mesh_setup(sk_showcase *sc, sk_error *err)
{
    sk_result r = SK_OK;
    if (sc->desc.surface) {
        sc->surface = sc->desc.surface;
    } else {
        sk_hand_surface_desc sd = {0};
        sd.triangles = sc->desc.hand_triangles;
        r = sk_hand_surface_create(&sc->own_surface, &sc->skeleton, &sd, err);
        if (r != SK_OK) return sk_error_prefix(err, r, "hand surface");
        sc->surface = sc->own_surface;
    }
    const sk_mesh *mesh = sk_hand_surface_mesh(sc->surface);
    size_t n = mesh->vertex_count;
    sc->positions = malloc(3 * n * sizeof *sc->positions);
    sc->normals = malloc(3 * n * sizeof *sc->normals);
    if (!sc->positions || !sc->normals)
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for the hand mesh");
    /* flesh radii in the relaxed posture (the surface's bind pose) */
    double dofs[SK_HAND_DOF_COUNT];
    sk_hand_relaxed(&sc->skeleton, dofs);
    sk_hand_frames frames;
    sk_hand_forward(&sc->skeleton, dofs, &frames);
    const uint16_t *links;
    const float *weights;
    sk_hand_surface_weights(sc->surface, SK_HAND_WEIGHTS_SMOOTH, &links, &weights);
    double tip[5] = {0};
    for (size_t v = 0; v < n; v++) {
        int l = links[4 * v];
        if (l <= 0 || l >= SK_HAND_LINK_COUNT) continue;
        const sk_mat3d *rot = &frames.rotation[l];
        sk_vec3d base = frames.point[sk_hand_link_point(l)];
        double d[3] = {mesh->positions[3 * v] - base.x, mesh->positions[3 * v + 1] - base.y,
                       mesh->positions[3 * v + 2] - base.z};
        double lx = d[0] * rot->m[0][0] + d[1] * rot->m[1][0] + d[2] * rot->m[2][0];
        double ly = d[0] * rot->m[0][1] + d[1] * rot->m[1][1] + d[2] * rot->m[2][1];
        double lz = d[0] * rot->m[0][2] + d[1] * rot->m[1][2] + d[2] * rot->m[2][2];
        double radial = sqrt(lx * lx + lz * lz);
        if (radial > sc->link_radius[l]) sc->link_radius[l] = radial;
        for (int f = 0; f < 5; f++)
            if (l == sk__distal_link(f) && ly > sc->skeleton.length[l] - TIP_REACH_MM &&
                radial > tip[f])
                tip[f] = radial;
    }
    bool given = false;
    for (int f = 0; f < 5; f++) given = given || sc->desc.performance.tip_radius_mm[f] != 0;
    for (int f = 0; f < 5 && !given; f++) sc->desc.performance.tip_radius_mm[f] = tip[f];
    /* the texture */
    if (sc->desc.skin_albedo && sc->desc.skin_normal) {
        sc->skin_albedo = sc->desc.skin_albedo;
        sc->skin_normal = sc->desc.skin_normal;
        return SK_OK;
    }
    sk_hand_texture_desc td = {0};
    td.size = sc->desc.texture_size;
    td.back_skin = sc->desc.back_skin;
    td.palm_skin = sc->desc.palm_skin;
    r = sk_hand_texture_bake(sc->surface, &td, &sc->own_albedo, &sc->own_normal, err);
    if (r != SK_OK) return sk_error_prefix(err, r, "hand texture");
    sc->skin_albedo = &sc->own_albedo;
    sc->skin_normal = &sc->own_normal;
    return SK_OK;
}

void sk__hand_mesh_free(sk_showcase *sc)
{
    sk_hand_surface_destroy(sc->own_surface);
    sk_image_free(&sc->own_albedo);
    sk_image_free(&sc->own_normal);
    free(sc->positions);
    free(sc->normals);
}

sk_result sk__hand_mesh_posed(sk_showcase *sc, const sk_hand_frames *frames, sk_mesh *out,
                              sk_error *err)
{
    sk_hand_surface_deform(sc->surface, frames, SK_HAND_SKINNING_DQS, sc->positions, sc->normals);
    sk_result r =
        sk_hand_surface_export_mesh(sc->surface, sc->positions, sc->normals, false, out, err);
    if (r != SK_OK) return r;
    for (size_t v = 0; v < out->vertex_count; v++) { /* into the scene */
        float *p = out->positions + 3 * v;
        sk_vec3d q = sk__hand_to_scene((sk_vec3d){p[0], p[1], p[2]});
        p[0] = (float)q.x, p[1] = (float)q.y, p[2] = (float)q.z;
        if (out->normals) {
            float *nm = out->normals + 3 * v;
            sk_vec3d m = sk__hand_to_scene((sk_vec3d){nm[0], nm[1], nm[2]});
            nm[0] = (float)m.x, nm[1] = (float)m.y, nm[2] = (float)m.z;
        }
    }
    return SK_OK;
}
