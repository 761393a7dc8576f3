/* Bones (Shigemori & Kawai sec. 3): three ellipsoids each, the two rounded ends and a
 * thinner shaft between them, fixed in the frame of the bone's joint, sized from the
 * segment's length and a radius. */
#include <math.h>
#include <string.h>

#include "models/tissue/tissue_internal.h"

static sk_vec3d vec3(const float v[3]) { return sk_v3d(v[0], v[1], v[2]); }

sk_result sk__bones_build(const sk_tissue_character_desc *d, const sk__skeleton *s, sk__bone *bones,
                          sk_error *err)
{
    for (int i = 0; i < d->bone_count; i++) {
        const sk_tissue_bone_desc *bd = &d->bones[i];
        sk__bone *b = &bones[i];
        memset(b, 0, sizeof *b);
        b->joint = sk__joint_find(d, bd->joint);
        b->start = vec3(bd->from_mm);
        b->end = bd->end[0] ? sk_v3d_sub(s->rest[sk__joint_find(d, bd->end)], s->rest[b->joint])
                            : vec3(bd->to_mm);
        sk_vec3d axis = sk_v3d_sub(b->end, b->start);
        b->length = sk_v3d_length(axis);
        if (!(b->length > 1e-6))
            return sk_fail(
                err, SK_ERROR_INVALID_ARGUMENT,
                "bones[%d] (\"%s\"): its start and end coincide (give `end` or a non-zero to_mm)",
                i, bd->name);
        sk_vec3d hint = vec3(bd->x_axis);
        if (sk_v3d_length(hint) == 0.0) hint = sk__axis_across(axis);
        sk_mat3d frame = sk__frame_from_z(axis, hint);
        double r = bd->radius_mm, depth = bd->depth_ratio, e = bd->end_length_mm,
               sr = r * bd->shaft_ratio;
        b->part[0] = (sk__ellipsoid){b->start, frame, sk_v3d(r, r * depth, e)};
        b->part[1] = (sk__ellipsoid){sk_v3d_scale(sk_v3d_add(b->start, b->end), 0.5), frame,
                                     sk_v3d(sr, sr * depth, 0.5 * b->length)};
        b->part[2] = (sk__ellipsoid){b->end, frame, sk_v3d(r, r * depth, e)};
        b->bound_centre = b->part[1].centre;
        double widest = fmax(r, fmax(r * depth, e));
        b->bound_radius = 0.5 * b->length + widest;
    }
    return SK_OK;
}

sk_vec3d sk__bone_point(const sk__bone *b, double at, sk_vec3d offset)
{
    return sk_v3d_add(sk_v3d_add(b->start, sk_v3d_scale(sk_v3d_sub(b->end, b->start), at)), offset);
}
