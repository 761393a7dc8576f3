/* The melody text format: one note a line, "NOTE START DURATION [FINGER] [VELOCITY]",
 * comments from a '#' that begins a field (C#4 is a note) to the end of the line, an
 * optional "bpm N" line before the notes (then times are in beats).
 * Strict: the first error stops the reading and names its line. */
#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "shitsukan/io.h"
#include "products/showcase/showcase_internal.h"

#define MAX_FIELDS 6
#define MAX_TOKEN 64

/* A whole decimal number (no hexadecimal, inf or nan, nothing after it). */
static bool parse_decimal(const char *s, double *out)
{
    if (!*s) return false;
    for (const char *p = s; *p; p++)
        if (!isdigit((unsigned char)*p) && *p != '.' && *p != 'e' && *p != 'E' && *p != '+' &&
            *p != '-')
            return false;
    char *end = NULL;
    errno = 0;
    double v = strtod(s, &end);
    if (*end || errno == ERANGE || !isfinite(v)) return false;
    *out = v;
    return true;
}

static bool parse_int(const char *s, long lo, long hi, int *out)
{
    if (!*s) return false;
    for (const char *p = s; *p; p++)
        if (!isdigit((unsigned char)*p)) return false;
    if (strlen(s) > 6) return false;
    long v = strtol(s, NULL, 10);
    if (v < lo || v > hi) return false;
    *out = (int)v;
    return true;
}

typedef struct text_reader {
    const char *name;
    long line;
    sk_error *err;
} text_reader;

static sk_result line_fail(const text_reader *r, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
static sk_result line_fail(const text_reader *r, const char *fmt, ...)
{
    char detail[400];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(detail, sizeof detail, fmt, ap);
    va_end(ap);
    return sk_fail(r->err, SK_ERROR_PARSE, "%s:%ld: %s", r->name, r->line, detail);
}

/* Splits one line (without its newline, comments cut) into tokens. */
static int split(const char *line, size_t length, char tokens[MAX_FIELDS + 1][MAX_TOKEN],
                 bool *too_long)
{
    int count = 0;
    size_t i = 0;
    *too_long = false;
    while (i < length) {
        while (i < length && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) i++;
        if (i >= length) break;
        size_t start = i;
        while (i < length && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') i++;
        if (count <= MAX_FIELDS) {
            size_t n = i - start;
            if (n >= MAX_TOKEN) {
                *too_long = true;
                n = MAX_TOKEN - 1;
            }
            memcpy(tokens[count], line + start, n);
            tokens[count][n] = '\0';
        }
        count++;
    }
    return count;
}

static sk_result parse_note(const text_reader *r, char tok[MAX_FIELDS + 1][MAX_TOKEN], int count,
                            double seconds_per_unit, sk_note *n)
{
    if (count < 3)
        return line_fail(r,
                         "a note needs NOTE START DURATION [FINGER] [VELOCITY] (%d field%s given)",
                         count, count == 1 ? "" : "s");
    if (count > 5)
        return line_fail(r, "%d fields: a note has at most 5 (NOTE START DURATION FINGER VELOCITY)",
                         count);
    memset(n, 0, sizeof *n);
    n->source = r->line;
    n->velocity = 80;
    int key;
    if (!sk_note_parse(tok[0], &key))
        return line_fail(r,
                         "note \"%s\" is neither a note name (C4, F#3, Bb5: A-G, # or b, octave "
                         "-1..9) nor a key "
                         "number %d..%d",
                         tok[0], SK_PIANO_KEY_FIRST, SK_PIANO_KEY_LAST);
    if (key < SK_PIANO_KEY_FIRST || key > SK_PIANO_KEY_LAST)
        return line_fail(r, "note \"%s\" (key %d) is not on the piano (%d..%d, A0..C8)", tok[0],
                         key, SK_PIANO_KEY_FIRST, SK_PIANO_KEY_LAST);
    n->key = key;
    double start, duration;
    double limit = SK_MELODY_MAX_SECONDS / seconds_per_unit;
    if (!parse_decimal(tok[1], &start) || start < 0 || start > limit)
        return line_fail(r, "start \"%s\" must be a number in [0, %g]", tok[1], limit);
    if (!parse_decimal(tok[2], &duration) || duration <= 0 || start + duration > limit)
        return line_fail(r, "duration \"%s\" must be a number > 0 that ends by %g", tok[2], limit);
    n->start_s = start * seconds_per_unit;
    n->duration_s = duration * seconds_per_unit;
    if (count >= 4 && strcmp(tok[3], "-") != 0 && !parse_int(tok[3], 1, 5, &n->finger))
        return line_fail(r, "finger \"%s\" must be 1 (thumb) .. 5 (little) or - (automatic)",
                         tok[3]);
    if (count >= 5 && !parse_int(tok[4], 1, 127, &n->velocity))
        return line_fail(r, "velocity \"%s\" must be an integer 1..127", tok[4]);
    return SK_OK;
}

sk_result sk_melody_parse_text(const char *text, size_t length, const char *source_name,
                               sk_melody *out, sk_error *err)
{
    memset(out, 0, sizeof *out);
    text_reader r = {source_name ? source_name : "melody", 0, err};
    if (length > SK_MELODY_MAX_BYTES)
        return sk_fail(err, SK_ERROR_LIMIT, "%s: %zu bytes: a melody file may have at most %u",
                       r.name, length, SK_MELODY_MAX_BYTES);
    /* count candidate lines for the allocation */
    size_t lines = 1;
    for (size_t i = 0; i < length; i++) lines += text[i] == '\n';
    int cap = lines > SK_MELODY_MAX_NOTES ? SK_MELODY_MAX_NOTES : (int)lines;
    sk_result res = sk__melody_alloc(out, cap, r.name, SK_MELODY_FORMAT_TEXT, err);
    if (res != SK_OK) return res;
    double seconds_per_unit = 1.0;
    bool tempo_given = false;
    size_t pos = 0;
    while (pos < length && res == SK_OK) {
        r.line++;
        size_t end = pos;
        while (end < length && text[end] != '\n') end++;
        size_t content = end;
        for (size_t i = pos; i < end; i++) {
            if (text[i] == '\0') {
                res = line_fail(&r, "a NUL byte (column %zu): the file is not text", i - pos + 1);
                break;
            }
            /* a comment starts at a '#' that begins a field (so C#4 is a note) */
            if (text[i] == '#' && content == end &&
                (i == pos || text[i - 1] == ' ' || text[i - 1] == '\t'))
                content = i;
        }
        if (res != SK_OK) break;
        char tok[MAX_FIELDS + 1][MAX_TOKEN];
        bool too_long;
        int count = split(text + pos, content - pos, tok, &too_long);
        pos = end + 1;
        if (count == 0) continue;
        if (too_long) {
            res = line_fail(&r, "a field longer than %d characters", MAX_TOKEN - 1);
            break;
        }
        if (strcmp(tok[0], "bpm") == 0) {
            double bpm;
            if (count != 2 || !parse_decimal(tok[1], &bpm) || bpm < 1 || bpm > 1000)
                res = line_fail(&r, "\"bpm N\" needs one number N in [1, 1000] (beats per minute)");
            else if (tempo_given || out->note_count > 0)
                res = line_fail(&r, "\"bpm\" must come once, before the first note");
            else
                seconds_per_unit = 60.0 / bpm, tempo_given = true;
            continue;
        }
        if (out->note_count >= SK_MELODY_MAX_NOTES) {
            res = line_fail(&r, "more than %d notes", SK_MELODY_MAX_NOTES);
            break;
        }
        res = parse_note(&r, tok, count, seconds_per_unit, &out->notes[out->note_count]);
        if (res == SK_OK) out->note_count++;
    }
    if (res == SK_OK) res = sk_melody_validate(out, err);
    if (res != SK_OK) sk_melody_free(out);
    return res;
}

sk_result sk_melody_write_text(const sk_melody *melody, const char *path, sk_error *err)
{
    sk_atomic_file f;
    sk_result r = sk_atomic_file_open(&f, path, err);
    if (r != SK_OK) return r;
    fprintf(f.fp, "# shitsukan melody: NOTE START DURATION FINGER VELOCITY (seconds; fingers 1 "
                  "thumb .. 5 little)\n");
    if (melody->name[0]) fprintf(f.fp, "# from %s\n", melody->name);
    for (int i = 0; i < melody->note_count; i++) {
        const sk_note *n = &melody->notes[i];
        char name[8], finger[4];
        sk_note_name(n->key, name, sizeof name);
        if (n->finger >= 1 && n->finger <= 5)
            snprintf(finger, sizeof finger, "%d", n->finger);
        else
            snprintf(finger, sizeof finger, "-");
        fprintf(f.fp, "%-4s %.10g %.10g %s %d\n", name, n->start_s, n->duration_s, finger,
                n->velocity);
    }
    return sk_atomic_file_commit(&f, err);
}

sk_result sk_melody_load(const char *path, sk_melody *out, sk_error *err)
{
    memset(out, 0, sizeof *out);
    char *data = NULL;
    size_t size = 0;
    sk_result r = sk_read_file(path, SK_MELODY_MAX_BYTES, &data, &size, err);
    if (r != SK_OK) return r;
    const char *name = strrchr(path, '/');
    name = name ? name + 1 : path;
    if (size >= 4 && memcmp(data, "MThd", 4) == 0)
        r = sk_melody_parse_midi((const uint8_t *)data, size, name, out, err);
    else
        r = sk_melody_parse_text(data, size, name, out, err);
    free(data);
    return r;
}
