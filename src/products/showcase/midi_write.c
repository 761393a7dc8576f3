/* Standard MIDI File writer: format 0, one track, 480 ticks per quarter note at 120 bpm
 * (a tick is 1/960 s), note-offs before note-ons at the same tick. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "shitsukan/io.h"
#include "products/showcase/showcase_internal.h"

#define TICKS_PER_QUARTER 480
#define MICROSECONDS_PER_QUARTER 500000
#define TICKS_PER_SECOND (TICKS_PER_QUARTER * 1000000.0 / MICROSECONDS_PER_QUARTER)

typedef struct midi_event {
    uint32_t tick;
    uint8_t on; /* 0 note-off, 1 note-on: offs sort first */
    uint8_t key, velocity;
} midi_event;

static int event_order(const void *pa, const void *pb)
{
    const midi_event *a = pa, *b = pb;
    if (a->tick != b->tick) return a->tick < b->tick ? -1 : 1;
    if (a->on != b->on) return a->on < b->on ? -1 : 1;
    return (a->key > b->key) - (a->key < b->key);
}

static void put_vlq(FILE *fp, uint32_t v)
{
    uint8_t x[4];
    int n = 1;
    x[3] = (uint8_t)(v & 0x7f);
    while ((v >>= 7) != 0 && n < 4) {
        x[3 - n] = (uint8_t)(0x80 | (v & 0x7f));
        n++;
    }
    fwrite(x + 4 - n, 1, (size_t)n, fp);
}

static size_t vlq_size(uint32_t v)
{
    size_t n = 1;
    while ((v >>= 7) != 0) n++;
    return n;
}

sk_result sk_melody_write_midi(const sk_melody *melody, const char *path, sk_error *err)
{
    int n = melody->note_count;
    midi_event *ev = calloc((size_t)(2 * n + 1), sizeof *ev);
    if (!ev) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for %d notes", n);
    for (int i = 0; i < n; i++) {
        const sk_note *note = &melody->notes[i];
        uint32_t on = (uint32_t)llround(note->start_s * TICKS_PER_SECOND);
        uint32_t off = (uint32_t)llround((note->start_s + note->duration_s) * TICKS_PER_SECOND);
        if (off <= on) off = on + 1;
        int v = note->velocity >= 1 && note->velocity <= 127 ? note->velocity : 80;
        ev[2 * i] = (midi_event){on, 1, (uint8_t)note->key, (uint8_t)v};
        ev[2 * i + 1] = (midi_event){off, 0, (uint8_t)note->key, 64};
    }
    qsort(ev, (size_t)(2 * n), sizeof *ev, event_order);
    /* track length: tempo (7 bytes) + events + end of track */
    size_t length = 7, last = 0;
    for (int i = 0; i < 2 * n; i++) {
        length += vlq_size(ev[i].tick - (uint32_t)last) + 3;
        last = ev[i].tick;
    }
    length += 4;
    sk_atomic_file f;
    sk_result r = sk_atomic_file_open(&f, path, err);
    if (r != SK_OK) {
        free(ev);
        return r;
    }
    static const uint8_t header[14] = {'M',
                                       'T',
                                       'h',
                                       'd',
                                       0,
                                       0,
                                       0,
                                       6,
                                       0,
                                       0,
                                       0,
                                       1,
                                       TICKS_PER_QUARTER >> 8,
                                       TICKS_PER_QUARTER & 0xff};
    fwrite(header, 1, sizeof header, f.fp);
    uint8_t track[8] = {'M',
                        'T',
                        'r',
                        'k',
                        (uint8_t)(length >> 24),
                        (uint8_t)(length >> 16),
                        (uint8_t)(length >> 8),
                        (uint8_t)length};
    fwrite(track, 1, sizeof track, f.fp);
    uint8_t tempo[7] = {0,
                        0xff,
                        0x51,
                        3,
                        (MICROSECONDS_PER_QUARTER >> 16) & 0xff,
                        (MICROSECONDS_PER_QUARTER >> 8) & 0xff,
                        MICROSECONDS_PER_QUARTER & 0xff};
    fwrite(tempo, 1, sizeof tempo, f.fp);
    uint32_t prev = 0;
    for (int i = 0; i < 2 * n; i++) {
        put_vlq(f.fp, ev[i].tick - prev);
        prev = ev[i].tick;
        uint8_t msg[3] = {(uint8_t)(ev[i].on ? 0x90 : 0x80), ev[i].key, ev[i].velocity};
        fwrite(msg, 1, 3, f.fp);
    }
    static const uint8_t end[4] = {0, 0xff, 0x2f, 0};
    fwrite(end, 1, sizeof end, f.fp);
    free(ev);
    return sk_atomic_file_commit(&f, err);
}
