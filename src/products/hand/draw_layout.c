/* Views and framing of the skeleton pictures: orthographic cameras along the world axes
 * (dorsal, palmar, radial, ulnar), a window fitted over the poses to show, and one scale
 * shared by all panels so that lengths compare across views and frames. */
#include <math.h>
#include <string.h>

#include "products/hand/hand_draw_internal.h"
#include "models/hand/hand_internal.h"
#include "shitsukan/hand.h"

sk_hand_draw_desc sk_hand_draw_desc_resolved(const sk_hand_draw_desc *desc)
{
    sk_hand_draw_desc d = {0};
    if (desc) d = *desc;
    if (d.view_count == 0) d.view_count = 2;
    if (d.view_count >= 1 && d.view_count <= SK_HAND_DRAW_MAX_VIEWS) {
        static const sk_hand_view order[SK_HAND_DRAW_MAX_VIEWS] = {
            SK_HAND_VIEW_DORSAL, SK_HAND_VIEW_RADIAL, SK_HAND_VIEW_PALMAR, SK_HAND_VIEW_ULNAR};
        for (int i = 0; i < d.view_count; i++)
            if (d.views[i] == SK_HAND_VIEW_DEFAULT) d.views[i] = order[i];
    }
    if (d.width == 0) d.width = 400 * d.view_count;
    if (d.height == 0) d.height = 480;
    if (d.text_scale == 0) d.text_scale = d.height >= 400 ? 2 : 1;
    if (d.framing == SK_HAND_FRAMING_DEFAULT) d.framing = SK_HAND_FRAMING_REACH;
    return d;
}

static sk_result check_desc(const sk_hand_draw_desc *d, sk_error *err)
{
    sk_result r = sk_check_range_i(err, "view_count", d->view_count, 1, SK_HAND_DRAW_MAX_VIEWS);
    if (r == SK_OK) r = sk_check_range_i(err, "width", d->width, 64, 8192);
    if (r == SK_OK) r = sk_check_range_i(err, "height", d->height, 64, 8192);
    if (r == SK_OK) r = sk_check_range_i(err, "text_scale", d->text_scale, 1, 8);
    if (r == SK_OK) r = sk_check_range_i(err, "framing", (int)d->framing, 0, SK_HAND_FRAMING_TIGHT);
    for (int i = 0; r == SK_OK && i < d->view_count; i++) {
        char name[32];
        snprintf(name, sizeof name, "views[%d]", i);
        r = sk_check_range_i(err, name, (int)d->views[i], 0, SK_HAND_VIEW_ULNAR);
    }
    if (r == SK_OK && d->width / d->view_count < 64)
        r = sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                    "width = %d leaves less than 64 pixels for each of %d views", d->width,
                    d->view_count);
    return r;
}

const char *sk__hand_view_title(sk_hand_view view)
{
    switch (view) {
    case SK_HAND_VIEW_PALMAR:
        return "palmar (palm)";
    case SK_HAND_VIEW_RADIAL:
        return "radial (thumb side)";
    case SK_HAND_VIEW_ULNAR:
        return "ulnar (little-finger side)";
    default:
        return "dorsal (back of the hand)";
    }
}

/* The camera: toward = direction from the hand to the viewer; up = +Y (fingers up);
 * right = up x toward keeps the picture unmirrored. The radial side of a left hand is
 * -X, so its radial view is the mirror image of a right hand's. */
static void view_axes(sk_hand_view view, sk_hand_side side, sk_hand_panel *p)
{
    double radial = side == SK_HAND_SIDE_LEFT ? -1.0 : 1.0;
    sk_vec3d toward;
    switch (view) {
    case SK_HAND_VIEW_PALMAR:
        toward = sk_v3d(0, 0, 1);
        break;
    case SK_HAND_VIEW_RADIAL:
        toward = sk_v3d(radial, 0, 0);
        break;
    case SK_HAND_VIEW_ULNAR:
        toward = sk_v3d(-radial, 0, 0);
        break;
    default:
        toward = sk_v3d(0, 0, -1);
        break;
    }
    p->view = view;
    p->toward = toward;
    p->up = sk_v3d(0, 1, 0);
    p->right = sk_v3d_cross(p->up, toward);
}

/* Band heights (pixels) of a layout: panel title, cue band at the panel bottom, caption
 * under the panels, and the margin around the drawing area. */
void sk__hand_bands(const sk_hand_draw_desc *d, sk__hand_band_sizes *b)
{
    int th = sk_draw_text_height(d->text_scale);
    b->margin = 4 * d->text_scale;
    b->title = d->hide_panel_titles ? 0 : th + 2 * b->margin;
    b->cues = d->hide_cues ? 0 : th + 3 * b->margin;
    /* a caption too wide for one line gets two */
    int lines = 0;
    if (d->caption && d->caption[0])
        lines =
            sk_draw_text_width(d->caption, d->text_scale) > d->width - 4 * d->text_scale ? 2 : 1;
    b->caption = lines ? lines * th + (lines - 1) * 3 * d->text_scale + 2 * b->margin : 0;
}

/* Poses that bound what the hand can reach with the given wrist DOFs: flat, relaxed,
 * every flexion at its upper limit (fist) and at its lower limit (extension), every
 * abduction at its upper limit with the fingers straight (spread). */
static void reach_pose(const sk_hand_skeleton *s, const double *pose, int which, double *q)
{
    for (int i = 0; i < SK_HAND_DOF_COUNT; i++) {
        const sk_hand_dof_data *dd = &s->dof[i];
        bool flex = sk_hand_dof(i)->axis == 'X';
        if (i < SK_HAND_WRIST_DOF_COUNT)
            q[i] = pose[i];
        else if (which == 0)
            q[i] = sk_clampd(0.0, dd->min, dd->max);
        else if (which == 1)
            q[i] = dd->relaxed;
        else if (which == 2)
            q[i] = flex ? dd->max : dd->relaxed;
        else if (which == 3)
            q[i] = flex ? dd->min : dd->relaxed;
        else
            q[i] = flex ? sk_clampd(0.0, dd->min, dd->max) : dd->max;
    }
}
#define REACH_POSE_COUNT 5

typedef struct box2 {
    double lo[SK_HAND_DRAW_MAX_VIEWS][2], hi[SK_HAND_DRAW_MAX_VIEWS][2]; /* right, up */
} box2;

static void box_add(box2 *b, const sk_hand_draw_layout *l, sk_vec3d p)
{
    for (int v = 0; v < l->view_count; v++) {
        const sk_hand_panel *pn = &l->panel[v];
        double c[2] = {sk_v3d_dot(p, pn->right), sk_v3d_dot(p, pn->up)};
        for (int k = 0; k < 2; k++) {
            if (c[k] < b->lo[v][k]) b->lo[v][k] = c[k];
            if (c[k] > b->hi[v][k]) b->hi[v][k] = c[k];
        }
    }
}

static void box_add_pose(box2 *b, const sk_hand_draw_layout *l, const sk_hand_skeleton *s,
                         const double *q, bool cues)
{
    sk_hand_frames f;
    sk_hand_forward(s, q, &f);
    for (int i = 0; i < SK_HAND_POINT_COUNT; i++) box_add(b, l, f.point[i]);
    /* the visible part of the forearm below the wrist */
    if (cues)
        box_add(b, l,
                sk_v3d_add(f.point[0], sk_v3d(0, -SK_HAND__FOREARM_SHOWN * s->hand_length_mm, 0)));
}

sk_result sk_hand_draw_layout_fit(const sk_hand_skeleton *skeleton, const double *poses,
                                  int pose_count, const sk_hand_draw_desc *desc,
                                  sk_hand_draw_layout *layout, sk_error *err)
{
    sk_hand_draw_desc d = sk_hand_draw_desc_resolved(desc);
    sk_result r = check_desc(&d, err);
    if (r != SK_OK) return r;
    if (!skeleton || !poses || pose_count < 1)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "pose_count = %d must be at least 1",
                       pose_count);
    for (size_t i = 0; i < (size_t)pose_count * SK_HAND_DOF_COUNT; i++)
        if (!isfinite(poses[i]))
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "pose %zu: %s is not finite",
                           i / SK_HAND_DOF_COUNT, sk_hand_dof((int)(i % SK_HAND_DOF_COUNT))->name);

    memset(layout, 0, sizeof *layout);
    layout->width = d.width;
    layout->height = d.height;
    layout->text_scale = d.text_scale;
    layout->view_count = d.view_count;
    for (int v = 0; v < d.view_count; v++) view_axes(d.views[v], skeleton->side, &layout->panel[v]);

    box2 box;
    for (int v = 0; v < SK_HAND_DRAW_MAX_VIEWS; v++)
        for (int k = 0; k < 2; k++) box.lo[v][k] = INFINITY, box.hi[v][k] = -INFINITY;
    for (int p = 0; p < pose_count; p++) {
        const double *pose = poses + (size_t)p * SK_HAND_DOF_COUNT;
        box_add_pose(&box, layout, skeleton, pose, !d.hide_cues);
        for (int w = 0; d.framing == SK_HAND_FRAMING_REACH && w < REACH_POSE_COUNT; w++) {
            double q[SK_HAND_DOF_COUNT];
            reach_pose(skeleton, pose, w, q);
            box_add_pose(&box, layout, skeleton, q, !d.hide_cues);
        }
    }

    sk__hand_band_sizes bands;
    sk__hand_bands(&d, &bands);
    int area_h = d.height - bands.caption - bands.title - bands.cues - 2 * bands.margin;
    /* at least a few pixels per millimetre's worth of room */
    double scale = INFINITY;
    int x = 0;
    for (int v = 0; v < d.view_count; v++) {
        sk_hand_panel *p = &layout->panel[v];
        p->x0 = x;
        p->width = (d.width - x) / (d.view_count - v);
        x += p->width;
        p->y0 = 0;
        p->height = d.height - bands.caption;
        int area_w = p->width - 2 * bands.margin;
        /* a minimum extent keeps a degenerate box (all points in a line) finite */
        double w = fmax(box.hi[v][0] - box.lo[v][0], 1.0),
               h = fmax(box.hi[v][1] - box.lo[v][1], 1.0);
        scale = fmin(scale, fmin(area_w / w, area_h / h));
    }
    if (!(scale > 0.0) || area_h < 16)
        return sk_fail(err, SK_ERROR_LIMIT,
                       "a %d x %d picture leaves no room for the skeleton below its text "
                       "(text_scale = %d)",
                       d.width, d.height, d.text_scale);
    layout->pixels_per_mm = scale;
    for (int v = 0; v < d.view_count; v++) {
        sk_hand_panel *p = &layout->panel[v];
        double cx = 0.5 * (box.lo[v][0] + box.hi[v][0]), cy = 0.5 * (box.lo[v][1] + box.hi[v][1]);
        double area_cx = p->x0 + 0.5 * p->width;
        double area_cy = p->y0 + bands.title + bands.margin + 0.5 * area_h;
        p->origin_x = area_cx - scale * cx;
        p->origin_y = area_cy + scale * cy;
    }
    return SK_OK;
}

sk_vec2d sk_hand_draw_project(const sk_hand_draw_layout *l, int view_index, sk_vec3d p)
{
    const sk_hand_panel *pn = &l->panel[view_index];
    return sk_v2d(pn->origin_x + l->pixels_per_mm * sk_v3d_dot(p, pn->right),
                  pn->origin_y - l->pixels_per_mm * sk_v3d_dot(p, pn->up));
}
