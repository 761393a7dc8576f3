/* Helpers of the `shitsukan tissue` commands (see cmd_tissue.h). */
#define _POSIX_C_SOURCE 200809L
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cmd_tissue.h"

int tissue_cli_build(const cli_command *cmd, const cli_args *args, sk_tissue_model **out)
{
    *out = NULL;
    const char *character = cli_get(cmd, args, "character");
    if (!character)
        return cli_fail(CLI_EXIT_USAGE, "--character is required (arm, body or a JSON file)");
    char found[PATH_MAX];
    if (!strchr(character, '/') && !strstr(character, ".json") &&
        !cli_find_preset("tissue", character, found, sizeof found))
        return cli_fail(CLI_EXIT_USAGE,
                        "--character '%s': no such character (arm, body or a JSON file; see "
                        "'shitsukan presets tissue')",
                        character);
    /* the character is a preset of the tissue module: reuse the preset loading with --set */
    cli_args *copy = malloc(sizeof *copy);
    if (!copy) return cli_fail(CLI_EXIT_RUNTIME, "out of memory");
    *copy = *args;
    copy->common.preset = character;
    sk_preset *preset = NULL;
    int status = cli_load_preset(cmd, copy, &preset);
    free(copy);
    if (status) return status;
    sk_tissue_character_desc *desc = malloc(sizeof *desc);
    sk_error err = {0};
    if (!desc) {
        sk_preset_free(preset);
        return cli_fail(CLI_EXIT_RUNTIME, "out of memory");
    }
    sk_result r = sk_tissue_character_bind(preset, desc, &err);
    sk_preset_free(preset);
    if (r != SK_OK) {
        free(desc);
        return cli_fail(cli_exit_status(r), "--character %s: %s", character, err.message);
    }
    /* the grid's memory, before anything is allocated for it */
    double bytes = 0;
    int grid[3] = {0};
    r = sk_tissue_model_memory(desc, &bytes, grid, &err);
    if (r != SK_OK) {
        free(desc);
        return cli_fail(cli_exit_status(r), "--character %s: %s", character, err.message);
    }
    char driver[160];
    snprintf(driver, sizeof driver,
             "--character %s (skin.spacing_mm = %g: a grid of %d x %d x %d points)", character,
             desc->skin.spacing_mm > 0 ? desc->skin.spacing_mm : 4.0, grid[0], grid[1], grid[2]);
    if ((status = cli_check_memory(args, bytes, driver))) {
        free(desc);
        return status;
    }
    sk_progress_bar bar;
    sk_progress_bar_begin(&bar, "skin", !args->common.quiet);
    sk_tissue_build_options options = {sk_progress_bar_sink(&bar)};
    r = sk_tissue_model_build(desc, &options, out, &err);
    sk_progress_bar_end(&bar);
    free(desc);
    if (r != SK_OK)
        return cli_fail(cli_exit_status(r), "--character %s: %s", character, err.message);
    return 0;
}

void tissue_cli_print_model(const sk_tissue_model *model)
{
    sk_tissue_model_stats s = sk_tissue_model_get_stats(model);
    printf("%s: grid %d x %d x %d at %g mm; %zu skin, %zu fat, %zu muscle, %zu bone points; %zu "
           "springs; "
           "%zu skin triangles; built in %.2f s\n",
           sk_tissue_model_desc(model)->name, s.grid[0], s.grid[1], s.grid[2], s.spacing_mm,
           s.skin_points, s.fat_points, s.muscle_points, s.bone_points, s.springs, s.skin_triangles,
           s.seconds_total);
}
