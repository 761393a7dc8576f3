/* Shared by the `shitsukan tissue` commands: loading a character (shipped name or file,
 * with --set edits) and building it with a progress bar. */
#ifndef SK_TOOLS_CMD_TISSUE_H
#define SK_TOOLS_CMD_TISSUE_H

#include "cli.h"
#include "shitsukan/tissue.h"

/* --character NAME|FILE with every --set applied, bound and validated into a built model
 * (*out; destroy with sk_tissue_model_destroy). Errors print and return their status. */
int tissue_cli_build(const cli_command *cmd, const cli_args *args, sk_tissue_model **out);
/* One line of counts and the build time on stdout. */
void tissue_cli_print_model(const sk_tissue_model *model);

#endif
