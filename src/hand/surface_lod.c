/* Levels of detail of the hand surface by meshoptimizer's edge-collapse simplifier (the
 * polygon reduction the thesis cites as its reference [3] for lighter models, 4.2.3).
 * The collapses keep a subset of the surface's own vertices, so every kept vertex has
 * the same position, normal and skin weights as in the full mesh. The only file of the
 * library that calls meshoptimizer. */
#include <meshoptimizer.h>
#include <stdlib.h>
#include <string.h>

#include "hand/surface_private.h"

const int sk_hand_lod_triangles[SK_HAND_LOD_COUNT] = {8000, 2000, 500};

sk_result sk_hand_surface_simplify(sk_hand_surface **out, const sk_hand_surface *base, int target, sk_error *err)
{
    *out = NULL;
    sk_result r = sk_check_range_i(err, "target_triangles", target, 100, 1000000);
    if (r != SK_OK) return r;
    const sk_mesh *m = &base->mesh;
    size_t V = m->vertex_count, T = m->triangle_count;
    bool left = base->skeleton.side == SK_HAND_SIDE_LEFT;
    float *pos = malloc(3 * V * sizeof *pos);
    uint32_t *idx = malloc(3 * T * sizeof *idx), *dst = malloc(3 * T * sizeof *dst), *remap = malloc(V * sizeof *remap);
    sk_hand_surface *s = calloc(1, sizeof *s);
    if (!pos || !idx || !dst || !remap || !s) {
        r = sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for a level of detail");
        goto done;
    }
    /* work on the right hand, as the full surface was built */
    memcpy(pos, m->positions, 3 * V * sizeof *pos);
    memcpy(idx, m->indices, 3 * T * sizeof *idx);
    if (left) {
        for (size_t v = 0; v < V; v++) pos[3 * v] = -pos[3 * v];
        for (size_t t = 0; t < T; t++) {
            uint32_t x = idx[3 * t + 1];
            idx[3 * t + 1] = idx[3 * t + 2], idx[3 * t + 2] = x;
        }
    }
    size_t n = (size_t)target < T ? meshopt_simplify(dst, idx, 3 * T, pos, V, 3 * sizeof *pos, 3 * (size_t)target, 1.0f, 0, NULL)
                                   : 3 * T;
    if ((size_t)target >= T) memcpy(dst, idx, 3 * T * sizeof *dst);
    for (size_t v = 0; v < V; v++) remap[v] = UINT32_MAX;
    for (size_t i = 0; i < n; i++) remap[dst[i]] = 0;
    size_t nv = 0;
    for (size_t v = 0; v < V; v++)
        if (remap[v] == 0) remap[v] = (uint32_t)nv++;
    s->skeleton = base->skeleton;
    s->right = base->right;
    s->flesh = base->flesh;
    s->field = base->field;
    if ((r = sk_mesh_create(&s->mesh, nv, n / 3, SK_MESH_NORMALS, err)) != SK_OK) goto done;
    for (size_t v = 0; v < V; v++)
        if (remap[v] != UINT32_MAX) memcpy(s->mesh.positions + 3 * (size_t)remap[v], pos + 3 * v, 3 * sizeof *pos);
    for (size_t i = 0; i < n; i++) s->mesh.indices[i] = remap[dst[i]];
    r = sk_hand__surface_finish(s, err);
done:
    free(pos), free(idx), free(dst), free(remap);
    if (r != SK_OK) {
        sk_hand_surface_destroy(s);
        return r;
    }
    *out = s;
    return SK_OK;
}
