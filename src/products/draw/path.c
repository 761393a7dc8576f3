/* Outline paths for the rasterizer: contours of straight edges, circles and arcs
 * flattened with a bounded error and the curve's exact area, and stroked segments. */
#include <stdlib.h>
#include <string.h>

#include "products/draw/draw_internal.h"

/* Largest distance between a flattened circle and the true circle, in pixels. */
#define SK__FLATTEN_TOLERANCE 0.01

void sk__path_init(sk__path *path)
{
    path->edges = path->inline_edges;
    path->count = 0;
    path->capacity = SK__PATH_INLINE_EDGES;
    path->failed = false;
    path->min_x = path->min_y = INFINITY;
    path->max_x = path->max_y = -INFINITY;
    path->start_x = path->start_y = path->last_x = path->last_y = 0.0;
    path->open = false;
}

void sk__path_free(sk__path *path)
{
    if (path->edges != path->inline_edges) free(path->edges);
    path->edges = path->inline_edges;
    path->count = 0;
    path->capacity = SK__PATH_INLINE_EDGES;
}

static void path_include(sk__path *path, double x, double y)
{
    if (x < path->min_x) path->min_x = x;
    if (x > path->max_x) path->max_x = x;
    if (y < path->min_y) path->min_y = y;
    if (y > path->max_y) path->max_y = y;
}

static void path_push(sk__path *path, double x0, double y0, double x1, double y1)
{
    if (path->failed) return;
    if (y0 == y1) return; /* horizontal edges add no coverage */
    if (path->count == path->capacity) {
        if (path->capacity > (1 << 26)) {
            path->failed = true;
            return;
        }
        int cap = path->capacity * 2;
        sk__edge *grown = malloc((size_t)cap * sizeof *grown);
        if (!grown) {
            path->failed = true;
            return;
        }
        memcpy(grown, path->edges, (size_t)path->count * sizeof *grown);
        if (path->edges != path->inline_edges) free(path->edges);
        path->edges = grown;
        path->capacity = cap;
    }
    sk__edge *e = &path->edges[path->count++];
    e->x0 = x0;
    e->y0 = y0;
    e->x1 = x1;
    e->y1 = y1;
}

void sk__path_close(sk__path *path)
{
    if (!path->open) return;
    path_push(path, path->last_x, path->last_y, path->start_x, path->start_y);
    path->open = false;
}

void sk__path_move_to(sk__path *path, double x, double y)
{
    sk__path_close(path);
    path->start_x = path->last_x = x;
    path->start_y = path->last_y = y;
    path->open = true;
    path_include(path, x, y);
}

void sk__path_line_to(sk__path *path, double x, double y)
{
    if (!path->open) {
        sk__path_move_to(path, x, y);
        return;
    }
    path_push(path, path->last_x, path->last_y, x, y);
    path->last_x = x;
    path->last_y = y;
    path_include(path, x, y);
}

int sk__circle_segments(double radius)
{
    if (!(radius > SK__FLATTEN_TOLERANCE)) return 8;
    /* A chord of angle t deviates from its arc by r (1 - cos(t / 2)). */
    double half_angle = acos(1.0 - SK__FLATTEN_TOLERANCE / radius);
    double n = ceil(SK_PI / half_angle);
    if (n < 8.0) return 8;
    if (n > 4096.0) return 4096;
    /* A multiple of 4, so half and quarter arcs (caps) split the circle evenly and keep
       its exact area too. */
    return ((int)n + 3) & ~3;
}

double sk__area_preserving_radius(double radius, int segments)
{
    /* A regular n-gon of circumradius R has area (n / 2) R^2 sin(2 pi / n). */
    double n = (double)segments;
    return radius * sqrt(2.0 * SK_PI / (n * sin(2.0 * SK_PI / n)));
}

/* Appends steps + 1 points around (cx, cy) starting at offset (ox, oy), each turned by
 * `step` radians from the previous (a rotation recurrence: one sin/cos per arc). */
static void arc_points(sk__path *path, double cx, double cy, double ox, double oy, double step,
                       int steps)
{
    double c = cos(step), s = sin(step);
    for (int i = 0; i <= steps; i++) {
        sk__path_line_to(path, cx + ox, cy + oy);
        double nx = ox * c - oy * s;
        oy = ox * s + oy * c;
        ox = nx;
    }
}

void sk__path_circle(sk__path *path, double cx, double cy, double radius, bool clockwise)
{
    int n = sk__circle_segments(radius);
    double r = sk__area_preserving_radius(radius, n);
    double step = (clockwise ? 2.0 : -2.0) * SK_PI / (double)n; /* y down: + is clockwise */
    sk__path_move_to(path, cx + r, cy);
    arc_points(path, cx, cy, r, 0.0, step, n - 1);
    sk__path_close(path);
}

bool sk__path_stroke_segment(sk__path *path, double x0, double y0, double x1, double y1,
                             double width, sk_line_cap cap)
{
    double h = 0.5 * width;
    double dx = x1 - x0, dy = y1 - y0;
    double len = hypot(dx, dy);
    if (cap == SK_CAP_DEFAULT) cap = SK_CAP_ROUND;
    if (!(len > 1e-9 * h) || !isfinite(len)) {
        if (!isfinite(len)) return false;
        /* Zero length: a round cap leaves a disc, a square cap an axis-aligned square. */
        if (cap == SK_CAP_ROUND) {
            sk__path_circle(path, x0, y0, h, true);
            return true;
        }
        if (cap == SK_CAP_SQUARE) {
            sk__path_move_to(path, x0 - h, y0 - h);
            sk__path_line_to(path, x0 + h, y0 - h);
            sk__path_line_to(path, x0 + h, y0 + h);
            sk__path_line_to(path, x0 - h, y0 + h);
            sk__path_close(path);
            return true;
        }
        return false;
    }
    double ux = dx / len, uy = dy / len;
    double nx = -uy * h, ny = ux * h; /* normal of length h */
    if (cap == SK_CAP_SQUARE) {
        x0 -= ux * h;
        y0 -= uy * h;
        x1 += ux * h;
        y1 += uy * h;
    }
    sk__path_move_to(path, x0 + nx, y0 + ny);
    sk__path_line_to(path, x1 + nx, y1 + ny);
    if (cap == SK_CAP_ROUND) {
        int n = sk__circle_segments(h);
        double k = sk__area_preserving_radius(h, n) / h;
        double step = -2.0 * SK_PI / (double)n;
        /* Half turns from +normal through the direction to -normal, and back at p0. */
        arc_points(path, x1, y1, nx * k, ny * k, step, n / 2);
        sk__path_line_to(path, x1 - nx, y1 - ny);
        sk__path_line_to(path, x0 - nx, y0 - ny);
        arc_points(path, x0, y0, -nx * k, -ny * k, step, n / 2);
    } else {
        sk__path_line_to(path, x1 - nx, y1 - ny);
        sk__path_line_to(path, x0 - nx, y0 - ny);
    }
    sk__path_close(path);
    return true;
}
