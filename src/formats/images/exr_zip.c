/* OpenEXR ZIP / ZIPS chunk compression with libdeflate (the library's own uses zlib, and
 * is several times slower). The format: the chunk's bytes split into the even-indexed
 * ones followed by the odd-indexed ones, each byte after the first replaced by its
 * difference from the one before plus 128 (mod 256), the result as a zlib stream; a chunk
 * that does not get smaller is stored as it is (readers tell by its size). */
#include <libdeflate.h>
#include <stdlib.h>
#include <string.h>

#include "formats/images/exr_internal.h"

exr_result_t sk__exr_zip_compress(exr_encode_pipeline_t *encode)
{
    sk__exr_zip *z = encode->encoding_user_data;
    const uint8_t *in = encode->packed_buffer;
    size_t n = (size_t)encode->packed_bytes;
    if (z->scratch_size < n) {
        uint8_t *grown = realloc(z->scratch, n);
        if (!grown) return EXR_ERR_OUT_OF_MEMORY;
        z->scratch = grown;
        z->scratch_size = n;
    }
    uint8_t *s = z->scratch;
    size_t half = (n + 1) / 2;
    for (size_t i = 0; i < half; i++) s[i] = in[2 * i];
    for (size_t i = 0; i < n / 2; i++) s[half + i] = in[2 * i + 1];
    for (size_t i = n - 1; i > 0; i--) s[i] = (uint8_t)(s[i] - s[i - 1] + 128u);
    size_t bound = libdeflate_zlib_compress_bound(z->compressor, n);
    uint8_t *out = malloc(bound > n ? bound : n);
    if (!out) return EXR_ERR_OUT_OF_MEMORY;
    size_t m = libdeflate_zlib_compress(z->compressor, s, n, out, bound);
    if (m == 0 || m >= n) {
        memcpy(out, in, n);
        m = n;
    }
    free(z->chunk);
    z->chunk = out;
    z->chunk_size = m;
    /* the pipeline points at the chunk without owning it (an allocation size of 0 is how
       it marks a borrowed buffer) */
    encode->compressed_buffer = out;
    encode->compressed_alloc_size = 0;
    encode->compressed_bytes = m;
    return EXR_ERR_SUCCESS;
}
