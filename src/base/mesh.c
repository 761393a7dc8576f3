/* Triangle meshes and point clouds: allocation within the read cap, named attributes,
 * validation, area-weighted normals, bounds, growable arrays for the readers, and reading
 * and writing by file extension. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "base/io_internal.h"
#include "base/mesh_internal.h"
#include "shitsukan/mesh.h"

size_t sk__mesh_read_cap(const sk_mesh_read_desc *desc)
{
    return (desc && desc->max_bytes) ? desc->max_bytes : SK__MESH_DEFAULT_MAX_BYTES;
}

bool sk__mesh_bytes(size_t vertex_count, size_t triangle_count, int flags, size_t attribute_floats,
                    size_t *out)
{
    size_t floats = 3 + attribute_floats;
    if (flags & SK_MESH_NORMALS) floats += 3;
    if (flags & SK_MESH_UVS) floats += 2;
    if (flags & SK_MESH_COLORS) floats += 3;
    size_t vbytes, tbytes;
    return sk_size_mul(vertex_count, floats * sizeof(float), &vbytes) &&
           sk_size_mul(triangle_count, 3 * sizeof(uint32_t), &tbytes) &&
           sk_size_add(vbytes, tbytes, out);
}

static float *alloc_floats(size_t count) { return count ? calloc(count, sizeof(float)) : NULL; }

sk_result sk__mesh_create_capped(sk_mesh *mesh, size_t vertex_count, size_t triangle_count,
                                 int flags, size_t max_bytes, sk_error *err)
{
    if (!mesh) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "mesh is NULL");
    memset(mesh, 0, sizeof *mesh);
    if (flags & ~(SK_MESH_NORMALS | SK_MESH_UVS | SK_MESH_COLORS))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "flags = 0x%x has unknown bits", flags);
    if (triangle_count > 0 && vertex_count == 0)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "%zu triangles need vertices",
                       triangle_count);
    size_t bytes;
    if ((uint64_t)vertex_count > (uint64_t)UINT32_MAX + 1 || /* in 64 bits: a 32-bit size_t wraps */
        !sk__mesh_bytes(vertex_count, triangle_count, flags, 0, &bytes) || bytes > max_bytes)
        return sk_fail(err, SK_ERROR_LIMIT,
                       "a mesh of %zu vertices and %zu triangles exceeds the cap of %zu bytes",
                       vertex_count, triangle_count, max_bytes);
    mesh->positions = alloc_floats(3 * vertex_count);
    if (flags & SK_MESH_NORMALS) mesh->normals = alloc_floats(3 * vertex_count);
    if (flags & SK_MESH_UVS) mesh->uvs = alloc_floats(2 * vertex_count);
    if (flags & SK_MESH_COLORS) mesh->colors = alloc_floats(3 * vertex_count);
    if (triangle_count) mesh->indices = calloc(3 * triangle_count, sizeof(uint32_t));
    bool failed =
        (vertex_count &&
         (!mesh->positions || ((flags & SK_MESH_NORMALS) && !mesh->normals) ||
          ((flags & SK_MESH_UVS) && !mesh->uvs) || ((flags & SK_MESH_COLORS) && !mesh->colors))) ||
        (triangle_count && !mesh->indices);
    if (failed) {
        sk_mesh_free(mesh);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for a mesh of %zu vertices",
                       vertex_count);
    }
    mesh->vertex_count = vertex_count;
    mesh->triangle_count = triangle_count;
    return SK_OK;
}

sk_result sk_mesh_create(sk_mesh *mesh, size_t vertex_count, size_t triangle_count, int flags,
                         sk_error *err)
{
    return sk__mesh_create_capped(mesh, vertex_count, triangle_count, flags,
                                  SK__MESH_DEFAULT_MAX_BYTES, err);
}

sk_result sk_mesh_add_attribute(sk_mesh *mesh, const char *name, int components, float **out_data,
                                sk_error *err)
{
    if (out_data) *out_data = NULL;
    if (!mesh || !name)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "mesh and name must not be NULL");
    size_t len = strlen(name);
    if (len == 0 || len >= SK_MESH_ATTRIBUTE_NAME_SIZE)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "attribute name \"%s\" must be 1-%d bytes long", name,
                       SK_MESH_ATTRIBUTE_NAME_SIZE - 1);
    if (components < 1 || components > 4)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "attribute \"%s\": components = %d is out of range [1, 4]", name,
                       components);
    if (sk_mesh_find_attribute(mesh, name))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "attribute \"%s\" already exists", name);
    if (mesh->attribute_count >= SK_MESH_MAX_ATTRIBUTES)
        return sk_fail(err, SK_ERROR_LIMIT, "cannot add attribute \"%s\": all %d slots are used",
                       name, SK_MESH_MAX_ATTRIBUTES);
    size_t count;
    if (!sk_size_mul(mesh->vertex_count, (size_t)components, &count))
        return sk_fail(err, SK_ERROR_LIMIT, "attribute \"%s\" is too large", name);
    float *data = alloc_floats(count);
    if (count && !data)
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for attribute \"%s\"", name);
    sk_mesh_attribute *a = &mesh->attributes[mesh->attribute_count++];
    memcpy(a->name, name, len + 1);
    a->components = components;
    a->data = data;
    if (out_data) *out_data = data;
    return SK_OK;
}

const sk_mesh_attribute *sk_mesh_find_attribute(const sk_mesh *mesh, const char *name)
{
    if (!mesh || !name) return NULL;
    for (int i = 0; i < mesh->attribute_count && i < SK_MESH_MAX_ATTRIBUTES; i++)
        if (strcmp(mesh->attributes[i].name, name) == 0) return &mesh->attributes[i];
    return NULL;
}

void sk_mesh_free(sk_mesh *mesh)
{
    if (!mesh) return;
    free(mesh->positions);
    free(mesh->normals);
    free(mesh->uvs);
    free(mesh->colors);
    free(mesh->indices);
    for (int i = 0; i < mesh->attribute_count && i < SK_MESH_MAX_ATTRIBUTES; i++)
        free(mesh->attributes[i].data);
    memset(mesh, 0, sizeof *mesh);
}

static sk_result check_finite(const float *data, size_t count, int stride, const char *what,
                              sk_error *err)
{
    for (size_t i = 0; i < count * (size_t)stride; i++)
        if (!isfinite(data[i]))
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "%s of vertex %zu is not finite (%g)",
                           what, i / (size_t)stride, (double)data[i]);
    return SK_OK;
}

static sk_result validate_indices(const sk_mesh *mesh, sk_error *err)
{
    if (!mesh) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "mesh is NULL");
    if (mesh->vertex_count && !mesh->positions)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "mesh has vertices but no positions");
    if (mesh->triangle_count && !mesh->indices)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "mesh has triangles but no indices");
    for (size_t i = 0; i < 3 * mesh->triangle_count; i++)
        if (mesh->indices[i] >= mesh->vertex_count)
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "triangle %zu: index %u is out of range (vertex count %zu)", i / 3,
                           mesh->indices[i], mesh->vertex_count);
    return SK_OK;
}

sk_result sk_mesh_validate(const sk_mesh *mesh, sk_error *err)
{
    sk_result r = validate_indices(mesh, err);
    if (r != SK_OK) return r;
    size_t n = mesh->vertex_count;
    if (mesh->attribute_count < 0 || mesh->attribute_count > SK_MESH_MAX_ATTRIBUTES)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "attribute_count = %d is out of range [0, %d]", mesh->attribute_count,
                       SK_MESH_MAX_ATTRIBUTES);
    r = check_finite(mesh->positions, n, 3, "position", err);
    if (r == SK_OK && mesh->normals) r = check_finite(mesh->normals, n, 3, "normal", err);
    if (r == SK_OK && mesh->uvs) r = check_finite(mesh->uvs, n, 2, "uv", err);
    if (r == SK_OK && mesh->colors) r = check_finite(mesh->colors, n, 3, "colour", err);
    for (int i = 0; r == SK_OK && i < mesh->attribute_count; i++) {
        const sk_mesh_attribute *a = &mesh->attributes[i];
        if (a->components < 1 || a->components > 4 || (n && !a->data) ||
            !memchr(a->name, '\0', sizeof a->name) || !a->name[0])
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "attribute %d is malformed (name, components 1-4, data)", i);
    }
    return r;
}

sk_result sk__mesh_normals_into(const sk_mesh *mesh, float *out, sk_error *err)
{
    size_t n = mesh->vertex_count;
    double *acc = n ? calloc(3 * n, sizeof *acc) : NULL;
    if (n && !acc) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for normals");
    const float *p = mesh->positions;
    for (size_t t = 0; t < mesh->triangle_count; t++) {
        const uint32_t *tri = mesh->indices + 3 * t;
        const float *a = p + 3 * (size_t)tri[0], *b = p + 3 * (size_t)tri[1],
                    *c = p + 3 * (size_t)tri[2];
        double e1[3] = {(double)b[0] - a[0], (double)b[1] - a[1], (double)b[2] - a[2]};
        double e2[3] = {(double)c[0] - a[0], (double)c[1] - a[1], (double)c[2] - a[2]};
        /* The cross product's length is twice the triangle's area: area weighting. */
        double cr[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                        e1[0] * e2[1] - e1[1] * e2[0]};
        for (int k = 0; k < 3; k++)
            for (int j = 0; j < 3; j++) acc[3 * (size_t)tri[k] + j] += cr[j];
    }
    for (size_t v = 0; v < n; v++) {
        double *a = acc + 3 * v;
        double len = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
        if (len > 0.0 && isfinite(len)) {
            out[3 * v] = (float)(a[0] / len);
            out[3 * v + 1] = (float)(a[1] / len);
            out[3 * v + 2] = (float)(a[2] / len);
        } else {
            out[3 * v] = 0.0f;
            out[3 * v + 1] = 0.0f;
            out[3 * v + 2] = 1.0f;
        }
    }
    free(acc);
    return SK_OK;
}

sk_result sk_mesh_compute_normals(sk_mesh *mesh, sk_error *err)
{
    sk_result r = validate_indices(mesh, err);
    if (r != SK_OK) return r;
    bool allocated = false;
    if (!mesh->normals && mesh->vertex_count) {
        mesh->normals = alloc_floats(3 * mesh->vertex_count);
        if (!mesh->normals)
            return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for normals");
        allocated = true;
    }
    r = sk__mesh_normals_into(mesh, mesh->normals, err);
    if (r != SK_OK && allocated) {
        free(mesh->normals);
        mesh->normals = NULL;
    }
    return r;
}

bool sk_mesh_bounds(const sk_mesh *mesh, sk_vec3f *lo, sk_vec3f *hi)
{
    if (!mesh || mesh->vertex_count == 0 || !mesh->positions) return false;
    float mn[3], mx[3];
    for (int k = 0; k < 3; k++) mn[k] = mx[k] = mesh->positions[k];
    for (size_t v = 1; v < mesh->vertex_count; v++)
        for (int k = 0; k < 3; k++) {
            float x = mesh->positions[3 * v + (size_t)k];
            mn[k] = fminf(mn[k], x);
            mx[k] = fmaxf(mx[k], x);
        }
    if (lo) *lo = sk_v3f(mn[0], mn[1], mn[2]);
    if (hi) *hi = sk_v3f(mx[0], mx[1], mx[2]);
    return true;
}

/* ------------------------------------------------------------------ growable arrays */

sk_result sk__array_reserve(sk__array *a, size_t extra, sk__budget *budget)
{
    size_t need;
    if (!sk_size_add(a->count, extra, &need)) return SK_ERROR_LIMIT;
    if (need <= a->capacity) return SK_OK;
    size_t cap = a->capacity ? a->capacity : 64;
    while (cap < need) {
        if (!sk_size_mul(cap, 2, &cap)) return SK_ERROR_LIMIT;
    }
    size_t old_bytes = a->capacity * a->elem, new_bytes;
    if (!sk_size_mul(cap, a->elem, &new_bytes)) return SK_ERROR_LIMIT;
    /* Doubling may overshoot the budget when the exact need would fit: grow just enough. */
    if (budget->used - old_bytes + new_bytes > budget->max) {
        if (!sk_size_mul(need, a->elem, &new_bytes) ||
            budget->used - old_bytes + new_bytes > budget->max)
            return SK_ERROR_LIMIT;
        cap = need;
    }
    void *data = realloc(a->data, new_bytes);
    if (!data) return SK_ERROR_OUT_OF_MEMORY;
    budget->used = budget->used - old_bytes + new_bytes;
    a->data = data;
    a->capacity = cap;
    return SK_OK;
}

void sk__array_free(sk__array *a)
{
    free(a->data);
    a->data = NULL;
    a->count = a->capacity = 0;
}

/* ------------------------------------------------------------------ by extension */
