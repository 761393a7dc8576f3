/* Image textures: PNG (decoded from sRGB for colour, linearly for normal maps) or EXR,
 * sampled bilinearly with repeat wrapping; texture coordinate t runs up the image. */
#include <math.h>
#include <string.h>

#include "render/render_internal.h"

sk_result sk__texture_load(sk__texture *tex, const char *path, bool srgb, sk_error *err)
{
    memset(tex, 0, sizeof *tex);
    if (sk__has_extension(path, ".png")) {
        sk_png_read_desc desc = {.encoding = srgb ? SK_PNG_ENCODING_SRGB : SK_PNG_ENCODING_LINEAR};
        return sk_image_read_png(&tex->image, path, &desc, NULL, NULL, err);
    }
    if (sk__has_extension(path, ".exr")) return sk_image_read_exr(&tex->image, path, NULL, err);
    return sk_fail(err, SK_ERROR_UNSUPPORTED, "\"%s\" is neither a .png nor an .exr image", path);
}

static void texel(const sk_image *img, int x, int y, float out[4])
{
    const float *p = sk_image_pixel(img, x, y);
    switch (img->channels) {
    case 1:
        out[0] = out[1] = out[2] = p[0], out[3] = 1.0f;
        break;
    case 2:
        out[0] = out[1] = out[2] = p[0], out[3] = p[1];
        break;
    case 3:
        out[0] = p[0], out[1] = p[1], out[2] = p[2], out[3] = 1.0f;
        break;
    default:
        out[0] = p[0], out[1] = p[1], out[2] = p[2], out[3] = p[3];
        break;
    }
}

void sk__texture_sample(const sk__texture *tex, sk_vec2f st, float out[4])
{
    const sk_image *img = &tex->image;
    float s = st.x - floorf(st.x), t = st.y - floorf(st.y);
    float x = s * (float)img->width - 0.5f, y = (1.0f - t) * (float)img->height - 0.5f;
    float fx = floorf(x), fy = floorf(y);
    float ax = x - fx, ay = y - fy;
    int x0 = sk_imodpos((int)fx, img->width), y0 = sk_imodpos((int)fy, img->height);
    int x1 = x0 + 1 == img->width ? 0 : x0 + 1, y1 = y0 + 1 == img->height ? 0 : y0 + 1;
    float a[4], b[4], c[4], d[4];
    texel(img, x0, y0, a);
    texel(img, x1, y0, b);
    texel(img, x0, y1, c);
    texel(img, x1, y1, d);
    for (int k = 0; k < 4; k++) {
        float top = a[k] + (b[k] - a[k]) * ax, bottom = c[k] + (d[k] - c[k]) * ax;
        out[k] = top + (bottom - top) * ay;
    }
}
