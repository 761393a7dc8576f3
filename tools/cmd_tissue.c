/* `shitsukan tissue skin | run | motion`: the fat and skin model of Shigemori & Kawai
 * (include/shitsukan/tissue.h): a character's generated rest skin and its layers, a
 * motion simulated into skin meshes, point caches and glTF, and the shipped motions.
 * Argument parsing only; the model is in the library. */
#define _POSIX_C_SOURCE 200809L
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "shitsukan/tissue.h"
#include "cmd_tissue.h"

static const cli_option k_skin_options[] = {
    {"character", 0, "arm|body|FILE",
     "the character: a shipped one (presets/tissue/) or a JSON file", false},
    {"layers", 0, "DIR",
     "also write the layers: bone, muscle, fat, skin point clouds (PLY) and pictures", false},
    {"stats", 0, "FILE", "write the build's counts and timings as JSON", false},
};

static int run_skin(const cli_command *cmd, const cli_args *args)
{
    if (!args->common.output && !cli_has(cmd, args, "layers"))
        return cli_fail(CLI_EXIT_USAGE, "nothing to write: give -o rest.obj and/or --layers DIR");
    /* the rest skin, the layers and the stats appear together, or none */
    static const char *const k_mesh[] = {".obj", ".ply", NULL}, *const k_json[] = {".json", NULL};
    const char *out = args->common.output, *layers = cli_get(cmd, args, "layers"),
               *stats = cli_get(cmd, args, "stats");
    const cli_output outputs[] = {{"-o", &out, k_mesh, false},
                                  {"--layers", &layers, NULL, true},
                                  {"--stats", &stats, k_json, false}};
    sk_output_set *written = NULL;
    int status = cli_reserve_outputs(outputs, 3, &written);
    if (status) return status;
    sk_tissue_model *model = NULL;
    status = tissue_cli_build(cmd, args, &model);
    if (status) return cli_finish_outputs(written, status);
    sk_error err = {0};
    sk_result r = SK_OK;
    if (out) {
        sk_mesh skin;
        r = sk_tissue_model_rest_skin(model, &skin, &err);
        if (r == SK_OK) {
            r = sk_mesh_write(&skin, out, &err);
            sk_mesh_free(&skin);
        }
    }
    if (r == SK_OK && layers) r = sk_tissue_write_layers(model, layers, &err);
    if (r == SK_OK && stats) r = sk_tissue_write_model_stats(model, stats, &err);
    status = cli_finish_outputs(written, r == SK_OK ? 0 : cli_fail_error(&err));
    if (!status && !args->common.quiet) tissue_cli_print_model(model);
    sk_tissue_model_destroy(model);
    return status;
}

const cli_command cmd_tissue_skin = {
    .name = "tissue skin",
    .summary = "a character's generated rest skin (Shigemori & Kawai) and its layers",
    .usage = "shitsukan tissue skin --character arm|body|FILE -o rest.obj [--layers DIR] [options]",
    .description = "Builds the character of Shigemori & Kawai's fat model: bones of three "
                   "ellipsoids, volume-keeping\n"
                   "muscles, a grid over the tissue dilated and cut at a threshold into a skin "
                   "whose vertices lie on\n"
                   "grid points, and the fat, skin, muscle and bone points with their springs. "
                   "Writes the rest skin\n"
                   "(OBJ or PLY by extension); --layers writes bone.ply, muscle.ply, fat.ply, "
                   "skin.ply (points),\n"
                   "bones.obj, muscles.obj (ellipsoids) and layers.png (the layers cut open). "
                   "Character keys can be\n"
                   "changed with --set, e.g. --set skin.spacing_mm=2 (see --help-keys).",
    .examples =
        "shitsukan tissue skin --character arm -o arm.obj --layers arm-layers\n"
        "shitsukan tissue skin --character body --set skin.smooth_iterations=10 -o body.obj",
    .options = k_skin_options,
    .option_count = sizeof k_skin_options / sizeof k_skin_options[0],
    .common = CLI_COMMON_OUTPUT | CLI_COMMON_SET | CLI_COMMON_THREADS | CLI_COMMON_QUIET,
    .preset_module = "tissue",
    .schema = &sk_tissue_character_schema,
    .run = run_skin,
};
