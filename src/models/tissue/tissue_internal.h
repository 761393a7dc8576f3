/* Private structures of the tissue module (Shigemori & Kawai fat model): the skeleton,
 * bones and muscles in their frames, the voxel grid of the skin generation, and the
 * built model's points and springs. */
#ifndef SK_TISSUE_INTERNAL_H
#define SK_TISSUE_INTERNAL_H

#include <stdint.h>

#include "shitsukan/tissue.h"

/* ------------------------------------------------------------ ellipsoids */
/* An ellipsoid in some frame: centre, orthonormal axes (columns X, Y, Z) and semi-axes. */
typedef struct sk__ellipsoid {
    sk_vec3d centre;
    sk_mat3d axes;
    sk_vec3d radii;
} sk__ellipsoid;

/* (x/a)^2 + (y/b)^2 + (z/c)^2 of p in the ellipsoid's own coordinates (< 1 inside). */
double sk__ellipsoid_level(const sk__ellipsoid *e, sk_vec3d p);
/* Axis-aligned bounds of the ellipsoid. */
void sk__ellipsoid_bounds(const sk__ellipsoid *e, sk_vec3d *lo, sk_vec3d *hi);
/* The ellipsoid moved by rotation r then translation t. */
sk__ellipsoid sk__ellipsoid_transform(const sk__ellipsoid *e, sk_mat3d r, sk_vec3d t);
/* Moves p out of the ellipsoid along the ray from its centre, to `margin` beyond the
 * surface (in level units: the result has level (1 + margin)^2). Returns whether p moved. */
bool sk__ellipsoid_push_out(const sk__ellipsoid *e, sk_vec3d *p, double margin);
/* An orthonormal frame whose Z is `z` and whose X is `hint` made orthogonal to it (a
 * hint along z falls back to the world axis most across z). */
sk_mat3d sk__frame_from_z(sk_vec3d z, sk_vec3d hint);
/* The world axis most across `z` (X, then Y, then Z on ties). */
sk_vec3d sk__axis_across(sk_vec3d z);

/* ------------------------------------------------------------ skeleton */
typedef struct sk__skeleton {
    int count;
    int root;
    int parent[SK_TISSUE_MAX_JOINTS];
    int order[SK_TISSUE_MAX_JOINTS]; /* every parent before its children */
    sk_vec3d offset[SK_TISSUE_MAX_JOINTS];
    sk_vec3d rest[SK_TISSUE_MAX_JOINTS]; /* rest world positions (mm) */
} sk__skeleton;

sk_result sk__skeleton_build(const sk_tissue_character_desc *desc, sk__skeleton *out,
                             sk_error *err);
int sk__joint_find(const sk_tissue_character_desc *desc, const char *name);
/* World pose from local rotations (relative to rest) and the root position. */
void sk__skeleton_pose(const sk__skeleton *s, const sk_quatd *local, sk_vec3d root,
                       sk_tissue_pose *out);
/* A world point carried by joint j: the pose's transform of a point given in the joint's
 * rest frame (offset from the joint's rest position). */
static inline sk_vec3d sk__pose_apply(const sk_tissue_pose *pose, int j, sk_vec3d local)
{
    return sk_v3d_add(pose->position[j], sk_qd_rotate(pose->rotation[j], local));
}

/* ------------------------------------------------------------ bones */
typedef struct sk__bone {
    int joint;           /* carrying joint */
    sk_vec3d start, end; /* in the joint's rest frame (mm from the joint) */
    double length;
    sk__ellipsoid part[3]; /* start end, shaft, far end; in the joint's rest frame */
    sk_vec3d bound_centre; /* bounding sphere of the three, joint frame */
    double bound_radius;
} sk__bone;

sk_result sk__bones_build(const sk_tissue_character_desc *desc, const sk__skeleton *s,
                          sk__bone *bones, sk_error *err);
/* The point `at` along a bone plus an offset, in the bone's joint rest frame. */
sk_vec3d sk__bone_point(const sk__bone *b, double at, sk_vec3d offset);

/* ------------------------------------------------------------ muscles */
typedef struct sk__muscle {
    int origin_bone, insertion_bone;
    int origin_joint, insertion_joint;
    sk_vec3d origin, insertion; /* in their joints' rest frames */
    double rest_length;         /* L0 */
    double a0, b0, c0;          /* rest semi-axes */
    sk_vec3d x_rest, z_rest;    /* X and Z directions in the origin joint's rest frame */
} sk__muscle;

/* A muscle's current shape: its ellipsoid in the world. */
typedef struct sk__muscle_state {
    sk__ellipsoid body;
} sk__muscle_state;

sk_result sk__muscles_build(const sk_tissue_character_desc *desc, const sk__skeleton *s,
                            const sk__bone *bones, sk__muscle *muscles, sk_error *err);
/* The muscle's deformed ellipsoid for a pose (sec. 3). */
void sk__muscle_shape(const sk__muscle *m, const sk_tissue_pose *pose, sk__ellipsoid *out);

/* Index of a bone / muscle by name, or -1. */
int sk__bone_find(const sk_tissue_character_desc *desc, const char *name);
int sk__muscle_find(const sk_tissue_character_desc *desc, const char *name);

/* ------------------------------------------------------------ voxel grid */
/* Labels of grid points: 0 outside tissue, 1 + b for bone b, 1 + MAX_BONES + m for
 * muscle m. */
#define SK__LABEL_NONE 0
#define SK__LABEL_MUSCLE0 (1 + SK_TISSUE_MAX_BONES)
typedef uint16_t sk__label;

typedef struct sk__grid {
    int n[3];
    size_t count; /* n[0] n[1] n[2] */
    double spacing;
    sk_vec3d origin; /* position of grid point (0, 0, 0) */
} sk__grid;

static inline size_t sk__grid_index(const sk__grid *g, int x, int y, int z)
{
    return ((size_t)z * (size_t)g->n[1] + (size_t)y) * (size_t)g->n[0] + (size_t)x;
}
static inline sk_vec3d sk__grid_position(const sk__grid *g, size_t index)
{
    size_t x = index % (size_t)g->n[0], y = (index / (size_t)g->n[0]) % (size_t)g->n[1];
    size_t z = index / ((size_t)g->n[0] * (size_t)g->n[1]);
    return sk_v3d(g->origin.x + g->spacing * (double)x, g->origin.y + g->spacing * (double)y,
                  g->origin.z + g->spacing * (double)z);
}
static inline void sk__grid_coords(const sk__grid *g, size_t index, int c[3])
{
    c[0] = (int)(index % (size_t)g->n[0]);
    c[1] = (int)((index / (size_t)g->n[0]) % (size_t)g->n[1]);
    c[2] = (int)(index / ((size_t)g->n[0] * (size_t)g->n[1]));
}

/* The rest tissue: bone and muscle ellipsoids in world coordinates. */
typedef struct sk__tissue_shapes {
    int bone_count, muscle_count;
    sk__ellipsoid bone[SK_TISSUE_MAX_BONES][3];
    sk__ellipsoid muscle[SK_TISSUE_MAX_MUSCLES];
} sk__tissue_shapes;

/* The label of the tissue at a world point (bones before muscles; the deepest inside). */
sk__label sk__tissue_label_at(const sk__tissue_shapes *t, sk_vec3d p);
/* Labels every grid point (parallel over slices). */
sk_result sk__voxelise(const sk__grid *g, const sk__tissue_shapes *t, sk__label *labels,
                       sk_error *err);

/* Euclidean distance (mm) from every grid point of the box [lo, hi] (grid indices) to the
 * nearest labelled point inside the box, exact (Felzenszwalb & Huttenlocher 2012,
 * separable squared distance transform); `distance` holds the box's points, x fastest.
 * (A point's distance is exact if the nearest tissue lies inside the box.) */
sk_result sk__distance_to_tissue(const sk__grid *g, const sk__label *labels, const int lo[3],
                                 const int hi[3], float *distance, sk_error *err);

/* Marks (sets 1) the grid points of the character's fat regions. */
sk_result sk__fat_regions_mark(const sk_tissue_character_desc *desc, const sk__skeleton *s,
                               const sk__bone *bones, const sk__muscle *muscles, const sk__grid *g,
                               const sk__label *labels, uint8_t *fat, sk_error *err);

/* The paper's dilation: values start at 1 on seeds, `passes` times every positive point
 * adds w(d) to the points within radius (see tissue.h). */
sk_result sk__dilate(const sk__grid *g, const uint8_t *seed, int passes, double radius_mm,
                     float *value, sk_error *err);

/* ------------------------------------------------------------ isosurface */
/* The cells (cubes of 8 grid points, indexed by their lowest corner) inside the skin: all
 * corners are points, connected to tissue, manifold boundary. Returns the number of
 * cells removed to keep the boundary manifold. */
sk_result sk__skin_cells(const sk__grid *g, const uint8_t *is_point, const sk__label *labels,
                         uint8_t *inside, size_t *removed, sk_error *err);
/* Where the inside cells are: for each row (y, z) of cells the range of x holding inside
 * cells (lo > hi for none), so scans over the grid skip the empty rows. */
typedef struct sk__cell_rows {
    int *lo, *hi; /* n[1] x n[2] rows, y fastest */
} sk__cell_rows;
sk_result sk__cell_rows_make(const sk__grid *g, const uint8_t *inside, sk__cell_rows *rows,
                             sk_error *err);
void sk__cell_rows_free(sk__cell_rows *rows);
/* The x range [lo, hi] of grid points (or vertices) of row (y, z) that are corners of
 * inside cells: the union of the four cell rows around it (false if none). */
bool sk__cell_rows_corners(const sk__grid *g, const sk__cell_rows *rows, int y, int z, int *lo,
                           int *hi);

/* The boundary of the inside cells as triangles whose vertices are grid points
 * (counter-clockwise seen from outside): grid indices of the vertices, 3 per triangle. */
sk_result sk__skin_faces(const sk__grid *g, const uint8_t *inside, size_t **out_corners,
                         size_t *out_triangles, sk_error *err);

/* ------------------------------------------------------------ springs */
/* Spring classes (the paper's: skin-skin along triangle edges, skin-fat, fat-fat,
 * fat-muscle / fat-bone). */
enum {
    SK__SPRING_SKIN = 0,
    SK__SPRING_SKIN_FAT,
    SK__SPRING_FAT,
    SK__SPRING_ANCHOR,
    SK__SPRING_CLASS_COUNT
};

/* Neighbour directions on the grid (the half of them with first non-zero component
 * positive): 9 for the 18-neighbourhood, 13 for the 26-neighbourhood. */
int sk__lattice_directions(int neighbourhood, int dirs[13][3]);
/* Index of the half-direction of d (either sign) among `dirs`, or -1. */
int sk__lattice_direction_index(int dirs[13][3], int count, const int d[3]);

/* ------------------------------------------------------------ model */
struct sk_tissue_model {
    sk_tissue_character_desc desc;
    sk__skeleton skeleton;
    sk__bone bones[SK_TISSUE_MAX_BONES];
    sk__muscle muscles[SK_TISSUE_MAX_MUSCLES];
    sk__grid grid;
    int neighbourhood;
    /* Points: skin points first (in rest-skin vertex order), then fat points (these two
       are the free points), then muscle points, then bone points. */
    size_t point_count, skin_count, fat_count, muscle_count, bone_count;
    size_t *grid_of;        /* grid index of every point */
    sk_vec3d *rest;         /* rest world position (skin points: after smoothing) */
    double *mass;           /* kg; 0 for muscle and bone points */
    int *owner;             /* muscle/bone points: muscle or bone index; free points: the
                               bone that carries them (or their muscle's origin bone) */
    int *carrier_muscle;    /* free points: the muscle that carries them, or -1 (a bone) */
    uint64_t *near_muscles; /* free points: bit i set when muscle i is near at rest (the
                               muscles the point is kept out of) */
    sk_vec3d *local;        /* bone points: position in the bone joint's rest frame;
                               muscle points: coordinates in units of the rest semi-axes;
                               free points: the same for the tissue nearest them at rest
                               (their carrier), so the tissue alone can carry them: the
                               skin without the fat layer */
    /* Springs sorted by colour: colour c holds springs colour_start[c] .. [c + 1]. */
    size_t spring_count;
    uint32_t *spring_i, *spring_j;
    double *spring_rest; /* mm */
    uint8_t *spring_class;
    int colour_count;
    size_t colour_start[27];
    size_t class_count[SK__SPRING_CLASS_COUNT];
    /* Rest skin triangles (indices of skin points). */
    size_t triangle_count;
    uint32_t *triangles;
    int tracked_point[SK_TISSUE_MAX_TRACKED]; /* skin point of each tracked desc */
    int32_t *grid_point; /* during the build only: point index of every grid point, or -1 */
    sk_tissue_model_stats stats;
};

/* Builds the points, springs and skin mesh of a model from its grid classification. */
typedef struct sk__skin_build {
    const sk__grid *grid;
    const sk__label *labels;
    const uint8_t *inside; /* cells */
    const size_t *corners; /* skin triangle vertices (grid indices) */
    size_t triangles;
} sk__skin_build;
sk_result sk__model_points(sk_tissue_model *m, const sk__skin_build *b, sk_error *err);
sk_result sk__model_springs(sk_tissue_model *m, sk_error *err);
/* Optional rest-skin smoothing (Taubin's lambda/mu), vertices kept outside the tissue. */
sk_result sk__skin_smooth(sk_tissue_model *m, const sk__tissue_shapes *t, int iterations,
                          sk_error *err);
/* Masses, reference bones and local coordinates (after the rest positions are final). */
void sk__model_attach(sk_tissue_model *m, const sk__tissue_shapes *t);

/* ------------------------------------------------------------ outputs */
struct cJSON;
/* The model's stats as a JSON object (NULL when out of memory). */
struct cJSON *sk__model_stats_json(const sk_tissue_model *m);
/* The skin's frames (positions and normals, 3 floats per vertex, frame-major) as a glTF
 * of the rest mesh (with normals) and one morph target per frame, animated at fps. */
sk_result sk__write_skin_glb(const sk_mesh *rest, const float *positions, const float *normals,
                             int frames, int first_frame, int fps, const char *path, sk_error *err);

#endif /* SK_TISSUE_INTERNAL_H */
