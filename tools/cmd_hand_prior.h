/* Shared by the hand commands: constraint sets by name, reading samples with --units,
 * --group and --ignore-columns, and the potential calibration of `hand calibrate`. */
#ifndef SK_TOOLS_CMD_HAND_PRIOR_H
#define SK_TOOLS_CMD_HAND_PRIOR_H

#include "cli.h"
#include "shitsukan/hand.h"

/* Reads a samples CSV with the command's --units, --group and --ignore-columns (each
 * must be an option of the command), warning when the units look wrong. */
int hand_read_samples(const cli_command *cmd, const cli_args *args, const char *path, sk_hand_samples *out);
/* "natural", "yasumuro-table-3.2", "none" or a file (`out` is zeroed for "none"). */
int hand_load_constraints(const char *name, const sk_hand_skeleton *skel, sk_hand_constraints *out);
/* `hand calibrate` without --pairs: the whole potential (--method, --components,
 * --prior-strength, --base, --seed). */
int hand_calibrate_potential(const cli_command *cmd, const cli_args *args);

#endif
