/* An image written in the format its file name asks for (.png, .exr). */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include "base/image_internal.h"
#include "base/io_internal.h"
#include "shitsukan/image.h"

sk_result sk_image_write_auto(const sk_image *image, const char *path,
                              const sk_image_metadata *metadata, sk_error *err)
{
    if (!path) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "output path is NULL");
    const char *ext = sk__path_extension(path);
    if (strcasecmp(ext, ".png") == 0) {
        sk_png_write_desc desc = {0};
        desc.metadata = metadata;
        return sk_image_write_png(image, path, &desc, err);
    }
    if (strcasecmp(ext, ".exr") == 0) {
        sk_exr_write_desc desc = {0};
        desc.metadata = metadata;
        return sk_image_write_exr(image, path, &desc, err);
    }
    return sk_fail(err, SK_ERROR_UNSUPPORTED,
                   "%s: unknown image extension \"%s\" (accepted: .png, .exr)", path, ext);
}
