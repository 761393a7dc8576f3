/* Fuzz harness: the BVH reader of the hand module; a parsed BVH is also evaluated. (The
 * hand's other readers have their own harnesses: fuzz_constraints, fuzz_anatomy,
 * fuzz_animation, fuzz_hand_samples.) */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#include "shitsukan/hand.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const char *text = (const char *)data;
    sk_bvh *b = malloc(sizeof *b);
    if (!b) abort();
    if (sk_bvh_parse(text, size, "fuzz", b, NULL) == SK_OK) {
        sk_vec3d *pos = malloc(sizeof(sk_vec3d) * SK_BVH_MAX_JOINTS);
        if (pos && b->frame_count > 0) sk_bvh_positions(b, 0, pos);
        free(pos);
        sk_bvh_free(b);
    }
    free(b);
    return 0;
}
