/* Automatic fingering of a right hand by dynamic programming (docs/showcase.md states the
 * rule). Notes are taken in time order; the state after note i is the finger of every
 * note still sounding when i starts, plus i's own, so notes held together always get
 * distinct fingers in the order of their keys within the hand's reach. The cost of a
 * step from note p to note i (fingers a, b; keys x_p, x_i; the fingers' places in the
 * five-finger position X_a, X_b), in white keys' widths P:
 *   s = |(x_i - x_p) - (X_b - X_a)|           how far the hand must shift (or stretch),
 *   p held when i starts:  s / P              (a stretch; s <= reach is required)
 *   otherwise:             s / P * (1 + 0.1 s / max(gap, 0.05 s))   (a quick shift costs
 *                          more), plus 2 when one finger moves to another key, plus 0.3
 *                          when a repeated key changes finger;
 * and per note: thumb on a black key 1.5, little finger on a black key 0.5, ring finger
 * 0.2. Notes held together never use two fingers the hand cannot hold down together
 * (`apart`). Two notes whose fingers are busy at once (from one's approach to the other's
 * lift) keep the keys' order (no finger passes another), share a finger only on the same
 * key or with at least `move_gap_s` between them, and on neighbouring fingers (index to little)
 * take keys at least `spacing_mm` apart (a half step would put one fingertip into the other).
 * Fingers given in the input are kept (states that contradict them are left out). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "showcase/showcase_internal.h"

#define MAX_HELD 5
#define MAX_STATES 256

typedef struct fstate {
    int8_t finger[MAX_HELD + 1]; /* fingers (0..4) of the notes of the step's set, in order */
    double cost;
    int back; /* state index at the previous step */
} fstate;

typedef struct step {
    int held_count;
    int held[MAX_HELD]; /* notes j < i still sounding at i's start, ascending */
    int state_count;
    fstate *states;
} step;

static double note_cost(bool black, int f)
{
    double c = 0;
    if (black && f == 0) c += 1.5;
    if (black && f == 4) c += 0.5;
    if (f == 3) c += 0.2;
    return c;
}

/* Two fingers of index to little (1..4 here) on keys closer than the fingertips from one
 * to the other need (the thumb plays in front of the others). */
static bool cramped(int a, int b, double dx, const sk_fingering_desc *d)
{
    return a != b && a > 0 && b > 0 && fabs(dx) < abs(a - b) * d->spacing_mm;
}

sk_result sk_melody_choose_fingers(sk_melody *melody, const sk_piano *piano,
                                   const sk_fingering_desc *desc, double *cost, sk_error *err)
{
    sk_fingering_desc d = desc ? *desc : (sk_fingering_desc){0};
    sk_piano default_piano;
    if (!piano) {
        sk_piano_init(&default_piano, NULL, NULL);
        piano = &default_piano;
    }
    if (d.pitch_mm == 0) d.pitch_mm = piano->desc.white_pitch_mm;
    if (d.reach_mm == 0) d.reach_mm = 30;
    if (d.spacing_mm == 0) d.spacing_mm = 17;
    if (d.busy_before_s == 0) d.busy_before_s = 0.12;
    if (d.busy_after_s == 0) d.busy_after_s = 0.14;
    if (d.move_gap_s == 0) d.move_gap_s = 0.05;
    bool any = false;
    for (int f = 0; f < 5; f++) any = any || d.finger_x_mm[f] != 0;
    if (!any)
        for (int f = 0; f < 5; f++) d.finger_x_mm[f] = f * d.pitch_mm;
    sk_result r;
    if ((r = sk_check_range_f(err, "fingering.reach_mm", d.reach_mm, 0, 200)) != SK_OK ||
        (r = sk_check_range_f(err, "fingering.pitch_mm", d.pitch_mm, 1, 100)) != SK_OK ||
        (r = sk_check_range_f(err, "fingering.spacing_mm", d.spacing_mm, 0, 50)) != SK_OK ||
        (r = sk_check_range_f(err, "fingering.busy_before_s", d.busy_before_s, 0, 2)) != SK_OK ||
        (r = sk_check_range_f(err, "fingering.busy_after_s", d.busy_after_s, 0, 2)) != SK_OK)
        return r;
    for (int f = 0; f < 5; f++)
        if ((r = sk_check_range_f(err, "fingering.finger_x_mm", d.finger_x_mm[f], -500, 500)) !=
            SK_OK)
            return r;
    int n = melody->note_count;
    if (cost) *cost = 0;
    if (n == 0) return SK_OK;
    step *steps = calloc((size_t)n, sizeof *steps);
    fstate *pool = calloc((size_t)n * MAX_STATES, sizeof *pool);
    if (!steps || !pool) {
        free(steps), free(pool);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for the fingering of %d notes",
                       n);
    }
    const sk_note *notes = melody->notes;
    char where[192];
    r = SK_OK;
    for (int i = 0; i < n && r == SK_OK; i++) {
        step *st = &steps[i];
        st->states = pool + (size_t)i * MAX_STATES;
        const sk_note *ni = &notes[i];
        /* the notes still sounding at i's start: a subset of the previous step's set */
        if (i > 0) {
            const step *pv = &steps[i - 1];
            int candidates[MAX_HELD + 1], cn = 0;
            for (int k = 0; k < pv->held_count; k++) candidates[cn++] = pv->held[k];
            candidates[cn++] = i - 1;
            for (int k = 0; k < cn; k++) {
                const sk_note *nj = &notes[candidates[k]];
                if (nj->start_s + nj->duration_s > ni->start_s + 1e-9) {
                    if (st->held_count == MAX_HELD - 1) {
                        sk__melody_where(melody, ni->source, where, sizeof where);
                        r = sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                                    "%smore than 5 notes sound at %g s; one hand has five fingers",
                                    where, ni->start_s);
                        break;
                    }
                    st->held[st->held_count++] = candidates[k];
                }
            }
            if (r != SK_OK) break;
        }
        double xi = sk_piano_key_get(piano, ni->key)->x_mm;
        bool black = sk_note_is_black(ni->key);
        const step *pv = i > 0 ? &steps[i - 1] : NULL;
        int prev_states = pv ? pv->state_count : 1;
        for (int ps = 0; ps < prev_states; ps++) {
            const fstate *from = pv ? &pv->states[ps] : NULL;
            /* fingers of the held notes, from the previous step's assignment */
            int held_f[MAX_HELD];
            for (int k = 0; k < st->held_count; k++) {
                int j = st->held[k], f = -1;
                if (j == i - 1) {
                    f = from->finger[pv->held_count];
                } else {
                    for (int q = 0; q < pv->held_count; q++)
                        if (pv->held[q] == j) f = from->finger[q];
                }
                held_f[k] = f;
            }
            for (int b = 0; b < 5; b++) {
                if (ni->finger != 0 && ni->finger != b + 1) continue;
                bool ok = true;
                double c = from ? from->cost : 0;
                for (int k = 0; k < st->held_count && ok; k++) {
                    const sk_note *nj = &notes[st->held[k]];
                    double dx = xi - sk_piano_key_get(piano, nj->key)->x_mm;
                    int a = held_f[k];
                    if (a == b || (b - a) * dx <= 0 || d.apart[a][b] || d.apart[b][a] ||
                        fabs(dx - (d.finger_x_mm[b] - d.finger_x_mm[a])) > d.reach_mm ||
                        cramped(a, b, dx, &d))
                        ok = false;
                }
                if (!ok) continue;
                if (from) { /* the step from the previous note */
                    const sk_note *np = &notes[i - 1];
                    int a = from->finger[pv->held_count];
                    double dx = xi - sk_piano_key_get(piano, np->key)->x_mm;
                    double s = fabs(dx - (d.finger_x_mm[b] - d.finger_x_mm[a]));
                    bool held = np->start_s + np->duration_s > ni->start_s + 1e-9;
                    double gap = ni->start_s - np->start_s;
                    bool busy = np->start_s + np->duration_s + d.busy_after_s >
                                ni->start_s - d.busy_before_s;
                    if (busy && (cramped(a, b, dx, &d) || (a != b && (b - a) * dx <= 0) ||
                                 (a == b && np->key != ni->key &&
                                  ni->start_s - (np->start_s + np->duration_s) < d.move_gap_s)))
                        continue;
                    if (held)
                        c += s / d.pitch_mm;
                    else
                        c += s / d.pitch_mm * (1 + 0.1 * (s / d.pitch_mm) / fmax(gap, 0.05)) +
                             (a == b && np->key != ni->key ? 2.0 : 0.0) +
                             (a != b && np->key == ni->key ? 0.3 : 0.0);
                }
                c += note_cost(black, b);
                /* merge with an equal state */
                fstate cand = {{0}, c, ps};
                for (int k = 0; k < st->held_count; k++) cand.finger[k] = (int8_t)held_f[k];
                cand.finger[st->held_count] = (int8_t)b;
                int same = -1;
                for (int q = 0; q < st->state_count && same < 0; q++)
                    if (memcmp(st->states[q].finger, cand.finger, (size_t)st->held_count + 1) == 0)
                        same = q;
                if (same >= 0) {
                    if (c < st->states[same].cost) st->states[same] = cand;
                } else if (st->state_count < MAX_STATES) {
                    st->states[st->state_count++] = cand;
                }
            }
        }
        if (st->state_count == 0) {
            char name[8];
            sk_note_name(ni->key, name, sizeof name);
            sk__melody_where(melody, ni->source, where, sizeof where);
            r = sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                        "%sno finger can play %s at %g s with the %d note%s still sounding: the "
                        "keys held together "
                        "are wider than the hand reaches or the given fingers are out of order",
                        where, name, ni->start_s, st->held_count, st->held_count == 1 ? "" : "s");
        }
    }
    if (r == SK_OK) {
        const step *last = &steps[n - 1];
        int best = 0;
        for (int q = 1; q < last->state_count; q++)
            if (last->states[q].cost < last->states[best].cost) best = q;
        if (cost) *cost = last->states[best].cost;
        for (int i = n - 1; i >= 0; i--) {
            const fstate *s = &steps[i].states[best];
            melody->notes[i].finger = s->finger[steps[i].held_count] + 1;
            best = s->back;
        }
    }
    free(steps);
    free(pool);
    return r;
}
