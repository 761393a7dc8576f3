/* The link tree of thesis 3.1.1 built from the anatomy: link offsets r_j (eq. 3.6) from
 * hand length and breadth, fixed CMC mounts, and the per-DOF limits, relaxed posture
 * (eq. 3.7) and stiffness (eq. 3.8). */
#include <math.h>
#include <string.h>

#include "models/hand/hand_internal.h"

sk_hand_skeleton_desc sk_hand_skeleton_desc_resolved(const sk_hand_skeleton_desc *desc)
{
    sk_hand_skeleton_desc d = {0};
    if (desc) d = *desc;
    if (d.side == SK_HAND_SIDE_DEFAULT) d.side = SK_HAND_SIDE_RIGHT;
    return d;
}

/* Rest orientation of a CMC frame: long axis turned by splay (about Z, in the palm
 * plane) and tilt (about X, toward the palm), after a roll about its own axis. */
static sk_mat3d mount_rotation(double splay, double tilt, double roll)
{
    return sk_m3d_mul(sk_m3d_mul(sk_m3d_rot_z(splay), sk_m3d_rot_x(tilt)), sk_m3d_rot_y(roll));
}

sk_result sk_hand_skeleton_init(sk_hand_skeleton *s, const sk_hand_skeleton_desc *desc,
                                sk_error *err)
{
    sk_hand_skeleton_desc d = sk_hand_skeleton_desc_resolved(desc);
    sk_hand_anatomy builtin;
    const sk_hand_anatomy *a = d.anatomy;
    if (!a) {
        sk_hand_anatomy_default(&builtin);
        a = &builtin;
    }
    if (d.side != SK_HAND_SIDE_RIGHT && d.side != SK_HAND_SIDE_LEFT)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "side = %d is not right (1) or left (2)",
                       (int)d.side);
    double hl = d.hand_length_mm != 0.0 ? d.hand_length_mm : a->hand_length_mm;
    double hb = d.hand_breadth_mm != 0.0 ? d.hand_breadth_mm : a->hand_breadth_mm;
    /* the sizes (the anatomy's when 0) within the ranges of sk_hand_skeleton_schema */
    sk_hand_skeleton_desc sized = d;
    sized.hand_length_mm = hl;
    sized.hand_breadth_mm = hb;
    sk_result r = sk_schema_check(&sk_hand_skeleton_schema, &sized, "", err);
    if (r != SK_OK) return r;
    for (int i = 0; i < SK_HAND_DOF_COUNT; i++) {
        const sk_hand_dof_data *dd = &a->dof[i];
        if (!(dd->min <= dd->relaxed && dd->relaxed <= dd->max) || !isfinite(dd->min) ||
            !isfinite(dd->max))
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "%s: relaxed value %g is outside the limits [%g, %g]",
                           sk_hand_dof(i)->name, dd->relaxed, dd->min, dd->max);
        if (!(dd->stiffness > 0.0) || !isfinite(dd->stiffness))
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "%s: stiffness = %g must be > 0",
                           sk_hand_dof(i)->name, dd->stiffness);
    }

    memset(s, 0, sizeof *s);
    s->side = d.side;
    s->hand_length_mm = hl;
    s->hand_breadth_mm = hb;
    memcpy(s->dof, a->dof, sizeof s->dof);
    s->parent[0] = -1;
    s->mount[0] = sk_m3d_identity();
    for (int f = 0; f < SK_HAND_FINGER_COUNT; f++) {
        const sk_hand_finger_data *fd = &a->finger[f];
        int first = sk__hand_first_link(f), n = sk__hand_link_count_of_finger(f);
        double mc_dx = fd->mc_dx_hb * hb, mc_dy = fd->mc_dy_hl * hl;
        double splay = f == SK_HAND_THUMB ? fd->thumb_splay : -atan2(mc_dx, mc_dy);
        s->parent[first] = 0;
        s->offset[first] = sk_v3d(fd->cmc_x_hb * hb, fd->cmc_y_hl * hl, fd->cmc_z_hb * hb);
        s->mount[first] = mount_rotation(splay, fd->mount_tilt, fd->mount_roll);
        s->length[first] = sqrt(mc_dx * mc_dx + mc_dy * mc_dy);
        for (int k = 1; k < n; k++) {
            int link = first + k;
            s->parent[link] = link - 1;
            s->offset[link] = sk_v3d(0.0, s->length[link - 1], 0.0);
            s->mount[link] = sk_m3d_identity();
            s->length[link] = fd->phalanx_hl[k - 1] * hl;
        }
    }
    return SK_OK;
}

void sk_hand_relaxed(const sk_hand_skeleton *s, double dofs[SK_HAND_DOF_COUNT])
{
    for (int i = 0; i < SK_HAND_DOF_COUNT; i++) dofs[i] = s->dof[i].relaxed;
}

int sk_hand_clamp_to_limits(const sk_hand_skeleton *s, double dofs[SK_HAND_DOF_COUNT])
{
    int changed = 0;
    for (int i = 0; i < SK_HAND_DOF_COUNT; i++) {
        double v = sk_clampd(dofs[i], s->dof[i].min, s->dof[i].max);
        if (v != dofs[i] || isnan(dofs[i])) {
            dofs[i] = isnan(dofs[i]) ? s->dof[i].relaxed : v;
            changed++;
        }
    }
    return changed;
}
