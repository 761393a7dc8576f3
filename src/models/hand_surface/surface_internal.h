/* Private parts of the hand surface (thesis 4.1 on a surface built from the skeleton):
 * the flesh primitives of the implicit surface, the meshing steps and the surface
 * object shared by the files of the surface. */
#ifndef SK_HAND_SURFACE_INTERNAL_H
#define SK_HAND_SURFACE_INTERNAL_H

#include "models/hand/hand_internal.h"
#include "shitsukan/hand_surface.h"

/* One flesh primitive: an elliptic capsule along local +Y from 0 to `length`, its
 * section's semi-axes rx (local X) and rz (local Z) and centre shift cz (local Z)
 * varying linearly from the base to the end, closed by half-ellipsoids whose semi-axis
 * along Y is ry. A pad is a capsule of length 0. */
typedef struct sk__hand_prim {
    sk_mat3d rotation; /* local axes as columns, in the rest-pose world */
    sk_vec3d origin;
    double length;
    double rx[2], rz[2], ry[2], cz[2];
    double blend;    /* smooth-union radius with what came before in its group */
    int group;       /* 0 = palm, 1 + finger = that finger's chain */
    int link;        /* link it belongs to (weights), -1 for webs */
    bool nail;       /* a nail plate (the material region) */
    sk_vec3d lo, hi; /* bounds in the world (without blending) */
} sk__hand_prim;

#define SK_HAND__MAX_PRIMS 64
#define SK_HAND__GROUPS (1 + SK_HAND_FINGER_COUNT)

typedef struct sk__hand_field {
    int count;
    sk__hand_prim prim[SK_HAND__MAX_PRIMS];
    double root_blend; /* fingers into the palm */
    sk_vec3d lo, hi;   /* bounds of all primitives */
} sk__hand_field;

/* Builds the primitives of a right hand in the skeleton's relaxed posture. */
void sk__hand_field_build(sk__hand_field *field, const sk_hand_skeleton *right_skeleton,
                          const sk_hand_flesh *flesh);
/* Distance-like value of one primitive (negative inside). */
double sk__hand_prim_eval(const sk__hand_prim *p, sk_vec3d x);
/* The field from a subset of primitives (indices ascending; NULL = all). */
double sk__hand_field_eval_list(const sk__hand_field *field, const int *list, int count,
                                sk_vec3d x);
static inline double sk__hand_field_eval(const sk__hand_field *field, sk_vec3d x)
{
    return sk__hand_field_eval_list(field, NULL, field->count, x);
}
sk_vec3d sk__hand_field_gradient(const sk__hand_field *field, sk_vec3d x);
/* Newton projection onto the zero set; returns the signed distance. */
double sk__hand_field_project(const sk__hand_field *field, sk_vec3d x, sk_vec3d *closest);

/* A growing triangle soup with shared vertices (the meshing steps' working mesh). */
typedef struct sk__hand_trimesh {
    size_t vertex_count, vertex_cap;
    double *pos; /* 3 per vertex */
    size_t tri_count, tri_cap;
    uint32_t *tri; /* 3 per triangle, counter-clockwise seen from outside */
} sk__hand_trimesh;
void sk__hand_trimesh_free(sk__hand_trimesh *m);

/* Marching tetrahedra (Kuhn split of every cube) of the field on a narrow band of a grid
 * of step `cell`: a closed, manifold, self-intersection-free piecewise-linear level set. */
sk_result sk__hand_extract(const sk__hand_field *field, double cell, sk__hand_trimesh *out,
                           sk_error *err);
/* Quadric edge collapses (Garland & Heckbert 1997) down to `target` triangles, keeping
 * the mesh manifold (link condition) and every triangle's orientation. */
sk_result sk__hand_simplify(sk__hand_trimesh *mesh, size_t target, sk_error *err);
/* Tangential relaxation of the vertices followed by projection onto the field's zero
 * set (better-shaped triangles on the true surface). */
void sk__hand_relax(sk__hand_trimesh *mesh, const sk__hand_field *field, int iterations);

/* Smooths the vertices around crossing triangle pairs until none cross. */
void sk__hand_untangle(sk__hand_trimesh *mesh, const sk__hand_field *field);

/* 1 if the triangles form a closed, oriented 2-manifold over all vertex_count vertices
 * (every edge in exactly two triangles wound oppositely, every vertex's triangles one
 * fan), 0 if not, -1 out of memory; `euler` (may be NULL) gets V - E + F when 1; `bad`
 * (vertex_count entries, may be NULL) marks the vertices of every defect with 1. */
int sk__hand_mesh_topology(const uint32_t *tri, size_t triangle_count, size_t vertex_count,
                           long *euler, uint8_t *bad);

/* Skin weights: 4 links and weights per vertex. */
void sk__hand_weights_compute(const sk__hand_field *field, const sk_hand_skeleton *right_skeleton,
                              const float *positions, size_t vertex_count, uint16_t *nearest_links,
                              float *nearest_weights, uint16_t *smooth_links,
                              float *smooth_weights);

struct sk_hand_surface {
    sk_hand_skeleton skeleton; /* as given (side included) */
    sk_hand_skeleton right;    /* the same on the right side */
    sk_hand_flesh flesh;
    sk__hand_field field; /* right-hand rest pose */
    sk_hand_frames bind;  /* relaxed frames of `skeleton` */
    sk_mesh mesh;         /* on `skeleton`'s side */
    uint16_t *links[2];   /* [0] nearest, [1] smooth: vertex_count x 4 */
    float *weights[2];
    uint8_t *influences;         /* non-zero smooth weights per vertex (1..4) */
    uint32_t *by_influence;      /* the vertices grouped by influence count, ascending
                                    within each group: the skinning loops run one
                                    count at a time, without a branch per vertex */
    uint32_t influence_first[5]; /* group n (1..4) is by_influence[first[n-1] ..
                                    first[n]); first[0] = 0 */
    /* atlas: export vertices (seam split) */
    size_t export_count;
    uint32_t *export_map;           /* export vertex -> mesh vertex */
    float *export_uv;               /* 2 per export vertex */
    uint32_t *export_indices;       /* 3 per triangle */
    float atlas_lo[2], atlas_hi[2]; /* rest-pose x, y bounds the charts cover (right hand) */
};

/* Fills the atlas of a surface whose mesh and weights are set (seam split, UVs). */
sk_result sk__hand_atlas_build(sk_hand_surface *s, sk_error *err);
/* Sets the weights, influences, normals and atlas of a surface whose mesh positions and
 * triangles are set on the right side, then mirrors it if the skeleton is a left one. */
sk_result sk__hand_surface_finish(sk_hand_surface *s, sk_error *err);

#endif /* SK_HAND_SURFACE_INTERNAL_H */
