/* Fuzz harness for the DEFLATE block walk that joins compressed PNG strips: any input
 * must walk or be refused without a crash, and a stream that walks, made continuable and
 * closed by a final empty block, must decompress to what it did before. */
#define _POSIX_C_SOURCE 200809L
#include <libdeflate.h>
#include <stdlib.h>
#include <string.h>

#include "formats/images/deflate_join.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    size_t header, end;
    if (!sk__deflate_stream_end(data, size, &header, &end)) return 0;
    if (header >= end || end > 8 * size) abort();
    enum { OUT = 1 << 20 };
    uint8_t *copy = malloc(size + 10), *a = malloc(OUT), *b = malloc(OUT);
    struct libdeflate_decompressor *dec = libdeflate_alloc_decompressor();
    if (!copy || !a || !b || !dec) abort();
    memcpy(copy, data, size);
    size_t n = size, na = 0, nb = 0;
    bool before = libdeflate_deflate_decompress(dec, data, size, a, OUT, &na) == LIBDEFLATE_SUCCESS;
    if (sk__deflate_make_continuable(copy, &n)) {
        static const uint8_t close_block[5] = {0x01, 0x00, 0x00, 0xff, 0xff};
        memcpy(copy + n, close_block, sizeof close_block);
        bool after =
            libdeflate_deflate_decompress(dec, copy, n + 5, b, OUT, &nb) == LIBDEFLATE_SUCCESS;
        if (before && (!after || na != nb || memcmp(a, b, na) != 0)) abort();
    }
    libdeflate_free_decompressor(dec);
    free(copy);
    free(a);
    free(b);
    return 0;
}
