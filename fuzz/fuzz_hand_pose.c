/* Fuzz harness: hand pose files (the "dofs" object of sk_hand_pose_write_json,
 * src/formats/hand/pose_read.c). */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#include "shitsukan/hand.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    sk_hand_skeleton skel;
    if (sk_hand_skeleton_init(&skel, NULL, NULL) != SK_OK) abort();
    double dofs[SK_HAND_DOF_COUNT];
    sk_hand_pose_parse((const char *)data, size, "fuzz", &skel, dofs, NULL);
    return 0;
}
