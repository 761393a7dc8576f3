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

#include "io/json_file.h"
#include "shitsukan/io.h"
#include "shitsukan/pointcache.h"
#include "tissue/draw_internal.h"
#include "tissue/sim_internal.h"

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

sk_result sk_tissue_run(const sk_tissue_model *m, const sk_tissue_motion *motion,
                        const sk_tissue_run_desc *d, sk_tissue_run_stats *out_stats, sk_error *err)
{
    int fps = 30, first = 0, last = 0;
    sk_result r = check_desc(d, motion ? motion->duration : 0.0, &fps, &first, &last, err);
    if (r != SK_OK) return r;
    int frames = last - first + 1;
    sk_tissue_run_stats st;
    memset(&st, 0, sizeof st);
    st.frames = frames;
    st.first_frame = first;
    st.fps = fps;
    char path[4096];
    r = sk_make_dirs(d->output_dir, err);
    if (r == SK_OK && d->obj_frames) {
        path_in(path, sizeof path, d->output_dir, "frames");
        r = sk_make_dirs(path, err);
    }
    if (r == SK_OK && d->render) {
        path_in(path, sizeof path, d->output_dir, "render");
        r = sk_make_dirs(path, err);
    }
    run_buffers b;
    memset(&b, 0, sizeof b);
    size_t ns = m->skin_count;
    int tracked = d->plot ? m->desc.tracked_count : 0;
    /* plot samples from the first frame to the last */
    size_t plot_cap = (size_t)ceil((double)(last - first) / fps * PLOT_HZ) + 2, samples = 0;
    if (r == SK_OK) {
        b.xyz = malloc(3 * ns * sizeof *b.xyz);
        b.ref = malloc(3 * ns * sizeof *b.ref);
        b.track_time = malloc(plot_cap * sizeof *b.track_time);
        b.track_with = malloc(plot_cap * (size_t)(tracked ? tracked : 1) * sizeof *b.track_with);
        b.track_without =
            malloc(plot_cap * (size_t)(tracked ? tracked : 1) * sizeof *b.track_without);
        if (!b.xyz || !b.ref || !b.track_time || !b.track_with || !b.track_without)
            r = sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for %zu skin points", ns);
    }
    if (r == SK_OK) r = sk_tissue_model_rest_skin(m, &b.mesh, err);
    if (r == SK_OK) r = sk_tissue_model_rest_skin(m, &b.rest, err);
    bool glb = !d->no_glb && frames <= GLB_MAX_FRAMES && (size_t)frames * 6 * ns <= GLB_MAX_FLOATS;
    if (r == SK_OK && glb) {
        b.glb_positions = malloc((size_t)frames * 3 * ns * sizeof *b.glb_positions);
        b.glb_normals = malloc((size_t)frames * 3 * ns * sizeof *b.glb_normals);
        if (!b.glb_positions || !b.glb_normals)
            r = sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for skin.glb");
    }
    st.glb = glb;
    if (r == SK_OK) {
        path_in(path, sizeof path, d->output_dir, "rest.obj");
        r = sk_mesh_write_obj(&b.mesh, path, NULL, err);
    }
    sk_tissue_sim *sim = NULL;
    if (r == SK_OK) r = sk_tissue_sim_create(m, motion, &sim, err);
    if (r == SK_OK && d->resume_state) {
        r = sk_tissue_sim_load_state_file(sim, d->resume_state, err);
        if (r == SK_OK && sk_tissue_sim_time(sim) > (double)first / fps + 1e-9)
            r = sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                        "%s: the state is at %.4f s, after frame %d (%.4f s)", d->resume_state,
                        sk_tissue_sim_time(sim), first, (double)first / fps);
    }
    sk_pc2_writer pc2 = {0};
    if (r == SK_OK && !d->no_pc2) {
        path_in(path, sizeof path, d->output_dir, "skin.pc2");
        r = sk_pc2_open(&pc2, path, (int)ns, (float)first, 1.0f, frames, err);
    }
    sk__view view = {0};
    int rw = d->render_width ? d->render_width : 480, rh = rw;
    if (r == SK_OK && d->render) {
        sk_vec3d lo, hi;
        double aspect;
        motion_bounds(m, motion, first, last, fps, &lo, &hi);
        view = sk__jiggle_view(lo, hi, &aspect);
        rh = (int)(rw / aspect + 0.5);
        rh += rh & 1; /* even sizes suit video encoders */
        rw += rw & 1;
    }
    int64_t steps0 = sim ? sk_tissue_sim_steps(sim) : 0;
    for (int f = first; r == SK_OK && f <= last; f++) {
        double t = (double)f / fps, t0 = sk_time_seconds();
        /* the plot's samples up to this frame (the simulation does not depend on how its
           time is split into calls) */
        while (tracked > 0 && samples < plot_cap &&
               (double)first / fps + (double)samples / PLOT_HZ <= t + 1e-9) {
            double ts = (double)first / fps + (double)samples / PLOT_HZ;
            r = sk_tissue_sim_advance(sim, ts, err);
            if (r != SK_OK) break;
            b.track_time[samples] = (float)ts;
            for (int k = 0; k < tracked; k++) {
                size_t p = (size_t)m->tracked_point[k];
                sk_vec3d ref = sk__sim_carried(sim, &sim->pose, sim->muscle, p);
                b.track_with[(size_t)k * plot_cap + samples] = (float)sim->x[3 * p + 1];
                b.track_without[(size_t)k * plot_cap + samples] = (float)ref.y;
            }
            samples++;
        }
        if (r == SK_OK) r = sk_tissue_sim_skin(sim, t, b.xyz, err);
        double t1 = sk_time_seconds();
        st.seconds_simulate += t1 - t0;
        if (r != SK_OK) break;
        sk_tissue_sim_skin_reference(sim, b.ref);
        int i = f - first;
        for (size_t p = 0; p < ns; p++) {
            float dx = b.xyz[3 * p] - b.ref[3 * p], dy = b.xyz[3 * p + 1] - b.ref[3 * p + 1],
                  dz = b.xyz[3 * p + 2] - b.ref[3 * p + 2];
            st.max_displacement_mm =
                fmax(st.max_displacement_mm, sqrt(dx * dx + dy * dy + dz * dz));
        }
        for (int k = 0; k < m->desc.tracked_count; k++) {
            size_t p = (size_t)m->tracked_point[k];
            float dx = b.xyz[3 * p] - b.ref[3 * p], dy = b.xyz[3 * p + 1] - b.ref[3 * p + 1],
                  dz = b.xyz[3 * p + 2] - b.ref[3 * p + 2];
            st.tracked_max_mm[k] = fmax(st.tracked_max_mm[k], sqrt(dx * dx + dy * dy + dz * dz));
        }
        if (!d->no_pc2) r = sk_pc2_append(&pc2, b.xyz, err);
        if (r == SK_OK && (d->obj_frames || d->render || glb)) {
            memcpy(b.mesh.positions, b.xyz, 3 * ns * sizeof(float));
            r = sk_mesh_compute_normals(&b.mesh, err);
        }
        if (r == SK_OK && glb) {
            memcpy(b.glb_positions + (size_t)i * 3 * ns, b.xyz, 3 * ns * sizeof(float));
            memcpy(b.glb_normals + (size_t)i * 3 * ns, b.mesh.normals, 3 * ns * sizeof(float));
        }
        if (r == SK_OK && d->obj_frames) {
            char name[64];
            snprintf(name, sizeof name, "frames/%04d.obj", f);
            path_in(path, sizeof path, d->output_dir, name);
            r = sk_mesh_write_obj(&b.mesh, path, NULL, err);
        }
        double t2 = sk_time_seconds();
        st.seconds_write += t2 - t1;
        if (r == SK_OK && d->render) {
            char name[64];
            snprintf(name, sizeof name, "render/%04d.png", f);
            path_in(path, sizeof path, d->output_dir, name);
            r = sk__render_skin(&b.mesh, &view, rw, rh, path, err);
            st.seconds_render += sk_time_seconds() - t2;
        }
        sk_progress_report(&d->progress, (double)(i + 1) / frames);
    }
    double t3 = sk_time_seconds();
    if (r == SK_OK && !d->no_pc2)
        r = sk_pc2_close(&pc2, err);
    else
        sk_pc2_abort(&pc2);
    if (r == SK_OK && glb) {
        path_in(path, sizeof path, d->output_dir, "skin.glb");
        r = sk__write_skin_glb(&b.rest, b.glb_positions, b.glb_normals, frames, first, fps, path,
                               err);
    }
    if (r == SK_OK && d->save_state) r = sk_tissue_sim_save_state_file(sim, d->save_state, err);
    if (r == SK_OK && d->plot && tracked > 0 && samples >= 2) {
        /* the series are point-major with plot_cap samples each: pack them to `samples` */
        for (int k = 1; k < tracked; k++) {
            memmove(b.track_with + (size_t)k * samples, b.track_with + (size_t)k * plot_cap,
                    samples * sizeof(float));
            memmove(b.track_without + (size_t)k * samples, b.track_without + (size_t)k * plot_cap,
                    samples * sizeof(float));
        }
        sk__tracked_series ts = {tracked,      (int)samples, {0},
                                 b.track_time, b.track_with, b.track_without};
        for (int k = 0; k < tracked; k++) ts.name[k] = m->desc.tracked[k].name;
        r = sk__plot_tracked(&ts, d->plot, err);
    }
    if (sim) {
        st.steps = sk_tissue_sim_steps(sim) - steps0;
        st.simulated_seconds = (double)st.steps / m->desc.simulation.step_hz;
    }
    st.frames_per_second = st.seconds_simulate > 0 ? frames / st.seconds_simulate : 0.0;
    st.seconds_write += sk_time_seconds() - t3;
    if (r == SK_OK) {
        path_in(path, sizeof path, d->output_dir, "stats.json");
        r = write_stats(m, &st, path, err);
    }
    sk_tissue_sim_destroy(sim);
    free_buffers(&b);
    if (out_stats) *out_stats = st;
    return r;
}
