/* The hand surface's outputs shared by `hand mesh` and `hand animate`: a posed mesh as
 * OBJ / PLY with the baked skin texture, and the skinned animation as glTF binary; their
 * options, memory and files checked before the work. Argument handling and calls into
 * the library only. */
#define _POSIX_C_SOURCE 200809L
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "cli.h"
#include "cmd_hand_surface.h"
#include "shitsukan/hand.h"
#include "shitsukan/io.h"
#include "shitsukan/skin.h"

static bool has_suffix(const char *s, const char *suffix)
{
    size_t a = strlen(s), b = strlen(suffix);
    return a >= b && strcmp(s + a - b, suffix) == 0;
}

static const char *base_name(const char *path)
{
    const char *slash = strrchr(path, '/');
    return slash ? slash + 1 : path;
}

int hand_surface_plan_parse(const cli_command *cmd, const cli_args *args, const hand_params *params,
                            hand_surface_plan *p)
{
    memset(p, 0, sizeof *p);
    /* the keys surface.*, texture.*, skinning, material with their stated defaults */
    p->desc = params->surface;
    sk_schema_apply_defaults(&sk_hand_surface_schema, &p->desc);
    p->texture = params->texture;
    sk_schema_apply_defaults(&sk_hand_texture_schema, &p->texture);
    p->method = params->skinning ? params->skinning : SK_HAND_SKINNING_DQS;
    p->material = params->material ? params->material : SK_HAND_GLTF_MATERIAL_BLEND;
    const char *flesh = cli_get(cmd, args, "flesh");
    sk_error err = {0};
    if (flesh) {
        if (sk_hand_flesh_load_file(flesh, &p->flesh, &err) != SK_OK) return cli_fail_error(&err);
        p->desc.flesh = &p->flesh;
    }
    p->prefix = cli_get(cmd, args, "texture");
    if (p->prefix) {
        if (!p->prefix[0])
            return cli_fail(CLI_EXIT_USAGE, "--texture needs a PREFIX for its file names");
        snprintf(p->albedo, sizeof p->albedo, "%s-albedo.png", p->prefix);
        snprintf(p->normal, sizeof p->normal, "%s-normal.png", p->prefix);
        p->albedo_out = p->albedo;
        p->normal_out = p->normal;
    }
    return 0;
}

int hand_surface_plan_check_memory(const cli_args *args, const hand_surface_plan *p,
                                   const sk_hand_skeleton *skel, bool bake, int lod_count)
{
    sk_hand_surface_desc d = p->desc;
    double bytes = sk_hand_surface_memory(skel, &d);
    /* the coarser levels are simplified from the finest: a copy of it each, at most */
    if (lod_count > 1) bytes *= 1.0 + 0.5 * (lod_count - 1);
    sk_hand_texture_desc td = p->texture;
    if (bake) bytes += sk_hand_texture_memory(&td);
    char driver[160];
    snprintf(driver, sizeof driver, "the hand surface (--triangles %d)%s", p->desc.triangles,
             bake ? " and its texture (--texture-size)" : "");
    return cli_check_memory(args, bytes, driver);
}

int hand_surface_plan_reserve(hand_surface_plan *p, sk_output_set *set, const char *obj)
{
    sk_error err = {0};
    sk_result r = SK_OK;
    if (p->prefix) {
        r = sk_output_set_file(set, p->albedo, &p->albedo_out, &err);
        if (r == SK_OK) r = sk_output_set_file(set, p->normal, &p->normal_out, &err);
    }
    struct stat st;
    if (r == SK_OK && obj && p->prefix && stat(obj, &st) == 0 &&
        (S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode)))
        return cli_fail(
            CLI_EXIT_USAGE,
            "--texture with -o '%s' (a device or FIFO): the MTL needs an .obj file name", obj);
    if (r == SK_OK && obj && p->prefix) {
        char *mtl = sk_obj_mtl_path(obj);
        if (!mtl) return cli_fail(CLI_EXIT_RUNTIME, "out of memory");
        snprintf(p->mtl, sizeof p->mtl, "%s", mtl);
        free(mtl);
        r = sk_output_set_file(set, p->mtl, &p->mtl_out, &err);
    }
    if (r != SK_OK) {
        sk_error_prefix(&err, r, "--texture");
        return cli_fail_error(&err);
    }
    return 0;
}

int hand_build_surface(const hand_surface_plan *p, const sk_hand_skeleton *skel, int lod,
                       sk_hand_surface **out)
{
    *out = NULL;
    sk_error err = {0};
    sk_hand_surface *base;
    if (sk_hand_surface_create(&base, skel, &p->desc, &err) != SK_OK) return cli_fail_error(&err);
    if (lod == 0) {
        *out = base;
        return 0;
    }
    sk_hand_surface *coarse;
    sk_result r = sk_hand_surface_simplify(&coarse, base, sk_hand_lod_triangles[lod], &err);
    sk_hand_surface_destroy(base);
    if (r != SK_OK) return cli_fail_error(&err);
    *out = coarse;
    return 0;
}

int hand_load_skin(const char *name, sk_skin **out)
{
    *out = NULL;
    char path[PATH_MAX];
    if (!cli_find_preset("skin", name, path, sizeof path))
        return cli_fail(CLI_EXIT_RUNTIME, "skin preset '%s' not found", name);
    sk_error err = {0};
    sk_preset *p = NULL;
    sk_skin_desc d = {0};
    sk_result r = sk_preset_load_file(&p, path, &err);
    if (r == SK_OK) r = sk_preset_bind(p, &sk_skin_schema, &d, &err);
    sk_preset_free(p);
    if (r == SK_OK) r = sk_skin_create(out, &d, &err);
    return r == SK_OK ? 0 : cli_fail_error(&err);
}

/* The atlas's albedo and normal map at --texture-size, with the skin module's microrelief. */
static int bake_texture(const hand_surface_plan *p, const sk_hand_surface *surface,
                        sk_image *albedo, sk_image *normal)
{
    sk_skin *back = NULL, *palm = NULL;
    int rc;
    if ((rc = hand_load_skin("back-of-hand", &back)) || (rc = hand_load_skin("palm", &palm))) {
        sk_skin_destroy(back);
        return rc;
    }
    sk_hand_texture_desc d = p->texture;
    d.back_skin = back;
    d.palm_skin = palm;
    sk_error err = {0};
    sk_result r = sk_hand_texture_bake(surface, &d, albedo, normal, &err);
    sk_skin_destroy(back);
    sk_skin_destroy(palm);
    return r == SK_OK ? 0 : cli_fail_error(&err);
}

/* --texture PREFIX: PREFIX-albedo.png and PREFIX-normal.png of the atlas. */
static int write_texture(const hand_surface_plan *p, const sk_hand_surface *surface)
{
    sk_image albedo, normal;
    int rc = bake_texture(p, surface, &albedo, &normal);
    if (rc) return rc;
    sk_png_write_desc linear = {.encoding = SK_PNG_ENCODING_LINEAR};
    sk_error err = {0};
    sk_result r = sk_image_write_png(&albedo, p->albedo_out, NULL, &err);
    if (r == SK_OK) r = sk_image_write_png(&normal, p->normal_out, &linear, &err);
    sk_image_free(&albedo);
    sk_image_free(&normal);
    return r == SK_OK ? 0 : cli_fail_error(&err);
}

int hand_write_posed_mesh(const hand_surface_plan *p, const sk_hand_surface *surface,
                          const double *dofs, const char *path)
{
    sk_error err = {0};
    sk_mesh posed, out;
    if (sk_hand_surface_pose(surface, dofs, p->method, &posed, &err) != SK_OK)
        return cli_fail_error(&err);
    bool ply = has_suffix(path, ".ply");
    sk_result r =
        sk_hand_surface_export_mesh(surface, posed.positions, posed.normals, ply, &out, &err);
    sk_mesh_free(&posed);
    if (r != SK_OK) return cli_fail_error(&err);
    int rc = p->prefix ? write_texture(p, surface) : 0;
    if (!rc) {
        if (ply) {
            r = sk_mesh_write_ply(&out, path, &err);
        } else {
            /* the MTL names the albedo relative to the OBJ's folder, by its final name */
            sk_obj_write_desc od = {.material_name = "skin"};
            if (p->prefix) {
                od.texture_path = base_name(p->albedo);
                od.mtl_path = p->mtl_out;
                od.mtl_name = base_name(p->mtl);
            }
            r = sk_mesh_write_obj(&out, path, &od, &err);
        }
        if (r != SK_OK) rc = cli_fail_error(&err);
    }
    sk_mesh_free(&out);
    return rc;
}

int hand_write_glb(const hand_surface_plan *p, const sk_hand_surface *surface, const double *dofs,
                   int frame_count, double fps, bool animation, int lod_count, const char *path)
{
    sk_hand_gltf_desc d = {.dofs = dofs,
                           .frame_count = frame_count,
                           .fps = fps,
                           .animation = animation,
                           .material = p->material,
                           .weights = p->method == SK_HAND_SKINNING_RIGID ? SK_HAND_WEIGHTS_NEAREST
                                                                          : SK_HAND_WEIGHTS_SMOOTH};
    const sk_hand_surface *lods[SK_HAND_LOD_COUNT] = {surface};
    sk_hand_surface *coarse[SK_HAND_LOD_COUNT] = {NULL};
    int count = lod_count < 1                   ? 1
                : lod_count > SK_HAND_LOD_COUNT ? SK_HAND_LOD_COUNT
                                                : lod_count,
        rc = 0;
    sk_error err = {0};
    for (int l = 1; l < count && !rc; l++) {
        if (sk_hand_surface_simplify(&coarse[l], surface, sk_hand_lod_triangles[l], &err) != SK_OK)
            rc = cli_fail_error(&err);
        lods[l] = coarse[l];
    }
    d.lods = lods;
    d.lod_count = count;
    sk_image albedo = {0}, normal = {0};
    if (!rc) rc = bake_texture(p, surface, &albedo, &normal);
    d.albedo = &albedo;
    d.normal_map = &normal;
    if (!rc && sk_hand_gltf_write(&d, path, &err) != SK_OK) rc = cli_fail_error(&err);
    sk_image_free(&albedo);
    sk_image_free(&normal);
    for (int l = 1; l < count; l++) sk_hand_surface_destroy(coarse[l]);
    return rc;
}

/* --mesh-frames "0,5,10": marks the listed frames (all when absent). */
static int parse_frames(const char *text, int frame_count, bool *use)
{
    for (int f = 0; f < frame_count; f++) use[f] = text == NULL;
    if (!text) return 0;
    const char *p = text;
    while (*p) {
        char *end;
        long f = strtol(p, &end, 10);
        if (end == p || (*end && *end != ',') || (*end == ',' && !end[1]) || f < 0 ||
            f >= frame_count || (*p < '0' || *p > '9'))
            return cli_fail(
                CLI_EXIT_USAGE,
                "--mesh-frames '%s': expected frame numbers in [0, %d], comma-separated", text,
                frame_count - 1);
        use[f] = true;
        p = *end ? end + 1 : end;
    }
    if (!text[0]) return cli_fail(CLI_EXIT_USAGE, "--mesh-frames is empty");
    return 0;
}

int hand_animate_surface_parse(const cli_command *cmd, const cli_args *args,
                               const hand_params *params, int frame_count, hand_animate_surface *s)
{
    memset(s, 0, sizeof *s);
    s->glb = cli_get(cmd, args, "glb");
    s->landmarks = cli_get(cmd, args, "landmarks");
    s->meshes_dir = cli_get(cmd, args, "meshes-dir");
    int rc = hand_surface_plan_parse(cmd, args, params, &s->plan);
    if (rc || !s->meshes_dir) return rc;
    s->use = malloc((size_t)frame_count * sizeof *s->use);
    if (!s->use) return cli_fail(CLI_EXIT_RUNTIME, "out of memory");
    return parse_frames(cli_get(cmd, args, "mesh-frames"), frame_count, s->use);
}

void hand_animate_surface_free(hand_animate_surface *s)
{
    free(s->use);
    s->use = NULL;
}

int hand_animate_surface_write(const hand_animate_surface *s, const sk_hand_skeleton *skel,
                               const double *dofs, int frame_count, double fps)
{
    sk_error err = {0};
    if (s->landmarks) {
        sk_hand_positions_format fmt =
            has_suffix(s->landmarks, ".json") ? SK_HAND_POSITIONS_JSON : SK_HAND_POSITIONS_CSV;
        if (sk_hand_landmarks_write(skel, dofs, frame_count, fmt, s->landmarks, &err) != SK_OK)
            return cli_fail_error(&err);
    }
    if (!s->glb && !s->meshes_dir) return 0;
    sk_hand_surface *surface = NULL;
    int rc = hand_build_surface(&s->plan, skel, 0, &surface);
    if (!rc && s->glb)
        rc = hand_write_glb(&s->plan, surface, dofs, frame_count, fps, true, SK_HAND_LOD_COUNT,
                            s->glb);
    if (!rc && s->meshes_dir && s->plan.prefix) rc = write_texture(&s->plan, surface);
    for (int f = 0; f < frame_count && !rc && s->meshes_dir; f++) {
        if (!s->use[f]) continue;
        char path[PATH_MAX];
        snprintf(path, sizeof path, "%s/frame_%04d.obj", s->meshes_dir, f);
        sk_mesh posed, out;
        if (sk_hand_surface_pose(surface, dofs + (size_t)f * SK_HAND_DOF_COUNT, s->plan.method,
                                 &posed, &err) != SK_OK) {
            rc = cli_fail_error(&err);
            break;
        }
        sk_result r =
            sk_hand_surface_export_mesh(surface, posed.positions, posed.normals, false, &out, &err);
        sk_mesh_free(&posed);
        if (r == SK_OK) {
            r = sk_mesh_write_obj(&out, path, NULL, &err);
            sk_mesh_free(&out);
        }
        if (r != SK_OK) rc = cli_fail_error(&err);
    }
    sk_hand_surface_destroy(surface);
    return rc;
}
