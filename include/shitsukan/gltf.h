/* shitsukan glTF 2.0: a writer of binary glTF (.glb) for what the modules export (static
 * meshes with materials and textures, node hierarchies, skins with joints and weights,
 * morph targets, keyframe animations of nodes and morph weights), and a strict reader of
 * the same subset, used by tests and importers.
 *
 * Conventions: glTF's own (metres are not imposed: positions are written in the units
 * the caller gives, and the caller scales, e.g. mm to m, through the root node or the
 * data); right-handed, +Y up as glTF specifies; quaternions (x, y, z, w); matrices
 * column-major; vertex colours COLOR_0 linear as glTF specifies.
 *
 * Every add call checks its input against what glTF and the Khronos validator require and
 * refuses it (SK_ERROR_INVALID_ARGUMENT naming the object and field, e.g. "meshes[2]:
 * weights[17] sum to 0.9: ...") instead of writing a file the validator would report; a
 * refused call adds nothing. What is written validates with no error, no warning and no
 * info, except the infos the caller's choices cause: a mesh's uvs without a texture that
 * reads them, objects no node uses, non-power-of-two textures. Caller arrays are copied.
 *
 * Thread-safety: a document belongs to one thread; distinct documents are independent. */
#ifndef SHITSUKAN_GLTF_H
#define SHITSUKAN_GLTF_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "shitsukan/core.h"
#include "shitsukan/image.h"
#include "shitsukan/mesh.h"

#ifdef __cplusplus
extern "C" {
#endif

/* "No such object" for the index fields below (parent, mesh, skin, material). */
#define SK_GLTF_NONE (-1)

/* A glTF document being built; objects are added in any order and referred to by the
 * index each add call returns (glTF's own indices). */
typedef struct sk_gltf sk_gltf;

sk_result sk_gltf_create(sk_gltf **out, sk_error *err);
void sk_gltf_destroy(sk_gltf *gltf);

/* ------------------------------------------------------------- materials */
typedef struct sk_gltf_material_desc {
    const char *name;    /* NULL = "material<N>" */
    float base_color[4]; /* linear RGBA factor in [0, 1]; all zero = (1, 1, 1, 1); an
                            alpha below 1 (or a texture alpha below 1) makes the
                            material alphaMode BLEND */
    float metallic;      /* [0, 1]; 0 = dielectric */
    float roughness;     /* (0, 1]; 0 = 0.5 */
    /* Optional textures, embedded as PNG in the binary chunk. base_color: linear RGB(A)
       in [0, 1] (written sRGB as glTF requires); normal: tangent-space, components in
       [-1, 1] (written as 0.5 n + 0.5, linear), 3 channels; a mesh with this material
       needs uvs, normals and a 4-component "tangent" attribute (glTF's TANGENT, e.g. from
       sk_mesh_compute_tangents). Textures are encoded as PNG when the material is added
       (the caller's image may be freed after the call). */
    const sk_image *base_color_texture;
    const sk_image *normal_texture;
    float normal_scale; /* 0 = 1 */
    bool double_sided;
    /* Light the surface gives off whatever lights it (glTF's emissive): a linear RGB factor
       in [0, 1] (all zero = none) multiplying emissive_texture (linear RGB in [0, 1],
       written sRGB; NULL = white). A texture without a factor emits nothing, so it is
       refused. */
    float emissive[3];
    const sk_image *emissive_texture;
} sk_gltf_material_desc;

sk_result sk_gltf_add_material(sk_gltf *gltf, const sk_gltf_material_desc *desc, int *out_index,
                               sk_error *err);

/* ---------------------------------------------------------------- meshes */
/* One triangle primitive. The mesh's positions, normals, uvs (TEXCOORD_0; v is flipped to
 * glTF's top-left origin when uv_origin_bottom_left is set), colours (COLOR_0, in [0, 1])
 * and indices are written as present; named attributes are not written, except "tangent"
 * (TANGENT) when the material has a normal texture. Normals and tangents within 1 % of
 * unit length are normalised (farther off they are refused). Accessor min/max are exact.
 * Indices are UNSIGNED_SHORT below 65535 vertices, else UNSIGNED_INT. Note that the
 * all-zero desc names material 0: set `material` to SK_GLTF_NONE for none. */
typedef struct sk_gltf_mesh_desc {
    const char *name;
    const sk_mesh *mesh;
    bool uv_origin_bottom_left; /* the mesh's v runs up (OBJ convention) */
    int material;               /* SK_GLTF_NONE or an index from sk_gltf_add_material */
    /* Skinning (JOINTS_0 / WEIGHTS_0): 4 per vertex; joints index the skin's joint list;
       each vertex's weights are >= 0 and sum to 1 within 1e-3 (renormalised on write to
       the exactness the validator requires); unused slots have weight 0 (their joint is
       written as 0); a joint appears at most once among a vertex's non-zero weights.
       JOINTS_0 is UNSIGNED_BYTE when every joint index is below 256. NULL = not skinned. */
    const uint16_t *joints;
    const float *weights;
    /* Morph targets: target_count position displacement sets (vertex_count * 3 each,
       target-major), optional normal displacements of the same layout; default weights
       (target_count values) or NULL = zeros; names or NULL (non-empty and distinct,
       written as mesh.extras.targetNames, which Blender and three.js read as shape key /
       morph names). target_count in [0, 4096]. */
    int target_count;
    const float *target_positions;
    const float *target_normals;
    const float *default_weights;
    const char *const *target_names;
} sk_gltf_mesh_desc;

sk_result sk_gltf_add_mesh(sk_gltf *gltf, const sk_gltf_mesh_desc *desc, int *out_index,
                           sk_error *err);

/* ----------------------------------------------------------------- nodes */
/* A node that carries a skinned mesh must be a root with the identity transform (glTF
 * ignores both there: the joints place the mesh) and name a skin whose joints cover the
 * mesh's joint indices; a skin needs a skinned mesh. */
typedef struct sk_gltf_node_desc {
    const char *name; /* NULL = "node<N>" */
    int parent;       /* SK_GLTF_NONE = a root of the scene; else an earlier node */
    double translation[3];
    double rotation[4]; /* unit quaternion x, y, z, w (normalised within 1e-3 of unit
                           length, refused farther off); all zero = identity */
    double scale[3];    /* all zero = (1, 1, 1) */
    int mesh;           /* SK_GLTF_NONE or a mesh index */
    int skin;           /* SK_GLTF_NONE or a skin index (needs a skinned mesh) */
} sk_gltf_node_desc;

/* A desc with no parent, mesh or skin and the identity transform. */
sk_gltf_node_desc sk_gltf_node_desc_default(void);
sk_result sk_gltf_add_node(sk_gltf *gltf, const sk_gltf_node_desc *desc, int *out_index,
                           sk_error *err);

/* ----------------------------------------------------------------- skins */
/* joints: node indices, distinct, with a common root (add them before the skin);
 * inverse_bind: 16 floats per joint, column-major with the last row (0, 0, 0, 1), or
 * NULL = the inverses of the joints' world transforms as the nodes stand (the bind
 * pose). name NULL = "skin<N>". */
sk_result sk_gltf_add_skin(sk_gltf *gltf, const char *name, const int *joints, int joint_count,
                           const float *inverse_bind, int *out_index, sk_error *err);

/* ------------------------------------------------------------ animations */
typedef enum sk_gltf_path {
    SK_GLTF_PATH_TRANSLATION = 0, /* 3 floats per key */
    SK_GLTF_PATH_ROTATION,        /* 4 floats per key (x, y, z, w) */
    SK_GLTF_PATH_SCALE,           /* 3 floats per key */
    SK_GLTF_PATH_WEIGHTS          /* target_count floats per key (morph weights) */
} sk_gltf_path;

typedef enum sk_gltf_interpolation {
    SK_GLTF_INTERPOLATION_DEFAULT = 0, /* = LINEAR */
    SK_GLTF_INTERPOLATION_LINEAR,
    SK_GLTF_INTERPOLATION_STEP
} sk_gltf_interpolation;

sk_result sk_gltf_add_animation(sk_gltf *gltf, const char *name, int *out_index, sk_error *err);
/* One channel: key times in seconds (strictly increasing, >= 0) and values. Identical
 * time arrays share one accessor. Rotations are normalised (refused farther than 1e-3
 * from unit length); weights need a node whose mesh has morph targets; translation,
 * rotation and scale of a node with a skinned mesh are refused (glTF ignores them); a
 * node and path animated twice in one animation are refused. An animation needs at least
 * one channel by the time it is written. name NULL = "animation<N>". */
sk_result sk_gltf_add_channel(sk_gltf *gltf, int animation, int node, sk_gltf_path path,
                              sk_gltf_interpolation interpolation, const float *times,
                              int key_count, const float *values, sk_error *err);

/* ----------------------------------------------------------------- write */
typedef struct sk_gltf_write_desc {
    const char *generator; /* asset.generator; NULL = "shitsukan <version>" */
    const char *copyright; /* NULL = none */
} sk_gltf_write_desc;

/* Writes the document as one .glb file (atomically: a failed write leaves no file). The
 * same document always gives the same bytes. Fails with SK_ERROR_INVALID_ARGUMENT for an
 * animation without channels, SK_ERROR_LIMIT beyond the GLB's 4 GiB. */
sk_result sk_gltf_write_glb(const sk_gltf *gltf, const char *path, const sk_gltf_write_desc *desc,
                            sk_error *err);
/* The same bytes into memory (free with free()). */
sk_result sk_gltf_write_glb_memory(const sk_gltf *gltf, const sk_gltf_write_desc *desc,
                                   uint8_t **out_data, size_t *out_size, sk_error *err);

/* ------------------------------------------------------------------ read */
/* A parsed .glb: the JSON and the binary chunk, checked (chunk layout, buffer views and
 * accessors inside the buffer, indices in range, component types and counts consistent).
 * Objects are reached by index through the functions below.
 *
 * Strictness: every failure names the JSON path of what is wrong ("accessors[3].count:
 * ...") with SK_ERROR_PARSE: the GLB header, chunk lengths (multiples of 4, adding up to
 * the file), JSON syntax, types and ranges of every property read, buffer views inside
 * the BIN chunk, accessors inside their views and aligned to their components, attribute
 * formats, equal vertex counts, index and joint values in range, one parent per node and
 * no loops, animation key times strictly increasing and >= 0, output counts by path.
 * SK_ERROR_UNSUPPORTED names what is valid glTF but not read: sparse accessors,
 * CUBICSPLINE interpolation, buffers with a uri, required extensions, glTF 1.0. Unknown
 * chunk types are skipped. Only the first primitive of a mesh is reached by the queries
 * (all are checked). */
typedef struct sk_gltf_doc sk_gltf_doc;

typedef struct sk_gltf_read_desc {
    size_t max_bytes; /* cap on the file and on what it makes the reader allocate (the
                         JSON tree is charged 40 bytes per byte of JSON text, its worst
                         case; each accessor read is capped alone); 0 = 1 GiB */
} sk_gltf_read_desc;

sk_result sk_gltf_read_glb(sk_gltf_doc **out, const char *path, const sk_gltf_read_desc *desc,
                           sk_error *err);
sk_result sk_gltf_read_glb_memory(sk_gltf_doc **out, const uint8_t *data, size_t size,
                                  const sk_gltf_read_desc *desc, sk_error *err);
void sk_gltf_doc_free(sk_gltf_doc *doc);

typedef struct sk_gltf_doc_counts {
    int nodes, meshes, skins, animations, materials, images, accessors;
} sk_gltf_doc_counts;
sk_gltf_doc_counts sk_gltf_doc_count(const sk_gltf_doc *doc);

typedef struct sk_gltf_doc_node {
    const char *name;                             /* "" when unnamed; owned by the doc */
    int parent;                                   /* SK_GLTF_NONE for roots */
    int mesh, skin;                               /* SK_GLTF_NONE when absent */
    double translation[3], rotation[4], scale[3]; /* from TRS or decomposed matrix */
} sk_gltf_doc_node;
sk_result sk_gltf_doc_get_node(const sk_gltf_doc *doc, int index, sk_gltf_doc_node *out,
                               sk_error *err);

/* Reads accessor `index` as floats (normalised integers converted as glTF specifies;
 * integer accessors converted exactly, as far as a float holds them: up to 2^24),
 * `components` per element (16 for MAT4) into a new array (free with free()). */
sk_result sk_gltf_doc_read_accessor(const sk_gltf_doc *doc, int index, float **out_values,
                                    size_t *out_count, int *out_components, sk_error *err);

/* Accessor indices of a mesh's first primitive by attribute name ("POSITION",
 * "JOINTS_0", ...; "indices" for the index accessor), morph target t's "POSITION"
 * through sk_gltf_doc_mesh_target_accessor; -1 when absent. */
int sk_gltf_doc_mesh_accessor(const sk_gltf_doc *doc, int mesh, const char *attribute);
int sk_gltf_doc_mesh_target_count(const sk_gltf_doc *doc, int mesh);
int sk_gltf_doc_mesh_target_accessor(const sk_gltf_doc *doc, int mesh, int target,
                                     const char *attribute);

/* A skin's joints (node indices, owned by the doc) and its inverse-bind accessor. */
sk_result sk_gltf_doc_get_skin(const sk_gltf_doc *doc, int index, const int **out_joints,
                               int *out_joint_count, int *out_inverse_bind_accessor, sk_error *err);

/* An animation's channels: node, path, and the sampler's input/output accessors. */
typedef struct sk_gltf_doc_channel {
    int node;
    sk_gltf_path path;
    sk_gltf_interpolation interpolation;
    int input_accessor, output_accessor;
} sk_gltf_doc_channel;
int sk_gltf_doc_channel_count(const sk_gltf_doc *doc, int animation);
sk_result sk_gltf_doc_get_channel(const sk_gltf_doc *doc, int animation, int channel,
                                  sk_gltf_doc_channel *out, sk_error *err);

#ifdef __cplusplus
}
#endif

#endif /* SHITSUKAN_GLTF_H */
