/* Blits: copying or compositing one image into another at an integer offset, with
 * channel conversion (grey <-> RGB by luminance, alpha added or dropped). */
#include "products/draw/draw_internal.h"

#define SK__BLIT_PARALLEL_PIXELS (1 << 18)

/* A pixel in any layout as straight RGBA. */
static inline void to_rgba(const float *px, int channels, float rgba[4])
{
    switch (channels) {
    case 1:
        rgba[0] = rgba[1] = rgba[2] = px[0];
        rgba[3] = 1.0f;
        break;
    case 2:
        rgba[0] = rgba[1] = rgba[2] = px[0];
        rgba[3] = px[1];
        break;
    case 3:
        rgba[0] = px[0];
        rgba[1] = px[1];
        rgba[2] = px[2];
        rgba[3] = 1.0f;
        break;
    default:
        rgba[0] = px[0];
        rgba[1] = px[1];
        rgba[2] = px[2];
        rgba[3] = px[3];
        break;
    }
}

/* Straight RGBA into a layout's values; a grey source keeps its exact grey. */
static inline void from_rgba(const float rgba[4], bool src_grey, int channels, float value[4])
{
    sk__color_to_layout(sk_rgba(rgba[0], rgba[1], rgba[2], rgba[3]), channels, value);
    if (src_grey && channels <= 2) value[0] = rgba[0];
}

void sk_draw_blit_mode(sk_image *dst, const sk_image *src, int x, int y, sk_blit_mode mode)
{
    if (!sk__image_valid(dst) || !sk__image_valid(src)) return;
    if ((int)mode < 0 || mode > SK_BLIT_OVER) return;
    bool src_alpha = src->channels == 2 || src->channels == 4;
    if (mode == SK_BLIT_DEFAULT) mode = src_alpha ? SK_BLIT_OVER : SK_BLIT_COPY;
    /* Overlap of src placed at (x, y) with dst, in long long to avoid int overflow. */
    long long x0 = x > 0 ? x : 0, y0 = y > 0 ? y : 0;
    long long x1 = (long long)x + src->width, y1 = (long long)y + src->height;
    if (x1 > dst->width) x1 = dst->width;
    if (y1 > dst->height) y1 = dst->height;
    if (x0 >= x1 || y0 >= y1) return;
    int dch = dst->channels, sch = src->channels;
    bool src_grey = sch <= 2;
    bool dst_alpha = dch == 2 || dch == 4;
    int colors = dst_alpha ? dch - 1 : dch;
    size_t pixels = (size_t)(x1 - x0) * (size_t)(y1 - y0);
#pragma omp parallel for schedule(static) if (pixels >= SK__BLIT_PARALLEL_PIXELS)
    for (long long dy = y0; dy < y1; dy++) {
        const float *sp = sk_image_pixel(src, (int)(x0 - x), (int)(dy - y));
        float *dp = sk_image_pixel(dst, (int)x0, (int)dy);
        for (long long dx = x0; dx < x1; dx++, sp += sch, dp += dch) {
            float rgba[4], value[4];
            to_rgba(sp, sch, rgba);
            from_rgba(rgba, src_grey, dch, value);
            float a = value[3]; /* clamped to [0, 1] */
            if (mode == SK_BLIT_OVER) {
                if (a > 0.0f) sk__composite_over(dp, dch, value, a);
            } else {
                for (int k = 0; k < colors; k++) dp[k] = value[k];
                if (dst_alpha) dp[colors] = a;
            }
        }
    }
}

void sk_draw_blit(sk_image *dst, const sk_image *src, int x, int y)
{
    sk_draw_blit_mode(dst, src, x, y, SK_BLIT_DEFAULT);
}
