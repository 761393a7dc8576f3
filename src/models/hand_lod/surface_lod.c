/* Levels of detail of the hand surface by meshoptimizer's edge-collapse simplifier (the
 * polygon reduction the thesis cites as its reference [3] for lighter models, 4.2.3),
 * checked to be closed 2-manifolds and redone around any defect. The collapses keep a
 * subset of the surface's own vertices, so every kept vertex has the same position,
 * normal and skin weights as in the full mesh. The only file of the library that calls
 * meshoptimizer. */
#include <meshoptimizer.h>
#include <stdlib.h>
#include <string.h>

#include "models/hand_surface/surface_internal.h"

const int sk_hand_lod_triangles[SK_HAND_LOD_COUNT] = {8000, 2000, 500};

/* Marks the vertices within one edge of a marked vertex (one ring more). */
static void grow(const uint32_t *idx, size_t T, uint8_t *mark, size_t V)
{
    for (size_t t = 0; t < T; t++) {
        const uint32_t *tv = idx + 3 * t;
        if (mark[tv[0]] == 1 || mark[tv[1]] == 1 || mark[tv[2]] == 1)
            for (int k = 0; k < 3; k++)
                if (!mark[tv[k]]) mark[tv[k]] = 2;
    }
    for (size_t v = 0; v < V; v++)
        if (mark[v]) mark[v] = 1;
}

/* meshoptimizer's collapses do not keep the link condition, so where two sheets of the
 * surface come close (the webs, the thumb against the palm) a collapse can glue them
 * along an edge. The result is checked; where it is not a closed 2-manifold, the
 * triangles around each defect (in the full mesh) are held out and the rest simplified
 * again with its border locked, so those triangles fit back exactly; the held region
 * grows by a ring each time a defect remains. It ends: with every triangle held the
 * result is the full mesh. `dst` gets up to 3 T indices into the full mesh. */
static sk_result simplify_manifold(const uint32_t *idx, size_t T, const float *pos, size_t V,
                                   size_t target, uint32_t *dst, size_t *out_count, sk_error *err)
{
    if (target >= T) {
        memcpy(dst, idx, 3 * T * sizeof *dst);
        *out_count = 3 * T;
        return SK_OK;
    }
    uint8_t *held = calloc(V, 1), *bad = malloc(V);
    uint32_t *kept = malloc(3 * T * sizeof *kept), *compact = malloc(3 * T * sizeof *compact),
             *map = malloc(V * sizeof *map);
    sk_result r = SK_OK;
    if (!held || !bad || !kept || !compact || !map) {
        r = sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for a level of detail");
        goto done;
    }
    for (;;) {
        /* the triangles touching a held vertex stay as they are */
        size_t nk = 0, nh = 0;
        for (size_t t = 0; t < T; t++) {
            const uint32_t *tv = idx + 3 * t;
            bool hold = held[tv[0]] || held[tv[1]] || held[tv[2]];
            if (!hold) memcpy(kept + 3 * nk++, tv, 3 * sizeof *tv);
        }
        nh = T - nk;
        size_t want = target > nh ? target - nh : 0;
        size_t n = nk > want ? meshopt_simplify(dst, kept, 3 * nk, pos, V, 3 * sizeof *pos,
                                                3 * want, 1.0f, meshopt_SimplifyLockBorder, NULL)
                             : 3 * nk;
        if (nk <= want) memcpy(dst, kept, 3 * nk * sizeof *dst);
        for (size_t t = 0; t < T; t++) {
            const uint32_t *tv = idx + 3 * t;
            if (held[tv[0]] || held[tv[1]] || held[tv[2]])
                memcpy(dst + n, tv, 3 * sizeof *tv), n += 3;
        }
        /* check it on its own vertices */
        for (size_t v = 0; v < V; v++) map[v] = UINT32_MAX;
        size_t nv = 0;
        for (size_t i = 0; i < n; i++)
            if (map[dst[i]] == UINT32_MAX) map[dst[i]] = (uint32_t)nv++;
        for (size_t i = 0; i < n; i++) compact[i] = map[dst[i]];
        int ok = sk__hand_mesh_topology(compact, n / 3, nv, NULL, bad);
        if (ok < 0) {
            r = sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for a level of detail");
            break;
        }
        *out_count = n;
        if (ok || nh == T) break;
        /* hold the full mesh's triangles around each defect, one ring wider than before */
        for (size_t v = 0; v < V; v++)
            if (map[v] != UINT32_MAX && bad[map[v]]) held[v] = 1;
        grow(idx, T, held, V);
    }
done:
    free(held), free(bad), free(kept), free(compact), free(map);
    return r;
}

sk_result sk_hand_surface_simplify(sk_hand_surface **out, const sk_hand_surface *base, int target,
                                   sk_error *err)
{
    *out = NULL;
    sk_result r = sk_check_range_i(err, "target_triangles", target, 100, 1000000);
    if (r != SK_OK) return r;
    const sk_mesh *m = &base->mesh;
    size_t V = m->vertex_count, T = m->triangle_count;
    bool left = base->skeleton.side == SK_HAND_SIDE_LEFT;
    float *pos = malloc(3 * V * sizeof *pos);
    uint32_t *idx = malloc(3 * T * sizeof *idx), *dst = malloc(3 * T * sizeof *dst),
             *remap = malloc(V * sizeof *remap);
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
    size_t n = 0;
    if ((r = simplify_manifold(idx, T, pos, V, (size_t)target, dst, &n, err)) != SK_OK) goto done;
    for (size_t v = 0; v < V; v++) remap[v] = UINT32_MAX;
    for (size_t i = 0; i < n; i++) remap[dst[i]] = 0;
    size_t nv = 0;
    for (size_t v = 0; v < V; v++)
        if (remap[v] == 0) remap[v] = (uint32_t)nv++;
    s->skeleton = base->skeleton;
    s->right = base->right;
    s->flesh = base->flesh;
    s->field = base->field;
    memcpy(s->atlas_lo, base->atlas_lo, sizeof s->atlas_lo);
    memcpy(s->atlas_hi, base->atlas_hi, sizeof s->atlas_hi);
    if ((r = sk_mesh_create(&s->mesh, nv, n / 3, SK_MESH_NORMALS, err)) != SK_OK) goto done;
    for (size_t v = 0; v < V; v++)
        if (remap[v] != UINT32_MAX)
            memcpy(s->mesh.positions + 3 * (size_t)remap[v], pos + 3 * v, 3 * sizeof *pos);
    for (size_t i = 0; i < n; i++) s->mesh.indices[i] = remap[dst[i]];
    r = sk__hand_surface_finish(s, err);
done:
    free(pos), free(idx), free(dst), free(remap);
    if (r != SK_OK) {
        sk_hand_surface_destroy(s);
        return r;
    }
    *out = s;
    return SK_OK;
}
