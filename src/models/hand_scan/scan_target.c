/* What the simulated range scanner of thesis 4.1.1 sees: a closed triangle mesh in a ray
 * hierarchy, optionally with the implicit surface it was meshed from, onto which ray hits
 * are refined so that the scans sample the smooth surface and not its facets. */
#include <stdlib.h>
#include <string.h>

#include "models/hand_scan/scan_internal.h"

sk_result sk_hand_scan_target_create(sk_hand_scan_target **out,
                                     const sk_hand_scan_target_desc *desc, sk_error *err)
{
    *out = NULL;
    if (!desc || !desc->mesh)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "scan target: no mesh given");
    const sk_mesh *m = desc->mesh;
    sk_result r = sk_mesh_validate(m, err);
    if (r != SK_OK) return r;
    if (m->triangle_count == 0)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "scan target: the mesh has no triangles (a point cloud)");
    if (m->triangle_count > (1u << 26))
        return sk_fail(err, SK_ERROR_LIMIT, "scan target: %zu triangles (at most 2^26)",
                       m->triangle_count);
    sk_hand_scan_target *t = calloc(1, sizeof *t);
    sk_vec3d(*tri)[3] = malloc(sizeof *tri * m->triangle_count);
    if (!t || !tri) {
        free(t), free(tri);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "scan target");
    }
    for (size_t i = 0; i < m->triangle_count; i++)
        for (int v = 0; v < 3; v++) {
            const float *p = m->positions + 3 * (size_t)m->indices[3 * i + (size_t)v];
            tri[i][v] = sk_v3d(p[0], p[1], p[2]);
        }
    r = sk__triangle_bvh_build(&t->bvh, (const sk_vec3d(*)[3])tri, (uint32_t)m->triangle_count,
                               err);
    free(tri);
    if (r != SK_OK) {
        free(t);
        return r;
    }
    for (int k = 0; k < 3; k++) t->lo[k] = t->bvh.nodes[0].lo[k], t->hi[k] = t->bvh.nodes[0].hi[k];
    t->sdf = desc->sdf;
    t->sdf_user = desc->sdf_user;
    *out = t;
    return SK_OK;
}

void sk_hand_scan_target_destroy(sk_hand_scan_target *target)
{
    if (!target) return;
    sk__triangle_bvh_free(&target->bvh);
    free(target);
}

double sk_hand_scan_target_distance(const sk_hand_scan_target *target, sk_vec3d p)
{
    if (target->sdf) {
        sk_vec3d g;
        double f = target->sdf(target->sdf_user, p, &g);
        double gl = sk_v3d_length(g);
        /* first-order distance: exact for a true distance field (|g| = 1), and still close
           where blending makes the field's slope differ from 1 */
        return fabs(f) / (gl > 1e-12 ? gl : 1.0);
    }
    return sqrt(sk__triangle_bvh_nearest(&target->bvh, p, INFINITY, NULL));
}

bool sk_hand_scan_target_raycast(const sk_hand_scan_target *target, sk_vec3d o, sk_vec3d d,
                                 double t_min, double t_max, double *t, sk_vec3d *normal)
{
    sk__triangle_hit hit;
    if (!sk__triangle_bvh_intersect(&target->bvh, o, d, t_min, t_max, &hit)) return false;
    if (t) *t = hit.t;
    if (normal) {
        sk_vec3d n = sk__triangle_bvh_normal(&target->bvh, hit.triangle);
        *normal = sk_v3d_dot(n, d) > 0.0 ? sk_v3d_scale(n, -1.0) : n;
    }
    return true;
}

bool sk__hand_target_refine(const sk_hand_scan_target *target, sk_vec3d o, sk_vec3d d,
                            double t_mesh, double *t)
{
    if (!target->sdf) return false;
    /* secant steps on f(o + t d) from the mesh's hit: the field's value only, no gradient
       (a field whose gradient is itself found by differences costs six values more) */
    double dl = sk_v3d_length(d), h = 0.02 / dl;
    double t0 = t_mesh,
           f0 = target->sdf(target->sdf_user, sk_v3d_add(o, sk_v3d_scale(d, t0)), NULL);
    double t1 = t_mesh + h,
           f1 = target->sdf(target->sdf_user, sk_v3d_add(o, sk_v3d_scale(d, t1)), NULL);
    for (int k = 0; k < 10; k++) {
        if (fabs(f0) < 1e-7) { /* far below the depth step and the surface's own accuracy */
            *t = t0;
            return true;
        }
        if (f1 == f0) return false; /* the ray grazes the implicit surface */
        double t2 = t1 - f1 * (t1 - t0) / (f1 - f0);
        if (fabs(t2 - t_mesh) * dl > 2.0) return false; /* wandered off to another sheet */
        t0 = t1, f0 = f1;
        t1 = t2, f1 = target->sdf(target->sdf_user, sk_v3d_add(o, sk_v3d_scale(d, t1)), NULL);
        if (fabs(t1 - t0) * dl < 1e-6) {
            *t = t1;
            return true;
        }
    }
    return false;
}

static double surface_sdf(void *user, sk_vec3d p, sk_vec3d *gradient)
{
    const sk_hand_surface *s = user;
    if (gradient) *gradient = sk_hand_surface_field_gradient(s, p);
    return sk_hand_surface_field(s, p);
}

sk_result sk_hand_scan_target_from_surface(sk_hand_scan_target **out,
                                           const sk_hand_surface *surface, sk_error *err)
{
    sk_hand_scan_target_desc d = {
        .mesh = sk_hand_surface_mesh(surface), .sdf = surface_sdf, .sdf_user = (void *)surface};
    return sk_hand_scan_target_create(out, &d, err);
}

sk_result sk_hand_scan_cast(const sk_hand_skeleton *skeleton, const double dofs[SK_HAND_DOF_COUNT],
                            const sk_hand_surface_desc *surface_desc,
                            sk_hand_skeleton *cast_skeleton, sk_hand_surface **surface,
                            sk_hand_scan_target **target, sk_error *err)
{
    *surface = NULL;
    *target = NULL;
    for (int i = 0; i < SK_HAND_DOF_COUNT; i++)
        if (!isfinite(dofs[i]))
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "pose: %s is not a finite number",
                           sk_hand_dof(i)->name);
    /* the surface is meshed around its skeleton's relaxed posture: make the cast's pose it */
    *cast_skeleton = *skeleton;
    for (int i = 0; i < SK_HAND_DOF_COUNT; i++) cast_skeleton->dof[i].relaxed = dofs[i];
    sk_result r = sk_hand_surface_create(surface, cast_skeleton, surface_desc, err);
    if (r == SK_OK) r = sk_hand_scan_target_from_surface(target, *surface, err);
    if (r != SK_OK) {
        sk_hand_surface_destroy(*surface);
        *surface = NULL;
    }
    return r;
}
