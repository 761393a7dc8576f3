/* Fuzz harness for the PNG reader: any input must give SK_OK or an error, never a crash
 * (both decodings, with metadata). */
#define _POSIX_C_SOURCE 200809L
#include "fuzz_support.h"

static void read_png(const char *path)
{
    for (int linear = 0; linear < 2; linear++) {
        sk_image image;
        sk_image_metadata meta;
        int depth = 0;
        sk_png_read_desc desc = {linear ? SK_PNG_ENCODING_LINEAR : SK_PNG_ENCODING_SRGB};
        sk_result r = sk_image_read_png(&image, path, &desc, &meta, &depth, NULL);
        if (r == SK_OK && (depth < 1 || depth > 16)) abort();
        sk_fuzz_check_image(r, &image, &meta);
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    sk_fuzz_with_file(data, size, read_png);
    return 0;
}
