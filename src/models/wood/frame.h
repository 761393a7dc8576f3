/* Tree frame (Kawai 2000 sec. 4.1): a rigid transform placing the tree in the scene and
 * the cylindrical coordinates (r, theta, y) of the tree frame, y along the pith. */
#ifndef SK_WOOD_FRAME_H
#define SK_WOOD_FRAME_H

#include <stdbool.h>

#include "shitsukan/wood.h"

typedef struct sk__wood_frame {
    sk_mat3f to_scene; /* rotation tree -> scene */
    sk_mat3f to_tree;  /* its transpose */
    sk_vec3f origin;   /* scene position of the tree origin */
    bool identity;     /* no rotation and no translation */
} sk__wood_frame;

void sk__wood_frame_init(sk__wood_frame *frame, const sk_wood_transform *transform);

static inline sk_vec3f sk__wood_frame_point_to_tree(const sk__wood_frame *f, sk_vec3f p)
{
    if (f->identity) return p;
    return sk_m3f_apply(f->to_tree, sk_v3f_sub(p, f->origin));
}
static inline sk_vec3f sk__wood_frame_dir_to_tree(const sk__wood_frame *f, sk_vec3f d)
{
    return f->identity ? d : sk_m3f_apply(f->to_tree, d);
}
static inline sk_vec3f sk__wood_frame_point_to_scene(const sk__wood_frame *f, sk_vec3f p)
{
    if (f->identity) return p;
    return sk_v3f_add(sk_m3f_apply(f->to_scene, p), f->origin);
}
static inline sk_vec3f sk__wood_frame_dir_to_scene(const sk__wood_frame *f, sk_vec3f d)
{
    return f->identity ? d : sk_m3f_apply(f->to_scene, d);
}

#endif
