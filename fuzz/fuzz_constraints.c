/* Fuzz harness: hand constraint sets (JSON rows of A, b, W; thesis 3.2.2). */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#include "shitsukan/hand.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    sk_hand_skeleton skel;
    if (sk_hand_skeleton_init(&skel, NULL, NULL) != SK_OK) abort();
    sk_hand_constraints *c = malloc(sizeof *c);
    if (!c) abort();
    sk_hand_constraints_parse((const char *)data, size, "fuzz", &skel, c, NULL);
    free(c);
    return 0;
}
