/* The last step of meshing the hand surface: finds pairs of triangles that cross (a
 * fold left where collapses and relaxation met in a tight spot, e.g. between curled
 * fingertips) and smooths the vertices around them toward their neighbours' centre
 * (and most of the way back onto the implicit surface) until no pair crosses. Crossings are found
 * with a uniform grid of triangle bounds and the segment-triangle test of Moller & Trumbore (1997)
 * on every edge. */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "models/hand_surface/surface_internal.h"

static bool segment_crosses(const double *p, const double *q, const double *a, const double *b,
                            const double *c)
{
    double d[3], e1[3], e2[3], h[3], s[3], qv[3];
    for (int k = 0; k < 3; k++) d[k] = q[k] - p[k], e1[k] = b[k] - a[k], e2[k] = c[k] - a[k];
    h[0] = d[1] * e2[2] - d[2] * e2[1], h[1] = d[2] * e2[0] - d[0] * e2[2],
    h[2] = d[0] * e2[1] - d[1] * e2[0];
    double det = e1[0] * h[0] + e1[1] * h[1] + e1[2] * h[2];
    if (fabs(det) < 1e-14) return false;
    double inv = 1.0 / det;
    for (int k = 0; k < 3; k++) s[k] = p[k] - a[k];
    double u = inv * (s[0] * h[0] + s[1] * h[1] + s[2] * h[2]);
    if (u < 0.0 || u > 1.0) return false;
    qv[0] = s[1] * e1[2] - s[2] * e1[1], qv[1] = s[2] * e1[0] - s[0] * e1[2],
    qv[2] = s[0] * e1[1] - s[1] * e1[0];
    double v = inv * (d[0] * qv[0] + d[1] * qv[1] + d[2] * qv[2]);
    if (v < 0.0 || u + v > 1.0) return false;
    double t = inv * (e2[0] * qv[0] + e2[1] * qv[1] + e2[2] * qv[2]);
    return t >= 0.0 && t <= 1.0;
}

static bool triangles_cross(const sk__hand_trimesh *m, const uint32_t *A, const uint32_t *B)
{
    const double *a[3], *b[3];
    for (int k = 0; k < 3; k++) a[k] = m->pos + 3 * (size_t)A[k], b[k] = m->pos + 3 * (size_t)B[k];
    for (int j = 0; j < 3; j++) {
        double alo = fmin(a[0][j], fmin(a[1][j], a[2][j])),
               ahi = fmax(a[0][j], fmax(a[1][j], a[2][j]));
        double blo = fmin(b[0][j], fmin(b[1][j], b[2][j])),
               bhi = fmax(b[0][j], fmax(b[1][j], b[2][j]));
        if (ahi < blo || bhi < alo) return false;
    }
    for (int k = 0; k < 3; k++)
        if (segment_crosses(a[k], a[(k + 1) % 3], b[0], b[1], b[2]) ||
            segment_crosses(b[k], b[(k + 1) % 3], a[0], a[1], a[2]))
            return true;
    return false;
}

/* Marks the vertices of crossing triangle pairs (not sharing a vertex); returns the
 * number of pairs. */
static size_t mark_crossings(const sk__hand_trimesh *m, bool *mark)
{
    size_t T = m->tri_count, V = m->vertex_count;
    double lo[3] = {DBL_MAX, DBL_MAX, DBL_MAX}, hi[3] = {-DBL_MAX, -DBL_MAX, -DBL_MAX}, longest = 0;
    for (size_t v = 0; v < V; v++)
        for (int k = 0; k < 3; k++)
            lo[k] = fmin(lo[k], m->pos[3 * v + k]), hi[k] = fmax(hi[k], m->pos[3 * v + k]);
    for (size_t t = 0; t < T; t++)
        for (int k = 0; k < 3; k++) {
            const double *p = m->pos + 3 * (size_t)m->tri[3 * t + k],
                         *q = m->pos + 3 * (size_t)m->tri[3 * t + (k + 1) % 3];
            longest =
                fmax(longest, sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                                   (p[2] - q[2]) * (p[2] - q[2])));
        }
    /* triangles filed by centroid; a crossing pair's centroids are within one longest edge */
    double cell = fmax(longest, 1e-3);
    long n[3];
    for (int k = 0; k < 3; k++) n[k] = (long)((hi[k] - lo[k]) / cell) + 1;
    size_t cells = (size_t)n[0] * (size_t)n[1] * (size_t)n[2];
    if (cells > 64 * T + 1024) return 0; /* degenerate spread: nothing sensible to do */
    long *head = malloc(cells * sizeof *head), *next = malloc(T * sizeof *next),
         *cid = malloc(T * sizeof *cid);
    size_t pairs = 0;
    if (!head || !next || !cid) goto done;
    for (size_t i = 0; i < cells; i++) head[i] = -1;
    for (size_t t = 0; t < T; t++) {
        long c[3];
        for (int k = 0; k < 3; k++) {
            double x =
                (m->pos[3 * (size_t)m->tri[3 * t] + k] + m->pos[3 * (size_t)m->tri[3 * t + 1] + k] +
                 m->pos[3 * (size_t)m->tri[3 * t + 2] + k]) /
                3.0;
            c[k] = (long)((x - lo[k]) / cell);
        }
        cid[t] = (c[2] * n[1] + c[1]) * n[0] + c[0];
        next[t] = head[cid[t]];
        head[cid[t]] = (long)t;
    }
    for (size_t t = 0; t < T; t++) {
        const uint32_t *A = m->tri + 3 * t;
        long c0 = cid[t] % n[0], c1 = (cid[t] / n[0]) % n[1], c2 = cid[t] / (n[0] * n[1]);
        for (long dz = -1; dz <= 1; dz++)
            for (long dy = -1; dy <= 1; dy++)
                for (long dx = -1; dx <= 1; dx++) {
                    long x = c0 + dx, y = c1 + dy, z = c2 + dz;
                    if (x < 0 || y < 0 || z < 0 || x >= n[0] || y >= n[1] || z >= n[2]) continue;
                    for (long u = head[(z * n[1] + y) * n[0] + x]; u >= 0; u = next[u]) {
                        if ((size_t)u <= t) continue;
                        const uint32_t *B = m->tri + 3 * (size_t)u;
                        bool shares = false;
                        for (int i = 0; i < 3; i++)
                            for (int j = 0; j < 3; j++) shares |= A[i] == B[j];
                        if (shares || !triangles_cross(m, A, B)) continue;
                        pairs++;
                        for (int i = 0; i < 3; i++) mark[A[i]] = mark[B[i]] = true;
                    }
                }
    }
done:
    free(head), free(next), free(cid);
    return pairs;
}

void sk__hand_untangle(sk__hand_trimesh *m, const sk__hand_field *field)
{
    size_t V = m->vertex_count, T = m->tri_count;
    bool *mark = calloc(V, sizeof *mark), *grow_mark = calloc(V, sizeof *grow_mark);
    double *next = malloc(3 * V * sizeof *next);
    uint32_t *deg = calloc(V, sizeof *deg);
    if (!mark || !grow_mark || !next || !deg) goto done;
    for (int round = 0; round < 8; round++) {
        memset(mark, 0, V * sizeof *mark);
        if (mark_crossings(m, mark) == 0) break;
        /* the crossing vertices and their rings, wider every round */
        for (int g = 0; g <= round / 2; g++) {
            memcpy(grow_mark, mark, V * sizeof *mark);
            for (size_t t = 0; t < T; t++) {
                const uint32_t *tv = m->tri + 3 * t;
                if (mark[tv[0]] || mark[tv[1]] || mark[tv[2]])
                    grow_mark[tv[0]] = grow_mark[tv[1]] = grow_mark[tv[2]] = true;
            }
            memcpy(mark, grow_mark, V * sizeof *mark);
        }
        for (int it = 0; it < 4; it++) {
            memset(next, 0, 3 * V * sizeof *next);
            memset(deg, 0, V * sizeof *deg);
            for (size_t t = 0; t < T; t++)
                for (int k = 0; k < 3; k++) {
                    uint32_t a = m->tri[3 * t + k], b = m->tri[3 * t + (k + 1) % 3];
                    for (int j = 0; j < 3; j++)
                        next[3 * (size_t)a + j] += m->pos[3 * (size_t)b + j];
                    deg[a]++;
                }
            for (size_t v = 0; v < V; v++) {
                if (!mark[v] || !deg[v]) continue;
                /* to the neighbours' centre, then back toward the surface by at most a
                   quarter of the way */
                sk_vec3d c = sk_v3d(next[3 * v] / deg[v], next[3 * v + 1] / deg[v],
                                    next[3 * v + 2] / deg[v]),
                         on;
                sk__hand_field_project(field, c, &on);
                sk_vec3d p = sk_v3d_add(c, sk_v3d_scale(sk_v3d_sub(on, c), 0.75));
                m->pos[3 * v] = p.x, m->pos[3 * v + 1] = p.y, m->pos[3 * v + 2] = p.z;
            }
        }
    }
done:
    free(mark), free(grow_mark), free(next), free(deg);
}
