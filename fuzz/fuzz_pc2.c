/* Fuzz harness: the PC2 point-cache reader (include/shitsukan/pointcache.h). A parsed
 * cache must hold finite values and counts that match its size. */
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#include "shitsukan/pointcache.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    sk_pc2 pc;
    if (sk_pc2_parse(data, size, "fuzz", &pc, NULL) == SK_OK) {
        size_t values = (size_t)pc.points * 3 * (size_t)pc.samples;
        if (pc.points < 1 || pc.samples < 0 || (values && !pc.xyz) ||
            values * 4 + SK_PC2_HEADER_BYTES != size)
            abort();
        for (size_t i = 0; i < values; i++)
            if (!isfinite(pc.xyz[i])) abort();
        sk_pc2_free(&pc);
    } else if (pc.xyz) {
        abort();
    }
    return 0;
}
