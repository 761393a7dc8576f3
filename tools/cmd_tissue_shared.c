/* Helpers of the `shitsukan tissue` commands (see cmd_tissue.h). */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cmd_tissue.h"

int tissue_cli_build(const cli_command *cmd, const cli_args *args, sk_tissue_model **out)
{
    *out = NULL;
    const char *character = cli_get(cmd, args, "character");
    if (!character) return cli_fail(CLI_EXIT_USAGE, "--character is required (arm, body or a JSON file)");
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
    sk_progress_bar bar;
    sk_progress_bar_begin(&bar, "skin", !args->common.quiet);
    sk_tissue_build_options options = {sk_progress_bar_sink(&bar)};
    r = sk_tissue_model_build(desc, &options, out, &err);
    sk_progress_bar_end(&bar);
    free(desc);
    if (r != SK_OK) return cli_fail(cli_exit_status(r), "--character %s: %s", character, err.message);
    return 0;
}

void tissue_cli_print_model(const sk_tissue_model *model)
{
    sk_tissue_model_stats s = sk_tissue_model_get_stats(model);
    printf("%s: grid %d x %d x %d at %g mm; %zu skin, %zu fat, %zu muscle, %zu bone points; %zu springs; "
           "%zu skin triangles; built in %.2f s\n",
           sk_tissue_model_desc(model)->name, s.grid[0], s.grid[1], s.grid[2], s.spacing_mm, s.skin_points,
           s.fat_points, s.muscle_points, s.bone_points, s.springs, s.skin_triangles, s.seconds_total);
}
