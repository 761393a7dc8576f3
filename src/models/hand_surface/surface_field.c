/* The implicit hand surface: flesh primitives around the posed skeleton's links (thesis
 * 4.1: the surface the thesis scanned from a cast is built here from the skeleton),
 * blended by polynomial smooth minima (Quilez 2013) in groups: the palm (carpus, wrist
 * stump, metacarpals, thenar and hypothenar pads, webs), each finger's chain, and the
 * fingers into the palm. Fingers meet each other only through the palm group's webs. */
#include <float.h>
#include <math.h>
#include <string.h>

#include "models/hand_surface/surface_internal.h"

#define FAR 1e30

static double smin(double a, double b, double k)
{
    double h = k - fabs(a - b);
    if (h <= 0.0) return a < b ? a : b;
    h /= k;
    return (a < b ? a : b) - h * h * k * 0.25;
}

double sk__hand_prim_eval(const sk__hand_prim *p, sk_vec3d x)
{
    sk_vec3d d = sk_v3d_sub(x, p->origin);
    const double(*m)[3] = p->rotation.m;
    double lx = m[0][0] * d.x + m[1][0] * d.y + m[2][0] * d.z;
    double ly = m[0][1] * d.x + m[1][1] * d.y + m[2][1] * d.z;
    double lz = m[0][2] * d.x + m[1][2] * d.y + m[2][2] * d.z;
    double t = p->length > 0.0 ? ly / p->length : 0.0;
    t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
    double rx = p->rx[0] + (p->rx[1] - p->rx[0]) * t;
    double rz = p->rz[0] + (p->rz[1] - p->rz[0]) * t;
    double cz = p->cz[0] + (p->cz[1] - p->cz[0]) * t;
    double dy = ly - t * p->length;
    double ry = dy < 0.0 ? p->ry[0] : p->ry[1];
    double ex = lx / rx, ey = dy / ry, ez = (lz - cz) / rz;
    double k0 = sqrt(ex * ex + ey * ey + ez * ez);
    double fx = ex / rx, fy = ey / ry, fz = ez / rz;
    double k1 = sqrt(fx * fx + fy * fy + fz * fz);
    /* the ellipsoid bound of Quilez: k0 (k0 - 1) / k1, exact on the surface's normal
       direction for a sphere; on the axis, minus the smallest semi-axis */
    if (k1 < 1e-12) {
        double r = rx < rz ? rx : rz;
        return -(ry < r && dy != 0.0 ? ry : r);
    }
    return k0 * (k0 - 1.0) / k1;
}

double sk__hand_field_eval_list(const sk__hand_field *f, const int *list, int count, sk_vec3d x)
{
    double g[SK_HAND__GROUPS];
    for (int i = 0; i < SK_HAND__GROUPS; i++) g[i] = FAR;
    for (int k = 0; k < count; k++) {
        const sk__hand_prim *p = &f->prim[list ? list[k] : k];
        double d = sk__hand_prim_eval(p, x);
        g[p->group] = g[p->group] >= FAR ? d : smin(g[p->group], d, p->blend);
    }
    double fingers = FAR;
    for (int i = 1; i < SK_HAND__GROUPS; i++) fingers = g[i] < fingers ? g[i] : fingers;
    if (g[0] >= FAR) return fingers;
    if (fingers >= FAR) return g[0];
    return smin(g[0], fingers, f->root_blend);
}

sk_vec3d sk__hand_field_gradient(const sk__hand_field *f, sk_vec3d x)
{
    const double e = 1e-3;
    sk_vec3d g;
    g.x = sk__hand_field_eval(f, sk_v3d(x.x + e, x.y, x.z)) -
          sk__hand_field_eval(f, sk_v3d(x.x - e, x.y, x.z));
    g.y = sk__hand_field_eval(f, sk_v3d(x.x, x.y + e, x.z)) -
          sk__hand_field_eval(f, sk_v3d(x.x, x.y - e, x.z));
    g.z = sk__hand_field_eval(f, sk_v3d(x.x, x.y, x.z + e)) -
          sk__hand_field_eval(f, sk_v3d(x.x, x.y, x.z - e));
    return sk_v3d_scale(g, 0.5 / e);
}

double sk__hand_field_project(const sk__hand_field *f, sk_vec3d x, sk_vec3d *closest)
{
    double v0 = sk__hand_field_eval(f, x);
    sk_vec3d p = x;
    double v = v0;
    for (int it = 0; it < 32 && fabs(v) > 1e-7; it++) {
        /* forward differences: the value at p is known */
        const double e = 1e-4;
        sk_vec3d g = sk_v3d((sk__hand_field_eval(f, sk_v3d(p.x + e, p.y, p.z)) - v) / e,
                            (sk__hand_field_eval(f, sk_v3d(p.x, p.y + e, p.z)) - v) / e,
                            (sk__hand_field_eval(f, sk_v3d(p.x, p.y, p.z + e)) - v) / e);
        double gg = sk_v3d_dot(g, g);
        if (gg < 1e-12) break;
        double step = v / gg;
        /* at most 2 mm per step: the field is a distance only near the surface */
        double len = fabs(step) * sqrt(gg);
        if (len > 2.0) step *= 2.0 / len;
        p = sk_v3d_sub(p, sk_v3d_scale(g, step));
        v = sk__hand_field_eval(f, p);
    }
    if (closest) *closest = p;
    double d = sk_v3d_length(sk_v3d_sub(p, x));
    return v0 < 0.0 ? -d : d;
}

/* ------------------------------------------------------------ building */

static void prim_bounds(sk__hand_prim *p)
{
    double rx = fmax(p->rx[0], p->rx[1]), rz = fmax(p->rz[0], p->rz[1]);
    double czlo = fmin(p->cz[0], p->cz[1]) - rz, czhi = fmax(p->cz[0], p->cz[1]) + rz;
    p->lo = sk_v3d(DBL_MAX, DBL_MAX, DBL_MAX);
    p->hi = sk_v3d(-DBL_MAX, -DBL_MAX, -DBL_MAX);
    for (int c = 0; c < 8; c++) {
        sk_vec3d l =
            sk_v3d(c & 1 ? rx : -rx, c & 2 ? p->length + p->ry[1] : -p->ry[0], c & 4 ? czhi : czlo);
        sk_vec3d w = sk_v3d_add(p->origin, sk_m3d_apply(p->rotation, l));
        p->lo = sk_v3d(fmin(p->lo.x, w.x), fmin(p->lo.y, w.y), fmin(p->lo.z, w.z));
        p->hi = sk_v3d(fmax(p->hi.x, w.x), fmax(p->hi.y, w.y), fmax(p->hi.z, w.z));
    }
}

static sk__hand_prim *add(sk__hand_field *f, int group, int link, double blend)
{
    sk__hand_prim *p = &f->prim[f->count++];
    memset(p, 0, sizeof *p);
    p->group = group;
    p->link = link;
    p->blend = blend;
    p->rotation = sk_m3d_identity();
    return p;
}

static void set_section(sk__hand_prim *p, double b0, double t0, double b1, double t1)
{
    p->rx[0] = 0.5 * b0, p->rz[0] = 0.5 * t0;
    p->rx[1] = 0.5 * b1, p->rz[1] = 0.5 * t1;
    p->ry[0] = fmin(p->rx[0], p->rz[0]);
    p->ry[1] = fmin(p->rx[1], p->rz[1]);
}

/* A capsule between two world points with its local Z as close as possible to `up`. */
static void between(sk__hand_prim *p, sk_vec3d a, sk_vec3d b, sk_vec3d up)
{
    sk_vec3d y = sk_v3d_sub(b, a);
    p->length = sk_v3d_length(y);
    y = sk_v3d_normalize(y);
    sk_vec3d z = sk_v3d_normalize(sk_v3d_sub(up, sk_v3d_scale(y, sk_v3d_dot(up, y))));
    sk_vec3d x = sk_v3d_cross(y, z);
    sk_mat3d r = {{{x.x, y.x, z.x}, {x.y, y.y, z.y}, {x.z, y.z, z.z}}};
    p->rotation = r;
    p->origin = a;
}

static sk_vec3d column(sk_mat3d m, int c) { return sk_v3d(m.m[0][c], m.m[1][c], m.m[2][c]); }

static sk_vec3d along(const sk_hand_frames *fr, const sk_hand_skeleton *s, int link, double t)
{
    sk_vec3d base = fr->point[sk_hand_link_point(link)];
    return sk_v3d_add(base, sk_v3d_scale(column(fr->rotation[link], 1), t * s->length[link]));
}

void sk__hand_field_build(sk__hand_field *f, const sk_hand_skeleton *s, const sk_hand_flesh *fl)
{
    memset(f, 0, sizeof *f);
    double q[SK_HAND_DOF_COUNT];
    sk_hand_relaxed(s, q);
    sk_hand_frames fr;
    sk_hand_forward(s, q, &fr);
    double sb = s->hand_breadth_mm / fl->reference_breadth_mm;
    double hl = s->hand_length_mm, hb = s->hand_breadth_mm;
    f->root_blend = fl->blend_root_mm * sb;
    double kp = fl->blend_palm_mm * sb, kj = fl->blend_joint_mm * sb;
    sk_vec3d wrist = fr.point[0];
    sk_mat3d carpus = fr.rotation[0];
    sk_vec3d palmar = column(carpus, 2);

    /* carpus, from the wrist crease to the CMC joints, and the stump of the forearm */
    double cmc_y = s->offset[sk__hand_first_link(SK_HAND_MIDDLE)].y;
    double span = s->offset[sk__hand_first_link(SK_HAND_INDEX)].x -
                  s->offset[sk__hand_first_link(SK_HAND_LITTLE)].x;
    sk__hand_prim *p = add(f, 0, 0, kp);
    p->rotation = carpus;
    p->origin = sk_v3d_add(
        wrist, sk_v3d_scale(column(carpus, 0), 0.5 * (s->offset[4].x + s->offset[16].x)));
    p->length = cmc_y;
    set_section(p, fl->wrist_breadth_mm * sb, fl->wrist_thickness_mm * sb,
                fmax(fl->wrist_breadth_mm * sb, span + 20 * sb),
                fl->wrist_thickness_mm * sb * 0.85);
    p = add(f, 0, 0, kp);
    p->rotation = carpus;
    p->origin = sk_v3d_sub(wrist, sk_v3d_scale(column(carpus, 1), fl->stump_length_mm * sb));
    p->origin = sk_v3d_add(
        p->origin, sk_v3d_scale(column(carpus, 0), 0.5 * (s->offset[4].x + s->offset[16].x)));
    p->length = fl->stump_length_mm * sb;
    set_section(p, fl->wrist_breadth_mm * sb * 0.96, fl->wrist_thickness_mm * sb * 0.96,
                fl->wrist_breadth_mm * sb, fl->wrist_thickness_mm * sb);
    p->ry[0] = 0.25 * p->rz[0]; /* a nearly flat cut end */

    /* metacarpals: the palm for I..L, the thumb's inside the thenar */
    for (int fi = 0; fi < SK_HAND_FINGER_COUNT; fi++) {
        const sk_hand_flesh_finger *ff = &fl->finger[fi];
        int link = sk__hand_first_link(fi);
        p = add(f, 0, link, kp);
        p->rotation = fr.rotation[link];
        p->origin = fr.point[sk_hand_link_point(link)];
        p->length = s->length[link];
        set_section(p, ff->metacarpal_breadth_mm[0] * sb, ff->metacarpal_thickness_mm[0] * sb,
                    ff->metacarpal_breadth_mm[1] * sb, ff->metacarpal_thickness_mm[1] * sb);
        if (fi != SK_HAND_THUMB) p->cz[0] = p->cz[1] = fl->palm_palmar_shift_mm * sb;
    }
    /* thenar and hypothenar pads (carpus frame) */
    const sk_hand_flesh_pad *pads[2] = {&fl->thenar, &fl->hypothenar};
    int pad_link[2] = {sk__hand_first_link(SK_HAND_THUMB), sk__hand_first_link(SK_HAND_LITTLE)};
    for (int i = 0; i < 2; i++) {
        const sk_hand_flesh_pad *pd = pads[i];
        p = add(f, 0, pad_link[i], 0.75 * kp);
        p->rotation = sk_m3d_mul(carpus, sk_m3d_rot_z(pd->angle_deg * SK_DEG_TO_RAD));
        p->origin = sk_v3d_add(
            wrist, sk_m3d_apply(carpus, sk_v3d(pd->centre_x_hb * hb, pd->centre_y_hl * hl,
                                               pd->centre_z_mm * sb)));
        p->rx[0] = p->rx[1] = pd->radius_mm[0] * sb;
        p->ry[0] = p->ry[1] = pd->radius_mm[1] * sb;
        p->rz[0] = p->rz[1] = pd->radius_mm[2] * sb;
    }
    /* webs between neighbouring fingers' proximal phalanges: a sheet from the knuckles
       up to the web's reach (its section long along the fingers) */
    for (int fi = SK_HAND_INDEX; fi < SK_HAND_LITTLE; fi++) {
        int la = sk__hand_first_link(fi) + 1, lb = sk__hand_first_link(fi + 1) + 1;
        double half = 0.5 * fl->web_reach;
        sk_vec3d a = along(&fr, s, la, half), b = along(&fr, s, lb, half);
        sk_vec3d up =
            sk_v3d_normalize(sk_v3d_add(column(fr.rotation[la], 2), column(fr.rotation[lb], 2)));
        p = add(f, 0, -1, 0.4 * kp);
        between(p, a, b, up);
        double r = 0.5 * fl->web_thickness_mm * sb;
        double along_fingers = half * 0.5 * (s->length[la] + s->length[lb]) + r;
        p->rx[0] = p->rx[1] = along_fingers;
        p->rz[0] = p->rz[1] = r;
        p->ry[0] = p->ry[1] = r;
        p->cz[0] = p->cz[1] = 0.3 * r;
    }
    {
        int lt = sk__hand_first_link(SK_HAND_THUMB) + 1, li = sk__hand_first_link(SK_HAND_INDEX);
        sk_vec3d a = along(&fr, s, lt, 0.15), b = along(&fr, s, li, 0.7);
        p = add(f, 0, -1, 0.5 * kp);
        between(p, a, b, palmar);
        double r = 0.5 * fl->thumb_web_thickness_mm * sb;
        p->rx[0] = p->rx[1] = r;
        p->rz[0] = p->rz[1] = r;
        p->ry[0] = p->ry[1] = r;
    }
    /* the fingers' chains of phalanges, with the nail plate on the last */
    for (int fi = 0; fi < SK_HAND_FINGER_COUNT; fi++) {
        const sk_hand_flesh_finger *ff = &fl->finger[fi];
        int first = sk__hand_first_link(fi), n = sk__hand_link_count_of_finger(fi);
        for (int k = 1; k < n; k++) {
            int link = first + k;
            bool last = k == n - 1;
            p = add(f, 1 + fi, link, kj);
            p->rotation = fr.rotation[link];
            p->origin = fr.point[sk_hand_link_point(link)];
            set_section(p, ff->breadth_mm[k - 1] * sb, ff->thickness_mm[k - 1] * sb,
                        ff->breadth_mm[k] * sb, ff->thickness_mm[k] * sb);
            p->length = s->length[link] - (last ? p->ry[1] : 0.0);
            if (!last) continue;
            /* nail plate: a flat elliptic plate on the dorsal side (local -Z), its outer
               face nail_thickness above the finger's dorsal surface */
            double len = fl->nail_length * s->length[link];
            double y0 = s->length[link] * 0.94 - len;
            double t_mid = (y0 + 0.5 * len) / p->length;
            double half_t = p->rz[0] + (p->rz[1] - p->rz[0]) * fmin(t_mid, 1.0);
            double half_b = p->rx[0] + (p->rx[1] - p->rx[0]) * fmin(t_mid, 1.0);
            sk__hand_prim *nail = add(f, 1 + fi, link, 0.6 * sb);
            nail->nail = true;
            nail->rotation = fr.rotation[link];
            double plate = 2.5 * sb, cap = 2.0 * sb;
            nail->origin = sk_v3d_add(fr.point[sk_hand_link_point(link)],
                                      sk_m3d_apply(fr.rotation[link], sk_v3d(0, y0 + cap, 0)));
            nail->length = fmax(len - 2 * cap, 0.1);
            nail->rx[0] = nail->rx[1] = fl->nail_breadth * half_b;
            nail->rz[0] = nail->rz[1] = plate;
            nail->ry[0] = nail->ry[1] = cap;
            nail->cz[0] = nail->cz[1] = -half_t + plate - fl->nail_thickness_mm * sb;
        }
    }
    f->lo = sk_v3d(DBL_MAX, DBL_MAX, DBL_MAX);
    f->hi = sk_v3d(-DBL_MAX, -DBL_MAX, -DBL_MAX);
    for (int i = 0; i < f->count; i++) {
        prim_bounds(&f->prim[i]);
        const sk__hand_prim *pi = &f->prim[i];
        f->lo = sk_v3d(fmin(f->lo.x, pi->lo.x), fmin(f->lo.y, pi->lo.y), fmin(f->lo.z, pi->lo.z));
        f->hi = sk_v3d(fmax(f->hi.x, pi->hi.x), fmax(f->hi.y, pi->hi.y), fmax(f->hi.z, pi->hi.z));
    }
}
