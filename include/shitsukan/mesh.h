/* shitsukan triangle meshes and point clouds: positions, optional normals, UVs, colours
 * and named per-vertex attributes; OBJ (+MTL) and PLY (ASCII, binary little/big endian)
 * readers with strict validation, and OBJ and binary little-endian PLY writers.
 *
 * Thread-safety: all functions are thread-safe on distinct meshes. */
#ifndef SHITSUKAN_MESH_H
#define SHITSUKAN_MESH_H

#include "shitsukan/core.h"

#ifdef __cplusplus
extern "C" {
#endif

#define SK_MESH_MAX_ATTRIBUTES 8
#define SK_MESH_ATTRIBUTE_NAME_SIZE 32

/* A named per-vertex attribute with 1-4 float components (e.g. "weight", "curvature"). */
typedef struct sk_mesh_attribute {
    char name[SK_MESH_ATTRIBUTE_NAME_SIZE];
    int components;
    float *data; /* vertex_count * components */
} sk_mesh_attribute;

/* Indexed triangle mesh; triangle_count = 0 makes it a point cloud. Optional arrays are
 * NULL when absent. Triangles wind counter-clockwise seen from the front. */
typedef struct sk_mesh {
    size_t vertex_count;
    float *positions; /* 3 per vertex */
    float *normals;   /* 3 per vertex, unit length, or NULL */
    float *uvs;       /* 2 per vertex, or NULL */
    float *colors;    /* 3 per vertex, linear RGB in [0, 1], or NULL (in memory always
                         linear; the OBJ and PLY files hold them sRGB-encoded, as Blender,
                         MeshLab and other tools read them) */
    size_t triangle_count;
    uint32_t *indices; /* 3 per triangle, each < vertex_count */
    int attribute_count;
    sk_mesh_attribute attributes[SK_MESH_MAX_ATTRIBUTES];
} sk_mesh;

/* Which optional arrays sk_mesh_create allocates. */
typedef enum sk_mesh_flags {
    SK_MESH_NORMALS = 1 << 0,
    SK_MESH_UVS = 1 << 1,
    SK_MESH_COLORS = 1 << 2
} sk_mesh_flags;

/* Allocates zero-filled arrays. Counts beyond the caps of sk_mesh_read_desc's defaults
 * (2 GiB of arrays, 2^32 vertices) fail with SK_ERROR_LIMIT before allocating; triangles
 * without vertices or unknown flags are SK_ERROR_INVALID_ARGUMENT. */
sk_result sk_mesh_create(sk_mesh *mesh, size_t vertex_count, size_t triangle_count, int flags,
                         sk_error *err);
/* Adds a zero-filled attribute (name 1-31 bytes, 1-4 components); fails if the name
 * exists (SK_ERROR_INVALID_ARGUMENT) or all slots are used (SK_ERROR_LIMIT). */
sk_result sk_mesh_add_attribute(sk_mesh *mesh, const char *name, int components, float **out_data,
                                sk_error *err);
/* NULL if absent. */
const sk_mesh_attribute *sk_mesh_find_attribute(const sk_mesh *mesh, const char *name);
void sk_mesh_free(sk_mesh *mesh);

/* Checks the invariants: indices in range, positions/normals/uvs/colours finite,
 * attributes well formed. Fails with SK_ERROR_INVALID_ARGUMENT naming the element. */
sk_result sk_mesh_validate(const sk_mesh *mesh, sk_error *err);
/* Computes area-weighted vertex normals (allocating `normals` if absent): each triangle
 * adds its cross product (twice its area times its unit normal) to its corners. Vertices
 * on no triangle of non-zero area (e.g. all of a point cloud) get (0, 0, 1). */
sk_result sk_mesh_compute_normals(sk_mesh *mesh, sk_error *err);
/* Adds a 4-component "tangent" attribute (xyz a unit tangent along +u, w = +-1 the
 * handedness: the bitangent is w * normal x tangent, as glTF's TANGENT) computed from
 * positions, normals and UVs: each triangle's dP/du and dP/dv summed per vertex with the
 * triangle's area as weight, then orthogonalised against the normal. A mesh without UVs
 * or normals gets an arbitrary tangent frame; one that has a 4-component "tangent"
 * attribute keeps it. */
sk_result sk_mesh_compute_tangents(sk_mesh *mesh, sk_error *err);
/* Axis-aligned bounds of the positions; false for an empty mesh. */
bool sk_mesh_bounds(const sk_mesh *mesh, sk_vec3f *lo, sk_vec3f *hi);

/* ------------------------------------------------------------------ reading */
typedef struct sk_mesh_read_desc {
    /* Cap on the memory a file may make the reader allocate; a header or count needing
       more fails with SK_ERROR_LIMIT before allocating. 0 = 2 GiB. */
    size_t max_bytes;
} sk_mesh_read_desc;

/* Reads OBJ: v (with optional r g b, sRGB-encoded in the file, decoded to linear), vt, vn, f with
 * v, v/vt, v//vn, v/vt/vn and negative (relative) indices; polygons are triangulated;
 * o/g/s/usemtl/mtllib lines are accepted and ignored; a file with only v lines is a point cloud.
 * Malformed lines, indices out of range and non-finite numbers fail with SK_ERROR_PARSE naming the
 * line.
 *
 * Details: each distinct (v, vt, vn) triple used by a face becomes one vertex (numbered in
 * order of first use; v lines no face uses are dropped). An index refers to an element
 * defined earlier in the file. File normals are normalised; corners without vn (or with
 * a zero vn) in a file that has some get computed normals. Vertices without a colour in a
 * file where others have one are white. "v x y z w" is accepted (w dropped). Polygons are
 * ear-clipped in their best-fit plane, polygons of more than 512 corners fanned. Lines
 * (l), points (p) and free-form geometry are skipped; unknown statements are errors.
 * A missing file is SK_ERROR_NOT_FOUND; a file larger than the cap is SK_ERROR_LIMIT. */
sk_result sk_mesh_read_obj(sk_mesh *mesh, const char *path, const sk_mesh_read_desc *desc,
                           sk_error *err);
/* Reads PLY 1.0 (ascii, binary_little_endian, binary_big_endian): vertex x y z, optional
 * nx ny nz, u v (or s t, texture_u texture_v), red green blue (8-bit or float), other
 * scalar vertex properties as 1-component attributes; face vertex_indices (or
 * vertex_index) lists, polygons triangulated; other elements skipped.
 *
 * Details: colours are sRGB-encoded in the file and decoded to linear: integer colours are
 * divided by their type's maximum (uchar 255, ushort 65535) first, float colours taken as
 * the encoded value. A run of properties "<name>_0", "<name>_1" .. (2-4 of them) is one
 * attribute "<name>" with that many components (the writer's form for vector
 * attributes); attributes beyond SK_MESH_MAX_ATTRIBUTES are skipped. Validation is strict,
 * with SK_ERROR_PARSE naming the element and record (and the line in ASCII): element
 * counts the rest of the file cannot hold, a truncated body, trailing data, an index out
 * of range, a face of fewer than 3 vertices, a non-finite value in a kept property, and in
 * ASCII a record not on its own line. Counts needing more memory than the cap fail with
 * SK_ERROR_LIMIT before allocating. Version other than 1.0: SK_ERROR_UNSUPPORTED. */
sk_result sk_mesh_read_ply(sk_mesh *mesh, const char *path, const sk_mesh_read_desc *desc,
                           sk_error *err);
/* By extension (.obj / .ply). */
sk_result sk_mesh_read(sk_mesh *mesh, const char *path, const sk_mesh_read_desc *desc,
                       sk_error *err);

/* ------------------------------------------------------------------ writing */
/* A material of the MTL file written beside an OBJ. */
typedef struct sk_obj_material {
    const char *name;         /* non-empty, no white space */
    float diffuse[3];         /* Kd: linear RGB in [0, 1] (Blender reads Kd as its linear
                                 base colour) */
    const char *texture_path; /* map_Kd, relative to the OBJ's folder, or NULL */
} sk_obj_material;

/* A run of triangles written as one OBJ object ("o name") with one material. */
typedef struct sk_obj_group {
    const char *name;      /* non-empty, no white space */
    size_t triangle_count; /* groups take the triangles in order and cover them all */
    int material;          /* index into the desc's materials, or -1 for none */
} sk_obj_group;

typedef struct sk_obj_write_desc {
    /* When set, an MTL file "<name>.mtl" is written beside the OBJ with one material
       whose diffuse map (map_Kd) is this path, and the OBJ references it. */
    const char *texture_path;
    const char *material_name; /* NULL = "material" */
    /* Several materials and objects instead (texture_path and material_name must then be
       NULL): the MTL file holds `materials`, the OBJ one "o" and "usemtl" per group. */
    const sk_obj_material *materials;
    int material_count;
    const sk_obj_group *groups;
    int group_count;
    /* Where the MTL file goes and the name the OBJ's mtllib gives it, for writing under
       names other than the final ones (the staged files of an sk_output_set): NULL =
       sk_obj_mtl_path(path), and that file's base name. */
    const char *mtl_path;
    const char *mtl_name;
} sk_obj_write_desc;

/* The MTL file sk_mesh_write_obj writes beside `obj_path`: "dir/name.obj" -> "dir/name.mtl"
 * (the extension replaced, or appended if none). NULL when out of memory; free with free(). */
char *sk_obj_mtl_path(const char *obj_path);

/* Writes v/vt/vn/f (attributes and colours are not representable in OBJ and are
 * skipped, except vertex colours as the common "v x y z r g b" extension, sRGB-encoded).
 * Floats are printed with 9 significant digits, so they read back bit-exact (colours to
 * about 1e-7, through the sRGB curve and back). With texture_path, the
 * MTL file takes the OBJ's name with the extension ".mtl", the OBJ names it by its base
 * name (mtllib), and texture_path is written as given (make it relative to the OBJ's
 * folder); material_name must have no white space. Both files are written atomically,
 * the MTL first. */
sk_result sk_mesh_write_obj(const sk_mesh *mesh, const char *path, const sk_obj_write_desc *desc,
                            sk_error *err);
/* Writes binary little-endian PLY with every array and attribute as float properties
 * (colours as sRGB-encoded uchar red/green/blue, so a linear 0.5 is code 188 and reads
 * back within half a code) and faces as "list uchar uint vertex_indices".
 * Property names: x y z, nx ny nz, s t (what Blender writes and reads), red green blue;
 * an attribute "<name>" of k > 1 components becomes "<name>_0" .. "<name>_{k-1}".
 * Attribute names must not contain white space nor be one of those standard names.
 * A point cloud has no face element. The byte order does not depend on the host. */
sk_result sk_mesh_write_ply(const sk_mesh *mesh, const char *path, sk_error *err);
/* By extension (.obj / .ply). */
sk_result sk_mesh_write(const sk_mesh *mesh, const char *path, sk_error *err);

#ifdef __cplusplus
}
#endif

#endif /* SHITSUKAN_MESH_H */
