/* Options shared by the `shitsukan hand ...` commands (tools/hand_args.c). */
#ifndef SK_TOOLS_HAND_ARGS_H
#define SK_TOOLS_HAND_ARGS_H

#include "cli.h"
#include "shitsukan/hand.h"

/* Skeleton from --side, --hand-length, --hand-breadth, --anatomy (each may be absent from
 * the command's options); `side`, `length_mm`, `breadth_mm` are the fallbacks. Returns 0
 * or the exit status after printing the error. */
int hand_build_skeleton(const cli_command *cmd, const cli_args *args, sk_hand_side side, double length_mm,
                        double breadth_mm, sk_hand_skeleton *skel);
/* "DOF=value" -> the DOF's index and the number (in file units: degrees, mm): a whole
 * decimal number of magnitude at most 1e6. */
int hand_parse_assignment(const char *option, const char *text, int *dof, double *value);
/* --pin and --torque (both options of the command) into an input: each DOF takes at most
 * one of them, once; a repeat is an error naming both. */
int hand_parse_inputs(const cli_command *cmd, const cli_args *args, sk_hand_input *in);

#endif
