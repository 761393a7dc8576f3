/* Fuzz harness: the hand module's file parsers (constraint sets, anatomy, animation
 * keys, joint-angle CSV) on the same input. BVH has its own harness (fuzz_bvh.c). */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#include "shitsukan/hand.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const char *text = (const char *)data;
    sk_hand_skeleton skel;
    if (sk_hand_skeleton_init(&skel, NULL, NULL) != SK_OK) abort();
    sk_hand_constraints *c = malloc(sizeof *c);
    sk_hand_animation *a = malloc(sizeof *a);
    if (!c || !a) abort();
    sk_hand_constraints_parse(text, size, "fuzz", &skel, c, NULL);
    sk_hand_anatomy anatomy;
    if (sk_hand_anatomy_parse(text, size, "fuzz", &anatomy, NULL) == SK_OK) {
        sk_hand_skeleton_desc d = {0};
        d.anatomy = &anatomy;
        sk_hand_skeleton_init(&skel, &d, NULL);
    }
    if (sk_hand_animation_parse(text, size, "fuzz", a, NULL) == SK_OK) {
        sk_hand_input in;
        int frames = sk_hand_animation_frame_count(a);
        for (int f = 0; f < frames && f < 64; f++) sk_hand_animation_input(a, f, &in);
    }
    sk_hand_samples s;
    if (sk_hand_samples_parse(text, size, "fuzz", &s, NULL) == SK_OK) sk_hand_samples_free(&s);
    free(c);
    free(a);
    return 0;
}
