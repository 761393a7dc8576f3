/* Stick figure of a posed skeleton (thesis 3.1: the link tree of Fig. 3.2): every link as
 * an anti-aliased bone in its finger's colour, joints as discs, the palm as a translucent
 * plate, drawn far to near with a depth cue, in orthographic panels laid out by
 * draw_layout.c, with the end of the forearm, direction arrows and a scale bar. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "products/hand/hand_draw_internal.h"
#include "models/hand/hand_internal.h"
#include "shitsukan/hand.h"

sk_color sk_hand_finger_color(sk_hand_finger finger)
{
    /* Okabe-Ito colours: thumb vermillion, index blue, middle bluish green, ring reddish
       purple, little orange */
    static const int palette_index[SK_HAND_FINGER_COUNT] = {1, 0, 2, 3, 4};
    if ((int)finger < 0 || finger >= SK_HAND_FINGER_COUNT) return sk_rgb(0.25f, 0.25f, 0.25f);
    return sk_palette(palette_index[finger]);
}

static const sk_color k_background = {1.0f, 1.0f, 1.0f, 1.0f};
static const sk_color k_ink = {0.06f, 0.06f, 0.06f, 1.0f};
static const sk_color k_carpus = {0.30f, 0.30f, 0.30f, 1.0f};

static sk_color mix(sk_color a, sk_color b, float t)
{
    return sk_rgba(a.r + (b.r - a.r) * t, a.g + (b.g - a.g) * t, a.b + (b.b - a.b) * t, a.a);
}

static sk_color scaled(sk_color c, float k) { return sk_rgba(c.r * k, c.g * k, c.b * k, c.a); }

/* One thing to draw, ordered far to near. */
typedef enum item_kind { ITEM_CARPAL, ITEM_BONE, ITEM_JOINT, ITEM_TIP } item_kind;
typedef struct draw_item {
    double depth; /* nearness to the viewer: larger is drawn later */
    item_kind kind;
    int a, b;  /* points: a bone from a to b; a joint at a */
    int order; /* stable tie-break */
} draw_item;

static int compare_items(const void *pa, const void *pb)
{
    const draw_item *a = pa, *b = pb;
    if (a->depth != b->depth) return a->depth < b->depth ? -1 : 1;
    return a->order - b->order;
}

/* Finger of a point (-1 for the wrist). */
static int finger_of_point(int point)
{
    if (point <= 0) return -1;
    if (point <= 4) return SK_HAND_THUMB;
    return 1 + (point - 5) / 5;
}

static bool point_is_tip(int point) { return point == 4 || (point >= 5 && (point - 5) % 5 == 4); }

/* Sizes in pixels derived from the scale. */
typedef struct sizes {
    float bone;  /* bone stroke width */
    float joint; /* joint disc radius */
    float tip;   /* fingertip disc radius */
} sizes;

static sizes stroke_sizes(double pixels_per_mm)
{
    sizes z;
    z.bone = (float)sk_clampd(3.4 * pixels_per_mm, 1.5, 28.0);
    z.joint = 0.95f * z.bone;
    z.tip = 0.62f * z.bone;
    return z;
}

typedef struct panel_ctx {
    const sk_hand_draw_layout *layout;
    const sk_hand_panel *panel;
    int view_index;
    const sk_hand_skeleton *skeleton;
    const sk_hand_frames *frames;
    sk_image *img; /* the panel's own image */
    sk__hand_band_sizes bands;
    int area_bottom; /* y of the drawing area's lower edge (panel coordinates) */
    sizes size;
} panel_ctx;

/* Pixel position in the panel image. */
static sk_vec2f to_panel(const panel_ctx *c, sk_vec3d p)
{
    sk_vec2d q = sk_hand_draw_project(c->layout, c->view_index, p);
    return sk_v2f((float)(q.x - c->panel->x0), (float)(q.y - c->panel->y0));
}

static double nearness(const panel_ctx *c, sk_vec3d p) { return sk_v3d_dot(p, c->panel->toward); }

/* Depth cue: 0 for points as near as the wrist or nearer, rising to 1 half a hand length
 * farther away (a property of the pose alone, so a pose looks the same in any frame). */
static float farness(const panel_ctx *c, double depth)
{
    double wrist = nearness(c, c->frames->point[0]);
    return (float)sk_clampd((wrist - depth) / (0.5 * c->skeleton->hand_length_mm), 0.0, 1.0);
}

/* The fixed forearm below the wrist: an elliptic cylinder along world -Y (about 0.6 HB
 * wide and 0.4 HB thick), fading out toward the bottom of the drawing area. */
static void draw_forearm(const panel_ctx *c)
{
    const sk_hand_panel *pn = c->panel;
    double hb = c->skeleton->hand_breadth_mm;
    double half =
        hypot(0.30 * hb * pn->right.x, 0.20 * hb * pn->right.z) * c->layout->pixels_per_mm;
    sk_vec2f w = to_panel(c, c->frames->point[0]);
    float top = w.y, bottom = (float)c->area_bottom;
    if (!(bottom > top)) return;
    int slices = 24;
    float step = (bottom - top) / (float)slices;
    for (int i = 0; i < slices; i++) {
        float t = (i + 0.5f) / (float)slices;
        float alpha = t < 0.4f ? 1.0f : 1.0f - (t - 0.4f) / 0.6f;
        sk_color col = sk_rgba(0.80f, 0.80f, 0.80f, alpha);
        sk_draw_rect(c->img, w.x - (float)half, top + i * step, (float)(2.0 * half), step, col);
    }
}

/* The palm plate: the metacarpal heads, the CMC joints of the little finger and the
 * thumb, and the two points at wrist level below them. */
static void draw_palm(const panel_ctx *c)
{
    const sk_hand_frames *f = c->frames;
    sk_vec3d wrist = f->point[0];
    sk_vec3d axis = sk_v3d(f->rotation[0].m[0][1], f->rotation[0].m[1][1], f->rotation[0].m[2][1]);
    static const int rim[] = {20, 21, 16, 11, 6, 1}; /* L.CMC L.MCP R.MCP M.MCP I.MCP T.CMC */
    int n = (int)(sizeof rim / sizeof rim[0]);
    sk_vec2f pts[8];
    for (int i = 0; i < n; i++) pts[i] = to_panel(c, f->point[rim[i]]);
    /* below T.CMC and L.CMC at the wrist's level along the carpus axis */
    int ends[2] = {1, 20};
    for (int k = 0; k < 2; k++) {
        sk_vec3d d = sk_v3d_sub(f->point[ends[k]], wrist);
        sk_vec3d foot = sk_v3d_add(wrist, sk_v3d_sub(d, sk_v3d_scale(axis, sk_v3d_dot(d, axis))));
        pts[n++] = to_panel(c, foot);
    }
    /* order: ... T.CMC, below T.CMC, below L.CMC, back to L.CMC */
    sk_draw_polygon(c->img, pts, n, sk_rgba(0.55f, 0.55f, 0.58f, 0.22f));
    sk_draw_polyline(c->img, pts, n, true, 1.0f, sk_rgba(0.45f, 0.45f, 0.48f, 0.55f));
}

static int build_items(const panel_ctx *c, draw_item *items)
{
    const sk_hand_frames *f = c->frames;
    int n = 0;
    double bone_depth[SK_HAND_POINT_COUNT]; /* of the bone ending at each point */
    for (int p = 1; p < SK_HAND_POINT_COUNT; p++) {
        int parent = sk_hand_point_parent(p);
        double d = 0.5 * (nearness(c, f->point[parent]) + nearness(c, f->point[p]));
        bone_depth[p] = d;
        draw_item it = {d, parent == 0 ? ITEM_CARPAL : ITEM_BONE, parent, p, n};
        items[n++] = it;
    }
    for (int p = 0; p < SK_HAND_POINT_COUNT; p++) {
        /* a joint is drawn over the bones that meet at it */
        double d = nearness(c, f->point[p]);
        if (p > 0) d = fmax(d, bone_depth[p]);
        for (int q = p + 1; q < SK_HAND_POINT_COUNT; q++)
            if (sk_hand_point_parent(q) == p && p > 0) d = fmax(d, bone_depth[q]);
        draw_item it = {d + 1e-6, point_is_tip(p) ? ITEM_TIP : ITEM_JOINT, p, p, n};
        items[n++] = it;
    }
    qsort(items, (size_t)n, sizeof *items, compare_items);
    return n;
}

static void draw_item_one(const panel_ctx *c, const draw_item *it)
{
    const sk_hand_frames *f = c->frames;
    float far = farness(c, it->depth);
    float shrink = 1.0f - 0.3f * far;
    int finger = finger_of_point(it->kind == ITEM_JOINT || it->kind == ITEM_TIP ? it->a : it->b);
    sk_color base = finger < 0 ? k_carpus : sk_hand_finger_color((sk_hand_finger)finger);
    sk_color col = mix(base, k_background, 0.55f * far);
    sk_vec2f a = to_panel(c, f->point[it->a]), b = to_panel(c, f->point[it->b]);
    switch (it->kind) {
    case ITEM_CARPAL:
        sk_draw_line(c->img, a.x, a.y, b.x, b.y, 0.45f * c->size.bone * shrink,
                     mix(k_carpus, k_background, 0.55f * far));
        break;
    case ITEM_BONE:
        sk_draw_line(c->img, a.x, a.y, b.x, b.y, c->size.bone * shrink, col);
        break;
    case ITEM_JOINT: {
        float r = c->size.joint * shrink;
        if (it->a == 0) r *= 1.15f;
        sk_draw_disc(c->img, a.x, a.y, r, mix(scaled(base, 0.55f), k_background, 0.55f * far));
        sk_draw_disc(c->img, a.x, a.y, 0.45f * r, mix(sk_rgb(1, 1, 1), k_background, far));
        break;
    }
    case ITEM_TIP:
        sk_draw_disc(c->img, a.x, a.y, c->size.tip * shrink,
                     mix(scaled(base, 0.55f), k_background, 0.55f * far));
        break;
    }
}

/* Point names beside the points: labels of the fingers on the radial side (thumb,
 * index) start looking for room on the radial side, the others on the ulnar side. */
static void draw_point_labels(const panel_ctx *c)
{
    double radial_x = c->skeleton->side == SK_HAND_SIDE_LEFT ? -1.0 : 1.0;
    double radial_screen = radial_x * c->panel->right.x;
    sk_vec2f pts[SK_HAND_POINT_COUNT];
    float radius[SK_HAND_POINT_COUNT], prefer[SK_HAND_POINT_COUNT];
    const char *names[SK_HAND_POINT_COUNT];
    sk_color colors[SK_HAND_POINT_COUNT];
    int bones[SK_HAND_POINT_COUNT][2], bone_count = 0;
    for (int p = 0; p < SK_HAND_POINT_COUNT; p++) {
        int finger = finger_of_point(p);
        pts[p] = to_panel(c, c->frames->point[p]);
        radius[p] = p == 0 ? 1.15f * c->size.joint : point_is_tip(p) ? c->size.tip : c->size.joint;
        names[p] = sk_hand_point_name(p);
        double dir =
            finger == SK_HAND_THUMB || finger == SK_HAND_INDEX ? radial_screen : -radial_screen;
        prefer[p] = fabs(dir) < 0.5 ? 1.0f : (float)dir;
        colors[p] = finger < 0 ? k_ink : scaled(sk_hand_finger_color((sk_hand_finger)finger), 0.7f);
        if (p > 0) {
            bones[bone_count][0] = sk_hand_point_parent(p);
            bones[bone_count++][1] = p;
        }
    }
    sk__hand_label_scene scene = {
        pts,          radius, SK_HAND_POINT_COUNT,   (const int(*)[2])bones, bone_count,
        c->size.bone, 0.0f,   (float)c->bands.title, (float)c->panel->width, (float)c->area_bottom};
    sk__hand_draw_labels(c->img, &scene, names, colors, prefer, c->layout->text_scale);
}

/* An arrow from (x0, y0) of length len in direction (dx, dy) (unit), with a head. */
static void draw_arrow(sk_image *img, float x0, float y0, float dx, float dy, float len,
                       float width, sk_color col)
{
    float x1 = x0 + dx * len, y1 = y0 + dy * len;
    float head = 3.0f * width + 2.0f;
    sk_draw_line(img, x0, y0, x1 - dx * head * 0.6f, y1 - dy * head * 0.6f, width, col);
    sk_vec2f tri[3] = {
        sk_v2f(x1, y1),
        sk_v2f(x1 - dx * head - dy * head * 0.5f, y1 - dy * head + dx * head * 0.5f),
        sk_v2f(x1 - dx * head + dy * head * 0.5f, y1 - dy * head - dx * head * 0.5f)};
    sk_draw_polygon(img, tri, 3, col);
}

/* Direction arrows (the hand's distal and radial or palmar directions, from the carpus
 * frame, as seen in this view) at the lower left, a scale bar at the lower right. */
static void draw_cues(const panel_ctx *c)
{
    const sk_hand_panel *pn = c->panel;
    int scale = c->layout->text_scale, m = c->bands.margin;
    float th = (float)sk_draw_text_height(scale);
    float yc = (float)pn->height - 0.5f * (float)c->bands.cues;
    sk_color grey = sk_rgb(0.25f, 0.25f, 0.25f);
    const sk_mat3d *rc = &c->frames->rotation[0];
    sk_vec3d distal = sk_v3d(rc->m[0][1], rc->m[1][1], rc->m[2][1]);
    bool side_view = fabs(pn->toward.x) > 0.5;
    /* the carpus X is radial for a right hand; the mirrored frame keeps it radial for a
       left one only after negation */
    sk_vec3d lateral = side_view ? sk_v3d(rc->m[0][2], rc->m[1][2], rc->m[2][2])
                                 : sk_v3d(rc->m[0][0], rc->m[1][0], rc->m[2][0]);
    if (!side_view && c->skeleton->side == SK_HAND_SIDE_LEFT) lateral = sk_v3d_scale(lateral, -1.0);
    const char *names[2] = {"distal", side_view ? "palmar" : "radial"};
    sk_vec3d dirs[2] = {distal, lateral};
    float x = (float)m;
    float width = fmaxf(1.5f, 0.75f * scale);
    for (int k = 0; k < 2; k++) {
        double dx = sk_v3d_dot(dirs[k], pn->right), dy = -sk_v3d_dot(dirs[k], pn->up);
        double len = hypot(dx, dy);
        if (len < 0.3) continue;
        dx /= len;
        dy /= len;
        float reach = fabsf((float)dy) > fabsf((float)dx) ? th : 2.0f * th;
        /* the arrow's box is reach wide (horizontal) or th wide (vertical), centred */
        float box_w = fabsf((float)dx) * reach + fabsf((float)dy) * 0.6f * th;
        float ax = x + 0.5f * box_w - 0.5f * (float)dx * reach, ay = yc - 0.5f * (float)dy * reach;
        draw_arrow(c->img, ax, ay, (float)dx, (float)dy, reach, width, grey);
        x += box_w + 2.0f * scale;
        x += (float)sk_draw_text(c->img, x, yc - 0.5f * th, names[k], scale, grey) + 4.0f * scale;
    }
    /* scale bar: the longest round length within a quarter of the panel */
    static const double lengths[] = {500, 200, 100, 50, 20, 10, 5, 2, 1};
    double s = c->layout->pixels_per_mm;
    for (size_t i = 0; i < sizeof lengths / sizeof lengths[0]; i++) {
        float len = (float)(lengths[i] * s);
        if (len > 0.25f * pn->width) continue;
        char label[32];
        snprintf(label, sizeof label, "%g mm", lengths[i]);
        float x1 = (float)(pn->width - m), x0 = x1 - len;
        float tw = (float)sk_draw_text_width(label, scale);
        if (x0 - 2.0f * scale - tw < x) break; /* no room beside the arrows */
        float bar = fmaxf(1.5f, 0.75f * scale);
        sk_draw_line_capped(c->img, x0, yc, x1, yc, bar, SK_CAP_BUTT, grey);
        sk_draw_line_capped(c->img, x0, yc - 0.4f * th, x0, yc + 0.4f * th, bar, SK_CAP_BUTT, grey);
        sk_draw_line_capped(c->img, x1, yc - 0.4f * th, x1, yc + 0.4f * th, bar, SK_CAP_BUTT, grey);
        sk_draw_text(c->img, x0 - 2.0f * scale - tw, yc - 0.5f * th, label, scale, grey);
        break;
    }
}

/* A line of text centred in [x0, x0 + width): at `scale`, or smaller, or cut with "..."
 * to fit. */
static void draw_centred_line(sk_image *img, int x0, int width, float y, const char *text,
                              int scale, sk_color col)
{
    char buf[512];
    snprintf(buf, sizeof buf, "%s", text);
    while (scale > 1 && sk_draw_text_width(buf, scale) > width - 4 * scale) scale--;
    size_t len = strlen(buf);
    while (len > 3 && sk_draw_text_width(buf, scale) > width - 4 * scale) {
        len--;
        memcpy(buf + len - 3, "...", 4);
    }
    float x = (float)x0 + 0.5f * (float)(width - sk_draw_text_width(buf, scale));
    sk_draw_text(img, x, y, buf, scale, col);
}

/* The caption in the band under the panels: one line, else two lines split at the ", "
 * nearest the middle, at the layout's text scale or smaller, else cut to fit. */
static void draw_caption(sk_image *out, const sk_hand_draw_layout *layout, const char *text)
{
    int y0 = layout->panel[0].height, band = layout->height - y0, width = layout->width;
    if (band <= 0) return;
    for (int scale = layout->text_scale; scale >= 1; scale--) {
        int th = sk_draw_text_height(scale), room = width - 4 * scale;
        if (sk_draw_text_width(text, scale) <= room && th <= band) {
            draw_centred_line(out, 0, width, (float)y0 + 0.5f * (float)(band - th), text, scale,
                              k_ink);
            return;
        }
        int two = 2 * th + 3 * scale;
        if (two > band) continue;
        const char *split = NULL, *mid = text + strlen(text) / 2;
        for (const char *p = strstr(text, ", "); p; p = strstr(p + 1, ", "))
            if (!split || labs(p - mid) < labs(split - mid)) split = p;
        if (!split) continue;
        char first[512];
        snprintf(first, sizeof first, "%.*s,", (int)(split - text), text);
        if (sk_draw_text_width(first, scale) > room || sk_draw_text_width(split + 2, scale) > room)
            continue;
        float y = (float)y0 + 0.5f * (float)(band - two);
        draw_centred_line(out, 0, width, y, first, scale, k_ink);
        draw_centred_line(out, 0, width, y + (float)(th + 3 * scale), split + 2, scale, k_ink);
        return;
    }
    draw_centred_line(out, 0, width, (float)y0 + 0.5f * (float)(band - sk_draw_text_height(1)),
                      text, 1, k_ink);
}

static sk_result draw_panel(const sk_hand_draw_layout *layout, int v, const sk_hand_draw_desc *d,
                            const sk_hand_skeleton *skeleton, const sk_hand_frames *frames,
                            sk_image *out, sk_error *err)
{
    const sk_hand_panel *pn = &layout->panel[v];
    sk_image img;
    sk_result r = sk_image_create(&img, pn->width, pn->height, 3, err);
    if (r != SK_OK) return r;
    sk_draw_clear(&img, k_background);
    panel_ctx c = {
        layout, pn, v, skeleton, frames, &img, {0}, 0, stroke_sizes(layout->pixels_per_mm)};
    sk_hand_draw_desc dd = *d;
    dd.text_scale = layout->text_scale;
    dd.caption = NULL; /* the caption band lies outside the panels */
    sk__hand_bands(&dd, &c.bands);
    c.area_bottom = pn->height - c.bands.cues - c.bands.margin;
    if (!d->hide_cues) draw_forearm(&c);
    draw_palm(&c);
    draw_item items[2 * SK_HAND_POINT_COUNT];
    int n = build_items(&c, items);
    for (int i = 0; i < n; i++) draw_item_one(&c, &items[i]);
    if (d->label_points) draw_point_labels(&c);
    if (!d->hide_cues) draw_cues(&c);
    if (!d->hide_panel_titles)
        draw_centred_line(&img, 0, pn->width, (float)c.bands.margin, sk__hand_view_title(pn->view),
                          layout->text_scale, k_ink);
    /* both are RGB: the panel's rows go in as they are (cheaper than a converting blit) */
    for (int y = 0; y < pn->height; y++)
        memcpy(sk_image_pixel(out, pn->x0, pn->y0 + y), sk_image_pixel(&img, 0, y),
               sizeof(float) * 3 * (size_t)pn->width);
    sk_image_free(&img);
    return SK_OK;
}

sk_result sk_hand_draw(const sk_hand_skeleton *skeleton, const double dofs[SK_HAND_DOF_COUNT],
                       const sk_hand_draw_desc *desc, const sk_hand_draw_layout *layout,
                       sk_image *out, sk_error *err)
{
    sk_hand_draw_desc d = sk_hand_draw_desc_resolved(desc);
    memset(out, 0, sizeof *out);
    sk_hand_draw_layout own;
    if (!layout) {
        sk_result r = sk_hand_draw_layout_fit(skeleton, dofs, 1, &d, &own, err);
        if (r != SK_OK) return r;
        layout = &own;
    }
    for (int i = 0; i < SK_HAND_DOF_COUNT; i++)
        if (!isfinite(dofs[i]))
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "%s is not finite",
                           sk_hand_dof(i)->name);
    sk_hand_frames frames;
    sk_hand_forward(skeleton, dofs, &frames);
    sk_result r = sk_image_create(out, layout->width, layout->height, 3, err);
    if (r != SK_OK) return r;
    /* the panels cover the rest (drawn apart, so that nothing crosses into a neighbour) */
    int caption_top = layout->panel[0].height;
    sk_draw_rect(out, 0.0f, (float)caption_top, (float)out->width,
                 (float)(out->height - caption_top), k_background);
    for (int v = 0; v < layout->view_count && r == SK_OK; v++)
        r = draw_panel(layout, v, &d, skeleton, &frames, out, err);
    for (int v = 1; v < layout->view_count && r == SK_OK; v++) {
        const sk_hand_panel *pn = &layout->panel[v];
        float x = (float)pn->x0 + 0.5f;
        sk_draw_line_capped(out, x, 6.0f, x, (float)(pn->height - 6), 1.0f, SK_CAP_BUTT,
                            sk_rgb(0.8f, 0.8f, 0.8f));
    }
    if (r == SK_OK && d.caption && d.caption[0]) draw_caption(out, layout, d.caption);
    if (r != SK_OK) sk_image_free(out);
    return r;
}
