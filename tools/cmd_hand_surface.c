/* The hand surface's outputs shared by `hand mesh` and `hand animate`: a posed mesh as
 * OBJ / PLY with the baked skin texture, and the skinned animation as glTF binary.
 * Argument handling and calls into the library only. */
#define _POSIX_C_SOURCE 200809L
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

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

/* A shipped skin preset bound into a skin (NULL and 0 when the preset is missing). */
static int load_skin(const char *name, sk_skin **out)
{
    *out = NULL;
    char path[PATH_MAX];
    if (!cli_find_preset("skin", name, path, sizeof path)) return cli_fail(CLI_EXIT_RUNTIME, "skin preset '%s' not found", name);
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
static int bake_texture(const cli_command *cmd, const cli_args *args, const sk_hand_surface *surface, sk_image *albedo,
                        sk_image *normal)
{
    long long n;
    int rc = cli_get_int(cmd, args, "texture-size", 1024, 64, 8192, &n);
    if (rc) return rc;
    sk_skin *back = NULL, *palm = NULL;
    if ((rc = load_skin("back-of-hand", &back)) || (rc = load_skin("palm", &palm))) {
        sk_skin_destroy(back);
        return rc;
    }
    sk_hand_texture_desc d = {.size = (int)n, .back_skin = back, .palm_skin = palm};
    sk_error err = {0};
    sk_result r = sk_hand_texture_bake(surface, &d, albedo, normal, &err);
    sk_skin_destroy(back);
    sk_skin_destroy(palm);
    return r == SK_OK ? 0 : cli_fail_error(&err);
}

/* --texture PREFIX: PREFIX-albedo.png and PREFIX-normal.png of the atlas. */
static int write_texture(const cli_command *cmd, const cli_args *args, const sk_hand_surface *surface, const char *prefix,
                         char *albedo_path, size_t size)
{
    sk_image albedo, normal;
    int rc = bake_texture(cmd, args, surface, &albedo, &normal);
    if (rc) return rc;
    char normal_path[PATH_MAX];
    snprintf(albedo_path, size, "%s-albedo.png", prefix);
    snprintf(normal_path, sizeof normal_path, "%s-normal.png", prefix);
    sk_png_write_desc linear = {.encoding = SK_PNG_ENCODING_LINEAR};
    sk_error err = {0};
    sk_result r = sk_image_write_png(&albedo, albedo_path, NULL, &err);
    if (r == SK_OK) r = sk_image_write_png(&normal, normal_path, &linear, &err);
    sk_image_free(&albedo);
    sk_image_free(&normal);
    return r == SK_OK ? 0 : cli_fail_error(&err);
}

int hand_write_posed_mesh(const cli_command *cmd, const cli_args *args, const sk_hand_surface *surface, const double *dofs,
                          sk_hand_skinning method, const char *path)
{
    sk_error err = {0};
    sk_mesh posed, out;
    if (sk_hand_surface_pose(surface, dofs, method, &posed, &err) != SK_OK) return cli_fail_error(&err);
    bool ply = has_suffix(path, ".ply");
    sk_result r = sk_hand_surface_export_mesh(surface, posed.positions, posed.normals, ply, &out, &err);
    sk_mesh_free(&posed);
    if (r != SK_OK) return cli_fail_error(&err);
    int rc = 0;
    char albedo[PATH_MAX] = "";
    const char *prefix = cli_get(cmd, args, "texture");
    if (prefix) rc = write_texture(cmd, args, surface, prefix, albedo, sizeof albedo);
    if (!rc) {
        if (ply) r = sk_mesh_write_ply(&out, path, &err);
        else {
            /* the MTL names the albedo relative to the OBJ's folder */
            const char *slash = strrchr(albedo, '/');
            sk_obj_write_desc od = {.texture_path = prefix ? (slash ? slash + 1 : albedo) : NULL, .material_name = "skin"};
            r = sk_mesh_write_obj(&out, path, &od, &err);
        }
        if (r != SK_OK) rc = cli_fail_error(&err);
    }
    sk_mesh_free(&out);
    return rc;
}

int hand_write_glb(const cli_command *cmd, const cli_args *args, const sk_hand_surface *surface, const double *dofs,
                   int frame_count, double fps, bool animation, int lod_count, sk_hand_skinning method, const char *path)
{
    const char *material = cli_get(cmd, args, "material");
    sk_hand_gltf_desc d = {.dofs = dofs, .frame_count = frame_count, .fps = fps, .animation = animation,
                           .weights = method == SK_HAND_SKINNING_RIGID ? SK_HAND_WEIGHTS_NEAREST : SK_HAND_WEIGHTS_SMOOTH};
    if (!material || strcmp(material, "blend") == 0) d.material = SK_HAND_GLTF_MATERIAL_BLEND;
    else if (strcmp(material, "pbr") == 0) d.material = SK_HAND_GLTF_MATERIAL_PBR;
    else return cli_fail(CLI_EXIT_USAGE, "--material '%s' must be blend or pbr", material);
    const sk_hand_surface *lods[SK_HAND_LOD_COUNT] = {surface};
    sk_hand_surface *coarse[SK_HAND_LOD_COUNT] = {NULL};
    int count = lod_count < 1 ? 1 : lod_count > SK_HAND_LOD_COUNT ? SK_HAND_LOD_COUNT : lod_count, rc = 0;
    sk_error err = {0};
    for (int l = 1; l < count && !rc; l++) {
        if (sk_hand_surface_simplify(&coarse[l], surface, sk_hand_lod_triangles[l], &err) != SK_OK) rc = cli_fail_error(&err);
        lods[l] = coarse[l];
    }
    d.lods = lods;
    d.lod_count = count;
    sk_image albedo = {0}, normal = {0};
    if (!rc) rc = bake_texture(cmd, args, surface, &albedo, &normal);
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
        if (end == p || (*end && *end != ',') || f < 0 || f >= frame_count)
            return cli_fail(CLI_EXIT_USAGE, "--mesh-frames '%s': expected frame numbers in [0, %d], comma-separated", text,
                            frame_count - 1);
        use[f] = true;
        p = *end ? end + 1 : end;
    }
    return 0;
}

int hand_animate_surface_outputs(const cli_command *cmd, const cli_args *args, const sk_hand_skeleton *skel,
                                 const double *dofs, int frame_count, double fps)
{
    sk_error err = {0};
    const char *landmarks = cli_get(cmd, args, "landmarks");
    if (landmarks) {
        sk_hand_positions_format fmt = has_suffix(landmarks, ".json") ? SK_HAND_POSITIONS_JSON : SK_HAND_POSITIONS_CSV;
        if (!has_suffix(landmarks, ".json") && !has_suffix(landmarks, ".csv"))
            return cli_fail(CLI_EXIT_USAGE, "--landmarks '%s': the extension must be .json or .csv", landmarks);
        if (sk_hand_landmarks_write(skel, dofs, frame_count, fmt, landmarks, &err) != SK_OK) return cli_fail_error(&err);
    }
    const char *glb = cli_get(cmd, args, "glb"), *dir = cli_get(cmd, args, "meshes-dir");
    if (!glb && !dir) return 0;
    sk_hand_skinning method;
    int rc = hand_parse_skinning(cli_get(cmd, args, "skinning"), &method);
    if (rc) return rc;
    bool *use = malloc((size_t)frame_count * sizeof *use);
    if (!use) return cli_fail(CLI_EXIT_RUNTIME, "out of memory");
    if (dir && (rc = parse_frames(cli_get(cmd, args, "mesh-frames"), frame_count, use))) {
        free(use);
        return rc;
    }
    sk_hand_surface *surface = NULL;
    rc = hand_build_surface(cmd, args, skel, 0, &surface);
    if (!rc && glb) rc = hand_write_glb(cmd, args, surface, dofs, frame_count, fps, true, SK_HAND_LOD_COUNT, method, glb);
    if (!rc && dir && sk_make_dirs(dir, &err) != SK_OK) rc = cli_fail_error(&err);
    const char *prefix = cli_get(cmd, args, "texture");
    char albedo[PATH_MAX] = "";
    if (!rc && dir && prefix) rc = write_texture(cmd, args, surface, prefix, albedo, sizeof albedo);
    for (int f = 0; f < frame_count && !rc && dir; f++) {
        if (!use[f]) continue;
        char path[PATH_MAX];
        snprintf(path, sizeof path, "%s/frame_%04d.obj", dir, f);
        sk_mesh posed, out;
        if (sk_hand_surface_pose(surface, dofs + (size_t)f * SK_HAND_DOF_COUNT, method, &posed, &err) != SK_OK) {
            rc = cli_fail_error(&err);
            break;
        }
        sk_result r = sk_hand_surface_export_mesh(surface, posed.positions, posed.normals, false, &out, &err);
        sk_mesh_free(&posed);
        if (r == SK_OK) r = sk_mesh_write_obj(&out, path, NULL, &err);
        if (r == SK_OK) sk_mesh_free(&out);
        if (r != SK_OK) rc = cli_fail_error(&err);
    }
    sk_hand_surface_destroy(surface);
    free(use);
    return rc;
}
