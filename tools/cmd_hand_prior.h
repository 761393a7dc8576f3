/* Shared by the hand commands: constraint sets by name, reading samples with --units,
 * --group and --ignore-columns, and the potential calibration of `hand calibrate`. */
#ifndef SK_TOOLS_CMD_HAND_PRIOR_H
#define SK_TOOLS_CMD_HAND_PRIOR_H

#include "cli.h"
#include "hand_params.h"
#include "shitsukan/hand.h"

/* Reads a samples CSV with the command's --units, --group and --ignore-columns (each
 * must be an option of the command), warning when the units look wrong. */
int hand_read_samples(const cli_command *cmd, const cli_args *args, const char *path,
                      sk_hand_samples *out);
/* "natural", "yasumuro-table-3.2", "none" or a file (`out` is zeroed for "none"). */
int hand_load_constraints(const char *name, const sk_hand_skeleton *skel, sk_hand_constraints *out);
/* `hand calibrate` without --pairs: the whole potential (the keys potential.*, --base). */
int hand_calibrate_potential(const cli_command *cmd, const cli_args *args,
                             const hand_params *params);
/* --prior-strength S into potential.prior_strength: S in [0, its maximum], 0 = none (the
 * key's -1). A command's set_option_keys. */
int hand_set_prior_strength(const cli_command *cmd, const cli_args *args, sk_preset *tree);

/* The posture solver of a command: a calibrated potential (--potential FILE of hand
 * calibrate) or a constraint set by name with lookup tables (which must outlive it). */
typedef struct hand_poser {
    sk_hand_solver *solver;
    sk_hand_potential_solver *potential;
} hand_poser;
/* potential_path NULL: the set `set_name` ("natural", a preset, "none" or a file). */
int hand_poser_open(hand_poser *poser, const sk_hand_skeleton *skel, const char *potential_path,
                    const char *set_name, const sk_hand_lut *luts, int lut_count);
int hand_poser_solve(hand_poser *poser, const sk_hand_input *in, double *q,
                     sk_hand_solve_info *info);
void hand_poser_close(hand_poser *poser);

#endif
