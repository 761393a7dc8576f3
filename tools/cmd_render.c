/* `shitsukan render`: renders a scene file (JSON) to a tone-mapped PNG and/or a linear EXR,
 * with command-line overrides of size, samples, exposure and any scene key. */
#define _POSIX_C_SOURCE 200809L
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "shitsukan/io.h"
#include "shitsukan/render.h"

static const cli_option k_options[] = {
    {"size", 0, "WxH", "image size in pixels (overrides image.width/height)", false},
    {"spp", 0, "N", "camera samples per pixel (overrides image.samples)", false},
    {"exposure", 0, "EV", "exposure in stops (overrides film.exposure)", false},
    {"exr", 0, "PATH", "also write the linear radiance as EXR", false},
    {"stats", 0, NULL, "print camera rays per second and the intersection / shading split", false},
    {"export", 0, "FILE",
     "write the scene's geometry and approximated materials as .glb or .obj "
     "(without -o: no image is rendered)",
     false},
    {"texture-size", 0, "N", "pixels per side of the textures --export bakes (default 1024)",
     false},
    {"no-textures", 0, NULL,
     "--export bakes no textures: wood gets its mean colour, skin no normal map", false},
};

static bool find_preset(void *user, const char *module, const char *name, char *path, size_t size)
{
    (void)user;
    return cli_find_preset(module, name, path, size);
}

/* Applies one formatted --set style assignment to the scene tree. */
static int set_key(sk_preset *scene, const char *assignment)
{
    sk_error err = {0};
    if (sk_preset_set(scene, assignment, &err) != SK_OK) return cli_fail_error(&err);
    return 0;
}

static int apply_overrides(const cli_command *command, const cli_args *args, sk_preset *scene)
{
    char text[96];
    int status, w, h;
    if (cli_has(command, args, "size")) {
        if ((status = cli_get_size(command, args, "size", 0, 0, SK_RENDER_MAX_DIMENSION, &w, &h)))
            return status;
        snprintf(text, sizeof text, "image.width=%d", w);
        if ((status = set_key(scene, text))) return status;
        snprintf(text, sizeof text, "image.height=%d", h);
        if ((status = set_key(scene, text))) return status;
    }
    if (cli_has(command, args, "spp")) {
        long long spp;
        if ((status = cli_get_int(command, args, "spp", 16, 1, SK_RENDER_MAX_SAMPLES, &spp)))
            return status;
        snprintf(text, sizeof text, "image.samples=%lld", spp);
        if ((status = set_key(scene, text))) return status;
    }
    if (cli_has(command, args, "exposure")) {
        double ev;
        if ((status = cli_get_double(command, args, "exposure", 0, -30, 30, &ev))) return status;
        snprintf(text, sizeof text, "film.exposure=%.9g", ev);
        if ((status = set_key(scene, text))) return status;
    }
    return 0;
}

static void default_output(const char *scene_path, char *out, size_t size)
{
    const char *base = strrchr(scene_path, '/');
    base = base ? base + 1 : scene_path;
    size_t n = strlen(base);
    if (n > 5 && strcmp(base + n - 5, ".json") == 0) n -= 5;
    snprintf(out, size, "%.*s.png", (int)n, base);
}

static int write_image(const sk_image *image, const sk_render_film_desc *film, const char *path,
                       const char *scene_path, int samples)
{
    sk_error err = {0};
    sk_image_metadata meta = {0};
    char spp[32];
    snprintf(spp, sizeof spp, "%d", samples);
    sk_image_metadata_set(&meta, "Software", "shitsukan " SK_VERSION_STRING, NULL);
    sk_image_metadata_set(&meta, "shitsukan:scene", scene_path, NULL);
    sk_image_metadata_set(&meta, "shitsukan:samples_per_pixel", spp, NULL);
    sk_image_metadata_set(&meta, "shitsukan:units",
                          "linear radiance, W sr^-1 m^-2 per unit light intensity", NULL);
    if (sk_render_write(image, film, path, &meta, &err) != SK_OK) return cli_fail_error(&err);
    return 0;
}

/* --export: the scene's geometry for other tools, its files reserved in the run's output
 * set (they appear with the image, or nothing does), its memory checked first. */
static int export_scene(const cli_command *command, const cli_args *args,
                        const sk_render_scene *scene, long long size, sk_output_set *outputs)
{
    sk_render_export_desc desc = {.texture_size = (int)size,
                                  .no_textures = cli_has(command, args, "no-textures"),
                                  .outputs = outputs};
    int status =
        cli_check_memory(args, sk_render_scene_export_memory(scene, &desc),
                         "--export (its textures: --texture-size; and the scene's meshes)");
    if (status) return status;
    sk_progress_bar bar;
    sk_progress_bar_begin(&bar, "export", !args->common.quiet);
    desc.progress = sk_progress_bar_sink(&bar);
    sk_error err = {0};
    sk_result r = sk_render_scene_export(scene, cli_get(command, args, "export"), &desc, &err);
    sk_progress_bar_end(&bar);
    return r == SK_OK ? 0 : cli_fail_error(&err);
}

static int run_render(const cli_command *command, const cli_args *args)
{
    if (args->positional_count == 1 && args->common.preset)
        return cli_fail(CLI_EXIT_USAGE, "give either a SCENE file or --preset, not both");
    if (args->positional_count == 0 && !args->common.preset)
        return cli_fail(CLI_EXIT_USAGE, "no scene: give a SCENE file or --preset NAME "
                                        "(see 'shitsukan presets scenes')");
    long long texture_size = 0;
    int status;
    const char *export_path = cli_get(command, args, "export");
    static const char *const k_export[] = {".glb", ".obj", NULL};
    int export_format;
    if (!export_path &&
        (cli_has(command, args, "texture-size") || cli_has(command, args, "no-textures")))
        return cli_fail(CLI_EXIT_USAGE, "--%s needs --export",
                        cli_has(command, args, "texture-size") ? "texture-size" : "no-textures");
    if (export_path && !args->common.output && cli_get(command, args, "exr"))
        return cli_fail(CLI_EXIT_USAGE,
                        "--exr with --export needs -o (without -o, --export renders no image)");
    if (export_path &&
        (status = cli_output_format("--export", export_path, k_export, &export_format)))
        return status;
    if (export_path) {
        sk_error check = {0};
        if (sk_output_check(export_path, &check) != SK_OK) {
            sk_error_prefix(&check, check.result, "--export");
            return cli_fail_error(&check);
        }
    }
    if (cli_has(command, args, "texture-size") &&
        (status = cli_get_int(command, args, "texture-size", 1024, 16, 8192, &texture_size)))
        return status;
    /* the scene tree with every --set applied (a positional SCENE is loaded like --preset) */
    cli_args scene_args = *args;
    if (args->positional_count == 1) scene_args.common.preset = args->positional[0];
    const char *name = scene_args.common.preset;
    char scene_path[PATH_MAX];
    if (strchr(name, '/') || strstr(name, ".json"))
        snprintf(scene_path, sizeof scene_path, "%s", name);
    else if (!cli_find_preset("scenes", name, scene_path, sizeof scene_path))
        snprintf(scene_path, sizeof scene_path, "%s", name); /* cli_load_preset reports it */
    sk_preset *tree = NULL;
    status = cli_load_preset(command, &scene_args, &tree);
    if (status) return status;
    if ((status = apply_overrides(command, args, tree))) {
        sk_preset_free(tree);
        return status;
    }
    sk_render_scene_desc *desc = calloc(1, sizeof *desc);
    if (!desc) {
        sk_preset_free(tree);
        return cli_fail(CLI_EXIT_RUNTIME, "out of memory");
    }
    sk_error err = {0};
    sk_render_load_desc load = {.scene_path = scene_path, .find_preset = find_preset};
    sk_result r = sk_render_scene_desc_bind(tree, &load, desc, &err);
    sk_preset_free(tree);
    /* every output is checked and reserved before the scene is built */
    char output[PATH_MAX];
    if (args->common.output)
        snprintf(output, sizeof output, "%s", args->common.output);
    else
        default_output(scene_path, output, sizeof output);
    const char *exr = cli_get(command, args, "exr");
    static const char *const k_formats[] = {".png", ".exr", NULL}, *const k_exr[] = {".exr", NULL};
    int format;
    if (r == SK_OK && ((status = cli_output_format("-o", output, k_formats, &format)) ||
                       (exr && (status = cli_output_format("--exr", exr, k_exr, &format))))) {
        free(desc);
        return status;
    }
    if (r == SK_OK) {
        int largest;
        double bytes = sk_render_scene_desc_memory(desc, &largest);
        char driver[160];
        if (largest >= 0)
            snprintf(driver, sizeof driver,
                     "the scene (%d objects, the largest objects[%d]: its segments, rings or "
                     "mesh file; and image.width x height)",
                     desc->object_count, largest);
        else
            snprintf(driver, sizeof driver, "the image (image.width x height, --size)");
        if ((status = cli_check_memory(args, bytes, driver))) {
            free(desc);
            return status;
        }
    }
    /* with --export and no -o, no image is rendered */
    bool image_wanted = args->common.output || !export_path;
    sk_output_set *outputs = NULL;
    const char *staged_output = NULL, *staged_exr = NULL;
    if (r == SK_OK) r = sk_output_set_create(&outputs, &err);
    if (r == SK_OK && image_wanted) r = sk_output_set_file(outputs, output, &staged_output, &err);
    if (r == SK_OK && exr) r = sk_output_set_file(outputs, exr, &staged_exr, &err);
    sk_render_scene *scene = NULL;
    if (r == SK_OK) r = sk_render_scene_create(desc, &scene, &err);
    free(desc);
    if (r != SK_OK) {
        sk_output_set_abort(outputs);
        return cli_fail_error(&err);
    }

    const sk_render_scene_desc *d = sk_render_scene_get_desc(scene);
    if (export_path) {
        status = export_scene(command, args, scene, texture_size, outputs);
        if (status || !image_wanted) {
            sk_render_scene_destroy(scene);
            return cli_finish_outputs(outputs, status);
        }
    }
    sk_progress_bar bar;
    sk_progress_bar_begin(&bar, "render", !args->common.quiet);
    sk_render_options options = {.progress = sk_progress_bar_sink(&bar),
                                 .timing = cli_has(command, args, "stats")};
    sk_render_stats stats;
    sk_image image = {0};
    r = sk_render_scene_render(scene, &options, &image, &stats, &err);
    sk_progress_bar_end(&bar);
    if (r != SK_OK) {
        sk_render_scene_destroy(scene);
        sk_output_set_abort(outputs);
        return cli_fail_error(&err);
    }
    status = write_image(&image, &d->film, staged_output, scene_path, d->image.samples);
    if (!status && exr)
        status = write_image(&image, &d->film, staged_exr, scene_path, d->image.samples);
    if (!status && sk_output_set_commit(outputs, &err) != SK_OK)
        status = cli_fail_error(&err);
    else if (status)
        sk_output_set_abort(outputs);
    if (!status && options.timing) {
        double busy = stats.intersect_seconds + stats.shade_seconds;
        fprintf(stderr,
                "render: %dx%d, %d spp: %.3f s wall, %.2f M camera rays/s, %.2f M shadow rays; "
                "intersection %.0f %%, shading %.0f %% of %.3f thread-s\n",
                d->image.width, d->image.height, d->image.samples, stats.seconds,
                stats.camera_rays_per_second / 1e6, (double)stats.shadow_rays / 1e6,
                busy > 0 ? 100 * stats.intersect_seconds / busy : 0,
                busy > 0 ? 100 * stats.shade_seconds / busy : 0, busy);
    }
    sk_image_free(&image);
    sk_render_scene_destroy(scene);
    return status;
}

const cli_command cmd_render = {
    .name = "render",
    .summary = "ray-trace a scene of meshes with skin and wood materials",
    .usage = "shitsukan render [SCENE.json] [options]",
    .description =
        "Renders a scene file (see docs/render.md): meshes and primitives, cameras, lights,\n"
        "standard, skin and wood materials. The output type follows the extension: .png is\n"
        "tone-mapped 8-bit sRGB with alpha, .exr keeps linear radiance (premultiplied RGBA).\n"
        "Without -o the image is written as <scene name>.png. Any scene key can be changed\n"
        "with --set (e.g. --set camera.fov_deg=30 --set lights[0].intensity=2).\n"
        "--export writes the geometry for other tools (Blender, game engines): primitives\n"
        "tessellated, meshes as loaded, object transforms, in metres; materials approximated\n"
        "(base colour, roughness; wood baked into a base colour texture, skin as a normal\n"
        "map of one tile; see docs/render.md, \"Export\"). With --export and no -o, nothing\n"
        "is rendered.",
    .examples =
        "  shitsukan render presets/scenes/wrist.json --size 1280x720 --spp 16 -o wrist.png\n"
        "  shitsukan render --preset wrist -o wrist.exr\n"
        "  shitsukan render scene.json --set camera.projection=orthographic --stats\n"
        "  shitsukan render --preset piano --export piano.glb",
    .options = k_options,
    .option_count = sizeof k_options / sizeof k_options[0],
    .common = CLI_COMMON_ALL,
    .min_positional = 0,
    .max_positional = 1,
    .preset_module = "scenes",
    .schema = &sk_render_schema,
    .run = run_render,
};
