/* Pictures of the scan pipeline of thesis 4.1, in the manner of its figures: the range
 * scans as the scanner's depth images (Fig. 4.3's data), the two scans registered, the
 * slices and their cross-sections with the resampled points (Figs. 4.5, 4.6), and meshes
 * (the polygons of Fig. 4.7, the patch layout of Fig. 4.10) from the back and the palm. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "products/hand/scan_draw_internal.h"
#include "models/hand/hand_internal.h"
#include "shitsukan/hand.h"

static const sk_color k_white = {1, 1, 1, 1};
static const sk_color k_ink = {0.08f, 0.08f, 0.08f, 1};

/* ------------------------------------------------------------ range scan */

sk_result sk_hand_draw_range_scan(const sk_hand_range_scan *scan, int scale, sk_image *out,
                                  sk_error *err)
{
    memset(out, 0, sizeof *out);
    if (scale == 0) scale = 1;
    sk_result r = sk_check_range_i(err, "scale", scale, 1, 8);
    if (r != SK_OK) return r;
    if (!scan || !scan->depth)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "no range scan to draw");
    int L = scan->lines, P = scan->points;
    sk_image img;
    r = sk_image_create(&img, P * scale, L * scale, 3, err);
    if (r != SK_OK) return r;
    float zmax = scan->table_threshold_mm + 1.0f;
    for (size_t k = 0; k < (size_t)L * P; k++)
        if (isfinite(scan->depth[k]) && scan->depth[k] > zmax) zmax = scan->depth[k];
    sk_vec3d light = sk_v3d_normalize(sk_v3d(-1.0, 1.0, 2.0));
    for (int i = 0; i < L; i++)
        for (int j = 0; j < P; j++) {
            size_t k = (size_t)i * P + j;
            float z = scan->depth[k];
            sk_color c;
            if (!isfinite(z)) {
                c = sk_rgb(0.85f, 0.22f, 0.16f); /* not measured: occluded or grazing */
            } else if (z < scan->table_threshold_mm) {
                c = k_white; /* the table, removed by the threshold */
            } else {
                /* hill shading from the depth image's own slopes */
                float zl = j > 0 && isfinite(scan->depth[k - 1]) ? scan->depth[k - 1] : z;
                float zr = j + 1 < P && isfinite(scan->depth[k + 1]) ? scan->depth[k + 1] : z;
                float zd = i > 0 && isfinite(scan->depth[k - P]) ? scan->depth[k - P] : z;
                float zu = i + 1 < L && isfinite(scan->depth[k + P]) ? scan->depth[k + P] : z;
                double gy = (zr - zl) / (2.0 * scan->step_y_mm),
                       gx = (zu - zd) / (2.0 * scan->step_x_mm);
                sk_vec3d n = sk_v3d_normalize(sk_v3d(-gx, -gy, 1.0));
                /* the picture's x is the line's y, its up is the scanner's x */
                sk_vec3d nl = {n.y, n.x, n.z};
                float shade = (float)(0.35 + 0.65 * fmax(0.0, sk_v3d_dot(nl, light)));
                float t = z / zmax;
                sk_color base = sk_rgb(0.30f + 0.62f * t, 0.33f + 0.55f * t, 0.42f + 0.38f * t);
                c = sk_rgb(base.r * shade, base.g * shade, base.b * shade);
            }
            for (int a = 0; a < scale; a++)
                for (int b = 0; b < scale; b++) {
                    float *px = sk_image_pixel(&img, j * scale + b, (L - 1 - i) * scale + a);
                    px[0] = c.r, px[1] = c.g, px[2] = c.b;
                }
        }
    char title[160];
    size_t measured = 0, unmeasured = 0;
    for (size_t k = 0; k < (size_t)L * P; k++) {
        measured += isfinite(scan->depth[k]) && scan->depth[k] >= scan->table_threshold_mm;
        unmeasured += !isfinite(scan->depth[k]);
    }
    snprintf(title, sizeof title, "%s scan, %d x %d: %zu on the cast, %zu unseen (red)",
             scan->side == SK_HAND_SCAN_BACK ? "back" : "palm", L, P, measured, unmeasured);
    const sk_image *tiles[1] = {&img};
    sk_contact_sheet_desc d = {
        .columns = 1, .padding = 6, .text_scale = 1, .title_scale = 2, .title = title};
    r = sk_contact_sheet(tiles, NULL, 1, &d, out, err);
    sk_image_free(&img);
    return r;
}

/* ------------------------------------------------------------ clouds */

typedef struct view_dir {
    sk_vec3d right, up;
    const char *name;
} view_dir;

/* Dorsal (from the back, thumb of a right hand on the left), palmar and radial views. */
static const view_dir k_dorsal = {{-1, 0, 0}, {0, 1, 0}, "from the back"};
static const view_dir k_palmar = {{1, 0, 0}, {0, 1, 0}, "from the palm"};
static const view_dir k_radial = {{0, 0, -1}, {0, 1, 0}, "from the thumb side"};

static void cloud_bounds(const sk_hand_cloud *c, sk_vec3d *lo, sk_vec3d *hi)
{
    *lo = sk_v3d(INFINITY, INFINITY, INFINITY), *hi = sk_v3d(-INFINITY, -INFINITY, -INFINITY);
    for (size_t i = 0; i < c->count; i++) {
        sk_vec3d p = c->position[i];
        lo->x = fmin(lo->x, p.x), lo->y = fmin(lo->y, p.y), lo->z = fmin(lo->z, p.z);
        hi->x = fmax(hi->x, p.x), hi->y = fmax(hi->y, p.y), hi->z = fmax(hi->z, p.z);
    }
}

static void label(sk_image *img, const char *text, float x, float y, int scale)
{
    int w = sk_draw_text_width(text, scale), h = sk_draw_text_height(scale);
    sk_draw_rect(img, x - 2, y - 2, (float)w + 4, (float)h + 4, sk_rgba(1, 1, 1, 0.8f));
    sk_draw_text(img, x, y, text, scale, k_ink);
}

static sk_result cloud_panel(const sk_hand_scan_result *res, view_dir vd, int w, int h,
                             sk_image *out, sk_error *err)
{
    sk_vec3d lo, hi;
    cloud_bounds(&res->cloud, &lo, &hi);
    sk__hand_view v;
    sk_result r = sk__hand_view_create(&v, w, h, vd.right, vd.up, lo, hi, 24, k_white, err);
    if (r != SK_OK) return r;
    sk_color palm = sk_palette(0), back = sk_palette(4);
    /* nearer points brighter: a depth cue for points without normals */
    double n0 = INFINITY, n1 = -INFINITY;
    for (int c = 0; c < 8; c++) {
        double z = sk_v3d_dot(sk_v3d(c & 1 ? hi.x : lo.x, c & 2 ? hi.y : lo.y, c & 4 ? hi.z : lo.z),
                              v.toward);
        n0 = fmin(n0, z), n1 = fmax(n1, z);
    }
    for (size_t i = 0; i < res->cloud.count; i++) {
        sk_color c = res->cloud.side[i] == SK_HAND_SCAN_BACK ? back : palm;
        float k = (float)(0.45 + 0.55 * (sk_v3d_dot(res->cloud.position[i], v.toward) - n0) /
                                     fmax(n1 - n0, 1e-9));
        sk__hand_view_point(&v, res->cloud.position[i], 0.55f, sk_rgb(c.r * k, c.g * k, c.b * k));
    }
    r = sk__hand_view_finish(&v, out, err);
    if (r == SK_OK && res->scanned) {
        /* the markers where the palm scan found them, with their residuals */
        sk_hand_rigid to_hand = sk_hand_rigid_inverse(&res->scan[SK_HAND_SCAN_PALM].placement);
        for (int k = 0; k < res->markers.count; k++) {
            sk_vec3d c = sk_hand_rigid_apply(&to_hand, res->registration.palm_centre[k]);
            sk_vec2f p = sk__hand_view_project(&v, c);
            float rad =
                (float)(res->markers.radius_mm * v.scale / SK_HAND__VIEW_SUPERSAMPLE) + 3.0f;
            sk_draw_circle(out, p.x, p.y, rad, 2.0f, k_ink);
            char text[32];
            snprintf(text, sizeof text, "%.3f", res->registration.residual_mm[k]);
            label(out, text, p.x + rad + 2, p.y - 4, 1);
        }
    }
    if (r == SK_OK) label(out, vd.name, 8, 8, 2);
    sk__hand_view_free(&v);
    return r;
}

sk_result sk_hand_draw_registered(const sk_hand_scan_result *res, sk_image *out, sk_error *err)
{
    memset(out, 0, sizeof *out);
    if (!res || res->cloud.count == 0)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "no point cloud to draw");
    sk_image panels[2] = {{0}};
    sk_result r = cloud_panel(res, k_dorsal, 520, 640, &panels[0], err);
    if (r == SK_OK) r = cloud_panel(res, k_radial, 360, 640, &panels[1], err);
    char title[200];
    if (res->scanned)
        snprintf(title, sizeof title,
                 "palm scan (blue) + back scan (orange), marker residuals mm (rms %.3f)",
                 res->registration.rms_mm);
    else
        snprintf(title, sizeof title,
                 "input point cloud: palm side (blue), back side (orange), %zu points",
                 res->cloud.count);
    const sk_image *tiles[2] = {&panels[0], &panels[1]};
    if (r == SK_OK) r = sk__hand_panels(tiles, 2, title, out, err);
    sk_image_free(&panels[0]);
    sk_image_free(&panels[1]);
    return r;
}

/* ------------------------------------------------------------ slices */

/* The slice nearest to height y. */
static int slice_near(const sk_hand_slices *s, double y)
{
    int best = 0;
    for (int k = 1; k < s->count; k++)
        if (fabs(s->y[k] - y) < fabs(s->y[best] - y)) best = k;
    return best;
}

/* One slice drawn flat: its points by link, the link centres, the resampled vertices of
 * both meshes (thesis: red; with neighbouring slices: black rings). */
static sk_result cross_section(const sk_hand_scan_result *res, int s, int w, int h, sk_image *out,
                               sk_error *err)
{
    const sk_hand_slices *sl = &res->slices;
    sk_result r = sk_image_create(out, w, h, 3, err);
    if (r != SK_OK) return r;
    sk_draw_clear(out, k_white);
    double x0 = INFINITY, x1 = -INFINITY, z0 = INFINITY, z1 = -INFINITY;
    for (size_t k = sl->first[s]; k < sl->first[s + 1]; k++) {
        sk_vec3d p = res->cloud.position[sl->points[k].point];
        x0 = fmin(x0, p.x), x1 = fmax(x1, p.x), z0 = fmin(z0, p.z), z1 = fmax(z1, p.z);
    }
    if (!(x1 > x0)) return SK_OK;
    int top = 24;
    double scale = fmin((w - 20) / (x1 - x0), (h - top - 12) / fmax(z1 - z0, 1.0));
    double cx = 0.5 * (x0 + x1), cz = 0.5 * (z0 + z1);
    /* seen from the wrist side looking distally, palm up: x to the right would mirror the
       dorsal view; keep the dorsal view's left-right (thumb of a right hand on the left) */
#define PX(x) ((float)(0.5 * w - scale * ((x)-cx)))
#define PY(z) ((float)(top + 0.5 * (h - top) - scale * ((z)-cz)))
    for (size_t k = sl->first[s]; k < sl->first[s + 1]; k++) {
        sk_vec3d p = res->cloud.position[sl->points[k].point];
        sk_draw_disc(out, PX(p.x), PY(p.z), 1.3f, sk__hand_link_color(sl->points[k].link));
    }
    for (int pass = 0; pass < 2; pass++) {
        const sk_mesh *m = pass ? &res->polygons : &res->polygons_thesis;
        for (size_t v = 0; v < m->vertex_count; v++) {
            if (fabs(m->positions[3 * v + 1] - sl->y[s]) > 1e-3) continue;
            float x = PX(m->positions[3 * v]), y = PY(m->positions[3 * v + 2]);
            if (pass)
                sk_draw_circle(out, x, y, 3.0f, 1.2f, k_ink);
            else
                sk_draw_rect(out, x - 1.8f, y - 1.8f, 3.6f, 3.6f, sk_rgb(0.85f, 0.15f, 0.1f));
        }
    }
    for (int l = 0; l < SK_HAND_LINK_COUNT; l++) {
        bool used = false;
        for (size_t k = sl->first[s]; k < sl->first[s + 1] && !used; k++)
            used = sl->points[k].link == l;
        if (!used) continue;
        sk_vec3d c = sl->centre[s][l];
        float x = PX(c.x), y = PY(c.z);
        sk_draw_line(out, x - 4, y, x + 4, y, 1.5f, k_ink);
        sk_draw_line(out, x, y - 4, x, y + 4, 1.5f, k_ink);
    }
#undef PX
#undef PY
    char text[96];
    snprintf(text, sizeof text, "slice %d of %d, y = %.1f mm", s + 1, sl->count, sl->y[s]);
    sk_draw_text(out, 6, 6, text, 1, k_ink);
    return SK_OK;
}

sk_result sk_hand_draw_slices(const sk_hand_scan_result *res, sk_image *out, sk_error *err)
{
    memset(out, 0, sizeof *out);
    if (!res || res->slices.count == 0)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "no slices to draw");
    const sk_hand_slices *sl = &res->slices;
    sk_vec3d lo, hi;
    cloud_bounds(&res->cloud, &lo, &hi);
    sk__hand_view v;
    sk_result r =
        sk__hand_view_create(&v, 520, 640, k_dorsal.right, k_dorsal.up, lo, hi, 24, k_white, err);
    if (r != SK_OK) return r;
    sk_color grey = sk_rgb(0.82f, 0.82f, 0.82f);
    for (size_t i = 0; i < res->cloud.count; i++)
        sk__hand_view_point(&v, res->cloud.position[i], 0.5f, grey);
    /* the slices' points on top (pushed toward the viewer) */
    for (size_t k = 0; k < sl->first[sl->count]; k++) {
        sk_vec3d p =
            sk_v3d_add(res->cloud.position[sl->points[k].point], sk_v3d_scale(v.toward, 200.0));
        sk__hand_view_point(&v, p, 0.9f, sk__hand_link_color(sl->points[k].link));
    }
    sk_image panels[4] = {{0}};
    r = sk__hand_view_finish(&v, &panels[0], err);
    sk__hand_view_free(&v);
    /* three cross-sections: the middle finger's proximal phalanx, the knuckles, the palm */
    const sk_hand_frames *f = &res->frames;
    double ys[3] = {0.5 * (f->point[sk_hand_link_point(9)].y + f->point[sk_hand_link_point(10)].y),
                    f->point[sk_hand_link_point(9)].y - 4.0,
                    0.5 * (f->point[sk_hand_link_point(8)].y + f->point[sk_hand_link_point(9)].y)};
    for (int k = 0; k < 3 && r == SK_OK; k++)
        r = cross_section(res, slice_near(sl, ys[k]), 420, 206, &panels[1 + k], err);
    sk_image column = {0}, *col = &column;
    if (r == SK_OK) {
        const sk_image *tiles[3] = {&panels[1], &panels[2], &panels[3]};
        sk_contact_sheet_desc d = {.columns = 1, .padding = 4, .tile_border = 1};
        r = sk_contact_sheet(tiles, NULL, 3, &d, col, err);
    }
    char title[200];
    snprintf(title, sizeof title,
             "%d slices, points by nearest link; resampled: red slice alone, black with "
             "neighbours",
             sl->count);
    if (r == SK_OK) {
        const sk_image *tiles[2] = {&panels[0], col};
        r = sk__hand_panels(tiles, 2, title, out, err);
    }
    for (int k = 0; k < 4; k++) sk_image_free(&panels[k]);
    sk_image_free(&column);
    return r;
}

/* ------------------------------------------------------------ meshes */

static view_dir view_of(sk_hand_view v)
{
    static const view_dir ulnar = {{0, 0, 1}, {0, 1, 0}, "from the little-finger side"};
    switch (v) {
    case SK_HAND_VIEW_PALMAR:
        return k_palmar;
    case SK_HAND_VIEW_RADIAL:
        return k_radial;
    case SK_HAND_VIEW_ULNAR:
        return ulnar;
    default:
        return k_dorsal;
    }
}

static sk_result mesh_panel(const sk_mesh *m, const sk_mesh_attribute *attr, bool link_colors,
                            view_dir vd, int w, int h, sk_image *out, sk_error *err)
{
    sk_vec3d lo, hi;
    if (!sk__hand_mesh_bounds(m, &lo, &hi))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "empty mesh");
    sk__hand_view v;
    sk_result r = sk__hand_view_create(&v, w, h, vd.right, vd.up, lo, hi, 24, k_white, err);
    if (r != SK_OK) return r;
    for (size_t t = 0; t < m->triangle_count; t++) {
        const uint32_t *ix = m->indices + 3 * t;
        sk_vec3d p[3];
        for (int c = 0; c < 3; c++)
            p[c] = sk_v3d(m->positions[3 * ix[c]], m->positions[3 * ix[c] + 1],
                          m->positions[3 * ix[c] + 2]);
        sk_color col = sk_rgb(0.8f, 0.78f, 0.74f);
        if (attr) {
            int k = (int)attr->data[(size_t)ix[0] * (size_t)attr->components];
            col = link_colors ? sk__hand_link_color(k) : sk__hand_index_color(k);
        }
        sk__hand_view_triangle(&v, p[0], p[1], p[2], col);
    }
    r = sk__hand_view_finish(&v, out, err);
    if (r == SK_OK) label(out, vd.name, 8, 8, 2);
    sk__hand_view_free(&v);
    return r;
}

sk_result sk_hand_draw_mesh_views(const sk_mesh *mesh, const char *title,
                                  const char *color_attribute, const sk_hand_view *views,
                                  int view_count, sk_image *out, sk_error *err)
{
    memset(out, 0, sizeof *out);
    if (!mesh || mesh->triangle_count == 0)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "no triangles to draw");
    sk_result r = sk_check_range_i(err, "view_count", view_count, 0, 4);
    if (r != SK_OK) return r;
    static const sk_hand_view pair[2] = {SK_HAND_VIEW_DORSAL, SK_HAND_VIEW_PALMAR};
    if (view_count == 0) views = pair, view_count = 2;
    const sk_mesh_attribute *attr =
        color_attribute ? sk_mesh_find_attribute(mesh, color_attribute) : NULL;
    bool link_colors = color_attribute && strcmp(color_attribute, "link") == 0;
    sk_image panels[4] = {{0}};
    const sk_image *tiles[4];
    for (int k = 0; k < view_count && r == SK_OK; k++) {
        view_dir vd = view_of(views[k]);
        bool side_view = views[k] == SK_HAND_VIEW_RADIAL || views[k] == SK_HAND_VIEW_ULNAR;
        r = mesh_panel(mesh, attr, link_colors, vd, side_view ? 360 : 480, 600, &panels[k], err);
        tiles[k] = &panels[k];
    }
    if (r == SK_OK) r = sk__hand_panels(tiles, view_count, title, out, err);
    for (int k = 0; k < 4; k++) sk_image_free(&panels[k]);
    return r;
}

/* The fitted patches moved to `pose` and tessellated. */
static sk_result posed_mesh(const sk_hand_patch_set *set, const sk_hand_frames *rest,
                            const sk_hand_frames *pose, const sk_hand_patch_weights *weights,
                            sk_mesh *out, sk_error *err)
{
    sk_hand_patch moved[SK_HAND_PATCH_COUNT];
    sk_hand_patch_weights w[16 * SK_HAND_PATCH_COUNT];
    int n = 0;
    for (int k = 0; k < set->count; k++) {
        if (!set->fitted[k]) continue;
        moved[n] = set->patch[k];
        if (weights) memcpy(&w[16 * n], &weights[16 * k], sizeof *w * 16);
        n++;
    }
    if (n == 0) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "no fitted patch to draw");
    sk_result r = sk_hand_patches_pose(moved, n, rest, pose, weights ? w : NULL, moved, err);
    if (r == SK_OK) r = sk_hand_patches_tessellate(moved, n, 16, out, err);
    return r;
}

sk_result sk_hand_draw_patches_posed(const sk_hand_patch_set *set, const sk_hand_frames *rest,
                                     const sk_hand_frames *pose,
                                     const sk_hand_patch_weights *weights, sk_image *out,
                                     sk_error *err)
{
    memset(out, 0, sizeof *out);
    static const sk_hand_view views[2] = {SK_HAND_VIEW_RADIAL, SK_HAND_VIEW_DORSAL};
    sk_image sheets[2] = {{0}};
    int count = weights ? 2 : 1;
    sk_result r = SK_OK;
    for (int k = 0; k < count && r == SK_OK; k++) {
        sk_mesh m = {0};
        r = posed_mesh(set, rest, pose, k ? weights : NULL, &m, err);
        if (r == SK_OK)
            r = sk_hand_draw_mesh_views(&m,
                                        k ? "control points with smooth weights"
                                          : "control points rigid with their links (thesis)",
                                        "patch", views, 2, &sheets[k], err);
        sk_mesh_free(&m);
    }
    const sk_image *tiles[2] = {&sheets[0], &sheets[1]};
    if (r == SK_OK) {
        sk_contact_sheet_desc d = {.columns = count, .padding = 4};
        r = sk_contact_sheet(tiles, NULL, count, &d, out, err);
    }
    sk_image_free(&sheets[0]);
    sk_image_free(&sheets[1]);
    return r;
}
