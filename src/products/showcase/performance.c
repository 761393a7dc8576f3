/* The performance: notes -> what each finger is asked to do and where the wrist is, at
 * any time t, computed from t alone. A note (start s, end e) gives its finger a motion
 * in phases (descent D, approach A, lift L):
 *   [s - A, s - D/2)       approach: the pad goes from hover height to the key top,
 *   [s - D/2, s + D/2)     descent: the key turns from 0 to full dip, half way at s,
 *   [s + D/2, e - D/2)     hold at the bottom,
 *   [e - D/2, e + D/2)     release: the key comes back up with the finger, half way at e,
 *   [e + D/2, e + D/2 + L) lift back to hover height,
 * so a key is half down exactly at its note's start and half up at its end (the sound's
 * onset and damping). The thesis's input is the press itself (two DOFs of the finger,
 * Fig. 4.21); the contact (contact.c) turns these targets into torques.
 * The wrist goes where its fingers need it: each note asks for the wrist position that
 * puts its finger over its key; the wrist takes a weighted mean of those positions, a
 * note's weight rising during the second half of its approach, 1 while its key is down
 * and falling as a Gaussian (width travel_s) once it comes up, so the hand stays put
 * while a key is held, travels between the presses, and is in place when a finger lands. It gives
 * way a little at every strike (strike_drop_mm). */
#include <math.h>
#include <string.h>

#include "products/showcase/showcase_internal.h"

#define RECOVER_S 0.08 /* the wrist's recovery after a strike */
#define NEAREST_WEIGHT 1e-3
#define CONTACT_MARGIN_MM 3.0 /* pads keep this far inside a key's part they press */
#define KEY_EDGE_CLEARANCE_MM                                                                      \
    5.0                         /* a white key's pad this far in front of the black keys           \
                                   beyond its radius (their edges' ramp, contact.c) */
#define HAND_DROP_MARGIN_MM 3.0 /* a press keeps this much of its arc in reserve */

sk_performance_desc sk__performance_desc_resolved(const sk_performance_desc *desc)
{
    sk_performance_desc d = desc ? *desc : (sk_performance_desc){0};
    sk_schema_apply_defaults(&sk__performance_schema, &d);
    if (d.strike_drop_mm < 0) d.strike_drop_mm = 0;
    return d; /* tip_radius_mm all 0: measured on the hand surface (hand_mesh.c) */
}

sk_result sk__performance_desc_validate(const sk_performance_desc *d, sk_error *err)
{
    sk_result r = sk_schema_check(&sk__performance_schema, d, "performance", err);
    if (r != SK_OK) return r;
    if (d->approach_s <= 0.5 * d->descent_s)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "performance.approach_s = %g must exceed half of performance.descent_s = %g",
                       d->approach_s, d->descent_s);
    bool any = false;
    for (int f = 0; f < 5; f++) any = any || d->tip_radius_mm[f] != 0;
    for (int f = 0; f < 5 && any; f++)
        if ((r = sk_check_range_f(err, "performance.tip_radius_mm", d->tip_radius_mm[f], 2, 20)) !=
            SK_OK)
            return r;
    return SK_OK;
}

static double ease(double u)
{
    u = u < 0 ? 0 : (u > 1 ? 1 : u);
    return u * u * (3 - 2 * u);
}

/* The key's descent time for a note (shorter for notes shorter than the descent). */
static double descent_of(const sk_performance_desc *d, const sk_note *n)
{
    return n->duration_s < d->descent_s ? n->duration_s : d->descent_s;
}

void sk__performance_note_depths(const sk__performance *perf, int i, double *lo, double *hi)
{
    const sk_note *n = &perf->melody->notes[i];
    const sk_piano_key *k = sk_piano_key_get(perf->piano, n->key);
    int f = n->finger - 1;
    sk__performance_contact_range(perf->rig, k, f, lo, hi);
    *lo -= perf->rig->press_offset[f].z;
    *hi -= perf->rig->press_offset[f].z;
}

sk_vec3d sk__performance_note_wrist(const sk__performance *perf, int i)
{
    const sk_note *n = &perf->melody->notes[i];
    const sk_piano_key *k = sk_piano_key_get(perf->piano, n->key);
    int f = n->finger - 1;
    sk_vec3d off = perf->rig->press_offset[f]; /* the pad as it strikes */
    /* the finger strikes where the hand at its home depth puts it, kept within the part
       of the key a pad can press without touching its neighbours: the hand moves in and
       out only as far as a key needs */
    double lo, hi;
    sk__performance_contact_range(perf->rig, k, f, &lo, &hi);
    double contact_z = perf->rig->home_z + off.z;
    contact_z = contact_z < lo ? lo : (contact_z > hi ? hi : contact_z);
    /* over a black key the hand rises by half the black keys' rise: its other fingers
       then hover over the black keys about as high as over the white ones */
    double rise = k->black ? 0.5 * (k->top_mm - perf->piano->desc.white_top_mm) : 0;
    /* a short finger whose press cannot reach the key's bottom from the hover height
       takes the hand down with it (the arm's weight in the key) */
    double dip = perf->piano->desc.dip_mm * (contact_z - perf->piano->pivot_z_mm) /
                 (perf->piano->desc.front_mm - perf->piano->pivot_z_mm);
    double need = perf->desc.hover_mm + rise + dip + HAND_DROP_MARGIN_MM - perf->rig->max_depth[f];
    double drop = need > 0 ? need : 0;
    return (sk_vec3d){k->x_mm - off.x, perf->hover_y + rise - drop, contact_z - off.z};
}

void sk__performance_contact_range(const sk__hand_rig *rig, const sk_piano_key *k, int finger,
                                   double *lo, double *hi)
{
    double radius = rig->tip_radius[finger];
    if (k->black) {
        *lo = k->back_mm + radius + CONTACT_MARGIN_MM;
        *hi = k->front_mm - CONTACT_MARGIN_MM;
    } else {
        /* a press draws the pad back toward the player: at hover height, before it, the
           pad must already be clear of the black keys */
        double retract = rig->press_offset[finger].z - rig->pad_offset[finger].z;
        *lo = k->notch_front_mm + radius + KEY_EDGE_CLEARANCE_MM + (retract > 0 ? retract : 0);
        *hi = k->front_mm - CONTACT_MARGIN_MM;
    }
    if (*lo > *hi) *lo = *hi;
}

/* Time from t to the window [a, b] (0 inside). */
static double outside(double t, double a, double b) { return t < a ? a - t : (t > b ? t - b : 0); }

void sk__performance_at(const sk__performance *perf, double t, sk__intent *out)
{
    const sk_performance_desc *d = &perf->desc;
    const sk_melody *m = perf->melody;
    memset(out, 0, sizeof *out);
    for (int f = 0; f < 5; f++) out->finger[f].note = -1;
    /* wrist: weighted mean of the notes' wrist positions. A note's weight rises from 0
       half way through its approach to 1 when its key starts down, stays 1 until the key
       starts back up, then falls as a Gaussian of width travel_s; a small weight that is
       a Gaussian of the time to the nearest note (relative to it, so it never vanishes)
       keeps the wrist defined between notes. */
    double nearest = INFINITY;
    for (int i = 0; i < m->note_count; i++) {
        const sk_note *n = &m->notes[i];
        double D = descent_of(d, n);
        double dist =
            outside(t, n->start_s - 0.5 * d->approach_s, n->start_s + n->duration_s - 0.5 * D);
        if (dist < nearest) nearest = dist;
    }
    sk_vec3d wrist = {0, perf->hover_y, perf->piano->desc.front_mm};
    double total = 0;
    double drop = 0;
    sk_vec3d sum = {0, 0, 0};
    double tau2 = d->travel_s * d->travel_s;
    for (int i = 0; i < m->note_count; i++) {
        const sk_note *n = &m->notes[i];
        double D = descent_of(d, n), s0 = n->start_s, e0 = n->start_s + n->duration_s;
        double a = s0 - 0.5 * d->approach_s, b = e0 - 0.5 * D;
        double dist = outside(t, a, b);
        double w = NEAREST_WEIGHT * exp(-fmin((dist * dist - nearest * nearest) / tau2, 700));
        if (t >= a && t < s0 - 0.5 * D)
            w += ease((t - a) / (s0 - 0.5 * D - a));
        else if (t >= s0 - 0.5 * D && t <= b)
            w += 1;
        else if (t > b)
            w += exp(-fmin((t - b) * (t - b) / tau2, 700));
        if (w > 1e-12) {
            sk_vec3d p = sk__performance_note_wrist(perf, i);
            sum.x += w * p.x, sum.y += w * p.y, sum.z += w * p.z;
            total += w;
        }
        /* the strike: the wrist gives way while the key goes down, then recovers */
        double tau = t - s0;
        if (tau > -0.5 * D && tau < 0.5 * D + 10 * RECOVER_S)
            drop += ease((tau + 0.5 * D) / D) * exp(-fmax(tau - 0.5 * D, 0) / RECOVER_S) *
                    n->velocity / 127.0;
    }
    if (total > 0) wrist = (sk_vec3d){sum.x / total, sum.y / total, sum.z / total};
    /* held together, notes need a depth that suits all their fingers: the mean, kept
       within the depths every held note's finger can strike from (if they overlap) */
    double zlo = -INFINITY, zhi = INFINITY;
    for (int i = 0; i < m->note_count; i++) {
        const sk_note *n = &m->notes[i];
        double D = descent_of(d, n);
        if (t < n->start_s - 0.5 * D || t > n->start_s + n->duration_s + 0.5 * D) continue;
        double lo, hi;
        sk__performance_note_depths(perf, i, &lo, &hi);
        zlo = fmax(zlo, lo), zhi = fmin(zhi, hi);
    }
    if (zlo <= zhi) wrist.z = wrist.z < zlo ? zlo : (wrist.z > zhi ? zhi : wrist.z);
    wrist.y -= d->strike_drop_mm * fmin(drop, 2.0);
    out->wrist = wrist;
    /* fingers: the note whose motion window holds t; of two (a lift and the next
       approach of one finger), the one further along toward its key */
    double depth[5];
    for (int f = 0; f < 5; f++) depth[f] = -1;
    for (int i = 0; i < m->note_count; i++) {
        const sk_note *n = &m->notes[i];
        int f = n->finger - 1;
        if (f < 0 || f > 4) continue;
        double s = n->start_s, e = n->start_s + n->duration_s, D = descent_of(d, n);
        if (t < s - d->approach_s || t >= e + 0.5 * D + d->lift_s) continue;
        sk__finger_intent fi = {SK__FINGER_FREE, i, n->key, 0, 0};
        double how_deep; /* 0 hover .. 1 key top .. 2 key bottom, to pick between notes */
        if (t < s - 0.5 * D) {
            fi.phase = SK__FINGER_APPROACH;
            fi.blend = ease((t - (s - d->approach_s)) / (d->approach_s - 0.5 * D));
            how_deep = fi.blend;
        } else if (t < e - 0.5 * D) {
            fi.phase = SK__FINGER_PRESS;
            fi.angle = perf->piano->max_angle * ease((t - (s - 0.5 * D)) / D);
            how_deep = 1 + fi.angle / perf->piano->max_angle;
        } else if (t < e + 0.5 * D) {
            fi.phase = SK__FINGER_PRESS;
            fi.angle = perf->piano->max_angle * (1 - ease((t - (e - 0.5 * D)) / D));
            how_deep = 1 + fi.angle / perf->piano->max_angle;
        } else {
            fi.phase = SK__FINGER_LIFT;
            fi.blend = 1 - ease((t - (e + 0.5 * D)) / d->lift_s);
            how_deep = fi.blend;
        }
        if (how_deep > depth[f]) {
            depth[f] = how_deep;
            out->finger[f] = fi;
        }
    }
}
