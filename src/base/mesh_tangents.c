/* Per-vertex tangent frames from UVs: each triangle's dP/du and dP/dv (from its edges and
 * UV differences) are summed per vertex with the triangle's area as weight, then the
 * tangent is orthogonalised against the vertex normal (Gram-Schmidt) and the handedness
 * records whether dP/dv agrees with normal x tangent. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "shitsukan/mesh.h"

static void any_tangent(sk_vec3f n, float out[4])
{
    sk_vec3f t, b;
    sk_v3f_basis(n, &t, &b);
    out[0] = t.x, out[1] = t.y, out[2] = t.z, out[3] = 1.0f;
}

sk_result sk_mesh_compute_tangents(sk_mesh *mesh, sk_error *err)
{
    const sk_mesh_attribute *existing = sk_mesh_find_attribute(mesh, "tangent");
    if (existing) {
        if (existing->components == 4) return SK_OK;
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "the mesh's \"tangent\" attribute has %d components, expected 4",
                       existing->components);
    }
    size_t nv = mesh->vertex_count;
    size_t bytes;
    if (!sk_size_mul(nv, 9 * sizeof(float), &bytes))
        return sk_fail(err, SK_ERROR_LIMIT, "mesh of %zu vertices is too large", nv);
    float *acc = calloc(1, bytes > 0 ? bytes : 1); /* per vertex: dP/du, dP/dv, face normal */
    if (!acc) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for tangents");
    const float *P = mesh->positions, *UV = mesh->uvs;
    for (size_t f = 0; f < mesh->triangle_count; f++) {
        const uint32_t *ix = mesh->indices + 3 * f;
        sk_vec3f p0 = sk_v3f_load(P + 3 * ix[0]);
        sk_vec3f e1 = sk_v3f_sub(sk_v3f_load(P + 3 * ix[1]), p0);
        sk_vec3f e2 = sk_v3f_sub(sk_v3f_load(P + 3 * ix[2]), p0);
        sk_vec3f face = sk_v3f_cross(e1, e2); /* length = 2 area */
        sk_vec3f du = sk_v3f(0, 0, 0), dv = sk_v3f(0, 0, 0);
        if (UV) {
            float a1 = UV[2 * ix[1]] - UV[2 * ix[0]], b1 = UV[2 * ix[1] + 1] - UV[2 * ix[0] + 1];
            float a2 = UV[2 * ix[2]] - UV[2 * ix[0]], b2 = UV[2 * ix[2] + 1] - UV[2 * ix[0] + 1];
            float det = a1 * b2 - a2 * b1;
            if (det != 0.0f && isfinite(det)) {
                float area = 0.5f * sk_v3f_length(face);
                du = sk_v3f_normalize(sk_v3f_scale(
                    sk_v3f_sub(sk_v3f_scale(e1, b2), sk_v3f_scale(e2, b1)), 1.0f / det));
                dv = sk_v3f_normalize(sk_v3f_scale(
                    sk_v3f_sub(sk_v3f_scale(e2, a1), sk_v3f_scale(e1, a2)), 1.0f / det));
                du = sk_v3f_scale(du, area);
                dv = sk_v3f_scale(dv, area);
            }
        }
        for (int k = 0; k < 3; k++) {
            float *a = acc + 9 * ix[k];
            a[0] += du.x, a[1] += du.y, a[2] += du.z;
            a[3] += dv.x, a[4] += dv.y, a[5] += dv.z;
            a[6] += face.x, a[7] += face.y, a[8] += face.z;
        }
    }
    float *out;
    sk_result r = sk_mesh_add_attribute(mesh, "tangent", 4, &out, err);
    if (r != SK_OK) {
        free(acc);
        return r;
    }
    for (size_t i = 0; i < nv; i++) {
        const float *a = acc + 9 * i;
        sk_vec3f n = mesh->normals ? sk_v3f_load(mesh->normals + 3 * i) : sk_v3f_load(a + 6);
        n = sk_v3f_normalize(n);
        sk_vec3f t = sk_v3f_load(a), b = sk_v3f_load(a + 3);
        t = sk_v3f_sub(t, sk_v3f_scale(n, sk_v3f_dot(n, t)));
        float len = sk_v3f_length(t);
        if (!(len > 1e-12f) || sk_v3f_length(n) == 0.0f) {
            any_tangent(n.x == 0 && n.y == 0 && n.z == 0 ? sk_v3f(0, 0, 1) : n, out + 4 * i);
            continue;
        }
        t = sk_v3f_scale(t, 1.0f / len);
        float w = sk_v3f_dot(sk_v3f_cross(n, t), b) < 0.0f ? -1.0f : 1.0f;
        out[4 * i] = t.x, out[4 * i + 1] = t.y, out[4 * i + 2] = t.z, out[4 * i + 3] = w;
    }
    free(acc);
    return SK_OK;
}
