/* Fuzz harness: the showcase's melody text reader; a parsed melody is fingered and
 * written back as MIDI bytes through the MIDI reader. */
#include <stddef.h>
#include <stdint.h>

#include "shitsukan/showcase.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    sk_melody m;
    if (sk_melody_parse_text((const char *)data, size, "fuzz", &m, NULL) != SK_OK) return 0;
    if (m.note_count <= 64) sk_melody_choose_fingers(&m, NULL, NULL, NULL, NULL);
    sk_melody_free(&m);
    return 0;
}
