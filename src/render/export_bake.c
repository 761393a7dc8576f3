/* The wood solid texture (Kawai 2000) baked into an image for other tools. A solid texture
 * has no uv parametrisation of its own, so the object gets an atlas: runs of consecutive
 * triangles that share edges (the rows of quads of the primitives) are laid flat at their
 * true size, each unfolded across the edge it shares with the one before (an isometric
 * chart; a run stops where the next triangle would overlap it or the chart would grow too
 * long), the charts are packed in shelves at one scale, the largest that fits (so every
 * part of the object has the same texels per mm and no texel is stretched), the mesh is
 * unwelded onto them, and every texel takes the wood's albedo at the surface point it maps
 * to, in the object frame the renderer evaluates it in (translation and rotation undone,
 * scale kept, mm), filtered over the texel's width. Texels around a triangle take its
 * nearest point, so bilinear filtering never reads an unbaked texel; texels of no chart
 * take the mean. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "render/export_internal.h"

#define GUTTER 2            /* texels around each chart and each triangle */
#define MAX_RUN 512         /* triangles per chart at most (the overlap test is quadratic) */
#define SUPERSAMPLE_MM 0.25 /* texels wider than this take 2 x 2 samples */

/* A run of consecutive triangles laid flat (their corners in `flat`, mm). */
typedef struct chart {
    size_t first, count; /* triangles first .. first + count - 1 */
    float w, h;          /* extent in mm, from (0, 0) */
    int x, y, wt, ht;    /* placement and size in texels, gutter included */
} chart;

/* A triangle laid flat: corners in mm (charts) or texels (the bake). */
typedef struct flat_tri {
    float p[3][2];
} flat_tri;
typedef struct texel_tri {
    double p[3][2];
} texel_tri;

/* The object-frame scale the wood sees (sk_render_surface.object_point keeps it). */
static sk_vec3f object_scale(const sk_render_scene *scene, int object)
{
    const float *s = scene->desc.objects[object].transform.scale;
    if (s[0] == 0 && s[1] == 0 && s[2] == 0) return sk_v3f(1, 1, 1);
    return sk_v3f(s[0], s[1], s[2]);
}

/* Vertex i of the mesh in the wood's object frame, in mm. */
static sk_vec3f object_point(const sk_mesh *m, uint32_t i, sk_vec3f scale, float mm)
{
    return sk_v3f_scale(sk_v3f_mul(sk_v3f_load(m->positions + 3 * i), scale), mm);
}

/* The wood's albedo at barycentric point b of triangle t (footprint in mm, 0 = a point). */
static sk_vec3f wood_at(const sk_render_scene *scene, int object, size_t t, const float b[3],
                        float footprint)
{
    const sk__instance *in = &scene->instances[object];
    const sk_mesh *m = &scene->meshes[in->mesh].mesh;
    sk_vec3f s = object_scale(scene, object);
    const uint32_t *ix = m->indices + 3 * t;
    sk_vec3f p[3], n = sk_v3f(0, 0, 0);
    for (int k = 0; k < 3; k++) {
        p[k] = object_point(m, ix[k], s, scene->desc.unit_mm);
        if (m->normals) n = sk_v3f_add(n, sk_v3f_scale(sk_v3f_load(m->normals + 3 * ix[k]), b[k]));
    }
    /* normals transform with the inverse scale; without any, the triangle's own */
    n = m->normals ? sk_v3f_mul(n, sk_v3f(1 / s.x, 1 / s.y, 1 / s.z))
                   : sk_v3f_cross(sk_v3f_sub(p[1], p[0]), sk_v3f_sub(p[2], p[0]));
    if (!(sk_v3f_dot(n, n) > 0)) n = sk_v3f(0, 0, 1);
    sk_vec3f point = sk_v3f_add(sk_v3f_scale(p[0], b[0]),
                                sk_v3f_add(sk_v3f_scale(p[1], b[1]), sk_v3f_scale(p[2], b[2])));
    sk_wood_sample w;
    sk_wood_eval_filtered(scene->materials[in->material].wood, point, sk_v3f_normalize(n),
                          footprint, &w);
    return sk_v3f(sk_clampf(w.albedo.x, 0, 1), sk_clampf(w.albedo.y, 0, 1),
                  sk_clampf(w.albedo.z, 0, 1));
}

double sk__export_surface_mm2(const sk_render_scene *scene, int object)
{
    const sk_mesh *m = &scene->meshes[scene->instances[object].mesh].mesh;
    sk_vec3f s = object_scale(scene, object);
    float mm = scene->desc.unit_mm;
    double area = 0;
    for (size_t t = 0; t < m->triangle_count; t++) {
        const uint32_t *ix = m->indices + 3 * t;
        sk_vec3f p0 = object_point(m, ix[0], s, mm), p1 = object_point(m, ix[1], s, mm),
                 p2 = object_point(m, ix[2], s, mm);
        area += 0.5 * sk_v3f_length(sk_v3f_cross(sk_v3f_sub(p1, p0), sk_v3f_sub(p2, p0)));
    }
    return area;
}

sk_vec3f sk__export_wood_mean(const sk_render_scene *scene, int object)
{
    const sk_mesh *m = &scene->meshes[scene->instances[object].mesh].mesh;
    sk_vec3f s = object_scale(scene, object);
    static const float points[4][3] = {{1.0f / 3, 1.0f / 3, 1.0f / 3},
                                       {2.0f / 3, 1.0f / 6, 1.0f / 6},
                                       {1.0f / 6, 2.0f / 3, 1.0f / 6},
                                       {1.0f / 6, 1.0f / 6, 2.0f / 3}};
    double sum[3] = {0, 0, 0}, total = 0;
    for (size_t t = 0; t < m->triangle_count; t++) {
        const uint32_t *ix = m->indices + 3 * t;
        sk_vec3f p0 = object_point(m, ix[0], s, 1), p1 = object_point(m, ix[1], s, 1),
                 p2 = object_point(m, ix[2], s, 1);
        double area = 0.5 * sk_v3f_length(sk_v3f_cross(sk_v3f_sub(p1, p0), sk_v3f_sub(p2, p0)));
        if (!(area > 0)) continue;
        for (int k = 0; k < 4; k++) {
            sk_vec3f c = wood_at(scene, object, t, points[k], 0.0f);
            sum[0] += area * c.x, sum[1] += area * c.y, sum[2] += area * c.z;
        }
        total += 4 * area;
    }
    if (!(total > 0)) return sk_v3f(0.5f, 0.5f, 0.5f);
    return sk_v3f((float)(sum[0] / total), (float)(sum[1] / total), (float)(sum[2] / total));
}

/* ------------------------------------------------------------------ charts */

/* Triangle corners q laid flat: corner 0 at the origin, corner 1 along +x. */
static void flatten(const sk_vec3f q[3], float out[3][2])
{
    sk_vec3f e = sk_v3f_sub(q[1], q[0]), c = sk_v3f_sub(q[2], q[0]);
    float len = sk_v3f_length(e);
    out[0][0] = out[0][1] = 0.0f;
    out[1][0] = len, out[1][1] = 0.0f;
    out[2][0] = len > 0 ? sk_v3f_dot(c, e) / len : 0.0f;
    out[2][1] = len > 0 ? sk_v3f_length(sk_v3f_cross(e, c)) / len : sk_v3f_length(c);
}

/* Lays a triangle (3D corners q1) out across the edge it shares with the flat triangle
 * t0 (corners a, b of t0 are corners ia, ib of it): its third corner at its true
 * distances from both, on the other side of the edge from t0's third corner. */
static void unfold(float t0[3][2], int a, int b, const sk_vec3f q1[3], int ia, int ib,
                   float out[3][2])
{
    int ic = 3 - ia - ib, c = 3 - a - b;
    float ax = t0[a][0], ay = t0[a][1], bx = t0[b][0], by = t0[b][1];
    float dx = bx - ax, dy = by - ay, d = sqrtf(dx * dx + dy * dy);
    float du = sk_v3f_length(sk_v3f_sub(q1[ic], q1[ia])),
          dv = sk_v3f_length(sk_v3f_sub(q1[ic], q1[ib]));
    float along = d > 0 ? (du * du - dv * dv + d * d) / (2 * d) : 0.0f;
    float perp = sqrtf(fmaxf(du * du - along * along, 0.0f));
    float ux = d > 0 ? dx / d : 1.0f, uy = d > 0 ? dy / d : 0.0f, nx = -uy, ny = ux;
    float side = (t0[c][0] - ax) * nx + (t0[c][1] - ay) * ny;
    if (side > 0) nx = -nx, ny = -ny;
    out[ia][0] = ax, out[ia][1] = ay;
    out[ib][0] = bx, out[ib][1] = by;
    out[ic][0] = ax + along * ux + perp * nx;
    out[ic][1] = ay + along * uy + perp * ny;
}

/* An edge shared by two triangles (the same vertex indices): corners a, b of i0 are
 * corners ia, ib of i1. */
static bool shared_edge(const uint32_t *i0, const uint32_t *i1, int *a, int *b, int *ia, int *ib)
{
    for (int k = 0; k < 3; k++)
        for (int l = 0; l < 3; l++) {
            if (i0[k] != i1[l]) continue;
            int k2 = (k + 1) % 3;
            for (int l2 = 0; l2 < 3; l2++)
                if (l2 != l && i0[k2] == i1[l2]) {
                    *a = k, *b = k2, *ia = l, *ib = l2;
                    return true;
                }
        }
    return false;
}

/* True if two flat triangles overlap by more than `eps` (separating axes of their 6
 * edges; triangles that only touch along an edge do not overlap). */
static bool overlap(const flat_tri *pt, const flat_tri *qt, float eps)
{
    const float(*p)[2] = pt->p, (*q)[2] = qt->p;
    for (int tri = 0; tri < 2; tri++) {
        const float(*e)[2] = tri ? q : p;
        for (int k = 0; k < 3; k++) {
            float nx = e[(k + 1) % 3][1] - e[k][1], ny = e[k][0] - e[(k + 1) % 3][0];
            float len = sqrtf(nx * nx + ny * ny);
            if (!(len > 0)) continue;
            nx /= len, ny /= len;
            float p_lo = INFINITY, p_hi = -INFINITY, q_lo = INFINITY, q_hi = -INFINITY;
            for (int v = 0; v < 3; v++) {
                float a = p[v][0] * nx + p[v][1] * ny, b = q[v][0] * nx + q[v][1] * ny;
                p_lo = fminf(p_lo, a), p_hi = fmaxf(p_hi, a), q_lo = fminf(q_lo, b),
                q_hi = fmaxf(q_hi, b);
            }
            if (p_hi <= q_lo + eps || q_hi <= p_lo + eps) return false;
        }
    }
    return true;
}

/* Grows a chart from triangle `first` along the following triangles (see the file
 * comment); their flat corners go to flat[t]. Returns the chart's triangle count. */
static size_t grow_chart(const sk_mesh *m, sk_vec3f scale, float mm, size_t first, float max_side,
                         flat_tri *flat)
{
    sk_vec3f q[3];
    const uint32_t *ix = m->indices;
    for (int k = 0; k < 3; k++) q[k] = object_point(m, ix[3 * first + (size_t)k], scale, mm);
    flatten(q, flat[first].p);
    float lo[2] = {0, 0}, hi[2] = {flat[first].p[1][0], 0};
    for (int k = 0; k < 3; k++)
        for (int a = 0; a < 2; a++)
            lo[a] = fminf(lo[a], flat[first].p[k][a]), hi[a] = fmaxf(hi[a], flat[first].p[k][a]);
    size_t count = 1;
    while (first + count < m->triangle_count && count < MAX_RUN) {
        size_t t = first + count;
        /* attached to one of the last two (a quad's triangles take turns) */
        size_t anchor = t - 1;
        int a, b, ia, ib;
        bool attached = shared_edge(ix + 3 * anchor, ix + 3 * t, &a, &b, &ia, &ib);
        if (!attached && count >= 2) {
            anchor = t - 2;
            attached = shared_edge(ix + 3 * anchor, ix + 3 * t, &a, &b, &ia, &ib);
        }
        if (!attached) break;
        for (int k = 0; k < 3; k++) q[k] = object_point(m, ix[3 * t + (size_t)k], scale, mm);
        unfold(flat[anchor].p, a, b, q, ia, ib, flat[t].p);
        float nlo[2] = {lo[0], lo[1]}, nhi[2] = {hi[0], hi[1]};
        for (int k = 0; k < 3; k++)
            for (int c = 0; c < 2; c++)
                nlo[c] = fminf(nlo[c], flat[t].p[k][c]), nhi[c] = fmaxf(nhi[c], flat[t].p[k][c]);
        if (fmaxf(nhi[0] - nlo[0], nhi[1] - nlo[1]) > max_side) break;
        float eps = 1e-4f * fmaxf(nhi[0] - nlo[0], nhi[1] - nlo[1]);
        bool clash = false;
        for (size_t u = first; u < t && !clash; u++) clash = overlap(&flat[u], &flat[t], eps);
        if (clash) break;
        memcpy(lo, nlo, sizeof lo);
        memcpy(hi, nhi, sizeof hi);
        count++;
    }
    for (size_t t = first; t < first + count; t++)
        for (int k = 0; k < 3; k++) flat[t].p[k][0] -= lo[0], flat[t].p[k][1] -= lo[1];
    return count;
}

static size_t make_charts(const sk_mesh *m, sk_vec3f scale, float mm, chart *charts, flat_tri *flat)
{
    /* no chart longer than half the side of a square of the object's whole area (so that
       the packing can keep the scale) or twice its longest edge (so that quads stay whole) */
    double area = 0;
    float longest = 0;
    for (size_t t = 0; t < m->triangle_count; t++) {
        const uint32_t *ix = m->indices + 3 * t;
        sk_vec3f p[3];
        for (int k = 0; k < 3; k++) p[k] = object_point(m, ix[k], scale, mm);
        area += 0.5 * sk_v3f_length(sk_v3f_cross(sk_v3f_sub(p[1], p[0]), sk_v3f_sub(p[2], p[0])));
        for (int k = 0; k < 3; k++)
            longest = fmaxf(longest, sk_v3f_length(sk_v3f_sub(p[(k + 1) % 3], p[k])));
    }
    float max_side = fmaxf((float)(0.5 * sqrt(area)), 2 * longest);
    size_t n = 0;
    for (size_t t = 0; t < m->triangle_count;) {
        chart *c = &charts[n++];
        memset(c, 0, sizeof *c);
        c->first = t;
        c->count = grow_chart(m, scale, mm, t, max_side, flat);
        for (size_t u = t; u < t + c->count; u++)
            for (int k = 0; k < 3; k++)
                c->w = fmaxf(c->w, flat[u].p[k][0]), c->h = fmaxf(c->h, flat[u].p[k][1]);
        /* lying down (wider than tall), shelves waste less; a mirrored chart bakes the same */
        if (c->h > c->w) {
            for (size_t u = t; u < t + c->count; u++)
                for (int k = 0; k < 3; k++) {
                    float x = flat[u].p[k][0];
                    flat[u].p[k][0] = flat[u].p[k][1];
                    flat[u].p[k][1] = x;
                }
            float w = c->w;
            c->w = c->h;
            c->h = w;
        }
        t += c->count;
    }
    return n;
}

static int by_height(const void *a, const void *b)
{
    const chart *x = *(chart *const *)a, *y = *(chart *const *)b;
    if (x->h != y->h) return x->h > y->h ? -1 : 1;
    if (x->w != y->w) return x->w > y->w ? -1 : 1;
    return x->first < y->first ? -1 : x->first > y->first; /* deterministic ties */
}

/* Shelf packing at `s` texels per mm into size x size; false when it does not fit. */
static bool pack(chart **order, size_t n, double s, int size)
{
    int x = 0, y = 0, shelf = 0;
    for (size_t i = 0; i < n; i++) {
        chart *c = order[i];
        double wt = ceil(c->w * s) + 2 * GUTTER + 1, ht = ceil(c->h * s) + 2 * GUTTER + 1;
        if (wt > size || ht > size) return false;
        if (x + (int)wt > size) x = 0, y += shelf, shelf = 0;
        if (y + (int)ht > size) return false;
        c->x = x, c->y = y, c->wt = (int)wt, c->ht = (int)ht;
        x += (int)wt;
        if ((int)ht > shelf) shelf = (int)ht;
    }
    return true;
}

/* The largest scale (texels per mm) at which the charts fit, by bisection; 0 if none. */
static double fit(chart **order, size_t n, int size)
{
    float largest = 0;
    for (size_t i = 0; i < n; i++) largest = fmaxf(largest, fmaxf(order[i]->w, order[i]->h));
    double lo = 0, hi = largest > 0 ? size / largest : 1;
    if (!pack(order, n, lo, size)) return 0;
    for (int it = 0; it < 40; it++) {
        double mid = 0.5 * (lo + hi);
        if (pack(order, n, mid, size))
            lo = mid;
        else
            hi = mid;
    }
    pack(order, n, lo, size);
    return lo;
}

/* ------------------------------------------------------------------ bake */

/* Corner k of flat triangle t of chart c in texel coordinates (x right, y down). */
static void texel_xy(const chart *c, const flat_tri *flat, size_t t, int k, double s, double *x,
                     double *y)
{
    *x = c->x + GUTTER + flat[t].p[k][0] * s;
    *y = c->y + GUTTER + flat[t].p[k][1] * s;
}

/* The unwelded mesh on the atlas: corner k of triangle t is vertex 3 t + k. */
static sk_result atlas_mesh(const sk_mesh *src, const chart *charts, size_t n, const flat_tri *flat,
                            double s, int size, sk_mesh *out, sk_error *err)
{
    int flags = SK_MESH_UVS | (src->normals ? SK_MESH_NORMALS : 0);
    sk_result r = sk_mesh_create(out, 3 * src->triangle_count, src->triangle_count, flags, err);
    if (r != SK_OK) return r;
    for (size_t ci = 0; ci < n; ci++) {
        const chart *c = &charts[ci];
        for (size_t t = c->first; t < c->first + c->count; t++)
            for (int k = 0; k < 3; k++) {
                size_t v = 3 * t + (size_t)k, i = src->indices[v];
                memcpy(out->positions + 3 * v, src->positions + 3 * i, 3 * sizeof(float));
                if (src->normals)
                    memcpy(out->normals + 3 * v, src->normals + 3 * i, 3 * sizeof(float));
                double x, y;
                texel_xy(c, flat, t, k, s, &x, &y);
                out->uvs[2 * v] = (float)(x / size);
                out->uvs[2 * v + 1] = (float)(1.0 - y / size); /* bottom-left origin */
                out->indices[v] = (uint32_t)v;
            }
    }
    return SK_OK;
}

static void barycentric(const texel_tri *tri, double x, double y, float b[3])
{
    const double(*p)[2] = tri->p;
    double ax = p[1][0] - p[0][0], ay = p[1][1] - p[0][1], bx = p[2][0] - p[0][0],
           by = p[2][1] - p[0][1];
    double qx = x - p[0][0], qy = y - p[0][1], det = ax * by - ay * bx;
    if (det == 0) {
        b[0] = 1, b[1] = b[2] = 0;
        return;
    }
    b[1] = (float)((qx * by - qy * bx) / det);
    b[2] = (float)((ax * qy - ay * qx) / det);
    b[0] = 1.0f - b[1] - b[2];
}

static float min3(const float b[3]) { return fminf(b[0], fminf(b[1], b[2])); }

/* Per texel: the triangle it belongs to (the one it lies most inside, its own within the
 * triangle, the nearest around it) and the score of that choice. */
typedef struct texel_owner {
    float *score;
    uint32_t *triangle;
} texel_owner;

static void bake_chart(const sk_render_scene *scene, int object, const chart *c,
                       const flat_tri *flat, double s, sk_image *img, texel_owner owner)
{
    int size = img->width;
    for (size_t t = c->first; t < c->first + c->count; t++) {
        texel_tri p;
        double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
        for (int k = 0; k < 3; k++) {
            texel_xy(c, flat, t, k, s, &p.p[k][0], &p.p[k][1]);
            for (int a = 0; a < 2; a++)
                lo[a] = fmin(lo[a], p.p[k][a]), hi[a] = fmax(hi[a], p.p[k][a]);
        }
        int x0 = (int)fmax(floor(lo[0]) - GUTTER, c->x),
            x1 = (int)fmin(ceil(hi[0]) + GUTTER, c->x + c->wt - 1);
        int y0 = (int)fmax(floor(lo[1]) - GUTTER, c->y),
            y1 = (int)fmin(ceil(hi[1]) + GUTTER, c->y + c->ht - 1);
        for (int y = y0; y <= y1; y++)
            for (int x = x0; x <= x1; x++) {
                float b[3];
                barycentric(&p, x + 0.5, y + 0.5, b);
                size_t i = (size_t)y * (size_t)size + (size_t)x;
                if (min3(b) > owner.score[i])
                    owner.score[i] = min3(b), owner.triangle[i] = (uint32_t)t;
            }
    }
    /* Texels coarser than SUPERSAMPLE_MM take 2 x 2 samples, each filtered over its
       quarter, so that rings and pores finer than a texel average out instead of aliasing
       into moire; texels around the triangles (seen only at their edges) take one. */
    bool super = 1.0 / s > SUPERSAMPLE_MM;
    for (int y = c->y; y < c->y + c->ht; y++)
        for (int x = c->x; x < c->x + c->wt; x++) {
            size_t i = (size_t)y * (size_t)size + (size_t)x;
            if (owner.score[i] == -INFINITY) continue;
            size_t t = owner.triangle[i];
            texel_tri p;
            for (int k = 0; k < 3; k++) texel_xy(c, flat, t, k, s, &p.p[k][0], &p.p[k][1]);
            int n = super && owner.score[i] >= 0 ? 2 : 1;
            float footprint = (float)(1.0 / (s * n));
            sk_vec3f colour = sk_v3f(0, 0, 0);
            for (int sub = 0; sub < n * n; sub++) {
                float b[3], sum = 0.0f;
                barycentric(&p, x + (0.5 + (sub % n)) / n, y + (0.5 + (sub / n)) / n, b);
                for (int k = 0; k < 3; k++) sum += b[k] = fmaxf(b[k], 0.0f); /* the nearest point */
                for (int k = 0; k < 3; k++) b[k] /= sum;
                colour = sk_v3f_add(colour, wood_at(scene, object, t, b, footprint));
            }
            float *px = sk_image_pixel(img, x, y);
            float w = 1.0f / (float)(n * n);
            px[0] = w * colour.x, px[1] = w * colour.y, px[2] = w * colour.z;
        }
}

sk_result sk__export_bake_wood(const sk_render_scene *scene, int object, int size, sk_mesh *mesh,
                               sk_image *albedo, sk_error *err)
{
    const sk_mesh *src = &scene->meshes[scene->instances[object].mesh].mesh;
    size_t t = src->triangle_count, texels = (size_t)size * (size_t)size;
    chart *charts = malloc(t * sizeof *charts);
    chart **order = malloc(t * sizeof *order);
    flat_tri *flat = malloc(t * sizeof *flat);
    texel_owner owner = {malloc(texels * sizeof(float)), malloc(texels * sizeof(uint32_t))};
    sk_result r = charts && order && flat && owner.score && owner.triangle
                      ? SK_OK
                      : sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for an atlas");
    size_t n = 0;
    double s = 0;
    if (r == SK_OK) {
        sk_vec3f scale = object_scale(scene, object);
        n = make_charts(src, scale, scene->desc.unit_mm, charts, flat);
        for (size_t i = 0; i < n; i++) order[i] = &charts[i];
        qsort(order, n, sizeof *order, by_height);
        s = fit(order, n, size);
        if (!(s > 0))
            r = sk_fail(err, SK_ERROR_LIMIT, "objects[%d]: %zu charts do not fit a %d x %d atlas",
                        object, n, size, size);
    }
    if (r == SK_OK) r = atlas_mesh(src, charts, n, flat, s, size, mesh, err);
    if (r == SK_OK && (r = sk_image_create(albedo, size, size, 3, err)) != SK_OK)
        sk_mesh_free(mesh);
    if (r == SK_OK) {
        for (size_t i = 0; i < texels; i++) owner.score[i] = -INFINITY;
            /* charts own disjoint rectangles of the image */
#pragma omp parallel for schedule(dynamic, 1)
        for (long i = 0; i < (long)n; i++)
            bake_chart(scene, object, &charts[i], flat, s, albedo, owner);
        /* texels of no triangle (seen only through coarse mipmaps): the mean of the others */
        double sum[3] = {0, 0, 0}, count = 0;
        for (size_t i = 0; i < texels; i++)
            if (owner.score[i] != -INFINITY) {
                for (int c = 0; c < 3; c++) sum[c] += albedo->data[3 * i + (size_t)c];
                count++;
            }
        for (size_t i = 0; i < texels; i++)
            if (owner.score[i] == -INFINITY)
                for (int c = 0; c < 3; c++)
                    albedo->data[3 * i + (size_t)c] = (float)(sum[c] / count);
    }
    free(charts);
    free(order);
    free(flat);
    free(owner.score);
    free(owner.triangle);
    return r;
}
