/* Queries on a read glTF document: counts, nodes, mesh attributes and morph targets, skins,
 * animation channels, and accessors decoded to floats (normalised integers as glTF 2.0
 * sec. 3.11 "Animations" / 3.7.2 define them: c / 255, max(c / 127, -1), ...). */
#define _POSIX_C_SOURCE 200809L
#include <stdlib.h>
#include <string.h>

#include "formats/gltf_doc_internal.h"
#include "formats/gltf_internal.h"

static const uint8_t *element(const sk_gltf_doc *doc, const sk__gltf_accessor *a, size_t i, int c)
{
    size_t within;
    if (a->columns) {
        int rows = a->components / a->columns;
        size_t column = ((size_t)rows * (size_t)a->component_size + 3) & ~(size_t)3;
        within = (size_t)(c / rows) * column + (size_t)(c % rows) * (size_t)a->component_size;
    } else {
        within = (size_t)c * (size_t)a->component_size;
    }
    return doc->bin + a->offset + a->stride * i + within;
}

static uint32_t raw_bits(const sk_gltf_doc *doc, const sk__gltf_accessor *a, size_t i, int c)
{
    if (a->view < 0) return 0; /* an accessor without a buffer view is all zeros */
    const uint8_t *p = element(doc, a, i, c);
    uint32_t v = 0;
    for (int k = 0; k < a->component_size; k++) v |= (uint32_t)p[k] << (8 * k);
    return v;
}

uint32_t sk__gltf_accessor_uint(const sk_gltf_doc *doc, const sk__gltf_accessor *a, size_t i, int c)
{
    return raw_bits(doc, a, i, c);
}

float sk__gltf_accessor_value(const sk_gltf_doc *doc, const sk__gltf_accessor *a, size_t i, int c)
{
    uint32_t bits = raw_bits(doc, a, i, c);
    float f;
    switch (a->component_type) {
    case SK__GLTF_FLOAT:
        memcpy(&f, &bits, 4);
        return f;
    case SK__GLTF_BYTE: {
        float v = (float)(int8_t)(uint8_t)bits;
        return a->normalized ? (v / 127.0f < -1.0f ? -1.0f : v / 127.0f) : v;
    }
    case SK__GLTF_UNSIGNED_BYTE:
        return a->normalized ? (float)bits / 255.0f : (float)bits;
    case SK__GLTF_SHORT: {
        float v = (float)(int16_t)(uint16_t)bits;
        return a->normalized ? (v / 32767.0f < -1.0f ? -1.0f : v / 32767.0f) : v;
    }
    case SK__GLTF_UNSIGNED_SHORT:
        return a->normalized ? (float)bits / 65535.0f : (float)bits;
    default:
        return (float)bits; /* UNSIGNED_INT */
    }
}

sk_gltf_doc_counts sk_gltf_doc_count(const sk_gltf_doc *doc)
{
    sk_gltf_doc_counts c = {0};
    if (!doc) return c;
    c.nodes = doc->node_count;
    c.meshes = doc->mesh_count;
    c.skins = doc->skin_count;
    c.animations = doc->animation_count;
    c.materials = doc->material_count;
    c.images = doc->image_count;
    c.accessors = doc->accessor_count;
    return c;
}

static sk_result check_index(const char *what, int index, int count, sk_error *err)
{
    if (index >= 0 && index < count) return SK_OK;
    return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "%s = %d is out of range [0, %d)", what, index,
                   count);
}

sk_result sk_gltf_doc_get_node(const sk_gltf_doc *doc, int index, sk_gltf_doc_node *out,
                               sk_error *err)
{
    if (!doc || !out) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "doc or out is NULL");
    sk_result r = check_index("node", index, doc->node_count, err);
    if (r == SK_OK) *out = doc->nodes[index];
    return r;
}

sk_result sk_gltf_doc_read_accessor(const sk_gltf_doc *doc, int index, float **out_values,
                                    size_t *out_count, int *out_components, sk_error *err)
{
    if (!doc || !out_values || !out_count || !out_components)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "doc or an output is NULL");
    *out_values = NULL;
    *out_count = 0;
    *out_components = 0;
    sk_result r = check_index("accessor", index, doc->accessor_count, err);
    if (r != SK_OK) return r;
    const sk__gltf_accessor *a = &doc->accessors[index];
    size_t n, bytes;
    if (!sk_size_mul(a->count, (size_t)a->components, &n) ||
        !sk_size_mul(n, sizeof(float), &bytes) || bytes > doc->max_bytes)
        return sk_fail(err, SK_ERROR_LIMIT,
                       "accessors[%d]: %zu elements exceed the cap of %zu bytes", index, a->count,
                       doc->max_bytes);
    float *v = malloc(bytes ? bytes : 1);
    if (!v) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "accessors[%d]: out of memory", index);
    for (size_t i = 0; i < a->count; i++)
        for (int c = 0; c < a->components; c++)
            v[i * (size_t)a->components + (size_t)c] = sk__gltf_accessor_value(doc, a, i, c);
    *out_values = v;
    *out_count = a->count;
    *out_components = a->components;
    return SK_OK;
}

static int attribute_index(const cJSON *attrs, const char *attribute)
{
    const cJSON *item = attribute ? sk__json_member(attrs, attribute) : NULL;
    return item ? (int)item->valuedouble : -1;
}

int sk_gltf_doc_mesh_accessor(const sk_gltf_doc *doc, int mesh, const char *attribute)
{
    if (!doc || mesh < 0 || mesh >= doc->mesh_count || !attribute) return -1;
    const sk__gltf_doc_mesh *m = &doc->meshes[mesh];
    if (strcmp(attribute, "indices") == 0) return m->indices;
    return attribute_index(m->attributes, attribute);
}

int sk_gltf_doc_mesh_target_count(const sk_gltf_doc *doc, int mesh)
{
    if (!doc || mesh < 0 || mesh >= doc->mesh_count) return 0;
    return doc->meshes[mesh].target_count;
}

int sk_gltf_doc_mesh_target_accessor(const sk_gltf_doc *doc, int mesh, int target,
                                     const char *attribute)
{
    if (!doc || mesh < 0 || mesh >= doc->mesh_count) return -1;
    const sk__gltf_doc_mesh *m = &doc->meshes[mesh];
    if (target < 0 || target >= m->target_count) return -1;
    const cJSON *t = m->targets ? m->targets->child : NULL;
    for (int k = 0; t && k < target; k++) t = t->next;
    return t ? attribute_index(t, attribute) : -1;
}

sk_result sk_gltf_doc_get_skin(const sk_gltf_doc *doc, int index, const int **out_joints,
                               int *out_joint_count, int *out_inverse_bind_accessor, sk_error *err)
{
    if (!doc || !out_joints || !out_joint_count || !out_inverse_bind_accessor)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "doc or an output is NULL");
    sk_result r = check_index("skin", index, doc->skin_count, err);
    if (r != SK_OK) return r;
    *out_joints = doc->skins[index].joints;
    *out_joint_count = doc->skins[index].joint_count;
    *out_inverse_bind_accessor = doc->skins[index].inverse_bind;
    return SK_OK;
}

int sk_gltf_doc_channel_count(const sk_gltf_doc *doc, int animation)
{
    if (!doc || animation < 0 || animation >= doc->animation_count) return 0;
    return doc->animations[animation].channel_count;
}

sk_result sk_gltf_doc_get_channel(const sk_gltf_doc *doc, int animation, int channel,
                                  sk_gltf_doc_channel *out, sk_error *err)
{
    if (!doc || !out) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "doc or out is NULL");
    sk_result r = check_index("animation", animation, doc->animation_count, err);
    if (r == SK_OK)
        r = check_index("channel", channel, doc->animations[animation].channel_count, err);
    if (r == SK_OK) *out = doc->animations[animation].channels[channel];
    return r;
}
