/* The layers of the model (Shigemori & Kawai Figs. 1-2: bones and muscles as ellipsoids,
 * fat points between them and the skin) written as point clouds and meshes, and shown cut
 * open: the front half of the muscles, the fat and the skin removed, the bones whole. */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <string.h>

#include "shitsukan/io.h"
#include "tissue/draw_internal.h"

static const char *const class_file[SK_TISSUE_POINT_CLASS_COUNT] = {"skin.ply", "fat.ply", "muscle.ply", "bone.ply"};

static void join(char *out, size_t size, const char *dir, const char *name) { snprintf(out, size, "%s/%s", dir, name); }

static sk_result write_files(const sk_tissue_model *m, const char *dir, sk_error *err)
{
    char path[4096];
    sk_result r = SK_OK;
    for (int c = 0; c < SK_TISSUE_POINT_CLASS_COUNT && r == SK_OK; c++) {
        sk_mesh cloud;
        if (sk_tissue_model_points(m, (sk_tissue_point_class)c, &cloud, NULL) != SK_OK) continue; /* none */
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

sk_result sk__draw_layers(const sk_tissue_model *m, const char *png_path, int width, sk_error *err)
{
    sk_mesh skin = {0}, bones = {0}, muscles = {0}, fat = {0}, skin_cut = {0}, muscles_cut = {0}, beads = {0};
    /* a quarter cut out towards the viewer (front, +x side), through the root */
    sk_vec3d root = m->skeleton.rest[m->skeleton.root];
    sk__wedge w = {{sk_v3d(1, 0, 0), sk_v3d(0, 0, 1)}, {root.x, root.z}};
    sk_result r = sk_tissue_model_rest_skin(m, &skin, err);
    if (r == SK_OK) r = sk_tissue_model_ellipsoids(m, SK_TISSUE_POINT_BONE, 48, &bones, err);
    bool has_muscles = m->desc.muscle_count > 0;
    if (r == SK_OK && has_muscles) r = sk_tissue_model_ellipsoids(m, SK_TISSUE_POINT_MUSCLE, 48, &muscles, err);
    if (r == SK_OK) r = sk_tissue_model_points(m, SK_TISSUE_POINT_FAT, &fat, err);
    if (r == SK_OK) r = sk__mesh_cut(&skin, &w, &skin_cut, err);
    if (r == SK_OK && has_muscles) r = sk__mesh_cut(&muscles, &w, &muscles_cut, err);
    if (r == SK_OK) r = sk__beads(&fat, 0.3 * m->grid.spacing, &w, &beads, err);
    if (r == SK_OK) {
        sk_vec3f lo, hi;
        sk_mesh_bounds(&skin, &lo, &hi);
        sk_vec3d l = sk_v3f_to_d(lo), h = sk_v3f_to_d(hi);
        /* a long limb lies across the picture */
        bool tall = h.y - l.y > 2.0 * (h.x - l.x);
        sk_vec3d up = tall ? sk_v3d(1, 0, 0) : sk_v3d(0, 1, 0);
        double across = h.x - l.x + 0.5 * (h.z - l.z), along = h.y - l.y;
        double aspect = sk_clampd(tall ? along / across : across / along, 0.5, 2.5);
        int height = (int)(width / aspect + 0.5);
        sk__view view = sk__view_framing(l, h, tall ? sk_v3d(0.7, 0.0, 1.0) : sk_v3d(0.7, 0.25, 1.0), up, 30.0, aspect);
        sk__render_item items[4] = {
            {&bones, {0.85f, 0.82f, 0.74f}, 0.1f},
            {&beads, {0.95f, 0.72f, 0.18f}, 0.0f},
            {&skin_cut, {0.80f, 0.55f, 0.45f}, 0.05f},
            {&muscles_cut, {0.62f, 0.10f, 0.09f}, 0.15f},
        };
        r = sk__render_items(items, has_muscles ? 4 : 3, &view, width, height, 4, png_path, err);
    }
    sk_mesh_free(&skin);
    sk_mesh_free(&bones);
    sk_mesh_free(&muscles);
    sk_mesh_free(&fat);
    sk_mesh_free(&skin_cut);
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
