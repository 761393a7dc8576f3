/* The glTF reader: the GLB container (glTF 2.0 sec. 4.4: header, a JSON chunk, an optional
 * BIN chunk, 4-byte aligned lengths that add up exactly), the JSON parsed within the memory
 * cap, the asset and required extensions, and the binary layout: buffers, buffer views and
 * accessors checked against the bytes they claim (sec. 3.6). The scene objects are checked
 * in gltf_read_objects.c. */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "formats/gltf_doc_internal.h"
#include "formats/gltf_internal.h"
#include "shitsukan/io.h"

sk_result sk__gltf_read_objects(sk_gltf_doc *doc, sk_error *err);

static uint32_t get_u32(const uint8_t *p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

/* Charges `bytes` of allocation against the cap (SK_ERROR_LIMIT beyond it). */
static sk_result charge(sk_gltf_doc *doc, size_t count, size_t size, const char *what,
                        sk_error *err)
{
    size_t bytes, total;
    if (!sk_size_mul(count, size, &bytes) || !sk_size_add(doc->charged, bytes, &total) ||
        total > doc->max_bytes)
        return sk_fail(err, SK_ERROR_LIMIT, "%s: %zu more bytes exceed the cap of %zu bytes", what,
                       count * size, doc->max_bytes);
    doc->charged = total;
    return SK_OK;
}

void *sk__gltf_doc_alloc(sk_gltf_doc *doc, int count, size_t size, const char *what, sk_result *r,
                         sk_error *err)
{
    if ((*r = charge(doc, (size_t)count, size, what, err)) != SK_OK) return NULL;
    void *p = calloc(count > 0 ? (size_t)count : 1, size);
    if (!p) *r = sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "%s: out of memory", what);
    return p;
}

sk_result sk__gltf_items(const sk_gltf_doc *doc, const char *key, const cJSON **array, int *count,
                         sk_error *err)
{
    sk_result r = sk__json_array(doc->json, "", key, false, 0, array, err);
    *count = r == SK_OK ? sk__json_count(*array) : 0;
    return r;
}

sk_result sk__gltf_each_item(sk_gltf_doc *doc, const cJSON *array, const char *key,
                             sk__gltf_item_fn fn, void *user, sk_error *err)
{
    int i = 0;
    const cJSON *item;
    cJSON_ArrayForEach(item, array)
    {
        char where[48];
        snprintf(where, sizeof where, "%s[%d]", key, i);
        if (!cJSON_IsObject(item))
            return sk_fail(err, SK_ERROR_PARSE, "%s: must be an object", where);
        sk_result r = fn(doc, item, i, where, user, err);
        if (r != SK_OK) return r;
        i++;
    }
    return SK_OK;
}

/* ------------------------------------------------------------- container */

static sk_result read_container(sk_gltf_doc *doc, size_t size, const uint8_t **json,
                                size_t *json_len, sk_error *err)
{
    const uint8_t *p = doc->file;
    if (size < SK__GLB_HEADER_BYTES)
        return sk_fail(err, SK_ERROR_PARSE, "GLB header: %zu bytes, a GLB has at least 12", size);
    if (get_u32(p) != SK__GLB_MAGIC)
        return sk_fail(err, SK_ERROR_PARSE, "GLB header: magic 0x%08x is not \"glTF\"", get_u32(p));
    if (get_u32(p + 4) != SK__GLB_VERSION)
        return sk_fail(err, SK_ERROR_UNSUPPORTED, "GLB header: version %u is not 2",
                       get_u32(p + 4));
    if (get_u32(p + 8) != size)
        return sk_fail(err, SK_ERROR_PARSE,
                       "GLB header: length %u does not match the file's %zu bytes", get_u32(p + 8),
                       size);
    size_t at = SK__GLB_HEADER_BYTES;
    for (int chunk = 0; at < size; chunk++) {
        if (size - at < SK__GLB_CHUNK_HEADER_BYTES)
            return sk_fail(err, SK_ERROR_PARSE, "chunk %d at byte %zu: truncated chunk header",
                           chunk, at);
        uint32_t len = get_u32(p + at), type = get_u32(p + at + 4);
        at += SK__GLB_CHUNK_HEADER_BYTES;
        if (len % 4 != 0)
            return sk_fail(err, SK_ERROR_PARSE, "chunk %d: length %u is not a multiple of 4", chunk,
                           len);
        if (len > size - at)
            return sk_fail(err, SK_ERROR_PARSE,
                           "chunk %d: length %u runs past the end of the file "
                           "(%zu bytes left)",
                           chunk, len, size - at);
        if (chunk == 0) {
            if (type != SK__GLB_CHUNK_JSON)
                return sk_fail(err, SK_ERROR_PARSE,
                               "chunk 0: type 0x%08x, the first chunk must be JSON", type);
            if (len == 0) return sk_fail(err, SK_ERROR_PARSE, "chunk 0: the JSON chunk is empty");
            *json = p + at;
            *json_len = len;
        } else if (type == SK__GLB_CHUNK_JSON) {
            return sk_fail(err, SK_ERROR_PARSE, "chunk %d: a second JSON chunk", chunk);
        } else if (type == SK__GLB_CHUNK_BIN) {
            if (chunk != 1)
                return sk_fail(err, SK_ERROR_PARSE, "chunk %d: the BIN chunk must be the second",
                               chunk);
            doc->bin = p + at;
            doc->bin_size = len;
        }
        /* chunks of other types are skipped, as glTF 2.0 sec. 4.4.3.1 asks of readers */
        at += len;
    }
    if (!*json) return sk_fail(err, SK_ERROR_PARSE, "GLB: the file has no JSON chunk");
    return SK_OK;
}

static sk_result parse_json(sk_gltf_doc *doc, const uint8_t *json, size_t len, sk_error *err)
{
    sk_result r = charge(doc, len, SK__GLTF_JSON_BYTES_PER_CHAR, "JSON chunk", err);
    if (r != SK_OK) return r;
    const char *text = (const char *)json, *end = NULL;
    doc->json = cJSON_ParseWithLengthOpts(text, len, &end, false);
    if (!doc->json) {
        size_t at = end && end >= text && end <= text + len ? (size_t)(end - text) : 0;
        return sk_fail(err, SK_ERROR_PARSE, "JSON chunk: invalid JSON near byte %zu", at);
    }
    for (const char *q = end; q < text + len; q++)
        if (*q != ' ' && *q != '\t' && *q != '\n' && *q != '\r')
            return sk_fail(err, SK_ERROR_PARSE,
                           "JSON chunk: byte %zu after the JSON value is not white space",
                           (size_t)(q - text));
    if (!cJSON_IsObject(doc->json))
        return sk_fail(err, SK_ERROR_PARSE, "JSON chunk: the root is not an object");
    return SK_OK;
}

static sk_result read_asset(const cJSON *root, sk_error *err)
{
    const cJSON *asset, *required;
    const char *version;
    sk_result r = sk__json_object(root, "", "asset", true, &asset, err);
    if (r == SK_OK) r = sk__json_string(asset, "asset", "version", true, &version, err);
    if (r != SK_OK) return r;
    if (strncmp(version, "2.", 2) != 0)
        return sk_fail(err, SK_ERROR_UNSUPPORTED, "asset.version = \"%s\": only glTF 2.x is read",
                       version);
    if ((r = sk__json_array(root, "", "extensionsRequired", false, 0, &required, err)) != SK_OK)
        return r;
    const cJSON *first = required ? required->child : NULL;
    if (first)
        return sk_fail(err, SK_ERROR_UNSUPPORTED, "extensionsRequired[0] = \"%s\" is not supported",
                       cJSON_IsString(first) ? first->valuestring : "?");
    return SK_OK;
}

/* ------------------------------------------------------ buffers and views */

/* What the buffer views are checked against: the GLB-stored buffer 0 (the only buffer a
 * .glb reader can load). */
typedef struct buffers {
    size_t length;
    int count;
} buffers;

static sk_result buffer_item(sk_gltf_doc *doc, const cJSON *b, int i, const char *where, void *user,
                             sk_error *err)
{
    buffers *bs = user;
    long long len;
    const char *uri;
    sk_result r;
    if ((r = sk__json_int(b, where, "byteLength", true, 1, (long long)UINT32_MAX, 0, &len, err)) ||
        (r = sk__json_string(b, where, "uri", false, &uri, err)))
        return r;
    if (uri)
        return sk_fail(
            err, SK_ERROR_UNSUPPORTED,
            "%s.uri: external and data-URI buffers are not read (only the GLB's own BIN chunk)",
            where);
    if (i > 0)
        return sk_fail(err, SK_ERROR_PARSE,
                       "%s: has no uri, which only buffers[0] (the BIN chunk) may", where);
    if (!doc->bin)
        return sk_fail(err, SK_ERROR_PARSE, "%s: refers to the BIN chunk, but the file has none",
                       where);
    if ((size_t)len > doc->bin_size)
        return sk_fail(err, SK_ERROR_PARSE,
                       "%s.byteLength = %lld exceeds the BIN chunk's %zu bytes", where, len,
                       doc->bin_size);
    bs->length = (size_t)len;
    return SK_OK;
}

static sk_result view_item(sk_gltf_doc *doc, const cJSON *v, int i, const char *where, void *user,
                           sk_error *err)
{
    const buffers *bs = user;
    int buffer;
    long long offset, length, stride;
    sk_result r;
    if ((r = sk__json_index(v, where, "buffer", true, bs->count, "buffers", &buffer, err)) ||
        (r = sk__json_int(v, where, "byteOffset", false, 0, (long long)UINT32_MAX, 0, &offset,
                          err)) ||
        (r = sk__json_int(v, where, "byteLength", true, 1, (long long)UINT32_MAX, 0, &length,
                          err)) ||
        (r = sk__json_int(v, where, "byteStride", false, 4, 252, 0, &stride, err)))
        return r;
    if (stride % 4 != 0)
        return sk_fail(err, SK_ERROR_PARSE, "%s.byteStride = %lld is not a multiple of 4", where,
                       stride);
    if ((size_t)offset > bs->length || (size_t)length > bs->length - (size_t)offset)
        return sk_fail(err, SK_ERROR_PARSE,
                       "%s: bytes [%lld, %lld) run past buffers[0] (%zu bytes)", where, offset,
                       offset + length, bs->length);
    doc->views[i] = (sk__gltf_view){(size_t)offset, (size_t)length, (size_t)stride};
    return SK_OK;
}

static sk_result read_views(sk_gltf_doc *doc, sk_error *err)
{
    const cJSON *array, *views;
    buffers bs = {0};
    sk_result r = sk__gltf_items(doc, "buffers", &array, &bs.count, err);
    if (r == SK_OK) r = sk__gltf_each_item(doc, array, "buffers", buffer_item, &bs, err);
    if (r == SK_OK) r = sk__gltf_items(doc, "bufferViews", &views, &doc->view_count, err);
    if (r != SK_OK) return r;
    doc->views =
        sk__gltf_doc_alloc(doc, doc->view_count, sizeof *doc->views, "bufferViews", &r, err);
    if (!doc->views) return r;
    return sk__gltf_each_item(doc, views, "bufferViews", view_item, &bs, err);
}

/* ----------------------------------------------------------------- accessors */

static int component_size(int type)
{
    switch (type) {
    case SK__GLTF_BYTE:
    case SK__GLTF_UNSIGNED_BYTE:
        return 1;
    case SK__GLTF_SHORT:
    case SK__GLTF_UNSIGNED_SHORT:
        return 2;
    case SK__GLTF_UNSIGNED_INT:
    case SK__GLTF_FLOAT:
        return 4;
    default:
        return 0;
    }
}

/* Components and matrix columns of an accessor type name. */
static bool type_shape(const char *type, int *components, int *columns)
{
    static const struct {
        const char *name;
        int components, columns;
    } k[] = {
        {"SCALAR", 1, 0}, {"VEC2", 2, 0}, {"VEC3", 3, 0},  {"VEC4", 4, 0},
        {"MAT2", 4, 2},   {"MAT3", 9, 3}, {"MAT4", 16, 4},
    };
    for (size_t i = 0; i < sizeof k / sizeof k[0]; i++)
        if (strcmp(type, k[i].name) == 0) {
            *components = k[i].components;
            *columns = k[i].columns;
            return true;
        }
    return false;
}

/* Bytes of one element: matrix columns start on 4-byte boundaries (sec. 3.6.2.4). */
static size_t element_size(const sk__gltf_accessor *a)
{
    if (a->columns == 0) return (size_t)a->components * (size_t)a->component_size;
    size_t rows = (size_t)(a->components / a->columns);
    size_t column = (rows * (size_t)a->component_size + 3) & ~(size_t)3;
    return column * (size_t)a->columns;
}

static sk_result accessor_item(sk_gltf_doc *doc, const cJSON *o, int index, const char *where,
                               void *user, sk_error *err)
{
    (void)user;
    sk__gltf_accessor *a = &doc->accessors[index];
    if (sk__json_member(o, "sparse"))
        return sk_fail(err, SK_ERROR_UNSUPPORTED, "%s.sparse: sparse accessors are not supported",
                       where);
    long long type_code, count, offset;
    const char *type;
    sk_result r;
    if ((r = sk__json_index(o, where, "bufferView", false, doc->view_count, "bufferViews", &a->view,
                            err)) ||
        (r = sk__json_int(o, where, "byteOffset", false, 0, (long long)UINT32_MAX, 0, &offset,
                          err)) ||
        (r = sk__json_int(o, where, "componentType", true, 0, 99999, 0, &type_code, err)) ||
        (r = sk__json_int(o, where, "count", true, 1, (long long)UINT32_MAX, 0, &count, err)) ||
        (r = sk__json_string(o, where, "type", true, &type, err)))
        return r;
    a->component_type = (int)type_code;
    a->component_size = component_size(a->component_type);
    if (a->component_size == 0)
        return sk_fail(err, SK_ERROR_PARSE,
                       "%s.componentType = %lld is not one of 5120, 5121, 5122, 5123, 5125, 5126",
                       where, type_code);
    if (!type_shape(type, &a->components, &a->columns))
        return sk_fail(err, SK_ERROR_PARSE,
                       "%s.type = \"%s\" is not SCALAR, VEC2, VEC3, VEC4, MAT2, MAT3 or MAT4",
                       where, type);
    const cJSON *norm = sk__json_member(o, "normalized");
    if (norm && !cJSON_IsBool(norm))
        return sk_fail(err, SK_ERROR_PARSE, "%s.normalized: must be a boolean", where);
    a->normalized = cJSON_IsTrue(norm);
    if (a->normalized &&
        (a->component_type == SK__GLTF_FLOAT || a->component_type == SK__GLTF_UNSIGNED_INT))
        return sk_fail(err, SK_ERROR_PARSE,
                       "%s.normalized: only byte and short components can be normalized", where);
    a->count = (size_t)count;
    double bounds[16];
    bool has_min, has_max;
    if ((r = sk__json_numbers(o, where, "min", a->components, bounds, &has_min, err)) ||
        (r = sk__json_numbers(o, where, "max", a->components, bounds, &has_max, err)))
        return r;
    a->has_bounds = has_min && has_max;
    size_t elem = element_size(a);
    if (a->view < 0) {
        if (offset != 0)
            return sk_fail(err, SK_ERROR_PARSE, "%s.byteOffset: given without a bufferView", where);
        a->stride = elem;
        return SK_OK;
    }
    const sk__gltf_view *v = &doc->views[a->view];
    a->stride = v->stride ? v->stride : elem;
    if (v->stride && v->stride < elem)
        return sk_fail(err, SK_ERROR_PARSE,
                       "%s: elements of %zu bytes do not fit bufferViews[%d].byteStride = %zu",
                       where, elem, a->view, v->stride);
    if (offset % a->component_size != 0 ||
        (v->offset + (size_t)offset) % (size_t)a->component_size != 0)
        return sk_fail(err, SK_ERROR_PARSE,
                       "%s.byteOffset = %lld: the data is not aligned to its %d-byte components",
                       where, offset, a->component_size);
    /* offset + stride (count - 1) + elem <= view length, without overflow */
    size_t span, end;
    if (!sk_size_mul(a->stride, a->count - 1, &span) || !sk_size_add(span, elem, &span) ||
        !sk_size_add(span, (size_t)offset, &end) || end > v->length)
        return sk_fail(
            err, SK_ERROR_PARSE,
            "%s.count = %zu: %zu elements of %zu bytes (stride %zu) from byte %lld do not fit "
            "bufferViews[%d] (%zu bytes)",
            where, a->count, a->count, elem, a->stride, offset, a->view, v->length);
    a->offset = v->offset + (size_t)offset;
    return SK_OK;
}

static sk_result read_accessors(sk_gltf_doc *doc, sk_error *err)
{
    const cJSON *accessors;
    sk_result r = sk__gltf_items(doc, "accessors", &accessors, &doc->accessor_count, err);
    if (r != SK_OK) return r;
    doc->accessors =
        sk__gltf_doc_alloc(doc, doc->accessor_count, sizeof *doc->accessors, "accessors", &r, err);
    if (!doc->accessors) return r;
    return sk__gltf_each_item(doc, accessors, "accessors", accessor_item, NULL, err);
}

/* ----------------------------------------------------------------- entry points */

static size_t cap_of(const sk_gltf_read_desc *desc)
{
    return desc && desc->max_bytes ? desc->max_bytes : SK__GLTF_DEFAULT_MAX_BYTES;
}

/* Takes ownership of `file` (malloc'ed, `size` bytes). */
static sk_result read_owned(sk_gltf_doc **out, uint8_t *file, size_t size, size_t cap,
                            sk_error *err)
{
    sk_gltf_doc *doc = calloc(1, sizeof *doc);
    if (!doc) {
        free(file);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    }
    doc->file = file;
    doc->max_bytes = cap;
    doc->charged = size;
    const uint8_t *json = NULL;
    size_t json_len = 0;
    sk_result r = read_container(doc, size, &json, &json_len, err);
    if (r == SK_OK) r = parse_json(doc, json, json_len, err);
    if (r == SK_OK) r = read_asset(doc->json, err);
    if (r == SK_OK) r = read_views(doc, err);
    if (r == SK_OK) r = read_accessors(doc, err);
    if (r == SK_OK) r = sk__gltf_read_objects(doc, err);
    if (r != SK_OK) {
        sk_gltf_doc_free(doc);
        return r;
    }
    *out = doc;
    return SK_OK;
}

sk_result sk_gltf_read_glb_memory(sk_gltf_doc **out, const uint8_t *data, size_t size,
                                  const sk_gltf_read_desc *desc, sk_error *err)
{
    if (!out) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "out is NULL");
    *out = NULL;
    if (!data && size > 0) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "data is NULL");
    size_t cap = cap_of(desc);
    if (size > cap)
        return sk_fail(err, SK_ERROR_LIMIT, "a GLB of %zu bytes exceeds the cap of %zu bytes", size,
                       cap);
    uint8_t *copy = malloc(size ? size : 1);
    if (!copy) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for %zu bytes", size);
    if (size) memcpy(copy, data, size);
    return read_owned(out, copy, size, cap, err);
}

sk_result sk_gltf_read_glb(sk_gltf_doc **out, const char *path, const sk_gltf_read_desc *desc,
                           sk_error *err)
{
    if (!out) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "out is NULL");
    *out = NULL;
    if (!path) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "path is NULL");
    char *data = NULL;
    size_t size = 0;
    size_t cap = cap_of(desc);
    sk_result r = sk_read_file(path, cap, &data, &size, err);
    if (r != SK_OK) return r;
    r = read_owned(out, (uint8_t *)data, size, cap, err);
    return r == SK_OK ? r : sk_error_prefix(err, r, "%s", path);
}

void sk_gltf_doc_free(sk_gltf_doc *doc)
{
    if (!doc) return;
    for (int i = 0; doc->skins && i < doc->skin_count; i++) free(doc->skins[i].joints);
    for (int i = 0; doc->animations && i < doc->animation_count; i++)
        free(doc->animations[i].channels);
    free(doc->views);
    free(doc->accessors);
    free(doc->nodes);
    free(doc->node_matrix);
    free(doc->meshes);
    free(doc->skins);
    free(doc->animations);
    cJSON_Delete(doc->json);
    free(doc->file);
    free(doc);
}
