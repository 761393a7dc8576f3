/* Convex polygon clipping by half-planes (Sutherland-Hodgman), keeping a tag per edge so
 * Voronoi cells know which neighbour or parent edge each side comes from (sec. 3.2.1 (1),
 * 3.2.3 (1): children are divided inside their parent polygon). */
#include <math.h>
#include <string.h>

#include "skin/skin_internal.h"

bool sk__poly_clip(sk__poly *p, double nx, double ny, double d, int64_t tag)
{
    int n = p->n;
    if (n == 0) return true;
    double dist[SK__POLY_MAX];
    bool any_out = false, any_in = false;
    for (int i = 0; i < n; i++) {
        dist[i] = nx * p->x[i] + ny * p->y[i] - d;
        if (dist[i] > 0)
            any_out = true;
        else
            any_in = true;
    }
    if (!any_out) return true;
    if (!any_in) {
        p->n = 0;
        return true;
    }
    sk__poly q;
    int m = 0;
    for (int i = 0; i < n; i++) {
        int j = (i + 1) % n;
        bool in_i = dist[i] <= 0, in_j = dist[j] <= 0;
        if (in_i) {
            if (m >= SK__POLY_MAX) return false;
            q.x[m] = p->x[i], q.y[m] = p->y[i];
            q.tag[m] = p->tag[i]; /* edge i survives, at least in part */
            m++;
        }
        if (in_i != in_j) {
            double t = dist[i] / (dist[i] - dist[j]);
            if (m >= SK__POLY_MAX) return false;
            q.x[m] = p->x[i] + t * (p->x[j] - p->x[i]);
            q.y[m] = p->y[i] + t * (p->y[j] - p->y[i]);
            /* Entering: the rest of edge i keeps its tag; leaving: the clip line. */
            q.tag[m] = in_i ? tag : p->tag[i];
            m++;
        }
    }
    /* Drop vertices that coincide with the next one (zero-length edges). */
    sk__poly r;
    int k = 0;
    for (int i = 0; i < m; i++) {
        int j = (i + 1) % m;
        double ex = q.x[j] - q.x[i], ey = q.y[j] - q.y[i];
        double scale = fabs(q.x[i]) + fabs(q.y[i]) + 1e-300;
        if (fabs(ex) + fabs(ey) <= 1e-13 * scale) continue;
        r.x[k] = q.x[i], r.y[k] = q.y[i], r.tag[k] = q.tag[i];
        k++;
    }
    r.n = k;
    if (k < 3) r.n = 0;
    memcpy(p->x, r.x, sizeof(double) * (size_t)r.n);
    memcpy(p->y, r.y, sizeof(double) * (size_t)r.n);
    memcpy(p->tag, r.tag, sizeof(int64_t) * (size_t)r.n);
    p->n = r.n;
    return true;
}

void sk__poly_centroid(const sk__poly *p, double *cx, double *cy)
{
    /* Relative to the first vertex for accuracy far from the origin. */
    double ox = p->x[0], oy = p->y[0], a = 0, sx = 0, sy = 0;
    for (int i = 0; i < p->n; i++) {
        int j = (i + 1) % p->n;
        double xi = p->x[i] - ox, yi = p->y[i] - oy, xj = p->x[j] - ox, yj = p->y[j] - oy;
        double c = xi * yj - xj * yi;
        a += c;
        sx += (xi + xj) * c;
        sy += (yi + yj) * c;
    }
    if (fabs(a) < 1e-300) {
        *cx = ox, *cy = oy;
        return;
    }
    *cx = ox + sx / (3.0 * a);
    *cy = oy + sy / (3.0 * a);
}
