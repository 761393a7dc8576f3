/* The keyboard of an 88-key piano: white keys at a fixed pitch (notched around the black
 * keys behind the black keys' fronts), black keys over the boundaries of their white
 * neighbours, standard sizes (a white key's visible top 150 mm long, a black key 92 mm
 * and 12 mm higher); every key turns about one axis across the keyboard behind the key
 * slip, so its front dips by at most the key dip. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "products/showcase/showcase_internal.h"

#define REFERENCE_PITCH_MM 23.5
#define WHITE_GAP_MM 1.2      /* between white keys (22.3 mm wide at 23.5 mm pitch) */
#define WHITE_LENGTH_MM 150.0 /* visible top, front to fallboard */
#define WHITE_THICKNESS_MM 22.0
#define BLACK_WIDTH_MM 13.0
#define BLACK_LENGTH_MM 92.0
#define BLACK_RISE_MM 12.0 /* black top above the white tops */
#define NOTCH_GAP_MM 0.8   /* white key's back part to a black key's side */
#define WHITE_KEY_COUNT 52

static int white_index(int key) /* white keys from A0 up to and including key */
{
    int n = 0;
    for (int k = SK_PIANO_KEY_FIRST; k <= key; k++) n += !sk_note_is_black(k);
    return n - 1;
}

sk_result sk_piano_init(sk_piano *piano, const sk_piano_desc *desc, sk_error *err)
{
    sk_piano_desc d = desc ? *desc : (sk_piano_desc){0};
    sk_schema_apply_defaults(&sk__piano_schema, &d);
    sk_result r = sk_schema_check(&sk__piano_schema, &d, "piano", err);
    if (r != SK_OK) return r;
    memset(piano, 0, sizeof *piano);
    piano->desc = d;
    piano->pivot_z_mm = d.front_mm - d.pivot_mm;
    piano->max_angle = asin(d.dip_mm / d.pivot_mm);
    double scale = d.white_pitch_mm / REFERENCE_PITCH_MM;
    double black_w = BLACK_WIDTH_MM * scale, white_w = d.white_pitch_mm - WHITE_GAP_MM * scale;
    double black_front = d.front_mm - (WHITE_LENGTH_MM - BLACK_LENGTH_MM);
    for (int key = SK_PIANO_KEY_FIRST; key <= SK_PIANO_KEY_LAST; key++) {
        sk_piano_key *k = &piano->keys[key - SK_PIANO_KEY_FIRST];
        k->key = key;
        k->black = sk_note_is_black(key);
        k->front_mm = k->black ? black_front : d.front_mm;
        k->back_mm = d.front_mm - WHITE_LENGTH_MM;
        if (k->black) {
            int below = white_index(key - 1);
            k->x_mm = (below + 0.5 - 0.5 * (WHITE_KEY_COUNT - 1)) * d.white_pitch_mm;
            k->width_mm = black_w;
            k->top_mm = d.white_top_mm + BLACK_RISE_MM;
            k->thickness_mm = BLACK_RISE_MM + 10;
            k->notch_front_mm = k->back_mm;
            k->back_x0_mm = k->x_mm - 0.5 * black_w;
            k->back_x1_mm = k->x_mm + 0.5 * black_w;
        } else {
            int w = white_index(key);
            k->x_mm = (w - 0.5 * (WHITE_KEY_COUNT - 1)) * d.white_pitch_mm;
            k->width_mm = white_w;
            k->top_mm = d.white_top_mm;
            k->thickness_mm = WHITE_THICKNESS_MM;
            k->notch_front_mm = black_front;
            bool black_below = key > SK_PIANO_KEY_FIRST && sk_note_is_black(key - 1);
            bool black_above = key < SK_PIANO_KEY_LAST && sk_note_is_black(key + 1);
            double edge = 0.5 * d.white_pitch_mm, notch = 0.5 * black_w + NOTCH_GAP_MM * scale;
            k->back_x0_mm = k->x_mm - (black_below ? edge - notch : 0.5 * white_w);
            k->back_x1_mm = k->x_mm + (black_above ? edge - notch : 0.5 * white_w);
        }
    }
    return SK_OK;
}

double sk_piano_key_top_at(const sk_piano *piano, const sk_piano_key *key, double angle, double z)
{
    double h = key->top_mm - piano->desc.white_top_mm; /* the top's height above the pivot */
    return piano->desc.white_top_mm + h / cos(angle) - (z - piano->pivot_z_mm) * tan(angle);
}

int sk_piano_key_under(const sk_piano *piano, double x, double z)
{
    int white = 0;
    for (int i = 0; i < SK_PIANO_KEY_COUNT; i++) {
        const sk_piano_key *k = &piano->keys[i];
        if (z > k->front_mm || z < k->back_mm) continue;
        if (k->black) {
            if (fabs(x - k->x_mm) <= 0.5 * k->width_mm) return k->key;
        } else if (z >= k->notch_front_mm ? fabs(x - k->x_mm) <= 0.5 * k->width_mm
                                          : x >= k->back_x0_mm && x <= k->back_x1_mm) {
            white = k->key;
        }
    }
    return white;
}

/* The key's boxes at rest: centre (x, y, z) and half sizes. */
static int key_boxes(const sk_piano_key *k, sk_vec3d centre[2], sk_vec3d half[2])
{
    double y = k->top_mm - 0.5 * k->thickness_mm;
    if (k->black) {
        centre[0] = (sk_vec3d){k->x_mm, y, 0.5 * (k->front_mm + k->back_mm)};
        half[0] =
            (sk_vec3d){0.5 * k->width_mm, 0.5 * k->thickness_mm, 0.5 * (k->front_mm - k->back_mm)};
        return 1;
    }
    centre[0] = (sk_vec3d){k->x_mm, y, 0.5 * (k->front_mm + k->notch_front_mm)};
    half[0] = (sk_vec3d){0.5 * k->width_mm, 0.5 * k->thickness_mm,
                         0.5 * (k->front_mm - k->notch_front_mm)};
    centre[1] = (sk_vec3d){0.5 * (k->back_x0_mm + k->back_x1_mm), y,
                           0.5 * (k->notch_front_mm + k->back_mm)};
    half[1] = (sk_vec3d){0.5 * (k->back_x1_mm - k->back_x0_mm), 0.5 * k->thickness_mm,
                         0.5 * (k->notch_front_mm - k->back_mm)};
    return 2;
}

/* A point turned about the keys' pivot axis (x direction) by `angle` (front down). */
static sk_vec3d turn(const sk_piano *piano, sk_vec3d p, double angle)
{
    double yp = piano->desc.white_top_mm, zp = piano->pivot_z_mm;
    double c = cos(angle), s = sin(angle), y = p.y - yp, z = p.z - zp;
    return (sk_vec3d){p.x, yp + y * c - z * s, zp + y * s + z * c};
}

double sk_piano_key_distance(const sk_piano *piano, const sk_piano_key *key, double angle,
                             sk_vec3d p)
{
    sk_vec3d q = turn(piano, p, -angle); /* into the key's rest frame */
    sk_vec3d centre[2], half[2];
    int n = key_boxes(key, centre, half);
    double best = INFINITY;
    for (int b = 0; b < n; b++) {
        double dx = fabs(q.x - centre[b].x) - half[b].x, dy = fabs(q.y - centre[b].y) - half[b].y,
               dz = fabs(q.z - centre[b].z) - half[b].z;
        double ox = fmax(dx, 0), oy = fmax(dy, 0), oz = fmax(dz, 0);
        double d = sqrt(ox * ox + oy * oy + oz * oz) + fmin(fmax(dx, fmax(dy, dz)), 0);
        if (d < best) best = d;
    }
    return best;
}

int sk_piano_key_objects(const sk_piano *piano, const sk_piano_key *key, double angle,
                         const char *material, sk_render_object_desc out[2])
{
    sk_vec3d centre[2], half[2];
    int n = key_boxes(key, centre, half);
    char name[8];
    sk_note_name(key->key, name, sizeof name);
    for (int b = 0; b < n; b++) {
        sk_render_object_desc *o = &out[b];
        memset(o, 0, sizeof *o);
        snprintf(o->name, sizeof o->name, "key-%s%s", name, b ? "-back" : "");
        o->shape = SK_RENDER_SHAPE_BOX;
        o->size[0] = (float)(2 * half[b].x), o->size[1] = (float)(2 * half[b].y),
        o->size[2] = (float)(2 * half[b].z);
        snprintf(o->material, sizeof o->material, "%s", material);
        sk_vec3d c = turn(piano, centre[b], angle);
        o->transform.translate[0] = (float)c.x, o->transform.translate[1] = (float)c.y;
        o->transform.translate[2] = (float)c.z;
        o->transform.rotate[0] = (float)angle;
    }
    return n;
}
