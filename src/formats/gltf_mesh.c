/* Meshes of the glTF document (glTF 2.0 sec. 3.7.2): one indexed triangle primitive per
 * mesh, copied from the caller and checked against what the Khronos validator requires:
 * unit normals and tangents, colours in [0, 1], joint indices unique per vertex and 0
 * where the weight is 0, weights whose float sum is 1, morph targets (sec. 3.7.2.2). */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "formats/gltf_internal.h"

void sk__gltf_mesh_free(sk__gltf_mesh *m)
{
    free(m->name);
    free(m->positions);
    free(m->normals);
    free(m->uvs);
    free(m->colors);
    free(m->tangents);
    free(m->indices);
    free(m->joints);
    free(m->weights);
    free(m->target_positions);
    free(m->target_normals);
    free(m->default_weights);
    if (m->target_names)
        for (int t = 0; t < m->target_count; t++) free(m->target_names[t]);
    free(m->target_names);
    memset(m, 0, sizeof *m);
}

static float *copy_floats(const float *src, size_t count)
{
    float *dst = malloc(count * sizeof(float));
    if (dst) memcpy(dst, src, count * sizeof(float));
    return dst;
}

/* Unit vectors (the first 3 floats of each `stride`) normalised in place. */
static sk_result normalise_vectors(float *v, size_t count, int stride, const char *what,
                                   sk_error *err)
{
    for (size_t i = 0; i < count; i++) {
        float *p = v + (size_t)stride * i;
        double len = sqrt((double)p[0] * p[0] + (double)p[1] * p[1] + (double)p[2] * p[2]);
        if (!(fabs(len - 1.0) <= SK__GLTF_VECTOR_TOLERANCE))
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "%s[%zu] has length %.9g: must be a unit vector", what, i, len);
        for (int c = 0; c < 3; c++) p[c] = (float)(p[c] / len);
    }
    return SK_OK;
}

static sk_result check_colors(const float *c, size_t count, sk_error *err)
{
    for (size_t i = 0; i < 3 * count; i++)
        if (!(c[i] >= 0.0f && c[i] <= 1.0f))
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "colors[%zu] component %zu = %g is out of range [0, 1]", i / 3, i % 3,
                           (double)c[i]);
    return SK_OK;
}

/* The validator sums a vertex's non-zero weights in float, in slot order, and accepts a
 * sum within 2e-7 per weight of 1; dividing by the sum in double and then moving the float
 * residual onto the largest weight lands there (one pass is enough in practice; a few are
 * allowed). */
static void renormalise(float w[4], double sum)
{
    int largest = 0;
    for (int k = 0; k < 4; k++) {
        w[k] = (float)(w[k] / sum);
        if (w[k] > w[largest]) largest = k;
    }
    for (int pass = 0; pass < 4; pass++) {
        float fsum = 0.0f;
        int used = 0;
        for (int k = 0; k < 4; k++)
            if (w[k] != 0.0f) fsum += w[k], used++;
        if (fabs((double)fsum - 1.0) <= 2e-7 * used * 0.5) return;
        w[largest] = (float)((double)w[largest] + (1.0 - (double)fsum));
    }
}

static sk_result copy_skinning(const sk_gltf_mesh_desc *d, sk__gltf_mesh *m, sk_error *err)
{
    size_t n = m->vertex_count;
    m->joints = malloc(4 * n * sizeof(uint16_t));
    m->weights = malloc(4 * n * sizeof(float));
    if (!m->joints || !m->weights) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    m->max_joint = 0;
    for (size_t v = 0; v < n; v++) {
        const uint16_t *j = d->joints + 4 * v;
        const float *w = d->weights + 4 * v;
        double sum = 0.0;
        for (int k = 0; k < 4; k++) {
            if (!(w[k] >= 0.0f) || !isfinite(w[k]))
                return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                               "weights[%zu][%d] = %g: weights must be finite and >= 0", v, k,
                               (double)w[k]);
            sum += w[k];
            if (w[k] == 0.0f) continue;
            for (int l = 0; l < k; l++)
                if (w[l] != 0.0f && j[l] == j[k])
                    return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                                   "joints[%zu] names joint %u twice (slots %d and %d)", v,
                                   (unsigned)j[k], l, k);
        }
        if (!(fabs(sum - 1.0) <= SK__GLTF_WEIGHT_SUM_TOLERANCE))
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "weights[%zu] sum to %.9g: a vertex's weights must sum to 1 "
                           "(within %g)",
                           v, sum, SK__GLTF_WEIGHT_SUM_TOLERANCE);
        float *ow = m->weights + 4 * v;
        uint16_t *oj = m->joints + 4 * v;
        memcpy(ow, w, 4 * sizeof(float));
        renormalise(ow, sum);
        for (int k = 0; k < 4; k++) {
            /* a slot of weight 0 names joint 0, or the validator warns */
            oj[k] = ow[k] != 0.0f ? j[k] : 0;
            if (oj[k] > m->max_joint) m->max_joint = oj[k];
        }
    }
    return SK_OK;
}

static sk_result copy_targets(const sk_gltf_mesh_desc *d, sk__gltf_mesh *m, sk_error *err)
{
    size_t per_target = m->vertex_count * 3, total;
    if (!sk_size_mul(per_target, (size_t)d->target_count, &total))
        return sk_fail(err, SK_ERROR_LIMIT, "target_count = %d is too large", d->target_count);
    if (!d->target_positions)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "target_count = %d but target_positions is NULL", d->target_count);
    m->target_count = d->target_count;
    for (size_t i = 0; i < total; i++) {
        if (!isfinite(d->target_positions[i]))
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "target_positions[%zu] (target %zu, vertex %zu) is not finite", i,
                           i / per_target, (i % per_target) / 3);
        if (d->target_normals && !isfinite(d->target_normals[i]))
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "target_normals[%zu] (target %zu, vertex %zu) is not finite", i,
                           i / per_target, (i % per_target) / 3);
    }
    m->target_positions = copy_floats(d->target_positions, total);
    if (!m->target_positions) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    if (d->target_normals && !(m->target_normals = copy_floats(d->target_normals, total)))
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    if (d->default_weights) {
        for (int t = 0; t < d->target_count; t++)
            if (!isfinite(d->default_weights[t]))
                return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "default_weights[%d] is not finite",
                               t);
        m->default_weights = copy_floats(d->default_weights, (size_t)d->target_count);
        if (!m->default_weights) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    }
    if (d->target_names) {
        m->target_names = calloc((size_t)d->target_count, sizeof(char *));
        if (!m->target_names) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
        for (int t = 0; t < d->target_count; t++) {
            const char *name = d->target_names[t];
            if (!name || !name[0])
                return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "target_names[%d] is empty", t);
            /* tools address shape keys by name, so the names must tell them apart */
            for (int u = 0; u < t; u++)
                if (strcmp(d->target_names[u], name) == 0)
                    return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                                   "target_names[%d] = \"%s\" repeats target_names[%d]", t, name,
                                   u);
            if (!(m->target_names[t] = strdup(name)))
                return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
        }
    }
    return SK_OK;
}

/* What the mesh's material asks of it: UVs for any texture, normals and tangents for a
 * normal texture (the validator warns when the tangent space must be generated). */
static sk_result copy_material_needs(const sk_gltf *gltf, const sk_gltf_mesh_desc *d,
                                     sk__gltf_mesh *m, sk_error *err)
{
    if (d->material == SK_GLTF_NONE) return SK_OK;
    if (d->material < 0 || d->material >= gltf->material_count)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "material = %d is not a material of the document (%d materials)",
                       d->material, gltf->material_count);
    const sk__gltf_material *mat = &gltf->materials[d->material];
    bool textured =
        mat->base_color_image >= 0 || mat->normal_image >= 0 || mat->emissive_image >= 0;
    if (textured && !d->mesh->uvs)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "material = %d has a texture: the mesh needs uvs", d->material);
    if (mat->normal_image < 0) return SK_OK;
    const sk_mesh_attribute *tan = sk_mesh_find_attribute(d->mesh, "tangent");
    if (!d->mesh->normals || !tan || tan->components != 4)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "material = %d has a normal texture: the mesh needs normals and a "
                       "4-component \"tangent\" attribute (e.g. from sk_mesh_compute_tangents)",
                       d->material);
    m->tangents = copy_floats(tan->data, 4 * m->vertex_count);
    if (!m->tangents) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    sk_result r = normalise_vectors(m->tangents, m->vertex_count, 4, "tangent", err);
    for (size_t v = 0; r == SK_OK && v < m->vertex_count; v++) {
        float w = m->tangents[4 * v + 3];
        if (w != 1.0f && w != -1.0f)
            r = sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "tangent[%zu].w = %g: must be 1 or -1", v,
                        (double)w);
    }
    return r;
}

static sk_result copy_mesh(const sk_gltf *gltf, const sk_gltf_mesh_desc *d, sk__gltf_mesh *m,
                           sk_error *err)
{
    const sk_mesh *src = d->mesh;
    sk_result r = sk_mesh_validate(src, err);
    if (r != SK_OK) return r;
    if (src->triangle_count == 0)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "the mesh has no triangles");
    if (src->vertex_count >= UINT32_MAX)
        return sk_fail(err, SK_ERROR_LIMIT, "%zu vertices: a glTF mesh holds fewer than 2^32 - 1",
                       src->vertex_count);
    if ((d->joints == NULL) != (d->weights == NULL))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "joints and weights must be given together");
    if (d->target_count < 0 || d->target_count > SK__GLTF_MAX_TARGETS)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "target_count = %d is out of range [0, %d]",
                       d->target_count, SK__GLTF_MAX_TARGETS);
    size_t n = src->vertex_count;
    m->vertex_count = n;
    m->triangle_count = src->triangle_count;
    m->material = d->material;
    m->max_joint = -1;
    m->positions = copy_floats(src->positions, 3 * n);
    m->indices = malloc(3 * m->triangle_count * sizeof(uint32_t));
    if (src->normals) m->normals = copy_floats(src->normals, 3 * n);
    if (src->uvs) m->uvs = copy_floats(src->uvs, 2 * n);
    if (src->colors) m->colors = copy_floats(src->colors, 3 * n);
    if (!m->positions || !m->indices || (src->normals && !m->normals) || (src->uvs && !m->uvs) ||
        (src->colors && !m->colors))
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for %zu vertices", n);
    memcpy(m->indices, src->indices, 3 * m->triangle_count * sizeof(uint32_t));
    if (m->uvs && d->uv_origin_bottom_left)
        for (size_t v = 0; v < n; v++) m->uvs[2 * v + 1] = 1.0f - m->uvs[2 * v + 1];
    if (m->normals && (r = normalise_vectors(m->normals, n, 3, "normals", err)) != SK_OK) return r;
    if (m->colors && (r = check_colors(m->colors, n, err)) != SK_OK) return r;
    if ((r = copy_material_needs(gltf, d, m, err)) != SK_OK) return r;
    if (d->joints && (r = copy_skinning(d, m, err)) != SK_OK) return r;
    if (d->target_count > 0 && (r = copy_targets(d, m, err)) != SK_OK) return r;
    return SK_OK;
}

sk_result sk_gltf_add_mesh(sk_gltf *gltf, const sk_gltf_mesh_desc *desc, int *out_index,
                           sk_error *err)
{
    if (!gltf || !desc || !out_index)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "gltf, desc or out_index is NULL");
    *out_index = SK_GLTF_NONE;
    int index = gltf->mesh_count;
    if (!desc->mesh)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "meshes[%d].mesh is NULL", index);
    sk_result r = sk__gltf_grow((void **)&gltf->meshes, gltf->mesh_count, &gltf->mesh_capacity,
                                sizeof *gltf->meshes, "meshes", err);
    if (r != SK_OK) return r;
    sk__gltf_mesh m = {0};
    r = copy_mesh(gltf, desc, &m, err);
    if (r == SK_OK && !(m.name = sk__gltf_name(desc->name, "mesh", index)))
        r = sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    if (r != SK_OK) {
        sk__gltf_mesh_free(&m);
        return sk_error_prefix(err, r, "meshes[%d]", index);
    }
    gltf->meshes[index] = m;
    gltf->mesh_count++;
    *out_index = index;
    return SK_OK;
}
