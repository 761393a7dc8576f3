/* Fuzz harness: joint-angle sample files (CSV with a header of DOF names); accepted
 * samples are within the documented range. */
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#include "shitsukan/hand.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    sk_hand_samples s;
    if (sk_hand_samples_parse((const char *)data, size, "fuzz", &s, NULL) != SK_OK) return 0;
    for (int d = 0; d < SK_HAND_DOF_COUNT; d++)
        for (int i = 0; s.present[d] && i < s.count; i++)
            if (!isfinite(s.column[d][i])) abort();
    sk_hand_samples_free(&s);
    return 0;
}
