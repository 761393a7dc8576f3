/* The 9 marker bumps of thesis 4.1.1, on the cast where both scans see them: placed on
 * the sides of the hand, and found again in each scan by fitting a sphere of their known
 * radius to the samples near where they should be (where the thesis's operator would
 * have picked them). */
#include <stdio.h>
#include <string.h>

#include "models/hand/hand_internal.h"
#include "models/hand_scan/scan_internal.h"

typedef struct marker_spec {
    int link;        /* link whose axis the bump sits beside */
    double fraction; /* along the link */
    int radial;      /* +1 radial side, -1 ulnar side */
    const char *name;
} marker_spec;

static const marker_spec specs[SK_HAND_MARKER_COUNT] = {
    {0, 0.3, +1, "wrist radial"},     {0, 0.3, -1, "wrist ulnar"},
    {1, 0.45, +1, "thumb base"},      {2, 0.5, +1, "thumb proximal"},
    {4, 0.85, +1, "index knuckle"},   {5, 0.5, +1, "index proximal"},
    {16, 0.15, -1, "hypothenar"},     {16, 0.75, -1, "little knuckle"},
    {17, 0.5, -1, "little proximal"},
};

/* The bump's centre beside the link at `fraction` along it: the first exit from the flesh
 * going `side`-ways (with an implicit surface, an exit leading into more flesh, where
 * parts of the mesh overlap, is passed), 0.3 radii beyond it. */
static bool side_surface(const sk_hand_scan_target *target, sk_vec3d a, sk_vec3d b, double fraction,
                         sk_vec3d side, double radius, sk_vec3d *centre)
{
    sk_vec3d start = sk_v3d_add(a, sk_v3d_scale(sk_v3d_sub(b, a), fraction));
    double t = 0.0;
    while (sk_hand_scan_target_raycast(target, start, side, t + 1e-3, 80.0, &t, NULL)) {
        if (!target->sdf || target->sdf(target->sdf_user,
                                        sk_v3d_add(start, sk_v3d_scale(side, t + 0.5)), NULL) > 0) {
            *centre = sk_v3d_add(start, sk_v3d_scale(side, t + 0.3 * radius));
            return true;
        }
    }
    return false;
}

/* Nothing of the cast above the bump's top or below its bottom (the two scanners look
 * along the palm's normal). */
static bool open_above_and_below(const sk_hand_scan_target *target, sk_vec3d c, sk_vec3d palmar,
                                 double radius)
{
    for (int s = -1; s <= 1; s += 2) {
        sk_vec3d dir = sk_v3d_scale(palmar, (double)s);
        if (sk_hand_scan_target_raycast(target, sk_v3d_add(c, sk_v3d_scale(dir, 0.9 * radius)), dir,
                                        0.0, 1e4, NULL, NULL))
            return false;
    }
    return true;
}

sk_result sk_hand_markers_place(const sk_hand_scan_target *target, const sk_hand_frames *frames,
                                double radius_mm, sk_hand_markers *out, sk_error *err)
{
    memset(out, 0, sizeof *out);
    if (radius_mm == 0) radius_mm = 2.5;
    sk_result r = sk_check_range_f(err, "marker_radius_mm", radius_mm, 0.5, 10);
    if (r != SK_OK) return r;
    sk_hand_link_geometry links;
    sk_hand_link_geometry_from_frames(frames, &links);
    /* the palm plane's normal, and which way is radial (toward the thumb: a left hand is
       mirrored) */
    sk_vec3d palmar = {frames->rotation[0].m[0][2], frames->rotation[0].m[1][2],
                       frames->rotation[0].m[2][2]};
    sk_vec3d hand_axis = {frames->rotation[0].m[0][1], frames->rotation[0].m[1][1],
                          frames->rotation[0].m[2][1]};
    sk_vec3d radial = sk_v3d_normalize(sk_v3d_cross(hand_axis, palmar));
    if (sk_v3d_dot(sk_v3d_sub(frames->point[sk_hand_link_end_point(1)], links.a[0]), radial) < 0.0)
        radial = sk_v3d_scale(radial, -1.0);
    out->radius_mm = radius_mm;
    for (int k = 0; k < SK_HAND_MARKER_COUNT; k++) {
        const marker_spec *m = &specs[k];
        /* sideways: across the link's own long axis (its frame's Y), in the palm plane */
        sk_vec3d axis = {frames->rotation[m->link].m[0][1], frames->rotation[m->link].m[1][1],
                         frames->rotation[m->link].m[2][1]};
        sk_vec3d side = sk_v3d_normalize(sk_v3d_cross(axis, palmar));
        if (sk_v3d_dot(side, radial) < 0.0) side = sk_v3d_scale(side, -1.0);
        side = sk_v3d_scale(side, (double)m->radial);
        /* the place along the link nearest the chosen one from which the bump is open to
           both the palm side and the back (another finger or the thumb may lie over it) */
        static const double shifts[7] = {0, -0.12, 0.12, -0.24, 0.24, -0.36, 0.36};
        bool placed = false, found_any = false;
        for (int c = 0; c < 7 && !placed; c++) {
            double f = sk_clampd(m->fraction + shifts[c], 0.05, 0.95);
            sk_vec3d centre;
            if (!side_surface(target, links.a[m->link], links.b[m->link], f, side, radius_mm,
                              &centre))
                continue;
            if (!found_any) out->centre[k] = centre; /* the fallback: the chosen place */
            found_any = true;
            if (open_above_and_below(target, centre, palmar, radius_mm)) {
                out->centre[k] = centre;
                placed = true;
            }
        }
        if (!found_any)
            return sk_fail(
                err, SK_ERROR_INVALID_ARGUMENT,
                "marker \"%s\": no surface within 80 mm beside link %s (is the skeleton inside the "
                "mesh, in the same frame and units?)",
                m->name, sk_hand_link_name(m->link));
        snprintf(out->name[k], sizeof out->name[k], "%s", m->name);
    }
    out->count = SK_HAND_MARKER_COUNT;
    return SK_OK;
}

/* Gauss-Newton for the centre of a sphere of known radius through the points. */
static sk_vec3d fit_sphere(const sk_vec3d *p, int n, double radius, sk_vec3d c)
{
    for (int it = 0; it < 20; it++) {
        double jtj[3][3] = {{0}}, jte[3] = {0};
        for (int i = 0; i < n; i++) {
            sk_vec3d d = sk_v3d_sub(p[i], c);
            double len = sk_v3d_length(d);
            if (len < 1e-9) continue;
            double g[3] = {-d.x / len, -d.y / len, -d.z / len}, e = len - radius;
            for (int a = 0; a < 3; a++) {
                jte[a] += g[a] * e;
                for (int b = 0; b < 3; b++) jtj[a][b] += g[a] * g[b];
            }
        }
        /* 3x3 solve by Cramer's rule */
        sk_mat3d m = {{{jtj[0][0], jtj[0][1], jtj[0][2]},
                       {jtj[1][0], jtj[1][1], jtj[1][2]},
                       {jtj[2][0], jtj[2][1], jtj[2][2]}}};
        double det = sk_m3d_det(m);
        if (fabs(det) < 1e-18) break;
        sk_vec3d delta = sk_m3d_solve_cramer(m, sk_v3d(-jte[0], -jte[1], -jte[2]), det);
        c = sk_v3d_add(c, delta);
        if (fabs(delta.x) + fabs(delta.y) + fabs(delta.z) < 1e-10) break;
    }
    return c;
}

#define MAX_MARKER_SAMPLES 4096

sk_result sk_hand_markers_locate(const sk_hand_range_scan *scan, const sk_hand_markers *markers,
                                 sk_vec3d centre[SK_HAND_MARKER_COUNT],
                                 int used[SK_HAND_MARKER_COUNT], sk_error *err)
{
    static const char *const side_names[2] = {"palm", "back"};
    sk_vec3d pts[MAX_MARKER_SAMPLES];
    double r = markers->radius_mm;
    for (int k = 0; k < markers->count; k++) {
        sk_vec3d c0 = sk_hand_rigid_apply(&scan->placement, markers->centre[k]);
        int i0 = (int)floor((c0.x - r - 1.0) / scan->step_x_mm),
            i1 = (int)ceil((c0.x + r + 1.0) / scan->step_x_mm);
        int j0 = (int)floor((c0.y - r - 1.0) / scan->step_y_mm),
            j1 = (int)ceil((c0.y + r + 1.0) / scan->step_y_mm);
        int n = 0;
        for (int i = i0 < 0 ? 0 : i0; i <= i1 && i < scan->lines; i++)
            for (int j = j0 < 0 ? 0 : j0; j <= j1 && j < scan->points; j++) {
                float z = scan->depth[(size_t)i * (size_t)scan->points + (size_t)j];
                if (!isfinite(z) || z < scan->table_threshold_mm) continue;
                sk_vec3d p = sk_hand_range_scan_point(scan, i, j, z);
                if (fabs(sqrt(sk__dist2(p, c0)) - r) < 1.0 && n < MAX_MARKER_SAMPLES) pts[n++] = p;
            }
        sk_vec3d c = c0;
        /* fit, drop the samples off the sphere (the hand around the bump), refit */
        for (int round = 0; round < 3 && n >= 6; round++) {
            c = fit_sphere(pts, n, r, c);
            int kept = 0;
            for (int i = 0; i < n; i++)
                if (fabs(sqrt(sk__dist2(pts[i], c)) - r) < 0.3) pts[kept++] = pts[i];
            n = kept;
        }
        if (n >= 6) c = fit_sphere(pts, n, r, c);
        if (n < 6)
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "marker \"%s\" is seen by only %d samples of the %s scan (6 needed): "
                           "the cast hides it "
                           "(an open hand, as the default pose, shows every marker)",
                           markers->name[k], n, side_names[scan->side == SK_HAND_SCAN_BACK]);
        centre[k] = c;
        if (used) used[k] = n;
    }
    return SK_OK;
}
