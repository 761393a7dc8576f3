/* The table of subcommands of the `shitsukan` command (one file per module's commands). */
#include "cli.h"

extern const cli_command cmd_presets;
extern const cli_command cmd_noise;
extern const cli_command cmd_sheet;
extern const cli_command cmd_hand_pose;
extern const cli_command cmd_hand_animate;
extern const cli_command cmd_hand_calibrate;
extern const cli_command cmd_hand_mesh;
extern const cli_command cmd_hand_scan;
extern const cli_command cmd_hand_evaluate;
extern const cli_command cmd_hand_synthesize;
extern const cli_command cmd_skin;
extern const cli_command cmd_skin_maps;
extern const cli_command cmd_wood_cut;
extern const cli_command cmd_wood_sweep;
extern const cli_command cmd_render;
extern const cli_command cmd_showcase;
extern const cli_command cmd_showcase_midi;
extern const cli_command cmd_tissue_skin;
extern const cli_command cmd_tissue_run;
extern const cli_command cmd_tissue_motion;
extern const cli_command cmd_studio;

const cli_command *const cli_commands[] = {
    &cmd_presets,       &cmd_noise,
    &cmd_sheet,         &cmd_hand_pose,
    &cmd_hand_animate,  &cmd_hand_calibrate,
    &cmd_hand_mesh,     &cmd_hand_scan,
    &cmd_hand_evaluate, &cmd_hand_synthesize,
    &cmd_skin,          &cmd_skin_maps,
    &cmd_wood_cut,      &cmd_wood_sweep,
    &cmd_render,        &cmd_showcase,
    &cmd_showcase_midi, &cmd_tissue_skin,
    &cmd_tissue_run,    &cmd_tissue_motion,
    &cmd_studio,        NULL,
};
