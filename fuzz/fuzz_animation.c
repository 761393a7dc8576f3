/* Fuzz harness: hand animation files (keys of pins and torques); an accepted animation is
 * interpolated over its first frames. */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#include "shitsukan/hand.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    sk_hand_animation *a = malloc(sizeof *a);
    if (!a) abort();
    if (sk_hand_animation_parse((const char *)data, size, "fuzz", a, NULL) == SK_OK) {
        sk_hand_input in;
        int frames = sk_hand_animation_frame_count(a);
        if (frames < 1) abort();
        for (int f = 0; f < frames && f < 64; f++) sk_hand_animation_input(a, f, &in);
        sk_hand_animation_input(a, frames - 1, &in);
    }
    free(a);
    return 0;
}
