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
 * puts its finger over its key; the wrist takes a weighted mean of those positions, the
 * weight 1 while the note's finger is busy and a Gaussian of the time to it outside
 * (width travel_s), so it travels smoothly between hand positions and stays put while
 * notes are held. It gives way a little at every strike (strike_drop_mm). */
#include <math.h>
#include <string.h>

#include "showcase/showcase_internal.h"

#define RECOVER_S 0.08 /* the wrist's recovery after a strike */
#define WHITE_CONTACT 0.5 /* white keys are struck half way along their front part */
#define BLACK_CONTACT_MM 28.0 /* black keys this far behind their fronts */

sk_performance_desc sk__performance_desc_resolved(const sk_performance_desc *desc)
{
    sk_performance_desc d = desc ? *desc : (sk_performance_desc){0};
    if (d.approach_s == 0) d.approach_s = 0.12;
    if (d.descent_s == 0) d.descent_s = 0.04;
    if (d.lift_s == 0) d.lift_s = 0.12;
    if (d.hover_mm == 0) d.hover_mm = 8;
    if (d.clearance_mm == 0) d.clearance_mm = 1;
    if (d.press_pip_ratio == 0) d.press_pip_ratio = 0.5 / 0.9;
    if (d.travel_s == 0) d.travel_s = 0.15;
    if (d.strike_drop_mm == 0) d.strike_drop_mm = 1.5;
    if (d.strike_drop_mm < 0) d.strike_drop_mm = 0;
    static const double radius[5] = {8.5, 7, 7.25, 6.75, 6.25};
    bool any = false;
    for (int f = 0; f < 5; f++) any = any || d.tip_radius_mm[f] != 0;
    if (!any) memcpy(d.tip_radius_mm, radius, sizeof radius);
    return d;
}

sk_result sk__performance_desc_validate(const sk_performance_desc *d, sk_error *err)
{
    sk_result r;
    if ((r = sk_check_range_f(err, "performance.approach_s", d->approach_s, 0.02, 1)) != SK_OK ||
        (r = sk_check_range_f(err, "performance.descent_s", d->descent_s, 0.005, 0.2)) != SK_OK ||
        (r = sk_check_range_f(err, "performance.lift_s", d->lift_s, 0.02, 1)) != SK_OK ||
        (r = sk_check_range_f(err, "performance.hover_mm", d->hover_mm, 2, 40)) != SK_OK ||
        (r = sk_check_range_f(err, "performance.clearance_mm", d->clearance_mm, 0, 10)) != SK_OK ||
        (r = sk_check_range_f(err, "performance.press_pip_ratio", d->press_pip_ratio, 0, 4)) != SK_OK ||
        (r = sk_check_range_f(err, "performance.travel_s", d->travel_s, 0.01, 2)) != SK_OK ||
        (r = sk_check_range_f(err, "performance.strike_drop_mm", d->strike_drop_mm, 0, 10)) != SK_OK)
        return r;
    if (d->approach_s <= 0.5 * d->descent_s)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "performance.approach_s = %g must exceed half of performance.descent_s = %g", d->approach_s,
                       d->descent_s);
    for (int f = 0; f < 5; f++)
        if ((r = sk_check_range_f(err, "performance.tip_radius_mm", d->tip_radius_mm[f], 2, 20)) != SK_OK) return r;
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

sk_vec3d sk__performance_note_wrist(const sk__performance *perf, int i)
{
    const sk_note *n = &perf->melody->notes[i];
    const sk_piano_key *k = sk_piano_key_get(perf->piano, n->key);
    int f = n->finger - 1;
    double contact_z = k->black ? k->front_mm - BLACK_CONTACT_MM
                                : k->notch_front_mm + WHITE_CONTACT * (k->front_mm - k->notch_front_mm);
    sk_vec3d off = perf->rig->press_offset[f]; /* the pad as it strikes */
    /* over a black key the hand rises by half the black keys' rise: its other fingers
       then hover over the black keys about as high as over the white ones */
    double rise = k->black ? 0.5 * (k->top_mm - perf->piano->desc.white_top_mm) : 0;
    return (sk_vec3d){k->x_mm - off.x, perf->hover_y + rise, contact_z - off.z};
}

/* Time from t to the window [a, b] (0 inside). */
static double outside(double t, double a, double b) { return t < a ? a - t : (t > b ? t - b : 0); }

void sk__performance_at(const sk__performance *perf, double t, sk__intent *out)
{
    const sk_performance_desc *d = &perf->desc;
    const sk_melody *m = perf->melody;
    memset(out, 0, sizeof *out);
    for (int f = 0; f < 5; f++) out->finger[f].note = -1;
    /* wrist: weighted mean of the notes' wrist positions (weights relative to the nearest
       window, so they never all underflow) */
    double nearest = INFINITY;
    for (int i = 0; i < m->note_count; i++) {
        const sk_note *n = &m->notes[i];
        double dist = outside(t, n->start_s - d->approach_s, n->start_s + n->duration_s);
        if (dist < nearest) nearest = dist;
    }
    sk_vec3d wrist = {0, perf->hover_y, perf->piano->desc.front_mm};
    double total = 0;
    double drop = 0;
    sk_vec3d sum = {0, 0, 0};
    for (int i = 0; i < m->note_count; i++) {
        const sk_note *n = &m->notes[i];
        double dist = outside(t, n->start_s - d->approach_s, n->start_s + n->duration_s);
        double e = (dist * dist - nearest * nearest) / (d->travel_s * d->travel_s);
        if (e < 40) {
            double w = exp(-e);
            sk_vec3d p = sk__performance_note_wrist(perf, i);
            sum.x += w * p.x, sum.y += w * p.y, sum.z += w * p.z;
            total += w;
        }
        /* the strike: the wrist gives way while the key goes down, then recovers */
        double D = descent_of(d, n), tau = t - n->start_s;
        if (tau > -0.5 * D && tau < 0.5 * D + 10 * RECOVER_S)
            drop += ease((tau + 0.5 * D) / D) * exp(-fmax(tau - 0.5 * D, 0) / RECOVER_S) * n->velocity / 127.0;
    }
    if (total > 0) wrist = (sk_vec3d){sum.x / total, sum.y / total, sum.z / total};
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
