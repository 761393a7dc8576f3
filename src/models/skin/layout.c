/* Centre points of one level (paper parameter 1, sec. 4.2 (1)): triangular lattice, square
 * lattice or uniform random points, with uniform or normal lattice jitter.
 *
 * The points must repeat with the tile (seamless maps): a lattice is fitted to the torus
 * by rounding. With P the torus periods in pre-stretch space and T the ideal lattice
 * basis, K = round(T^-1 P) is an integer matrix, and the lattice B = P K^-1 contains the
 * torus lattice, so it wraps exactly; B differs from T by about one part in the number of
 * cells across. Its |det K| points are the integer vectors v with K^-1 v in [0, 1)^2. */
#include <math.h>
#include <stdlib.h>

#include "models/skin/skin_internal.h"

#define SK__SALT_LAYOUT 0x4c41594fULL /* "LAYO" */

/* Chooses K near kf with a non-zero determinant (floor/ceil of each entry). */
static void fit_lattice(double kf[2][2], long long k[2][2])
{
    double best = INFINITY;
    k[0][0] = 1, k[0][1] = 0, k[1][0] = 0, k[1][1] = 1;
    for (int mask = 0; mask < 16; mask++) {
        long long c[2][2];
        double e = 0;
        for (int i = 0; i < 4; i++) {
            double v = kf[i / 2][i % 2];
            double r = ((mask >> i) & 1) ? ceil(v) : floor(v);
            c[i / 2][i % 2] = (long long)r;
            e += (r - v) * (r - v);
        }
        if (c[0][0] * c[1][1] - c[0][1] * c[1][0] == 0) continue;
        if (e < best) {
            best = e;
            for (int i = 0; i < 4; i++) k[i / 2][i % 2] = c[i / 2][i % 2];
        }
    }
}

static void jitter_offset(const sk_skin_level *lv, sk_rng *rng, double *dx, double *dy)
{
    double r = lv->jitter_rate * lv->spacing_mm;
    *dx = *dy = 0.0;
    if (r <= 0.0) return;
    if (lv->jitter == SK_SKIN_JITTER_NORMAL) {
        for (int tries = 0; tries < 32; tries++) {
            double x = sk_rng_normal(rng) * 0.5 * r, y = sk_rng_normal(rng) * 0.5 * r;
            if (x * x + y * y <= r * r) {
                *dx = x, *dy = y;
                return;
            }
        }
        return; /* (probability 0.135^32) */
    }
    double rad = r * sqrt(sk_rng_uniform(rng)), ang = 2.0 * SK_PI * sk_rng_uniform(rng);
    *dx = rad * cos(ang);
    *dy = rad * sin(ang);
}

sk_result sk__layout_points(const sk_skin *skin, int level, double **xy_out, uint32_t *count_out,
                            sk_error *err)
{
    const sk_skin_level *lv = &skin->desc.levels[level];
    const sk__level *L = &skin->levels[level];
    double w = skin->period[0], h = skin->period[1];
    double s = lv->spacing_mm;
    /* Torus periods in pre-stretch space: columns of M^-1 diag(w, h). */
    double p[2][2] = {{L->minv[0][0] * w, L->minv[0][1] * h},
                      {L->minv[1][0] * w, L->minv[1][1] * h}};
    double area = fabs(p[0][0] * p[1][1] - p[0][1] * p[1][0]);
    uint64_t seed = skin->desc.seed;
    *xy_out = NULL;
    *count_out = 0;

    if (lv->layout == SK_SKIN_LAYOUT_RANDOM) {
        double n = floor(area / (0.5 * sqrt(3.0) * s * s) + 0.5);
        if (n > SK_SKIN_MAX_CELLS)
            return sk_fail(err, SK_ERROR_LIMIT,
                           "levels[%d]: %.0f random centre points; at most %d cells are "
                           "supported (raise levels[%d].spacing_mm or reduce size_mm)",
                           level, n, SK_SKIN_MAX_CELLS, level);
        uint32_t count = n < 1 ? 1 : (uint32_t)n;
        double *xy = malloc(sizeof(double) * 2 * count);
        if (!xy) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for centre points");
        for (uint32_t i = 0; i < count; i++) {
            sk_rng rng = sk_rng_make(seed, SK__SALT_LAYOUT, (uint64_t)level, i);
            xy[2 * i] = w * sk_rng_uniform(&rng);
            xy[2 * i + 1] = h * sk_rng_uniform(&rng);
        }
        *xy_out = xy;
        *count_out = count;
        return SK_OK;
    }

    /* Ideal basis T (columns): triangular rows along x, or square. */
    double t[2][2];
    if (lv->layout == SK_SKIN_LAYOUT_SQUARE) {
        t[0][0] = s, t[0][1] = 0, t[1][0] = 0, t[1][1] = s;
    } else {
        t[0][0] = s, t[0][1] = 0.5 * s, t[1][0] = 0, t[1][1] = 0.5 * sqrt(3.0) * s;
    }
    double tdet = t[0][0] * t[1][1] - t[0][1] * t[1][0];
    double tinv[2][2] = {{t[1][1] / tdet, -t[0][1] / tdet}, {-t[1][0] / tdet, t[0][0] / tdet}};
    double kf[2][2];
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 2; j++) {
            kf[i][j] = tinv[i][0] * p[0][j] + tinv[i][1] * p[1][j];
            if (!(fabs(kf[i][j]) < 1e7))
                return sk_fail(err, SK_ERROR_LIMIT,
                               "levels[%d].spacing_mm = %g is too small for a %g x %g mm tile",
                               level, s, w, h);
        }
    long long k[2][2];
    fit_lattice(kf, k);
    long long det = k[0][0] * k[1][1] - k[0][1] * k[1][0];
    long long n = llabs(det);
    if (n > SK_SKIN_MAX_CELLS)
        return sk_fail(err, SK_ERROR_LIMIT,
                       "levels[%d]: %lld centre points; at most %d cells are supported "
                       "(raise levels[%d].spacing_mm or reduce size_mm)",
                       level, n, SK_SKIN_MAX_CELLS, level);
    double *xy = malloc(sizeof(double) * 2 * (size_t)n);
    if (!xy) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for centre points");
    /* adj(K) v / det in [0, 1)^2 <=> the vector is one of the |det| coset representatives. */
    long long adj[2][2] = {{k[1][1], -k[0][1]}, {-k[1][0], k[0][0]}};
    long long lo[2] = {0, 0}, hi[2] = {0, 0};
    for (int c = 0; c < 4; c++) {
        long long cx = (c & 1) * k[0][0] + (c >> 1) * k[0][1];
        long long cy = (c & 1) * k[1][0] + (c >> 1) * k[1][1];
        if (cx < lo[0]) lo[0] = cx;
        if (cx > hi[0]) hi[0] = cx;
        if (cy < lo[1]) lo[1] = cy;
        if (cy > hi[1]) hi[1] = cy;
    }
    uint32_t count = 0;
    for (long long j = lo[1]; j <= hi[1]; j++)
        for (long long i = lo[0]; i <= hi[0]; i++) {
            long long a = adj[0][0] * i + adj[0][1] * j;
            long long b = adj[1][0] * i + adj[1][1] * j;
            bool in = det > 0 ? (a >= 0 && a < det && b >= 0 && b < det)
                              : (a <= 0 && a > det && b <= 0 && b > det);
            if (!in || count >= (uint32_t)n) continue;
            double fx = (double)a / (double)det, fy = (double)b / (double)det;
            sk_rng rng = sk_rng_make(seed, SK__SALT_LAYOUT, (uint64_t)level, count);
            double dx, dy;
            jitter_offset(lv, &rng, &dx, &dy);
            /* y = M (P f + jitter) = diag(w, h) f + M jitter */
            double x = w * fx + L->m[0][0] * dx + L->m[0][1] * dy;
            double y = h * fy + L->m[1][0] * dx + L->m[1][1] * dy;
            xy[2 * count] = sk__wrap(x, w);
            xy[2 * count + 1] = sk__wrap(y, h);
            count++;
        }
    *xy_out = xy;
    *count_out = count;
    return SK_OK;
}
