/* Melodies: the note list shared by the text and MIDI readers, its checks and copies. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "products/showcase/showcase_internal.h"

void sk__melody_where(const sk_melody *melody, long source, char *out, size_t size)
{
    if (source <= 0 && melody->format == SK_MELODY_FORMAT_TEXT)
        snprintf(out, size, "%s%s", melody->name, melody->name[0] ? ": " : "");
    else if (melody->format == SK_MELODY_FORMAT_TEXT)
        snprintf(out, size, "%s:%ld: ", melody->name, source);
    else
        snprintf(out, size, "%s: byte %ld: ", melody->name, source);
}

static int note_order(const void *pa, const void *pb)
{
    const sk_note *a = pa, *b = pb;
    if (a->start_s != b->start_s) return a->start_s < b->start_s ? -1 : 1;
    if (a->key != b->key) return a->key < b->key ? -1 : 1;
    return (a->source > b->source) - (a->source < b->source);
}

void sk__melody_sort(sk_note *notes, int count)
{
    if (count > 1) qsort(notes, (size_t)count, sizeof *notes, note_order);
}

sk_result sk__melody_alloc(sk_melody *out, int count, const char *name, sk_melody_format format,
                           sk_error *err)
{
    memset(out, 0, sizeof *out);
    out->format = format;
    snprintf(out->name, sizeof out->name, "%s", name ? name : "");
    out->notes = calloc((size_t)(count > 0 ? count : 1), sizeof *out->notes);
    if (!out->notes)
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for %d notes", count);
    return SK_OK;
}

void sk_melody_free(sk_melody *melody)
{
    if (!melody) return;
    free(melody->notes);
    memset(melody, 0, sizeof *melody);
}

sk_result sk_melody_copy(const sk_melody *melody, sk_melody *out, sk_error *err)
{
    sk_result r = sk__melody_alloc(out, melody->note_count, melody->name, melody->format, err);
    if (r != SK_OK) return r;
    if (melody->note_count > 0)
        memcpy(out->notes, melody->notes, (size_t)melody->note_count * sizeof *out->notes);
    out->note_count = melody->note_count;
    return SK_OK;
}

double sk_melody_end(const sk_melody *melody)
{
    double end = 0;
    for (int i = 0; i < melody->note_count; i++) {
        double e = melody->notes[i].start_s + melody->notes[i].duration_s;
        if (e > end) end = e;
    }
    return end;
}

sk_result sk_melody_validate(sk_melody *melody, sk_error *err)
{
    char where[192];
    if (melody->note_count < 0 || melody->note_count > SK_MELODY_MAX_NOTES)
        return sk_fail(err, SK_ERROR_LIMIT, "%s%d notes: at most %d", melody->name,
                       melody->note_count, SK_MELODY_MAX_NOTES);
    if (melody->note_count > 0 && !melody->notes)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "melody: %d notes but no note array",
                       melody->note_count);
    for (int i = 0; i < melody->note_count; i++) {
        const sk_note *n = &melody->notes[i];
        sk__melody_where(melody, n->source, where, sizeof where);
        if (n->key < SK_PIANO_KEY_FIRST || n->key > SK_PIANO_KEY_LAST)
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "%skey %d is not a piano key (%d..%d, A0..C8)", where, n->key,
                           SK_PIANO_KEY_FIRST, SK_PIANO_KEY_LAST);
        if (!isfinite(n->start_s) || n->start_s < 0 || n->start_s > SK_MELODY_MAX_SECONDS)
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "%sstart %g s is out of range [0, %g]",
                           where, n->start_s, SK_MELODY_MAX_SECONDS);
        if (!isfinite(n->duration_s) || n->duration_s <= 0 ||
            n->start_s + n->duration_s > SK_MELODY_MAX_SECONDS)
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "%sduration %g s must be > 0 and end by %g s", where, n->duration_s,
                           SK_MELODY_MAX_SECONDS);
        if (n->finger < 0 || n->finger > 5)
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "%sfinger %d is out of range 1..5 (0 = automatic)", where, n->finger);
        if (n->velocity < 1 || n->velocity > 127)
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "%svelocity %d is out of range 1..127",
                           where, n->velocity);
    }
    sk__melody_sort(melody->notes, melody->note_count);
    /* a key struck again while it sounds */
    double held_until[SK_PIANO_KEY_COUNT];
    int held_by[SK_PIANO_KEY_COUNT];
    for (int k = 0; k < SK_PIANO_KEY_COUNT; k++) held_until[k] = -1, held_by[k] = -1;
    for (int i = 0; i < melody->note_count; i++) {
        const sk_note *n = &melody->notes[i];
        int k = n->key - SK_PIANO_KEY_FIRST;
        if (held_by[k] >= 0 && n->start_s < held_until[k] - 1e-9) {
            char name[8], other[192];
            sk_note_name(n->key, name, sizeof name);
            sk__melody_where(melody, n->source, where, sizeof where);
            const sk_note *o = &melody->notes[held_by[k]];
            if (melody->format == SK_MELODY_FORMAT_TEXT && o->source > 0)
                snprintf(other, sizeof other, "the note of line %ld", o->source);
            else if (o->source > 0)
                snprintf(other, sizeof other, "the note at byte %ld", o->source);
            else
                snprintf(other, sizeof other, "an earlier note");
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "%skey %s is struck at %g s while %s still holds it until %g s", where,
                           name, n->start_s, other, held_until[k]);
        }
        held_by[k] = i;
        held_until[k] = n->start_s + n->duration_s;
    }
    return SK_OK;
}

sk_result sk_melody_cut(sk_melody *melody, double seconds, sk_error *err)
{
    sk_result r = sk_check_range_f(err, "seconds", seconds, 1e-3, SK_MELODY_MAX_SECONDS);
    if (r != SK_OK) return r;
    int w = 0;
    for (int i = 0; i < melody->note_count; i++) {
        sk_note n = melody->notes[i];
        if (n.start_s >= seconds) continue;
        if (n.start_s + n.duration_s > seconds) n.duration_s = seconds - n.start_s;
        melody->notes[w++] = n;
    }
    melody->note_count = w;
    return SK_OK;
}
