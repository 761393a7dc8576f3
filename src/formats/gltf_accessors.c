/* The writer's binary chunk: buffer views and accessors (glTF 2.0 sec. 3.6) holding floats,
 * triangle indices and joint indices in little-endian order whatever the host, each view
 * on a 4-byte boundary, with exact min / max where they are written. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "formats/gltf_internal.h"

cJSON *sk__gltf_json(sk__gltf_out *out, cJSON *item)
{
    if (!item) out->failed = true;
    return item;
}

/* Room for `extra` more bytes after padding to 4. */
static uint8_t *reserve(sk__gltf_out *out, size_t extra)
{
    size_t start = (out->bin_size + 3) & ~(size_t)3, end;
    /* the GLB length field is 32 bits: the whole file must stay below 4 GiB */
    if (!sk_size_add(start, extra, &end) || end > (size_t)UINT32_MAX - (1u << 24)) {
        out->failed = true;
        return NULL;
    }
    if (end > out->bin_capacity) {
        size_t cap = out->bin_capacity ? out->bin_capacity : 4096;
        while (cap < end) cap = cap > SIZE_MAX / 2 ? end : 2 * cap;
        uint8_t *grown = realloc(out->bin, cap);
        if (!grown) {
            out->failed = true;
            return NULL;
        }
        out->bin = grown;
        out->bin_capacity = cap;
    }
    memset(out->bin + out->bin_size, 0, start - out->bin_size);
    out->bin_size = end;
    return out->bin + start;
}

static void put_u16(uint8_t *p, uint16_t v)
{
    p[0] = (uint8_t)v;
    p[1] = (uint8_t)(v >> 8);
}

static void put_u32(uint8_t *p, uint32_t v)
{
    for (int k = 0; k < 4; k++) p[k] = (uint8_t)(v >> (8 * k));
}

static void put_f32(uint8_t *p, float f)
{
    uint32_t bits;
    memcpy(&bits, &f, 4);
    put_u32(p, bits);
}

static int add_view(sk__gltf_out *out, size_t offset, size_t bytes, int target)
{
    cJSON *view = sk__gltf_json(out, cJSON_CreateObject());
    if (!view) return -1;
    cJSON_AddItemToArray(out->views, view);
    sk__gltf_json(out, cJSON_AddNumberToObject(view, "buffer", 0));
    sk__gltf_json(out, cJSON_AddNumberToObject(view, "byteOffset", (double)offset));
    sk__gltf_json(out, cJSON_AddNumberToObject(view, "byteLength", (double)bytes));
    if (target) sk__gltf_json(out, cJSON_AddNumberToObject(view, "target", target));
    return out->view_count++;
}

int sk__gltf_put_view(sk__gltf_out *out, const void *data, size_t bytes, int target)
{
    uint8_t *p = reserve(out, bytes);
    if (!p) return -1;
    memcpy(p, data, bytes);
    return add_view(out, (size_t)(p - out->bin), bytes, target);
}

static const char *type_name(int components)
{
    switch (components) {
    case 1:
        return "SCALAR";
    case 2:
        return "VEC2";
    case 3:
        return "VEC3";
    case 4:
        return "VEC4";
    default:
        return "MAT4";
    }
}

static cJSON *number_array(sk__gltf_out *out, const double *v, int n)
{
    cJSON *a = sk__gltf_json(out, cJSON_CreateArray());
    for (int i = 0; a && i < n; i++)
        cJSON_AddItemToArray(a, sk__gltf_json(out, cJSON_CreateNumber(v[i])));
    return a;
}

static int add_accessor(sk__gltf_out *out, int view, int component_type, size_t count,
                        int components, const double *min, const double *max)
{
    if (view < 0) return -1;
    cJSON *acc = sk__gltf_json(out, cJSON_CreateObject());
    if (!acc) return -1;
    cJSON_AddItemToArray(out->accessors, acc);
    sk__gltf_json(out, cJSON_AddNumberToObject(acc, "bufferView", view));
    sk__gltf_json(out, cJSON_AddNumberToObject(acc, "componentType", component_type));
    sk__gltf_json(out, cJSON_AddNumberToObject(acc, "count", (double)count));
    sk__gltf_json(out, cJSON_AddStringToObject(acc, "type", type_name(components)));
    if (min) cJSON_AddItemToObject(acc, "min", number_array(out, min, components));
    if (max) cJSON_AddItemToObject(acc, "max", number_array(out, max, components));
    return out->accessor_count++;
}

int sk__gltf_put_floats(sk__gltf_out *out, const float *data, size_t count, int components,
                        int target, bool bounds)
{
    size_t n = count * (size_t)components;
    uint8_t *p = reserve(out, 4 * n);
    if (!p) return -1;
    double lo[16], hi[16];
    for (int c = 0; c < components; c++) lo[c] = hi[c] = data[c];
    for (size_t i = 0; i < n; i++) {
        put_f32(p + 4 * i, data[i]);
        int c = (int)(i % (size_t)components);
        if (data[i] < lo[c]) lo[c] = data[i];
        if (data[i] > hi[c]) hi[c] = data[i];
    }
    /* -0 and +0 compare equal; the bound keeps whichever came first, which the validator
       accepts as the same number */
    int view = add_view(out, (size_t)(p - out->bin), 4 * n, target);
    return add_accessor(out, view, SK__GLTF_FLOAT, count, components, bounds ? lo : NULL,
                        bounds ? hi : NULL);
}

int sk__gltf_put_indices(sk__gltf_out *out, const uint32_t *indices, size_t count,
                         size_t vertex_count)
{
    bool shorts = vertex_count <= 65535; /* every index <= 65534 */
    size_t size = shorts ? 2 : 4;
    uint8_t *p = reserve(out, size * count);
    if (!p) return -1;
    for (size_t i = 0; i < count; i++) {
        if (shorts)
            put_u16(p + 2 * i, (uint16_t)indices[i]);
        else
            put_u32(p + 4 * i, indices[i]);
    }
    int view = add_view(out, (size_t)(p - out->bin), size * count, SK__GLTF_ELEMENT_ARRAY_BUFFER);
    return add_accessor(out, view, shorts ? SK__GLTF_UNSIGNED_SHORT : SK__GLTF_UNSIGNED_INT, count,
                        1, NULL, NULL);
}

int sk__gltf_put_joints(sk__gltf_out *out, const uint16_t *joints, size_t vertex_count,
                        int max_joint)
{
    bool bytes = max_joint < 256;
    size_t size = bytes ? 1 : 2, n = 4 * vertex_count;
    uint8_t *p = reserve(out, size * n);
    if (!p) return -1;
    for (size_t i = 0; i < n; i++) {
        if (bytes)
            p[i] = (uint8_t)joints[i];
        else
            put_u16(p + 2 * i, joints[i]);
    }
    int view = add_view(out, (size_t)(p - out->bin), size * n, SK__GLTF_ARRAY_BUFFER);
    return add_accessor(out, view, bytes ? SK__GLTF_UNSIGNED_BYTE : SK__GLTF_UNSIGNED_SHORT,
                        vertex_count, 4, NULL, NULL);
}
