/* Polygon triangulation for the mesh readers: ear clipping in the plane of Newell's normal
 * (Newell's method: Sutherland, Sproull & Schumacker 1974), with a fan as the fallback for
 * degenerate input. */
#include <math.h>
#include <stdlib.h>

#include "base/polygon_triangulate.h"

static void fan(size_t n, uint32_t *out)
{
    for (size_t k = 0; k + 2 < n; k++) {
        out[3 * k] = 0;
        out[3 * k + 1] = (uint32_t)(k + 1);
        out[3 * k + 2] = (uint32_t)(k + 2);
    }
}

static void emit(uint32_t *out, size_t k, uint32_t a, uint32_t b, uint32_t c)
{
    out[3 * k] = a;
    out[3 * k + 1] = b;
    out[3 * k + 2] = c;
}

static sk_result reserve(sk__triangulator *t, size_t n)
{
    if (n <= t->capacity) return SK_OK;
    double *xy = realloc(t->xy, 2 * n * sizeof *xy);
    if (xy) t->xy = xy;
    uint32_t *prev = realloc(t->prev, n * sizeof *prev);
    if (prev) t->prev = prev;
    uint32_t *next = realloc(t->next, n * sizeof *next);
    if (next) t->next = next;
    if (!xy || !prev || !next) return SK_ERROR_OUT_OF_MEMORY;
    t->capacity = n;
    return SK_OK;
}

void sk__triangulator_free(sk__triangulator *t)
{
    free(t->xy);
    free(t->prev);
    free(t->next);
    t->xy = NULL;
    t->prev = t->next = NULL;
    t->capacity = 0;
}

/* Projects the corners onto an orthonormal basis (u, v) of the plane with normal n, so
 * that u x v = n and a polygon wound counter-clockwise about n stays counter-clockwise. */
static void project(sk__triangulator *t, const float *positions, const uint32_t *corners,
                    size_t count, const double n[3])
{
    /* u: n crossed with the axis least aligned with it. */
    double ax[3] = {0, 0, 0};
    int k = fabs(n[0]) <= fabs(n[1]) ? (fabs(n[0]) <= fabs(n[2]) ? 0 : 2)
                                     : (fabs(n[1]) <= fabs(n[2]) ? 1 : 2);
    ax[k] = 1.0;
    double u[3] = {ax[1] * n[2] - ax[2] * n[1], ax[2] * n[0] - ax[0] * n[2],
                   ax[0] * n[1] - ax[1] * n[0]};
    double ul = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    for (int i = 0; i < 3; i++) u[i] /= ul;
    double v[3] = {n[1] * u[2] - n[2] * u[1], n[2] * u[0] - n[0] * u[2], n[0] * u[1] - n[1] * u[0]};
    const float *origin = positions + 3 * (size_t)corners[0];
    for (size_t i = 0; i < count; i++) {
        const float *p = positions + 3 * (size_t)corners[i];
        double d[3] = {(double)p[0] - origin[0], (double)p[1] - origin[1],
                       (double)p[2] - origin[2]};
        t->xy[2 * i] = d[0] * u[0] + d[1] * u[1] + d[2] * u[2];
        t->xy[2 * i + 1] = d[0] * v[0] + d[1] * v[1] + d[2] * v[2];
    }
}

/* Twice the signed area of triangle (a, b, c); positive when counter-clockwise. */
static double orient(const double *xy, uint32_t a, uint32_t b, uint32_t c)
{
    const double *pa = xy + 2 * a, *pb = xy + 2 * b, *pc = xy + 2 * c;
    return (pb[0] - pa[0]) * (pc[1] - pa[1]) - (pb[1] - pa[1]) * (pc[0] - pa[0]);
}

static bool same_point(const double *xy, uint32_t a, uint32_t b)
{
    return xy[2 * a] == xy[2 * b] && xy[2 * a + 1] == xy[2 * b + 1];
}

/* Corner b (between a and c) is an ear when the triangle turns left (or, relaxed, is
 * flat) and no other remaining corner lies inside it or on its edges. */
static bool is_ear(const sk__triangulator *t, uint32_t b, double eps, bool relaxed)
{
    uint32_t a = t->prev[b], c = t->next[b];
    double area = orient(t->xy, a, b, c);
    if (relaxed ? area < -eps : area <= eps) return false;
    for (uint32_t p = t->next[c]; p != a; p = t->next[p]) {
        /* A corner repeated at an ear's tip does not block it (touching polygons). */
        if (same_point(t->xy, p, a) || same_point(t->xy, p, b) || same_point(t->xy, p, c)) continue;
        if (orient(t->xy, a, b, p) >= -eps && orient(t->xy, b, c, p) >= -eps &&
            orient(t->xy, c, a, p) >= -eps)
            return false;
    }
    return true;
}

sk_result sk__triangulate(sk__triangulator *t, const float *positions, const uint32_t *corners,
                          size_t n, uint32_t *out)
{
    if (n == 3 || n > SK__TRIANGULATE_EAR_MAX) {
        fan(n, out);
        return SK_OK;
    }
    /* Newell's normal: robust for non-planar and concave polygons, and its direction
       follows the winding. */
    double nrm[3] = {0, 0, 0};
    for (size_t i = 0; i < n; i++) {
        const float *p = positions + 3 * (size_t)corners[i];
        const float *q = positions + 3 * (size_t)corners[(i + 1) % n];
        nrm[0] += ((double)p[1] - q[1]) * ((double)p[2] + q[2]);
        nrm[1] += ((double)p[2] - q[2]) * ((double)p[0] + q[0]);
        nrm[2] += ((double)p[0] - q[0]) * ((double)p[1] + q[1]);
    }
    double len = sqrt(nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2]);
    if (!(len > 0.0) || !isfinite(len)) {
        fan(n, out);
        return SK_OK;
    }
    if (reserve(t, n) != SK_OK) return SK_ERROR_OUT_OF_MEMORY;
    for (int i = 0; i < 3; i++) nrm[i] /= len;
    project(t, positions, corners, n, nrm);

    double extent = 0.0;
    for (size_t i = 0; i < 2 * n; i++) extent = fmax(extent, fabs(t->xy[i]));
    const double eps = 1e-12 * extent * extent; /* relative to the polygon's size */
    for (size_t i = 0; i < n; i++) {
        t->prev[i] = (uint32_t)(i == 0 ? n - 1 : i - 1);
        t->next[i] = (uint32_t)(i + 1 == n ? 0 : i + 1);
    }
    size_t remaining = n, emitted = 0, stall = 0;
    uint32_t b = 0;
    bool relaxed = false;
    while (remaining > 3) {
        if (is_ear(t, b, eps, relaxed)) {
            uint32_t a = t->prev[b], c = t->next[b];
            emit(out, emitted++, a, b, c);
            t->next[a] = c;
            t->prev[c] = a;
            remaining--;
            b = a; /* a's ear status changed; look there first */
            stall = 0;
            relaxed = false;
            continue;
        }
        b = t->next[b];
        if (++stall < remaining) continue;
        if (!relaxed) {
            relaxed = true; /* a full turn without a proper ear: accept flat ones */
            stall = 0;
            continue;
        }
        /* No ear at all (self-intersecting input): fan what is left. */
        uint32_t first = b;
        for (uint32_t p = t->next[first]; t->next[p] != first; p = t->next[p]) {
            emit(out, emitted++, first, p, t->next[p]);
        }
        return SK_OK;
    }
    emit(out, emitted, t->prev[b], b, t->next[b]);
    return SK_OK;
}
