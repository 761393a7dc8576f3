/* The layers of the model (Shigemori & Kawai Figs. 1-2: bones and muscles as ellipsoids,
 * fat points between them and the skin) written as point clouds and meshes, and shown cut
 * open: everything beyond a plane through the root removed, the fat points at the cut
 * drawn as beads. */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <string.h>

#include "shitsukan/io.h"
#include "products/tissue/tissue_draw_internal.h"

static const char *const class_file[SK_TISSUE_POINT_CLASS_COUNT] = {"skin.ply", "fat.ply",
                                                                    "muscle.ply", "bone.ply"};

static void join(char *out, size_t size, const char *dir, const char *name)
{
    snprintf(out, size, "%s/%s", dir, name);
}

static sk_result write_files(const sk_tissue_model *m, const char *dir, sk_error *err)
{
    char path[4096];
    sk_result r = SK_OK;
    for (int c = 0; c < SK_TISSUE_POINT_CLASS_COUNT && r == SK_OK; c++) {
        sk_mesh cloud;
        if (sk_tissue_model_points(m, (sk_tissue_point_class)c, &cloud, NULL) != SK_OK)
            continue; /* none */
        join(path, sizeof path, dir, class_file[c]);
        r = sk_mesh_write_ply(&cloud, path, err);
        sk_mesh_free(&cloud);
    }
    const sk_tissue_point_class shapes[2] = {SK_TISSUE_POINT_BONE, SK_TISSUE_POINT_MUSCLE};
    const char *names[2] = {"bones.obj", "muscles.obj"};
    for (int k = 0; k < 2 && r == SK_OK; k++) {
        sk_mesh mesh;
        if (sk_tissue_model_ellipsoids(m, shapes[k], 32, &mesh, NULL) != SK_OK) continue;
        join(path, sizeof path, dir, names[k]);
        r = sk_mesh_write_obj(&mesh, path, NULL, err);
        sk_mesh_free(&mesh);
    }
    if (r == SK_OK) {
        sk_mesh skin;
        r = sk_tissue_model_rest_skin(m, &skin, err);
        join(path, sizeof path, dir, "rest.obj");
        if (r == SK_OK) r = sk_mesh_write_obj(&skin, path, NULL, err);
        sk_mesh_free(&skin);
    }
    return r;
}

/* The fat points within two spacings behind the cut plane (so the cut shows a band of
 * fat, not the fat hidden under the skin). */
static sk_result fat_slice(const sk_mesh *fat, sk_vec3d n, double offset, double depth,
                           sk_mesh *out, sk_error *err)
{
    sk__wedge keep_out = {{n, n}, {offset, offset}};
    sk_mesh near = {0};
    size_t count = 0;
    for (size_t i = 0; i < fat->vertex_count; i++) {
        const float *p = fat->positions + 3 * i;
        double d = p[0] * n.x + p[1] * n.y + p[2] * n.z;
        count += d <= offset && d > offset - depth;
    }
    if (count == 0) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "no fat points at the cut");
    sk_result r = sk_mesh_create(&near, count, 0, 0, err);
    if (r != SK_OK) return r;
    size_t k = 0;
    for (size_t i = 0; i < fat->vertex_count; i++) {
        const float *p = fat->positions + 3 * i;
        double d = p[0] * n.x + p[1] * n.y + p[2] * n.z;
        if (d <= offset && d > offset - depth)
            memcpy(near.positions + 3 * k++, p, 3 * sizeof(float));
    }
    r = sk__beads(&near, 0.32 * depth / 2.0, &keep_out, out, err);
    sk_mesh_free(&near);
    return r;
}

sk_result sk__draw_layers(const sk_tissue_model *m, const char *png_path, int width, sk_error *err)
{
    sk_mesh skin = {0}, bones = {0}, muscles = {0}, fat = {0}, skin_cut = {0}, bones_cut = {0},
            muscles_cut = {0}, beads = {0};
    sk_result r = sk_tissue_model_rest_skin(m, &skin, err);
    if (r != SK_OK) return r;
    sk_vec3f lo, hi;
    sk_mesh_bounds(&skin, &lo, &hi);
    sk_vec3d l = sk_v3f_to_d(lo), h = sk_v3f_to_d(hi);
    /* a limb is cut along its length, seen from the side; a body through its middle, from
       the front: everything beyond the plane through the root is removed */
    bool limb = h.y - l.y > 2.0 * (h.x - l.x);
    sk_vec3d root = m->skeleton.rest[m->skeleton.root];
    sk_vec3d n = limb ? sk_v3d(1, 0, 0) : sk_v3d(0, 0, 1);
    double offset = sk_v3d_dot(n, root) + 0.25 * m->grid.spacing;
    sk__wedge cut = {{n, n}, {offset, offset}};
    r = sk_tissue_model_ellipsoids(m, SK_TISSUE_POINT_BONE, 48, &bones, err);
    bool has_muscles = m->desc.muscle_count > 0;
    if (r == SK_OK && has_muscles)
        r = sk_tissue_model_ellipsoids(m, SK_TISSUE_POINT_MUSCLE, 48, &muscles, err);
    if (r == SK_OK) r = sk_tissue_model_points(m, SK_TISSUE_POINT_FAT, &fat, err);
    if (r == SK_OK) r = sk__mesh_cut(&skin, &cut, &skin_cut, err);
    if (r == SK_OK) r = sk__mesh_cut(&bones, &cut, &bones_cut, err);
    if (r == SK_OK && has_muscles) r = sk__mesh_cut(&muscles, &cut, &muscles_cut, err);
    if (r == SK_OK) r = fat_slice(&fat, n, offset, 2.0 * m->grid.spacing, &beads, err);
    if (r == SK_OK) {
        sk_vec3d up = limb ? sk_v3d(0, 0, 1) : sk_v3d(0, 1, 0);
        sk_vec3d dir = limb ? sk_v3d(1.0, 0.15, 0.3) : sk_v3d(0.3, 0.15, 1.0);
        double across = limb ? h.y - l.y : h.x - l.x,
               along = limb ? h.z - l.z + 0.3 * (h.x - l.x) : h.y - l.y;
        if (limb) up = sk_v3d(0, 0, 1); /* the limb lies across the picture */
        double aspect = sk_clampd(across / along, 0.5, 3.0);
        int height = (int)(width / aspect + 0.5);
        sk__view view = sk__view_framing(l, h, dir, up, 30.0, aspect);
        sk__render_item items[4] = {
            {&bones_cut, {0.85f, 0.82f, 0.74f}, 0.1f},
            {&beads, {0.95f, 0.72f, 0.18f}, 0.0f},
            {&skin_cut, {0.80f, 0.55f, 0.45f}, 0.05f},
            {&muscles_cut, {0.62f, 0.10f, 0.09f}, 0.15f},
        };
        r = sk__render_items(items, has_muscles ? 4 : 3, &view, width, height, 4, true, png_path,
                             err);
    }
    sk_mesh_free(&skin);
    sk_mesh_free(&bones);
    sk_mesh_free(&muscles);
    sk_mesh_free(&fat);
    sk_mesh_free(&skin_cut);
    sk_mesh_free(&bones_cut);
    sk_mesh_free(&muscles_cut);
    sk_mesh_free(&beads);
    return r;
}

sk_result sk_tissue_write_layers(const sk_tissue_model *m, const char *dir, sk_error *err)
{
    sk_result r = sk_make_dirs(dir, err);
    if (r == SK_OK) r = write_files(m, dir, err);
    char path[4096];
    join(path, sizeof path, dir, "layers.png");
    if (r == SK_OK) r = sk__draw_layers(m, path, 720, err);
    return r;
}
