/* Muscles (Shigemori & Kawai sec. 3): a belly ellipsoid on two tendons fixed to points on
 * bones. As the bones move the belly's Z axis follows the attachment distance and its
 * volume and X:Y ratio stay constant, so a stretched muscle thins and a shortened one
 * bulges (spec/tissue.md): c = c0 L / L0, a = a0 sqrt(c0 / c), b = b0 sqrt(c0 / c). */
#include <math.h>

#include "models/tissue/tissue_internal.h"

void sk_tissue_muscle_axes(double a0, double b0, double c0, double rest_length, double length,
                           double *a, double *b, double *c)
{
    /* a b c = a0 b0 c0 (volume 4/3 pi a b c) and a / b = a0 / b0 */
    double stretch = fmax(length / rest_length, 1e-6);
    double cc = c0 * stretch, thin = 1.0 / sqrt(stretch);
    *a = a0 * thin;
    *b = b0 * thin;
    *c = cc;
}

static sk_vec3d vec3(const float v[3]) { return sk_v3d(v[0], v[1], v[2]); }

sk_result sk__muscles_build(const sk_tissue_character_desc *d, const sk__skeleton *s,
                            const sk__bone *bones, sk__muscle *muscles, sk_error *err)
{
    for (int i = 0; i < d->muscle_count; i++) {
        const sk_tissue_muscle_desc *md = &d->muscles[i];
        sk__muscle *m = &muscles[i];
        m->origin_bone = sk__bone_find(d, md->origin.bone);
        m->insertion_bone = sk__bone_find(d, md->insertion.bone);
        const sk__bone *ob = &bones[m->origin_bone], *ib = &bones[m->insertion_bone];
        m->origin_joint = ob->joint;
        m->insertion_joint = ib->joint;
        m->origin = sk__bone_point(ob, md->origin.at, vec3(md->origin.offset_mm));
        m->insertion = sk__bone_point(ib, md->insertion.at, vec3(md->insertion.offset_mm));
        sk_vec3d o = sk_v3d_add(s->rest[m->origin_joint], m->origin);
        sk_vec3d in = sk_v3d_add(s->rest[m->insertion_joint], m->insertion);
        sk_vec3d z = sk_v3d_sub(in, o);
        m->rest_length = sk_v3d_length(z);
        if (!(m->rest_length > 1e-3))
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "muscles[%d] (\"%s\"): origin and insertion coincide", i, md->name);
        m->a0 = 0.5 * md->thickness_mm;
        m->b0 = m->a0 * md->width_ratio;
        m->c0 = 0.5 * md->belly_fraction * m->rest_length;
        sk_vec3d hint = vec3(md->x_axis);
        if (sk_v3d_length(hint) == 0.0) {
            /* away from the origin bone's axis, through the belly's centre */
            sk_vec3d mid = sk_v3d_scale(sk_v3d_add(o, in), 0.5);
            sk_vec3d a0 = sk_v3d_add(s->rest[ob->joint], ob->start),
                     a1 = sk_v3d_add(s->rest[ob->joint], ob->end);
            sk_vec3d axis = sk_v3d_normalize(sk_v3d_sub(a1, a0));
            sk_vec3d foot =
                sk_v3d_add(a0, sk_v3d_scale(axis, sk_v3d_dot(sk_v3d_sub(mid, a0), axis)));
            hint = sk_v3d_sub(mid, foot);
        }
        sk_mat3d f = sk__frame_from_z(z, hint);
        m->x_rest = sk_v3d(f.m[0][0], f.m[1][0], f.m[2][0]); /* rest frames are world-aligned */
        m->z_rest = sk_v3d(f.m[0][2], f.m[1][2], f.m[2][2]);
    }
    return SK_OK;
}

/* The smallest rotation turning unit vector a onto unit vector b. */
static sk_quatd swing(sk_vec3d a, sk_vec3d b)
{
    double d = sk_v3d_dot(a, b);
    if (d < -0.999999)
        return sk_qd_axis_angle(sk__axis_across(a), SK_PI); /* opposite: any axis across */
    sk_vec3d c = sk_v3d_cross(a, b);
    return sk_qd_normalize(sk_qd(1.0 + d, c.x, c.y, c.z));
}

void sk__muscle_shape(const sk__muscle *m, const sk_tissue_pose *pose, sk__ellipsoid *out)
{
    sk_vec3d o = sk__pose_apply(pose, m->origin_joint, m->origin);
    sk_vec3d in = sk__pose_apply(pose, m->insertion_joint, m->insertion);
    sk_vec3d z = sk_v3d_sub(in, o);
    double length = sk_v3d_length(z);
    /* the muscle's frame as the origin bone carries it, then swung (without twist about the
       muscle's own axis) onto the line between the tendons */
    sk_quatd carried = pose->rotation[m->origin_joint];
    sk_vec3d z_carried = sk_qd_rotate(carried, m->z_rest);
    sk_vec3d zn = length > 0 ? sk_v3d_scale(z, 1.0 / length) : z_carried;
    sk_vec3d x = sk_qd_rotate(swing(z_carried, zn), sk_qd_rotate(carried, m->x_rest));
    out->axes = sk__frame_from_z(zn, x);
    sk_tissue_muscle_axes(m->a0, m->b0, m->c0, m->rest_length, length, &out->radii.x, &out->radii.y,
                          &out->radii.z);
    out->centre = sk_v3d_scale(sk_v3d_add(o, in), 0.5);
}
