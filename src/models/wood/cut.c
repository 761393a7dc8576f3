/* Planar cuts through the solid texture (end grain, flat-sawn, quarter-sawn or any plane),
 * rendered into caller buffers in parallel rows, each row in runs of pixels whose samples
 * are evaluated as one batch (eval.c) and shaded together. Each pixel's position depends
 * only on its coordinates in the full image, and a sample's value not on its batch, so a
 * region is exactly that part of the full image, and the output does not depend on the
 * thread count. A cut whose image columns run across the tree axis and whose rows run
 * along it (flat- and quarter-sawn faces, not tilted) has every sample's place on the
 * cross-section, and all that follows from it (T(r, theta), the ring profile), set by
 * its column: that stage is evaluated once per sub-pixel column and shared by every row
 * and sub-row, the same values a sample would compute. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/loop_progress.h"
#include "base/parallel.h"
#include "models/wood/wood_internal.h"

static sk_vec3f tilt_towards(sk_vec3f n, sk_vec3f up, sk_vec3f side, double incidence,
                             double azimuth)
{
    sk_vec3f dir =
        sk_v3f_add(sk_v3f_scale(up, (float)cos(azimuth)), sk_v3f_scale(side, (float)sin(azimuth)));
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

/* Everything a planar cut's pixels share. */
typedef struct cut_context {
    const sk_wood *wood;
    const sk_wood_cut_desc *desc;
    sk_vec3f n, a, up, light, view; /* unit normal, image right and up; light and view */
    int rx, ry, rw;                 /* region origin and width */
    int S;                          /* samples per pixel along each axis */
    double inv_W, inv_H, width_mm, height_mm;
    double sub[8];                  /* (s + 0.5) / S: sample offsets inside a pixel */
    int pixel_of[SK__WOOD_BATCH];   /* sample j of a span: its pixel */
    double pixel_x[SK__WOOD_BATCH]; /* that pixel's column in the span, and the sample's */
    double sub_x[SK__WOOD_BATCH];   /* offset inside the pixel */
    float footprint, inv;           /* sample footprint (mm); 1 / samples per pixel */
    bool figure, lit;               /* eq. (4) shading; light above the surface */
    sk__figure_light fl;
    unsigned flags;
    /* the cross-section stage of every sub-pixel column of the region (rw S entries,
       sub-column k = pixel k / S, sample k % S), when the cut allows it; else NULL */
    const sk__wood_section *columns;
} cut_context;

/* eq. (4) of the batch's samples under the cut's light (sk__shade_figure_lit), into rgb. */
static void shade_figure_batch(const cut_context *c, const sk__wood_batch *b, int count,
                               float rgb[3][SK__WOOD_BATCH])
{
    const sk__shading *s = &c->wood->shading;
    const sk__figure_light *fl = &c->fl;
    float nx = c->n.x, ny = c->n.y, nz = c->n.z;
    double u[SK__WOOD_BATCH];
    if (!c->lit) {
        for (int k = 0; k < 3; k++)
            for (int j = 0; j < count; j++) rgb[k][j] = 0.0f;
        return;
    }
    /* sk__shade_figure_lit in two loops: the arithmetic vectorized, then the table */
#pragma omp simd
    for (int j = 0; j < count; j++) {
        double sin_a = -(double)(b->fibre[0][j] * nx + b->fibre[1][j] * ny + b->fibre[2][j] * nz);
        u[j] = sk__figure_position(s, fl, sin_a);
    }
    for (int j = 0; j < count; j++) {
        float spec = (float)sk__figure_specular(s, u[j], b->vessel[j]);
        for (int k = 0; k < 3; k++) rgb[k][j] = b->albedo[k][j] * fl->diffuse + spec;
    }
}

/* Adds the batch's values src[j] to out[pixel_of[j]]. With one sample per pixel
 * (`single`, pixel_of[j] = j) the value is stored as 0 + src[j], the same sum without
 * clearing the output first. */
static void accumulate(float *out, const float *src, int count, const int *pixel_of, bool single)
{
    if (single) {
        for (int j = 0; j < count; j++) out[j] = 0.0f + src[j];
    } else {
        for (int j = 0; j < count; j++) out[pixel_of[j]] += src[j];
    }
}

/* accumulate for the three channels of RGB pixels (r, g, b: the batch's arrays). */
static void accumulate_rgb(float *out, const float *r, const float *g, const float *b, int count,
                           const int *pixel_of, bool single)
{
    if (single) {
        for (int j = 0; j < count; j++) {
            out[3 * j + 0] = 0.0f + r[j];
            out[3 * j + 1] = 0.0f + g[j];
            out[3 * j + 2] = 0.0f + b[j];
        }
    } else {
        for (int j = 0; j < count; j++) {
            float *o = out + 3 * pixel_of[j];
            o[0] += r[j];
            o[1] += g[j];
            o[2] += b[j];
        }
    }
}

/* Renders `pixels` (<= SK__WOOD_BATCH / S) pixels of region row yy from region column x0:
 * the samples of each pixel are summed in the output buffers, then scaled to their mean. */
static void render_span(const cut_context *c, int yy, int x0, int pixels)
{
    const sk_wood_cut_desc *desc = c->desc;
    const sk_wood *wood = c->wood;
    sk_vec3f n = c->n, a = c->a, up = c->up;
    float px[SK__WOOD_BATCH], py[SK__WOOD_BATCH], pz[SK__WOOD_BATCH];
    const float *points[3] = {px, py, pz};
    sk__wood_batch b;
    float rgb[3][SK__WOOD_BATCH];
    int Y = c->ry + yy, count = pixels * c->S;
    bool single = c->S == 1;
    size_t px0 = (size_t)yy * (size_t)c->rw + (size_t)x0;
    float *sh = desc->shaded ? desc->shaded + 3 * px0 : NULL;
    float *al = desc->albedo ? desc->albedo + 3 * px0 : NULL;
    float *fi = desc->fibre ? desc->fibre + 3 * px0 : NULL;
    float *ve = desc->vessel ? desc->vessel + px0 : NULL;
    float *dv = desc->dive ? desc->dive + px0 : NULL;
    if (!single) {
        float *rgb_outputs[3] = {sh, al, fi};
        for (int o = 0; o < 3; o++)
            if (rgb_outputs[o]) memset(rgb_outputs[o], 0, 3 * (size_t)pixels * sizeof(float));
        if (ve) memset(ve, 0, (size_t)pixels * sizeof(float));
        if (dv) memset(dv, 0, (size_t)pixels * sizeof(float));
    }
    for (int sy = 0; sy < c->S; sy++) {
        /* the pixel position depends only on (X, Y): regions match the image */
        double fy = 0.5 - (Y + c->sub[sy]) * c->inv_H;
        sk_vec3f row = sk_v3f_add(desc->point, sk_v3f_scale(up, (float)(fy * c->height_mm)));
        double column = c->rx + x0;
        if (c->columns) {
            /* the row's height and the columns' cross-section stage (sk_wood_cut checked
               that x and z follow the column alone and y the row: a.y = 0) */
            double y[SK__WOOD_BATCH];
#pragma omp simd
            for (int j = 0; j < count; j++) {
                double fx = (column + c->pixel_x[j] + c->sub_x[j]) * c->inv_W - 0.5;
                y[j] = row.y + a.y * (float)(fx * c->width_mm); /* row.y, to the sign of 0 */
            }
            size_t k = (size_t)x0 * (size_t)c->S;
            const sk__wood_section *cs = c->columns;
            sk__wood_section sec = {cs->r + k,     cs->cos_t + k, cs->sin_t + k,
                                    cs->theta + k, cs->t + k,     cs->width + k,
                                    cs->dR + k,    cs->half + k,  cs->late + k};
            sk__wood_eval_section_batch(wood, count, &sec, y, n, c->footprint, c->flags, &b);
        } else {
#pragma omp simd
            for (int j = 0; j < count; j++) {
                /* (rx + x0 + pixel + sample offset) / W - 0.5, the integer part exact */
                double fx = (column + c->pixel_x[j] + c->sub_x[j]) * c->inv_W - 0.5;
                float s = (float)(fx * c->width_mm);
                px[j] = row.x + a.x * s;
                py[j] = row.y + a.y * s;
                pz[j] = row.z + a.z * s;
            }
            sk__wood_eval_batch(wood, count, points, n, c->footprint, c->flags, &b);
        }
        if (sh) {
            if (c->figure) {
                shade_figure_batch(c, &b, count, rgb);
            } else {
                for (int j = 0; j < count; j++) {
                    sk_wood_sample smp = {0};
                    smp.albedo = sk_v3f(b.albedo[0][j], b.albedo[1][j], b.albedo[2][j]);
                    smp.vessel = b.vessel[j];
                    smp.fibre = sk_v3f(b.fibre[0][j], b.fibre[1][j], b.fibre[2][j]);
                    smp.up = b.up;
                    sk_vec3f col = sk__shade_fibre(&wood->shading, &smp, n, c->light, c->view);
                    rgb[0][j] = col.x;
                    rgb[1][j] = col.y;
                    rgb[2][j] = col.z;
                }
            }
            accumulate_rgb(sh, rgb[0], rgb[1], rgb[2], count, c->pixel_of, single);
        }
        if (al)
            accumulate_rgb(al, b.albedo[0], b.albedo[1], b.albedo[2], count, c->pixel_of, single);
        if (fi) {
            /* the fibre in the cut's frame (x = image right, y = image up, z = viewer) */
            for (int j = 0; j < count; j++) {
                sk_vec3f f = sk_v3f(b.fibre[0][j], b.fibre[1][j], b.fibre[2][j]);
                rgb[0][j] = sk_v3f_dot(f, a);
                rgb[1][j] = sk_v3f_dot(f, up);
                rgb[2][j] = sk_v3f_dot(f, n);
            }
            accumulate_rgb(fi, rgb[0], rgb[1], rgb[2], count, c->pixel_of, single);
        }
        if (ve) accumulate(ve, b.vessel, count, c->pixel_of, single);
        if (dv) accumulate(dv, b.dive, count, c->pixel_of, single);
    }
    float inv = c->inv;
    if (inv != 1.0f) { /* x * 1 = x: nothing to scale with one sample */
        float *outputs[4] = {sh, al, ve, dv};
        int sizes[4] = {3 * pixels, 3 * pixels, pixels, pixels};
        for (int o = 0; o < 4; o++)
            if (outputs[o])
                for (int k = 0; k < sizes[o]; k++) outputs[o][k] *= inv;
    }
    if (fi)
        for (int k = 0; k < pixels; k++) {
            float *o = fi + 3 * k;
            sk_vec3f sum = sk_v3f(o[0], o[1], o[2]);
            float len = sk_v3f_length(sum);
            sk_vec3f f = len > 0.0f ? sk_v3f_scale(sum, 1.0f / len) : sk_v3f(0, 1, 0);
            o[0] = 0.5f + 0.5f * f.x;
            o[1] = 0.5f + 0.5f * f.y;
            o[2] = 0.5f + 0.5f * f.z;
        }
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
                       "cut region %d,%d,%d,%d does not lie inside the %dx%d image", rx, ry, rw, rh,
                       desc->width, desc->height);
    float nlen = sk_v3f_length(desc->normal);
    if (!(nlen > 1e-12f)) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "cut normal is zero");
    sk_vec3f n = sk_v3f_scale(desc->normal, 1.0f / nlen);
    sk_vec3f a = sk_v3f_sub(desc->axis, sk_v3f_scale(n, sk_v3f_dot(desc->axis, n)));
    float alen = sk_v3f_length(a);
    if (!(alen > 1e-6f * (sk_v3f_length(desc->axis) + 1e-30f)))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "cut axis is zero or along the normal");
    a = sk_v3f_scale(a, 1.0f / alen);
    sk_vec3f up = sk_v3f_cross(n, a);
    int S = desc->samples ? desc->samples : 1;
    double W = desc->width, H = desc->height, width_mm = desc->width_mm;
    sk_vec3f light = tilt_towards(n, up, a, desc->light_incidence, desc->light_azimuth);
    cut_context c = {
        .wood = wood,
        .desc = desc,
        .n = n,
        .a = a,
        .up = up,
        .light = light,
        .view = tilt_towards(n, up, a, desc->view_incidence, 0.0),
        .rx = rx,
        .ry = ry,
        .rw = rw,
        .S = S,
        .inv_W = 1.0 / W,
        .inv_H = 1.0 / H,
        .width_mm = width_mm,
        .height_mm = width_mm * H / W,
        .footprint = (float)(width_mm / W / S),
        .inv = 1.0f / (float)(S * S),
        .figure = wood->shading.model != SK_WOOD_SHADING_FIBRE,
        /* eq. (4)'s light terms are the same for every sample of the plane */
        .fl = sk__figure_light_make(&wood->shading, n,
                                    sk__wood_surface_up(wood, sk_v3f_normalize(n)), light),
        .flags = desc->dive ? SK__WOOD_EVAL_DIVE : 0u,
    };
    c.lit = c.fl.cos_i > 0.0;
    double inv_S = 1.0 / S;
    for (int k = 0; k < S; k++) c.sub[k] = (k + 0.5) * inv_S;
    for (int j = 0; j < SK__WOOD_BATCH; j++) {
        c.pixel_of[j] = j / S;
        c.pixel_x[j] = j / S;
        c.sub_x[j] = c.sub[j % S];
    }
    int batch_pixels = SK__WOOD_BATCH / S;

    /* the shared cross-section stage: x and z of a sample follow its column alone when the
       image's up has no x or z and its right no y, in the tree frame (= the scene's) */
    sk__wood_section columns = {0};
    double *column_store = NULL;
    if (wood->frame.identity && up.x == 0.0f && up.z == 0.0f && a.y == 0.0f) {
        size_t count = (size_t)rw * (size_t)S;
        column_store = malloc(SK__WOOD_SECTION_FIELDS * count * sizeof(double));
        if (column_store) {
            double **fields[SK__WOOD_SECTION_FIELDS] = {
                &columns.r,     &columns.cos_t, &columns.sin_t, &columns.theta, &columns.t,
                &columns.width, &columns.dR,    &columns.half,  &columns.late};
            for (int f = 0; f < SK__WOOD_SECTION_FIELDS; f++)
                *fields[f] = column_store + (size_t)f * count;
            c.columns = &columns;
            int blocks = (int)((count + SK__WOOD_BATCH - 1) / SK__WOOD_BATCH);
#pragma omp parallel for schedule(static) if (sk__parallel_worth(count, 60.0))
            for (int blk = 0; blk < blocks; blk++) {
                size_t k0 = (size_t)blk * SK__WOOD_BATCH;
                int m = count - k0 < SK__WOOD_BATCH ? (int)(count - k0) : SK__WOOD_BATCH;
                float px[SK__WOOD_BATCH], pz[SK__WOOD_BATCH];
                for (int j = 0; j < m; j++) {
                    size_t k = k0 + (size_t)j;
                    /* render_span's sample position, the row's part being 0 in x and z */
                    double fx =
                        ((double)(rx + (int)(k / (size_t)S)) + c.sub[k % (size_t)S]) * c.inv_W -
                        0.5;
                    float sx = (float)(fx * c.width_mm);
                    px[j] = desc->point.x + a.x * sx;
                    pz[j] = desc->point.z + a.z * sx;
                }
                sk__wood_section part = {columns.r + k0,     columns.cos_t + k0, columns.sin_t + k0,
                                         columns.theta + k0, columns.t + k0,     columns.width + k0,
                                         columns.dR + k0,    columns.half + k0,  columns.late + k0};
                sk__wood_section_eval(wood, m, px, pz, n, c.footprint, &part);
            }
        }
    }

    sk__loop_progress lp;
    sk__loop_progress_init(&lp, &desc->progress, rh);
    /* about 100 ns a sample */
    bool parallel = sk__parallel_worth((double)rw * rh * S * S, 100.0);
#pragma omp parallel for schedule(dynamic, 1) if (parallel)
    for (int yy = 0; yy < rh; yy++) {
        for (int x0 = 0; x0 < rw; x0 += batch_pixels) {
            int pixels = rw - x0 < batch_pixels ? rw - x0 : batch_pixels;
            render_span(&c, yy, x0, pixels);
        }
        sk__loop_progress_tick(&lp);
    }
    sk_progress_report(&desc->progress, 1.0);
    free(column_store);
    return SK_OK;
}
