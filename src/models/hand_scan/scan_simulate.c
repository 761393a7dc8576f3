/* Simulated range scans of the plaster cast, thesis 4.1.1: the laser range finder
 * (Kubota CUBIST) takes 512 scan lines x = const of 512 points over 250 x 200 x 200 mm
 * with a depth resolution of 0.2 mm; the cast is scanned palm up and turned over, back up.
 * Modelled as a light-section scanner: a laser sheet straight down, a camera seeing it at
 * a triangulation angle; a sample is measured only where the laser's first hit is also in
 * view of the camera (ray casting both ways), with depth noise and quantisation. */
#include <float.h>
#include <stdlib.h>
#include <string.h>

#include "models/hand_scan/scan_internal.h"

sk_hand_scanner_desc sk_hand_scanner_desc_resolved(const sk_hand_scanner_desc *desc)
{
    sk_hand_scanner_desc d = desc ? *desc : (sk_hand_scanner_desc){0};
    sk_schema_apply_defaults(&sk_hand_scanner_schema, &d);
    if (d.no_noise) d.noise_mm = 0;
    return d;
}

sk_result sk_hand_scanner_desc_validate(const sk_hand_scanner_desc *d, sk_error *err)
{
    return sk_schema_check(&sk_hand_scanner_schema, d, "scanner", err);
}

/* Bounds of the target's vertices after a rotation. */
static void rotated_bounds(const sk_hand_scan_target *t, sk_mat3d r, double lo[3], double hi[3])
{
    for (int k = 0; k < 3; k++) lo[k] = INFINITY, hi[k] = -INFINITY;
    for (uint32_t i = 0; i < t->bvh.triangle_count; i++)
        for (int v = 0; v < 3; v++) {
            sk_vec3d p = sk_m3d_apply(r, t->bvh.tri[i][v]);
            double q[3] = {p.x, p.y, p.z};
            for (int k = 0; k < 3; k++) {
                if (q[k] < lo[k]) lo[k] = q[k];
                if (q[k] > hi[k]) hi[k] = q[k];
            }
        }
}

/* Rotation r, then the translation that centres the target over the table (plus a shift)
 * with its lowest point on the table. */
static sk_result rest_on_table(const sk_hand_scan_target *t, const sk_hand_scanner_desc *d,
                               sk_mat3d r, double shift_x, double shift_y, const char *which,
                               sk_hand_rigid *out, sk_error *err)
{
    double lo[3], hi[3];
    rotated_bounds(t, r, lo, hi);
    double size[3] = {d->size_x_mm, d->size_y_mm, d->size_z_mm};
    static const char *const names[3] = {"size_x_mm", "size_y_mm", "size_z_mm"};
    for (int k = 0; k < 3; k++) {
        double extent = hi[k] - lo[k] + (k < 2 ? 2.0 * fabs(k == 0 ? shift_x : shift_y) : 0.0);
        if (extent > size[k])
            return sk_fail(
                err, SK_ERROR_INVALID_ARGUMENT,
                "the surface lying %s is %.1f mm across the scanner's %c axis: more than "
                "scanner.%s = %.1f mm",
                which, extent, 'x' + k, names[k], size[k]);
    }
    out->rotation = r;
    out->translation = sk_v3d(0.5 * d->size_x_mm - 0.5 * (lo[0] + hi[0]) + shift_x,
                              0.5 * d->size_y_mm - 0.5 * (lo[1] + hi[1]) + shift_y, -lo[2]);
    return SK_OK;
}

sk_result sk_hand_scan_placements(const sk_hand_scan_target *target,
                                  const sk_hand_scanner_desc *desc,
                                  sk_hand_rigid placement[SK_HAND_SCAN_SIDE_COUNT], sk_error *err)
{
    sk_hand_scanner_desc d = sk_hand_scanner_desc_resolved(desc);
    sk_result r = sk_hand_scanner_desc_validate(&d, err);
    if (r != SK_OK) return r;
    /* palm up: the hand's distal Y along the scanner's x, its palmar Z up */
    sk_mat3d palm = {{{0, 1, 0}, {-1, 0, 0}, {0, 0, 1}}};
    r = rest_on_table(target, &d, palm, 0.0, 0.0, "palm up", &placement[SK_HAND_SCAN_PALM], err);
    if (r != SK_OK) return r;
    /* turned over about the scanner's x axis, and not put back exactly: turned 3 deg about
       the vertical, tilted 1.5 deg, shifted by (+6, -4) mm */
    sk_mat3d back = sk_m3d_mul(
        sk_m3d_rot_z(3.0 * SK_DEG_TO_RAD),
        sk_m3d_mul(sk_m3d_rot_x(1.5 * SK_DEG_TO_RAD), sk_m3d_mul(sk_m3d_rot_x(SK_PI), palm)));
    return rest_on_table(target, &d, back, 6.0, -4.0, "back up", &placement[SK_HAND_SCAN_BACK],
                         err);
}

/* Entry and exit of the ray o + t d (|d| = 1) with a sphere; false on a miss. */
static bool ray_sphere(sk_vec3d o, sk_vec3d d, sk_vec3d c, double radius, double *t0, double *t1)
{
    sk_vec3d oc = sk_v3d_sub(o, c);
    double b = sk_v3d_dot(oc, d), cc = sk_v3d_dot(oc, oc) - radius * radius;
    double disc = b * b - cc;
    if (disc < 0.0) return false;
    double s = sqrt(disc);
    *t0 = -b - s;
    *t1 = -b + s;
    return true;
}

typedef struct scan_setup {
    const sk_hand_scan_target *target;
    const sk_hand_markers *markers;
    sk_hand_rigid to_scanner, to_hand;
    sk_vec3d down_h, camera_s, camera_h; /* laser and camera directions */
    double cos_grazing;
    sk_hand_scanner_desc d;
    uint64_t seed;
    int side;
} scan_setup;

/* Is the ray from p (hand frame) toward the camera blocked by the cast or a marker? */
static bool camera_blocked(const scan_setup *s, sk_vec3d p)
{
    const double t_min = 1e-4;
    if (sk__triangle_bvh_occluded(&s->target->bvh, p, s->camera_h, t_min, DBL_MAX)) return true;
    if (s->markers)
        for (int k = 0; k < s->markers->count; k++) {
            double t0, t1;
            if (ray_sphere(p, s->camera_h, s->markers->centre[k], s->markers->radius_mm, &t0,
                           &t1) &&
                t1 > t_min)
                return true;
        }
    return false;
}

static void scan_sample(const scan_setup *s, int i, int j, float *depth, float *true_depth,
                        uint8_t *kind)
{
    const sk_hand_scanner_desc *d = &s->d;
    double step_x = d->size_x_mm / d->lines, step_y = d->size_y_mm / d->points;
    double z_top = d->size_z_mm + 10.0;
    sk_vec3d o_s = {(i + 0.5) * step_x, (j + 0.5) * step_y, z_top};
    sk_vec3d o = sk_hand_rigid_apply(&s->to_hand, o_s);
    double t_table = z_top; /* the table is the plane z = 0 */
    double t_hit = t_table;
    int what = SK_HAND_SAMPLE_TABLE;
    sk_vec3d n_h = sk_m3d_apply(s->to_hand.rotation, sk_v3d(0, 0, 1)), occ_origin = o;
    sk__triangle_hit hit;
    bool mesh_hit = sk__triangle_bvh_intersect(&s->target->bvh, o, s->down_h, 0.0, t_table, &hit);
    if (mesh_hit) {
        t_hit = hit.t;
        what = SK_HAND_SAMPLE_SURFACE;
        sk_vec3d nf = sk__triangle_bvh_normal(&s->target->bvh, hit.triangle);
        if (sk_v3d_dot(nf, s->down_h) > 0.0) nf = sk_v3d_scale(nf, -1.0);
        n_h = nf;
        /* occlusion is tested from the mesh's own hit, just off its face */
        occ_origin =
            sk_v3d_add(sk_v3d_add(o, sk_v3d_scale(s->down_h, hit.t)), sk_v3d_scale(nf, 1e-4));
        /* the hit on the implicit surface, if there is one; the facet's normal is close
           enough for the incidence angles */
        double t_fine;
        if (sk__hand_target_refine(s->target, o, s->down_h, hit.t, &t_fine)) t_hit = t_fine;
    }
    if (s->markers)
        for (int k = 0; k < s->markers->count; k++) {
            double t0, t1;
            if (ray_sphere(o, s->down_h, s->markers->centre[k], s->markers->radius_mm, &t0, &t1) &&
                t0 > 0.0 && t0 < t_hit) {
                t_hit = t0;
                what = SK_HAND_SAMPLE_MARKER;
                sk_vec3d p = sk_v3d_add(o, sk_v3d_scale(s->down_h, t0));
                n_h = sk_v3d_normalize(sk_v3d_sub(p, s->markers->centre[k]));
                occ_origin = sk_v3d_add(p, sk_v3d_scale(n_h, 1e-4));
            }
        }
    sk_vec3d p_h = sk_v3d_add(o, sk_v3d_scale(s->down_h, t_hit));
    if (what == SK_HAND_SAMPLE_TABLE) occ_origin = sk_v3d_add(p_h, sk_v3d_scale(n_h, 1e-4));
    sk_vec3d n_s = sk_m3d_apply(s->to_scanner.rotation, n_h);
    double cos_laser = n_s.z, cos_camera = sk_v3d_dot(n_s, s->camera_s);
    double z_true = z_top - t_hit;
    *true_depth = (float)z_true;
    if (cos_laser < s->cos_grazing || cos_camera < s->cos_grazing ||
        camera_blocked(s, occ_origin)) {
        *depth = NAN;
        *kind = SK_HAND_SAMPLE_NONE;
        return;
    }
    double sigma = d->noise_mm / (cos_camera > 0.25 ? cos_camera : 0.25);
    double z = z_true;
    if (sigma > 0.0)
        z += sigma * sk_rand_normal(s->seed, (uint64_t)s->side, (uint64_t)i, (uint64_t)j);
    z = d->depth_step_mm * nearbyint(z / d->depth_step_mm);
    if (z > d->size_z_mm) {
        *depth = NAN;
        *kind = SK_HAND_SAMPLE_NONE;
        return;
    }
    *depth = (float)z;
    *kind = (uint8_t)what;
}

sk_result sk_hand_scan_simulate(const sk_hand_scan_target *target, const sk_hand_markers *markers,
                                sk_hand_scan_side side, const sk_hand_rigid *placement,
                                const sk_hand_scanner_desc *desc, uint64_t seed,
                                sk_hand_range_scan *out, sk_error *err)
{
    memset(out, 0, sizeof *out);
    if (side != SK_HAND_SCAN_PALM && side != SK_HAND_SCAN_BACK)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "scan side %d is neither palm (0) nor back (1)", (int)side);
    scan_setup s;
    memset(&s, 0, sizeof s);
    s.target = target;
    s.markers = markers && markers->count > 0 ? markers : NULL;
    s.d = sk_hand_scanner_desc_resolved(desc);
    sk_result r = sk_hand_scanner_desc_validate(&s.d, err);
    if (r != SK_OK) return r;
    s.to_scanner = *placement;
    s.to_hand = sk_hand_rigid_inverse(placement);
    s.down_h = sk_m3d_apply(s.to_hand.rotation, sk_v3d(0, 0, -1));
    double a = s.d.triangulation_deg * SK_DEG_TO_RAD;
    s.camera_s = sk_v3d(sin(a), 0.0, cos(a));
    s.camera_h = sk_m3d_apply(s.to_hand.rotation, s.camera_s);
    s.cos_grazing = cos(s.d.grazing_deg * SK_DEG_TO_RAD);
    s.seed = seed;
    s.side = side;
    size_t n = (size_t)s.d.lines * (size_t)s.d.points;
    out->depth = malloc(sizeof *out->depth * n);
    out->true_depth = malloc(sizeof *out->true_depth * n);
    out->kind = malloc(n);
    if (!out->depth || !out->true_depth || !out->kind) {
        sk_hand_range_scan_free(out);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "range scan of %d x %d samples", s.d.lines,
                       s.d.points);
    }
    out->side = side;
    out->lines = s.d.lines;
    out->points = s.d.points;
    out->step_x_mm = s.d.size_x_mm / s.d.lines;
    out->step_y_mm = s.d.size_y_mm / s.d.points;
    out->table_threshold_mm = s.d.table_threshold_mm;
    out->placement = *placement;
    int lines = s.d.lines, points = s.d.points;
#pragma omp parallel for schedule(dynamic, 4)
    for (int i = 0; i < lines; i++)
        for (int j = 0; j < points; j++) {
            size_t k = (size_t)i * (size_t)points + (size_t)j;
            scan_sample(&s, i, j, &out->depth[k], &out->true_depth[k], &out->kind[k]);
        }
    /* samples on each marker: the marker nearest to each marker sample */
    if (s.markers)
        for (int i = 0; i < lines; i++)
            for (int j = 0; j < points; j++) {
                size_t k = (size_t)i * (size_t)points + (size_t)j;
                if (out->kind[k] != SK_HAND_SAMPLE_MARKER) continue;
                sk_vec3d p = sk_hand_rigid_apply(
                    &s.to_hand, sk_hand_range_scan_point(out, i, j, out->true_depth[k]));
                int best = 0;
                for (int m = 1; m < s.markers->count; m++)
                    if (sk__dist2(p, s.markers->centre[m]) < sk__dist2(p, s.markers->centre[best]))
                        best = m;
                out->marker_points[best]++;
            }
    return SK_OK;
}

void sk_hand_range_scan_free(sk_hand_range_scan *scan)
{
    free(scan->depth);
    free(scan->true_depth);
    free(scan->kind);
    memset(scan, 0, sizeof *scan);
}

sk_vec3d sk_hand_range_scan_point(const sk_hand_range_scan *scan, int i, int j, double z)
{
    return sk_v3d((i + 0.5) * scan->step_x_mm, (j + 0.5) * scan->step_y_mm, z);
}
