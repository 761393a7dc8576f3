/* Fuzz harness for the OpenEXR reader: any input must give SK_OK or an error, never a
 * crash. */
#define _POSIX_C_SOURCE 200809L
#include "fuzz_support.h"

static void read_exr(const char *path)
{
    sk_image image;
    sk_image_metadata meta;
    sk_fuzz_check_image(sk_image_read_exr(&image, path, &meta, NULL), &image, &meta);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    sk_fuzz_with_file(data, size, read_exr);
    return 0;
}
