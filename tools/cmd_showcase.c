/* `shitsukan showcase` and `shitsukan showcase midi`: the hand playing the piano (frames,
 * WAV, MP4) and the MIDI writer. Argument parsing only; the showcase is in the library
 * (include/shitsukan/showcase.h). */
#define _POSIX_C_SOURCE 200809L
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "cmd_hand_surface.h"
#include "shitsukan/hand.h"
#include "shitsukan/showcase.h"
#include "video_ffmpeg.h"

static const cli_option k_options[] = {
    {"melody", 0, "FILE", "the melody: text (docs/showcase.md) or a Standard MIDI File (.mid)",
     false},
    {"frames", 0, "A:B",
     "render only frames A..B (inclusive; default all); any split gives the same frames", false},
    {"size", 0, "WxH", "frame size in pixels (default 1280x720)", false},
    {"spp", 0, "N", "camera samples per pixel (default 16)", false},
    {"fps", 0, "N", "frames per second (default 24)", false},
    {"duration", 0, "S", "play only the first S seconds of the melody", false},
    {"constraints", 0, "NAME|FILE", "the hand's coupling potential (default natural)", false},
    {"texture-size", 0, "N", "the hand's skin texture (atlas) in pixels (default 1024)", false},
    {"hand-triangles", 0, "N", "triangles of the hand's surface (default 8000, the thesis's)",
     false},
    {"forearm", 0, "NAME|FILE",
     "the forearm's tissue character (default presets/showcase/forearm.json)", false},
    {"no-forearm", 0, NULL, "leave the forearm out (the hand ends at its wrist)", false},
    {"join", 0, NULL, "render nothing: make the MP4 from the frames already in the folder", false},
    {"no-video", 0, NULL, "do not make the MP4", false},
    {"ffmpeg", 0, "PROGRAM", "the ffmpeg to run (default ffmpeg on the PATH)", false},
};

static bool find_preset(void *user, const char *module, const char *name, char *path, size_t size)
{
    (void)user;
    return cli_find_preset(module, name, path, size);
}

static int load_melody(const char *path, double duration, sk_melody *melody)
{
    sk_error err = {0};
    if (sk_melody_load(path, melody, &err) != SK_OK) return cli_fail_error(&err);
    if (duration > 0 && sk_melody_cut(melody, duration, &err) != SK_OK) {
        sk_melody_free(melody);
        return cli_fail_error(&err);
    }
    return 0;
}

/* The showcase's own keys: the object "showcase" of the stage preset (--set showcase.fps=30),
   beside the stage scene's keys. */
static const sk_schema_field k_part_fields[] = {
    {.key = "showcase",
     .type = SK_FIELD_OBJECT,
     .offset = 0,
     .schema = &sk_showcase_schema,
     .doc = "the frames, the hand, the keyboard, how it is played and the tone"},
};
static const sk_schema k_part_schema = {"showcase", k_part_fields, 1, NULL};

static const cli_key_option k_keys[] = {
    {"spp", "showcase.samples", NULL, false},
    {"fps", "showcase.fps", NULL, true},
    {"texture-size", "showcase.texture_size", NULL, false},
    {"hand-triangles", "showcase.hand_triangles", NULL, false},
};

/* --size WxH: showcase.width and showcase.height. */
static int set_size(const cli_command *command, const cli_args *args, sk_preset *tree)
{
    if (!cli_has(command, args, "size")) return 0;
    const sk_schema_field *w = cli_find_key(command, "showcase.width");
    int width, height;
    int status = cli_get_size(command, args, "size", 0, 0, (int)w->max, &width, &height);
    if (status) return status;
    if (width < w->min || height < w->min)
        return cli_fail(CLI_EXIT_USAGE, "--size %dx%d: at least %gx%g", width, height, w->min,
                        w->min);
    char json[32];
    snprintf(json, sizeof json, "%d", width);
    if ((status = cli_set_key(tree, "showcase.width", json))) return status;
    snprintf(json, sizeof json, "%d", height);
    return cli_set_key(tree, "showcase.height", json);
}

/* The stage scene (--preset, default presets/showcase/stage.json) and the showcase's own
   keys of the same tree (its "showcase" object, the key options, --set). */
static int load_stage(const cli_command *command, const cli_args *args, sk_render_scene_desc *stage,
                      sk_showcase_desc *numbers)
{
    cli_args stage_args = *args;
    if (!stage_args.common.preset) stage_args.common.preset = "stage";
    const char *name = stage_args.common.preset;
    char path[PATH_MAX];
    if (strchr(name, '/') || strstr(name, ".json"))
        snprintf(path, sizeof path, "%s", name);
    else if (!cli_find_preset("showcase", name, path, sizeof path))
        snprintf(path, sizeof path, "%s", name);
    sk_preset *tree = NULL, *part = NULL;
    int status = cli_load_preset(command, &stage_args, &tree);
    if (status) return status;
    sk_error err = {0};
    memset(numbers, 0, sizeof *numbers);
    sk_result r = sk_preset_detach(tree, "showcase", &part, &err);
    if (r == SK_OK) r = sk_preset_bind(part, &k_part_schema, numbers, &err);
    sk_preset_free(part);
    /* the stated defaults (the showcase resolves the same) */
    sk_schema_apply_defaults(&sk_showcase_schema, numbers);
    sk_render_load_desc load = {.scene_path = path, .find_preset = find_preset};
    if (r == SK_OK) r = sk_render_scene_desc_bind(tree, &load, stage, &err);
    sk_preset_free(tree);
    if (r != SK_OK) return cli_fail_error(&err);
    return 0;
}

/* A shipped preset's name or a file's path into `path`. */
static int preset_path(const char *option, const char *name, const char *module,
                       const char *example, char *path, size_t size)
{
    if (strchr(name, '/') || strstr(name, ".json"))
        snprintf(path, size, "%s", name);
    else if (!cli_find_preset(module, name, path, size))
        return cli_fail(CLI_EXIT_USAGE, "--%s '%s': no such preset in %s (e.g. %s)", option, name,
                        module, example);
    return 0;
}

static int load_constraints(const cli_command *command, const cli_args *args,
                            const sk_hand_skeleton *skeleton, sk_hand_constraints *out)
{
    const char *name = cli_get(command, args, "constraints");
    if (!name) name = "natural";
    char path[PATH_MAX];
    int status = preset_path("constraints", name, "hand", "natural", path, sizeof path);
    if (status) return status;
    sk_error err = {0};
    if (sk_hand_constraints_load_file(path, skeleton, out, &err) != SK_OK)
        return cli_fail_error(&err);
    return 0;
}

static int parse_frames(const char *text, int *first, int *last)
{
    char *end;
    long a = strtol(text, &end, 10);
    if (end == text || *end != ':' || a < 0 || a > 10000000)
        return cli_fail(CLI_EXIT_USAGE,
                        "--frames '%s': expected A:B, two frame numbers (A <= B, from 0)", text);
    const char *b_text = end + 1;
    long b = strtol(b_text, &end, 10);
    if (end == b_text || *end || b < a || b > 10000000)
        return cli_fail(CLI_EXIT_USAGE,
                        "--frames '%s': expected A:B, two frame numbers (A <= B, from 0)", text);
    *first = (int)a, *last = (int)b;
    return 0;
}

/* The forearm's tissue character (NULL with --no-forearm). */
static int load_forearm(const cli_command *command, const cli_args *args,
                        sk_tissue_character_desc **out)
{
    *out = NULL;
    if (cli_has(command, args, "no-forearm")) return 0;
    const char *name = cli_get(command, args, "forearm");
    if (!name) name = "forearm";
    char path[PATH_MAX];
    int status = preset_path("forearm", name, "showcase", "forearm", path, sizeof path);
    if (status) return status;
    *out = malloc(sizeof **out);
    if (!*out) return cli_fail(CLI_EXIT_RUNTIME, "out of memory");
    sk_error err = {0};
    if (sk_tissue_character_load(path, *out, &err) != SK_OK) return cli_fail_error(&err);
    return 0;
}

typedef struct run_state {
    sk_skin *back_skin, *palm_skin;
    sk_melody melody;
    sk_render_scene_desc *stage;
    sk_hand_constraints *constraints;
    sk_tissue_character_desc *forearm;
    sk_showcase *showcase;
} run_state;

static void run_state_free(run_state *s)
{
    sk_showcase_destroy(s->showcase);
    sk_skin_destroy(s->back_skin);
    sk_skin_destroy(s->palm_skin);
    free(s->stage);
    free(s->constraints);
    free(s->forearm);
    sk_melody_free(&s->melody);
}

/* Refuses (exit 2) a run whose largest parts need more than --max-memory, before any work:
 * the hand surface (--hand-triangles) and its baked texture (--texture-size), the
 * forearm's tissue grid (its character's skin.spacing_mm) and a frame's render buffers
 * (--size; 32 bytes a pixel: radiance, samples and the 8-bit image). */
static int check_memory(const cli_args *args, const sk_hand_skeleton *skeleton,
                        const sk_tissue_character_desc *forearm, int width, int height, int texture,
                        int triangles)
{
    sk_hand_surface_desc surface = {.triangles = triangles};
    sk_hand_texture_desc bake = {.size = texture};
    double bytes = sk_hand_surface_memory(skeleton, &surface) + sk_hand_texture_memory(&bake) +
                   cli_image_bytes(width, height, 32);
    if (forearm) {
        double tissue = 0;
        sk_error err = {0};
        if (sk_tissue_model_memory(forearm, &tissue, NULL, &err) != SK_OK)
            return cli_fail_error(&err);
        bytes += tissue;
    }
    return cli_check_memory(
        args, bytes,
        "the showcase (--hand-triangles, --texture-size, --size and the forearm's "
        "skin.spacing_mm)");
}

static int run(const cli_command *command, const cli_args *args, run_state *s)
{
    const char *melody_path = cli_get(command, args, "melody");
    if (!melody_path)
        return cli_fail(CLI_EXIT_USAGE,
                        "no melody: give --melody FILE (e.g. presets/showcase/twinkle.txt)");
    if (!args->common.output) return cli_fail(CLI_EXIT_USAGE, "no output folder: give -o DIR");
    int status;
    double duration;
    if ((status =
             cli_get_double(command, args, "duration", 0, 0.001, SK_MELODY_MAX_SECONDS, &duration)))
        return status;
    int first = 0, last = -1;
    const char *frames = cli_get(command, args, "frames");
    if (frames && (status = parse_frames(frames, &first, &last))) return status;
    sk_showcase_run_desc run_desc = {0};
    run_desc.output_dir = args->common.output;
    run_desc.join_only = cli_has(command, args, "join");
    run_desc.no_video = cli_has(command, args, "no-video");
    const char *ffmpeg = cli_get(command, args, "ffmpeg");
    run_desc.encode_video = video_ffmpeg_encode;
    run_desc.encode_video_user = (void *)ffmpeg;
    sk_error err = {0};
    if (sk_showcase_check_output(&run_desc, &err) != SK_OK) return cli_fail_error(&err);
    /* a named ffmpeg must run (the default one may be absent: the run then notes it) */
    if (ffmpeg && !run_desc.no_video && !video_ffmpeg_available(ffmpeg))
        return cli_fail(
            CLI_EXIT_USAGE,
            "ffmpeg '%s' does not run ('%s -version' failed): give a working ffmpeg or --no-video",
            ffmpeg, ffmpeg);
    if ((status = load_melody(melody_path, duration, &s->melody))) return status;
    s->stage = calloc(1, sizeof *s->stage);
    s->constraints = calloc(1, sizeof *s->constraints);
    if (!s->stage || !s->constraints) return cli_fail(CLI_EXIT_RUNTIME, "out of memory");
    sk_showcase_desc desc;
    if ((status = load_stage(command, args, s->stage, &desc))) return status;
    sk_hand_skeleton skeleton;
    if (sk_hand_skeleton_init(&skeleton, NULL, &err) != SK_OK) return cli_fail_error(&err);
    if ((status = load_constraints(command, args, &skeleton, s->constraints))) return status;
    if ((status = load_forearm(command, args, &s->forearm))) return status;
    cli_apply_threads(args);
    if ((status = check_memory(args, &skeleton, s->forearm, desc.width, desc.height,
                               desc.texture_size, desc.hand_triangles)))
        return status;
    if ((status = hand_load_skin("back-of-hand", &s->back_skin)) ||
        (status = hand_load_skin("palm", &s->palm_skin)))
        return status;
    desc.back_skin = s->back_skin;
    desc.palm_skin = s->palm_skin;
    desc.melody = &s->melody;
    desc.stage = s->stage;
    desc.constraints = s->constraints;
    desc.forearm = s->forearm;
    if (sk_showcase_create(&desc, &s->showcase, &err) != SK_OK) return cli_fail_error(&err);
    int count = sk_showcase_frame_count(s->showcase);
    if (last >= count || first >= count)
        return cli_fail(CLI_EXIT_USAGE, "--frames %s: the piece has frames 0:%d", frames,
                        count - 1);
    sk_progress_bar bar;
    sk_progress_bar_begin(&bar, "showcase", !args->common.quiet);
    run_desc.first_frame = first;
    run_desc.last_frame = last;
    run_desc.progress = sk_progress_bar_sink(&bar);
    sk_showcase_stats stats;
    sk_result r = sk_showcase_run(s->showcase, &run_desc, &stats, &err);
    sk_progress_bar_end(&bar);
    if (r != SK_OK) return cli_fail_error(&err);
    if (!args->common.quiet) {
        double posture = stats.seconds_input + stats.seconds_solve;
        double total = posture + stats.seconds_tissue + stats.seconds_skin + stats.seconds_scene +
                       stats.seconds_render + stats.seconds_write;
        if (stats.frames > 0 && total > 0)
            fprintf(stderr,
                    "showcase: %d frames (%d in the piece), %.2f s a frame: render %.0f%%, scene "
                    "%.0f%%, "
                    "posture %.0f%%, forearm %.0f%%, files %.0f%%\n",
                    stats.frames, count, total / stats.frames, 100 * stats.seconds_render / total,
                    100 * stats.seconds_scene / total, 100 * posture / total,
                    100 * stats.seconds_tissue / total, 100 * stats.seconds_write / total);
        if (stats.video_written)
            fprintf(stderr, "showcase: %s/showcase.mp4\n", args->common.output);
        else if (stats.video_note[0])
            fprintf(stderr, "showcase: %s\n", stats.video_note);
    }
    return 0;
}

static int run_showcase(const cli_command *command, const cli_args *args)
{
    run_state s;
    memset(&s, 0, sizeof s);
    int status = run(command, args, &s);
    run_state_free(&s);
    return status;
}

const cli_command cmd_showcase = {
    .name = "showcase",
    .summary = "a hand with skin microrelief plays a wooden piano: frames, WAV and MP4",
    .usage = "shitsukan showcase --melody FILE -o DIR [options]",
    .description =
        "The four models in one scene (docs/showcase.md): a right hand posed by its natural\n"
        "coupling plays a piano cut from the wood solid texture; each note drives two DOFs of\n"
        "its finger (MCP and PIP flexion, thesis Fig. 4.21), the fingertips push the keys\n"
        "down, the wrist travels to reach the notes, a fingering is chosen where the melody\n"
        "gives none; the forearm is a tissue character (presets/showcase/forearm.json) whose fat\n"
        "swings as the wrist travels and strikes. Writes DIR/frames/frame_NNNN.png, "
        "DIR/showcase.wav (44.1 kHz 16-bit),\n"
        "DIR/fingering.txt and, once every frame is in DIR and ffmpeg runs, DIR/showcase.mp4.\n"
        "--frames A:B renders a part (the same frames as a whole run), so a job can be split;\n"
        "the run that completes the folder joins the frames (or run again with --join).\n"
        "The stage (cabinet, lights, film) is presets/showcase/stage.json; --preset takes\n"
        "another and --set changes any of its keys.",
    .examples =
        "  shitsukan showcase --melody presets/showcase/twinkle.txt -o twinkle\n"
        "  shitsukan showcase --melody presets/showcase/ode-to-joy.mid --size 640x360 --spp 4 -o "
        "preview\n"
        "  shitsukan showcase --melody presets/showcase/twinkle.txt --frames 0:99 -o twinkle",
    .options = k_options,
    .option_count = sizeof k_options / sizeof k_options[0],
    .common = CLI_COMMON_OUTPUT | CLI_COMMON_PRESET | CLI_COMMON_SET | CLI_COMMON_THREADS |
              CLI_COMMON_QUIET,
    .min_positional = 0,
    .max_positional = 0,
    .preset_module = "showcase",
    .schema = &sk_render_schema,
    .run = run_showcase,
    .key_options = k_keys,
    .key_option_count = (int)(sizeof k_keys / sizeof k_keys[0]),
    .set_option_keys = set_size,
    .part_schema = &k_part_schema,
};

/* ------------------------------------------------------------ showcase midi */

static const cli_option k_midi_options[] = {
    {"melody", 0, "FILE", "the melody to write (text or MIDI)", false},
};

static int run_midi(const cli_command *command, const cli_args *args)
{
    const char *melody_path = cli_get(command, args, "melody");
    if (!melody_path) return cli_fail(CLI_EXIT_USAGE, "no melody: give --melody FILE");
    if (!args->common.output) return cli_fail(CLI_EXIT_USAGE, "no output: give -o FILE.mid");
    static const char *const midi_extensions[] = {".mid", ".midi", NULL};
    int format;
    int status = cli_output_format("-o", args->common.output, midi_extensions, &format);
    if (status) return status;
    sk_melody melody;
    status = load_melody(melody_path, 0, &melody);
    if (status) return status;
    sk_error err = {0};
    sk_result r = sk_melody_write_midi(&melody, args->common.output, &err);
    sk_melody_free(&melody);
    if (r != SK_OK) return cli_fail_error(&err);
    return 0;
}

const cli_command cmd_showcase_midi = {
    .name = "showcase midi",
    .summary = "write a melody as a Standard MIDI File",
    .usage = "shitsukan showcase midi --melody FILE -o OUT.mid",
    .description =
        "Writes the melody as a format-0 Standard MIDI File (480 ticks per quarter note at\n"
        "120 bpm, so every time lands on a tick of 1/960 s; velocities kept; MIDI has no\n"
        "fingering). presets/showcase/ode-to-joy.mid is made this way from ode-to-joy.txt.",
    .examples =
        "  shitsukan showcase midi --melody presets/showcase/ode-to-joy.txt -o ode-to-joy.mid",
    .options = k_midi_options,
    .option_count = sizeof k_midi_options / sizeof k_midi_options[0],
    .common = CLI_COMMON_OUTPUT | CLI_COMMON_QUIET,
    .min_positional = 0,
    .max_positional = 0,
    .run = run_midi,
};
