/* Colour compositing for the draw module: a colour prepared for an image's channel
 * layout, and the straight-alpha "over" operator (Porter & Duff 1984) applied per pixel
 * with the rasterizer's coverage as an extra weight. */
#include "products/draw/draw_internal.h"

bool sk__image_valid(const sk_image *img)
{
    return img && img->data && img->channels >= 1 && img->channels <= 4 && img->width > 0 &&
           img->height > 0;
}

sk__clip sk__clip_image(const sk_image *img)
{
    sk__clip c = {0, 0, img->width, img->height};
    return c;
}

sk__clip sk__clip_bounds(sk__clip clip, double x0, double y0, double x1, double y1)
{
    sk__clip out = clip;
    /* Pixels touched by [x0, x1]: columns floor(x0) .. ceil(x1) - 1, compared in double
       before any conversion so that huge coordinates cannot overflow an int. */
    double fx0 = floor(x0), fy0 = floor(y0), cx1 = ceil(x1), cy1 = ceil(y1);
    if (!(fx0 < (double)clip.x1 && cx1 > (double)clip.x0 && fy0 < (double)clip.y1 &&
          cy1 > (double)clip.y0)) {
        out.x1 = out.x0;
        out.y1 = out.y0;
        return out;
    }
    if (fx0 > (double)clip.x0) out.x0 = (int)fx0;
    if (fy0 > (double)clip.y0) out.y0 = (int)fy0;
    if (cx1 < (double)clip.x1) out.x1 = (int)cx1;
    if (cy1 < (double)clip.y1) out.y1 = (int)cy1;
    return out;
}

void sk__color_to_layout(sk_color c, int channels, float v[4])
{
    float a = c.a < 0.0f ? 0.0f : (c.a > 1.0f ? 1.0f : c.a);
    if (channels <= 2) {
        v[0] = sk__luminance(c);
        v[1] = a;
        v[2] = 0.0f;
    } else {
        v[0] = c.r;
        v[1] = c.g;
        v[2] = c.b;
    }
    v[3] = a;
}

bool sk__paint_init(sk__paint *paint, sk_image *img, sk_color c)
{
    if (!sk__image_valid(img) || !sk__color_finite(c) || !(c.a > 0.0f)) return false;
    paint->img = img;
    paint->channels = img->channels;
    sk__color_to_layout(c, img->channels, paint->value);
    paint->alpha = paint->value[3];
    return true;
}

/* The span loop for a fixed channel count, so the compiler unrolls the channels. */
#define SK__PAINT_SPAN_LOOP(CH)                                                                    \
    for (int i = 0; i < n; i++, px += (CH)) {                                                      \
        float w = coverage[i];                                                                     \
        if (w > 0.0f) sk__composite_over(px, (CH), paint->value, alpha *(w < 1.0f ? w : 1.0f));    \
    }

void sk__paint_span(const sk__paint *paint, int x, int y, int n, const float *coverage)
{
    float *px = sk_image_pixel(paint->img, x, y);
    float alpha = paint->alpha;
    switch (paint->channels) {
    case 1:
        SK__PAINT_SPAN_LOOP(1) break;
    case 2:
        SK__PAINT_SPAN_LOOP(2) break;
    case 3:
        SK__PAINT_SPAN_LOOP(3) break;
    default:
        SK__PAINT_SPAN_LOOP(4) break;
    }
}

void sk__paint_span_fn(void *user, int x, int y, int n, const float *coverage)
{
    sk__paint_span((const sk__paint *)user, x, y, n, coverage);
}
