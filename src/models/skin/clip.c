/* Convex polygon clipping by half-planes (Sutherland-Hodgman), keeping a tag per edge so
 * Voronoi cells know which neighbour or parent edge each side comes from (sec. 3.2.1 (1),
 * 3.2.3 (1): children are divided inside their parent polygon). */
#include <math.h>
#include <string.h>

#include "models/skin/skin_internal.h"

/* Appends pending vertex (hx, hy) unless the next one (vx, vy) coincides with it (the edge
 * between them would have zero length). False when the polygon would overflow. */
static bool keep_vertex(sk__poly *q, double hx, double hy, int64_t htag, double vx, double vy)
{
    double scale = fabs(hx) + fabs(hy) + 1e-300;
    if (fabs(vx - hx) + fabs(vy - hy) <= 1e-13 * scale) return true;
    if (q->n >= SK__POLY_MAX) return false;
    q->x[q->n] = hx, q->y[q->n] = hy, q->tag[q->n] = htag;
    q->n++;
    return true;
}

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
    /* The kept polygon, dropping every vertex that coincides with the next one (a
       zero-length edge): a vertex is only written once its successor is known. */
    sk__poly q;
    q.n = 0;
    double first_x = 0, first_y = 0;
    bool have = false; /* a vertex is pending */
    double hx = 0, hy = 0;
    int64_t htag = 0;
    for (int i = 0; i < n; i++) {
        int j = i + 1 == n ? 0 : i + 1;
        bool in_i = dist[i] <= 0, in_j = dist[j] <= 0;
        for (int pass = 0; pass < 2; pass++) {
            double vx, vy;
            int64_t vtag;
            if (pass == 0) {
                if (!in_i) continue;
                vx = p->x[i], vy = p->y[i],
                vtag = p->tag[i]; /* edge i survives, at least in part */
            } else {
                if (in_i == in_j) continue;
                double t = dist[i] / (dist[i] - dist[j]);
                vx = p->x[i] + t * (p->x[j] - p->x[i]);
                vy = p->y[i] + t * (p->y[j] - p->y[i]);
                /* Entering: the rest of edge i keeps its tag; leaving: the clip line. */
                vtag = in_i ? tag : p->tag[i];
            }
            if (!have)
                first_x = vx, first_y = vy;
            else if (!keep_vertex(&q, hx, hy, htag, vx, vy))
                return false;
            hx = vx, hy = vy, htag = vtag, have = true;
        }
    }
    /* the last vertex against the first one as produced */
    if (!keep_vertex(&q, hx, hy, htag, first_x, first_y)) return false;
    int m = q.n < 3 ? 0 : q.n;
    memcpy(p->x, q.x, sizeof(double) * (size_t)m);
    memcpy(p->y, q.y, sizeof(double) * (size_t)m);
    memcpy(p->tag, q.tag, sizeof(int64_t) * (size_t)m);
    p->n = m;
    return true;
}

void sk__polygon_centroid(const double *x, const double *y, int n, double *cx, double *cy)
{
    /* Relative to the first vertex for accuracy far from the origin. */
    double ox = x[0], oy = y[0], a = 0, sx = 0, sy = 0;
    for (int i = 0; i < n; i++) {
        int j = (i + 1) % n;
        double xi = x[i] - ox, yi = y[i] - oy, xj = x[j] - ox, yj = y[j] - oy;
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
