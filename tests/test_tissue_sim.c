/* Tests of the tissue simulation (Shigemori & Kawai sec. 5, with the decisions of
 * docs/tissue.md): a spring's period and damping ratio are those of its stiffness and
 * mass, nothing moves at rest, a sudden stop overshoots and settles, a steady motion
 * leaves no lag, energy stays bounded under random motion (no NaN), teleports and extreme
 * stiffness stay bounded, no skin point ends inside a bone, and the result does not depend
 * on the output frame rate, the thread count, the vector paths or a save and resume. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "shitsukan/io.h"
#include "shitsukan/pointcache.h"
#include "test_result.h"
#include "test_support.h"
#include "models/tissue/sim_internal.h"
#include "tissue_fixture.h"

static bool sanitized(void) { return getenv("SK_TEST_SANITIZED") != NULL; }

static sk_tissue_sim *make_sim(const sk_tissue_model *m, const sk_tissue_motion *motion)
{
    sk_tissue_sim *s = NULL;
    SK_ASSERT_OK(sk_tissue_sim_create(m, motion, &s, &e_));
    return s;
}

/* Largest distance of a free point from where the tissue alone carries its rest position. */
static double max_offset(const sk_tissue_sim *s)
{
    double worst = 0.0;
    for (size_t p = 0; p < s->nfree; p++) {
        sk_vec3d q = sk__sim_carried(s, &s->pose, s->muscle, p);
        worst = fmax(worst, sk_v3d_length(sk_v3d_sub(
                                q, sk_v3d(s->x[3 * p], s->x[3 * p + 1], s->x[3 * p + 2]))));
    }
    return worst;
}

/* Mass-weighted mean x offset of the free points from where the tissue carries them. */
static double mean_offset_x(const sk_tissue_sim *s)
{
    double sum = 0.0, mass = 0.0;
    for (size_t p = 0; p < s->nfree; p++) {
        sk_vec3d q = sk__sim_carried(s, &s->pose, s->muscle, p);
        sum += s->m->mass[p] * (s->x[3 * p] - q.x);
        mass += s->m->mass[p];
    }
    return sum / mass;
}

/* ------------------------------------------------------------ one spring */
/* A free point on a spring to a driven point (the simulation's step: prediction, XPBD,
 * velocity from the positions) oscillates with the period 2 pi sqrt(m / k) and decays by
 * the damping ratio it was given (logarithmic decrement). */
static void test_one_spring_period_and_damping(void **state)
{
    (void)state;
    sk_tissue_model *m = calloc(1, sizeof *m);
    const double k = 2.0, mass = 5e-3, zeta = 0.05, h = 1.0 / 480; /* omega h = 0.04 */
    m->point_count = 2;
    m->skin_count = 1;
    m->spring_count = 1;
    m->grid.n[0] = m->grid.n[1] = m->grid.n[2] = 4;
    m->grid.count = 64;
    m->grid.spacing = 10;
    size_t grid_of[2] = {0, 1};
    double masses[2] = {mass, 0.0}, rest = 10.0;
    uint32_t si = 0, sj = 1;
    uint8_t cls = SK__SPRING_ANCHOR;
    m->grid_of = grid_of;
    m->mass = masses;
    m->spring_i = &si;
    m->spring_j = &sj;
    m->spring_rest = &rest;
    m->spring_class = &cls;
    m->desc.material.anchor_stiffness = (float)k;
    m->desc.material.damping_ratio = (float)zeta;
    m->desc.material.tether_stiffness = 1e-4f; /* 5e-5 of k: no visible change */
    sk__solver *solver = NULL;
    SK_ASSERT_OK(sk__solver_xpbd.create(m, h, &solver, &e_));
    double x[6] = {13.0, 0, 0, 0, 0, 0}, base[6], v[3] = {0, 0, 0}; /* stretched by 3 mm */
    const double target[3] = {10.0, 0, 0};
    double prev_d = x[0] - rest, prev_v = 0.0, peaks[8];
    int crossings = 0, npeaks = 0;
    double first_cross = 0, last_cross = 0, t = 0;
    for (int step = 0; step < 2 * 480 && npeaks < 8; step++) {
        memcpy(base, x, sizeof x);
        for (int c = 0; c < 3; c++) x[c] += h * v[c];
        sk__solver_xpbd.step(solver, x, base, target, target);
        for (int c = 0; c < 3; c++) v[c] = (x[c] - base[c]) / h;
        t += h;
        double d = x[0] - rest;
        if (prev_d < 0 && d >= 0) { /* upward zero crossing */
            double tc = t - h * d / (d - prev_d);
            if (crossings == 0) first_cross = tc;
            last_cross = tc;
            crossings++;
        }
        prev_d = d;
        /* an extremum of d when the velocity changes sign */
        if (step > 0 && ((prev_v > 0) != (v[0] > 0))) peaks[npeaks++] = fabs(d);
        prev_v = v[0];
    }
    double period = (last_cross - first_cross) / (crossings - 1),
           expected = 2 * SK_PI * sqrt(mass / k);
    assert_true(crossings >= 3);
    if (fabs(period / expected - 1) > 0.01)
        fail_msg("period %.5f s, expected %.5f s", period, expected);
    /* peaks a period apart: ratio exp(-2 zeta pi / sqrt(1 - zeta^2)) */
    assert_true(npeaks >= 4);
    double ratio = peaks[3] / peaks[1], want = exp(-2 * zeta * SK_PI / sqrt(1 - zeta * zeta));
    if (fabs(ratio / want - 1) > 0.05)
        fail_msg("decay over a period %.4f, expected %.4f", ratio, want);
    sk__solver_xpbd.destroy(solver);
    free(m);
}

/* ------------------------------------------------------------ the rod */
static void test_at_rest_nothing_moves(void **state)
{
    (void)state;
    sk_tissue_model *m = sk_test_rod_model(5.0);
    sk_test_motion mo = {SK_TEST_MOTION_REST, 0, 0, 0, 0};
    sk_tissue_motion motion = sk_test_motion_get(&mo, 1.0);
    sk_tissue_sim *s = make_sim(m, &motion);
    SK_ASSERT_OK(sk_tissue_sim_advance(s, 1.0, &e_));
    double worst = 0.0;
    for (size_t p = 0; p < s->n; p++)
        worst =
            fmax(worst, sk_v3d_length(sk_v3d_sub(
                            m->rest[p], sk_v3d(s->x[3 * p], s->x[3 * p + 1], s->x[3 * p + 2]))));
    if (worst > 1e-9) fail_msg("at rest a point moved %g mm", worst);
    double pe, ke;
    sk_tissue_sim_energy(s, &pe, &ke);
    assert_true(pe < 1e-20 && ke < 1e-20);
    sk_tissue_sim_destroy(s);
    sk_tissue_model_destroy(m);
}

/* The rod moves along x at constant speed and stops dead: while it moves the flesh keeps
 * up (no lag in a steady motion); after the stop it runs on, swings back (overshoot) and
 * settles, with a period no shorter than that of the fat moving as one body on its springs
 * and tethers to the tissue (Rayleigh: that motion's frequency bounds the lowest one from
 * above). */
static void test_sudden_stop_overshoots_and_settles(void **state)
{
    (void)state;
    sk_tissue_model *m = sk_test_rod_model(5.0);
    sk_test_motion mo = {SK_TEST_MOTION_STOP, 300.0, 1.0, 0, 0};
    sk_tissue_motion motion = sk_test_motion_get(&mo, 3.0);
    sk_tissue_sim *s = make_sim(m, &motion);
    SK_ASSERT_OK(sk_tissue_sim_advance(s, 0.95, &e_));
    double steady = mean_offset_x(s);
    SK_ASSERT_OK(sk_tissue_sim_advance(s, 1.0, &e_));
    double first_peak = 0.0, second = 0.0, prev = mean_offset_x(s), t_prev = 1.0;
    double crossings[8];
    int nc = 0;
    for (int k = 1; k <= 480; k++) {
        double t = 1.0 + k / 480.0;
        SK_ASSERT_OK(sk_tissue_sim_advance(s, t, &e_));
        double d = mean_offset_x(s);
        if (nc == 0) first_peak = fmax(first_peak, d);
        if (nc == 1) second = fmin(second, d);
        if ((prev > 0) != (d > 0) && nc < 8)
            crossings[nc++] = t_prev + (t - t_prev) * prev / (prev - d);
        prev = d;
        t_prev = t;
    }
    SK_ASSERT_OK(sk_tissue_sim_advance(s, 3.0, &e_));
    double settled = max_offset(s);
    /* no lag while moving steadily; forward after the stop, then back past rest */
    if (fabs(steady) > 0.02 * first_peak)
        fail_msg("steady lag %g mm (peak %g mm)", steady, first_peak);
    assert_true(first_peak > 0.01);
    assert_true(second < -0.05 * first_peak);
    assert_true(nc >= 3);
    if (settled > 1e-4) fail_msg("2 s after the stop a point is still %g mm off", settled);
    double period = 2.0 * (crossings[2] - crossings[0]) / 2.0;
    /* the fat moving as one body along x stretches its springs to the tissue and its tethers */
    double stiffness = 0.0, mass = 0.0;
    for (size_t p = 0; p < s->nfree; p++) {
        mass += m->mass[p];
        stiffness += m->desc.material.tether_stiffness;
    }
    for (size_t k = 0; k < m->spring_count; k++) {
        if (m->spring_class[k] != SK__SPRING_ANCHOR) continue;
        sk_vec3d d = sk_v3d_sub(m->rest[m->spring_i[k]], m->rest[m->spring_j[k]]);
        double c = d.x / sk_v3d_length(d), kk, damping;
        sk__spring_constants(m, k, &kk, &damping);
        stiffness += kk * c * c;
    }
    double rigid = 2 * SK_PI * sqrt(mass / stiffness);
    if (period < 0.9 * rigid || period > 20 * rigid)
        fail_msg("period %g s, the fat as one body %g s", period, rigid);
    sk_tissue_sim_destroy(s);
    sk_tissue_model_destroy(m);
}

/* The rod bends, moves at random, and comes back to rest: the flesh returns exactly to
 * its rest shape. */
static void test_returns_exactly_to_rest(void **state)
{
    (void)state;
    sk_tissue_model *m = sk_test_rod_model(6.0);
    sk_test_motion mo = {SK_TEST_MOTION_BEND, 0, 0.3, 1.2, 0};
    sk_tissue_motion motion = sk_test_motion_get(&mo, 1.0);
    sk_tissue_sim *s = make_sim(m, &motion);
    SK_ASSERT_OK(sk_tissue_sim_advance(s, 0.6, &e_));
    assert_true(max_offset(s) > 0.1); /* bent: the flesh deforms */
    sk_tissue_sim_destroy(s);
    sk_test_motion rnd = {SK_TEST_MOTION_RANDOM, 0, 0, 0, 11};
    motion = sk_test_motion_get(&rnd, 1.0);
    s = make_sim(m, &motion);
    SK_ASSERT_OK(sk_tissue_sim_advance(s, 0.8, &e_));
    /* switch the motion to the rest pose held still */
    sk_test_motion still = {SK_TEST_MOTION_REST, 0, 0, 0, 0};
    s->motion = sk_test_motion_get(&still, 1.0);
    SK_ASSERT_OK(sk_tissue_sim_advance(s, 3.8, &e_));
    double worst = 0.0;
    for (size_t p = 0; p < s->nfree; p++)
        worst =
            fmax(worst, sk_v3d_length(sk_v3d_sub(
                            m->rest[p], sk_v3d(s->x[3 * p], s->x[3 * p + 1], s->x[3 * p + 2]))));
    if (worst > 1e-6) fail_msg("3 s after the motion a point is %g mm from rest", worst);
    sk_tissue_sim_destroy(s);
    sk_tissue_model_destroy(m);
}

static void test_energy_stays_bounded_under_random_motion(void **state)
{
    (void)state;
    sk_tissue_model *m = sk_test_rod_model(6.0);
    sk_test_motion mo = {SK_TEST_MOTION_RANDOM, 0, 0, 0, 3};
    sk_tissue_motion motion = sk_test_motion_get(&mo, 100.0);
    sk_tissue_sim *s = make_sim(m, &motion);
    int steps = sanitized() ? 2000 : 10000, chunk = 50;
    double early = 0.0, late = 0.0;
    for (int k = chunk; k <= steps; k += chunk) {
        SK_ASSERT_OK(sk_tissue_sim_advance(s, (double)k / s->step_hz, &e_));
        double pe, ke;
        sk_tissue_sim_energy(s, &pe, &ke);
        assert_true(isfinite(pe) && isfinite(ke));
        if (k <= steps / 2)
            early = fmax(early, pe + ke);
        else
            late = fmax(late, pe + ke);
    }
    for (size_t i = 0; i < 3 * s->n; i++) assert_true(isfinite(s->x[i]));
    if (!(late < 3.0 * early))
        fail_msg("energy grew: at most %g J in the first half, %g J in the second", early, late);
    sk_tissue_sim_destroy(s);
    sk_tissue_model_destroy(m);
}

/* No fat or skin point inside a bone, whatever the motion. */
static void check_outside_bones(const sk_tissue_sim *s)
{
    for (int b = 0; b < s->m->desc.bone_count; b++)
        for (int k = 0; k < 3; k++) {
            const sk__ellipsoid *e = &s->obstacles[b].part[k].e;
            for (size_t p = 0; p < s->nfree; p++)
                if (sk__ellipsoid_level(e, sk_v3d(s->x[3 * p], s->x[3 * p + 1], s->x[3 * p + 2])) <
                    1.0 - 1e-9)
                    fail_msg("point %zu is inside bone %d", p, b);
        }
}

static void test_no_skin_point_inside_a_bone(void **state)
{
    (void)state;
    sk_tissue_model *m = sk_test_rod_model(6.0);
    sk_test_motion mo = {SK_TEST_MOTION_RANDOM, 0, 0, 0, 5};
    sk_tissue_motion motion = sk_test_motion_get(&mo, 10.0);
    sk_tissue_sim *s = make_sim(m, &motion);
    for (int k = 1; k <= (sanitized() ? 60 : 240); k++) {
        SK_ASSERT_OK(sk_tissue_sim_advance(s, k * 10.0 / s->step_hz, &e_));
        check_outside_bones(s);
    }
    sk_tissue_sim_destroy(s);
    sk_tissue_model_destroy(m);
}

/* A bone that jumps carries its flesh (nothing is flung); with the guard off the flesh is
 * flung but stays bounded and settles; stiffness at the ends of the documented range stays
 * finite and bounded. */
static void test_teleports_and_extreme_stiffness_stay_bounded(void **state)
{
    (void)state;
    sk_tissue_model *m = sk_test_rod_model(6.0);
    sk_test_motion mo = {SK_TEST_MOTION_TELEPORT, 800.0, 0.2, 0, 0};
    sk_tissue_motion motion = sk_test_motion_get(&mo, 2.0);
    sk_tissue_sim *s = make_sim(m, &motion);
    SK_ASSERT_OK(sk_tissue_sim_advance(s, 0.3, &e_));
    if (max_offset(s) > 1e-6) fail_msg("a teleport flung the flesh %g mm", max_offset(s));
    check_outside_bones(s);
    sk_tissue_sim_destroy(s);
    sk_tissue_model_destroy(m);

    sk_tissue_character_desc *d = sk_test_rod_desc(6.0);
    d->simulation.teleport_speed_m_s = 1e6; /* no guard: an 800 mm jump stretches every spring */
    sk_tissue_model *raw = NULL;
    SK_ASSERT_OK(sk_tissue_model_build(d, NULL, &raw, &e_));
    s = make_sim(raw, &motion);
    double worst = 0.0;
    for (int k = 1; k <= 40; k++) {
        SK_ASSERT_OK(sk_tissue_sim_advance(s, 0.2 + k * 0.02, &e_));
        worst = fmax(worst, max_offset(s));
        for (size_t i = 0; i < 3 * s->n; i++) assert_true(isfinite(s->x[i]));
    }
    assert_true(worst > 1.0 && worst < 2000.0);
    check_outside_bones(s);
    sk_tissue_sim_destroy(s);
    sk_tissue_model_destroy(raw);

    const float stiffness[2] = {1e-3f, 1e6f};
    sk_test_motion rnd = {SK_TEST_MOTION_RANDOM, 0, 0, 0, 9};
    motion = sk_test_motion_get(&rnd, 2.0);
    for (int i = 0; i < 2; i++) {
        d->simulation.teleport_speed_m_s = 0;
        d->material.fat_stiffness = d->material.skin_stiffness = d->material.anchor_stiffness =
            stiffness[i];
        sk_tissue_character_desc_resolve(d);
        sk_tissue_model *mk = NULL;
        SK_ASSERT_OK(sk_tissue_model_build(d, NULL, &mk, &e_));
        s = make_sim(mk, &motion);
        SK_ASSERT_OK(sk_tissue_sim_advance(s, sanitized() ? 0.2 : 0.8, &e_));
        for (size_t k = 0; k < 3 * s->n; k++) assert_true(isfinite(s->x[k]));
        double off = max_offset(s);
        if (!(off < 500.0)) fail_msg("stiffness %g N/m: the flesh is %g mm off", stiffness[i], off);
        sk_tissue_sim_destroy(s);
        sk_tissue_model_destroy(mk);
    }
    free(d);
}

/* ------------------------------------------------------------ sampling */
static float *skin_at(sk_tissue_sim *s, double t)
{
    float *xyz = malloc(3 * s->m->skin_count * sizeof *xyz);
    SK_ASSERT_OK(sk_tissue_sim_skin(s, t, xyz, &e_));
    return xyz;
}

/* The skin at the instants 24, 30 and 60 fps share (every 1/6 s) is the same bits. */
static void test_frame_rate_independence(void **state)
{
    (void)state;
    sk_tissue_model *m = sk_test_rod_model(6.0);
    sk_test_motion mo = {SK_TEST_MOTION_RANDOM, 0, 0, 0, 21};
    sk_tissue_motion motion = sk_test_motion_get(&mo, 1.0);
    const int rates[3] = {24, 30, 60};
    float *shared[3][7];
    for (int r = 0; r < 3; r++) {
        sk_tissue_sim *s = make_sim(m, &motion);
        for (int f = 0; f <= rates[r]; f++) {
            float *xyz = skin_at(s, (double)f / rates[r]);
            if (f % (rates[r] / 6) == 0)
                shared[r][f / (rates[r] / 6)] = xyz;
            else
                free(xyz);
        }
        sk_tissue_sim_destroy(s);
    }
    size_t bytes = 3 * m->skin_count * sizeof(float);
    for (int k = 0; k < 7; k++) {
        assert_memory_equal(shared[0][k], shared[1][k], bytes);
        assert_memory_equal(shared[0][k], shared[2][k], bytes);
        for (int r = 0; r < 3; r++) free(shared[r][k]);
    }
    /* a time between steps blends the two steps around it */
    sk_tissue_sim *s = make_sim(m, &motion);
    float *a = skin_at(s, 10.0 / 480), *mid = skin_at(s, 10.5 / 480);
    SK_ASSERT_OK(sk_tissue_sim_advance(s, 11.0 / 480, &e_));
    float *b = malloc(bytes);
    SK_ASSERT_OK(sk_tissue_sim_skin(s, 11.0 / 480, b, &e_));
    for (size_t i = 0; i < 3 * m->skin_count; i++)
        assert_true(fabsf(mid[i] - 0.5f * (a[i] + b[i])) < 1e-3f);
    sk_error err = {0};
    sk_test_expect_failure(sk_tissue_sim_skin(s, 1.0 / 480, b, &err), &err,
                           SK_ERROR_INVALID_ARGUMENT, "before the last two steps");
    free(a);
    free(mid);
    free(b);
    sk_tissue_sim_destroy(s);
    sk_tissue_model_destroy(m);
}

/* The same run with one thread and with two gives the same bits. */
static void test_thread_count_independence(void **state)
{
    (void)state;
    sk_tissue_model *m = sk_test_rod_model(5.0);
    sk_test_motion mo = {SK_TEST_MOTION_RANDOM, 0, 0, 0, 4};
    sk_tissue_motion motion = sk_test_motion_get(&mo, 1.0);
    /* 1, 2 and 3 threads: each thread solves its own run of slabs (an uneven split too) */
    float *out[3];
    for (int i = 0; i < 3; i++) {
        sk_threads_set(i + 1);
        sk_tissue_sim *s = make_sim(m, &motion);
        s->parallel_points = 0; /* the small model on every thread, as a large one runs */
        out[i] = skin_at(s, 0.3);
        sk_tissue_sim_destroy(s);
    }
    sk_threads_set(0);
    for (int i = 1; i < 3; i++) {
        assert_memory_equal(out[0], out[i], 3 * m->skin_count * sizeof(float));
        free(out[i]);
    }
    free(out[0]);
    sk_tissue_model_destroy(m);
}

/* A model machine for the thread choice's clock: a step costs 1 s on one thread and, on
 * two, 0.5 s until step `busy_from` and 3 s from there on (another job took a core: the
 * threads wait for each other at every barrier). The clock adds the cost of the steps run
 * since its last reading, on the threads the simulation was running them on. */
static const sk_tissue_sim *clock_sim;
static int64_t clock_step, busy_from;
static double clock_now;
static int clock_calls;
static double model_clock(void)
{
    const sk_tissue_sim *s = clock_sim;
    bool two = s->probe_phase == 2 || (s->probe_phase == 0 && s->threads > 1);
    for (; clock_step < s->step; clock_step++)
        clock_now += !two ? 1.0 : clock_step < busy_from ? 0.5 : 3.0;
    clock_calls++;
    return clock_now;
}

/* The thread choice (sim.c): a few steps timed on one thread and on two keep the faster,
 * timed over several calls when a call is fewer steps (a frame: 8 steps at 240 steps/s and
 * 30 fps); on two threads every run is timed, and one much slower than one thread's steps
 * makes the choice again at once. On the model machine, two threads win the first choice
 * and keep it while the machine is quiet; once it is busy one thread is chosen within a few
 * frames. The steps are the same bits as one thread's. */
static void test_thread_choice_follows_the_machine(void **state)
{
    (void)state;
    sk_tissue_model *m = sk_test_rod_model(5.0);
    sk_test_motion mo = {SK_TEST_MOTION_RANDOM, 0, 0, 0, 4};
    sk_tissue_motion motion = sk_test_motion_get(&mo, 1.0);
    sk_threads_set(2);
    sk_tissue_sim *s = make_sim(m, &motion);
    s->parallel_points = 0;
    int64_t start = s->step;
    clock_sim = s, clock_step = start, busy_from = start + 100, clock_now = 0.0, clock_calls = 0;
    s->clock = model_clock;
    for (int64_t k = start + 8; k <= start + 96; k += 8) {
        SK_ASSERT_OK(sk_tissue_sim_advance(s, (double)k / s->step_hz, &e_));
        assert_int_equal(s->step, k);
        /* the first choice took 12 steps on one thread and 12 on two, over three frames */
        if (k >= start + 24)
            assert_int_equal(s->threads, 2), assert_int_equal(s->probe_phase, 0);
        else
            assert_int_not_equal(s->probe_phase, 0);
    }
    assert_float_equal(s->one_thread_step_s, 1.0, 1e-12);
    assert_int_equal(s->next_probe, start + 24 + 1200);
    for (int64_t k = start + 104; k <= start + 160; k += 8)
        SK_ASSERT_OK(sk_tissue_sim_advance(s, (double)k / s->step_hz, &e_));
    /* busy from step 100: the run of steps 96-104 is slow, the choice runs again over
       steps 104-128 and keeps one thread, with no clock until the next choice */
    assert_int_equal(s->threads, 1);
    assert_int_equal(s->next_probe, start + 128 + 1200);
    int calls = clock_calls;
    SK_ASSERT_OK(sk_tissue_sim_advance(s, (double)(start + 400) / s->step_hz, &e_));
    assert_int_equal(clock_calls, calls);
    s->clock = sk_time_seconds;
    double t = (double)(start + 480) / s->step_hz;
    float *chosen = skin_at(s, t);
    sk_tissue_sim_destroy(s);
    sk_threads_set(1);
    s = make_sim(m, &motion);
    float *one = skin_at(s, t);
    sk_tissue_sim_destroy(s);
    sk_threads_set(0);
    assert_memory_equal(chosen, one, 3 * m->skin_count * sizeof(float));
    free(chosen), free(one);
    sk_tissue_model_destroy(m);
}

/* The vector paths (AVX2 springs four at a time on packed points, the collisions' test of
 * four points at once) give the same bits as the scalar code, with the bones and the muscle
 * pushing flesh out (a fast random motion), on one thread and on two. Where the processor
 * has no AVX2 both runs take the scalar code. */
static void test_vector_paths_give_the_same_bits(void **state)
{
    (void)state;
    sk_tissue_model *m = sk_test_rod_model(5.0);
    sk_test_motion mo = {SK_TEST_MOTION_RANDOM, 0, 0, 0, 11};
    sk_tissue_motion motion = sk_test_motion_get(&mo, 1.0);
    for (int threads = 1; threads <= 2; threads++) {
        sk_threads_set(threads);
        double *out[2]; /* every free point's position in double (no rounding to float) */
        size_t bytes = 0;
        for (int vectors = 0; vectors < 2; vectors++) {
            sk_tissue_sim *s = make_sim(m, &motion);
            s->parallel_points = 0;
            sk__sim_use_vectors(s, vectors == 1);
            SK_ASSERT_OK(sk_tissue_sim_advance(s, 0.4, &e_));
            bytes = 3 * s->nfree * sizeof(double);
            out[vectors] = malloc(bytes);
            memcpy(out[vectors], s->x, bytes);
            sk_tissue_sim_destroy(s);
        }
        assert_memory_equal(out[0], out[1], bytes);
        free(out[0]), free(out[1]);
    }
    sk_threads_set(0);
    sk_tissue_model_destroy(m);
}

/* A baked run (sk_tissue_run's point cache) equals a live run frame by frame and a run
 * resumed from a saved state. */
static void test_bake_equals_live_equals_resumed(void **state)
{
    (void)state;
    sk_tissue_model *m = sk_test_rod_model(6.0);
    sk_test_motion mo = {SK_TEST_MOTION_RANDOM, 0, 0, 0, 8};
    sk_tissue_motion motion = sk_test_motion_get(&mo, 1.0);
    const char *dir = sk_test_path("tissue-bake/full");
    sk_tissue_run_desc d = {0};
    d.output_dir = dir;
    d.fps = 30;
    d.last_frame = 24;
    d.no_glb = true;
    SK_ASSERT_OK(sk_tissue_run(m, &motion, &d, NULL, &e_));
    char path[1024];
    snprintf(path, sizeof path, "%s/skin.pc2", dir);
    sk_pc2 baked;
    SK_ASSERT_OK(sk_pc2_read(path, 0, &baked, &e_));
    assert_int_equal(baked.samples, 25);
    assert_int_equal(baked.points, (int)m->skin_count);
    size_t frame = 3 * m->skin_count;
    /* live */
    sk_tissue_sim *s = make_sim(m, &motion);
    for (int f = 0; f <= 24; f++) {
        float *xyz = skin_at(s, f / 30.0);
        if (memcmp(xyz, baked.xyz + (size_t)f * frame, frame * sizeof(float)) != 0)
            fail_msg("frame %d: baked != live", f);
        free(xyz);
    }
    sk_tissue_sim_destroy(s);
    /* resumed: frames 0..12 saving the state, then 12..24 from it */
    const char *first = sk_test_path("tissue-bake/first"),
               *second = sk_test_path("tissue-bake/second");
    const char *state_path = sk_test_path("tissue-bake/state.bin");
    d.output_dir = first;
    d.last_frame = 12;
    d.save_state = state_path;
    SK_ASSERT_OK(sk_tissue_run(m, &motion, &d, NULL, &e_));
    d.output_dir = second;
    d.first_frame = 12;
    d.last_frame = 24;
    d.save_state = NULL;
    d.resume_state = state_path;
    SK_ASSERT_OK(sk_tissue_run(m, &motion, &d, NULL, &e_));
    snprintf(path, sizeof path, "%s/skin.pc2", second);
    sk_pc2 resumed;
    SK_ASSERT_OK(sk_pc2_read(path, 0, &resumed, &e_));
    assert_int_equal(resumed.samples, 13);
    assert_true(resumed.start_frame == 12.0f);
    assert_memory_equal(resumed.xyz, baked.xyz + 12 * frame, 13 * frame * sizeof(float));
    /* a state from another character is refused */
    sk_tissue_model *other = sk_test_rod_model(5.0);
    s = make_sim(other, &motion);
    sk_error err = {0};
    sk_test_expect_failure(sk_tissue_sim_load_state_file(s, state_path, &err), &err,
                           SK_ERROR_INVALID_ARGUMENT, "belongs to another character");
    sk_tissue_sim_destroy(s);
    sk_tissue_model_destroy(other);
    /* a state at a step the simulation cannot go on from (beyond 1e7 s) is refused, the
       last one it can is taken (fuzz_tissue_state loaded 2.7e8 s, then could not step) */
    uint8_t *bytes = NULL;
    size_t size = 0;
    SK_ASSERT_OK(sk_read_file(state_path, 0, (char **)&bytes, &size, &e_));
    uint32_t hz;
    memcpy(&hz, bytes + 12, 4);
    s = make_sim(m, &motion);
    int64_t step = (int64_t)1e7 * hz + 1;
    memcpy(bytes + 24, &step, 8);
    sk_test_expect_failure(sk_tissue_sim_load_state(s, bytes, size, &err), &err, SK_ERROR_PARSE,
                           "is not a step count in [0,");
    step -= 1;
    memcpy(bytes + 24, &step, 8);
    SK_ASSERT_OK(sk_tissue_sim_load_state(s, bytes, size, &e_));
    assert_true(sk_tissue_sim_time(s) == 1e7);
    sk_tissue_sim_destroy(s);
    free(bytes);
    sk_pc2_free(&baked);
    sk_pc2_free(&resumed);
    sk_tissue_model_destroy(m);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_one_spring_period_and_damping),
        cmocka_unit_test(test_at_rest_nothing_moves),
        cmocka_unit_test(test_sudden_stop_overshoots_and_settles),
        cmocka_unit_test(test_returns_exactly_to_rest),
        cmocka_unit_test(test_energy_stays_bounded_under_random_motion),
        cmocka_unit_test(test_no_skin_point_inside_a_bone),
        cmocka_unit_test(test_teleports_and_extreme_stiffness_stay_bounded),
        cmocka_unit_test(test_frame_rate_independence),
        cmocka_unit_test(test_thread_count_independence),
        cmocka_unit_test(test_thread_choice_follows_the_machine),
        cmocka_unit_test(test_vector_paths_give_the_same_bits),
        cmocka_unit_test(test_bake_equals_live_equals_resumed),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
