/* Image resizing as two separable passes (rows, then columns), each output sample a
 * fixed-order weighted sum of source samples: nearest, bilinear (tent between pixel
 * centres, edges clamped) or box (exact area average), so results are deterministic and
 * independent of the thread count. */
#include <stdlib.h>

#include "products/draw/draw_internal.h"

/* The source samples one output index reads along one axis. */
typedef struct resize_taps {
    int *first;     /* first source index per output index */
    int *count;     /* number of taps per output index */
    float *weights; /* max_taps per output index */
    int max_taps;
} resize_taps;

static void taps_free(resize_taps *t)
{
    free(t->first);
    free(t->count);
    free(t->weights);
}

static sk_resize_filter axis_filter(sk_resize_filter filter, int src_n, int dst_n)
{
    if (filter != SK_RESIZE_DEFAULT) return filter;
    return dst_n < src_n ? SK_RESIZE_BOX : SK_RESIZE_BILINEAR;
}

static bool taps_build(resize_taps *t, sk_resize_filter filter, int src_n, int dst_n)
{
    double scale = (double)src_n / (double)dst_n;
    t->max_taps = filter == SK_RESIZE_BOX ? (int)ceil(scale) + 1 : 2;
    t->first = malloc((size_t)dst_n * sizeof *t->first);
    t->count = malloc((size_t)dst_n * sizeof *t->count);
    t->weights = malloc((size_t)dst_n * (size_t)t->max_taps * sizeof *t->weights);
    if (!t->first || !t->count || !t->weights) return false;
    for (int i = 0; i < dst_n; i++) {
        float *w = t->weights + (size_t)i * (size_t)t->max_taps;
        if (filter == SK_RESIZE_NEAREST) {
            int s = (int)floor(((double)i + 0.5) * scale);
            t->first[i] = s < src_n ? s : src_n - 1;
            t->count[i] = 1;
            w[0] = 1.0f;
        } else if (filter == SK_RESIZE_BILINEAR) {
            double c = ((double)i + 0.5) * scale - 0.5;
            double f0 = floor(c);
            double f = c - f0;
            int s0 = (int)f0, s1 = s0 + 1;
            if (s0 < 0) s0 = 0;
            if (s1 < 0) s1 = 0;
            if (s0 > src_n - 1) s0 = src_n - 1;
            if (s1 > src_n - 1) s1 = src_n - 1;
            t->first[i] = s0;
            if (s1 == s0 || f == 0.0) {
                t->count[i] = 1;
                w[0] = 1.0f;
            } else {
                t->count[i] = 2;
                w[0] = (float)(1.0 - f);
                w[1] = (float)f;
            }
        } else {
            /* Box: the output pixel covers source [i scale, (i + 1) scale). */
            double lo = (double)i * scale, hi = ((double)i + 1.0) * scale;
            int s0 = (int)floor(lo);
            int s1 = (int)ceil(hi) - 1;
            if (s1 > src_n - 1) s1 = src_n - 1;
            if (s1 < s0) s1 = s0;
            int n = 0;
            double total = 0.0;
            for (int s = s0; s <= s1 && n < t->max_taps; s++) {
                double a = fmax((double)s, lo), b = fmin((double)s + 1.0, hi);
                double ww = b > a ? b - a : 0.0;
                w[n++] = (float)ww;
                total += ww;
            }
            t->first[i] = s0;
            t->count[i] = n;
            /* Normalised so that a constant image stays exactly constant. */
            for (int k = 0; k < n; k++) w[k] = (float)((double)w[k] / total);
        }
    }
    return true;
}

sk_result sk_image_resize_filter(const sk_image *src, int width, int height,
                                 sk_resize_filter filter, sk_image *out, sk_error *err)
{
    if (!out) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "resize: out is NULL");
    sk_result r = sk__image_check(src, "resize source", err);
    if (r != SK_OK) return r;
    if ((int)filter < 0 || filter > SK_RESIZE_BOX)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "resize filter = %d is out of range [0, %d]",
                       (int)filter, (int)SK_RESIZE_BOX);
    sk_image dst = {0};
    r = sk__image_alloc(&dst, width, height, src->channels, "resized image", err);
    if (r != SK_OK) return r;

    int ch = src->channels;
    /* The intermediate image (new width x old height): both sides are at most
       SK_IMAGE_MAX_DIMENSION, so the product cannot overflow a 64-bit size_t. */
    size_t tmp_bytes = (size_t)width * (size_t)ch * (size_t)src->height * sizeof(float);
    if (tmp_bytes > SK_IMAGE_MAX_BYTES) {
        free(dst.data);
        return sk_fail(err, SK_ERROR_LIMIT,
                       "resize %d x %d to %d x %d needs an intermediate image over the limit of "
                       "%llu bytes",
                       src->width, src->height, width, height,
                       (unsigned long long)SK_IMAGE_MAX_BYTES);
    }
    float *tmp = NULL;
    resize_taps tx = {0}, ty = {0};
    bool ok = (tmp = malloc(tmp_bytes)) != NULL &&
              taps_build(&tx, axis_filter(filter, src->width, width), src->width, width) &&
              taps_build(&ty, axis_filter(filter, src->height, height), src->height, height);
    if (!ok) {
        free(tmp);
        taps_free(&tx);
        taps_free(&ty);
        free(dst.data);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "resize to %d x %d: out of memory", width,
                       height);
    }

    /* Pass 1: every source row resampled to the new width. */
    long long src_h = src->height;
#pragma omp parallel for schedule(static)
    for (long long y = 0; y < src_h; y++) {
        const float *row = sk_image_pixel(src, 0, (int)y);
        float *o = tmp + (size_t)y * (size_t)width * (size_t)ch;
        for (int i = 0; i < width; i++, o += ch) {
            const float *w = tx.weights + (size_t)i * (size_t)tx.max_taps;
            const float *s = row + (size_t)tx.first[i] * (size_t)ch;
            for (int k = 0; k < ch; k++) {
                float sum = 0.0f;
                for (int t = 0; t < tx.count[i]; t++)
                    sum += w[t] * s[(size_t)t * (size_t)ch + (size_t)k];
                o[k] = sum;
            }
        }
    }
    /* Pass 2: columns resampled to the new height. */
    size_t row_floats = (size_t)width * (size_t)ch;
    long long dst_h = height;
#pragma omp parallel for schedule(static)
    for (long long j = 0; j < dst_h; j++) {
        float *o = dst.data + (size_t)j * row_floats;
        const float *w = ty.weights + (size_t)j * (size_t)ty.max_taps;
        const float *base = tmp + (size_t)ty.first[j] * row_floats;
        for (size_t k = 0; k < row_floats; k++) {
            float sum = 0.0f;
            for (int t = 0; t < ty.count[j]; t++) sum += w[t] * base[(size_t)t * row_floats + k];
            o[k] = sum;
        }
    }
    free(tmp);
    taps_free(&tx);
    taps_free(&ty);
    *out = dst;
    return SK_OK;
}

sk_result sk_image_resize(const sk_image *src, int width, int height, sk_image *out, sk_error *err)
{
    return sk_image_resize_filter(src, width, height, SK_RESIZE_DEFAULT, out, err);
}
