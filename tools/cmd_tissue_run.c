/* `shitsukan tissue run`: a character (Shigemori & Kawai's fat model) driven by a motion
 * capture file, simulated and written as a rest mesh, a point cache, glTF, OBJ frames,
 * rendered frames, a plot and statistics. Argument parsing only (sk_tissue_run). */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cmd_tissue.h"

static const cli_option k_run_options[] = {
    {"character", 0, "arm|body|FILE",
     "the character: a shipped one (presets/tissue/) or a JSON file", false},
    {"motion", 0, "FILE.bvh|curl|jump|walk", "the motion: a BVH file or a shipped motion", false},
    {"fps", 0, "N", "output frames per second (1-1000); default 30", false},
    {"frames", 0, "A:B", "write frames A to B only (the simulation still starts at 0); default all",
     false},
    {"motion-unit-mm", 0, "MM",
     "millimetres per length unit of the motion; default the character's", false},
    {"obj-frames", 0, NULL, "also write frames/NNNN.obj", false},
    {"render", 0, NULL, "also render every frame to render/NNNN.png", false},
    {"render-width", 0, "N", "width of the rendered frames in pixels (64-4096); default 480",
     false},
    {"plot", 0, "FILE.png", "plot the tracked skin points with and without the fat layer", false},
    {"no-glb", 0, NULL, "do not write skin.glb", false},
    {"no-pc2", 0, NULL, "do not write skin.pc2", false},
    {"save-state", 0, "FILE", "save the simulation state after the last frame", false},
    {"resume", 0, "FILE", "start from a saved state (at or before the first frame)", false},
};

/* "A:B" with 0 <= A <= B. */
static int parse_frames(const char *text, int *a, int *b)
{
    char *end;
    errno = 0;
    long x = strtol(text, &end, 10);
    if (end == text || *end != ':' || errno) goto bad;
    const char *second = end + 1;
    long y = strtol(second, &end, 10);
    if (end == second || *end || errno || x < 0 || y < x || y > 100000000) goto bad;
    *a = (int)x;
    *b = (int)y;
    return 0;
bad:
    return cli_fail(CLI_EXIT_USAGE, "--frames '%s' must be A:B with 0 <= A <= B", text);
}

/* A shipped motion name, or the path as given. */
static int motion_path(const char *motion, char *path, size_t size)
{
    bool looks_like_file = strchr(motion, '/') || strstr(motion, ".bvh");
    if (looks_like_file) {
        snprintf(path, size, "%s", motion);
        return 0;
    }
    const char *dirs[8];
    int n = cli_preset_dirs(dirs, 8);
    for (int i = 0; i < n; i++) {
        snprintf(path, size, "%s/tissue/%s.bvh", dirs[i], motion);
        FILE *f = fopen(path, "rb");
        if (f) {
            fclose(f);
            return 0;
        }
    }
    return cli_fail(CLI_EXIT_USAGE,
                    "--motion '%s': no such file or shipped motion (curl, jump, walk)", motion);
}

static int run_run(const cli_command *cmd, const cli_args *args)
{
    const char *out = args->common.output;
    const char *motion_name = cli_get(cmd, args, "motion");
    if (!out) return cli_fail(CLI_EXIT_USAGE, "-o DIR is required (the output folder)");
    if (!motion_name)
        return cli_fail(CLI_EXIT_USAGE, "--motion is required (a BVH file, or curl, jump, walk)");
    sk_tissue_run_desc desc = {0};
    desc.output_dir = out;
    long long fps, width;
    double unit;
    int status = cli_get_int(cmd, args, "fps", 30, 1, 1000, &fps);
    if (!status) status = cli_get_int(cmd, args, "render-width", 480, 64, 4096, &width);
    if (!status) status = cli_get_double(cmd, args, "motion-unit-mm", 0, 1e-3, 1e4, &unit);
    if (!status && cli_has(cmd, args, "frames"))
        status = parse_frames(cli_get(cmd, args, "frames"), &desc.first_frame, &desc.last_frame);
    char path[PATH_MAX];
    if (!status) status = motion_path(motion_name, path, sizeof path);
    if (status) return status;
    desc.fps = (int)fps;
    desc.render_width = (int)width;
    desc.obj_frames = cli_has(cmd, args, "obj-frames");
    desc.render = cli_has(cmd, args, "render");
    desc.no_glb = cli_has(cmd, args, "no-glb");
    desc.no_pc2 = cli_has(cmd, args, "no-pc2");
    desc.plot = cli_get(cmd, args, "plot");
    desc.save_state = cli_get(cmd, args, "save-state");
    desc.resume_state = cli_get(cmd, args, "resume");
    if (cli_has(cmd, args, "frames") && desc.first_frame == 0 && desc.last_frame == 0)
        desc.last_frame = 0;

    sk_error err = {0};
    sk_bvh *bvh = malloc(sizeof *bvh);
    if (!bvh) return cli_fail(CLI_EXIT_RUNTIME, "out of memory");
    if (sk_bvh_load_file(path, bvh, &err) != SK_OK) {
        free(bvh);
        return cli_fail_error(&err);
    }
    /* the folder, the plot and the saved state appear together at the end, or none */
    static const char *const k_png[] = {".png", NULL};
    const char *plot = desc.plot, *state = desc.save_state;
    const cli_output outputs[] = {{"-o", &desc.output_dir, NULL, true},
                                  {"--plot", &plot, k_png, false},
                                  {"--save-state", &state, NULL, false}};
    sk_output_set *written = NULL;
    if ((status = cli_reserve_outputs(outputs, 3, &written))) {
        sk_bvh_free(bvh);
        free(bvh);
        return status;
    }
    desc.plot = plot;
    desc.save_state = state;
    sk_tissue_model *model = NULL;
    status = tissue_cli_build(cmd, args, &model);
    sk_tissue_bvh_motion *bm = NULL;
    if (!status &&
        sk_tissue_bvh_motion_create(model, bvh, cli_has(cmd, args, "motion-unit-mm") ? unit : 0.0,
                                    &bm, &err) != SK_OK)
        status = cli_fail(cli_exit_status(err.result), "--motion %s: %s", motion_name, err.message);
    sk_bvh_free(bvh);
    free(bvh);
    sk_tissue_run_stats stats;
    if (!status) {
        sk_tissue_motion motion = sk_tissue_bvh_motion_get(bm);
        sk_progress_bar bar;
        sk_progress_bar_begin(&bar, "simulate", !args->common.quiet);
        desc.progress = sk_progress_bar_sink(&bar);
        sk_result r = sk_tissue_run(model, &motion, &desc, &stats, &err);
        sk_progress_bar_end(&bar);
        if (r != SK_OK) status = cli_fail_error(&err);
    }
    status = cli_finish_outputs(written, status);
    if (!status && !args->common.quiet) {
        tissue_cli_print_model(model);
        printf("%d frames at %d fps (%.2f s of motion, %lld steps): %.1f simulated frames per "
               "second; largest skin "
               "displacement %.2f mm; outputs in %s\n",
               stats.frames, stats.fps, stats.simulated_seconds, (long long)stats.steps,
               stats.frames_per_second, stats.max_displacement_mm, out);
    }
    sk_tissue_bvh_motion_destroy(bm);
    sk_tissue_model_destroy(model);
    return status;
}

const cli_command cmd_tissue_run = {
    .name = "tissue run",
    .summary = "a character's fat and skin jiggling through a motion-capture motion",
    .usage = "shitsukan tissue run --character arm|body|FILE --motion FILE.bvh [--fps N] [--frames "
             "A:B] -o DIR",
    .description =
        "Builds the character (see 'tissue skin'), drives its bones by the BVH motion (joints "
        "bound by name,\n"
        "or by the character's joint_map), moves the muscle points with their volume-keeping "
        "muscles and the\n"
        "fat and skin points by their springs at the character's fixed internal step (XPBD), and "
        "writes into\n"
        "DIR: rest.obj, skin.pc2 (Blender: Mesh Cache modifier on rest.obj), skin.glb, stats.json, "
        "and on\n"
        "request frames/NNNN.obj, render/NNNN.png and a plot. The result does not depend on --fps "
        "or\n"
        "--frames: the same motion gives the same skin at any instant two frame rates share.",
    .examples = "shitsukan tissue run --character arm --motion curl -o out/curl --render\n"
                "shitsukan tissue run --character body --motion walk.bvh --fps 60 --frames 0:120 "
                "-o walk --obj-frames",
    .options = k_run_options,
    .option_count = sizeof k_run_options / sizeof k_run_options[0],
    .common = CLI_COMMON_OUTPUT | CLI_COMMON_SET | CLI_COMMON_THREADS | CLI_COMMON_QUIET,
    .preset_module = "tissue",
    .schema = &sk_tissue_character_schema,
    .run = run_run,
};
