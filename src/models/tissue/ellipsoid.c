/* Ellipsoids, the shape every bone and muscle is made of (Shigemori & Kawai sec. 2,
 * Fig. 1): level in the ellipsoid's own coordinates, bounds, transforms, and pushing a
 * point out (used to keep skin points out of bones). */
#include <math.h>

#include "models/tissue/tissue_internal.h"

static sk_vec3d to_local(const sk__ellipsoid *e, sk_vec3d p)
{
    sk_vec3d d = sk_v3d_sub(p, e->centre);
    const sk_mat3d *A = &e->axes;
    return sk_v3d(A->m[0][0] * d.x + A->m[1][0] * d.y + A->m[2][0] * d.z,
                  A->m[0][1] * d.x + A->m[1][1] * d.y + A->m[2][1] * d.z,
                  A->m[0][2] * d.x + A->m[1][2] * d.y + A->m[2][2] * d.z);
}

double sk__ellipsoid_level(const sk__ellipsoid *e, sk_vec3d p)
{
    sk_vec3d l = to_local(e, p);
    double x = l.x / e->radii.x, y = l.y / e->radii.y, z = l.z / e->radii.z;
    return x * x + y * y + z * z;
}

void sk__ellipsoid_bounds(const sk__ellipsoid *e, sk_vec3d *lo, sk_vec3d *hi)
{
    double h[3];
    for (int i = 0; i < 3; i++) {
        double x = e->axes.m[i][0] * e->radii.x, y = e->axes.m[i][1] * e->radii.y,
               z = e->axes.m[i][2] * e->radii.z;
        h[i] = sqrt(x * x + y * y + z * z);
    }
    *lo = sk_v3d(e->centre.x - h[0], e->centre.y - h[1], e->centre.z - h[2]);
    *hi = sk_v3d(e->centre.x + h[0], e->centre.y + h[1], e->centre.z + h[2]);
}

sk__ellipsoid sk__ellipsoid_transform(const sk__ellipsoid *e, sk_mat3d r, sk_vec3d t)
{
    sk__ellipsoid out = *e;
    out.centre = sk_v3d_add(sk_m3d_apply(r, e->centre), t);
    out.axes = sk_m3d_mul(r, e->axes);
    return out;
}

bool sk__ellipsoid_push_out(const sk__ellipsoid *e, sk_vec3d *p, double margin)
{
    sk_vec3d l = to_local(e, *p);
    double x = l.x / e->radii.x, y = l.y / e->radii.y, z = l.z / e->radii.z;
    double q = x * x + y * y + z * z, target = (1.0 + margin) * (1.0 + margin);
    if (q >= target) return false;
    double s;
    if (q > 1e-24) {
        s = sqrt(target / q);
    } else { /* at the centre: out along the shortest axis */
        l = sk_v3d(e->radii.x, 0, 0);
        s = 1.0 + margin;
    }
    l = sk_v3d_scale(l, s);
    *p = sk_v3d_add(e->centre, sk_m3d_apply(e->axes, l));
    return true;
}

sk_vec3d sk__axis_across(sk_vec3d z)
{
    double ax = fabs(z.x), ay = fabs(z.y), az = fabs(z.z);
    if (ax <= ay && ax <= az) return sk_v3d(1, 0, 0);
    if (ay <= az) return sk_v3d(0, 1, 0);
    return sk_v3d(0, 0, 1);
}

sk_mat3d sk__frame_from_z(sk_vec3d z, sk_vec3d hint)
{
    z = sk_v3d_normalize(z);
    sk_vec3d x = sk_v3d_sub(hint, sk_v3d_scale(z, sk_v3d_dot(hint, z)));
    if (sk_v3d_length(x) < 1e-6 * (sk_v3d_length(hint) + 1e-300)) {
        sk_vec3d a = sk__axis_across(z);
        x = sk_v3d_sub(a, sk_v3d_scale(z, sk_v3d_dot(a, z)));
    }
    x = sk_v3d_normalize(x);
    sk_vec3d y = sk_v3d_cross(z, x);
    sk_mat3d f = {{{x.x, y.x, z.x}, {x.y, y.y, z.y}, {x.z, y.z, z.z}}};
    return f;
}
