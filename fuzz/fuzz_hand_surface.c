/* Fuzz harness: the hand surface's data file readers (flesh sizes). */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#include "shitsukan/hand.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const char *text = (const char *)data;
    sk_hand_flesh flesh;
    sk_hand_flesh_parse(text, size, "fuzz", &flesh, NULL);
    return 0;
}
