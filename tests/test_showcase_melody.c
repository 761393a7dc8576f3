/* Showcase melodies: the text format (names, numbers, beats, fingers, strict one-line
 * errors naming the line), Standard MIDI Files (tempo, running status, tracks merged,
 * errors naming the byte offset, malformed framing that would crash libsmf), the MIDI
 * writer's round trip, the shipped MIDI file equal to its generator's output, and the
 * automatic fingering's rule. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "test_support.h"
#include "shitsukan/io.h"
#include "shitsukan/showcase.h"

static sk_melody parse_ok(const char *text)
{
    sk_melody m;
    sk_error err = {0};
    if (sk_melody_parse_text(text, strlen(text), "t.txt", &m, &err) != SK_OK)
        fail_msg("%s", err.message);
    return m;
}

/* The error message of a malformed text, checked to be one line containing `where`. */
static void parse_fails(const char *text, const char *where, const char *what)
{
    sk_melody m;
    sk_error err = {0};
    sk_result r = sk_melody_parse_text(text, strlen(text), "t.txt", &m, &err);
    if (r == SK_OK) fail_msg("accepted: %s", text);
    if (!strstr(err.message, where)) fail_msg("\"%s\" lacks \"%s\"", err.message, where);
    if (what && !strstr(err.message, what)) fail_msg("\"%s\" lacks \"%s\"", err.message, what);
    assert_null(strchr(err.message, '\n'));
    assert_null(m.notes);
}

static void test_note_names(void **state)
{
    (void)state;
    int k;
    assert_true(sk_note_parse("C4", &k)), assert_int_equal(k, 60);
    assert_true(sk_note_parse("A4", &k)), assert_int_equal(k, 69);
    assert_true(sk_note_parse("a0", &k)), assert_int_equal(k, 21);
    assert_true(sk_note_parse("C8", &k)), assert_int_equal(k, 108);
    assert_true(sk_note_parse("F#3", &k)), assert_int_equal(k, 54);
    assert_true(sk_note_parse("Bb5", &k)), assert_int_equal(k, 82);
    assert_true(sk_note_parse("Cb4", &k)), assert_int_equal(k, 59);
    assert_true(sk_note_parse("C-1", &k)), assert_int_equal(k, 0);
    assert_true(sk_note_parse("64", &k)), assert_int_equal(k, 64);
    assert_false(sk_note_parse("H4", &k));
    assert_false(sk_note_parse("C", &k));
    assert_false(sk_note_parse("C44", &k));
    assert_false(sk_note_parse("128", &k));
    char name[8];
    for (int key = 0; key < 128; key++) { /* names read back */
        sk_note_name(key, name, sizeof name);
        assert_true(sk_note_parse(name, &k));
        assert_int_equal(k, key);
    }
    assert_true(sk_note_is_black(61)), assert_false(sk_note_is_black(60)),
        assert_true(sk_note_is_black(70));
}

static void test_text_format(void **state)
{
    (void)state;
    sk_melody m = parse_ok("# a comment\n"
                           "E4 1.0 0.5   # after the note\n"
                           "60 0 0.5 1 100\r\n"
                           "\n"
                           "C#4 2 0.25 - 30\n"
                           "D4 2 0.25 3\n");
    assert_int_equal(m.note_count, 4);
    /* sorted by start, then key */
    assert_int_equal(m.notes[0].key, 60), assert_int_equal(m.notes[0].finger, 1);
    assert_int_equal(m.notes[0].velocity, 100), assert_int_equal(m.notes[0].source, 3);
    assert_int_equal(m.notes[1].key, 64), assert_int_equal(m.notes[1].finger, 0);
    assert_int_equal(m.notes[1].velocity, 80);
    assert_int_equal(m.notes[2].key, 61), assert_int_equal(m.notes[2].velocity, 30);
    assert_int_equal(m.notes[3].key, 62), assert_int_equal(m.notes[3].finger, 3);
    assert_true(fabs(sk_melody_end(&m) - 2.25) < 1e-12);
    sk_melody_free(&m);
    /* beats */
    m = parse_ok("bpm 120\nC4 2 1\n");
    assert_true(fabs(m.notes[0].start_s - 1.0) < 1e-12 &&
                fabs(m.notes[0].duration_s - 0.5) < 1e-12);
    sk_melody_free(&m);
    /* the same key again once the first has ended */
    m = parse_ok("C4 0 1\nC4 1 1\n");
    assert_int_equal(m.note_count, 2);
    sk_melody_free(&m);
    m = parse_ok("");
    assert_int_equal(m.note_count, 0);
    sk_melody_free(&m);
}

static void test_text_errors(void **state)
{
    (void)state;
    parse_fails("C4 0 1\nH4 1 1\n", "t.txt:2:", "note \"H4\"");
    parse_fails("C4 0 1\n\n12 1 1\n", "t.txt:3:", "not on the piano");
    parse_fails("C9 0 1\n", "t.txt:1:", "not on the piano");
    parse_fails("C4 -1 1\n", "t.txt:1:", "start");
    parse_fails("C4 0 0\n", "t.txt:1:", "duration");
    parse_fails("C4 0 nan\n", "t.txt:1:", "duration");
    parse_fails("C4 0 inf\n", "t.txt:1:", "duration");
    parse_fails("C4 0x10 1\n", "t.txt:1:", "start");
    parse_fails("C4 0 1 6\n", "t.txt:1:", "finger");
    parse_fails("C4 0 1 1 128\n", "t.txt:1:", "velocity");
    parse_fails("C4 0 1 1 80 extra\n", "t.txt:1:", "at most 5");
    parse_fails("C4 0\n", "t.txt:1:", "NOTE START DURATION");
    parse_fails("C4 0 1\nbpm 90\n", "t.txt:2:", "before the first note");
    parse_fails("bpm 0\n", "t.txt:1:", "bpm");
    parse_fails("C4 0 4000\n", "t.txt:1:", "duration");
    parse_fails("C4 0 2\nC4 1 1\n", "t.txt:2:", "line 1");
    static const char nul[] = "C4 0 1\nD4\0 1 1\n";
    sk_melody m;
    sk_error err = {0};
    assert_int_equal(sk_melody_parse_text(nul, sizeof nul - 1, "t.txt", &m, &err), SK_ERROR_PARSE);
    assert_non_null(strstr(err.message, "t.txt:2:"));
}

/* ------------------------------------------------------------ MIDI */

typedef struct bytes {
    uint8_t b[512];
    size_t n;
} bytes;

static void put(bytes *o, const void *data, size_t n)
{
    assert_true(o->n + n <= sizeof o->b);
    memcpy(o->b + o->n, data, n);
    o->n += n;
}

/* A file from a header and raw track bodies (their chunk headers added here). */
static bytes smf(int format, int division, int tracks, const bytes *body)
{
    bytes o = {{0}, 0};
    uint8_t h[14] = {'M',
                     'T',
                     'h',
                     'd',
                     0,
                     0,
                     0,
                     6,
                     0,
                     (uint8_t)format,
                     0,
                     (uint8_t)tracks,
                     (uint8_t)(division >> 8),
                     (uint8_t)division};
    put(&o, h, sizeof h);
    for (int t = 0; t < tracks; t++) {
        uint8_t c[8] = {'M', 'T', 'r', 'k', 0, 0, (uint8_t)(body[t].n >> 8), (uint8_t)body[t].n};
        put(&o, c, 8);
        put(&o, body[t].b, body[t].n);
    }
    return o;
}

static bytes track(const uint8_t *events, size_t n)
{
    bytes t = {{0}, 0};
    put(&t, events, n);
    return t;
}

static void midi_fails(const bytes *file, const char *where, const char *what)
{
    sk_melody m;
    sk_error err = {0};
    if (sk_melody_parse_midi(file->b, file->n, "m.mid", &m, &err) == SK_OK) fail_msg("accepted");
    if (!strstr(err.message, where)) fail_msg("\"%s\" lacks \"%s\"", err.message, where);
    if (what && !strstr(err.message, what)) fail_msg("\"%s\" lacks \"%s\"", err.message, what);
    assert_null(strchr(err.message, '\n'));
}

static void test_midi_reading(void **state)
{
    (void)state;
    /* 96 ticks a quarter; tempo 1 s a quarter from tick 0, 0.5 s from tick 192; running
       status; a note-on of velocity 0 ends a note; a text meta event and a sysex skipped;
       a second track with a note that never ends (it ends with its track) */
    const uint8_t t1[] = {0x00, 0xff, 0x51, 0x03, 0x0f, 0x42, 0x40, /* 1000000 us */
                          0x00, 0xff, 0x01, 0x02, 'h',  'i',        /* text */
                          0x00, 0x90, 60,   100,                    /* C4 on at 0 */
                          0x60, 64,   90,                           /* E4 on at 96 (running) */
                          0x00, 0xf0, 0x02, 0x7e, 0xf7,             /* sysex */
                          0x60, 0x80, 60,   0,                      /* C4 off at 192 */
                          0x00, 0xff, 0x51, 0x03, 0x07, 0xa1, 0x20, /* 500000 us */
                          0x00, 0x90, 64,   0,                      /* E4 off at 192 */
                          0x60, 0xff, 0x2f, 0x00};                  /* end at 288 */
    const uint8_t t2[] = {0x81, 0x40, 0x91, 67,   50, /* G4 on at 192 (delta 192 as a 2-byte VLQ) */
                          0x81, 0x40, 0xff, 0x2f, 0x00}; /* end at 384 */
    bytes body[2] = {track(t1, sizeof t1), track(t2, sizeof t2)};
    bytes f = smf(1, 96, 2, body);
    sk_melody m;
    sk_error err = {0};
    if (sk_melody_parse_midi(f.b, f.n, "m.mid", &m, &err) != SK_OK) fail_msg("%s", err.message);
    assert_int_equal(m.note_count, 3);
    assert_int_equal(m.notes[0].key, 60);
    assert_true(fabs(m.notes[0].start_s) < 1e-9 && fabs(m.notes[0].duration_s - 2.0) < 1e-9);
    assert_int_equal(m.notes[0].velocity, 100);
    assert_int_equal(m.notes[0].finger, 0);
    assert_int_equal(m.notes[0].source, 14 + 8 + 13 + 1); /* byte offset of its status */
    assert_int_equal(m.notes[1].key, 64);
    assert_true(fabs(m.notes[1].start_s - 1.0) < 1e-9 && fabs(m.notes[1].duration_s - 1.0) < 1e-9);
    assert_int_equal(m.notes[2].key, 67);
    /* 192 ticks at 1 s a quarter = 2 s; then to tick 384 at 0.5 s a quarter = 1 s more */
    assert_true(fabs(m.notes[2].start_s - 2.0) < 1e-9 && fabs(m.notes[2].duration_s - 1.0) < 1e-9);
    sk_melody_free(&m);
}

static void test_midi_errors(void **state)
{
    (void)state;
    const uint8_t ok[] = {0x00, 0x90, 60, 100, 0x60, 0x80, 60, 0, 0x00, 0xff, 0x2f, 0x00};
    bytes body = track(ok, sizeof ok);
    bytes f = smf(0, 96, 1, &body);
    sk_melody m;
    sk_error err = {0};
    assert_int_equal(sk_melody_parse_midi(f.b, f.n, "m.mid", &m, &err), SK_OK);
    sk_melody_free(&m);
    /* truncated inside a track chunk */
    bytes cut = f;
    cut.n -= 3;
    midi_fails(&cut, "m.mid: byte 14:", "claims");
    /* no end of track: libsmf would assert here */
    const uint8_t no_end[] = {0x00, 0x90, 60, 100, 0x60, 0x80, 60, 0};
    body = track(no_end, sizeof no_end);
    f = smf(0, 96, 1, &body);
    midi_fails(&f, "byte 30:", "no end-of-track");
    /* a meta event whose length runs past its track */
    const uint8_t long_meta[] = {0x00, 0xff, 0x01, 0x7f, 'x', 0x00, 0xff, 0x2f, 0x00};
    body = track(long_meta, sizeof long_meta);
    f = smf(0, 96, 1, &body);
    midi_fails(&f, "byte 23:", "meta event 0x01");
    /* running status after a meta event */
    const uint8_t bad_running[] = {0x00, 0x90, 60, 100,  0x00, 0xff, 0x01, 0x00,
                                   0x10, 62,   90, 0x00, 0xff, 0x2f, 0x00};
    body = track(bad_running, sizeof bad_running);
    f = smf(0, 96, 1, &body);
    midi_fails(&f, "byte 31:", "without a status");
    /* a data byte with its top bit set */
    const uint8_t bad_data[] = {0x00, 0x90, 0xc0, 100, 0x00, 0xff, 0x2f, 0x00};
    body = track(bad_data, sizeof bad_data);
    f = smf(0, 96, 1, &body);
    midi_fails(&f, "byte 24:", "top bit");
    /* a variable-length number of five bytes */
    const uint8_t vlq[] = {0x81, 0x81, 0x81, 0x81, 0x01, 0xff, 0x2f, 0x00};
    body = track(vlq, sizeof vlq);
    f = smf(0, 96, 1, &body);
    midi_fails(&f, "byte 22:", "longer than 4 bytes");
    /* header problems */
    body = track(ok, sizeof ok);
    f = smf(2, 96, 1, &body);
    midi_fails(&f, "byte 8:", "format 2");
    f = smf(0, 0x8000 | 25, 1, &body);
    midi_fails(&f, "byte 12:", "SMPTE");
    f = smf(1, 96, 1, &body);
    f.b[11] = 2; /* declares two tracks, holds one */
    midi_fails(&f, "byte 34:", "declares 2 tracks");
    /* a note below the piano, with the offset of its event */
    const uint8_t low[] = {0x00, 0x90, 12, 100, 0x60, 0x80, 12, 0, 0x00, 0xff, 0x2f, 0x00};
    body = track(low, sizeof low);
    f = smf(0, 96, 1, &body);
    midi_fails(&f, "m.mid: byte 23:", "not a piano key");
    bytes text = {{'h', 'e', 'l', 'l', 'o'}, 5};
    midi_fails(&text, "byte 0:", "not a Standard MIDI File");
    /* a file of the right name through sk_melody_load: text is read as text */
    const char *path = sk_test_path("not-midi.mid");
    sk_test_write_file(path, "C4 0 1\nX 1 1\n", 13);
    assert_int_equal(sk_melody_load(path, &m, &err), SK_ERROR_PARSE);
    assert_non_null(strstr(err.message, "not-midi.mid:2:"));
}

static void test_midi_round_trip(void **state)
{
    (void)state;
    char path[512];
    snprintf(path, sizeof path, "%s/showcase/ode-to-joy.txt", SK_TEST_PRESET_DIR);
    sk_melody text, back;
    sk_error err = {0};
    assert_int_equal(sk_melody_load(path, &text, &err), SK_OK);
    const char *out = sk_test_path("ode.mid");
    assert_int_equal(sk_melody_write_midi(&text, out, &err), SK_OK);
    assert_int_equal(sk_melody_load(out, &back, &err), SK_OK);
    assert_int_equal(back.note_count, text.note_count);
    assert_int_equal(back.format, SK_MELODY_FORMAT_MIDI);
    for (int i = 0; i < text.note_count; i++) {
        assert_int_equal(back.notes[i].key, text.notes[i].key);
        assert_int_equal(back.notes[i].velocity, text.notes[i].velocity);
        assert_true(fabs(back.notes[i].start_s - text.notes[i].start_s) <= 0.5 / 960 + 1e-9);
        assert_true(fabs(back.notes[i].duration_s - text.notes[i].duration_s) <= 1.0 / 960 + 1e-9);
        assert_true(back.notes[i].source > 14);
    }
    /* the shipped file is what the generator writes */
    char shipped[512];
    snprintf(shipped, sizeof shipped, "%s/showcase/ode-to-joy.mid", SK_TEST_PRESET_DIR);
    assert_true(sk_test_same_file(out, shipped));
    /* the text writer reads back with the fingers */
    const char *txt = sk_test_path("ode.txt");
    assert_int_equal(sk_melody_choose_fingers(&text, NULL, NULL, NULL, &err), SK_OK);
    assert_int_equal(sk_melody_write_text(&text, txt, &err), SK_OK);
    sk_melody again;
    assert_int_equal(sk_melody_load(txt, &again, &err), SK_OK);
    for (int i = 0; i < text.note_count; i++) {
        assert_int_equal(again.notes[i].finger, text.notes[i].finger);
        assert_true(fabs(again.notes[i].start_s - text.notes[i].start_s) < 1e-9);
    }
    sk_melody_free(&text), sk_melody_free(&back), sk_melody_free(&again);
}

/* ------------------------------------------------------------ fingering */

static void fingers_of(const char *text, int *out)
{
    sk_melody m = parse_ok(text);
    sk_error err = {0};
    if (sk_melody_choose_fingers(&m, NULL, NULL, NULL, &err) != SK_OK) fail_msg("%s", err.message);
    for (int i = 0; i < m.note_count; i++) out[i] = m.notes[i].finger;
    sk_melody_free(&m);
}

static void test_fingering(void **state)
{
    (void)state;
    int f[16];
    fingers_of("C4 0 0.4\nD4 0.5 0.4\nE4 1 0.4\nF4 1.5 0.4\nG4 2 0.4\n", f);
    for (int i = 0; i < 5; i++) assert_int_equal(f[i], i + 1);
    fingers_of("G4 0 0.4\nF4 0.5 0.4\nE4 1 0.4\nD4 1.5 0.4\nC4 2 0.4\n", f);
    for (int i = 0; i < 5; i++) assert_int_equal(f[i], 5 - i);
    /* a repeated note keeps its finger */
    fingers_of("E4 0 0.4\nE4 0.5 0.4\nE4 1 0.4\n", f);
    assert_int_equal(f[0], f[1]), assert_int_equal(f[1], f[2]);
    /* a chord in the five-finger position */
    fingers_of("C4 0 1\nE4 0 1\nG4 0 1\n", f);
    assert_int_equal(f[0], 1), assert_int_equal(f[1], 3), assert_int_equal(f[2], 5);
    /* held notes: distinct fingers in the keys' order, whatever comes later */
    fingers_of("C4 0 2\nD4 0.5 0.4\nE4 1 0.4\nF4 1.5 0.4\n", f);
    for (int i = 1; i < 4; i++) assert_true(f[i] > f[0]);
    /* given fingers are kept, the others fit around them */
    fingers_of("C4 0 0.4 2\nD4 0.5 0.4\nE4 1 0.4\n", f);
    assert_int_equal(f[0], 2), assert_int_equal(f[1], 3), assert_int_equal(f[2], 4);
    /* errors: wider than a hand reaches, six notes at once, given fingers out of order */
    sk_melody m = parse_ok("C4 0 1\nC6 0.5 1\n");
    sk_error err = {0};
    assert_int_equal(sk_melody_choose_fingers(&m, NULL, NULL, NULL, &err),
                     SK_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(err.message, "t.txt:2:"));
    sk_melody_free(&m);
    m = parse_ok("C4 0 1\nD4 0 1\nE4 0 1\nF4 0 1\nG4 0 1\nA4 0 1\n");
    assert_int_equal(sk_melody_choose_fingers(&m, NULL, NULL, NULL, &err),
                     SK_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(err.message, "more than 5 notes"));
    sk_melody_free(&m);
    m = parse_ok("C4 0 1 3\nD4 0 1 2\n");
    assert_int_equal(sk_melody_choose_fingers(&m, NULL, NULL, NULL, &err),
                     SK_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(err.message, "t.txt:2:"));
    sk_melody_free(&m);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_note_names),  cmocka_unit_test(test_text_format),
        cmocka_unit_test(test_text_errors), cmocka_unit_test(test_midi_reading),
        cmocka_unit_test(test_midi_errors), cmocka_unit_test(test_midi_round_trip),
        cmocka_unit_test(test_fingering),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
