/* `shitsukan hand pose | animate | calibrate`: the hand skeleton posed by its natural
 * coupling (Yasumuro 2000, ch. 3), keyframe animation to BVH and joint positions, and
 * calibration of constraint rows from measured samples. Argument parsing only; the model
 * is in the library (include/shitsukan/hand.h). */
#define _POSIX_C_SOURCE 200809L
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "cmd_hand_surface.h"
#include "cmd_hand_prior.h"
#include "hand_args.h"
#include "hand_params.h"
#include "shitsukan/hand.h"
#include "shitsukan/io.h"

/* ------------------------------------------------------------ helpers */

static int write_positions(const sk_hand_skeleton *skel, const double *dofs, int frames,
                           const char *path)
{
    size_t len = strlen(path);
    bool json = len >= 5 && strcmp(path + len - 5, ".json") == 0;
    sk_error err = {0};
    if (sk_hand_positions_write(skel, dofs, frames,
                                json ? SK_HAND_POSITIONS_JSON : SK_HAND_POSITIONS_CSV, path,
                                &err) != SK_OK)
        return cli_fail_error(&err);
    return 0;
}

/* Fails when one of `options` (NULL-terminated) is given without `needed`. */
static int require_option(const cli_command *cmd, const cli_args *args, const char *needed,
                          const char *const *options)
{
    if (cli_has(cmd, args, needed)) return 0;
    for (int i = 0; options[i]; i++)
        if (cli_has(cmd, args, options[i]))
            return cli_fail(CLI_EXIT_USAGE, "--%s needs --%s", options[i], needed);
    return 0;
}

static const char *const k_png_format[] = {".png", NULL};
static const char *const k_positions_formats[] = {".csv", ".json", NULL};

/* --views, --png-size and --labels into a picture desc. */
static int parse_draw_options(const cli_command *cmd, const cli_args *args, sk_hand_draw_desc *d)
{
    memset(d, 0, sizeof *d);
    const char *views = cli_get(cmd, args, "views");
    if (views) {
        static const char *const names[] = {"dorsal", "palmar", "radial", "ulnar"};
        static const sk_hand_view values[] = {SK_HAND_VIEW_DORSAL, SK_HAND_VIEW_PALMAR,
                                              SK_HAND_VIEW_RADIAL, SK_HAND_VIEW_ULNAR};
        const char *p = views;
        while (*p) {
            size_t n = strcspn(p, ",");
            int found = -1;
            for (int i = 0; i < 4; i++)
                if (strlen(names[i]) == n && strncmp(p, names[i], n) == 0) found = i;
            if (found < 0 || d->view_count == SK_HAND_DRAW_MAX_VIEWS)
                return cli_fail(CLI_EXIT_USAGE,
                                "--views '%s': expected 1 to 4 of dorsal, palmar, radial, ulnar, "
                                "comma-separated",
                                views);
            d->views[d->view_count++] = values[found];
            p += n;
            if (*p == ',') p++;
        }
        if (d->view_count == 0) return cli_fail(CLI_EXIT_USAGE, "--views is empty");
    }
    int rc = 0;
    if (cli_has(cmd, args, "png-size")) {
        rc = cli_get_size(cmd, args, "png-size", 0, 0, 8192, &d->width, &d->height);
        if (!rc && (d->width < 64 || d->height < 64))
            rc = cli_fail(CLI_EXIT_USAGE, "--png-size %dx%d: each side must be at least 64 pixels",
                          d->width, d->height);
    }
    d->label_points = cli_has(cmd, args, "labels");
    /* the stick figure alone, for figure sheets that say the view and the frame */
    d->hide_panel_titles = d->hide_cues = cli_has(cmd, args, "bare");
    return rc;
}

/* The inputs that drive a pose, with the angles they produced: "L.MCP.flex = 60.0 deg
 * (pinned), ..." (the caption of the pictures). */
static void describe_inputs(const sk_hand_input *in, const double *q, char *buf, size_t size)
{
    size_t used = 0;
    buf[0] = '\0';
    for (int i = 0; i < SK_HAND_DOF_COUNT && used < size; i++) {
        if (!in->pinned[i] && in->torque[i] == 0.0) continue;
        const sk_hand_dof_info *info = sk_hand_dof(i);
        double v = info->translation ? q[i] : q[i] * SK_RAD_TO_DEG;
        char how[48];
        if (in->pinned[i])
            snprintf(how, sizeof how, "pinned");
        else
            snprintf(how, sizeof how, "torque %.2f", in->torque[i]);
        used += (size_t)snprintf(buf + used, size - used, "%s%s = %.1f %s (%s)", used ? ", " : "",
                                 info->name, v, info->translation ? "mm" : "deg", how);
    }
    if (!buf[0]) snprintf(buf, size, "relaxed posture (no input)");
}

static int write_pose_png(const sk_hand_skeleton *skel, const double *q,
                          const sk_hand_draw_desc *desc, const char *path)
{
    sk_error err = {0};
    sk_image img;
    if (sk_hand_draw(skel, q, desc, NULL, &img, &err) != SK_OK) return cli_fail_error(&err);
    sk_result r = sk_image_write_png(&img, path, NULL, &err);
    sk_image_free(&img);
    return r == SK_OK ? 0 : cli_fail_error(&err);
}

/* Lookup tables from --samples and --pairs (3.2.3), of the keys `desc` (lut.*). */
static int build_luts(const cli_command *cmd, const cli_args *args, const sk_hand_lut_desc *desc,
                      sk_hand_lut *luts, int *count)
{
    *count = 0;
    const char *samples_path = cli_get(cmd, args, "samples");
    const char *pairs_text = cli_get(cmd, args, "pairs");
    if (!samples_path && !pairs_text) return 0;
    if (!samples_path || !pairs_text)
        return cli_fail(CLI_EXIT_USAGE, "--samples and --pairs go together");
    sk_error err = {0};
    int pairs[16][2], n = 0;
    if (sk_hand_parse_pairs(pairs_text, pairs, 16, &n, &err) != SK_OK) {
        sk_error_prefix(&err, err.result, "--pairs");
        return cli_fail_error(&err);
    }
    sk_hand_samples samples;
    if (sk_hand_samples_load_file(samples_path, &samples, &err) != SK_OK)
        return cli_fail_error(&err);
    for (int k = 0; k < n; k++) {
        int x = pairs[k][0], y = pairs[k][1];
        if (!samples.present[x] || !samples.present[y]) {
            sk_hand_samples_free(&samples);
            for (int j = 0; j < *count; j++) sk_hand_lut_free(&luts[j]);
            *count = 0;
            return cli_fail(CLI_EXIT_USAGE, "%s: no column \"%s\" for pair %s:%s", samples_path,
                            sk_hand_dof(samples.present[x] ? y : x)->name, sk_hand_dof(x)->name,
                            sk_hand_dof(y)->name);
        }
        if (sk_hand_lut_build(&luts[k], x, y, samples.column[x], samples.column[y], samples.count,
                              desc, &err) != SK_OK) {
            sk_hand_samples_free(&samples);
            for (int j = 0; j < *count; j++) sk_hand_lut_free(&luts[j]);
            *count = 0;
            return cli_fail_error(&err);
        }
        (*count)++;
    }
    sk_hand_samples_free(&samples);
    return 0;
}

/* ------------------------------------------------------------ hand pose */

static const cli_option pose_options[] = {
    {"pin", 0, "DOF=DEG",
     "hold a DOF at an angle in degrees (mm for wrist.tx/ty/tz), |value| <= 1e6; once per DOF",
     true},
    {"torque", 0, "DOF=T",
     "directed input torque on a DOF (stiffness x radians), |T| <= 1e6; once per DOF", true},
    {"constraints", 0, "SET",
     "natural (default), yasumuro-table-3.2, none, or a constraint JSON file", false},
    {"potential", 0, "FILE", "a calibrated potential (hand calibrate) instead of --constraints",
     false},
    {"samples", 0, "CSV",
     "joint-angle samples (header of DOF names, degrees) for lookup-table potentials", false},
    {"pairs", 0, "A:B,...", "DOF pairs that get a lookup-table potential from --samples", false},
    {"lut-resolution", 0, "N", "lookup-table grid nodes per axis (default 100)", false},
    {"lut-weight", 0, "W", "weight of each lookup-table potential (default 1)", false},
    {"lut-interp", 0, "MODE",
     "hermite (default, converges to 1e-6) or bilinear (the tables as they are)", false},
    {"side", 0, "SIDE", "right (default) or left (the mirror image)", false},
    {"hand-length", 0, "MM", "hand length, wrist crease to middle fingertip (default 190)", false},
    {"hand-breadth", 0, "MM", "hand breadth across the knuckles (default 85)", false},
    {"anatomy", 0, "FILE", "anatomy JSON (limits, relaxed posture, proportions; default built in)",
     false},
    {"bvh", 0, "FILE", "also write the pose as a one-frame BVH", false},
    {"positions", 0, "FILE", "also write joint positions (.csv or .json)", false},
    {"png", 0, "FILE", "also draw the pose as a stick figure (PNG, dorsal and radial views)",
     false},
    {"views", 0, "LIST",
     "views of the picture: 1-4 of dorsal, palmar, radial, ulnar (default dorsal,radial)", false},
    {"png-size", 0, "WxH", "picture size in pixels (default 400 per view x 480)", false},
    {"labels", 0, NULL, "write the joint names in the picture", false},
    {"bare", 0, NULL,
     "the stick figure alone: no view titles, direction arrows, scale bar or caption", false},
    {"caption", 0, "TEXT",
     "line under the picture (default: the inputs and the angles they gave; '' = none)", false},
};

static const cli_key_option pose_keys[] = {HAND_SKELETON_KEY_OPTIONS, HAND_LUT_KEY_OPTIONS};

static int run_pose(const cli_command *cmd, const cli_args *args)
{
    static const char *const picture_options[] = {"views", "png-size", "labels",
                                                  "bare",  "caption",  NULL};
    int rc = require_option(cmd, args, "png", picture_options);
    if (rc) return rc;
    const char *png = cli_get(cmd, args, "png"), *out = args->common.output;
    const char *bvh = cli_get(cmd, args, "bvh"), *positions = cli_get(cmd, args, "positions");
    const cli_output outputs[] = {{"--png", &png, k_png_format, false},
                                  {"-o", &out, NULL, false},
                                  {"--bvh", &bvh, NULL, false},
                                  {"--positions", &positions, k_positions_formats, false}};
    hand_params params;
    if ((rc = hand_load_params(cmd, args, &params))) return rc;
    sk_hand_skeleton skel;
    rc = hand_build_skeleton(cmd, args, &params.hand, SK_HAND_SIDE_RIGHT, 0, 0, &skel);
    if (rc) return rc;
    sk_output_set *written = NULL;
    if ((rc = cli_reserve_outputs(outputs, 4, &written))) return rc;
    const char *set = cli_get(cmd, args, "constraints");
    sk_hand_input in = {0};
    if (!rc) rc = hand_parse_inputs(cmd, args, &in);
    sk_hand_lut luts[16];
    int lut_count = 0;
    if (!rc) rc = build_luts(cmd, args, &params.lut, luts, &lut_count);
    sk_error err = {0};
    double q[SK_HAND_DOF_COUNT];
    sk_hand_solve_info info;
    const char *potential = cli_get(cmd, args, "potential");
    if (!rc && potential && (set || lut_count > 0))
        rc = cli_fail(CLI_EXIT_USAGE, "--potential does not go with --constraints or --samples");
    hand_poser poser = {0};
    if (!rc) rc = hand_poser_open(&poser, &skel, potential, set ? set : "natural", luts, lut_count);
    if (!rc) rc = hand_poser_solve(&poser, &in, q, &info);
    if (!rc && info.pins_clamped > 0)
        fprintf(
            stderr,
            "shitsukan: note: %d pinned value(s) were outside the joint limits and were clamped\n",
            info.pins_clamped);
    if (!rc && !info.converged)
        fprintf(stderr,
                "shitsukan: note: the iterative solve stopped at residual %.3g after %d steps\n",
                info.residual, info.newton_iterations);
    sk_hand_draw_desc draw;
    char caption[512];
    if (!rc && png && !(rc = parse_draw_options(cmd, args, &draw))) {
        const char *given = cli_get(cmd, args, "caption");
        if (given || draw.hide_cues)
            snprintf(caption, sizeof caption, "%s", given ? given : "");
        else
            describe_inputs(&in, q, caption, sizeof caption);
        draw.caption = caption;
        rc = write_pose_png(&skel, q, &draw, png);
    }
    if (!rc && out && sk_hand_pose_write_json(&skel, q, &info, out, &err) != SK_OK)
        rc = cli_fail_error(&err);
    if (!rc && bvh && sk_hand_bvh_write(&skel, q, 1, 1.0 / 30.0, bvh, &err) != SK_OK)
        rc = cli_fail_error(&err);
    if (!rc && positions) rc = write_positions(&skel, q, 1, positions);
    rc = cli_finish_outputs(written, rc);
    if (!rc && !out) {
        for (int i = 0; i < SK_HAND_DOF_COUNT; i++)
            printf("%-11s %10.4f%s\n", sk_hand_dof(i)->name,
                   sk_hand_dof(i)->translation ? q[i] : q[i] * SK_RAD_TO_DEG,
                   sk_hand_dof(i)->translation ? " mm" : "");
    }
    hand_poser_close(&poser);
    for (int i = 0; i < lut_count; i++) sk_hand_lut_free(&luts[i]);
    return rc;
}

const cli_command cmd_hand_pose = {
    .name = "hand pose",
    .summary = "pose the hand skeleton from a few pinned angles or torques (natural coupling)",
    .usage = "shitsukan hand pose [--pin DOF=DEG]... [--torque DOF=T]... [options]",
    .description =
        "Solves the equilibrium of joint springs and the natural-coupling potential of\n"
        "Yasumuro's thesis (eq. 3.17): pinned DOFs are held, the others settle, every DOF\n"
        "stays within its limits. DOF names: wrist.tx/ty/tz (mm), wrist.flex/roll/dev,\n"
        "T.CMC.flex T.CMC.abd T.MCP.flex T.MCP.abd T.IP.flex, and for F in I M R L:\n"
        "F.CMC.flex F.CMC.abd F.MCP.flex F.MCP.abd F.PIP.flex F.DIP.flex (flexion positive;\n"
        "docs/hand.md has axes, signs and ranges). Writes the pose as JSON with -o, else\n"
        "prints the DOF values in degrees; --png draws it as a stick figure (orthographic\n"
        "views, dorsal and radial by default). With --samples and --pairs, lookup-table\n"
        "potentials built from the samples join the linear rows (thesis 3.2.3).",
    .examples = "  shitsukan hand pose --pin L.MCP.flex=60 -o pose.json --png pose.png\n"
                "  shitsukan hand pose --torque I.MCP.flex=0.8 --constraints yasumuro-table-3.2\n"
                "  shitsukan hand pose --samples angles.csv --pairs I.MCP.flex:I.PIP.flex --pin "
                "I.MCP.flex=50",
    .options = pose_options,
    .option_count = (int)(sizeof pose_options / sizeof pose_options[0]),
    .common = CLI_COMMON_OUTPUT | CLI_COMMON_QUIET | CLI_COMMON_PRESET | CLI_COMMON_SET,
    .min_positional = 0,
    .max_positional = 0,
    .preset_module = "hand",
    .schema = &hand_pose_schema,
    .run = run_pose,
    .key_options = pose_keys,
    .key_option_count = (int)(sizeof pose_keys / sizeof pose_keys[0]),
};

/* ------------------------------------------------------------ hand animate */

static const cli_option animate_options[] = {
    {"bvh", 0, "FILE", "write the motion as BVH (mm, Blender: import with scale 0.001)", false},
    {"positions", 0, "FILE", "write joint positions of every frame (.csv or .json)", false},
    {"angles", 0, "FILE", "write the joint angles of every frame as CSV (degrees)", false},
    {"constraints", 0, "SET",
     "override the file's constraint set (natural, yasumuro-table-3.2, none, FILE)", false},
    {"potential", 0, "FILE",
     "a calibrated potential (hand calibrate) instead of the file's constraint set", false},
    {"side", 0, "SIDE", "override the file's side: right or left", false},
    {"hand-length", 0, "MM", "override the hand length", false},
    {"hand-breadth", 0, "MM", "override the hand breadth", false},
    {"anatomy", 0, "FILE", "anatomy JSON (default built in)", false},
    {"frames-dir", 0, "DIR", "draw every frame as a stick figure: DIR/frame_0000.png, ...", false},
    {"views", 0, "LIST",
     "views of the frames: 1-4 of dorsal, palmar, radial, ulnar (default dorsal,radial)", false},
    {"png-size", 0, "WxH", "frame size in pixels (default 400 per view x 480)", false},
    {"labels", 0, NULL, "write the joint names in the frames", false},
    {"bare", 0, NULL,
     "the stick figures alone: no view titles, direction arrows, scale bar or captions", false},
    {"plot", 0, "FILE", "joint-angle plot (PNG) of the driven DOFs and those that follow them",
     false},
    {"plot-dofs", 0, "LIST",
     "DOFs to plot, comma-separated (default: the driven ones, then the most moving)", false},
    {"plot-title", 0, "TEXT", "title of the plot (default: the animation file's name)", false},
    {"plot-size", 0, "WxH", "plot size in pixels (default 800x560)", false},
    {"glb", 0, "FILE",
     "write the skinned, animated hand surface as glTF binary (skeleton, weights, 3 LODs)", false},
    {"landmarks", 0, "FILE", "write the 21 hand landmarks of every frame (.json or .csv)", false},
    {"meshes-dir", 0, "DIR",
     "write the hand surface of frames as DIR/frame_0000.obj, ... (with --mesh-frames)", false},
    {"mesh-frames", 0, "LIST", "frames for --meshes-dir, comma-separated (default all)", false},
    {"skinning", 0, "METHOD", "skinning of the surface outputs: rigid, lbs or dqs (default)",
     false},
    {"texture", 0, "PREFIX",
     "with --meshes-dir: also bake the skin texture PREFIX-albedo.png, PREFIX-normal.png", false},
    {"texture-size", 0, "N", "atlas size of --texture and --glb in pixels (default 1024)", false},
    {"material", 0, "KIND",
     "--glb material: blend (the thesis's 0.3 lit : 0.7 unlit texture, default) or pbr", false},
    {"triangles", 0, "N", "triangles of the surface's level 0 (default 8000)", false},
    {"flesh", 0, "FILE", "flesh sizes JSON of the surface (default built in)", false},
};

/* --plot: the listed DOFs (or the driven ones and those that move most) over the frames. */
static int write_angle_plot(const cli_command *cmd, const cli_args *args,
                            const sk_hand_animation *anim, const double *dofs, int frames,
                            const char *path)
{
    bool driven[SK_HAND_DOF_COUNT];
    sk_hand_animation_driven(anim, driven);
    int list[SK_HAND_DOF_COUNT], n = 0;
    const char *given = cli_get(cmd, args, "plot-dofs");
    if (given) {
        const char *p = given;
        while (*p) {
            size_t len = strcspn(p, ",");
            char name[64];
            snprintf(name, sizeof name, "%.*s", (int)(len < sizeof name ? len : sizeof name - 1),
                     p);
            int d = sk_hand_dof_find(name);
            if (d < 0) return cli_fail(CLI_EXIT_USAGE, "--plot-dofs: unknown DOF \"%s\"", name);
            if (n == SK_HAND_DOF_COUNT)
                return cli_fail(CLI_EXIT_USAGE, "--plot-dofs: too many DOFs");
            list[n++] = d;
            p += len;
            if (*p == ',') p++;
        }
        if (n == 0) return cli_fail(CLI_EXIT_USAGE, "--plot-dofs is empty");
    } else {
        /* the driven DOFs, then the others that move most (at least half a degree): five
           lines keep the legend small */
        n = sk_hand_moving_dofs(dofs, frames, driven, 0.5 * SK_DEG_TO_RAD, list, 5);
    }
    char title[256];
    const char *given_title = cli_get(cmd, args, "plot-title");
    const char *base = strrchr(args->positional[0], '/');
    snprintf(title, sizeof title, "%s",
             given_title ? given_title
             : base      ? base + 1
                         : args->positional[0]);
    sk_plot_desc pd = {.title = title[0] ? title : NULL};
    int rc = cli_get_size(cmd, args, "plot-size", 800, 560, 16384, &pd.width, &pd.height);
    if (rc) return rc;
    if (pd.width < 64 || pd.height < 64)
        return cli_fail(CLI_EXIT_USAGE, "--plot-size %dx%d: each side must be at least 64 pixels",
                        pd.width, pd.height);
    sk_error err = {0};
    sk_image img;
    if (sk_hand_plot_angles(dofs, frames, list, n, driven, &pd, &img, &err) != SK_OK)
        return cli_fail_error(&err);
    sk_result r = sk_image_write_png(&img, path, NULL, &err);
    sk_image_free(&img);
    return r == SK_OK ? 0 : cli_fail_error(&err);
}

/* --frames-dir: every frame as a stick figure, captioned with its inputs. */
static int write_frames(const sk_hand_skeleton *skel, const sk_hand_animation *anim,
                        const double *dofs, int frames, const sk_hand_draw_desc *draw,
                        const char *dir, bool quiet)
{
    char(*text)[160] = malloc(sizeof *text * (size_t)frames);
    const char **captions = malloc(sizeof *captions * (size_t)frames);
    if (!text || !captions) {
        free(text);
        free(captions);
        return cli_fail(CLI_EXIT_RUNTIME, "out of memory");
    }
    for (int f = 0; f < frames; f++) {
        sk_hand_input in;
        sk_hand_animation_input(anim, f, &in);
        int n = snprintf(text[f], sizeof text[f], "frame %d/%d: ", f, frames - 1);
        describe_inputs(&in, dofs + (size_t)f * SK_HAND_DOF_COUNT, text[f] + n,
                        sizeof text[f] - (size_t)n);
        captions[f] = text[f];
    }
    sk_progress_bar bar;
    sk_progress_bar_begin(&bar, "frames", !quiet);
    sk_error err = {0};
    sk_result r =
        sk_hand_frames_write_png(skel, dofs, frames, draw, draw->hide_cues ? NULL : captions, dir,
                                 sk_progress_bar_sink(&bar), &err);
    sk_progress_bar_end(&bar);
    free(text);
    free(captions);
    return r == SK_OK ? 0 : cli_fail_error(&err);
}

static const cli_key_option animate_keys[] = {HAND_SKELETON_KEY_OPTIONS, HAND_SURFACE_KEY_OPTIONS};

static int run_animate(const cli_command *cmd, const cli_args *args)
{
    const char *bvh = cli_get(cmd, args, "bvh"), *positions = cli_get(cmd, args, "positions");
    const char *angles = cli_get(cmd, args, "angles");
    const char *frames_dir = cli_get(cmd, args, "frames-dir"), *plot = cli_get(cmd, args, "plot");
    bool surface_outputs = cli_has(cmd, args, "glb") || cli_has(cmd, args, "landmarks") ||
                           cli_has(cmd, args, "meshes-dir");
    if (!bvh && !positions && !angles && !frames_dir && !plot && !surface_outputs)
        return cli_fail(
            CLI_EXIT_USAGE,
            "nothing to write: give --bvh, --positions, --angles, --plot, --frames-dir, --glb, "
            "--landmarks or --meshes-dir");
    static const char *const frame_options[] = {"views", "png-size", "labels", "bare", NULL};
    static const char *const plot_options[] = {"plot-dofs", "plot-title", "plot-size", NULL};
    sk_hand_draw_desc draw;
    int draw_rc = require_option(cmd, args, "frames-dir", frame_options);
    if (!draw_rc) draw_rc = require_option(cmd, args, "plot", plot_options);
    if (!draw_rc) draw_rc = parse_draw_options(cmd, args, &draw);
    if (draw_rc) return draw_rc;
    static const char *const surface_options[] = {"skinning", "triangles", "flesh", NULL};
    static const char *const mesh_options[] = {"mesh-frames", "texture", NULL};
    if (!cli_has(cmd, args, "glb") && !cli_has(cmd, args, "meshes-dir"))
        draw_rc = require_option(cmd, args, "glb", surface_options);
    if (!draw_rc) draw_rc = require_option(cmd, args, "meshes-dir", mesh_options);
    if (!draw_rc)
        draw_rc = require_option(cmd, args, "glb", (const char *const[]){"material", NULL});
    if (!draw_rc && cli_has(cmd, args, "texture-size") && !cli_has(cmd, args, "glb") &&
        !cli_has(cmd, args, "texture"))
        draw_rc = cli_fail(CLI_EXIT_USAGE, "--texture-size needs --glb or --texture");
    if (draw_rc) return draw_rc;
    hand_animate_surface surface;
    memset(&surface, 0, sizeof surface);
    static const char *const k_glb_format[] = {".glb", NULL};
    const cli_output outputs[] = {{"--bvh", &bvh, NULL, false},
                                  {"--positions", &positions, k_positions_formats, false},
                                  {"--angles", &angles, NULL, false},
                                  {"--plot", &plot, k_png_format, false},
                                  {"--frames-dir", &frames_dir, NULL, true},
                                  {"--glb", &surface.glb, k_glb_format, false},
                                  {"--landmarks", &surface.landmarks, k_positions_formats, false},
                                  {"--meshes-dir", &surface.meshes_dir, NULL, true}};
    sk_output_set *written = NULL;
    sk_error err = {0};
    sk_hand_animation *anim = malloc(sizeof *anim);
    double *dofs = NULL;
    hand_poser poser = {0};
    int rc = 0;
    if (!anim) rc = cli_fail(CLI_EXIT_RUNTIME, "out of memory");
    const char *path = args->positional[0];
    if (!rc && sk_hand_animation_load_file(path, anim, &err) != SK_OK) rc = cli_fail_error(&err);
    hand_params params;
    if (!rc) rc = hand_load_params(cmd, args, &params);
    sk_hand_skeleton skel;
    if (!rc)
        rc = hand_build_skeleton(cmd, args, &params.hand, anim->side, anim->hand_length_mm,
                                 anim->hand_breadth_mm, &skel);
    const char *set = cli_get(cmd, args, "constraints"),
               *potential = cli_get(cmd, args, "potential");
    if (!rc && set && potential)
        rc = cli_fail(CLI_EXIT_USAGE, "--potential does not go with --constraints");
    if (!rc) rc = hand_poser_open(&poser, &skel, potential, set ? set : anim->constraints, NULL, 0);
    int frames = rc ? 0 : sk_hand_animation_frame_count(anim);
    if (!rc) {
        /* the solved angles, and the frame pictures being drawn (one per thread) */
        char driver[128];
        snprintf(driver, sizeof driver, "%d frames ((keys - 1) x steps of %s)", frames, path);
        double picture = frames_dir ? cli_image_bytes(draw.width > 0 ? draw.width : 1600,
                                                      draw.height > 0 ? draw.height : 480, 8) *
                                          sk_threads_max()
                                    : 0;
        rc = cli_check_memory(args, (double)frames * SK_HAND_DOF_COUNT * sizeof *dofs * 2 + picture,
                              driver);
    }
    /* the surface outputs' options, memory and texture files */
    if (!rc && surface_outputs)
        rc = hand_animate_surface_parse(cmd, args, &params, frames, &surface);
    if (!rc && (surface.glb || surface.meshes_dir))
        rc = hand_surface_plan_check_memory(args, &surface.plan, &skel,
                                            surface.glb || surface.plan.prefix,
                                            surface.glb ? SK_HAND_LOD_COUNT : 1);
    if (!rc) rc = cli_reserve_outputs(outputs, 8, &written);
    if (!rc && surface_outputs) rc = hand_surface_plan_reserve(&surface.plan, written, NULL);
    if (!rc && !(dofs = malloc((size_t)frames * SK_HAND_DOF_COUNT * sizeof *dofs)))
        rc = cli_fail(CLI_EXIT_RUNTIME, "out of memory");
    sk_progress_bar bar;
    bool bar_begun = !rc;
    if (bar_begun) sk_progress_bar_begin(&bar, "hand animate", !args->common.quiet);
    int unconverged = 0;
    for (int f = 0; f < frames && !rc; f++) {
        sk_hand_input in;
        sk_hand_solve_info info;
        sk_hand_animation_input(anim, f, &in);
        rc = hand_poser_solve(&poser, &in, dofs + (size_t)f * SK_HAND_DOF_COUNT, &info);
        unconverged += !rc && !info.converged;
        sk_progress_bar_update(&bar, (f + 1.0) / frames);
    }
    if (bar_begun) sk_progress_bar_end(&bar);
    if (!rc && unconverged > 0)
        fprintf(
            stderr,
            "shitsukan: warning: %d of %d frames did not converge (their last iterates are kept)\n",
            unconverged, frames);
    double frame_time = rc ? 0 : 1.0 / anim->fps;
    if (!rc && bvh && sk_hand_bvh_write(&skel, dofs, frames, frame_time, bvh, &err) != SK_OK)
        rc = cli_fail_error(&err);
    if (!rc && positions) rc = write_positions(&skel, dofs, frames, positions);
    if (!rc && angles && sk_hand_angles_write_csv(dofs, frames, frame_time, angles, &err) != SK_OK)
        rc = cli_fail_error(&err);
    if (!rc && plot) rc = write_angle_plot(cmd, args, anim, dofs, frames, plot);
    if (!rc && frames_dir)
        rc = write_frames(&skel, anim, dofs, frames, &draw, frames_dir, args->common.quiet);
    if (!rc && surface_outputs)
        rc = hand_animate_surface_write(&surface, &skel, dofs, frames, anim->fps);
    if (written) rc = cli_finish_outputs(written, rc);
    if (!rc && !args->common.quiet)
        fprintf(stderr, "shitsukan: %d frames from %d keys\n", frames, anim->key_count);
    hand_animate_surface_free(&surface);
    hand_poser_close(&poser);
    free(dofs);
    free(anim);
    return rc;
}

const cli_command cmd_hand_animate = {
    .name = "hand animate",
    .summary = "keyframe animation of the hand with the equilibrium solved every frame",
    .usage =
        "shitsukan hand animate FILE [--bvh OUT.bvh] [--positions OUT.csv] [--angles OUT.csv]\n"
        "       [--plot ANGLES.png] [--frames-dir DIR]",
    .description =
        "Reads an animation file (keys of partial inputs: \"pin\" angles in degrees and\n"
        "\"torque\" values per DOF), interpolates every input between keys by cubic Bezier\n"
        "curves (thesis 4.2.2) or Catmull-Rom, solves the natural posture at every frame and\n"
        "writes BVH (root with 6 channels, joints Zrotation Yrotation Xrotation, offsets in\n"
        "mm), joint positions and joint angles, a joint-angle plot, and stick-figure frames\n"
        "(dorsal and radial views by default). --potential poses with a calibrated potential\n"
        "(hand calibrate) instead of the file's constraint set; with a mixture, pins and\n"
        "torques choose the blend of its components. Shipped examples:\n"
        "presets/hand/little-mcp.json (Fig. 4.19), little-dip.json (Fig. 4.20), piano-key.json.",
    .examples =
        "  shitsukan hand animate presets/hand/little-mcp.json --bvh little-mcp.bvh\n"
        "  shitsukan hand animate presets/hand/piano-key.json --positions keys.json --side left\n"
        "  shitsukan hand animate presets/hand/little-dip.json --plot angles.png --frames-dir "
        "frames",
    .options = animate_options,
    .option_count = (int)(sizeof animate_options / sizeof animate_options[0]),
    .common = CLI_COMMON_QUIET | CLI_COMMON_PRESET | CLI_COMMON_SET,
    .min_positional = 1,
    .max_positional = 1,
    .preset_module = "hand",
    .schema = &hand_animate_schema,
    .run = run_animate,
    .key_options = animate_keys,
    .key_option_count = (int)(sizeof animate_keys / sizeof animate_keys[0]),
};

/* ------------------------------------------------------------ hand calibrate */

static const cli_option calibrate_options[] = {
    {"pairs", 0, "A:B,...",
     "fit the thesis's pair lines y = A x + b instead (constraint rows file)", false},
    {"weights", 0, "RULE",
     "pair lines: thesis (eq. 3.18, default) or inverse-variance (default of --method pairs)",
     false},
    {"method", 0, "METHOD",
     "potential: mixture (default; components chosen on held-out samples), gaussian, or pairs "
     "(the thesis's form: relaxed posture measured, pair rows and weight scale chosen on "
     "held-out samples, --pairs the candidates)",
     false},
    {"weight-scale", 0, "S", "--method pairs: multiplies the fitted weights (default: chosen)",
     false},
    {"max-pairs", 0, "N", "--method pairs: fitted rows at most (default 16)", false},
    {"components", 0, "N", "potential: fixed mixture component count (default: chosen)", false},
    {"prior-strength", 0, "S",
     "potential: pseudo-samples of the base set's Gaussian (default: chosen; 0 = none)", false},
    {"base", 0, "SET",
     "potential: set kept outside the samples' DOFs and shrunk toward (default natural)", false},
    {"units", 0, "UNIT", "angles of the CSV: deg (default) or rad", false},
    {"group", 0, "COLUMN",
     "CSV column naming the trial or person (held out together when choosing)", false},
    {"ignore-columns", 0, "A,B", "CSV columns to skip (besides frame and time)", false},
};

static const cli_key_option calibrate_keys[] = {
    {"method", "potential.method", NULL, false},
    {"components", "potential.components", NULL, false},
    {"max-pairs", "potential.max_pairs", NULL, false},
    {"weight-scale", "potential.weight_scale", NULL, false},
    {"weights", "potential.weight_rule", NULL, false},
};

static int run_calibrate(const cli_command *cmd, const cli_args *args)
{
    const char *pairs_text = cli_get(cmd, args, "pairs");
    hand_params params;
    int params_rc = hand_load_params(cmd, args, &params);
    if (params_rc) return params_rc;
    if (params.potential.method == SK_HAND_POTENTIAL_PAIRS)
        return hand_calibrate_potential(cmd, args, &params);
    static const char *const selection_only[] = {"weight-scale", "max-pairs", NULL};
    for (int i = 0; selection_only[i]; i++)
        if (cli_has(cmd, args, selection_only[i]))
            return cli_fail(CLI_EXIT_USAGE, "--%s needs --method pairs", selection_only[i]);
    if (!pairs_text) {
        static const char *const pair_only[] = {"weights", NULL};
        int rc = require_option(cmd, args, "pairs", pair_only);
        return rc ? rc : hand_calibrate_potential(cmd, args, &params);
    }
    static const char *const potential_only[] = {"method", "components", "prior-strength", "base",
                                                 NULL};
    for (int i = 0; potential_only[i]; i++)
        if (cli_has(cmd, args, potential_only[i]))
            return cli_fail(CLI_EXIT_USAGE,
                            "--%s is for the potential; it does not go with --pairs",
                            potential_only[i]);
    if (!args->common.output) return cli_fail(CLI_EXIT_USAGE, "-o rows.json is required");
    sk_hand_weight_rule rule =
        params.potential.weight_rule ? params.potential.weight_rule : SK_HAND_WEIGHT_THESIS;
    sk_error err = {0};
    int pairs[64][2], n = 0;
    if (sk_hand_parse_pairs(pairs_text, pairs, 64, &n, &err) != SK_OK) {
        sk_error_prefix(&err, err.result, "--pairs");
        return cli_fail_error(&err);
    }
    sk_hand_samples samples;
    const char *path = args->positional[0];
    int read_rc = hand_read_samples(cmd, args, path, &samples);
    if (read_rc) return read_rc;
    sk_hand_fit fits[64];
    int rc = 0;
    if (sk_hand_calibrate((const double *const *)samples.column, samples.count,
                          (const int(*)[2])pairs, n, rule, fits, &err) != SK_OK) {
        sk_error_prefix(&err, err.result, "%s", path);
        rc = cli_fail_error(&err);
    }
    char note[512];
    snprintf(note, sizeof note, "fitted from %d samples of %s", samples.count, path);
    if (!rc && sk_hand_fits_write_json(fits, n, rule, note, args->common.output, &err) != SK_OK)
        rc = cli_fail_error(&err);
    for (int k = 0; k < n && !rc && !args->common.quiet; k++)
        printf("%s:%s  A %.4f  b %.3f deg  W %.3f  rms %.3f deg\n",
               sk_hand_dof(fits[k].dof_x)->name, sk_hand_dof(fits[k].dof_y)->name, fits[k].slope,
               fits[k].intercept * SK_RAD_TO_DEG, fits[k].weight,
               sqrt(fits[k].mean_sq_distance) * SK_RAD_TO_DEG);
    sk_hand_samples_free(&samples);
    return rc;
}

const cli_command cmd_hand_calibrate = {
    .name = "hand calibrate",
    .summary = "fit the natural-posture potential (or the thesis's pair rows) to joint-angle "
               "samples (3.2.2)",
    .usage =
        "shitsukan hand calibrate SAMPLES.csv -o potential.json [--method mixture|gaussian|pairs]\n"
        "       shitsukan hand calibrate SAMPLES.csv --pairs A:B[,C:D...] -o rows.json",
    .description =
        "Reads measured joint angles (a CSV with a header of DOF names and one sample per\n"
        "line, degrees or --units rad; columns 'frame', 'time', --group and --ignore-columns\n"
        "are not DOFs). Without --pairs it fits the whole potential of eq. 3.17: the relaxed\n"
        "posture is the samples' mean and K + A'WA their precision (springs and coupling rows),\n"
        "shrunk toward the base set, as a mixture of such Gaussians where held-out samples\n"
        "say it helps; use it with hand pose --potential. --method pairs keeps the thesis's\n"
        "form instead: the relaxed posture from the samples, the base set's springs, and the\n"
        "pair rows (of --pairs, default every pair) and their weight scale chosen by the\n"
        "held-out error, starting from the base set's rows. With --pairs alone it fits one\n"
        "least-squares line y = A x + b per pair and weights it by the spread about the line,\n"
        "w = mean l^2 / max over the pairs (eq. 3.18: the loosest pair weighs most), or by\n"
        "inverse variance; the result is a constraint file for --constraints.",
    .examples =
        "  shitsukan hand calibrate glove.csv --group person -o potential.json\n"
        "  shitsukan hand calibrate glove.csv --group person --method pairs -o potential.json\n"
        "  shitsukan hand calibrate glove.csv --pairs R.MCP.flex:L.MCP.flex,I.PIP.flex:I.DIP.flex "
        "-o rows.json",
    .options = calibrate_options,
    .option_count = (int)(sizeof calibrate_options / sizeof calibrate_options[0]),
    .common =
        CLI_COMMON_OUTPUT | CLI_COMMON_QUIET | CLI_COMMON_SEED | CLI_COMMON_PRESET | CLI_COMMON_SET,
    .min_positional = 1,
    .max_positional = 1,
    .preset_module = "hand",
    .schema = &hand_calibrate_schema,
    .run = run_calibrate,
    .key_options = calibrate_keys,
    .key_option_count = (int)(sizeof calibrate_keys / sizeof calibrate_keys[0]),
    .seed_key = "potential.seed",
    .set_option_keys = hand_set_prior_strength,
};
