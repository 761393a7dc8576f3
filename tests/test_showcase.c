/* The showcase: every note presses its key within one frame of its start with the finger
 * the fingering chose and releases it at its end; no fingertip passes through a key; no
 * finger through its neighbour; poses depend on their time alone; frames are the same for
 * any thread count and any split of the frames; the sound is in sync with the strikes;
 * the piano's keys turn where the renderer sees them; the command's errors and its MP4
 * (checked with ffprobe when present). Frames are tiny; the hand surface is a coarse one
 * built once. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "test_support.h"
#include "shitsukan/io.h"
#include "shitsukan/showcase.h"

typedef struct fixture {
    sk_hand_skeleton skeleton;
    sk_hand_constraints *constraints;
    sk_hand_surface *surface;
    sk_image albedo, normal;
    sk_render_scene_desc *stage;
    sk_melody melody;
    sk_melody short_melody; /* its first 0.7 s */
    sk_tissue_character_desc *forearm;
    sk_showcase *showcase;
    sk_showcase_pose *sampled; /* the poses every 1/SAMPLE_RATE s over the piece, shared */
    int sampled_count;
} fixture;

#define SAMPLE_RATE 120 /* poses a second the contact tests check */

static fixture fx;

/* A stage without wood (fast): keys' materials, a floor and a light. */
static sk_render_scene_desc *test_stage(void)
{
    sk_render_scene_desc *d = calloc(1, sizeof *d);
    assert_non_null(d);
    d->material_count = 3;
    snprintf(d->materials[0].name, sizeof d->materials[0].name, "ivory");
    snprintf(d->materials[1].name, sizeof d->materials[1].name, "ebony");
    d->materials[1].albedo[0] = d->materials[1].albedo[1] = d->materials[1].albedo[2] = 0.03f;
    snprintf(d->materials[2].name, sizeof d->materials[2].name, "floor");
    d->object_count = 1;
    d->objects[0].shape = SK_RENDER_SHAPE_PLANE;
    d->objects[0].size[0] = d->objects[0].size[2] = 4000;
    snprintf(d->objects[0].material, sizeof d->objects[0].material, "floor");
    d->film.opaque = true;
    d->light_count = 1;
    d->lights[0].direction[0] = 0.3f, d->lights[0].direction[1] = -1,
    d->lights[0].direction[2] = -0.4f;
    return d;
}

static sk_showcase_desc showcase_desc(const sk_melody *melody, int width, int height, bool forearm)
{
    sk_showcase_desc d = {0};
    d.forearm = forearm ? fx.forearm : NULL;
    d.melody = melody;
    d.stage = fx.stage;
    d.constraints = fx.constraints;
    d.surface = fx.surface;
    d.skin_albedo = &fx.albedo;
    d.skin_normal = &fx.normal;
    d.width = width, d.height = height, d.samples = 1;
    return d;
}

static sk_showcase *make_showcase_from(const sk_showcase_desc *desc)
{
    sk_showcase *sc = NULL;
    sk_error err = {0};
    if (sk_showcase_create(desc, &sc, &err) != SK_OK) fail_msg("%s", err.message);
    return sc;
}

static sk_showcase *make_showcase_with(const sk_melody *melody, int width, int height, bool forearm)
{
    sk_showcase_desc d = showcase_desc(melody, width, height, forearm);
    return make_showcase_from(&d);
}

/* A short piece with the forearm at a few frames a second and a short tail: the frames
   and flesh it gives must not depend on the thread count or the order of the frames. */
static sk_showcase *make_short_forearm_showcase(const sk_melody *melody)
{
    sk_showcase_desc d = showcase_desc(melody, 24, 16, true);
    d.fps = 12;
    d.synth.tail_s = 0.25;
    return make_showcase_from(&d);
}

static sk_showcase *make_showcase(const sk_melody *melody, int width, int height)
{
    return make_showcase_with(melody, width, height, false);
}

static int setup(void **state)
{
    (void)state;
    sk_error err = {0};
    char path[512];
    if (sk_hand_skeleton_init(&fx.skeleton, NULL, &err) != SK_OK) return -1;
    fx.constraints = calloc(1, sizeof *fx.constraints);
    snprintf(path, sizeof path, "%s/hand/natural.json", SK_TEST_PRESET_DIR);
    if (sk_hand_constraints_load_file(path, &fx.skeleton, fx.constraints, &err) != SK_OK) return -1;
    sk_hand_surface_desc sd = {.triangles = 2000};
    if (sk_hand_surface_create(&fx.surface, &fx.skeleton, &sd, &err) != SK_OK) return -1;
    if (sk_image_create(&fx.albedo, 8, 8, 3, &err) != SK_OK ||
        sk_image_create(&fx.normal, 8, 8, 3, &err) != SK_OK)
        return -1;
    for (int i = 0; i < 64; i++) {
        fx.albedo.data[3 * i] = 0.8f, fx.albedo.data[3 * i + 1] = 0.6f,
                           fx.albedo.data[3 * i + 2] = 0.5f;
        fx.normal.data[3 * i] = 0.5f, fx.normal.data[3 * i + 1] = 0.5f,
                           fx.normal.data[3 * i + 2] = 1.0f;
    }
    fx.stage = test_stage();
    fx.forearm = calloc(1, sizeof *fx.forearm);
    snprintf(path, sizeof path, "%s/showcase/forearm.json", SK_TEST_PRESET_DIR);
    if (sk_tissue_character_load(path, fx.forearm, &err) != SK_OK) return -1;
    snprintf(path, sizeof path, "%s/showcase/melody.txt", SK_TEST_DATA_DIR);
    if (sk_melody_load(path, &fx.melody, &err) != SK_OK) return -1;
    if (sk_melody_copy(&fx.melody, &fx.short_melody, &err) != SK_OK ||
        sk_melody_cut(&fx.short_melody, 0.7, &err) != SK_OK)
        return -1;
    fx.showcase = make_showcase(&fx.melody, 32, 18);
    return 0;
}

static int teardown(void **state)
{
    (void)state;
    sk_showcase_destroy(fx.showcase);
    free(fx.sampled);
    sk_melody_free(&fx.melody);
    sk_melody_free(&fx.short_melody);
    free(fx.stage);
    free(fx.forearm);
    sk_image_free(&fx.albedo), sk_image_free(&fx.normal);
    sk_hand_surface_destroy(fx.surface);
    free(fx.constraints);
    return 0;
}

static sk_showcase_pose pose_at(double t)
{
    sk_showcase_pose p;
    sk_error err = {0};
    if (sk_showcase_pose_at(fx.showcase, t, &p, &err) != SK_OK) fail_msg("%s", err.message);
    return p;
}

/* The pose at sample i (time i / SAMPLE_RATE, from the melody's start to 0.3 s after its
   end), solved once and shared by the contact tests; NULL past the end. */
static const sk_showcase_pose *sampled_pose(int i)
{
    if (!fx.sampled) {
        double end = sk_melody_end(sk_showcase_melody(fx.showcase)) + 0.3;
        fx.sampled_count = (int)ceil(end * SAMPLE_RATE);
        fx.sampled = malloc((size_t)fx.sampled_count * sizeof *fx.sampled);
        assert_non_null(fx.sampled);
        for (int k = 0; k < fx.sampled_count; k++) fx.sampled[k] = pose_at((double)k / SAMPLE_RATE);
    }
    return i < fx.sampled_count ? &fx.sampled[i] : NULL;
}

/* ------------------------------------------------------------ the performance */

static void test_presses_and_releases(void **state)
{
    (void)state;
    const sk_melody *m = sk_showcase_melody(fx.showcase);
    const sk_piano *piano = sk_showcase_piano(fx.showcase);
    double fps = sk_showcase_fps(fx.showcase), half = 0.5 * piano->max_angle, tol = 1e-4;
    assert_int_equal(m->note_count, fx.melody.note_count);
    for (int i = 0; i < m->note_count; i++) {
        const sk_note *n = &m->notes[i];
        assert_true(n->finger >= 1 && n->finger <= 5);
        if (fx.melody.notes[i].finger) assert_int_equal(n->finger, fx.melody.notes[i].finger);
        int k = n->key - SK_PIANO_KEY_FIRST;
        double e = n->start_s + n->duration_s;
        int first = (int)ceil(n->start_s * fps - 1e-9), after = (int)ceil(e * fps - 1e-9);
        /* down at the first frame at or after the start, by the chosen finger; up before */
        sk_showcase_pose p = pose_at(first / fps);
        if (!(p.key_angle[k] >= half - tol))
            fail_msg("note %d (key %d) not down at frame %d", i, n->key, first);
        assert_int_equal(p.key_finger[k], n->finger);
        p = pose_at((first - 1) / fps);
        if (!(p.key_angle[k] < half + tol))
            fail_msg("note %d (key %d) down before its start", i, n->key);
        /* held on every frame of the note, up at the first frame at or after its end */
        for (int f = first + 1; f < after; f++) {
            p = pose_at(f / fps);
            if (!(p.key_angle[k] >= half - tol) || p.key_finger[k] != n->finger)
                fail_msg("note %d (key %d) not held at frame %d", i, n->key, f);
        }
        p = pose_at(after / fps);
        if (!(p.key_angle[k] < half + tol))
            fail_msg("note %d (key %d) still down at frame %d", i, n->key, after);
    }
    /* keys no note plays stay up */
    for (int f = 0; f < sk_showcase_frame_count(fx.showcase); f += 3) {
        sk_showcase_pose p = pose_at(f / fps);
        for (int k = 0; k < SK_PIANO_KEY_COUNT; k++) {
            bool played = false;
            for (int i = 0; i < m->note_count; i++)
                played = played || m->notes[i].key == k + SK_PIANO_KEY_FIRST;
            if (!played) assert_true(p.key_angle[k] < half);
        }
    }
}

/* Distance between segments [p0, p1] and [q0, q1] (sampled finely; exact enough here). */
static double segment_distance(sk_vec3d p0, sk_vec3d p1, sk_vec3d q0, sk_vec3d q1)
{
    double best = INFINITY;
    for (int i = 0; i <= 24; i++)
        for (int j = 0; j <= 24; j++) {
            double a = i / 24.0, b = j / 24.0;
            double dx = p0.x + (p1.x - p0.x) * a - q0.x - (q1.x - q0.x) * b;
            double dy = p0.y + (p1.y - p0.y) * a - q0.y - (q1.y - q0.y) * b;
            double dz = p0.z + (p1.z - p0.z) * a - q0.z - (q1.z - q0.z) * b;
            best = fmin(best, sqrt(dx * dx + dy * dy + dz * dz));
        }
    return best;
}

static int distal_link(int f) { return f == 0 ? 3 : 4 * f + 3; }

static void test_no_fingertip_through_a_key(void **state)
{
    (void)state;
    const sk_piano *piano = sk_showcase_piano(fx.showcase);
    double worst = INFINITY;
    const sk_showcase_pose *sample;
    for (int i = 0; (sample = sampled_pose(i)) != NULL; i++) {
        const sk_showcase_pose p = *sample;
        double t = p.time_s;
        for (int f = 0; f < 5; f++) {
            /* the pad, and the distal phalanx as that sphere swept back to its joint */
            sk_vec3d joint = sk_showcase_hand_to_scene(
                fx.showcase, p.frames.point[sk_hand_link_point(distal_link(f))]);
            for (int k = 0; k < SK_PIANO_KEY_COUNT; k++) {
                const sk_piano_key *key = &piano->keys[k];
                if (fabs(key->x_mm - p.tip_centre[f].x) > 40) continue;
                for (int s = 0; s <= 8; s++) {
                    double a = s / 8.0;
                    sk_vec3d q = {p.tip_centre[f].x + (joint.x - p.tip_centre[f].x) * a,
                                  p.tip_centre[f].y + (joint.y - p.tip_centre[f].y) * a,
                                  p.tip_centre[f].z + (joint.z - p.tip_centre[f].z) * a};
                    double gap =
                        sk_piano_key_distance(piano, key, p.key_angle[k], q) - p.tip_radius[f];
                    if (gap < worst) worst = gap;
                    if (gap < -0.1)
                        fail_msg("t = %.3f: finger %d is %.2f mm inside key %d", t, f + 1, -gap,
                                 key->key);
                }
            }
        }
    }
    /* and the fingers do touch the keys they press */
    assert_true(worst < 0.05);
}

static void test_no_finger_through_its_neighbour(void **state)
{
    (void)state;
    const sk_showcase_pose *sample;
    for (int s = 0; (sample = sampled_pose(s)) != NULL; s += SAMPLE_RATE / 60) {
        const sk_showcase_pose p = *sample;
        double t = p.time_s;
        for (int f = 0; f < 4; f++) {
            int a_links[2] = {distal_link(f) - 1, distal_link(f)},
                b_links[2] = {distal_link(f + 1) - 1, distal_link(f + 1)};
            for (int i = 0; i < 2; i++)
                for (int j = 0; j < 2; j++) {
                    int la = a_links[i], lb = b_links[j];
                    const sk_vec3d *pt = p.frames.point;
                    double d = segment_distance(
                        pt[sk_hand_link_point(la)], pt[sk_hand_link_end_point(la)],
                        pt[sk_hand_link_point(lb)], pt[sk_hand_link_end_point(lb)]);
                    double ra = sk_showcase_link_radius(fx.showcase, la),
                           rb = sk_showcase_link_radius(fx.showcase, lb);
                    assert_true(ra > 3 && rb > 3);
                    /* the flesh may press together, the bones may not come through it */
                    if (d < 0.5 * (ra + rb))
                        fail_msg("t = %.3f: fingers %d and %d are %.2f mm apart (flesh radii %.1f, "
                                 "%.1f)",
                                 t, f + 1, f + 2, d, ra, rb);
                }
        }
    }
}

static void test_poses_depend_on_time_alone(void **state)
{
    (void)state;
    const double times[6] = {2.9, 0.5, 4.7, 0.5, 1.66, 2.9};
    sk_showcase_pose a[6];
    for (int i = 0; i < 6; i++) a[i] = pose_at(times[i]);
    assert_memory_equal(a[1].dofs, a[3].dofs, sizeof a[1].dofs);
    assert_memory_equal(a[0].dofs, a[5].dofs, sizeof a[0].dofs);
    assert_memory_equal(a[0].key_angle, a[5].key_angle, sizeof a[0].key_angle);
    /* a fresh showcase gives the same */
    sk_showcase *other = make_showcase(&fx.melody, 32, 18);
    sk_showcase_pose b;
    sk_error err = {0};
    assert_int_equal(sk_showcase_pose_at(other, 2.9, &b, &err), SK_OK);
    assert_memory_equal(a[0].dofs, b.dofs, sizeof b.dofs);
    sk_showcase_destroy(other);
    /* the wrist travels: C5 is far beyond the hand's span from C4 */
    sk_showcase_pose c4 = pose_at(0.45), c5 = pose_at(4.7);
    assert_true(c5.dofs[0] < c4.dofs[0] - 60); /* wrist.tx is minus the scene's x */
}

/* ------------------------------------------------------------ frames and sound */

static void test_frames_for_any_split_and_threads(void **state)
{
    (void)state;
    sk_error err = {0};
    char whole[512], split[512];
    snprintf(whole, sizeof whole, "%s", sk_test_path("frames-whole"));
    snprintf(split, sizeof split, "%s", sk_test_path("frames-split"));
    sk_threads_set(1);
    sk_showcase *a = make_short_forearm_showcase(&fx.short_melody);
    int n = sk_showcase_frame_count(a);
    assert_true(n >= 6);
    sk_showcase_run_desc rd = {.output_dir = whole, .last_frame = -1, .no_video = true};
    assert_int_equal(sk_showcase_run(a, &rd, NULL, &err), SK_OK);
    sk_showcase_destroy(a);
    sk_threads_set(2);
    for (int part = 0; part < 2; part++) { /* the second half first, each by a fresh showcase */
        sk_showcase *b = make_short_forearm_showcase(&fx.short_melody);
        sk_showcase_run_desc pd = {.output_dir = split, .no_video = true};
        pd.first_frame = part == 0 ? n / 2 : 0;
        pd.last_frame = part == 0 ? n - 1 : n / 2 - 1;
        assert_int_equal(sk_showcase_run(b, &pd, NULL, &err), SK_OK);
        sk_showcase_destroy(b);
    }
    sk_threads_set(0);
    for (int f = 0; f < n; f++) {
        char pa[600], pb[600];
        snprintf(pa, sizeof pa, "%s/frames/frame_%04d.png", whole, f);
        snprintf(pb, sizeof pb, "%s/frames/frame_%04d.png", split, f);
        if (!sk_test_same_file(pa, pb)) fail_msg("frame %d differs between the runs", f);
    }
    char wa[600], wb[600];
    snprintf(wa, sizeof wa, "%s/showcase.wav", whole);
    snprintf(wb, sizeof wb, "%s/showcase.wav", split);
    assert_true(sk_test_same_file(wa, wb));
}

/* The library makes no video itself: it hands a finished run to the caller's encoder,
   once, with the frame pattern, the rate and the WAV; a split run calls it only when the
   folder holds every frame; without an encoder it notes that there is no MP4. */
typedef struct encoder_calls {
    int count;
    char pattern[600], wav[600], path[600];
    double fps;
} encoder_calls;

static sk_result fake_encoder(void *user, const char *frames_pattern, double fps, const char *wav,
                              const char *path, char *note, size_t note_size, bool *written,
                              sk_error *err)
{
    encoder_calls *c = user;
    c->count++;
    snprintf(c->pattern, sizeof c->pattern, "%s", frames_pattern);
    snprintf(c->wav, sizeof c->wav, "%s", wav);
    snprintf(c->path, sizeof c->path, "%s", path);
    c->fps = fps;
    *written = true;
    return SK_OK;
}

static void test_video_through_the_callers_encoder(void **state)
{
    (void)state;
    sk_error err = {0};
    char dir[512];
    snprintf(dir, sizeof dir, "%s", sk_test_path("frames-video"));
    sk_showcase *sc = make_short_forearm_showcase(&fx.short_melody);
    int n = sk_showcase_frame_count(sc);
    for (int f = 0; f < n; f++) { /* a fresh folder: no frames of an earlier run */
        char frame[600];
        snprintf(frame, sizeof frame, "%s/frames/frame_%04d.png", dir, f);
        remove(frame);
    }
    encoder_calls calls = {0};
    sk_showcase_stats stats;
    sk_showcase_run_desc rd = {.output_dir = dir,
                               .last_frame = n / 2 - 1,
                               .encode_video = fake_encoder,
                               .encode_video_user = &calls};
    if (sk_showcase_run(sc, &rd, &stats, &err) != SK_OK) fail_msg("%s", err.message);
    assert_int_equal(calls.count, 0); /* half the frames: no video yet */
    assert_false(stats.video_written);
    assert_non_null(strstr(stats.video_note, "all"));
    rd.first_frame = n / 2;
    rd.last_frame = -1;
    assert_int_equal(sk_showcase_run(sc, &rd, &stats, &err), SK_OK);
    assert_int_equal(calls.count, 1);
    assert_true(stats.video_written);
    char want[600];
    snprintf(want, sizeof want, "%s/frames/frame_%%04d.png", dir);
    assert_string_equal(calls.pattern, want);
    snprintf(want, sizeof want, "%s/showcase.wav", dir);
    assert_string_equal(calls.wav, want);
    snprintf(want, sizeof want, "%s/showcase.mp4", dir);
    assert_string_equal(calls.path, want);
    assert_true(calls.fps > 0);
    /* no encoder: a note, no error */
    sk_showcase_run_desc none = {.output_dir = dir, .join_only = true};
    assert_int_equal(sk_showcase_run(sc, &none, &stats, &err), SK_OK);
    assert_false(stats.video_written);
    assert_non_null(strstr(stats.video_note, "no video encoder"));
    sk_showcase_destroy(sc);
}

/* ------------------------------------------------------------ the forearm */

/* Largest distance of a forearm skin point from where its bones carry it (the flesh's
   own motion). */
static double flesh_offset(sk_showcase *sc, int frame, float *skin, float *carried)
{
    sk_error err = {0};
    if (sk_showcase_forearm_at(sc, frame, skin, carried, &err) != SK_OK)
        fail_msg("%s", err.message);
    size_t n = sk_showcase_forearm_points(sc);
    double worst = 0;
    for (size_t i = 0; i < n; i++) {
        double dx = skin[3 * i] - carried[3 * i], dy = skin[3 * i + 1] - carried[3 * i + 1],
               dz = skin[3 * i + 2] - carried[3 * i + 2];
        worst = fmax(worst, sqrt(dx * dx + dy * dy + dz * dz));
    }
    return worst;
}

/* The thumb strikes C4, then E4: the wrist travels two white keys between the strikes,
 * then the hand rests. The flesh moves relative to the bones while the wrist is (almost)
 * still after it stops, and settles back onto them. */
static void test_forearm_swings_and_settles(void **state)
{
    (void)state;
    const char text[] = "C4 0.1 0.3 1\nE4 0.6 0.3 1\n";
    sk_melody leap;
    sk_error err = {0};
    assert_int_equal(sk_melody_parse_text(text, strlen(text), "leap", &leap, &err), SK_OK);
    sk_showcase *sc = make_showcase_with(&leap, 16, 16, true);
    size_t n = sk_showcase_forearm_points(sc);
    assert_true(n > 500);
    float *skin = malloc(3 * n * sizeof *skin), *carried = malloc(3 * n * sizeof *carried);
    int frames = sk_showcase_frame_count(sc);
    double fps = sk_showcase_fps(sc);
    double still_swing = 0, peak = 0, last = 0;
    sk_vec3d before = {0, 0, 0};
    for (int f = 0; f < frames; f++) {
        double offset = flesh_offset(sc, f, skin, carried);
        sk_showcase_pose p;
        assert_int_equal(sk_showcase_pose_at(sc, f / fps, &p, &err), SK_OK);
        sk_vec3d wrist = p.frames.point[0];
        bool still =
            f > 0 &&
            fabs(wrist.x - before.x) + fabs(wrist.y - before.y) + fabs(wrist.z - before.z) < 0.05;
        if (still && f / fps > 0.4) still_swing = fmax(still_swing, offset);
        peak = fmax(peak, offset);
        before = wrist, last = offset;
    }
    /* the flesh swings by a visible amount while the wrist holds still */
    if (!(still_swing > 0.3))
        fail_msg("the flesh moves %.3f mm while the wrist is still (peak %.3f)", still_swing, peak);
    /* and is back on its bones a second after the last note */
    if (!(last < 0.02 * peak))
        fail_msg("the flesh is still %.4f mm off its bones at the end (peak %.3f)", last, peak);
    free(skin), free(carried);
    sk_showcase_destroy(sc);
    sk_melody_free(&leap);
}

/* The flesh at a frame is the same bits whether the simulation ran through every frame
 * before it, jumped to it, or came back to it, on one thread or two. */
static void test_forearm_any_start(void **state)
{
    (void)state;
    sk_error err = {0};
    sk_threads_set(1);
    sk_showcase *a = make_short_forearm_showcase(&fx.short_melody);
    sk_threads_set(2);
    sk_showcase *b = make_short_forearm_showcase(&fx.short_melody);
    size_t n = sk_showcase_forearm_points(a);
    assert_int_equal(n, sk_showcase_forearm_points(b));
    float *xa = malloc(3 * n * sizeof *xa), *xb = malloc(3 * n * sizeof *xb);
    int target = sk_showcase_frame_count(a) / 2;
    sk_threads_set(1);
    for (int f = 0; f <= target; f++)
        assert_int_equal(sk_showcase_forearm_at(a, f, xa, NULL, &err), SK_OK);
    sk_threads_set(2);
    assert_int_equal(sk_showcase_forearm_at(b, target + 3, xb, NULL, &err), SK_OK);
    assert_int_equal(sk_showcase_forearm_at(b, target, xb, NULL, &err),
                     SK_OK); /* back: a restart */
    assert_memory_equal(xa, xb, 3 * n * sizeof *xa);
    sk_threads_set(0);
    free(xa), free(xb);
    sk_showcase_destroy(a), sk_showcase_destroy(b);
}

static uint32_t le32(const unsigned char *p)
{
    return p[0] | p[1] << 8 | p[2] << 16 | (uint32_t)p[3] << 24;
}

/* Power of a signal at frequency f (Goertzel). */
static double power_at(const float *x, size_t n, double f, double rate)
{
    double w = 2 * SK_PI * f / rate, c = 2 * cos(w), s1 = 0, s2 = 0;
    for (size_t i = 0; i < n; i++) {
        double s0 = x[i] + c * s1 - s2;
        s2 = s1, s1 = s0;
    }
    return s1 * s1 + s2 * s2 - c * s1 * s2;
}

static void test_sound(void **state)
{
    (void)state;
    const char *path = sk_test_path("showcase.wav");
    sk_error err = {0};
    assert_int_equal(sk_showcase_write_wav(fx.showcase, path, &err), SK_OK);
    char *data = NULL;
    size_t size = 0;
    assert_int_equal(sk_read_file(path, 0, &data, &size, &err), SK_OK);
    const unsigned char *h = (const unsigned char *)data;
    assert_memory_equal(h, "RIFF", 4), assert_memory_equal(h + 8, "WAVEfmt ", 8);
    assert_int_equal(h[20] | h[21] << 8, 1); /* PCM */
    assert_int_equal(h[22] | h[23] << 8, 1); /* mono */
    assert_int_equal(le32(h + 24), 44100);
    assert_int_equal(h[34] | h[35] << 8, 16); /* bits */
    size_t samples = le32(h + 40) / 2;
    assert_int_equal(size, 44 + 2 * samples);
    double seconds = sk_showcase_frame_count(fx.showcase) / sk_showcase_fps(fx.showcase);
    assert_true(fabs(samples / 44100.0 - seconds) < 1.0 / 44100 + 1e-9);
    /* silent until the first strike, sounding right after it */
    const int16_t *pcm = (const int16_t *)(data + 44);
    size_t onset = (size_t)(fx.melody.notes[0].start_s * 44100);
    for (size_t i = 0; i + 1 < onset; i++)
        if (pcm[i] != 0) fail_msg("sample %zu before the first note is %d", i, pcm[i]);
    int loud = 0;
    for (size_t i = onset; i < onset + 441; i++) loud = abs(pcm[i]) > loud ? abs(pcm[i]) : loud;
    assert_true(loud > 500);
    free(data);
    /* the tone: its fundamental, not between partials; the same for any thread count */
    sk_melody a4 = {0};
    sk_note n = {.key = 69, .start_s = 0, .duration_s = 0.5, .velocity = 100};
    a4.note_count = 1, a4.notes = &n;
    size_t count = sk_synth_length(&a4, NULL);
    float *one = malloc(count * sizeof *one), *two = malloc(count * sizeof *two);
    sk_threads_set(1);
    assert_int_equal(sk_synth_render(&a4, NULL, one, count, &err), SK_OK);
    sk_threads_set(2);
    assert_int_equal(sk_synth_render(&a4, NULL, two, count, &err), SK_OK);
    sk_threads_set(0);
    assert_memory_equal(one, two, count * sizeof *one);
    size_t window = 8820; /* 0.2 s */
    assert_true(power_at(one, window, 440.0, 44100) > 20 * power_at(one, window, 660.0, 44100));
    /* it decays, and the damper ends it */
    double early = 0, late = 0;
    for (size_t i = 0; i < window; i++)
        early += one[i] * one[i], late += one[i + 3 * window] * one[i + 3 * window];
    assert_true(late < 0.05 * early);
    free(one), free(two);
}

/* ------------------------------------------------------------ the piano */

static void test_piano_keys(void **state)
{
    (void)state;
    sk_piano piano;
    sk_error err = {0};
    assert_int_equal(sk_piano_init(&piano, NULL, &err), SK_OK);
    const sk_piano_key *c4 = sk_piano_key_get(&piano, 60), *cs4 = sk_piano_key_get(&piano, 61);
    const sk_piano_key *a0 = sk_piano_key_get(&piano, 21), *c8 = sk_piano_key_get(&piano, 108);
    assert_false(c4->black), assert_true(cs4->black);
    assert_true(fabs(a0->x_mm + c8->x_mm) < 1e-9); /* the keyboard is centred */
    assert_true(fabs((c8->x_mm - a0->x_mm) - 51 * 23.5) < 1e-9);
    assert_true(fabs(cs4->x_mm - (c4->x_mm + 0.5 * 23.5)) < 1e-9);
    assert_int_equal(sk_piano_key_under(&piano, c4->x_mm, c4->front_mm - 10), 60);
    assert_int_equal(sk_piano_key_under(&piano, cs4->x_mm, cs4->front_mm - 10), 61);
    assert_int_equal(sk_piano_key_under(&piano, c4->x_mm + 11.0, c4->front_mm - 80), 61);
    /* full dip at the front */
    double dip = sk_piano_key_top_at(&piano, c4, 0, c4->front_mm) -
                 sk_piano_key_top_at(&piano, c4, piano.max_angle, c4->front_mm);
    assert_true(fabs(dip - 10 / sqrt(1 - (10.0 / 250) * (10.0 / 250))) < 1e-9); /* tan of asin */
    /* the renderer sees the turned keys where the piano says they are */
    sk_render_scene_desc *d = calloc(1, sizeof *d);
    d->material_count = 1;
    snprintf(d->materials[0].name, sizeof d->materials[0].name, "ivory");
    double angle = 0.7 * piano.max_angle;
    int n = sk_piano_key_objects(&piano, c4, angle, "ivory", d->objects);
    n += sk_piano_key_objects(&piano, cs4, 0.3 * piano.max_angle, "ivory", d->objects + n);
    assert_int_equal(n, 3);
    d->object_count = n;
    sk_render_scene *scene = NULL;
    assert_int_equal(sk_render_scene_create(d, &scene, &err), SK_OK);
    const double zs[3] = {c4->front_mm - 5, c4->front_mm - 40, c4->notch_front_mm - 30};
    for (int i = 0; i < 3; i++) {
        sk_render_hit hit;
        double x = i == 2 ? 0.5 * (c4->back_x0_mm + c4->back_x1_mm) : c4->x_mm;
        sk_render_scene_intersect(scene, sk_v3f((float)x, 2000, (float)zs[i]), sk_v3f(0, -1, 0),
                                  1e5f, &hit);
        assert_true(hit.hit);
        double expect = sk_piano_key_top_at(&piano, c4, angle, zs[i]);
        if (fabs(hit.point.y - expect) > 0.02)
            fail_msg("key top at z %.1f: %.3f, expected %.3f", zs[i], hit.point.y, expect);
        sk_vec3d p = {x, expect + 1, zs[i]};
        assert_true(fabs(sk_piano_key_distance(&piano, c4, angle, p) - 1) < 0.01);
        p.y = expect - 1;
        assert_true(sk_piano_key_distance(&piano, c4, angle, p) < 0);
    }
    sk_render_hit hit;
    double angle_b = 0.3 * piano.max_angle, zb = cs4->front_mm - 20;
    sk_render_scene_intersect(scene, sk_v3f((float)cs4->x_mm, 2000, (float)zb), sk_v3f(0, -1, 0),
                              1e5f, &hit);
    assert_true(hit.hit &&
                fabs(hit.point.y - sk_piano_key_top_at(&piano, cs4, angle_b, zb)) < 0.02);
    sk_render_scene_destroy(scene);
    free(d);
    sk_piano_desc bad = {.dip_mm = 50};
    assert_int_equal(sk_piano_init(&piano, &bad, &err), SK_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(err.message, "piano.dip_mm"));
}

/* ------------------------------------------------------------ the command */

static void test_command(void **state)
{
    (void)state;
    sk_test_run run;
    const char *bad = sk_test_path("bad-melody.txt");
    sk_test_write_file(bad, "C4 0 1\nC4 x 1\n", 14);
    const char *dir = sk_test_path("cli-out");
    char clean[700];
    snprintf(clean, sizeof clean, "rm -rf '%s'", dir);
    assert_int_equal(system(clean), 0);
    assert_int_equal(sk_test_cli(&run, "showcase --melody %s -o %s", bad, dir), 2);
    assert_non_null(strstr(run.err, "bad-melody.txt:2:"));
    assert_int_equal(sk_test_count_lines(run.err), 1);
    assert_false(sk_test_file_exists(dir));
    const char *mid = sk_test_path("bad.mid");
    sk_test_write_file(mid, "MThd\0\0\0\6\0\0\0\1\0\x60MTrk\0\0\0\4\0\x90\x3c", 26);
    assert_int_equal(sk_test_cli(&run, "showcase --melody %s -o %s", mid, dir), 2);
    assert_non_null(strstr(run.err, "bad.mid: byte"));
    assert_int_equal(sk_test_count_lines(run.err), 1);
    char melody[512];
    snprintf(melody, sizeof melody, "%s/showcase/melody.txt", SK_TEST_DATA_DIR);
    assert_int_equal(sk_test_cli(&run, "showcase --melody %s --frames 9:3 -o %s", melody, dir), 2);
    assert_int_equal(sk_test_cli(&run, "showcase --melody %s -o %s --size 8x8", melody, dir), 2);
    assert_int_equal(sk_test_cli(&run, "showcase --help"), 0);
    assert_non_null(strstr(run.out, "--frames"));
    /* a whole tiny run of an odd size: frames, sound, fingering, and the MP4 */
    int status = sk_test_cli(
        &run,
        "showcase --melody %s --duration 0.6 --size 33x19 --spp 1 --fps 6 --texture-size 64 "
        "--hand-triangles 500 -q -o %s",
        melody, dir);
    if (status != 0) fail_msg("%s", run.err);
    char path[600];
    snprintf(path, sizeof path, "%s/frames/frame_0000.png", dir);
    assert_true(sk_test_file_exists(path));
    snprintf(path, sizeof path, "%s/fingering.txt", dir);
    assert_true(sk_test_file_exists(path));
    char frames[600];
    snprintf(frames, sizeof frames, "%s/frames", dir);
    assert_int_equal(sk_test_count_files_containing(frames, ".tmp"), 0);
    if (system("ffprobe -version > /dev/null 2>&1") != 0) {
        fprintf(stderr, "ffprobe not found: MP4 not checked\n");
        return;
    }
    snprintf(path, sizeof path, "%s/showcase.mp4", dir);
    assert_true(sk_test_file_exists(path));
    char cmd[1400], out[512] = {0};
    snprintf(cmd, sizeof cmd,
             "ffprobe -v error -show_entries "
             "stream=codec_type,codec_name,width,height:format=duration -of csv=p=0 %s",
             path);
    FILE *pipe = popen(cmd, "r");
    assert_non_null(pipe);
    size_t got = fread(out, 1, sizeof out - 1, pipe);
    pclose(pipe);
    out[got] = '\0';
    assert_non_null(strstr(out, "h264,video,34,20"));
    assert_non_null(strstr(out, "aac,audio"));
    /* duration: 0.6 s of melody plus the 1 s tail, at 6 frames a second */
    const char *last = strrchr(out, '\n');
    while (last && last > out && last[1] == '\0') {
        const char *prev = last - 1;
        while (prev > out && *prev != '\n') prev--;
        if (prev == out) break;
        last = prev;
    }
    double duration = atof(last ? last + 1 : out);
    double frames_s = (floor(1.6 * 6) + 1) / 6.0;
    if (!(fabs(duration - frames_s) < 0.15))
        fail_msg("MP4 lasts %.3f s, the frames %.3f s (%s)", duration, frames_s, out);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_presses_and_releases),
        cmocka_unit_test(test_no_fingertip_through_a_key),
        cmocka_unit_test(test_no_finger_through_its_neighbour),
        cmocka_unit_test(test_poses_depend_on_time_alone),
        cmocka_unit_test(test_frames_for_any_split_and_threads),
        cmocka_unit_test(test_forearm_swings_and_settles),
        cmocka_unit_test(test_forearm_any_start),
        cmocka_unit_test(test_sound),
        cmocka_unit_test(test_video_through_the_callers_encoder),
        cmocka_unit_test(test_piano_keys),
        cmocka_unit_test(test_command),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
