/* Benchmark of the showcase: frames per second of the whole pipeline and the share of
 * each stage (melody -> finger intents and wrist, posture solve with the fingertips'
 * contact, skinning of the hand surface, forearm simulation, building the render scene,
 * ray tracing, PNG files) at 1280 x 720 and at a preview size; the non-render stages per
 * frame against their 2 ms budget; then the command as a user runs it, files included. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench_load.h"
#include "shitsukan/preset.h"
#include "shitsukan/showcase.h"

static sk_skin *load_skin(const char *name)
{
    char path[512];
    snprintf(path, sizeof path, "%s/skin/%s.json", SK_BENCH_PRESET_DIR, name);
    sk_preset *p = NULL;
    sk_skin_desc d = {0};
    sk_skin *skin = NULL;
    sk_error err = {0};
    if (sk_preset_load_file(&p, path, &err) != SK_OK ||
        sk_preset_bind(p, &sk_skin_schema, &d, &err) != SK_OK ||
        sk_skin_create(&skin, &d, &err) != SK_OK) {
        fprintf(stderr, "bench_showcase: %s\n", err.message);
        exit(1);
    }
    sk_preset_free(p);
    return skin;
}

static void report(const char *label, const sk_showcase_stats *s, double wall)
{
    char load[128];
    bench_load_average(load, sizeof load);
    double n = s->frames > 0 ? s->frames : 1;
    double non_render = s->seconds_input + s->seconds_solve + s->seconds_skin + s->seconds_tissue;
    double total = non_render + s->seconds_scene + s->seconds_render + s->seconds_write;
    printf("%s: %d frames in %.2f s = %.2f frames/s (load average %s)\n", label, s->frames, wall,
           s->frames / wall, load);
    printf("  per frame: input %.3f ms, posture solve %.3f ms, skinning %.3f ms, tissue %.3f ms | "
           "non-render %.3f ms "
           "(budget 2 ms)\n",
           1e3 * s->seconds_input / n, 1e3 * s->seconds_solve / n, 1e3 * s->seconds_skin / n,
           1e3 * s->seconds_tissue / n, 1e3 * non_render / n);
    printf("  shares: input %.2f%%, solve %.2f%%, skinning %.2f%%, tissue %.2f%%, scene %.1f%%, "
           "render %.1f%%, "
           "files %.1f%%\n",
           100 * s->seconds_input / total, 100 * s->seconds_solve / total,
           100 * s->seconds_skin / total, 100 * s->seconds_tissue / total,
           100 * s->seconds_scene / total, 100 * s->seconds_render / total,
           100 * s->seconds_write / total);
}

/* The forearm's step rate: its skin over the first 4 s of the piece at a few rates
   against 1920 steps a second (converged), as the root mean square over points and
   frames of the distance from it, beside the rms of the flesh's own motion. */
static int step_rates(const sk_showcase_desc *base, const sk_hand_surface *surface)
{
    static const int rates[] = {1920, 480, 240, 144};
    const int count = (int)(sizeof rates / sizeof rates[0]);
    sk_error err = {0};
    sk_melody cut;
    if (sk_melody_copy(base->melody, &cut, &err) != SK_OK ||
        sk_melody_cut(&cut, 4.0, &err) != SK_OK)
        return fprintf(stderr, "%s\n", err.message), 1;
    float *reference = NULL, *skin = NULL, *carried = NULL;
    for (int r = 0; r < count; r++) {
        sk_tissue_character_desc forearm = *base->forearm;
        forearm.simulation.step_hz = rates[r];
        sk_showcase_desc d = *base;
        d.melody = &cut, d.forearm = &forearm, d.surface = surface, d.texture_size = 64;
        d.width = d.height = 16, d.samples = 1;
        sk_showcase *sc = NULL;
        if (sk_showcase_create(&d, &sc, &err) != SK_OK)
            return fprintf(stderr, "%s\n", err.message), 1;
        int frames = sk_showcase_frame_count(sc);
        size_t n = 3 * sk_showcase_forearm_points(sc);
        if (!reference) {
            reference = malloc((size_t)frames * n * sizeof *reference);
            skin = malloc(n * sizeof *skin), carried = malloc(n * sizeof *carried);
            if (!reference || !skin || !carried)
                return fprintf(stderr, "bench_showcase: out of memory\n"), 1;
        }
        double motion = 0, miss = 0;
        for (int f = 0; f < frames; f++) {
            if (sk_showcase_forearm_at(sc, f, skin, carried, &err) != SK_OK)
                return fprintf(stderr, "%s\n", err.message), 1;
            float *ref = reference + (size_t)f * n;
            if (r == 0) memcpy(ref, skin, n * sizeof *skin);
            for (size_t i = 0; i < n; i++) {
                motion += (double)(skin[i] - carried[i]) * (skin[i] - carried[i]);
                miss += (double)(skin[i] - ref[i]) * (skin[i] - ref[i]);
            }
        }
        double points = (double)frames * (double)(n / 3);
        printf("forearm at %d steps a second: the flesh's motion %.3f mm rms, %.3f mm rms from "
               "1920 steps a second\n",
               rates[r], sqrt(motion / points), sqrt(miss / points));
        sk_showcase_destroy(sc);
    }
    free(reference), free(skin), free(carried);
    sk_melody_free(&cut);
    return 0;
}

/* What the showcase plays and shows, from the presets. */
typedef struct inputs {
    sk_melody melody;
    sk_render_scene_desc *stage;
    sk_hand_constraints *constraints;
    sk_skin *back, *palm;
    sk_tissue_character_desc *forearm;
} inputs;

/* The piece, the stage, the hand's natural constraints, the two skins and the forearm. */
static int load_inputs(inputs *in)
{
    char path[512];
    sk_error err = {0};
    snprintf(path, sizeof path, "%s/showcase/twinkle.txt", SK_BENCH_PRESET_DIR);
    if (sk_melody_load(path, &in->melody, &err) != SK_OK)
        return fprintf(stderr, "%s\n", err.message), 1;
    sk_render_scene_desc *stage = calloc(1, sizeof *stage);
    in->stage = stage;
    snprintf(path, sizeof path, "%s/showcase/stage.json", SK_BENCH_PRESET_DIR);
    if (sk_render_scene_desc_load(path, stage, &err) != SK_OK)
        return fprintf(stderr, "%s\n", err.message), 1;
    sk_hand_skeleton skeleton;
    sk_hand_skeleton_init(&skeleton, NULL, &err);
    sk_hand_constraints *constraints = calloc(1, sizeof *constraints);
    in->constraints = constraints;
    snprintf(path, sizeof path, "%s/hand/natural.json", SK_BENCH_PRESET_DIR);
    if (sk_hand_constraints_load_file(path, &skeleton, constraints, &err) != SK_OK)
        return fprintf(stderr, "%s\n", err.message), 1;
    in->back = load_skin("back-of-hand"), in->palm = load_skin("palm");
    sk_tissue_character_desc *forearm = calloc(1, sizeof *forearm);
    in->forearm = forearm;
    snprintf(path, sizeof path, "%s/showcase/forearm.json", SK_BENCH_PRESET_DIR);
    if (sk_tissue_character_load(path, forearm, &err) != SK_OK)
        return fprintf(stderr, "%s\n", err.message), 1;
    return 0;
}

/* the stages alone over the whole piece: no rendering; best of three, wall and CPU */
static void bench_pose(sk_showcase *full)
{
    sk_error err = {0};
    int frames = sk_showcase_frame_count(full);
    double fps = sk_showcase_fps(full);
    sk_showcase_pose pose;
    double pose_wall = 1e30, pose_cpu = 1e30;
    int solves = 0;
    for (int run = 0; run < 3; run++) {
        double ta = sk_time_seconds(), ca = bench_cpu_seconds(CLOCK_PROCESS_CPUTIME_ID);
        solves = 0;
        for (int f = 0; f < frames; f++) {
            sk_showcase_pose_at(full, f / fps, &pose, &err);
            solves += pose.solves;
        }
        pose_wall = fmin(pose_wall, sk_time_seconds() - ta);
        pose_cpu = fmin(pose_cpu, bench_cpu_seconds(CLOCK_PROCESS_CPUTIME_ID) - ca);
    }
    printf("performance + posture over all %d frames of twinkle: %.3f ms a frame wall, %.3f ms CPU "
           "(%.1f posture "
           "solves a frame; best of 3)\n",
           frames, 1e3 * pose_wall / frames, 1e3 * pose_cpu / frames, (double)solves / frames);
}

/* the forearm's simulation over the whole piece, frame after frame (asking frame 0
   again restarts it), on one thread and on all; best of three, wall and CPU (skin: room
   for the skin points) */
static int bench_forearm(sk_showcase *full, float *skin)
{
    sk_error err = {0};
    int frames = sk_showcase_frame_count(full);
    double fps = sk_showcase_fps(full);
    double steps = 240 / fps;
    for (int threads = 1; threads >= 0; threads--) {
        sk_threads_set(threads);
        double wall = 1e30, cpu = 1e30;
        for (int run = 0; run < 3; run++) {
            double ta = sk_time_seconds(), ca = bench_cpu_seconds(CLOCK_PROCESS_CPUTIME_ID);
            for (int f = 0; f < frames; f++)
                if (sk_showcase_forearm_at(full, f, skin, NULL, &err) != SK_OK)
                    return fprintf(stderr, "%s\n", err.message), 1;
            wall = fmin(wall, sk_time_seconds() - ta);
            cpu = fmin(cpu, bench_cpu_seconds(CLOCK_PROCESS_CPUTIME_ID) - ca);
        }
        char load[128];
        bench_load_average(load, sizeof load);
        printf("forearm tissue over all %d frames (%.0f steps a frame), %s: %.3f ms a frame wall, "
               "%.3f ms CPU "
               "(%.3f ms CPU a step; best of 3; load average %s)\n",
               frames, steps, threads == 1 ? "1 thread" : "all threads", 1e3 * wall / frames,
               1e3 * cpu / frames, 1e3 * cpu / (frames * steps), load);
    }
    sk_threads_set(0);
    return 0;
}

/* how far the flesh moves from where its bones carry it: over the piece, and while
   the wrist holds still (the strikes alone) */
static int bench_flesh(sk_showcase *full, float *skin)
{
    sk_error err = {0};
    int frames = sk_showcase_frame_count(full);
    double fps = sk_showcase_fps(full);
    size_t points = sk_showcase_forearm_points(full);
    sk_showcase_pose pose;
    float *carried = malloc(3 * points * sizeof *carried);
    double largest = 0, largest_still = 0;
    sk_vec3d before = {0, 0, 0};
    for (int f = 0; f < frames; f++) {
        if (sk_showcase_forearm_at(full, f, skin, carried, &err) != SK_OK)
            return fprintf(stderr, "%s\n", err.message), 1;
        double worst = 0;
        for (size_t i = 0; i < 3 * points; i += 3) {
            double dx = skin[i] - carried[i], dy = skin[i + 1] - carried[i + 1],
                   dz = skin[i + 2] - carried[i + 2];
            worst = fmax(worst, sqrt(dx * dx + dy * dy + dz * dz));
        }
        sk_showcase_pose_at(full, f / fps, &pose, &err);
        sk_vec3d w = pose.frames.point[0];
        bool still =
            f > 0 && fabs(w.x - before.x) + fabs(w.y - before.y) + fabs(w.z - before.z) < 0.05;
        largest = fmax(largest, worst);
        if (still) largest_still = fmax(largest_still, worst);
        before = w;
    }
    printf("forearm flesh off its bones: largest %.2f mm over the piece, %.2f mm in frames where "
           "the wrist holds still\n",
           largest, largest_still);
    free(carried);
    return 0;
}

/* full size: a few frames through the renderer */
static int bench_full_size(sk_showcase *full)
{
    sk_error err = {0};
    sk_showcase_stats st = {0};
    if (sk_showcase_forearm_at(full, 35, NULL, NULL, &err) != SK_OK)
        return fprintf(stderr, "%s\n", err.message), 1;
    double tw = sk_time_seconds();
    for (int f = 36; f < 38; f++) { /* the forearm's simulation runs on from frame 35 */
        sk_image img;
        if (sk_showcase_render_frame(full, f, &img, &st, &err) != SK_OK)
            return fprintf(stderr, "%s\n", err.message), 1;
        sk_image_free(&img);
    }
    report("1280x720, 16 samples", &st, sk_time_seconds() - tw);
    return 0;
}

/* preview: 24 frames, three times; each stage's best of the three (the machine is
   shared: a run's stage times include what others took of the processor) */
static int bench_preview(sk_showcase_desc d)
{
    sk_error err = {0};
    d.width = 320, d.height = 180, d.samples = 4, d.texture_size = 512;
    sk_showcase *preview = NULL;
    if (sk_showcase_create(&d, &preview, &err) != SK_OK)
        return fprintf(stderr, "%s\n", err.message), 1;
    sk_showcase_stats st, best = {0};
    double best_wall = 1e30;
    for (int run = 0; run < 3; run++) {
        memset(&st, 0, sizeof st);
        /* frame 29 first (the forearm's simulation restarts and runs up to it) */
        if (sk_showcase_forearm_at(preview, 29, NULL, NULL, &err) != SK_OK)
            return fprintf(stderr, "%s\n", err.message), 1;
        double tw = sk_time_seconds();
        for (int f = 30; f < 54; f++) {
            sk_image img;
            if (sk_showcase_render_frame(preview, f, &img, &st, &err) != SK_OK)
                return fprintf(stderr, "%s\n", err.message), 1;
            sk_image_free(&img);
        }
        best_wall = fmin(best_wall, sk_time_seconds() - tw);
        if (run == 0) best = st;
        best.seconds_input = fmin(best.seconds_input, st.seconds_input);
        best.seconds_solve = fmin(best.seconds_solve, st.seconds_solve);
        best.seconds_skin = fmin(best.seconds_skin, st.seconds_skin);
        best.seconds_tissue = fmin(best.seconds_tissue, st.seconds_tissue);
        best.seconds_scene = fmin(best.seconds_scene, st.seconds_scene);
        best.seconds_render = fmin(best.seconds_render, st.seconds_render);
    }
    report("320x180, 4 samples (each stage the best of 3 runs)", &best, best_wall);
    sk_showcase_destroy(preview);
    return 0;
}

/* the command as a user runs it: 12 preview frames with their PNG files and the WAV */
static int bench_command(void)
{
    char dir[] = "/tmp/bench_showcase_XXXXXX", cmd[1024];
    if (!mkdtemp(dir)) return fprintf(stderr, "bench_showcase: no temporary folder\n"), 1;
    snprintf(cmd, sizeof cmd,
             "%s showcase --melody %s/showcase/twinkle.txt --frames 30:41 --size 320x180 --spp 4 "
             "--texture-size 512 -q "
             "-o %s/out",
             SK_BENCH_CLI, SK_BENCH_PRESET_DIR, dir);
    double tw = sk_time_seconds();
    int rc = system(cmd);
    printf("command (setup + 12 frames at 320x180 + WAV + PNGs): %.2f s wall (exit %d)\n",
           sk_time_seconds() - tw, rc);
    snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
    if (system(cmd) != 0) fprintf(stderr, "bench_showcase: %s left behind\n", dir);
    return 0;
}

int main(void)
{
    sk_error err = {0};
    inputs in = {0};
    if (load_inputs(&in) != 0) return 1;
    double t0 = sk_time_seconds();
    sk_showcase_desc d = {0};
    d.melody = &in.melody, d.stage = in.stage, d.constraints = in.constraints;
    d.back_skin = in.back, d.palm_skin = in.palm;
    d.forearm = in.forearm;
    sk_showcase *full = NULL;
    if (sk_showcase_create(&d, &full, &err) != SK_OK)
        return fprintf(stderr, "%s\n", err.message), 1;
    double setup = sk_time_seconds() - t0;
    printf("setup (fingering, playing posture, hand surface 8000 triangles, texture 1024 with "
           "microrelief, wood, "
           "forearm of %zu skin points): %.2f s\n",
           sk_showcase_forearm_points(full), setup);
    bench_pose(full);
    size_t points = sk_showcase_forearm_points(full);
    float *skin = malloc(3 * points * sizeof *skin);
    if (bench_forearm(full, skin) != 0 || bench_flesh(full, skin) != 0) return 1;
    free(skin);
    if (step_rates(&d, sk_showcase_surface(full)) != 0) return 1;
    if (bench_full_size(full) != 0) return 1;
    sk_showcase_destroy(full);
    if (bench_preview(d) != 0 || bench_command() != 0) return 1;
    sk_skin_destroy(in.back), sk_skin_destroy(in.palm);
    free(in.stage), free(in.constraints), free(in.forearm);
    sk_melody_free(&in.melody);
    return 0;
}
