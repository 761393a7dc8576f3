/* A 2D piecewise-constant distribution over [0, 1)^2 for importance sampling an image:
 * the marginal density of the rows and, per row, the conditional density of its columns,
 * each sampled by inverting its tabulated CDF (Pharr, Jakob & Humphreys, PBRT 3rd ed.
 * sec. 13.6.5 "Piecewise-Constant 2D Distributions", Distribution1D / Distribution2D). */
#include <stdlib.h>
#include <string.h>

#include "render/render_internal.h"

/* CDF of n values: cdf[0] = 0 .. cdf[n] = 1; returns the integral (mean of func). A row
 * of zeros gets a uniform CDF, as in PBRT. */
static float build_cdf(const float *func, int n, float *cdf)
{
    cdf[0] = 0;
    for (int i = 0; i < n; i++) cdf[i + 1] = cdf[i] + func[i] / (float)n;
    float integral = cdf[n];
    for (int i = 1; i <= n; i++) cdf[i] = integral > 0 ? cdf[i] / integral : (float)i / (float)n;
    return integral;
}

/* Largest i in [0, n) with cdf[i] <= u (binary search). */
static int find_interval(const float *cdf, int n, float u)
{
    int lo = 0, hi = n;
    while (hi - lo > 1) {
        int mid = (lo + hi) / 2;
        if (cdf[mid] <= u)
            lo = mid;
        else
            hi = mid;
    }
    return lo;
}

sk_result sk__distribution2d_build(sk__distribution2d *d, const float *func, int w, int h,
                                   sk_error *err)
{
    memset(d, 0, sizeof *d);
    size_t n = (size_t)w * (size_t)h;
    d->func = malloc(n * sizeof *d->func);
    d->conditional = malloc((size_t)h * (size_t)(w + 1) * sizeof *d->conditional);
    d->row_integral = malloc((size_t)h * sizeof *d->row_integral);
    d->marginal = malloc((size_t)(h + 1) * sizeof *d->marginal);
    if (!d->func || !d->conditional || !d->row_integral || !d->marginal) {
        sk__distribution2d_free(d);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for an environment of %d x %d",
                       w, h);
    }
    d->width = w, d->height = h;
    memcpy(d->func, func, n * sizeof *d->func);
    for (int y = 0; y < h; y++)
        d->row_integral[y] =
            build_cdf(d->func + (size_t)y * w, w, d->conditional + (size_t)y * (w + 1));
    d->integral = build_cdf(d->row_integral, h, d->marginal);
    return SK_OK;
}

void sk__distribution2d_free(sk__distribution2d *d)
{
    free(d->func);
    free(d->conditional);
    free(d->row_integral);
    free(d->marginal);
    memset(d, 0, sizeof *d);
}

/* Samples one piecewise-constant 1D distribution: the continuous position in [0, 1) and
 * the cell index. */
static float sample_1d(const float *cdf, int n, float u, int *cell)
{
    int i = find_interval(cdf, n, u);
    float width = cdf[i + 1] - cdf[i];
    float du = width > 0 ? (u - cdf[i]) / width : 0.5f;
    *cell = i;
    float x = ((float)i + du) / (float)n;
    return x < 1.0f ? x : 0x1.fffffep-1f;
}

sk_vec2f sk__distribution2d_sample(const sk__distribution2d *d, sk_vec2f u, float *pdf)
{
    int row, col;
    float v = sample_1d(d->marginal, d->height, u.y, &row);
    float x = sample_1d(d->conditional + (size_t)row * (d->width + 1), d->width, u.x, &col);
    *pdf = d->integral > 0 ? d->func[(size_t)row * d->width + col] / d->integral : 0.0f;
    return sk_v2f(x, v);
}

float sk__distribution2d_pdf(const sk__distribution2d *d, sk_vec2f uv)
{
    int x = (int)(uv.x * (float)d->width), y = (int)(uv.y * (float)d->height);
    x = x < 0 ? 0 : x >= d->width ? d->width - 1 : x;
    y = y < 0 ? 0 : y >= d->height ? d->height - 1 : y;
    return d->integral > 0 ? d->func[(size_t)y * d->width + x] / d->integral : 0.0f;
}
