/* Private structures of the glTF reader: a parsed .glb with its JSON tree and binary chunk,
 * the buffer views, accessors, nodes, meshes, skins and animations checked into arrays,
 * and the checked JSON access every part of the reader uses (not installed). */
#ifndef SK_IO_GLTF_DOC_INTERNAL_H
#define SK_IO_GLTF_DOC_INTERNAL_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include <cjson/cJSON.h>

#include "shitsukan/gltf.h"

/* Default cap of sk_gltf_read_desc.max_bytes. */
#define SK__GLTF_DEFAULT_MAX_BYTES ((size_t)1 << 30)
/* What one byte of JSON text may cost as a cJSON tree at worst ("0," is one 64-byte node),
   charged against the cap before parsing. */
#define SK__GLTF_JSON_BYTES_PER_CHAR 40

typedef struct sk__gltf_view {
    size_t offset, length; /* offset: into the binary chunk */
    size_t stride;         /* 0 = tightly packed */
} sk__gltf_view;

typedef struct sk__gltf_accessor {
    int view;      /* -1: no buffer view, all zeros */
    size_t offset; /* absolute, into the binary chunk */
    size_t stride; /* bytes between elements */
    size_t count;
    int component_type; /* SK__GLTF_BYTE .. SK__GLTF_FLOAT */
    int component_size; /* bytes */
    int components;     /* 1, 2, 3, 4, 4 (MAT2), 9 (MAT3), 16 (MAT4) */
    int columns;        /* matrix columns (their starts are 4-byte aligned), or 0 */
    bool normalized;
    bool has_bounds; /* min and max given */
} sk__gltf_accessor;

typedef struct sk__gltf_doc_mesh {
    const cJSON *attributes; /* of the first primitive */
    const cJSON *targets;    /* of the first primitive, or NULL */
    int target_count;
    int indices;         /* accessor or -1 */
    long long max_joint; /* largest JOINTS_n value of any primitive, -1 without */
} sk__gltf_doc_mesh;

typedef struct sk__gltf_doc_skin {
    int *joints;
    int joint_count;
    int inverse_bind; /* accessor or -1 (identity matrices) */
} sk__gltf_doc_skin;

typedef struct sk__gltf_doc_animation {
    sk_gltf_doc_channel *channels;
    int channel_count;
} sk__gltf_doc_animation;

struct sk_gltf_doc {
    uint8_t *file;      /* the whole .glb (owned) */
    const uint8_t *bin; /* the BIN chunk's data inside `file`, or NULL */
    size_t bin_size;
    cJSON *json;
    size_t max_bytes;
    sk__gltf_view *views;
    int view_count;
    sk__gltf_accessor *accessors;
    int accessor_count;
    sk_gltf_doc_node *nodes;
    bool *node_matrix; /* the node was given as a matrix (its TRS cannot be animated) */
    int node_count;
    sk__gltf_doc_mesh *meshes;
    int mesh_count;
    sk__gltf_doc_skin *skins;
    int skin_count;
    sk__gltf_doc_animation *animations;
    int animation_count;
    int material_count, image_count, texture_count;
    size_t charged; /* bytes counted against max_bytes so far */
};

/* ---- checked JSON access (gltf_json.c). `where` is the JSON path of `obj` as messages
   show it ("accessors[3]"); failures name "<where>.<key>" and are SK_ERROR_PARSE. */

/* The member `key` of object `obj`, or NULL when absent. */
const cJSON *sk__json_member(const cJSON *obj, const char *key);
/* An optional integer member in [lo, hi] (*out = def when absent). */
sk_result sk__json_int(const cJSON *obj, const char *where, const char *key, bool required,
                       long long lo, long long hi, long long def, long long *out, sk_error *err);
/* An optional index of an object of a top-level array holding `count` objects
   (*out = -1 when absent); `array` names that array in the message ("accessors"). */
sk_result sk__json_index(const cJSON *obj, const char *where, const char *key, bool required,
                         int count, const char *array, int *out, sk_error *err);
/* The same for an item already found (an array element: key is then e.g. "children[2]"). */
sk_result sk__json_index_item(const cJSON *item, const char *where, const char *key, int count,
                              const char *array, int *out, sk_error *err);
/* An optional member that must be an array (of at least min_items) / object / string. */
sk_result sk__json_array(const cJSON *obj, const char *where, const char *key, bool required,
                         int min_items, const cJSON **out, sk_error *err);
sk_result sk__json_object(const cJSON *obj, const char *where, const char *key, bool required,
                          const cJSON **out, sk_error *err);
sk_result sk__json_string(const cJSON *obj, const char *where, const char *key, bool required,
                          const char **out, sk_error *err);
/* Exactly n finite numbers (an array member), or absent (returns SK_OK, *found false). */
sk_result sk__json_numbers(const cJSON *obj, const char *where, const char *key, int n, double *out,
                           bool *found, sk_error *err);
/* Items of an array (counted by walking it: cJSON_GetArraySize is not needed then). */
int sk__json_count(const cJSON *array);
/* An optional array member of indices into a top-level array of `count` objects: every
   item checked ("<where>.<key>[k]: ..."), *n its length, and the indices written to `out`
   (n of them) when it is not NULL. */
sk_result sk__json_indices(const cJSON *obj, const char *where, const char *key, int count,
                           const char *array, int *out, int *n, sk_error *err);

/* ---- the reader's walk over top-level arrays (gltf_read.c) */

/* The top-level array `key` (NULL when absent) and its length. */
sk_result sk__gltf_items(const struct sk_gltf_doc *doc, const char *key, const cJSON **array,
                         int *count, sk_error *err);
/* Calls `fn` on each item of `array` (which must all be objects) with its path "key[i]". */
typedef sk_result (*sk__gltf_item_fn)(struct sk_gltf_doc *doc, const cJSON *item, int index,
                                      const char *where, void *user, sk_error *err);
sk_result sk__gltf_each_item(struct sk_gltf_doc *doc, const cJSON *array, const char *key,
                             sk__gltf_item_fn fn, void *user, sk_error *err);
/* A zeroed array of `count` items charged against the cap (SK_ERROR_LIMIT beyond it); NULL
   with *r set on failure. */
void *sk__gltf_doc_alloc(struct sk_gltf_doc *doc, int count, size_t size, const char *what,
                         sk_result *r, sk_error *err);

/* ---- accessors (gltf_doc.c) */

/* Element `i`, component `c` of accessor `a` as a float (normalised integers converted as
   glTF 2.0 sec. 3.11 says; other integers as their value). No bounds checks: the reader
   checked the accessor against its buffer view. */
float sk__gltf_accessor_value(const struct sk_gltf_doc *doc, const sk__gltf_accessor *a, size_t i,
                              int c);
/* The same as an exact unsigned integer (for index and joint accessors). */
uint32_t sk__gltf_accessor_uint(const struct sk_gltf_doc *doc, const sk__gltf_accessor *a, size_t i,
                                int c);

#endif
