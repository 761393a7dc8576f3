/* Options shared by the `shitsukan hand ...` commands (tools/hand_args.c). */
#ifndef SK_TOOLS_HAND_ARGS_H
#define SK_TOOLS_HAND_ARGS_H

#include "cli.h"
#include "shitsukan/hand.h"

/* Skeleton from the keys `given` (their zeros: `side`, `length_mm`, `breadth_mm`, the
 * fallbacks) and --anatomy (which may be absent from the command's options). Returns 0
 * or the exit status after printing the error. */
int hand_build_skeleton(const cli_command *cmd, const cli_args *args,
                        const sk_hand_skeleton_desc *given, sk_hand_side side, double length_mm,
                        double breadth_mm, sk_hand_skeleton *skel);
/* "DOF=value" -> the DOF's index and the number (in file units: degrees, mm): a whole
 * decimal number of magnitude at most 1e6. */
int hand_parse_assignment(const char *option, const char *text, int *dof, double *value);
/* --pin and --torque (those of them the command has) into an input: each DOF takes at
 * most one of them, once; a repeat is an error naming both. Pins are in model units
 * (radians; mm for the wrist translations), torques as given. No count limit beyond the
 * command line's. */
int hand_parse_inputs(const cli_command *cmd, const cli_args *args, sk_hand_input *in);
/* A repeatable "DOF=value" option (e.g. --bend) by the same rules: given[dof] and
 * value[dof] (model units: radians, mm) for each DOF named, each at most once. */
int hand_parse_dof_values(const cli_command *cmd, const cli_args *args, const char *option,
                          bool given[SK_HAND_DOF_COUNT], double value[SK_HAND_DOF_COUNT]);

#endif
