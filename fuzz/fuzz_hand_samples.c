/* Fuzz harness: the joint-angle samples CSV reader with its options (units, a group
 * column, ignored columns). A parsed set must hold consistent groups and finite values. */
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#include "shitsukan/hand.h"

static void check(const sk_hand_samples *s)
{
    if (s->count < 1) abort();
    for (int d = 0; d < SK_HAND_DOF_COUNT; d++) {
        if (s->present[d] != (s->column[d] != NULL)) abort();
        for (int i = 0; s->present[d] && i < s->count; i++)
            if (!isfinite(s->column[d][i])) abort();
    }
    for (int i = 0; s->group && i < s->count; i++)
        if (s->group[i] < 0 || s->group[i] >= s->group_count) abort();
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const sk_hand_samples_desc descs[] = {
        {0},
        {.units = SK_HAND_UNIT_RAD, .group_column = "person", .ignore_columns = "trial"},
        {.group_column = "trial", .ignore_columns = "person,frame"},
    };
    for (size_t k = 0; k < sizeof descs / sizeof descs[0]; k++) {
        sk_hand_samples s;
        if (sk_hand_samples_parse_desc((const char *)data, size, "fuzz", &descs[k], &s, NULL) ==
            SK_OK) {
            check(&s);
            sk_hand_samples_free(&s);
        } else if (s.count != 0 || s.group) {
            abort();
        }
    }
    return 0;
}
