/* Private helpers shared by the mesh readers and writers (not installed). */
#ifndef SK_IO_MESH_INTERNAL_H
#define SK_IO_MESH_INTERNAL_H

#include <stddef.h>

#include "shitsukan/mesh.h"

/* Default cap on what a mesh file may make a reader allocate (sk_mesh_read_desc). */
#define SK__MESH_DEFAULT_MAX_BYTES ((size_t)2 << 30)

/* desc->max_bytes, or the default when desc is NULL or the field is 0. */
size_t sk__mesh_read_cap(const sk_mesh_read_desc *desc);

/* Bytes a mesh with these counts needs: positions, the optional arrays in `flags`, the
 * indices and `attribute_floats` floats per vertex. False on overflow. */
bool sk__mesh_bytes(size_t vertex_count, size_t triangle_count, int flags, size_t attribute_floats,
                    size_t *out);

/* sk_mesh_create with an explicit cap (SK_ERROR_LIMIT beyond it, before allocating). */
sk_result sk__mesh_create_capped(sk_mesh *mesh, size_t vertex_count, size_t triangle_count,
                                 int flags, size_t max_bytes, sk_error *err);

/* Area-weighted vertex normals of `mesh` into `out` (3 floats per vertex); vertices on no
 * triangle of non-zero area get (0, 0, 1). Indices must be in range. */
sk_result sk__mesh_normals_into(const sk_mesh *mesh, float *out, sk_error *err);

/* A byte budget shared by the growing arrays of one read, so that a file cannot make the
 * reader allocate more than the cap however its content is arranged. */
typedef struct sk__budget {
    size_t used, max;
} sk__budget;

/* A growable array of `elem`-byte items. */
typedef struct sk__array {
    void *data;
    size_t count, capacity, elem;
} sk__array;

/* Makes room for `extra` more items (doubling), charging the budget. Returns SK_OK,
 * SK_ERROR_LIMIT (budget exceeded) or SK_ERROR_OUT_OF_MEMORY, without a message. */
sk_result sk__array_reserve(sk__array *a, size_t extra, sk__budget *budget);
void sk__array_free(sk__array *a);

#endif
