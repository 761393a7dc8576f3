/* Orthographic views with a depth buffer for the scan pipeline's pictures (thesis 4.1:
 * the measured data of Fig. 4.3, the slices of Fig. 4.5, the polygons of Fig. 4.7 and the
 * patches of Fig. 4.10): flat-shaded triangles and point splats, drawn at twice the size
 * and reduced by area averaging. */
#include <stdlib.h>
#include <string.h>

#include "products/hand/scan_draw_internal.h"
#include "models/hand/hand_internal.h"
#include "shitsukan/hand.h"

sk_result sk__hand_view_create(sk__hand_view *v, int width, int height, sk_vec3d right, sk_vec3d up,
                               sk_vec3d lo, sk_vec3d hi, int margin, sk_color bg, sk_error *err)
{
    memset(v, 0, sizeof *v);
    int S = SK_HAND__VIEW_SUPERSAMPLE;
    sk_result r = sk_image_create(&v->image, width * S, height * S, 3, err);
    if (r != SK_OK) return r;
    size_t n = (size_t)width * S * (size_t)height * S;
    v->depth = malloc(sizeof *v->depth * n);
    if (!v->depth) {
        sk_image_free(&v->image);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "picture of %d x %d", width, height);
    }
    for (size_t i = 0; i < n; i++) v->depth[i] = -INFINITY;
    sk_draw_clear(&v->image, bg);
    v->right = right, v->up = up, v->toward = sk_v3d_cross(right, up);
    /* extent of the box's corners across and up the view */
    double rx0 = INFINITY, rx1 = -INFINITY, uy0 = INFINITY, uy1 = -INFINITY;
    for (int c = 0; c < 8; c++) {
        sk_vec3d p = {c & 1 ? hi.x : lo.x, c & 2 ? hi.y : lo.y, c & 4 ? hi.z : lo.z};
        double x = sk_v3d_dot(p, right), y = sk_v3d_dot(p, up);
        rx0 = fmin(rx0, x), rx1 = fmax(rx1, x), uy0 = fmin(uy0, y), uy1 = fmax(uy1, y);
    }
    double w = fmax(rx1 - rx0, 1e-6), h = fmax(uy1 - uy0, 1e-6);
    double sx = (width - 2.0 * margin) / w, sy = (height - 2.0 * margin) / h;
    double s = fmin(sx, sy);
    v->scale = s * S;
    v->ox = (0.5 * width - s * 0.5 * (rx0 + rx1)) * S;
    v->oy = (0.5 * height + s * 0.5 * (uy0 + uy1)) * S;
    return SK_OK;
}

void sk__hand_view_free(sk__hand_view *v)
{
    sk_image_free(&v->image);
    free(v->depth);
    memset(v, 0, sizeof *v);
}

static inline void to_pixel(const sk__hand_view *v, sk_vec3d p, double *x, double *y, double *z)
{
    *x = v->ox + v->scale * sk_v3d_dot(p, v->right);
    *y = v->oy - v->scale * sk_v3d_dot(p, v->up);
    *z = sk_v3d_dot(p, v->toward);
}

sk_vec2f sk__hand_view_project(const sk__hand_view *v, sk_vec3d p)
{
    double x, y, z;
    to_pixel(v, p, &x, &y, &z);
    return sk_v2f((float)(x / SK_HAND__VIEW_SUPERSAMPLE), (float)(y / SK_HAND__VIEW_SUPERSAMPLE));
}

static inline void plot(sk__hand_view *v, int x, int y, float z, sk_color c)
{
    size_t i = (size_t)y * (size_t)v->image.width + (size_t)x;
    if (z <= v->depth[i]) return;
    v->depth[i] = z;
    float *px = v->image.data + 3 * i;
    px[0] = c.r, px[1] = c.g, px[2] = c.b;
}

void sk__hand_view_triangle(sk__hand_view *v, sk_vec3d a, sk_vec3d b, sk_vec3d c, sk_color color)
{
    sk_vec3d n = sk_v3d_normalize(sk_v3d_cross(sk_v3d_sub(b, a), sk_v3d_sub(c, a)));
    if (sk_v3d_dot(n, v->toward) < 0) n = sk_v3d_scale(n, -1.0);
    /* light from the viewer's upper left, a little ambient */
    sk_vec3d light = sk_v3d_normalize(
        sk_v3d_add(sk_v3d_add(sk_v3d_scale(v->toward, 1.0), sk_v3d_scale(v->up, 0.6)),
                   sk_v3d_scale(v->right, -0.4)));
    float k = (float)(0.28 + 0.72 * fmax(0.0, sk_v3d_dot(n, light)));
    sk_color shaded = sk_rgb(color.r * k, color.g * k, color.b * k);
    double x[3], y[3], z[3];
    to_pixel(v, a, &x[0], &y[0], &z[0]);
    to_pixel(v, b, &x[1], &y[1], &z[1]);
    to_pixel(v, c, &x[2], &y[2], &z[2]);
    double area = (x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0]);
    if (fabs(area) < 1e-12 || !isfinite(area)) return;
    int x0 = (int)floor(fmin(x[0], fmin(x[1], x[2]))), x1 = (int)ceil(fmax(x[0], fmax(x[1], x[2])));
    int y0 = (int)floor(fmin(y[0], fmin(y[1], y[2]))), y1 = (int)ceil(fmax(y[0], fmax(y[1], y[2])));
    x0 = x0 < 0 ? 0 : x0, y0 = y0 < 0 ? 0 : y0;
    x1 = x1 >= v->image.width ? v->image.width - 1 : x1;
    y1 = y1 >= v->image.height ? v->image.height - 1 : y1;
    for (int py = y0; py <= y1; py++)
        for (int px = x0; px <= x1; px++) {
            double cx = px + 0.5, cy = py + 0.5;
            double w0 = ((x[1] - cx) * (y[2] - cy) - (x[2] - cx) * (y[1] - cy)) / area;
            double w1 = ((x[2] - cx) * (y[0] - cy) - (x[0] - cx) * (y[2] - cy)) / area;
            double w2 = 1.0 - w0 - w1;
            if (w0 < 0 || w1 < 0 || w2 < 0) continue;
            plot(v, px, py, (float)(w0 * z[0] + w1 * z[1] + w2 * z[2]), shaded);
        }
}

void sk__hand_view_point(sk__hand_view *v, sk_vec3d p, float radius, sk_color color)
{
    double x, y, z;
    to_pixel(v, p, &x, &y, &z);
    double r = radius * SK_HAND__VIEW_SUPERSAMPLE;
    int x0 = (int)floor(x - r), x1 = (int)floor(x + r), y0 = (int)floor(y - r),
        y1 = (int)floor(y + r);
    for (int py = y0 < 0 ? 0 : y0; py <= y1 && py < v->image.height; py++)
        for (int px = x0 < 0 ? 0 : x0; px <= x1 && px < v->image.width; px++)
            plot(v, px, py, (float)z, color);
}

sk_result sk__hand_view_finish(sk__hand_view *v, sk_image *out, sk_error *err)
{
    int S = SK_HAND__VIEW_SUPERSAMPLE;
    return sk_image_resize_filter(&v->image, v->image.width / S, v->image.height / S, SK_RESIZE_BOX,
                                  out, err);
}

bool sk__hand_mesh_bounds(const sk_mesh *m, sk_vec3d *lo, sk_vec3d *hi)
{
    sk_vec3f l, h;
    if (!sk_mesh_bounds(m, &l, &h)) return false;
    *lo = sk_v3f_to_d(l);
    *hi = sk_v3f_to_d(h);
    return true;
}

sk_color sk__hand_index_color(int k)
{
    /* hue by the golden ratio, alternating lightness: neighbours in index differ */
    double h = sk_fmodpos(0.13 + 0.61803398875 * k, 1.0) * 6.0;
    double f = h - floor(h), q = 1 - f;
    double rgb[6][3] = {{1, f, 0}, {q, 1, 0}, {0, 1, f}, {0, q, 1}, {f, 0, 1}, {1, 0, q}};
    const double *c = rgb[(int)h % 6];
    double light = k % 2 ? 0.55 : 0.8, sat = 0.75;
    return sk_rgb((float)(light * (1 - sat + sat * c[0])), (float)(light * (1 - sat + sat * c[1])),
                  (float)(light * (1 - sat + sat * c[2])));
}

sk_color sk__hand_link_color(int link)
{
    if (link <= 0) return sk_rgb(0.45f, 0.45f, 0.45f);
    int finger = sk__hand_finger_of_link(link), segment = link - sk__hand_first_link(finger);
    sk_color c = sk_hand_finger_color((sk_hand_finger)finger);
    float t = 0.16f * (float)segment;
    return sk_rgb(c.r + (1 - c.r) * t, c.g + (1 - c.g) * t, c.b + (1 - c.b) * t);
}

sk_result sk__hand_panels(const sk_image *const *panels, int count, const char *title,
                          sk_image *out, sk_error *err)
{
    sk_contact_sheet_desc d = {.columns = count,
                               .padding = 6,
                               .text_scale = 1,
                               .title_scale = 2,
                               .title = title,
                               .tile_border = 1};
    return sk_contact_sheet(panels, NULL, count, &d, out, err);
}
