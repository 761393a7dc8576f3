/* Options shared by the `shitsukan hand ...` commands: the skeleton from its keys
 * (hand.side, hand.hand_length_mm, hand.hand_breadth_mm: hand_params.h) and --anatomy, and
 * "DOF=value" assignments. Argument parsing only. */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hand_args.h"

int hand_build_skeleton(const cli_command *cmd, const cli_args *args,
                        const sk_hand_skeleton_desc *given, sk_hand_side side, double length_mm,
                        double breadth_mm, sk_hand_skeleton *skel)
{
    sk_error err = {0};
    sk_hand_anatomy anatomy;
    sk_hand_skeleton_desc desc = {0};
    const char *anatomy_path = cli_get(cmd, args, "anatomy");
    if (anatomy_path) {
        if (sk_hand_anatomy_load_file(anatomy_path, &anatomy, &err) != SK_OK)
            return cli_fail_error(&err);
        desc.anatomy = &anatomy;
    }
    /* the keys given (options, presets, --set), else the fallbacks (e.g. an animation's) */
    desc.side = given->side ? given->side : side;
    desc.hand_length_mm = given->hand_length_mm ? given->hand_length_mm : length_mm;
    desc.hand_breadth_mm = given->hand_breadth_mm ? given->hand_breadth_mm : breadth_mm;
    if (sk_hand_skeleton_init(skel, &desc, &err) != SK_OK) return cli_fail_error(&err);
    return 0;
}

/* Largest magnitude of a --pin or --torque value (degrees, mm or stiffness x radians):
   pins beyond a joint's limits are clamped to them, so any larger value means nothing. */
#define INPUT_VALUE_MAX 1e6

int hand_parse_assignment(const char *option, const char *text, int *dof, double *value)
{
    const char *eq = strchr(text, '=');
    if (!eq)
        return cli_fail(CLI_EXIT_USAGE, "--%s '%s': expected DOF=value, e.g. L.MCP.flex=60", option,
                        text);
    char name[64];
    size_t n = (size_t)(eq - text);
    if (n >= sizeof name) n = sizeof name - 1;
    memcpy(name, text, n);
    name[n] = '\0';
    *dof = sk_hand_dof_find(name);
    if (*dof < 0)
        return cli_fail(CLI_EXIT_USAGE,
                        "--%s '%s': unknown DOF \"%s\" (see shitsukan hand pose --help)", option,
                        text, name);
    if (!cli_parse_decimal(eq + 1, value) || fabs(*value) > INPUT_VALUE_MAX)
        return cli_fail(CLI_EXIT_USAGE,
                        "--%s '%s': the value must be a decimal number in [%.0f, %.0f]", option,
                        text, -INPUT_VALUE_MAX, INPUT_VALUE_MAX);
    return 0;
}

/* The values of repeatable option `option` ("DOF=value" each), in model units when
   `angles` (degrees to radians; mm stay mm), as given otherwise. `taken[dof]` names the
   option that already set a DOF (shared between the options of one input). */
static int parse_dof_option(const cli_command *cmd, const cli_args *args, const char *option,
                            bool angles, const char *taken[SK_HAND_DOF_COUNT],
                            bool given[SK_HAND_DOF_COUNT], double value[SK_HAND_DOF_COUNT])
{
    if (!cli_takes(cmd, option)) return 0;
    const char *values[CLI_MAX_VALUES];
    int n = cli_get_all(cmd, args, option, values, CLI_MAX_VALUES);
    for (int i = 0; i < n; i++) {
        int dof = 0;
        double v = 0.0;
        int rc = hand_parse_assignment(option, values[i], &dof, &v);
        if (rc) return rc;
        if (taken[dof])
            return cli_fail(CLI_EXIT_USAGE, "--%s '%s': %s already has --%s (one value per DOF)",
                            option, values[i], sk_hand_dof(dof)->name, taken[dof]);
        taken[dof] = option;
        given[dof] = true;
        value[dof] = angles && !sk_hand_dof(dof)->translation ? v * SK_DEG_TO_RAD : v;
    }
    return 0;
}

int hand_parse_inputs(const cli_command *cmd, const cli_args *args, sk_hand_input *in)
{
    const char *taken[SK_HAND_DOF_COUNT] = {0};
    bool torqued[SK_HAND_DOF_COUNT] = {0};
    memset(in, 0, sizeof *in);
    int rc = parse_dof_option(cmd, args, "pin", true, taken, in->pinned, in->pin_value);
    if (!rc) rc = parse_dof_option(cmd, args, "torque", false, taken, torqued, in->torque);
    return rc;
}

int hand_parse_dof_values(const cli_command *cmd, const cli_args *args, const char *option,
                          bool given[SK_HAND_DOF_COUNT], double value[SK_HAND_DOF_COUNT])
{
    const char *taken[SK_HAND_DOF_COUNT] = {0};
    memset(given, 0, SK_HAND_DOF_COUNT * sizeof *given);
    return parse_dof_option(cmd, args, option, true, taken, given, value);
}
