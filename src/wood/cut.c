/* Planar cuts through the solid texture (end grain, flat-sawn, quarter-sawn or any plane),
 * rendered pixel by pixel into caller buffers, in parallel rows. Each pixel's position
 * depends only on its coordinates in the full image, so a region is exactly that part of
 * the full image, and the output does not depend on the thread count. */
#include <math.h>
#include <string.h>

#include "core/loop_progress.h"
#include "wood/wood_internal.h"

static sk_vec3f tilt_towards(sk_vec3f n, sk_vec3f up, sk_vec3f side, double incidence,
                             double azimuth)
{
    sk_vec3f dir = sk_v3f_add(sk_v3f_scale(up, (float)cos(azimuth)),
                              sk_v3f_scale(side, (float)sin(azimuth)));
    return sk_v3f_normalize(sk_v3f_add(sk_v3f_scale(n, (float)cos(incidence)),
                                       sk_v3f_scale(dir, (float)sin(incidence))));
}

void sk_wood_view_cut(const sk_wood *wood, const sk_wood_view_desc *view_in, sk_wood_cut_desc *cut)
{
    sk_wood_desc tmp = wood->desc;
    tmp.view = *view_in;
    tmp = sk_wood_desc_resolved(&tmp);
    const sk_wood_view_desc *view = &tmp.view;
    sk_vec3f n, axis = sk_v3f(1, 0, 0), centre;
    switch (view->plane) {
    case SK_WOOD_PLANE_END:
        n = sk_v3f(0, 1, 0);
        centre = sk_v3f(view->distance_mm, view->height_mm, 0);
        break;
    case SK_WOOD_PLANE_QUARTER:
        n = sk_v3f(0, 0, 1);
        centre = sk_v3f(view->distance_mm, view->height_mm, 0);
        break;
    default: /* flat-sawn: tangential to the rings at z = distance */
        n = sk_v3f(0, 0, 1);
        centre = sk_v3f(0, view->height_mm, view->distance_mm);
        break;
    }
    /* tilt the plane about its horizontal axis */
    sk_vec3f up = sk_v3f_cross(n, axis);
    float c = cosf(view->tilt), s = sinf(view->tilt);
    n = sk_v3f_sub(sk_v3f_scale(n, c), sk_v3f_scale(up, s));
    cut->point = sk__wood_frame_point_to_scene(&wood->frame, centre);
    cut->normal = sk__wood_frame_dir_to_scene(&wood->frame, n);
    cut->axis = sk__wood_frame_dir_to_scene(&wood->frame, axis);
    cut->width_mm = view->width_mm;
    cut->light_incidence = view->light_incidence;
    cut->light_azimuth = view->light_azimuth;
    cut->view_incidence = view->view_incidence;
}

sk_result sk_wood_cut(const sk_wood *wood, const sk_wood_cut_desc *desc, sk_error *err)
{
    if (!wood || !desc) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "wood cut: NULL argument");
    sk_result r;
    if ((r = sk_check_range_i(err, "cut width", desc->width, 1, 65536)) != SK_OK) return r;
    if ((r = sk_check_range_i(err, "cut height", desc->height, 1, 65536)) != SK_OK) return r;
    if ((r = sk_check_range_f(err, "cut width_mm", desc->width_mm, 1e-6, 1e7)) != SK_OK) return r;
    if ((r = sk_check_range_i(err, "cut samples", desc->samples, 0, 8)) != SK_OK) return r;
    const float *vecs[3] = {&desc->point.x, &desc->normal.x, &desc->axis.x};
    const char *names[3] = {"cut point", "cut normal", "cut axis"};
    for (int v = 0; v < 3; v++)
        for (int i = 0; i < 3; i++)
            if ((r = sk_check_range_f(err, names[v], vecs[v][i], -1e7, 1e7)) != SK_OK) return r;
    const float *angles[3] = {&desc->light_incidence, &desc->light_azimuth, &desc->view_incidence};
    const char *angle_names[3] = {"cut light_incidence", "cut light_azimuth", "cut view_incidence"};
    for (int i = 0; i < 3; i++)
        if ((r = sk_check_range_f(err, angle_names[i], *angles[i], -7.0, 7.0)) != SK_OK) return r;
    int rx = desc->region[0], ry = desc->region[1], rw = desc->region[2], rh = desc->region[3];
    if (rx == 0 && ry == 0 && rw == 0 && rh == 0) {
        rw = desc->width;
        rh = desc->height;
    }
    if (rx < 0 || ry < 0 || rw < 1 || rh < 1 || rx > desc->width - rw || ry > desc->height - rh)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "cut region %d,%d,%d,%d does not lie inside the %dx%d image", rx, ry, rw,
                       rh, desc->width, desc->height);
    float nlen = sk_v3f_length(desc->normal);
    if (!(nlen > 1e-12f)) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "cut normal is zero");
    sk_vec3f n = sk_v3f_scale(desc->normal, 1.0f / nlen);
    sk_vec3f a = sk_v3f_sub(desc->axis, sk_v3f_scale(n, sk_v3f_dot(desc->axis, n)));
    float alen = sk_v3f_length(a);
    if (!(alen > 1e-6f * (sk_v3f_length(desc->axis) + 1e-30f)))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "cut axis is zero or along the normal");
    a = sk_v3f_scale(a, 1.0f / alen);
    sk_vec3f up = sk_v3f_cross(n, a);
    sk_vec3f light = tilt_towards(n, up, a, desc->light_incidence, desc->light_azimuth);
    sk_vec3f view = tilt_towards(n, up, a, desc->view_incidence, 0.0);
    int S = desc->samples ? desc->samples : 1;
    double W = desc->width, H = desc->height, inv_W = 1.0 / W, inv_H = 1.0 / H, inv_S = 1.0 / S;
    double width_mm = desc->width_mm, height_mm = width_mm * H / W;
    float footprint = (float)(width_mm / W / S);
    float inv = 1.0f / (float)(S * S);

    sk__loop_progress lp;
    sk__loop_progress_init(&lp, &desc->progress, rh);
#pragma omp parallel for schedule(dynamic, 1)
    for (int yy = 0; yy < rh; yy++) {
        int Y = ry + yy;
        /* sample positions of the row, one sub-row at a time, in batches of points */
        sk_vec3f shaded[SK__WOOD_BATCH], albedo[SK__WOOD_BATCH], fibre[SK__WOOD_BATCH];
        float vessel[SK__WOOD_BATCH], dive[SK__WOOD_BATCH];
        sk_vec3f points[SK__WOOD_BATCH];
        sk_wood_sample s[SK__WOOD_BATCH];
        for (int x0 = 0; x0 < rw; x0 += SK__WOOD_BATCH / S) {
            int pixels = rw - x0 < SK__WOOD_BATCH / S ? rw - x0 : SK__WOOD_BATCH / S;
            for (int k = 0; k < pixels; k++) {
                shaded[k] = albedo[k] = fibre[k] = sk_v3f(0, 0, 0);
                vessel[k] = dive[k] = 0.0f;
            }
            for (int sy = 0; sy < S; sy++) {
                /* the pixel position depends only on (X, Y): regions match the image */
                double fy = 0.5 - (Y + (sy + 0.5) * inv_S) * inv_H;
                sk_vec3f row = sk_v3f_add(desc->point, sk_v3f_scale(up, (float)(fy * height_mm)));
                int count = 0;
                for (int k = 0; k < pixels; k++)
                    for (int sx = 0; sx < S; sx++) {
                        double fx = (rx + x0 + k + (sx + 0.5) * inv_S) * inv_W - 0.5;
                        points[count++] = sk_v3f_add(row, sk_v3f_scale(a, (float)(fx * width_mm)));
                    }
                sk__wood_eval_batch(wood, count, points, n, footprint, s);
                for (int j = 0; j < count; j++) {
                    int k = j / S;
                    if (desc->shaded)
                        shaded[k] = sk_v3f_add(shaded[k], sk__shade(&wood->shading, &s[j], n, light, view));
                    if (desc->albedo) albedo[k] = sk_v3f_add(albedo[k], s[j].albedo);
                    if (desc->fibre)
                        fibre[k] = sk_v3f_add(fibre[k], sk_v3f(sk_v3f_dot(s[j].fibre, a),
                                                               sk_v3f_dot(s[j].fibre, up),
                                                               sk_v3f_dot(s[j].fibre, n)));
                    vessel[k] += s[j].vessel;
                    dive[k] += s[j].dive;
                }
            }
            for (int k = 0; k < pixels; k++) {
                size_t px = (size_t)yy * (size_t)rw + (size_t)(x0 + k);
                if (desc->shaded) {
                    desc->shaded[3 * px + 0] = shaded[k].x * inv;
                    desc->shaded[3 * px + 1] = shaded[k].y * inv;
                    desc->shaded[3 * px + 2] = shaded[k].z * inv;
                }
                if (desc->albedo) {
                    desc->albedo[3 * px + 0] = albedo[k].x * inv;
                    desc->albedo[3 * px + 1] = albedo[k].y * inv;
                    desc->albedo[3 * px + 2] = albedo[k].z * inv;
                }
                if (desc->fibre) {
                    float len = sk_v3f_length(fibre[k]);
                    sk_vec3f f = len > 0.0f ? sk_v3f_scale(fibre[k], 1.0f / len) : sk_v3f(0, 1, 0);
                    desc->fibre[3 * px + 0] = 0.5f + 0.5f * f.x;
                    desc->fibre[3 * px + 1] = 0.5f + 0.5f * f.y;
                    desc->fibre[3 * px + 2] = 0.5f + 0.5f * f.z;
                }
                if (desc->vessel) desc->vessel[px] = vessel[k] * inv;
                if (desc->dive) desc->dive[px] = dive[k] * inv;
            }
        }
        sk__loop_progress_tick(&lp);
    }
    sk_progress_report(&desc->progress, 1.0);
    return SK_OK;
}
