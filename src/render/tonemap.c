/* From rendered radiance to files: the EXR keeps linear premultiplied RGBA; the PNG gets
 * exposure, a tone curve and clamping here, and the sRGB transfer curve in the PNG writer
 * (IEC 61966-2-1), so the curve is applied exactly once. */
#include <math.h>
#include <string.h>

#include "render/render_internal.h"

/* Extended Reinhard on luminance (Reinhard et al. 2002, "Photographic Tone Reproduction",
 * eq. 4): L (1 + L / W^2) / (1 + L), W = the luminance mapped to white (0: none). */
static void reinhard(float rgb[3], float white)
{
    float y = 0.2126f * rgb[0] + 0.7152f * rgb[1] + 0.0722f * rgb[2];
    if (!(y > 0)) return;
    float mapped = white > 0 ? y * (1.0f + y / (white * white)) / (1.0f + y) : y / (1.0f + y);
    float k = mapped / y;
    for (int c = 0; c < 3; c++) rgb[c] *= k;
}

/* The ACES reference tone curve fitted by a rational function (K. Narkowicz, "ACES Filmic
 * Tone Mapping Curve", 2015), applied per channel. */
static float filmic(float x) { return x * (2.51f * x + 0.03f) / (x * (2.43f * x + 0.59f) + 0.14f); }

sk_result sk_render_tonemap(const sk_image *linear, const sk_render_film_desc *film,
                            sk_image *display, sk_error *err)
{
    if (linear->channels != 4)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "a rendered image has 4 channels, not %d",
                       linear->channels);
    int channels = film->opaque ? 3 : 4;
    sk_result r = sk_image_create(display, linear->width, linear->height, channels, err);
    if (r != SK_OK) return r;
    float scale = exp2f(film->exposure);
    size_t n = (size_t)linear->width * (size_t)linear->height;
    for (size_t i = 0; i < n; i++) {
        const float *src = linear->data + 4 * i;
        float *dst = display->data + (size_t)channels * i;
        float alpha = film->opaque ? 1.0f : sk_clampf(src[3], 0.0f, 1.0f);
        float rgb[3];
        for (int c = 0; c < 3; c++) {
            float v = alpha > 0 ? src[c] / alpha * scale : 0.0f;
            rgb[c] = isfinite(v) && v > 0 ? v : 0.0f;
        }
        if (film->tonemap == SK_RENDER_TONEMAP_REINHARD) reinhard(rgb, film->white);
        if (film->tonemap == SK_RENDER_TONEMAP_FILMIC)
            for (int c = 0; c < 3; c++) rgb[c] = filmic(rgb[c]);
        for (int c = 0; c < 3; c++) dst[c] = sk_clampf(rgb[c], 0.0f, 1.0f);
        if (channels == 4) dst[3] = alpha;
    }
    return SK_OK;
}

sk_result sk_render_write(const sk_image *linear, const sk_render_film_desc *film, const char *path,
                          const sk_image_metadata *metadata, sk_error *err)
{
    sk_result r;
    sk_image out = {0};
    if (sk__has_extension(path, ".png")) {
        if ((r = sk_render_tonemap(linear, film, &out, err)) != SK_OK) return r;
        sk_png_write_desc desc = {
            .bit_depth = 8, .encoding = SK_PNG_ENCODING_SRGB, .metadata = metadata};
        r = sk_image_write_png(&out, path, &desc, err);
    } else if (sk__has_extension(path, ".exr")) {
        const sk_image *src = linear;
        if (film->opaque) { /* alpha is 1 everywhere: plain RGB */
            if ((r = sk_image_create(&out, linear->width, linear->height, 3, err)) != SK_OK)
                return r;
            size_t n = (size_t)linear->width * (size_t)linear->height;
            for (size_t i = 0; i < n; i++)
                memcpy(out.data + 3 * i, linear->data + 4 * i, 3 * sizeof(float));
            src = &out;
        }
        sk_exr_write_desc desc = {.metadata = metadata};
        r = sk_image_write_exr(src, path, &desc, err);
    } else {
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "output \"%s\": unknown image type (use .png or .exr)", path);
    }
    sk_image_free(&out);
    return r;
}
