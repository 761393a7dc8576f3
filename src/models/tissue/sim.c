/* The motion of the model (Shigemori & Kawai sec. 5): at every fixed internal step the
 * bones take the motion's pose, bone points move rigidly with their bones, muscle points
 * with their muscles' deformation, and fat and skin points under the springs (solver.h).
 * The clock is the step count, never the output frame rate, so a run is the same however
 * its outputs are sampled, and two runs of the same model and motion agree bit for bit.
 * A bone end that jumps faster than the teleport speed in one step carries its flesh with
 * it (a cut in the motion is not a blow to the flesh). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "models/tissue/sim_internal.h"
#include "models/tissue/simd.h"

/* Relaxation steps at the start pose before time 0 (the flesh carried there by the tissue
 * is let settle, so a motion that does not start at rest does not start with a jolt), until
 * no point moves more than SETTLED_MM in a step. */
#define SETTLE_STEPS 240
#define SETTLED_MM 1e-6
/* Steps timed on one thread and on all to choose, and steps until the choice is made again.
 * On several threads the steps also run in runs of WATCH_STEPS, each timed: a run whose
 * steps are WATCH_SLOWDOWN times slower than one thread's at the last choice (the machine
 * got busy and the threads wait for each other at every barrier) makes the choice again
 * at once, so a choice made in a quiet moment is not kept through a busy one. */
#define PROBE_STEPS 12
#define REPROBE_STEPS 1200
#define WATCH_STEPS 24
#define WATCH_SLOWDOWN 1.25

void sk__sim_pose_at(const sk_tissue_sim *s, int64_t k, sk_tissue_pose *pose)
{
    sk_quatd local[SK_TISSUE_MAX_JOINTS];
    const sk__skeleton *sk = &s->m->skeleton;
    for (int j = 0; j < sk->count; j++) local[j] = sk_qd_identity();
    sk_vec3d root = sk->rest[sk->root];
    s->motion.sample(s->motion.user, (double)k / (double)s->step_hz, local, &root);
    sk__skeleton_pose(sk, local, root, pose);
}

void sk__sim_shape_muscles(const sk_tissue_sim *s, const sk_tissue_pose *pose,
                           sk__muscle_state *muscle)
{
    for (int i = 0; i < s->m->desc.muscle_count; i++)
        sk__muscle_shape(&s->m->muscles[i], pose, &muscle[i].body);
}

/* Muscle or bone point p where a pose (and the muscles' shapes at it) puts it. */
static sk_vec3d anchor_at(const sk_tissue_sim *s, const sk_tissue_pose *pose,
                          const sk__muscle_state *muscle, size_t p)
{
    const sk_tissue_model *m = s->m;
    if (p < s->nfree + m->muscle_count) {
        const sk__ellipsoid *e = &muscle[m->owner[p]].body;
        sk_vec3d u = m->local[p];
        return sk_v3d_add(
            e->centre,
            sk_m3d_apply(e->axes, sk_v3d(u.x * e->radii.x, u.y * e->radii.y, u.z * e->radii.z)));
    }
    return sk__pose_apply(pose, m->bones[m->owner[p]].joint, m->local[p]);
}

void sk__sim_place_anchors(const sk_tissue_sim *s, const sk_tissue_pose *pose,
                           const sk__muscle_state *muscle, double *x)
{
#pragma omp for schedule(static)
    for (size_t p = s->nfree; p < s->n; p++) {
        sk_vec3d q = anchor_at(s, pose, muscle, p);
        x[3 * p] = q.x;
        x[3 * p + 1] = q.y;
        x[3 * p + 2] = q.z;
    }
}

static uint64_t fingerprint(const sk_tissue_model *m, int step_hz)
{
    uint64_t h = sk_hash(0x7469737375650001ULL, m->point_count, m->spring_count, (uint64_t)step_hz);
    for (size_t p = 0; p < m->point_count; p++) {
        uint64_t bits[4];
        memcpy(bits, &m->rest[p], 3 * sizeof(double));
        memcpy(bits + 3, &m->mass[p], sizeof(double));
        h = sk_hash(h, bits[0] ^ (bits[3] << 1), bits[1], bits[2]);
    }
    const sk_tissue_material_desc *mat = &m->desc.material;
    float params[8] = {mat->fat_stiffness, mat->anchor_stiffness, mat->skin_stiffness,
                       mat->fat_density,   mat->skin_density,     mat->skin_thickness_mm,
                       mat->damping_ratio, mat->tether_stiffness};
    uint32_t bits[8];
    memcpy(bits, params, sizeof bits);
    for (int i = 0; i < 8; i++) h = sk_hash(h, bits[i], (uint64_t)i, m->desc.simulation.no_fat);
    h = sk_hash(h, (uint64_t)m->desc.simulation.iterations, 0, 0);
    return h;
}

/* The free points where the tissue carries them at the current pose (also the tethers'
 * targets). */
static void carry_all(sk_tissue_sim *s)
{
    for (size_t p = 0; p < s->nfree; p++) {
        sk_vec3d q = sk__sim_carried(s, &s->pose, s->muscle, p);
        double v[3] = {q.x, q.y, q.z};
        for (int c = 0; c < 3; c++)
            s->x[3 * p + (size_t)c] = s->target[3 * p + (size_t)c] =
                s->target_base[3 * p + (size_t)c] = v[c];
    }
}

/* Threads for a model's loops: one below the size where waking others costs more than it
 * saves (the solver synchronises a few times per step). */
static int threads_for(const sk_tissue_sim *s)
{
    return s->nfree >= s->parallel_points ? sk_threads_max() : 1;
}

/* The flesh relaxed at the start pose (no inertia): every thread of a region calls it.
 * The largest move of a step is a max over the threads' maxima, the same for any count. */
static void settle(sk_tissue_sim *s)
{
    for (int i = 0; i < SETTLE_STEPS; i++) {
#pragma omp for schedule(static)
        for (size_t k = 0; k < 3 * s->n; k++) s->base[k] = s->x[k];
        s->ops->step(s->solver, s->x, s->base, s->target, s->target);
        sk__collide(s->obstacles, s->obstacle_count, s->m->desc.bone_count, s->m->near_muscles,
                    s->x, s->nfree, s->vectors);
#pragma omp single
        s->settle_move = 0.0;
        double move = 0.0; /* this thread's largest (a max is the same in any order) */
#pragma omp for schedule(static)
        for (size_t k = 0; k < 3 * s->nfree; k++) {
            double d = fabs(s->x[k] - s->base[k]);
            if (d > move) move = d;
        }
#pragma omp critical(sk_tissue_settle)
        if (move > s->settle_move) s->settle_move = move;
#pragma omp barrier
        if (s->settle_move < SETTLED_MM) break;
#pragma omp barrier
    }
}

sk_result sk_tissue_sim_create(const sk_tissue_model *m, const sk_tissue_motion *motion,
                               sk_tissue_sim **out, sk_error *err)
{
    *out = NULL;
    if (!m || !motion || !motion->sample)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "a simulation needs a model and a motion with a sample function");
    sk_tissue_sim *s = calloc(1, sizeof *s);
    if (!s) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    s->m = m;
    s->motion = *motion;
    s->ops = &sk__solver_xpbd;
    s->step_hz = m->desc.simulation.step_hz;
    s->h = 1.0 / s->step_hz;
    s->n = m->point_count;
    s->nfree = m->skin_count + m->fat_count;
    s->x = malloc(3 * s->n * sizeof *s->x);
    s->prev = malloc(3 * s->n * sizeof *s->prev);
    s->base = malloc(3 * s->n * sizeof *s->base);
    s->v = calloc(3 * (s->nfree ? s->nfree : 1), sizeof *s->v);
    s->target = malloc(3 * (s->nfree ? s->nfree : 1) * sizeof *s->target);
    s->target_base = malloc(3 * (s->nfree ? s->nfree : 1) * sizeof *s->target_base);
    sk_result r = SK_OK;
    if (!s->x || !s->prev || !s->base || !s->v || !s->target || !s->target_base)
        r = sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for %zu points", s->n);
    if (r == SK_OK && !m->desc.simulation.no_fat) r = s->ops->create(m, s->h, &s->solver, err);
    if (r != SK_OK) {
        sk_tissue_sim_destroy(s);
        return r;
    }
    s->fingerprint = fingerprint(m, s->step_hz);
    s->vectors = sk__have_avx2();
    s->parallel_points = 20000;
    s->threads = sk_threads_max();
    s->clock = sk_time_seconds;
    sk__sim_pose_at(s, 0, &s->pose);
    s->pose_prev = s->pose;
    sk__sim_shape_muscles(s, &s->pose, s->muscle);
    memcpy(s->muscle_prev, s->muscle, sizeof s->muscle);
    s->obstacle_count = sk__obstacles(m, &s->pose, s->muscle, s->obstacles);
    sk__sim_place_anchors(s, &s->pose, s->muscle, s->x);
    carry_all(s);
    if (s->solver) {
#pragma omp parallel num_threads(threads_for(s))
        settle(s);
    }
    memcpy(s->prev, s->x, 3 * s->n * sizeof *s->x);
    *out = s;
    return SK_OK;
}

void sk_tissue_sim_destroy(sk_tissue_sim *s)
{
    if (!s) return;
    if (s->solver) s->ops->destroy(s->solver);
    free(s->x);
    free(s->prev);
    free(s->base);
    free(s->v);
    free(s->target);
    free(s->target_base);
    free(s);
}

/* The largest distance a bone's ends moved between two poses. */
static double bone_jump(const sk_tissue_model *m, int b, const sk_tissue_pose *from,
                        const sk_tissue_pose *to)
{
    const sk__bone *bone = &m->bones[b];
    double worst = 0.0;
    const sk_vec3d ends[2] = {bone->start, bone->end};
    for (int e = 0; e < 2; e++) {
        sk_vec3d a = sk__pose_apply(from, bone->joint, ends[e]),
                 c = sk__pose_apply(to, bone->joint, ends[e]);
        worst = fmax(worst, sk_v3d_length(sk_v3d_sub(c, a)));
    }
    return worst;
}

/* What one thread does before a step: the pose at the step's end, the bones that jumped,
 * the muscles' shapes and the bones' ellipsoids there. */
static void prepare_step(sk_tissue_sim *s)
{
    const sk_tissue_model *m = s->m;
    sk__sim_pose_at(s, s->step + 1, &s->next);
    double limit = m->desc.simulation.teleport_speed_m_s * 1000.0 * s->h;
    s->any_carry = false;
    for (int b = 0; b < m->desc.bone_count; b++) {
        s->carry[b] = bone_jump(m, b, &s->pose, &s->next) > limit;
        s->any_carry |= s->carry[b];
        int j = m->bones[b].joint;
        s->turn[b] =
            sk_qd_normalize(sk_qd_mul(s->next.rotation[j], sk_qd_conj(s->pose.rotation[j])));
    }
    sk__sim_shape_muscles(s, &s->next, s->muscle_next);
    s->obstacle_count = sk__obstacles(m, &s->next, s->muscle_next, s->obstacles);
}

/* Whether driven point p's bone (or a bone of its muscle) jumped this step. */
static bool anchor_jumped(const sk_tissue_sim *s, size_t p)
{
    const sk_tissue_model *m = s->m;
    if (!s->any_carry) return false;
    if (p < s->nfree + m->muscle_count) {
        const sk__muscle *mu = &m->muscles[m->owner[p]];
        return s->carry[mu->origin_bone] || s->carry[mu->insertion_bone];
    }
    return s->carry[m->owner[p]];
}

/* The step taken: the pose at its end becomes the current one. */
static void finish_step(sk_tissue_sim *s)
{
    s->pose_prev = s->pose;
    s->pose = s->next;
    memcpy(s->muscle_prev, s->muscle, sizeof s->muscle);
    memcpy(s->muscle, s->muscle_next, sizeof s->muscle);
    s->step++;
}

/* One internal step, prepared (prepare_step); every thread of a parallel region calls it.
 * Returns with the points moved; the caller finishes it (finish_step) in one thread. */
static void step_parallel(sk_tissue_sim *s)
{
    const sk_tissue_model *m = s->m;
    /* driven points: to the new pose; the springs' damping sees their motion over the step,
       unless their bone jumped (then they are taken to have been carried there) */
#pragma omp for schedule(static) nowait
    for (size_t p = s->nfree; p < s->n; p++) {
        double *x = s->x + 3 * p, *prev = s->prev + 3 * p, *base = s->base + 3 * p;
        sk_vec3d q = anchor_at(s, &s->next, s->muscle_next, p);
        bool jumped = anchor_jumped(s, p);
        for (int c = 0; c < 3; c++) prev[c] = x[c];
        x[0] = q.x;
        x[1] = q.y;
        x[2] = q.z;
        for (int c = 0; c < 3; c++) base[c] = jumped ? x[c] : prev[c];
    }
    /* free points: the inertial prediction (carried along by a bone that jumped) */
    bool no_fat = m->desc.simulation.no_fat;
#pragma omp for schedule(static)
    for (size_t p = 0; p < s->nfree; p++) {
        double *x = s->x + 3 * p, *prev = s->prev + 3 * p, *base = s->base + 3 * p,
               *v = s->v + 3 * p;
        double *target = s->target + 3 * p, *target_base = s->target_base + 3 * p;
        for (int c = 0; c < 3; c++) prev[c] = x[c];
        sk_vec3d q = sk_v3d(x[0], x[1], x[2]), vel = sk_v3d(v[0], v[1], v[2]);
        sk_vec3d r = sk__sim_carried(s, &s->next, s->muscle_next, p);
        int b = m->owner[p];
        /* the tether's end moves with the tissue; a jump is not a pull */
        for (int c = 0; c < 3; c++)
            target_base[c] = s->carry[b] ? (c == 0 ? r.x : c == 1 ? r.y : r.z) : target[c];
        target[0] = r.x;
        target[1] = r.y;
        target[2] = r.z;
        if (no_fat) {
            q = r;
            vel = sk_v3d(0, 0, 0);
        } else if (s->carry[b]) {
            int j = m->bones[b].joint;
            q = sk_v3d_add(s->next.position[j],
                           sk_qd_rotate(s->turn[b], sk_v3d_sub(q, s->pose.position[j])));
            vel = sk_qd_rotate(s->turn[b], vel);
        }
        base[0] = q.x;
        base[1] = q.y;
        base[2] = q.z;
        x[0] = q.x + s->h * vel.x;
        x[1] = q.y + s->h * vel.y;
        x[2] = q.z + s->h * vel.z;
    }
    if (!no_fat) s->ops->step(s->solver, s->x, s->base, s->target, s->target_base);
    /* out of the bones and muscles, then the velocities, block by block */
    sk__collide_finish(s->obstacles, no_fat ? 0 : s->obstacle_count, s->m->desc.bone_count,
                       s->m->near_muscles, s->x, s->base, s->v, 1.0 / s->h, s->nfree, s->vectors);
}

/* Steps on `threads` threads until step `end`. */
static void run_steps(sk_tissue_sim *s, int64_t end, int threads)
{
    if (s->step >= end) return;
    prepare_step(s);
#pragma omp parallel num_threads(threads)
    while (s->step < end) {
        step_parallel(s);
        /* one synchronisation between steps: this one, then the next prepared */
#pragma omp single
        {
            finish_step(s);
            if (s->step < end) prepare_step(s);
        }
    }
}

/* Steps until `end` on `threads` threads; the seconds they took by the choice's clock. */
static double timed_steps(sk_tissue_sim *s, int64_t end, int threads)
{
    double t0 = s->clock();
    run_steps(s, end, threads);
    return s->clock() - t0;
}

sk_result sk_tissue_sim_advance(sk_tissue_sim *s, double seconds, sk_error *err)
{
    if (!isfinite(seconds) || seconds > SK__SIM_MAX_SECONDS)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "time %g s is not a finite time up to %g s",
                       seconds, SK__SIM_MAX_SECONDS);
    double k = seconds * s->step_hz;
    int64_t target = (int64_t)ceil(k - 1e-6);
    int most = threads_for(s);
    while (s->step < target) {
        if (most > 1 && s->probe_phase == 0 && s->step >= s->next_probe) {
            s->probe_phase = 1;
            s->probe_steps[0] = s->probe_steps[1] = 0;
            s->probe_s[0] = s->probe_s[1] = 0.0;
        }
        if (most > 1 && s->probe_phase > 0) {
            /* the choice: PROBE_STEPS steps timed on one thread, then as many on all, over
               as many calls as it takes (a frame may be fewer steps); the faster is kept
               (the machine may be shared; the result is the same either way) */
            int p = s->probe_phase - 1;
            int64_t a0 = s->step, left = PROBE_STEPS - s->probe_steps[p];
            s->probe_s[p] +=
                timed_steps(s, a0 + left < target ? a0 + left : target, p == 0 ? 1 : most);
            s->probe_steps[p] += s->step - a0;
            if (s->probe_steps[p] < PROBE_STEPS) continue;
            if (p == 0) {
                s->probe_phase = 2;
                continue;
            }
            s->probe_phase = 0;
            s->one_thread_step_s = s->probe_s[0] / PROBE_STEPS;
            s->threads = s->probe_s[1] < s->probe_s[0] ? most : 1;
            s->next_probe = s->step + REPROBE_STEPS;
            continue;
        }
        int64_t end = most > 1 && s->next_probe < target ? s->next_probe : target;
        if (most > 1 && s->threads > 1) {
            /* a timed run; too slow against one thread: choose again */
            int64_t a0 = s->step;
            double took = timed_steps(s, a0 + WATCH_STEPS < end ? a0 + WATCH_STEPS : end, most);
            if (s->step > a0 && s->one_thread_step_s > 0 &&
                took > WATCH_SLOWDOWN * s->one_thread_step_s * (double)(s->step - a0))
                s->next_probe = s->step;
            continue;
        }
        run_steps(s, end, 1); /* one thread: the one chosen, or all there is */
    }
    return SK_OK;
}

void sk__sim_use_vectors(sk_tissue_sim *s, bool on)
{
    s->vectors = on && sk__have_avx2();
    if (s->solver) sk__solver_xpbd_use_vectors(s->solver, on);
}

int64_t sk_tissue_sim_steps(const sk_tissue_sim *s) { return s->step; }
double sk_tissue_sim_time(const sk_tissue_sim *s) { return (double)s->step / s->step_hz; }

sk_result sk_tissue_sim_skin(sk_tissue_sim *s, double seconds, float *xyz, sk_error *err)
{
    sk_result r = sk_tissue_sim_advance(s, seconds, err);
    if (r != SK_OK) return r;
    double k = seconds * s->step_hz;
    int64_t nearest = (int64_t)llround(k);
    bool exact = fabs(k - (double)nearest) < 1e-6;
    int64_t hi = exact ? nearest : (int64_t)ceil(k);
    double frac = exact ? 1.0 : k - floor(k);
    if (hi < 0) hi = 0, frac = 1.0;
    if (hi > s->step || hi < s->step - 1 || (!exact && hi < s->step))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "time %g s is before the last two steps kept (now at %.6f s)", seconds,
                       sk_tissue_sim_time(s));
    const double *a = s->prev, *b = hi == s->step ? s->x : s->prev;
    size_t n = s->m->skin_count;
    if (exact) { /* a step's own state, not a blend */
        for (size_t i = 0; i < 3 * n; i++) xyz[i] = (float)b[i];
        return SK_OK;
    }
#pragma omp parallel for schedule(static) if (n >= 20000)
    for (size_t i = 0; i < 3 * n; i++) xyz[i] = (float)(a[i] + (b[i] - a[i]) * frac);
    return SK_OK;
}

void sk_tissue_sim_skin_reference(const sk_tissue_sim *s, float *xyz)
{
    size_t n = s->m->skin_count;
#pragma omp parallel for schedule(static) if (n >= 20000)
    for (size_t p = 0; p < n; p++) {
        sk_vec3d q = sk__sim_carried(s, &s->pose, s->muscle, p);
        xyz[3 * p] = (float)q.x;
        xyz[3 * p + 1] = (float)q.y;
        xyz[3 * p + 2] = (float)q.z;
    }
}

/* Sums in fixed chunks added in order, so the total does not depend on the thread count. */
#define CHUNKS 64

void sk_tissue_sim_energy(const sk_tissue_sim *s, double *potential_j, double *kinetic_j)
{
    const sk_tissue_model *m = s->m;
    double pe[CHUNKS] = {0}, ke[CHUNKS] = {0};
#pragma omp parallel for schedule(static)
    for (int c = 0; c < CHUNKS; c++) {
        size_t k0 = m->spring_count * (size_t)c / CHUNKS,
               k1 = m->spring_count * (size_t)(c + 1) / CHUNKS;
        for (size_t k = k0; k < k1; k++) {
            const double *a = s->x + 3 * m->spring_i[k], *b = s->x + 3 * m->spring_j[k];
            double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
            double stretch = (sqrt(dx * dx + dy * dy + dz * dz) - m->spring_rest[k]) * 1e-3; /* m */
            double stiffness, damping;
            sk__spring_constants(m, k, &stiffness, &damping);
            pe[c] += 0.5 * stiffness * stretch * stretch;
        }
        size_t p0 = s->nfree * (size_t)c / CHUNKS, p1 = s->nfree * (size_t)(c + 1) / CHUNKS;
        for (size_t p = p0; p < p1; p++) {
            sk_vec3d now = sk__sim_carried(s, &s->pose, s->muscle, p);
            sk_vec3d before = sk__sim_carried(s, &s->pose_prev, s->muscle_prev, p);
            sk_vec3d rig = sk_v3d_scale(sk_v3d_sub(now, before), s->step > 0 ? 1.0 / s->h : 0.0);
            sk_vec3d rel = sk_v3d_sub(sk_v3d(s->v[3 * p], s->v[3 * p + 1], s->v[3 * p + 2]), rig);
            ke[c] += 0.5 * m->mass[p] * sk_v3d_dot(rel, rel) * 1e-6; /* (mm/s)^2 -> (m/s)^2 */
        }
    }
    double tp = 0.0, tk = 0.0;
    for (int c = 0; c < CHUNKS; c++) {
        tp += pe[c];
        tk += ke[c];
    }
    *potential_j = tp;
    *kinetic_j = tk;
}
