/* The texture atlas of the hand surface, after the thesis's planar mapping (4.1.6): palm
 * and back photos correspond to the model's x-y coordinates. The back of the hand takes
 * the left half of the atlas as seen from the back (a right hand's thumb on the left),
 * the palm the right half as seen from the palm; both at one scale in mm. Each triangle
 * goes to the chart its rest normal faces (isolated triangles follow their neighbours),
 * and vertices on the seam between the charts are split. */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "models/hand_surface/surface_internal.h"

typedef struct edge_rec {
    uint32_t lo, hi, tri;
} edge_rec;

static int edge_cmp(const void *a, const void *b)
{
    const edge_rec *x = a, *y = b;
    if (x->lo != y->lo) return x->lo < y->lo ? -1 : 1;
    if (x->hi != y->hi) return x->hi < y->hi ? -1 : 1;
    return x->tri < y->tri ? -1 : (x->tri > y->tri);
}

sk_result sk__hand_atlas_build(sk_hand_surface *s, sk_error *err)
{
    const sk_mesh *m = &s->mesh;
    size_t V = m->vertex_count, T = m->triangle_count;
    uint8_t *chart = malloc(T), *next = malloc(T);
    uint32_t *nb = malloc(3 * T * sizeof *nb);
    edge_rec *edges = malloc(3 * T * sizeof *edges);
    uint32_t *first = malloc(2 * V * sizeof *first);
    sk_result r = SK_OK;
    if (!chart || !next || !nb || !edges || !first) {
        r = sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for the atlas");
        goto done;
    }
    /* rest normals (right hand: +z is palmar) */
    for (size_t t = 0; t < T; t++) {
        const uint32_t *tv = m->indices + 3 * t;
        float nz =
            m->normals[3 * tv[0] + 2] + m->normals[3 * tv[1] + 2] + m->normals[3 * tv[2] + 2];
        chart[t] = nz > 0.0f;
    }
    /* triangle neighbours across edges */
    for (size_t t = 0; t < T; t++)
        for (int k = 0; k < 3; k++) {
            uint32_t a = m->indices[3 * t + k], b = m->indices[3 * t + (k + 1) % 3];
            edges[3 * t + k] = (edge_rec){a < b ? a : b, a < b ? b : a, (uint32_t)t};
        }
    qsort(edges, 3 * T, sizeof *edges, edge_cmp);
    for (size_t i = 0; i < 3 * T; i++) nb[i] = UINT32_MAX;
    for (size_t i = 0; i + 1 < 3 * T; i++) {
        if (edges[i].lo != edges[i + 1].lo || edges[i].hi != edges[i + 1].hi) continue;
        uint32_t ta = edges[i].tri, tb = edges[i + 1].tri;
        for (int k = 0; k < 3; k++) {
            if (nb[3 * ta + k] == UINT32_MAX) {
                nb[3 * ta + k] = tb;
                break;
            }
        }
        for (int k = 0; k < 3; k++) {
            if (nb[3 * tb + k] == UINT32_MAX) {
                nb[3 * tb + k] = ta;
                break;
            }
        }
        i++;
    }
    /* a triangle whose neighbours are mostly in the other chart joins them */
    for (int pass = 0; pass < 4; pass++) {
        for (size_t t = 0; t < T; t++) {
            int other = 0;
            for (int k = 0; k < 3; k++)
                other += nb[3 * t + k] != UINT32_MAX && chart[nb[3 * t + k]] != chart[t];
            next[t] = other >= 2 ? !chart[t] : chart[t];
        }
        memcpy(chart, next, T);
    }
    /* export vertices: one per (vertex, chart) in use, in vertex order */
    for (size_t i = 0; i < 2 * V; i++) first[i] = UINT32_MAX;
    for (size_t t = 0; t < T; t++)
        for (int k = 0; k < 3; k++) first[2 * m->indices[3 * t + k] + chart[t]] = 0;
    size_t n = 0;
    for (size_t i = 0; i < 2 * V; i++)
        if (first[i] == 0) first[i] = (uint32_t)n++;
    s->export_count = n;
    s->export_map = malloc(n * sizeof *s->export_map);
    s->export_uv = malloc(2 * n * sizeof *s->export_uv);
    s->export_indices = malloc(3 * T * sizeof *s->export_indices);
    if (!s->export_map || !s->export_uv || !s->export_indices) {
        r = sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for the atlas");
        goto done;
    }
    /* bounds given beforehand (a level of detail keeps its full surface's, so that one
       texture fits every level) or those of the mesh */
    float lo[2] = {FLT_MAX, FLT_MAX}, hi[2] = {-FLT_MAX, -FLT_MAX};
    if (s->atlas_hi[0] > s->atlas_lo[0]) {
        memcpy(lo, s->atlas_lo, sizeof lo);
        memcpy(hi, s->atlas_hi, sizeof hi);
    } else {
        for (size_t v = 0; v < V; v++)
            for (int a = 0; a < 2; a++) {
                lo[a] = fminf(lo[a], m->positions[3 * v + a]);
                hi[a] = fmaxf(hi[a], m->positions[3 * v + a]);
            }
        memcpy(s->atlas_lo, lo, sizeof lo);
        memcpy(s->atlas_hi, hi, sizeof hi);
    }
    float cx = 0.5f * (lo[0] + hi[0]), cy = 0.5f * (lo[1] + hi[1]);
    float k = 0.97f * fminf(0.5f / (hi[0] - lo[0]), 1.0f / (hi[1] - lo[1]));
    for (size_t i = 0; i < 2 * V; i++) {
        if (first[i] == UINT32_MAX) continue;
        uint32_t e = first[i], v = (uint32_t)(i / 2);
        int palm = (int)(i % 2);
        float x = m->positions[3 * v], y = m->positions[3 * v + 1];
        s->export_map[e] = v;
        s->export_uv[2 * e] = palm ? 0.75f + k * (x - cx) : 0.25f - k * (x - cx);
        s->export_uv[2 * e + 1] = 0.5f + k * (y - cy);
    }
    for (size_t t = 0; t < T; t++)
        for (int j = 0; j < 3; j++)
            s->export_indices[3 * t + j] = first[2 * m->indices[3 * t + j] + chart[t]];
done:
    free(chart), free(next), free(nb), free(edges), free(first);
    return r;
}

const uint32_t *sk_hand_surface_export_map(const sk_hand_surface *s, size_t *count)
{
    if (count) *count = s->export_count;
    return s->export_map;
}

sk_result sk_hand_surface_export_mesh(const sk_hand_surface *s, const float *positions,
                                      const float *normals, bool with_weights, sk_mesh *out,
                                      sk_error *err)
{
    const sk_mesh *m = &s->mesh;
    if (!positions) positions = m->positions;
    if (!normals) normals = m->normals;
    size_t n = s->export_count;
    sk_result r = sk_mesh_create(out, n, m->triangle_count, SK_MESH_NORMALS | SK_MESH_UVS, err);
    if (r != SK_OK) return r;
    const sk_mesh_attribute *nail_src = sk_mesh_find_attribute(m, "nail");
    float *nail = NULL, *joints = NULL, *weights = NULL;
    r = sk_mesh_add_attribute(out, "nail", 1, &nail, err);
    if (r == SK_OK && with_weights) r = sk_mesh_add_attribute(out, "joints", 4, &joints, err);
    if (r == SK_OK && with_weights) r = sk_mesh_add_attribute(out, "weights", 4, &weights, err);
    if (r != SK_OK) {
        sk_mesh_free(out);
        return r;
    }
    for (size_t e = 0; e < n; e++) {
        uint32_t v = s->export_map[e];
        memcpy(out->positions + 3 * e, positions + 3 * (size_t)v, 3 * sizeof *positions);
        memcpy(out->normals + 3 * e, normals + 3 * (size_t)v, 3 * sizeof *normals);
        out->uvs[2 * e] = s->export_uv[2 * e];
        out->uvs[2 * e + 1] = s->export_uv[2 * e + 1];
        nail[e] = nail_src ? nail_src->data[v] : 0.0f;
        if (!with_weights) continue;
        for (int k = 0; k < 4; k++) {
            joints[4 * e + k] = s->links[1][4 * (size_t)v + k];
            weights[4 * e + k] = s->weights[1][4 * (size_t)v + k];
        }
    }
    memcpy(out->indices, s->export_indices, 3 * m->triangle_count * sizeof *out->indices);
    return SK_OK;
}
