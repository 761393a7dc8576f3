/* A whole run of the fat model (Shigemori & Kawai sec. 5) as `shitsukan tissue run` makes
 * it: the motion simulated from time 0 at the model's fixed step, the skin sampled at the
 * output frames and written as a point cache, meshes, pictures and statistics. Sampling
 * never changes the simulation: the same model and motion give the same skin at a shared
 * instant for any frame rate, and a resumed run continues bit for bit. */
#define _POSIX_C_SOURCE 200809L
#include <cjson/cJSON.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "formats/json_file.h"
#include "shitsukan/io.h"
#include "shitsukan/pointcache.h"
#include "products/tissue/tissue_draw_internal.h"
#include "models/tissue/sim_internal.h"

#define MAX_FRAMES 100000
/* The tracked points are sampled at this rate for the plot (finer than any output frame
 * rate, so the jiggle shows). */
#define PLOT_HZ 240
/* skin.glb holds every frame in memory and one morph target per frame: written up to
   these sizes (larger runs leave it out and say so in stats.json). */
#define GLB_MAX_FRAMES 4096
#define GLB_MAX_FLOATS ((size_t)96 << 20)

typedef struct run_buffers {
    float *xyz, *ref;
    float *glb_positions, *glb_normals;
    sk_mesh rest;
    sk_mesh mesh;
    float *track_time, *track_with, *track_without;
} run_buffers;

static void free_buffers(run_buffers *b)
{
    free(b->xyz);
    free(b->ref);
    free(b->glb_positions);
    free(b->glb_normals);
    sk_mesh_free(&b->rest);
    sk_mesh_free(&b->mesh);
    free(b->track_time);
    free(b->track_with);
    free(b->track_without);
}

static void path_in(char *out, size_t size, const char *dir, const char *name)
{
    snprintf(out, size, "%s/%s", dir, name);
}

/* Bounds of the skin over the frames, carried by the bones (for a fixed camera). */
static void motion_bounds(const sk_tissue_model *m, const sk_tissue_motion *motion, int first,
                          int last, int fps, sk_vec3d *lo, sk_vec3d *hi)
{
    *lo = sk_v3d(DBL_MAX, DBL_MAX, DBL_MAX);
    *hi = sk_v3d(-DBL_MAX, -DBL_MAX, -DBL_MAX);
    int stride = (last - first) / 60 + 1;
    for (int f = first; f <= last; f += stride) {
        sk_quatd local[SK_TISSUE_MAX_JOINTS];
        for (int j = 0; j < m->skeleton.count; j++) local[j] = sk_qd_identity();
        sk_vec3d root = m->skeleton.rest[m->skeleton.root];
        motion->sample(motion->user, (double)f / fps, local, &root);
        sk_tissue_pose pose;
        sk__skeleton_pose(&m->skeleton, local, root, &pose);
        for (size_t p = 0; p < m->skin_count; p += 7) {
            sk_vec3d q = sk__pose_apply(&pose, m->bones[m->owner[p]].joint, m->local[p]);
            *lo = sk_v3d(fmin(lo->x, q.x), fmin(lo->y, q.y), fmin(lo->z, q.z));
            *hi = sk_v3d(fmax(hi->x, q.x), fmax(hi->y, q.y), fmax(hi->z, q.z));
        }
    }
}

static sk_result write_stats(const sk_tissue_model *m, const sk_tissue_run_stats *st,
                             const char *path, sk_error *err)
{
    cJSON *root = cJSON_CreateObject();
    if (!root) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    cJSON_AddNumberToObject(root, "frames", st->frames);
    cJSON_AddNumberToObject(root, "first_frame", st->first_frame);
    cJSON_AddNumberToObject(root, "fps", st->fps);
    cJSON_AddNumberToObject(root, "step_hz", m->desc.simulation.step_hz);
    cJSON_AddNumberToObject(root, "steps", (double)st->steps);
    cJSON_AddNumberToObject(root, "simulated_seconds", st->simulated_seconds);
    cJSON_AddNumberToObject(root, "simulated_frames_per_second", st->frames_per_second);
    cJSON_AddNumberToObject(root, "max_displacement_mm", st->max_displacement_mm);
    cJSON_AddBoolToObject(root, "glb", st->glb);
    cJSON *tracked = cJSON_AddObjectToObject(root, "tracked_max_displacement_mm");
    for (int k = 0; k < m->desc.tracked_count; k++)
        cJSON_AddNumberToObject(tracked, m->desc.tracked[k].name, st->tracked_max_mm[k]);
    cJSON *sec = cJSON_AddObjectToObject(root, "seconds");
    cJSON_AddNumberToObject(sec, "simulate", st->seconds_simulate);
    cJSON_AddNumberToObject(sec, "write", st->seconds_write);
    cJSON_AddNumberToObject(sec, "render", st->seconds_render);
    cJSON *model = sk__model_stats_json(m);
    if (model) cJSON_AddItemToObject(root, "model", model);
    return sk__json_write_file(root, path, err);
}

static sk_result check_desc(const sk_tissue_run_desc *d, double duration, int *fps, int *first,
                            int *last, sk_error *err)
{
    if (!d || !d->output_dir || !d->output_dir[0])
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "no output folder");
    *fps = d->fps ? d->fps : 30;
    sk_result r = sk_check_range_i(err, "fps", *fps, 1, 1000);
    if (r != SK_OK) return r;
    *first = d->first_frame;
    *last = d->last_frame ? d->last_frame : (int)floor(duration * *fps + 1e-6);
    if (*first < 0 || *last < *first)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "frames %d:%d: the first must be from 0 and not after the last", *first,
                       *last);
    if (*last - *first + 1 > MAX_FRAMES)
        return sk_fail(err, SK_ERROR_LIMIT, "frames %d:%d are more than %d frames", *first, *last,
                       MAX_FRAMES);
    if (d->render_width && (d->render_width < 64 || d->render_width > 4096))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "render width %d is out of range [64, 4096]",
                       d->render_width);
    return SK_OK;
}

/* One run's settings, buffers and open outputs, shared by its steps. */
typedef struct run_state {
    const sk_tissue_model *m;
    const sk_tissue_run_desc *d;
    int fps, first, last, frames;
    size_t ns;
    int tracked;              /* points plotted (0 without a plot) */
    size_t plot_cap, samples; /* the plot's series' capacity and samples taken */
    bool glb;
    run_buffers b;
    sk_tissue_sim *sim;
    sk_pc2_writer pc2;
    sk__view view;
    int rw, rh;
    sk_tissue_run_stats st;
} run_state;

/* The run's frame range, sizes and which outputs it writes, before anything is made. */
static void run_init(run_state *run, const sk_tissue_model *m, const sk_tissue_run_desc *d, int fps,
                     int first, int last)
{
    memset(run, 0, sizeof *run);
    run->m = m;
    run->d = d;
    run->fps = fps;
    run->first = first;
    run->last = last;
    run->frames = last - first + 1;
    run->st.frames = run->frames;
    run->st.first_frame = first;
    run->st.fps = fps;
    run->ns = m->skin_count;
    run->tracked = d->plot ? m->desc.tracked_count : 0;
    /* plot samples from the first frame to the last */
    run->plot_cap = (size_t)ceil((double)(last - first) / fps * PLOT_HZ) + 2;
    run->glb = !d->no_glb && run->frames <= GLB_MAX_FRAMES &&
               (size_t)run->frames * 6 * run->ns <= GLB_MAX_FLOATS;
    run->st.glb = run->glb;
    run->rw = d->render_width ? d->render_width : 480;
    run->rh = run->rw;
}

/* The output folder, with frames/ and render/ in it when those are written. */
static sk_result make_output_dirs(const sk_tissue_run_desc *d, sk_error *err)
{
    char path[4096];
    sk_result r = sk_make_dirs(d->output_dir, err);
    if (r == SK_OK && d->obj_frames) {
        path_in(path, sizeof path, d->output_dir, "frames");
        r = sk_make_dirs(path, err);
    }
    if (r == SK_OK && d->render) {
        path_in(path, sizeof path, d->output_dir, "render");
        r = sk_make_dirs(path, err);
    }
    return r;
}

/* The skin and plot buffers, the two rest meshes and, for skin.glb, every frame's skin. */
static sk_result alloc_buffers(run_state *run, sk_error *err)
{
    run_buffers *b = &run->b;
    size_t ns = run->ns, plot_cap = run->plot_cap;
    int tracked = run->tracked;
    b->xyz = malloc(3 * ns * sizeof *b->xyz);
    b->ref = malloc(3 * ns * sizeof *b->ref);
    b->track_time = malloc(plot_cap * sizeof *b->track_time);
    b->track_with = malloc(plot_cap * (size_t)(tracked ? tracked : 1) * sizeof *b->track_with);
    b->track_without =
        malloc(plot_cap * (size_t)(tracked ? tracked : 1) * sizeof *b->track_without);
    if (!b->xyz || !b->ref || !b->track_time || !b->track_with || !b->track_without)
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for %zu skin points", ns);
    sk_result r = sk_tissue_model_rest_skin(run->m, &b->mesh, err);
    if (r == SK_OK) r = sk_tissue_model_rest_skin(run->m, &b->rest, err);
    if (r == SK_OK && run->glb) {
        b->glb_positions = malloc((size_t)run->frames * 3 * ns * sizeof *b->glb_positions);
        b->glb_normals = malloc((size_t)run->frames * 3 * ns * sizeof *b->glb_normals);
        if (!b->glb_positions || !b->glb_normals)
            r = sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for skin.glb");
    }
    return r;
}

/* rest.obj written, the simulation made (from the saved state when resuming) and skin.pc2
 * opened. */
static sk_result start_run(run_state *run, const sk_tissue_motion *motion, sk_error *err)
{
    const sk_tissue_run_desc *d = run->d;
    char path[4096];
    path_in(path, sizeof path, d->output_dir, "rest.obj");
    sk_result r = sk_mesh_write_obj(&run->b.mesh, path, NULL, err);
    if (r == SK_OK) r = sk_tissue_sim_create(run->m, motion, &run->sim, err);
    if (r == SK_OK && d->resume_state) {
        double t_first = (double)run->first / run->fps;
        r = sk_tissue_sim_load_state_file(run->sim, d->resume_state, err);
        if (r == SK_OK && sk_tissue_sim_time(run->sim) > t_first + 1e-9)
            r = sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                        "%s: the state is at %.4f s, after frame %d (%.4f s)", d->resume_state,
                        sk_tissue_sim_time(run->sim), run->first, t_first);
    }
    if (r == SK_OK && !d->no_pc2) {
        path_in(path, sizeof path, d->output_dir, "skin.pc2");
        r = sk_pc2_open(&run->pc2, path, (int)run->ns, (float)run->first, 1.0f, run->frames, err);
    }
    return r;
}

/* The fixed camera over the skin's bounds through the frames, and the picture's size. */
static void frame_camera(run_state *run, const sk_tissue_motion *motion)
{
    sk_vec3d lo, hi;
    double aspect;
    motion_bounds(run->m, motion, run->first, run->last, run->fps, &lo, &hi);
    run->view = sk__jiggle_view(lo, hi, &aspect);
    run->rh = (int)(run->rw / aspect + 0.5);
    run->rh += run->rh & 1; /* even sizes suit video encoders */
    run->rw += run->rw & 1;
}

/* The plot's samples up to instant t: the tracked points' heights with the fat and as the
 * bones alone carry them, every 1 / PLOT_HZ s from the first frame. */
static sk_result sample_plot(run_state *run, double t, sk_error *err)
{
    const sk_tissue_model *m = run->m;
    sk_tissue_sim *sim = run->sim;
    run_buffers *b = &run->b;
    size_t plot_cap = run->plot_cap;
    double t_first = (double)run->first / run->fps;
    while (run->tracked > 0 && run->samples < plot_cap &&
           t_first + (double)run->samples / PLOT_HZ <= t + 1e-9) {
        double ts = t_first + (double)run->samples / PLOT_HZ;
        sk_result r = sk_tissue_sim_advance(sim, ts, err);
        if (r != SK_OK) return r;
        b->track_time[run->samples] = (float)ts;
        for (int k = 0; k < run->tracked; k++) {
            size_t p = (size_t)m->tracked_point[k];
            sk_vec3d ref = sk__sim_carried(sim, &sim->pose, sim->muscle, p);
            b->track_with[(size_t)k * plot_cap + run->samples] = (float)sim->x[3 * p + 1];
            b->track_without[(size_t)k * plot_cap + run->samples] = (float)ref.y;
        }
        run->samples++;
    }
    return SK_OK;
}

/* How far skin point p is from where the bones alone carry it. */
static inline double displacement(const float *xyz, const float *ref, size_t p)
{
    float dx = xyz[3 * p] - ref[3 * p], dy = xyz[3 * p + 1] - ref[3 * p + 1],
          dz = xyz[3 * p + 2] - ref[3 * p + 2];
    return sqrt(dx * dx + dy * dy + dz * dz);
}

/* The frame's largest displacement of the skin and of each tracked point, kept if the
 * largest so far. */
static void measure_displacement(run_state *run)
{
    const sk_tissue_model *m = run->m;
    run_buffers *b = &run->b;
    sk_tissue_sim_skin_reference(run->sim, b->ref);
    for (size_t p = 0; p < run->ns; p++)
        run->st.max_displacement_mm =
            fmax(run->st.max_displacement_mm, displacement(b->xyz, b->ref, p));
    for (int k = 0; k < m->desc.tracked_count; k++) {
        size_t p = (size_t)m->tracked_point[k];
        run->st.tracked_max_mm[k] =
            fmax(run->st.tracked_max_mm[k], displacement(b->xyz, b->ref, p));
    }
}

/* The frame's skin into skin.pc2, its normals, its place in skin.glb and frames/NNNN.obj. */
static sk_result write_frame(run_state *run, int f, sk_error *err)
{
    const sk_tissue_run_desc *d = run->d;
    run_buffers *b = &run->b;
    size_t ns = run->ns;
    int i = f - run->first;
    sk_result r = SK_OK;
    if (!d->no_pc2) r = sk_pc2_append(&run->pc2, b->xyz, err);
    if (r == SK_OK && (d->obj_frames || d->render || run->glb)) {
        memcpy(b->mesh.positions, b->xyz, 3 * ns * sizeof(float));
        r = sk_mesh_compute_normals(&b->mesh, err);
    }
    if (r == SK_OK && run->glb) {
        memcpy(b->glb_positions + (size_t)i * 3 * ns, b->xyz, 3 * ns * sizeof(float));
        memcpy(b->glb_normals + (size_t)i * 3 * ns, b->mesh.normals, 3 * ns * sizeof(float));
    }
    if (r == SK_OK && d->obj_frames) {
        char name[64], path[4096];
        snprintf(name, sizeof name, "frames/%04d.obj", f);
        path_in(path, sizeof path, d->output_dir, name);
        r = sk_mesh_write_obj(&b->mesh, path, NULL, err);
    }
    return r;
}

/* One output frame: the simulation to its instant (the plot's samples on the way), the
 * displacements, the frame's files and its picture, each step timed. */
static sk_result run_frame(run_state *run, int f, sk_error *err)
{
    const sk_tissue_run_desc *d = run->d;
    sk_tissue_run_stats *st = &run->st;
    double t = (double)f / run->fps, t0 = sk_time_seconds();
    /* the plot's samples up to this frame (the simulation does not depend on how its
       time is split into calls) */
    sk_result r = sample_plot(run, t, err);
    if (r == SK_OK) r = sk_tissue_sim_skin(run->sim, t, run->b.xyz, err);
    double t1 = sk_time_seconds();
    st->seconds_simulate += t1 - t0;
    if (r != SK_OK) return r;
    measure_displacement(run);
    r = write_frame(run, f, err);
    double t2 = sk_time_seconds();
    st->seconds_write += t2 - t1;
    if (r == SK_OK && d->render) {
        char name[64], path[4096];
        snprintf(name, sizeof name, "render/%04d.png", f);
        path_in(path, sizeof path, d->output_dir, name);
        r = sk__render_skin(&run->b.mesh, &run->view, run->rw, run->rh, path, err);
        st->seconds_render += sk_time_seconds() - t2;
    }
    sk_progress_report(&d->progress, (double)(f - run->first + 1) / run->frames);
    return r;
}

/* The plot of the tracked points with and without the fat. */
static sk_result plot_tracked(run_state *run, sk_error *err)
{
    run_buffers *b = &run->b;
    int tracked = run->tracked;
    size_t samples = run->samples, plot_cap = run->plot_cap;
    /* the series are point-major with plot_cap samples each: pack them to `samples` */
    for (int k = 1; k < tracked; k++) {
        memmove(b->track_with + (size_t)k * samples, b->track_with + (size_t)k * plot_cap,
                samples * sizeof(float));
        memmove(b->track_without + (size_t)k * samples, b->track_without + (size_t)k * plot_cap,
                samples * sizeof(float));
    }
    sk__tracked_series ts = {tracked,       (int)samples,  {0},
                             b->track_time, b->track_with, b->track_without};
    for (int k = 0; k < tracked; k++) ts.name[k] = run->m->desc.tracked[k].name;
    return sk__plot_tracked(&ts, run->d->plot, err);
}

/* After the frames (r: how they went): skin.pc2 closed (or dropped after a failure), then
 * skin.glb, the saved state and the plot. */
static sk_result finish_outputs(run_state *run, sk_result r, sk_error *err)
{
    const sk_tissue_run_desc *d = run->d;
    if (r == SK_OK && !d->no_pc2)
        r = sk_pc2_close(&run->pc2, err);
    else
        sk_pc2_abort(&run->pc2);
    if (r == SK_OK && run->glb) {
        char path[4096];
        path_in(path, sizeof path, d->output_dir, "skin.glb");
        r = sk__write_skin_glb(&run->b.rest, run->b.glb_positions, run->b.glb_normals, run->frames,
                               run->first, run->fps, path, err);
    }
    if (r == SK_OK && d->save_state)
        r = sk_tissue_sim_save_state_file(run->sim, d->save_state, err);
    if (r == SK_OK && d->plot && run->tracked > 0 && run->samples >= 2) r = plot_tracked(run, err);
    return r;
}

sk_result sk_tissue_run(const sk_tissue_model *m, const sk_tissue_motion *motion,
                        const sk_tissue_run_desc *d, sk_tissue_run_stats *out_stats, sk_error *err)
{
    int fps = 30, first = 0, last = 0;
    sk_result r = check_desc(d, motion ? motion->duration : 0.0, &fps, &first, &last, err);
    if (r != SK_OK) return r;
    run_state run;
    run_init(&run, m, d, fps, first, last);
    sk_tissue_run_stats *st = &run.st;
    r = make_output_dirs(d, err);
    if (r == SK_OK) r = alloc_buffers(&run, err);
    if (r == SK_OK) r = start_run(&run, motion, err);
    if (r == SK_OK && d->render) frame_camera(&run, motion);
    int64_t steps0 = run.sim ? sk_tissue_sim_steps(run.sim) : 0;
    for (int f = first; r == SK_OK && f <= last; f++) r = run_frame(&run, f, err);
    double t3 = sk_time_seconds();
    r = finish_outputs(&run, r, err);
    if (run.sim) {
        st->steps = sk_tissue_sim_steps(run.sim) - steps0;
        st->simulated_seconds = (double)st->steps / m->desc.simulation.step_hz;
    }
    st->frames_per_second = st->seconds_simulate > 0 ? run.frames / st->seconds_simulate : 0.0;
    st->seconds_write += sk_time_seconds() - t3;
    if (r == SK_OK) {
        char path[4096];
        path_in(path, sizeof path, d->output_dir, "stats.json");
        r = write_stats(m, st, path, err);
    }
    sk_tissue_sim_destroy(run.sim);
    free_buffers(&run.b);
    if (out_stats) *out_stats = *st;
    return r;
}
