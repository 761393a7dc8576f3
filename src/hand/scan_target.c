/* What the simulated range scanner of thesis 4.1.1 sees: a closed triangle mesh in a ray
 * hierarchy, optionally with the implicit surface it was meshed from, onto which ray hits
 * are refined so that the scans sample the smooth surface and not its facets. */
#include <stdlib.h>
#include <string.h>

#include "hand/scan_private.h"

sk_result sk_hand_scan_target_create(sk_hand_scan_target **out, const sk_hand_scan_target_desc *desc,
                                     sk_error *err)
{
    *out = NULL;
    if (!desc || !desc->mesh) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "scan target: no mesh given");
    const sk_mesh *m = desc->mesh;
    sk_result r = sk_mesh_validate(m, err);
    if (r != SK_OK) return r;
    if (m->triangle_count == 0)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "scan target: the mesh has no triangles (a point cloud)");
    if (m->triangle_count > (1u << 26))
        return sk_fail(err, SK_ERROR_LIMIT, "scan target: %zu triangles (at most 2^26)", m->triangle_count);
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
    r = sk_hand__bvh_build(&t->bvh, (const sk_vec3d(*)[3])tri, (uint32_t)m->triangle_count, err);
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
    sk_hand__bvh_free(&target->bvh);
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
    return sqrt(sk_hand__bvh_nearest(&target->bvh, p, INFINITY, NULL));
}

bool sk_hand_scan_target_raycast(const sk_hand_scan_target *target, sk_vec3d o, sk_vec3d d, double t_min,
                                 double t_max, double *t, sk_vec3d *normal)
{
    sk_hand__ray_hit hit;
    if (!sk_hand__bvh_intersect(&target->bvh, o, d, t_min, t_max, &hit)) return false;
    if (t) *t = hit.t;
    if (normal) {
        sk_vec3d n = sk_hand__bvh_normal(&target->bvh, hit.triangle);
        *normal = sk_v3d_dot(n, d) > 0.0 ? sk_v3d_scale(n, -1.0) : n;
    }
    return true;
}

bool sk_hand__target_refine(const sk_hand_scan_target *target, sk_vec3d o, sk_vec3d d, double t_mesh,
                            double *t, sk_vec3d *normal)
{
    if (!target->sdf) return false;
    double tt = t_mesh, dl = sk_v3d_length(d);
    sk_vec3d g = {0, 0, 0};
    for (int k = 0; k < 8; k++) {
        double f = target->sdf(target->sdf_user, sk_v3d_add(o, sk_v3d_scale(d, tt)), &g);
        double slope = sk_v3d_dot(g, d);
        if (fabs(slope) < 1e-9 * dl) return false; /* the ray grazes the implicit surface */
        double step = f / slope;
        tt -= step;
        if (fabs(tt - t_mesh) * dl > 2.0) return false; /* wandered off to another sheet */
        if (fabs(step) * dl < 1e-9) {
            *t = tt;
            if (normal) {
                sk_vec3d n = sk_v3d_normalize(g);
                *normal = sk_v3d_dot(n, d) > 0.0 ? sk_v3d_scale(n, -1.0) : n;
            }
            return true;
        }
    }
    return false;
}
