/* Pictures of the tissue model through the renderer (include/shitsukan/render.h): a few
 * coloured meshes under a key light and a sky, seen by a fixed camera (so the frames of a
 * sequence line up). Used by the layer pictures and the jiggle sequences. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "shitsukan/render.h"
#include "products/tissue/tissue_draw_internal.h"

sk__view sk__view_framing(sk_vec3d lo, sk_vec3d hi, sk_vec3d direction, sk_vec3d up, double fov_deg,
                          double aspect)
{
    sk__view v;
    v.target = sk_v3d_scale(sk_v3d_add(lo, hi), 0.5);
    /* the box's half extents seen across the view direction fill the frame */
    sk_vec3d d = sk_v3d_normalize(direction);
    if (fabs(sk_v3d_dot(d, sk_v3d_normalize(up))) > 0.99) up = sk__axis_across(d);
    sk_vec3d right = sk_v3d_normalize(sk_v3d_cross(up, d)), top = sk_v3d_cross(d, right);
    double w = 0.0, h = 0.0, depth = 0.0;
    for (int c = 0; c < 8; c++) {
        sk_vec3d p = sk_v3d((c & 1) ? hi.x : lo.x, (c & 2) ? hi.y : lo.y, (c & 4) ? hi.z : lo.z);
        sk_vec3d q = sk_v3d_sub(p, v.target);
        w = fmax(w, fabs(sk_v3d_dot(q, right)));
        h = fmax(h, fabs(sk_v3d_dot(q, top)));
        depth = fmax(depth, fabs(sk_v3d_dot(q, d)));
    }
    double half = tan(0.5 * fov_deg * SK_DEG_TO_RAD);
    double dist = fmax(h, w / aspect) * 1.08 / half + depth;
    v.position = sk_v3d_add(v.target, sk_v3d_scale(d, dist));
    v.up = top;
    v.fov_deg = fov_deg;
    return v;
}

static void put3(float *dst, sk_vec3d v)
{
    dst[0] = (float)v.x;
    dst[1] = (float)v.y;
    dst[2] = (float)v.z;
}

sk_result sk__render_items(const sk__render_item *items, int count, const sk__view *view, int width,
                           int height, int samples, bool occlusion, const char *png_path,
                           sk_error *err)
{
    if (count > SK_RENDER_MAX_MATERIALS)
        return sk_fail(err, SK_ERROR_LIMIT, "too many layers to render");
    sk_render_scene_desc *d = calloc(1, sizeof *d);
    if (!d) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for a render");
    d->image.width = width;
    d->image.height = height;
    d->image.samples = samples;
    d->film.opaque = true;
    d->film.background[0] = d->film.background[1] = d->film.background[2] = 1.0f;
    d->film.tonemap = SK_RENDER_TONEMAP_FILMIC;
    d->film.exposure = 0.0f;
    d->camera.fov = (float)(view->fov_deg * SK_DEG_TO_RAD);
    put3(d->camera.position, view->position);
    put3(d->camera.target, view->target);
    put3(d->camera.up, view->up);
    d->environment.radiance[0] = d->environment.radiance[1] = d->environment.radiance[2] = 0.3f;
    d->environment.ambient_occlusion = occlusion;
    d->environment.ao_samples = 1;
    d->environment.ao_distance = 60.0f;
    d->light_count = 2;
    /* key light from the camera's upper left, a weaker fill from the right */
    sk_vec3d to_target = sk_v3d_normalize(sk_v3d_sub(view->target, view->position));
    sk_vec3d right = sk_v3d_normalize(sk_v3d_cross(to_target, view->up));
    sk_vec3d key = sk_v3d_normalize(
        sk_v3d_sub(sk_v3d_add(to_target, sk_v3d_scale(right, 0.6)), sk_v3d_scale(view->up, 0.8)));
    sk_vec3d fill = sk_v3d_normalize(sk_v3d_sub(to_target, sk_v3d_scale(right, 0.9)));
    put3(d->lights[0].direction, key);
    d->lights[0].intensity = 1.9f;
    put3(d->lights[1].direction, fill);
    d->lights[1].intensity = 0.5f;
    d->lights[1].no_shadows = true;
    d->material_count = count;
    d->object_count = count;
    for (int i = 0; i < count; i++) {
        sk_render_material_desc *mat = &d->materials[i];
        snprintf(mat->name, sizeof mat->name, "layer%d", i);
        memcpy(mat->albedo, items[i].color, sizeof mat->albedo);
        mat->specular = items[i].specular;
        mat->shininess = 40.0f;
        sk_render_object_desc *o = &d->objects[i];
        snprintf(o->name, sizeof o->name, "layer%d", i);
        snprintf(o->material, sizeof o->material, "layer%d", i);
        o->mesh = items[i].mesh;
    }
    sk_render_scene *scene = NULL;
    sk_image image = {0};
    sk_result r = sk_render_scene_create(d, &scene, err);
    if (r == SK_OK) r = sk_render_scene_render(scene, NULL, &image, NULL, err);
    if (r == SK_OK) r = sk_render_write(&image, &d->film, png_path, NULL, err);
    sk_image_free(&image);
    sk_render_scene_destroy(scene);
    free(d);
    return r;
}

bool sk__in_wedge(const sk__wedge *w, const float *p)
{
    return p[0] * w->n[0].x + p[1] * w->n[0].y + p[2] * w->n[0].z > w->offset[0] &&
           p[0] * w->n[1].x + p[1] * w->n[1].y + p[2] * w->n[1].z > w->offset[1];
}

/* Whether triangle t has all three corners in the wedge (then it is cut away). */
static bool cut_away(const sk_mesh *in, size_t t, const sk__wedge *w)
{
    for (int k = 0; k < 3; k++)
        if (!sk__in_wedge(w, in->positions + 3 * in->indices[3 * t + (size_t)k])) return false;
    return true;
}

sk_result sk__mesh_cut(const sk_mesh *in, const sk__wedge *w, sk_mesh *out, sk_error *err)
{
    memset(out, 0, sizeof *out);
    size_t keep = 0;
    for (size_t t = 0; t < in->triangle_count; t++) keep += !cut_away(in, t, w);
    sk_result r = sk_mesh_create(out, in->vertex_count, keep ? keep : 1,
                                 in->normals ? SK_MESH_NORMALS : 0, err);
    if (r != SK_OK) return r;
    memcpy(out->positions, in->positions, in->vertex_count * 3 * sizeof(float));
    if (in->normals) memcpy(out->normals, in->normals, in->vertex_count * 3 * sizeof(float));
    size_t n = 0;
    for (size_t t = 0; t < in->triangle_count; t++)
        if (!cut_away(in, t, w))
            memcpy(out->indices + 3 * n++, in->indices + 3 * t, 3 * sizeof(uint32_t));
    if (n == 0) memset(out->indices, 0, 3 * sizeof(uint32_t));
    out->triangle_count = n ? n : 1;
    return SK_OK;
}

/* A small octahedron at every point of a cloud (for drawing points as beads). */
sk_result sk__beads(const sk_mesh *cloud, double radius, const sk__wedge *w, sk_mesh *out,
                    sk_error *err)
{
    memset(out, 0, sizeof *out);
    size_t keep = 0;
    for (size_t i = 0; i < cloud->vertex_count; i++)
        keep += !sk__in_wedge(w, cloud->positions + 3 * i);
    if (keep == 0) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "no points outside the cut");
    sk_result r = sk_mesh_create(out, keep * 6, keep * 8, 0, err);
    if (r != SK_OK) return r;
    static const float dir[6][3] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                    {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
    static const uint32_t face[8][3] = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                                        {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    size_t n = 0;
    for (size_t i = 0; i < cloud->vertex_count; i++) {
        const float *p = cloud->positions + 3 * i;
        if (sk__in_wedge(w, p)) continue;
        for (int k = 0; k < 6; k++)
            for (int c = 0; c < 3; c++)
                out->positions[3 * (6 * n + (size_t)k) + (size_t)c] =
                    p[c] + (float)radius * dir[k][c];
        for (int f = 0; f < 8; f++)
            for (int c = 0; c < 3; c++)
                out->indices[3 * (8 * n + (size_t)f) + (size_t)c] = (uint32_t)(6 * n) + face[f][c];
        n++;
    }
    return sk_mesh_compute_normals(out, err);
}
