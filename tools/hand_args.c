/* Options shared by the `shitsukan hand ...` commands: the skeleton from --side,
 * --hand-length, --hand-breadth and --anatomy, and "DOF=value" assignments. Argument
 * parsing only. */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hand_args.h"

static int parse_side(const char *text, sk_hand_side *side)
{
    if (!text || strcmp(text, "right") == 0) *side = SK_HAND_SIDE_RIGHT;
    else if (strcmp(text, "left") == 0) *side = SK_HAND_SIDE_LEFT;
    else return cli_fail(CLI_EXIT_USAGE, "--side '%s' must be right or left", text);
    return 0;
}

int hand_build_skeleton(const cli_command *cmd, const cli_args *args, sk_hand_side side, double length_mm,
                        double breadth_mm, sk_hand_skeleton *skel)
{
    sk_error err = {0};
    sk_hand_anatomy anatomy;
    sk_hand_skeleton_desc desc = {0};
    const char *anatomy_path = cli_get(cmd, args, "anatomy");
    if (anatomy_path) {
        if (sk_hand_anatomy_load_file(anatomy_path, &anatomy, &err) != SK_OK) return cli_fail_error(&err);
        desc.anatomy = &anatomy;
    }
    double hl = length_mm, hb = breadth_mm;
    int rc = cli_get_double(cmd, args, "hand-length", hl, 60, 400, &hl);
    if (rc == 0) rc = cli_get_double(cmd, args, "hand-breadth", hb, 30, 200, &hb);
    if (rc) return rc;
    const char *side_text = cli_get(cmd, args, "side");
    if (side_text && (rc = parse_side(side_text, &side))) return rc;
    desc.side = side;
    desc.hand_length_mm = hl;
    desc.hand_breadth_mm = hb;
    if (sk_hand_skeleton_init(skel, &desc, &err) != SK_OK) return cli_fail_error(&err);
    return 0;
}

int hand_parse_assignment(const char *option, const char *text, int *dof, double *value)
{
    const char *eq = strchr(text, '=');
    if (!eq) return cli_fail(CLI_EXIT_USAGE, "--%s '%s': expected DOF=value, e.g. L.MCP.flex=60", option, text);
    char name[64];
    size_t n = (size_t)(eq - text);
    if (n >= sizeof name) n = sizeof name - 1;
    memcpy(name, text, n);
    name[n] = '\0';
    *dof = sk_hand_dof_find(name);
    if (*dof < 0)
        return cli_fail(CLI_EXIT_USAGE, "--%s '%s': unknown DOF \"%s\" (see shitsukan hand pose --help)",
                        option, text, name);
    char *end;
    errno = 0;
    *value = strtod(eq + 1, &end);
    if (!eq[1] || *end || errno == ERANGE || !isfinite(*value) || fabs(*value) > 1e6)
        return cli_fail(CLI_EXIT_USAGE, "--%s '%s': \"%s\" is not a finite number", option, text, eq + 1);
    return 0;
}

