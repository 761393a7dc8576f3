/* Fuzz harness: hand anatomy files (limits, relaxed posture, proportions); an accepted
 * anatomy must build a skeleton. */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#include "shitsukan/hand.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    sk_hand_anatomy anatomy;
    if (sk_hand_anatomy_parse((const char *)data, size, "fuzz", &anatomy, NULL) == SK_OK) {
        sk_hand_skeleton skel;
        sk_hand_skeleton_desc d = {0};
        d.anatomy = &anatomy;
        sk_hand_skeleton_init(&skel, &d, NULL);
    }
    return 0;
}
