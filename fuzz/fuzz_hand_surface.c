/* Fuzz harness: the hand surface's data file readers (flesh sizes, pose files). */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#include "shitsukan/hand.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const char *text = (const char *)data;
    sk_hand_flesh flesh;
    sk_hand_flesh_parse(text, size, "fuzz", &flesh, NULL);
    sk_hand_skeleton skel;
    if (sk_hand_skeleton_init(&skel, NULL, NULL) != SK_OK) abort();
    double q[SK_HAND_DOF_COUNT];
    if (sk_hand_pose_parse(text, size, "fuzz", &skel, q, NULL) == SK_OK) {
        sk_hand_frames fr;
        sk_hand_forward(&skel, q, &fr);
    }
    return 0;
}
