/* Private structures of the glTF 2.0 writer: the document as the add calls build it (every
 * array copied from the caller and checked), the growable arrays behind it, node transforms,
 * and the glTF constants both the writer and the reader use (not installed). */
#ifndef SK_IO_GLTF_INTERNAL_H
#define SK_IO_GLTF_INTERNAL_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include <cjson/cJSON.h>

#include "shitsukan/gltf.h"

/* glTF 2.0 sec. 3.6.2.2: accessor component types (the GL enums) and buffer view targets. */
#define SK__GLTF_BYTE 5120
#define SK__GLTF_UNSIGNED_BYTE 5121
#define SK__GLTF_SHORT 5122
#define SK__GLTF_UNSIGNED_SHORT 5123
#define SK__GLTF_UNSIGNED_INT 5125
#define SK__GLTF_FLOAT 5126
#define SK__GLTF_ARRAY_BUFFER 34962
#define SK__GLTF_ELEMENT_ARRAY_BUFFER 34963
#define SK__GLTF_TRIANGLES 4

/* GLB container (glTF 2.0 sec. 4.4): magic "glTF", version 2, chunk types "JSON", "BIN\0". */
#define SK__GLB_MAGIC 0x46546C67u
#define SK__GLB_VERSION 2u
#define SK__GLB_CHUNK_JSON 0x4E4F534Au
#define SK__GLB_CHUNK_BIN 0x004E4942u
#define SK__GLB_HEADER_BYTES 12u
#define SK__GLB_CHUNK_HEADER_BYTES 8u

/* Caps that keep every count an int and every size computable. */
#define SK__GLTF_MAX_OBJECTS (1 << 20) /* of each kind: nodes, meshes, channels, ... */
#define SK__GLTF_MAX_JOINTS 65536      /* JOINTS_0 holds unsigned shorts */
#define SK__GLTF_MAX_TARGETS 4096

/* A vertex's weights may miss 1 by this much before the writer refuses them (they are
   renormalised to float exactness on the way in). */
#define SK__GLTF_WEIGHT_SUM_TOLERANCE 1e-3
/* Quaternions given within this of length 1 are normalised; farther off they are refused. */
#define SK__GLTF_UNIT_TOLERANCE 1e-3
/* The same for normals and tangents, which come from interpolation more often (the
   validator's own tolerance is 0.00674, so they are always normalised on the way in). */
#define SK__GLTF_VECTOR_TOLERANCE 1e-2

typedef struct sk__gltf_image {
    uint8_t *png; /* encoded PNG bytes */
    size_t size;
    bool has_alpha; /* some alpha below 1 (the material then blends) */
} sk__gltf_image;

typedef struct sk__gltf_material {
    char *name;
    float base_color[4];
    float metallic, roughness;
    int base_color_image; /* index into images or -1 */
    int normal_image;
    float normal_scale;
    bool double_sided;
    float emissive[3];
    int emissive_image;
} sk__gltf_material;

typedef struct sk__gltf_mesh {
    char *name;
    size_t vertex_count, triangle_count;
    float *positions;  /* 3 per vertex */
    float *normals;    /* 3, unit, or NULL */
    float *uvs;        /* 2, glTF's top-left origin, or NULL */
    float *colors;     /* 3, linear in [0, 1], or NULL */
    float *tangents;   /* 4 (xyz unit, w = +-1) when the material has a normal texture */
    uint32_t *indices; /* 3 per triangle */
    int material;
    uint16_t *joints; /* 4 per vertex, 0 where the weight is 0, or NULL */
    float *weights;   /* 4 per vertex, float sums exactly 1 (see gltf_mesh.c) */
    int max_joint;    /* largest joint index used, -1 without skinning */
    int target_count;
    float *target_positions; /* target_count * vertex_count * 3, or NULL */
    float *target_normals;
    float *default_weights; /* target_count, or NULL */
    char **target_names;    /* target_count, or NULL */
} sk__gltf_mesh;

typedef struct sk__gltf_node {
    char *name;
    int parent;
    double translation[3], rotation[4], scale[3]; /* rotation unit (x, y, z, w) */
    int mesh, skin;
    bool has_child;
} sk__gltf_node;

typedef struct sk__gltf_skin {
    char *name;
    int *joints;
    int joint_count;
    float *inverse_bind; /* 16 per joint, column-major, last row exactly (0, 0, 0, 1) */
} sk__gltf_skin;

typedef struct sk__gltf_channel {
    int node;
    sk_gltf_path path;
    sk_gltf_interpolation interpolation; /* resolved: LINEAR or STEP */
    int key_count;
    int components; /* values per key */
    float *times;
    float *values; /* key_count * components */
} sk__gltf_channel;

typedef struct sk__gltf_animation {
    char *name;
    sk__gltf_channel *channels;
    int channel_count, channel_capacity;
} sk__gltf_animation;

struct sk_gltf {
    sk__gltf_image *images;
    int image_count, image_capacity;
    sk__gltf_material *materials;
    int material_count, material_capacity;
    sk__gltf_mesh *meshes;
    int mesh_count, mesh_capacity;
    sk__gltf_node *nodes;
    int node_count, node_capacity;
    sk__gltf_skin *skins;
    int skin_count, skin_capacity;
    sk__gltf_animation *animations;
    int animation_count, animation_capacity;
};

/* Makes room for one more element of `elem` bytes in *data (count used, *capacity
 * allocated), doubling; SK_ERROR_LIMIT beyond SK__GLTF_MAX_OBJECTS. `what` names the kind
 * in the message ("nodes"). */
sk_result sk__gltf_grow(void **data, int count, int *capacity, size_t elem, const char *what,
                        sk_error *err);

/* A copy of `name`, or of "<prefix><index>" when name is NULL; NULL when out of memory. */
char *sk__gltf_name(const char *name, const char *prefix, int index);

/* Adds an image to the document as PNG bytes. `normal_map` writes 0.5 n + 0.5 linearly
 * (components in [-1, 1]), otherwise colour is written sRGB (alpha linear). */
sk_result sk__gltf_add_image(sk_gltf *gltf, const sk_image *image, bool normal_map,
                             const char *field, int *out_index, sk_error *err);

void sk__gltf_mesh_free(sk__gltf_mesh *mesh);
void sk__gltf_animation_free(sk__gltf_animation *animation);

/* ---- transforms (gltf_transform.c); matrices are column-major double[16] as in glTF */

/* T * R * S of a translation, unit quaternion (x, y, z, w) and scale. */
void sk__gltf_trs_matrix(const double t[3], const double r[4], const double s[3], double out[16]);
/* a * b */
void sk__gltf_matrix_mul(const double a[16], const double b[16], double out[16]);
/* Inverse of an affine matrix (last row 0 0 0 1); false when singular. The result's last
   row is exactly (0, 0, 0, 1). */
bool sk__gltf_affine_inverse(const double m[16], double out[16]);
/* The node's world matrix (its ancestors' transforms applied). */
void sk__gltf_node_world(const sk_gltf *gltf, int node, double out[16]);
/* Decomposes an affine matrix without shear into translation, rotation (x, y, z, w) and
   scale (a negative determinant flips the x scale). False when it has a shear, a
   projective row or a zero scale. */
bool sk__gltf_matrix_to_trs(const double m[16], double t[3], double r[4], double s[3]);

/* ---- the writer's binary chunk and accessors (gltf_accessors.c) */

/* What the writer builds: the JSON arrays of accessors and buffer views and the bytes of
 * the binary chunk. Each accessor gets its own buffer view (so no view needs a byteStride)
 * starting on a 4-byte boundary, which every component type and vertex attribute needs. */
typedef struct sk__gltf_out {
    cJSON *accessors, *views;
    uint8_t *bin;
    size_t bin_size, bin_capacity;
    int accessor_count, view_count;
    bool failed; /* out of memory (or the 4 GiB GLB limit) somewhere: the write fails */
} sk__gltf_out;

/* Appends bytes as a buffer view (target 0 = none); returns its index, -1 on failure. */
int sk__gltf_put_view(sk__gltf_out *out, const void *data, size_t bytes, int target);
/* Float vectors of 1-4 components or MAT4 (16) as one accessor; with `bounds` min and max
   are written, exactly the float values (the validator compares them bit for bit). */
int sk__gltf_put_floats(sk__gltf_out *out, const float *data, size_t count, int components,
                        int target, bool bounds);
/* Triangle indices as UNSIGNED_SHORT when every index is below 65535 (the primitive
   restart value is not allowed), else UNSIGNED_INT. */
int sk__gltf_put_indices(sk__gltf_out *out, const uint32_t *indices, size_t count,
                         size_t vertex_count);
/* JOINTS_0: VEC4 of UNSIGNED_BYTE when max_joint < 256, else UNSIGNED_SHORT. */
int sk__gltf_put_joints(sk__gltf_out *out, const uint16_t *joints, size_t vertex_count,
                        int max_joint);
/* A cJSON call result, recording an allocation failure. */
cJSON *sk__gltf_json(sk__gltf_out *out, cJSON *item);

#endif
