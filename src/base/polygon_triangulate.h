/* Private polygon triangulation shared by the OBJ and PLY readers (not installed). */
#ifndef SK_IO_POLYGON_TRIANGULATE_H
#define SK_IO_POLYGON_TRIANGULATE_H

#include <stddef.h>
#include <stdint.h>

#include "shitsukan/core.h"

/* Reusable workspace, so that a mesh of many polygons does not allocate per polygon.
 * Zero-initialise; release with sk__triangulator_free. */
typedef struct sk__triangulator {
    size_t capacity;
    double *xy;     /* 2 per corner: the polygon projected into its best-fit plane */
    uint32_t *prev; /* ring of the corners not yet clipped */
    uint32_t *next;
} sk__triangulator;

/* Above this many corners a polygon is fan-triangulated: ear clipping costs up to
 * O(n^3), and a file must not be able to make the reader hang. */
#define SK__TRIANGULATE_EAR_MAX 512

/* Triangulates the polygon whose n >= 3 corners are the vertex indices `corners` into
 * `positions` (3 floats per vertex), writing n - 2 triangles to `out` as triples of corner
 * numbers (0 .. n-1, so the caller maps them to its own vertex numbering), wound like the
 * polygon. Ear clipping runs in the plane given by Newell's normal; degenerate polygons
 * (zero area, collinear, self-overlapping) that defeat it are finished as a fan, so the
 * count is always n - 2. Fails only with SK_ERROR_OUT_OF_MEMORY. */
sk_result sk__triangulate(sk__triangulator *t, const float *positions, const uint32_t *corners,
                          size_t n, uint32_t *out);
void sk__triangulator_free(sk__triangulator *t);

#endif
