/* `shitsukan tissue motion`: writes the shipped motions (an arm curl, a jump, a walk) as
 * BVH, so presets/tissue can be made again. Argument parsing only. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cmd_tissue.h"

static int run_motion(const cli_command *cmd, const cli_args *args)
{
    (void)cmd;
    const char *name = args->positional[0];
    int kind = -1;
    for (int k = 0; sk_tissue_motion_kind_names[k]; k++)
        if (strcmp(name, sk_tissue_motion_kind_names[k]) == 0) kind = k;
    if (kind < 0) return cli_fail(CLI_EXIT_USAGE, "motion '%s' must be curl, jump or walk", name);
    if (!args->common.output) return cli_fail(CLI_EXIT_USAGE, "-o FILE.bvh is required");
    static const char *const k_bvh[] = {".bvh", NULL};
    int format;
    int status = cli_output_format("-o", args->common.output, k_bvh, &format);
    if (status) return status;
    sk_error err = {0};
    sk_bvh *b = malloc(sizeof *b);
    if (!b) return cli_fail(CLI_EXIT_RUNTIME, "out of memory");
    sk_result r = sk_tissue_make_motion((sk_tissue_motion_kind)kind, b, &err);
    if (r == SK_OK) r = sk_bvh_write(b, args->common.output, &err);
    sk_bvh_free(b);
    free(b);
    return r == SK_OK ? 0 : cli_fail_error(&err);
}

const cli_command cmd_tissue_motion = {
    .name = "tissue motion",
    .summary = "the shipped tissue motions (arm curl, jump, walk) as BVH",
    .usage = "shitsukan tissue motion curl|jump|walk -o FILE.bvh",
    .description = "Generates one of the motions shipped in presets/tissue: 'curl' for the arm "
                   "character, 'jump' and\n"
                   "'walk' for the full body (joint names as the characters', centimetres, 60 "
                   "frames per second).",
    .examples = "shitsukan tissue motion jump -o jump.bvh",
    .common = CLI_COMMON_OUTPUT,
    .min_positional = 1,
    .max_positional = 1,
    .run = run_motion,
};
