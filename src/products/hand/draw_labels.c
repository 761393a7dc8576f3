/* Labels of the skeleton pictures placed greedily where they cover the least: other
 * labels, joint discs and bones (a simple point-feature labelling: candidates on rings
 * of growing radius around each point, the cheapest taken in order). */
#include <math.h>

#include "products/hand/hand_draw_internal.h"

typedef struct rect {
    float x0, y0, x1, y1;
} rect;

static float overlap_area(rect a, rect b)
{
    float w = fminf(a.x1, b.x1) - fmaxf(a.x0, b.x0), h = fminf(a.y1, b.y1) - fmaxf(a.y0, b.y0);
    return w > 0.0f && h > 0.0f ? w * h : 0.0f;
}

/* Length of the segment p-q inside the rectangle (Liang-Barsky clipping). */
static float clipped_length(sk_vec2f p, sk_vec2f q, rect r)
{
    float t0 = 0.0f, t1 = 1.0f, dx = q.x - p.x, dy = q.y - p.y;
    float pk[4] = {-dx, dx, -dy, dy}, qk[4] = {p.x - r.x0, r.x1 - p.x, p.y - r.y0, r.y1 - p.y};
    for (int k = 0; k < 4; k++) {
        if (pk[k] == 0.0f) {
            if (qk[k] < 0.0f) return 0.0f;
            continue;
        }
        float t = qk[k] / pk[k];
        if (pk[k] < 0.0f)
            t0 = fmaxf(t0, t);
        else
            t1 = fminf(t1, t);
        if (t0 > t1) return 0.0f;
    }
    return (t1 - t0) * sqrtf(dx * dx + dy * dy);
}

static float rect_cost(rect r, const sk__hand_label_scene *s, const rect *placed, int placed_count,
                       int self)
{
    if (r.x0 < s->x0 || r.y0 < s->y0 || r.x1 > s->x1 || r.y1 > s->y1) return 1e9f;
    float cost = 0.0f;
    for (int i = 0; i < placed_count; i++) cost += 20.0f * overlap_area(r, placed[i]);
    for (int i = 0; i < s->point_count; i++) {
        float rad = s->radius[i] + 1.0f;
        rect disc = {s->points[i].x - rad, s->points[i].y - rad, s->points[i].x + rad,
                     s->points[i].y + rad};
        cost += (i == self ? 20.0f : 8.0f) * overlap_area(r, disc);
    }
    float hw = 0.5f * s->bone_width + 1.0f;
    rect grown = {r.x0 - hw, r.y0 - hw, r.x1 + hw, r.y1 + hw};
    for (int b = 0; b < s->bone_count; b++)
        cost += 4.0f * s->bone_width *
                clipped_length(s->points[s->bones[b][0]], s->points[s->bones[b][1]], grown);
    return cost;
}

/* Text with a white halo so it stays legible wherever it lands. */
static void draw_haloed(sk_image *img, float x, float y, const char *text, int scale, sk_color c)
{
    sk_color white = sk_rgb(1, 1, 1);
    for (int dy = -1; dy <= 1; dy++)
        for (int dx = -1; dx <= 1; dx++)
            if (dx || dy)
                sk_draw_text(img, x + (float)(dx * scale), y + (float)(dy * scale), text, scale,
                             white);
    sk_draw_text(img, x, y, text, scale, c);
}

void sk__hand_draw_labels(sk_image *img, const sk__hand_label_scene *s, const char *const *names,
                          const sk_color *colors, const float *prefer_x, int scale)
{
    enum { MAX_POINTS = 64, DIRECTIONS = 16, RINGS = 5 };
    rect placed[MAX_POINTS];
    int count = 0;
    float th = (float)sk_draw_text_height(scale), pad = (float)scale;
    for (int i = 0; i < s->point_count && i < MAX_POINTS; i++) {
        if (!names[i]) continue;
        float w = (float)sk_draw_text_width(names[i], scale) + 2.0f * pad, h = th + 2.0f * pad;
        sk_vec2f p = s->points[i];
        float gap = s->radius[i] + pad;
        rect best = {0};
        float best_cost = INFINITY, best_dist = 0.0f;
        for (int ring = 0; ring < RINGS; ring++) {
            float d = gap + (float)ring * 0.9f * th;
            for (int k = 0; k < DIRECTIONS; k++) {
                /* alternate around the preferred side: 0, +1, -1, +2, -2 ... steps */
                int step = (k + 1) / 2 * (k % 2 ? 1 : -1);
                double a = (prefer_x[i] < 0 ? SK_PI : 0.0) + step * (2.0 * SK_PI / DIRECTIONS);
                float cx = (float)cos(a), cy = (float)sin(a);
                /* push the box out until its nearest edge is d away along the direction */
                float t = d + fabsf(cx) * 0.5f * w + fabsf(cy) * 0.5f * h;
                float mx = p.x + cx * t, my = p.y + cy * t;
                rect r = {mx - 0.5f * w, my - 0.5f * h, mx + 0.5f * w, my + 0.5f * h};
                /* nearer and more preferred places win ties */
                float cost =
                    rect_cost(r, s, placed, count, i) + 0.5f * (float)k + 6.0f * (float)ring;
                if (cost < best_cost) {
                    best_cost = cost;
                    best = r;
                    best_dist = d;
                }
            }
        }
        if (best_cost >= 1e9f) continue; /* nowhere inside the panel */
        placed[count++] = best;
        if (best_dist > gap + 0.5f * th) {
            /* leader from the disc's rim to the nearest point of the box */
            float qx = sk_clampf(p.x, best.x0, best.x1), qy = sk_clampf(p.y, best.y0, best.y1);
            float dx = qx - p.x, dy = qy - p.y, len = sqrtf(dx * dx + dy * dy);
            if (len > s->radius[i] + 2.0f) {
                float sx = p.x + dx / len * s->radius[i], sy = p.y + dy / len * s->radius[i];
                sk_draw_line(img, sx, sy, qx, qy, fmaxf(1.0f, 0.5f * scale),
                             sk_rgba(0.35f, 0.35f, 0.35f, 0.8f));
            }
        }
        draw_haloed(img, best.x0 + pad, best.y0 + pad, names[i], scale, colors[i]);
    }
}
