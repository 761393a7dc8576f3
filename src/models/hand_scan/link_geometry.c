/* The skeleton placed in the scan data (thesis 4.1.2, step 1): each link as a segment
 * from its base joint to the next joint (or the fingertip), the nearest link of a point
 * (step 4), and a point's coordinates along and about a link. */
#include <math.h>

#include "models/hand/hand_internal.h"
#include "models/hand_scan/scan_internal.h"

void sk_hand_link_geometry_from_frames(const sk_hand_frames *frames, sk_hand_link_geometry *out)
{
    for (int l = 0; l < SK_HAND_LINK_COUNT; l++) {
        out->a[l] = frames->point[sk_hand_link_point(l)];
        out->frame[l] = frames->rotation[l];
        int end = sk_hand_link_end_point(l);
        if (end >= 0) {
            out->b[l] = frames->point[end];
        } else {
            /* the carpus ends at five CMC joints: take the mean of the four finger CMCs */
            sk_vec3d m = {0, 0, 0};
            for (int f = SK_HAND_INDEX; f <= SK_HAND_LITTLE; f++)
                m = sk_v3d_add(m, frames->point[sk_hand_link_point(sk__hand_first_link(f))]);
            out->b[l] = sk_v3d_scale(m, 0.25);
        }
    }
}

static double segment_distance2(sk_vec3d a, sk_vec3d b, sk_vec3d p)
{
    sk_vec3d ab = sk_v3d_sub(b, a);
    double len2 = sk_v3d_dot(ab, ab);
    double t = len2 > 0.0 ? sk_v3d_dot(sk_v3d_sub(p, a), ab) / len2 : 0.0;
    t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
    return sk__dist2(p, sk_v3d_add(a, sk_v3d_scale(ab, t)));
}

int sk_hand_nearest_link(const sk_hand_link_geometry *links, sk_vec3d p, double *distance)
{
    int best = 0;
    double best_d2 = INFINITY;
    for (int l = 0; l < SK_HAND_LINK_COUNT; l++) {
        double d2 = segment_distance2(links->a[l], links->b[l], p);
        if (d2 < best_d2) {
            best_d2 = d2;
            best = l;
        }
    }
    if (distance) *distance = sqrt(best_d2);
    return best;
}

void sk__hand_link_coordinates(const sk_hand_link_geometry *links, int link, sk_vec3d p,
                               double *along, double *angle)
{
    sk_vec3d axis = sk_v3d_normalize(sk_v3d_sub(links->b[link], links->a[link]));
    sk_vec3d q = sk_v3d_sub(p, links->a[link]);
    double s = sk_v3d_dot(q, axis);
    if (along) *along = s;
    if (angle) {
        /* the frame's X and Z made perpendicular to the segment (a metacarpal's segment
           need not run exactly along its frame's Y) */
        sk_vec3d x = {links->frame[link].m[0][0], links->frame[link].m[1][0],
                      links->frame[link].m[2][0]};
        x = sk_v3d_normalize(sk_v3d_sub(x, sk_v3d_scale(axis, sk_v3d_dot(x, axis))));
        sk_vec3d z = sk_v3d_cross(x, axis);
        sk_vec3d r = sk_v3d_sub(q, sk_v3d_scale(axis, s));
        *angle = atan2(sk_v3d_dot(r, z), sk_v3d_dot(r, x));
    }
}

bool sk__hand_link_is_phalanx(int link)
{
    if (link <= 0 || link >= SK_HAND_LINK_COUNT) return false;
    int finger = sk__hand_finger_of_link(link);
    return link != sk__hand_first_link(finger);
}
