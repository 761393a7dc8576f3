/* The table of subcommands of the `shitsukan` command (one file per module's commands). */
#include "cli.h"

extern const cli_command cmd_presets;

const cli_command *const cli_commands[] = {
    &cmd_presets,
    NULL,
};
