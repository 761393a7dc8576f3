/* `shitsukan hand mesh`: the hand's skin surface (Yasumuro 2000, sec. 4.1) in a pose, as
 * OBJ, PLY or glTF binary. Argument parsing only; the model is in the library
 * (include/shitsukan/hand.h, section "hand surface"). */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "cmd_hand_prior.h"
#include "cmd_hand_surface.h"
#include "hand_args.h"
#include "hand_params.h"
#include "shitsukan/hand.h"

static const cli_option mesh_options[] = {
    {"pose", 0, "FILE", "pose JSON ({\"dofs\": {...}} in degrees, as `hand pose -o` writes)",
     false},
    {"pin", 0, "DOF=DEG",
     "hold a DOF at an absolute angle (the others follow the natural coupling); repeatable", true},
    {"constraints", 0, "SET",
     "coupling of --pin: natural (default), yasumuro-table-3.2, none, or a JSON file", false},
    {"potential", 0, "FILE",
     "coupling of --pin: a calibrated potential (hand calibrate) instead of --constraints", false},
    {"skinning", 0, "METHOD", "rigid (the thesis: nearest link), lbs or dqs (default)", false},
    {"lod", 0, "N", "level of detail: 0 = 8000 triangles (default), 1 = 2000, 2 = 500", false},
    {"left", 0, NULL, "a left hand (the exact mirror image)", false},
    {"triangles", 0, "N", "triangles of level 0 (default 8000)", false},
    {"flesh", 0, "FILE", "flesh sizes JSON (default presets/hand/flesh.json's built-in values)",
     false},
    {"texture", 0, "PREFIX",
     "also bake the skin texture: PREFIX-albedo.png and PREFIX-normal.png (OBJ: an MTL)", false},
    {"texture-size", 0, "N", "atlas size in pixels (default 1024)", false},
    {"material", 0, "KIND",
     ".glb material: blend (the thesis's 0.3 lit : 0.7 unlit texture, default) or pbr", false},
};

/* --pin solved with the coupling of --constraints ("natural", "yasumuro-table-3.2", "none"
   or a file) or a calibrated --potential. */
static int solve_pins(const cli_command *cmd, const cli_args *args, const sk_hand_skeleton *skel,
                      double *q)
{
    sk_hand_input in;
    int rc = hand_parse_inputs(cmd, args, &in);
    if (rc) return rc;
    const char *set = cli_get(cmd, args, "constraints"),
               *potential = cli_get(cmd, args, "potential");
    if (set && potential)
        return cli_fail(CLI_EXIT_USAGE, "--potential does not go with --constraints");
    hand_poser poser;
    rc = hand_poser_open(&poser, skel, potential, set ? set : "natural", NULL, 0);
    sk_hand_solve_info info;
    if (!rc) rc = hand_poser_solve(&poser, &in, q, &info);
    hand_poser_close(&poser);
    return rc;
}

static const cli_key_option mesh_keys[] = {
    {"left", "hand.side", "left", false},
    HAND_SURFACE_KEY_OPTIONS,
};

static int run_mesh(const cli_command *cmd, const cli_args *args)
{
    const char *out = args->common.output;
    if (!out) return cli_fail(CLI_EXIT_USAGE, "-o hand.obj|hand.ply|hand.glb is required");
    static const char *const k_formats[] = {".obj", ".ply", ".glb", NULL};
    int format;
    int rc = cli_output_format("-o", out, k_formats, &format);
    if (rc) return rc;
    bool glb = format == 2;
    if (cli_has(cmd, args, "pose") && cli_has(cmd, args, "pin"))
        return cli_fail(CLI_EXIT_USAGE, "give --pose or --pin, not both");
    if (glb && cli_has(cmd, args, "texture"))
        return cli_fail(CLI_EXIT_USAGE, "--texture is for .obj and .ply: a .glb holds its texture");
    if (!glb && cli_has(cmd, args, "material"))
        return cli_fail(CLI_EXIT_USAGE, "--material is for a .glb");
    if (!glb && !cli_has(cmd, args, "texture") && cli_has(cmd, args, "texture-size"))
        return cli_fail(CLI_EXIT_USAGE, "--texture-size needs --texture (or a .glb)");
    long long lod;
    hand_surface_plan plan;
    hand_params params;
    rc = cli_get_int(cmd, args, "lod", 0, 0, SK_HAND_LOD_COUNT - 1, &lod);
    if (!rc) rc = hand_load_params(cmd, args, &params);
    if (!rc) rc = hand_surface_plan_parse(cmd, args, &params, &plan);
    if (rc) return rc;
    sk_error err = {0};
    sk_hand_skeleton skel;
    /* the keys hand.* (--left: hand.side=left) */
    sk_hand_skeleton_desc sd = params.hand;
    if (!sd.side) sd.side = SK_HAND_SIDE_RIGHT;
    if (sk_hand_skeleton_init(&skel, &sd, &err) != SK_OK) return cli_fail_error(&err);
    double q[SK_HAND_DOF_COUNT];
    const char *pose = cli_get(cmd, args, "pose");
    if (pose && sk_hand_pose_load_file(pose, &skel, q, &err) != SK_OK) return cli_fail_error(&err);
    if (!pose && (rc = solve_pins(cmd, args, &skel, q))) return rc;
    /* a .glb holds all three levels of detail, unless --lod chose one */
    int lod_count = glb && !cli_has(cmd, args, "lod") ? SK_HAND_LOD_COUNT : 1;
    if ((rc = hand_surface_plan_check_memory(args, &plan, &skel, glb || plan.prefix,
                                             lod > 0 ? 2 : lod_count)))
        return rc;
    /* the mesh, its MTL and textures appear together or not at all */
    const cli_output outputs[] = {{"-o", &out, k_formats, false}};
    sk_output_set *written = NULL;
    if ((rc = cli_reserve_outputs(outputs, 1, &written))) return rc;
    rc = hand_surface_plan_reserve(&plan, written, glb || format == 1 ? NULL : args->common.output);
    sk_hand_surface *surface = NULL;
    if (!rc) rc = hand_build_surface(&plan, &skel, (int)lod, &surface);
    if (!rc && glb)
        rc = hand_write_glb(&plan, surface, q, 1, 30.0, false, lod_count, out);
    else if (!rc)
        rc = hand_write_posed_mesh(&plan, surface, q, out);
    rc = cli_finish_outputs(written, rc);
    if (!rc && !args->common.quiet)
        fprintf(stderr, "shitsukan: %zu vertices, %zu triangles (%s skinning)\n",
                sk_hand_surface_mesh(surface)->vertex_count,
                sk_hand_surface_mesh(surface)->triangle_count,
                plan.method == SK_HAND_SKINNING_RIGID ? "rigid"
                : plan.method == SK_HAND_SKINNING_LBS ? "lbs"
                                                      : "dqs");
    sk_hand_surface_destroy(surface);
    return rc;
}

const cli_command cmd_hand_mesh = {
    .name = "hand mesh",
    .summary = "the hand's skin surface in a pose (OBJ, PLY or glTF binary)",
    .usage =
        "shitsukan hand mesh [--pose pose.json | --pin DOF=DEG ...] [--skinning rigid|lbs|dqs]\n"
        "       [--lod 0|1|2] [--left] -o hand.obj|hand.ply|hand.glb",
    .description =
        "Builds the skin surface of Yasumuro's thesis (sec. 4.1) from the skeleton: flesh of\n"
        "published sizes around every link, blended into one implicit surface and meshed in\n"
        "the relaxed posture into a closed manifold mesh of about 8000 triangles (the\n"
        "thesis's count), then moves it into the pose: rigidly with the nearest link (the\n"
        "thesis), by linear blend (lbs) or dual quaternion skinning (dqs, default) with\n"
        "smooth weights. The pose comes from a pose file or from pinned DOFs solved with the\n"
        "natural coupling (as `hand pose`); without either, the relaxed posture. OBJ and PLY\n"
        "carry UVs of the palm/back atlas; PLY also the skin weights (joints_*, weights_*).\n"
        "Units: mm (glTF: metres).",
    .examples = "  shitsukan hand mesh -o hand.obj --texture hand\n"
                "  shitsukan hand mesh --pin I.PIP.flex=100 --skinning rigid -o rigid.ply\n"
                "  shitsukan hand mesh --pose pose.json --lod 1 --left -o left.glb",
    .options = mesh_options,
    .option_count = (int)(sizeof mesh_options / sizeof mesh_options[0]),
    .common = CLI_COMMON_OUTPUT | CLI_COMMON_QUIET | CLI_COMMON_THREADS | CLI_COMMON_PRESET |
              CLI_COMMON_SET,
    .min_positional = 0,
    .max_positional = 0,
    .preset_module = "hand",
    .schema = &hand_mesh_schema,
    .run = run_mesh,
    .key_options = mesh_keys,
    .key_option_count = (int)(sizeof mesh_keys / sizeof mesh_keys[0]),
};
