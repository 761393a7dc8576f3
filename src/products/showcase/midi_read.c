/* Standard MIDI Files to melodies through libsmf: the file's framing is checked first
 * (midi_framing.c), libsmf reads the plain copy (tempo map, tracks merged in time order)
 * with its glib log captured, and note-ons are paired with their note-offs per key. */
#include <glib.h>
#include <pthread.h>
#include <smf.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "products/showcase/showcase_internal.h"

#define GM_PERCUSSION_CHANNEL 9 /* channel 10: General MIDI drums, not pitched */

/* libsmf reports through glib's log, a process-wide handler: one load at a time sets it. */
static pthread_mutex_t log_lock = PTHREAD_MUTEX_INITIALIZER;

typedef struct log_capture {
    int count;
    char first[256];
} log_capture;

static void capture_log(const gchar *domain, GLogLevelFlags level, const gchar *message,
                        gpointer user)
{
    (void)domain, (void)level;
    log_capture *c = user;
    if (c->count++ == 0) snprintf(c->first, sizeof c->first, "%s", message ? message : "");
}

typedef struct pairing {
    int note[SK_PIANO_KEY_COUNT];  /* sounding note per key, -1 none */
    int track[SK_PIANO_KEY_COUNT]; /* its track */
} pairing;

/* Ends the note sounding on key k at `t` (a zero-length note is dropped). */
static void end_note(sk_melody *m, pairing *pr, int k, double t, bool *dropped)
{
    int i = pr->note[k];
    if (i < 0) return;
    m->notes[i].duration_s = t - m->notes[i].start_s;
    if (!(m->notes[i].duration_s > 0)) {
        m->notes[i].duration_s = 0;
        *dropped = true;
    }
    pr->note[k] = -1;
}

static sk_result read_events(smf_t *smf, const sk__midi_plain *plain, const char *name,
                             sk_melody *m, sk_error *err)
{
    pairing pr;
    for (int k = 0; k < SK_PIANO_KEY_COUNT; k++) pr.note[k] = pr.track[k] = -1;
    bool dropped = false;
    smf_event_t *e;
    while ((e = smf_get_next_event(smf)) != NULL) {
        int track = e->track ? e->track->track_number : 0;
        if (track < 1 || track > plain->track_count || e->event_number < 1 ||
            e->event_number > plain->event_count[track - 1] || e->midi_buffer_length < 1)
            return sk_fail(err, SK_ERROR_PARSE,
                           "%s: libsmf returned an event the file does not hold", name);
        long offset = plain->offset[track - 1][e->event_number - 1];
        const uint8_t *b = e->midi_buffer;
        double t = e->time_seconds;
        if (b[0] == 0xff && e->midi_buffer_length >= 2 && b[1] == 0x2f) {
            for (int k = 0; k < SK_PIANO_KEY_COUNT; k++)
                if (pr.note[k] >= 0 && pr.track[k] == track) end_note(m, &pr, k, t, &dropped);
            continue;
        }
        if (e->midi_buffer_length != 3) continue;
        int kind = b[0] & 0xf0, channel = b[0] & 0x0f, key = b[1], velocity = b[2];
        if (kind != 0x80 && kind != 0x90) continue;
        if (channel == GM_PERCUSSION_CHANNEL) continue;
        bool on = kind == 0x90 && velocity > 0;
        if (key < SK_PIANO_KEY_FIRST || key > SK_PIANO_KEY_LAST) {
            if (!on) continue;
            char nm[8];
            sk_note_name(key, nm, sizeof nm);
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "%s: byte %ld: note %d (%s) is not a piano key (%d..%d, A0..C8)", name,
                           offset, key, nm, SK_PIANO_KEY_FIRST, SK_PIANO_KEY_LAST);
        }
        int k = key - SK_PIANO_KEY_FIRST;
        end_note(m, &pr, k, t, &dropped); /* a note-off, or a key struck again */
        if (!on) continue;
        if (m->note_count >= SK_MELODY_MAX_NOTES)
            return sk_fail(err, SK_ERROR_LIMIT, "%s: byte %ld: more than %d notes", name, offset,
                           SK_MELODY_MAX_NOTES);
        sk_note *n = &m->notes[m->note_count];
        memset(n, 0, sizeof *n);
        n->key = key;
        n->start_s = t;
        n->velocity = velocity;
        n->source = offset;
        pr.note[k] = m->note_count++;
        pr.track[k] = track;
    }
    if (dropped) { /* zero-length notes cannot be played */
        int w = 0;
        for (int i = 0; i < m->note_count; i++)
            if (m->notes[i].duration_s > 0) m->notes[w++] = m->notes[i];
        m->note_count = w;
    }
    return SK_OK;
}

sk_result sk_melody_parse_midi(const uint8_t *data, size_t length, const char *source_name,
                               sk_melody *out, sk_error *err)
{
    const char *name = source_name ? source_name : "midi";
    memset(out, 0, sizeof *out);
    sk__midi_plain plain;
    sk_result r = sk__midi_plain_make(data, length, name, &plain, err);
    if (r != SK_OK) return r;
    int events = 0;
    for (int t = 0; t < plain.track_count; t++) events += plain.event_count[t];
    int cap = events < SK_MELODY_MAX_NOTES ? events : SK_MELODY_MAX_NOTES;
    if ((r = sk__melody_alloc(out, cap, name, SK_MELODY_FORMAT_MIDI, err)) != SK_OK) {
        sk__midi_plain_free(&plain);
        return r;
    }
    log_capture capture = {0};
    pthread_mutex_lock(&log_lock);
    guint handler = g_log_set_handler(
        "libsmf", (GLogLevelFlags)(G_LOG_LEVEL_MASK | G_LOG_FLAG_FATAL | G_LOG_FLAG_RECURSION),
        capture_log, &capture);
    smf_t *smf = smf_load_from_memory(plain.bytes, (int)plain.size);
    if (smf && capture.count == 0) {
        smf_rewind(smf);
        r = read_events(smf, &plain, name, out, err);
    }
    if (smf) smf_delete(smf);
    g_log_remove_handler("libsmf", handler);
    pthread_mutex_unlock(&log_lock);
    if (r == SK_OK && (!smf || capture.count > 0))
        r = sk_fail(err, SK_ERROR_PARSE, "%s: libsmf: %s", name,
                    capture.count ? capture.first : "the file could not be read");
    sk__midi_plain_free(&plain);
    if (r == SK_OK) r = sk_melody_validate(out, err);
    if (r != SK_OK) sk_melody_free(out);
    return r;
}
