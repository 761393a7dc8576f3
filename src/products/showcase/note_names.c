/* Note names of scientific pitch notation (C4 = MIDI 60, A4 = 69) and the black keys. */
#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "shitsukan/showcase.h"

static const int letter_semitone[7] = {9, 11, 0, 2, 4, 5, 7}; /* A B C D E F G */

bool sk_note_parse(const char *text, int *key)
{
    if (!text || !*text) return false;
    if (isdigit((unsigned char)text[0])) {
        char *end = NULL;
        long v = strtol(text, &end, 10);
        if (*end || v < 0 || v > 127) return false;
        *key = (int)v;
        return true;
    }
    int c = toupper((unsigned char)text[0]);
    if (c < 'A' || c > 'G') return false;
    int semitone = letter_semitone[c - 'A'];
    const char *p = text + 1;
    for (int n = 0; n < 2 && (*p == '#' || *p == 'b'); n++, p++) semitone += *p == '#' ? 1 : -1;
    int sign = 1;
    if (*p == '-') sign = -1, p++;
    if (!isdigit((unsigned char)*p) || p[1] != '\0') return false;
    int octave = sign * (*p - '0');
    if (octave < -1 || octave > 9) return false;
    int v = (octave + 1) * 12 + semitone;
    if (v < 0 || v > 127) return false;
    *key = v;
    return true;
}

void sk_note_name(int key, char *out, size_t size)
{
    static const char *names[12] = {"C",  "C#", "D",  "D#", "E",  "F",
                                    "F#", "G",  "G#", "A",  "A#", "B"};
    if (key < 0 || key > 127) {
        snprintf(out, size, "?");
        return;
    }
    snprintf(out, size, "%s%d", names[key % 12], key / 12 - 1);
}

bool sk_note_is_black(int key)
{
    int s = ((key % 12) + 12) % 12;
    return s == 1 || s == 3 || s == 6 || s == 8 || s == 10;
}
