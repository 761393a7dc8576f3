/* Tree frame (Kawai 2000 sec. 4.1): the rigid transform that places the tree's cylinder
 * (pith along y, y = 0 at the ground) in the scene. */
#include "models/wood/frame.h"

void sk__wood_frame_init(sk__wood_frame *frame, const sk_wood_transform *transform)
{
    /* scene = Rz Ry Rx tree + translate */
    sk_mat3d rot = sk_m3d_mul(
        sk_m3d_rot_z(transform->rotate[2]),
        sk_m3d_mul(sk_m3d_rot_y(transform->rotate[1]), sk_m3d_rot_x(transform->rotate[0])));
    frame->to_scene = sk_m3d_to_f(rot);
    frame->to_tree = sk_m3d_to_f(sk_m3d_transpose(rot));
    frame->origin =
        sk_v3f(transform->translate_mm[0], transform->translate_mm[1], transform->translate_mm[2]);
    frame->identity = transform->rotate[0] == 0.0f && transform->rotate[1] == 0.0f &&
                      transform->rotate[2] == 0.0f && transform->translate_mm[0] == 0.0f &&
                      transform->translate_mm[1] == 0.0f && transform->translate_mm[2] == 0.0f;
}
