/* The hand surface's skin texture (thesis 4.1.6): every atlas texel rasterised back to
 * its point on the relaxed surface, where the colour (generated, or the palm and back
 * photos by planar projection through the model's x-y coordinates, softened across the
 * sides as the thesis blurred its photos' outlines by hand) and a height field are
 * evaluated; the height field's slopes become the tangent-space normal map. The
 * microrelief comes from the skin module (Ishii et al. 1991) through its public API. */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "models/hand_surface/surface_internal.h"

/* A periodic tile of a skin's height field, sampled once and read bilinearly. */
typedef struct relief_tile {
    float *h;
    int n;
    double size[2];
} relief_tile;

static sk_result tile_make(const sk_skin *skin, relief_tile *t, sk_error *err)
{
    memset(t, 0, sizeof *t);
    if (!skin) return SK_OK;
    sk_skin_tile_size(skin, &t->size[0], &t->size[1]);
    t->n = (int)fmin(1024.0, ceil(fmax(t->size[0], t->size[1]) / 0.04));
    t->h = malloc((size_t)t->n * (size_t)t->n * sizeof *t->h);
    if (!t->h) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for the skin relief");
    sk_skin_render_desc d = {.width = t->n, .height = t->n, .height_mm = t->h};
    return sk_skin_render(skin, &d, err);
}

static double tile_height(const relief_tile *t, double x, double y)
{
    if (!t->h) return 0.0;
    double u = sk_fmodpos(x / t->size[0], 1.0) * t->n,
           v = (1.0 - sk_fmodpos(y / t->size[1], 1.0)) * t->n;
    int x0 = (int)floor(u), y0 = (int)floor(v);
    double fx = u - x0, fy = v - y0;
    int x1 = (x0 + 1) % t->n, y1 = (y0 + 1) % t->n;
    x0 %= t->n, y0 %= t->n;
    const float *h = t->h;
    double a = h[y0 * t->n + x0], b = h[y0 * t->n + x1], c = h[y1 * t->n + x0],
           d = h[y1 * t->n + x1];
    return (a + (b - a) * fx) * (1 - fy) + (c + (d - c) * fx) * fy;
}

/* A crease profile: a groove of half-width w at signed distance d. */
static double groove(double d, double w) { return exp(-(d * d) / (w * w)); }

typedef struct bake_ctx {
    const sk_hand_surface *s;
    sk_hand_frames rest;
    relief_tile back, palm;
    double relief, crease, seam;
    double mean_back, mean_palm;
    float lo[2], hi[2]; /* the charts' bounds in the model's x-y coordinates */
} bake_ctx;

/* Heights of the creases at a rest point (right hand) with palm weight w_palm. */
static double creases(const bake_ctx *c, sk_vec3d p, double w_palm)
{
    const sk_hand_skeleton *sk = &c->s->right;
    double h = 0;
    for (int f = 0; f < SK_HAND_FINGER_COUNT; f++) {
        int first = sk__hand_first_link(f), n = sk__hand_link_count_of_finger(f);
        for (int k = 1; k < n; k++) {
            int link = first + k; /* the joint at this link's base */
            sk_vec3d o = c->rest.point[sk_hand_link_point(link)];
            sk_mat3d r = c->rest.rotation[link];
            sk_vec3d d = sk_m3d_apply(sk_m3d_transpose(r), sk_v3d_sub(p, o));
            double along = d.y, across = d.x;
            double reach = 0.55 * (k == 1 ? 20.0 : 16.0) * sk->hand_breadth_mm / 85.0;
            if (fabs(along) > 12.0 || fabs(across) > reach) continue;
            double fade = 1.0 - (across / reach) * (across / reach);
            bool dorsal = d.z < 0;
            if (dorsal && k > 1) {
                /* knuckle wrinkles over PIP and DIP: a few transverse folds */
                for (int i = -2; i <= 2; i++)
                    h -= 0.35 * fade * groove(along - 1.3 * i, 0.35) * (1.0 - w_palm);
            } else if (!dorsal) {
                /* flexion creases: two at the PIP, one at the DIP and at the finger's base */
                double offsets[2] = {k == 2 ? -1.2 : 0.0, k == 2 ? 1.2 : 0.0};
                int count = k == 2 ? 2 : 1;
                double base_shift = k == 1 ? 0.35 * sk->length[link]
                                           : 0.0; /* the finger's base crease lies at the web */
                for (int i = 0; i < count; i++)
                    h -= fade * groove(along - offsets[i] - base_shift, 0.45) * w_palm;
            }
        }
    }
    /* palm creases (the palm chart's plane): distal and proximal transverse, thenar */
    if (w_palm > 0) {
        double hl = sk->hand_length_mm, hb = sk->hand_breadth_mm;
        double x = p.x / hb, y = p.y / hl;
        double distal = y - (0.41 - 0.06 * (x + 0.45)), proximal = y - (0.36 - 0.05 * (x + 0.2));
        if (x > -0.5 && x < 0.12) h -= 0.9 * groove(distal * hl, 0.6) * w_palm;
        if (x > -0.35 && x < 0.3) h -= 0.8 * groove(proximal * hl, 0.6) * w_palm;
        double tx = x - 0.02, ty = y - 0.12;
        double thenar = sqrt(tx * tx * 4.0 + ty * ty) - 0.25;
        if (x > 0.0 && y < 0.36) h -= 0.8 * groove(thenar * hl, 0.7) * w_palm;
    }
    return h * c->crease;
}

typedef struct texel {
    bool covered;
    sk_vec3d p, n;
    double nail;
} texel;

double sk_hand_texture_memory(const sk_hand_texture_desc *desc)
{
    double n = desc && desc->size > 0 ? desc->size : 1024;
    /* the texels being baked, the height field, the albedo and the normal map */
    return n * n * (double)(sizeof(texel) + sizeof(float) + 2 * 3 * sizeof(float));
}

/* One atlas triangle's texels (e: its three export vertices): the rest point, normal and
   nail weight interpolated at each texel it covers. */
static void rasterise_triangle(const sk_hand_surface *s, const sk_mesh_attribute *nail, double flip,
                               const uint32_t *e, int N, texel *tx)
{
    const sk_mesh *m = &s->mesh;
    double u[3], v[3];
    for (int k = 0; k < 3; k++)
        u[k] = s->export_uv[2 * e[k]] * N - 0.5,
        v[k] = (1.0 - s->export_uv[2 * e[k] + 1]) * N - 0.5;
    double area = (u[1] - u[0]) * (v[2] - v[0]) - (u[2] - u[0]) * (v[1] - v[0]);
    if (fabs(area) < 1e-12) return;
    int x0 = (int)fmax(0, floor(fmin(u[0], fmin(u[1], u[2])))),
        x1 = (int)fmin(N - 1, ceil(fmax(u[0], fmax(u[1], u[2]))));
    int y0 = (int)fmax(0, floor(fmin(v[0], fmin(v[1], v[2])))),
        y1 = (int)fmin(N - 1, ceil(fmax(v[0], fmax(v[1], v[2]))));
    for (int y = y0; y <= y1; y++)
        for (int x = x0; x <= x1; x++) {
            double b1 = ((u[2] - x) * (v[0] - y) - (u[0] - x) * (v[2] - y)) / area;
            double b2 = ((u[0] - x) * (v[1] - y) - (u[1] - x) * (v[0] - y)) / area;
            double b0 = 1.0 - b1 - b2;
            if (b0 < -1e-6 || b1 < -1e-6 || b2 < -1e-6) continue;
            texel *te = &tx[(size_t)y * N + x];
            double b[3] = {b0, b1, b2};
            te->covered = true;
            te->p = te->n = sk_v3d(0, 0, 0);
            te->nail = 0;
            for (int k = 0; k < 3; k++) {
                uint32_t vi = s->export_map[e[k]];
                const float *P = m->positions + 3 * (size_t)vi, *Nn = m->normals + 3 * (size_t)vi;
                te->p = sk_v3d_add(te->p, sk_v3d_scale(sk_v3d(flip * P[0], P[1], P[2]), b[k]));
                te->n = sk_v3d_add(te->n, sk_v3d_scale(sk_v3d(flip * Nn[0], Nn[1], Nn[2]), b[k]));
                if (nail) te->nail += b[k] * nail->data[vi];
            }
            te->n = sk_v3d_normalize(te->n);
        }
}

/* rasterise the atlas triangles (right-hand rest positions) */
static void rasterise_atlas(const sk_hand_surface *s, int N, texel *tx)
{
    const sk_mesh *m = &s->mesh;
    const sk_mesh_attribute *nail = sk_mesh_find_attribute(m, "nail");
    double flip = s->skeleton.side == SK_HAND_SIDE_LEFT ? -1.0 : 1.0;
    for (size_t t = 0; t < m->triangle_count; t++)
        rasterise_triangle(s, nail, flip, s->export_indices + 3 * t, N, tx);
}

/* A photo's colour at the chart coordinates (fu, fv): the planar projection's pixel. */
static sk_vec3f photo_colour(const sk_image *ph, double fu, double fv)
{
    float px[4] = {0};
    int ix = (int)sk_clampd(fu * ph->width, 0, ph->width - 1),
        iy = (int)sk_clampd((1.0 - fv) * ph->height, 0, ph->height - 1);
    memcpy(px, sk_image_pixel(ph, ix, iy), (size_t)(ph->channels < 3 ? 1 : 3) * sizeof(float));
    return ph->channels < 3 ? sk_v3f(px[0], px[0], px[0]) : sk_v3f(px[0], px[1], px[2]);
}

/* redder over the knuckles: the weight (0..1) of the nearest PIP or DIP joint at p */
static double knuckle_weight(const bake_ctx *c, sk_vec3d p)
{
    double k = 0;
    for (int f = 1; f < SK_HAND_FINGER_COUNT; f++)
        for (int j = 1; j < 3; j++) {
            sk_vec3d o = c->rest.point[sk_hand_link_point(sk__hand_first_link(f) + j)];
            double dd = sk_v3d_length(sk_v3d_sub(p, o));
            k = fmax(k, exp(-dd * dd / 60.0));
        }
    return k;
}

/* the free edge: the last 15 % of the distal segment (0 before it, 1 at the tip) */
static double nail_edge(const bake_ctx *c, sk_vec3d p)
{
    double t_edge = 0;
    for (int f = 0; f < SK_HAND_FINGER_COUNT; f++) {
        int link = sk__hand_first_link(f) + sk__hand_link_count_of_finger(f) - 1;
        sk_vec3d o = c->rest.point[sk_hand_link_point(link)];
        sk_vec3d l = sk_m3d_apply(sk_m3d_transpose(c->rest.rotation[link]), sk_v3d_sub(p, o));
        if (fabs(l.x) < 12 && l.y > 0 && l.y < c->s->right.length[link] * 1.1)
            t_edge = fmax(t_edge, sk_clampd((l.y / c->s->right.length[link] - 0.8) / 0.08, 0, 1));
    }
    return t_edge;
}

/* The colour of a covered texel with palm weight w: the back's and the palm's (generated
   or from the photos) blended across the sides, and the nail's over it. */
static sk_vec3f texel_colour(const bake_ctx *c, const sk_hand_texture_desc *d, const texel *te,
                             double w)
{
    sk_vec3f back_colour = sk_v3f(0.56f, 0.34f, 0.25f), palm_colour = sk_v3f(0.68f, 0.43f, 0.35f);
    sk_vec3f knuckle = sk_v3f(0.55f, 0.29f, 0.24f), nail_colour = sk_v3f(0.72f, 0.47f, 0.45f),
             edge = sk_v3f(0.86f, 0.8f, 0.72f);
    sk_vec3d p = te->p;
    sk_vec3f back = back_colour, palm = palm_colour;
    double fu = (p.x - c->lo[0]) / (c->hi[0] - c->lo[0]),
           fv = (p.y - c->lo[1]) / (c->hi[1] - c->lo[1]);
    if (d->back_photo) back = photo_colour(d->back_photo, 1.0 - fu, fv);
    if (d->palm_photo) palm = photo_colour(d->palm_photo, fu, fv);
    if (!d->back_photo) back = sk_v3f_lerp(back, knuckle, (float)(0.6 * knuckle_weight(c, p)));
    sk_vec3f col = sk_v3f_lerp(back, palm, (float)w);
    if (te->nail > 0.02) {
        sk_vec3f nc = sk_v3f_lerp(nail_colour, edge, (float)nail_edge(c, p));
        col = sk_v3f_lerp(col, nc, (float)sk_clampd(te->nail, 0, 1));
    }
    return col;
}

/* The albedo and the height field (microrelief and creases, none on the nails) of every
   covered texel. */
static void bake_texels(const bake_ctx *c, const sk_hand_texture_desc *d, const texel *tx, int N,
                        sk_image *albedo, float *height)
{
#pragma omp parallel for schedule(dynamic, 16)
    for (int y = 0; y < N; y++)
        for (int x = 0; x < N; x++) {
            const texel *te = &tx[(size_t)y * N + x];
            if (!te->covered) continue;
            sk_vec3d p = te->p;
            double w = sk_clampd((te->n.z + c->seam) / (2.0 * c->seam), 0.0, 1.0);
            w = w * w * (3 - 2 * w); /* palm weight, smooth across the sides */
            sk_vec3f col = texel_colour(c, d, te, w);
            float *a = sk_image_pixel(albedo, x, y);
            a[0] = col.x, a[1] = col.y, a[2] = col.z;
            double relief =
                (1.0 - w) * tile_height(&c->back, p.x, p.y) + w * tile_height(&c->palm, p.x, p.y);
            height[(size_t)y * N + x] = (float)(c->relief * relief * (1.0 - te->nail) +
                                                creases(c, p, w) * (1.0 - te->nail));
        }
}

/* The tangent-space normal map from the height field's slopes (differences across the
   covered neighbours). */
static void bake_normals(const bake_ctx *c, const texel *tx, const float *height, int N,
                         sk_image *normal_map)
{
    const float *lo = c->lo, *hi = c->hi;
    /* mm per texel on both charts */
    double mm = 1.0 / (N * 0.97 * fmin(0.5 / (hi[0] - lo[0]), 1.0 / (hi[1] - lo[1])));
#pragma omp parallel for schedule(static)
    for (int y = 0; y < N; y++)
        for (int x = 0; x < N; x++) {
            float *o = sk_image_pixel(normal_map, x, y);
            const texel *te = &tx[(size_t)y * N + x];
            double gx = 0, gy = 0;
            if (te->covered) {
                int xl = x > 0 && tx[(size_t)y * N + x - 1].covered ? x - 1 : x;
                int xr = x + 1 < N && tx[(size_t)y * N + x + 1].covered ? x + 1 : x;
                int yu = y > 0 && tx[(size_t)(y - 1) * N + x].covered ? y - 1 : y;
                int yd = y + 1 < N && tx[(size_t)(y + 1) * N + x].covered ? y + 1 : y;
                if (xr > xl)
                    gx = (height[(size_t)y * N + xr] - height[(size_t)y * N + xl]) /
                         ((xr - xl) * mm);
                /* image rows run down, v runs up */
                if (yd > yu)
                    gy = (height[(size_t)yu * N + x] - height[(size_t)yd * N + x]) /
                         ((yd - yu) * mm);
            }
            sk_vec3d n = sk_v3d_normalize(sk_v3d(-gx, -gy, 1.0));
            o[0] = (float)(0.5 * n.x + 0.5), o[1] = (float)(0.5 * n.y + 0.5),
            o[2] = (float)(0.5 * n.z + 0.5);
        }
}

/* grow the charts' colours a few texels outward so filtering at their borders finds skin */
static void grow_charts(texel *tx, int N, sk_image *albedo)
{
    for (int pass = 0; pass < 4; pass++) {
        for (int y = 0; y < N; y++)
            for (int x = 0; x < N; x++) {
                texel *te = &tx[(size_t)y * N + x];
                if (te->covered) continue;
                static const int dx[4] = {1, -1, 0, 0}, dy[4] = {0, 0, 1, -1};
                for (int k = 0; k < 4; k++) {
                    int xx = x + dx[k], yy = y + dy[k];
                    if (xx < 0 || yy < 0 || xx >= N || yy >= N ||
                        !tx[(size_t)yy * N + xx].covered || tx[(size_t)yy * N + xx].nail < 0)
                        continue;
                    memcpy(sk_image_pixel(albedo, x, y), sk_image_pixel(albedo, xx, yy),
                           3 * sizeof(float));
                    te->nail = -1; /* filled this pass, not a source until the next */
                    break;
                }
            }
        for (size_t i = 0; i < (size_t)N * N; i++)
            if (tx[i].nail < 0) tx[i].covered = true, tx[i].nail = 0;
    }
}

sk_result sk_hand_texture_bake(const sk_hand_surface *s, const sk_hand_texture_desc *desc,
                               sk_image *albedo, sk_image *normal_map, sk_error *err)
{
    sk_hand_texture_desc d = {0};
    if (desc) d = *desc;
    /* the defaults and ranges sk_hand_texture_schema states */
    sk_schema_apply_defaults(&sk_hand_texture_schema, &d);
    int N = d.size;
    sk_result r = sk_schema_check(&sk_hand_texture_schema, &d, "", err);
    if (r != SK_OK) return r;
    bake_ctx c = {.s = s,
                  .relief = d.relief_scale,
                  .crease = d.crease_depth_mm,
                  .seam = d.seam_width,
                  .lo = {s->atlas_lo[0], s->atlas_lo[1]},
                  .hi = {s->atlas_hi[0], s->atlas_hi[1]}};
    double q[SK_HAND_DOF_COUNT];
    sk_hand_relaxed(&s->right, q);
    sk_hand_forward(&s->right, q, &c.rest);
    texel *tx = calloc((size_t)N * N, sizeof *tx);
    float *height = calloc((size_t)N * N, sizeof *height);
    memset(albedo, 0, sizeof *albedo);
    memset(normal_map, 0, sizeof *normal_map);
    if (!tx || !height) {
        free(tx), free(height);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for a %d x %d atlas", N, N);
    }
    if ((r = tile_make(d.back_skin, &c.back, err)) == SK_OK)
        r = tile_make(d.palm_skin, &c.palm, err);
    if (r == SK_OK) r = sk_image_create(albedo, N, N, 3, err);
    if (r == SK_OK) r = sk_image_create(normal_map, N, N, 3, err);
    if (r != SK_OK) goto done;
    rasterise_atlas(s, N, tx);
    bake_texels(&c, &d, tx, N, albedo, height);
    bake_normals(&c, tx, height, N, normal_map);
    grow_charts(tx, N, albedo);
done:
    free(tx), free(height), free(c.back.h), free(c.palm.h);
    if (r != SK_OK) {
        sk_image_free(albedo);
        sk_image_free(normal_map);
    }
    return r;
}
