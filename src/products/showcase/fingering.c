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

#include "products/showcase/showcase_internal.h"

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

/* The desc with its defaults filled in (the piano's white-key pitch, fingers a pitch apart),
 * checked. */
static sk_result fingering_settings(const sk_fingering_desc *desc, const sk_piano *piano,
                                    sk_fingering_desc *d, sk_error *err)
{
    *d = desc ? *desc : (sk_fingering_desc){0};
    if (d->pitch_mm == 0) d->pitch_mm = piano->desc.white_pitch_mm;
    sk_schema_apply_defaults(&sk__fingering_schema, d);
    bool any = false;
    for (int f = 0; f < 5; f++) any = any || d->finger_x_mm[f] != 0;
    if (!any)
        for (int f = 0; f < 5; f++) d->finger_x_mm[f] = f * d->pitch_mm;
    sk_result r = sk_schema_check(&sk__fingering_schema, d, "fingering", err);
    if (r != SK_OK) return r;
    for (int f = 0; f < 5; f++)
        if ((r = sk_check_range_f(err, "fingering.finger_x_mm", d->finger_x_mm[f], -500, 500)) !=
            SK_OK)
            return r;
    return SK_OK;
}

/* The search's inputs and its steps, one per note. */
typedef struct fingering {
    const sk_melody *melody;
    const sk_piano *piano;
    const sk_fingering_desc *d;
    step *steps;
} fingering;

/* The notes still sounding at note i's start (a subset of the previous step's set); fails
 * when more than five sound. */
static sk_result find_held(const fingering *fg, int i, sk_error *err)
{
    const sk_note *notes = fg->melody->notes, *ni = &notes[i];
    step *st = &fg->steps[i];
    const step *pv = &fg->steps[i - 1];
    int candidates[MAX_HELD + 1], cn = 0;
    for (int k = 0; k < pv->held_count; k++) candidates[cn++] = pv->held[k];
    candidates[cn++] = i - 1;
    for (int k = 0; k < cn; k++) {
        const sk_note *nj = &notes[candidates[k]];
        if (nj->start_s + nj->duration_s > ni->start_s + 1e-9) {
            if (st->held_count == MAX_HELD - 1) {
                char where[192];
                sk__melody_where(fg->melody, ni->source, where, sizeof where);
                return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                               "%smore than 5 notes sound at %g s; one hand has five fingers",
                               where, ni->start_s);
            }
            st->held[st->held_count++] = candidates[k];
        }
    }
    return SK_OK;
}

/* The fingers of note i's held notes in state `from` of the previous step. */
static void held_fingers(const step *st, const step *pv, const fstate *from, int i, int *held_f)
{
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
}

/* Whether finger b on note i (at xi) can be held down with the held notes' fingers: distinct,
 * in the keys' order, not `apart`, within reach and not cramped. */
static bool fits_held(const fingering *fg, const step *st, const int *held_f, double xi, int b)
{
    const sk_fingering_desc *d = fg->d;
    bool ok = true;
    for (int k = 0; k < st->held_count && ok; k++) {
        const sk_note *nj = &fg->melody->notes[st->held[k]];
        double dx = xi - sk_piano_key_get(fg->piano, nj->key)->x_mm;
        int a = held_f[k];
        if (a == b || (b - a) * dx <= 0 || d->apart[a][b] || d->apart[b][a] ||
            fabs(dx - (d->finger_x_mm[b] - d->finger_x_mm[a])) > d->reach_mm ||
            cramped(a, b, dx, d))
            ok = false;
    }
    return ok;
}

/* The cost of the step from note i - 1 (finger a) to note i (finger b, key at xi) into
 * *cost; false when the two are busy at once and the fingers cross, crowd or move too
 * quickly. */
static bool step_cost(const fingering *fg, int i, int a, int b, double xi, double *cost)
{
    const sk_fingering_desc *d = fg->d;
    const sk_note *np = &fg->melody->notes[i - 1], *ni = &fg->melody->notes[i];
    double dx = xi - sk_piano_key_get(fg->piano, np->key)->x_mm;
    double s = fabs(dx - (d->finger_x_mm[b] - d->finger_x_mm[a]));
    bool held = np->start_s + np->duration_s > ni->start_s + 1e-9;
    double gap = ni->start_s - np->start_s;
    bool busy = np->start_s + np->duration_s + d->busy_after_s > ni->start_s - d->busy_before_s;
    if (busy && (cramped(a, b, dx, d) || (a != b && (b - a) * dx <= 0) ||
                 (a == b && np->key != ni->key &&
                  ni->start_s - (np->start_s + np->duration_s) < d->move_gap_s)))
        return false;
    if (held)
        *cost = s / d->pitch_mm;
    else
        *cost = s / d->pitch_mm * (1 + 0.1 * (s / d->pitch_mm) / fmax(gap, 0.05)) +
                (a == b && np->key != ni->key ? 2.0 : 0.0) +
                (a != b && np->key == ni->key ? 0.3 : 0.0);
    return true;
}

/* A candidate state into the step: merged with an equal state (the cheaper kept), else
 * added while there is room. */
static void merge_state(step *st, const fstate *cand)
{
    int same = -1;
    for (int q = 0; q < st->state_count && same < 0; q++)
        if (memcmp(st->states[q].finger, cand->finger, (size_t)st->held_count + 1) == 0) same = q;
    if (same >= 0) {
        if (cand->cost < st->states[same].cost) st->states[same] = *cand;
    } else if (st->state_count < MAX_STATES) {
        st->states[st->state_count++] = *cand;
    }
}

/* Step i's states: every previous state extended by each finger allowed on note i. */
static void extend_states(const fingering *fg, int i)
{
    const sk_note *ni = &fg->melody->notes[i];
    step *st = &fg->steps[i];
    double xi = sk_piano_key_get(fg->piano, ni->key)->x_mm;
    bool black = sk_note_is_black(ni->key);
    const step *pv = i > 0 ? &fg->steps[i - 1] : NULL;
    int prev_states = pv ? pv->state_count : 1;
    for (int ps = 0; ps < prev_states; ps++) {
        const fstate *from = pv ? &pv->states[ps] : NULL;
        /* fingers of the held notes, from the previous step's assignment */
        int held_f[MAX_HELD];
        held_fingers(st, pv, from, i, held_f);
        for (int b = 0; b < 5; b++) {
            if (ni->finger != 0 && ni->finger != b + 1) continue;
            double c = from ? from->cost : 0;
            if (!fits_held(fg, st, held_f, xi, b)) continue;
            if (from) { /* the step from the previous note */
                double step_c;
                if (!step_cost(fg, i, from->finger[pv->held_count], b, xi, &step_c)) continue;
                c += step_c;
            }
            c += note_cost(black, b);
            /* merge with an equal state */
            fstate cand = {{0}, c, ps};
            for (int k = 0; k < st->held_count; k++) cand.finger[k] = (int8_t)held_f[k];
            cand.finger[st->held_count] = (int8_t)b;
            merge_state(st, &cand);
        }
    }
}

/* The error for a note no finger can play. */
static sk_result no_finger_error(const fingering *fg, int i, sk_error *err)
{
    const sk_note *ni = &fg->melody->notes[i];
    const step *st = &fg->steps[i];
    char name[8], where[192];
    sk_note_name(ni->key, name, sizeof name);
    sk__melody_where(fg->melody, ni->source, where, sizeof where);
    return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                   "%sno finger can play %s at %g s with the %d note%s still sounding: the "
                   "keys held together "
                   "are wider than the hand reaches or the given fingers are out of order",
                   where, name, ni->start_s, st->held_count, st->held_count == 1 ? "" : "s");
}

/* The cheapest last state traced back: each note's finger, and the total cost. */
static void backtrack(const step *steps, int n, sk_melody *melody, double *cost)
{
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

sk_result sk_melody_choose_fingers(sk_melody *melody, const sk_piano *piano,
                                   const sk_fingering_desc *desc, double *cost, sk_error *err)
{
    sk_piano default_piano;
    if (!piano) {
        sk_piano_init(&default_piano, NULL, NULL);
        piano = &default_piano;
    }
    sk_fingering_desc d;
    sk_result r = fingering_settings(desc, piano, &d, err);
    if (r != SK_OK) return r;
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
    fingering fg = {melody, piano, &d, steps};
    for (int i = 0; i < n && r == SK_OK; i++) {
        steps[i].states = pool + (size_t)i * MAX_STATES;
        /* the notes still sounding at i's start: a subset of the previous step's set */
        if (i > 0) r = find_held(&fg, i, err);
        if (r != SK_OK) break;
        extend_states(&fg, i);
        if (steps[i].state_count == 0) r = no_finger_error(&fg, i, err);
    }
    if (r == SK_OK) backtrack(steps, n, melody, cost);
    free(steps);
    free(pool);
    return r;
}
