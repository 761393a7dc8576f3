/* Benchmarks of the hand posture model (thesis 3.2): the equilibrium solve (3.17) with a
 * cached Cholesky factorisation, a full pose update (solve + forward kinematics of every
 * joint), and the iterative solve with lookup-table potentials (3.2.3). Medians over
 * many poses. Targets: 5 us, 20 us, 200 us. Also the stick-figure picture's drawing time,
 * and the calibrated potential of the shipped synthetic recordings (fit and blended solve). */
#include <stdio.h>
#include <stdlib.h>

#include "shitsukan/hand.h"

#define POSES 4000

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

static double median_us(double *t, int n)
{
    qsort(t, (size_t)n, sizeof *t, cmp_double);
    return t[n / 2] * 1e6;
}

static void fail(const sk_error *err)
{
    fprintf(stderr, "bench_hand: %s\n", err->message);
    exit(1);
}

/* Slider-like inputs: the little finger's MCP pinned at a new angle each pose, small
 * torques on two other fingers. */
static void make_input(sk_hand_input *in, int pose)
{
    sk_rng rng = sk_rng_make(17, (uint64_t)pose, 0, 0);
    *in = (sk_hand_input){0};
    int l = sk_hand_dof_find("L.MCP.flex");
    in->pinned[l] = true;
    in->pin_value[l] = sk_rng_range(&rng, 0.0, 1.5);
    in->torque[sk_hand_dof_find("I.PIP.flex")] = sk_rng_range(&rng, -0.2, 0.6);
    in->torque[sk_hand_dof_find("T.MCP.flex")] = sk_rng_range(&rng, -0.1, 0.4);
}

int main(void)
{
    sk_error err;
    sk_hand_skeleton skel;
    sk_hand_skeleton_desc sd = {0};
    if (sk_hand_skeleton_init(&skel, &sd, &err) != SK_OK) fail(&err);
    static sk_hand_constraints c;
    if (sk_hand_constraints_load_file(SK_BENCH_PRESET_DIR "/hand/natural.json", &skel, &c, &err) !=
        SK_OK)
        fail(&err);
    sk_hand_solver *solver;
    if (sk_hand_solver_create(&solver, &skel, &c, NULL, 0, NULL, &err) != SK_OK) fail(&err);
    static double t_solve[POSES], t_pose[POSES], t_lut[POSES];
    double q[SK_HAND_DOF_COUNT];
    sk_hand_frames frames;
    sk_hand_input in;
    double checksum = 0.0;
    /* warm the factorisation cache */
    make_input(&in, 0);
    if (sk_hand_solve(solver, &in, q, NULL, &err) != SK_OK) fail(&err);
    for (int p = 0; p < POSES; p++) {
        make_input(&in, p);
        double t0 = sk_time_seconds();
        if (sk_hand_solve(solver, &in, q, NULL, &err) != SK_OK) fail(&err);
        double t1 = sk_time_seconds();
        sk_hand_forward(&skel, q, &frames);
        double t2 = sk_time_seconds();
        t_solve[p] = t1 - t0;
        t_pose[p] = t2 - t0;
        checksum += frames.point[24].z;
    }

    /* lookup tables for two pairs from synthetic curved samples (Fig. 3.11-like) */
    enum { N = 600 };
    static double xs[N], ys[N], us[N], vs[N];
    for (int i = 0; i < N; i++) {
        double t = (double)i / (N - 1);
        xs[i] = (10 + 70 * t) * SK_DEG_TO_RAD;
        ys[i] = (15 + 80 * t * t) * SK_DEG_TO_RAD;
        us[i] = (5 + 80 * t) * SK_DEG_TO_RAD;
        vs[i] = (10 + 70 * t + 10 * t * (1 - t)) * SK_DEG_TO_RAD;
    }
    sk_hand_lut luts[2];
    double tb0 = sk_time_seconds();
    if (sk_hand_lut_build(&luts[0], sk_hand_dof_find("I.MCP.flex"), sk_hand_dof_find("I.PIP.flex"),
                          xs, ys, N, NULL, &err) != SK_OK ||
        sk_hand_lut_build(&luts[1], sk_hand_dof_find("L.MCP.flex"), sk_hand_dof_find("R.MCP.flex"),
                          us, vs, N, NULL, &err) != SK_OK)
        fail(&err);
    double build_ms = (sk_time_seconds() - tb0) * 1e3 / 2.0;
    sk_hand_solver *lsolver;
    if (sk_hand_solver_create(&lsolver, &skel, &c, luts, 2, NULL, &err) != SK_OK) fail(&err);
    int converged = 0;
    long iterations = 0;
    double worst_residual = 0.0;
    for (int p = 0; p < POSES; p++) {
        make_input(&in, p);
        sk_hand_solve_info info;
        double t0 = sk_time_seconds();
        if (sk_hand_solve(lsolver, &in, q, &info, &err) != SK_OK) fail(&err);
        t_lut[p] = sk_time_seconds() - t0;
        converged += info.converged;
        iterations += info.newton_iterations;
        if (info.residual > worst_residual) worst_residual = info.residual;
        checksum += q[5];
    }
    printf("hand: equilibrium solve (3.17), cached Cholesky, 35 DOF, %d rows: median %.2f us "
           "(target 5)\n",
           c.row_count, median_us(t_solve, POSES));
    printf("hand: full pose update (solve + forward kinematics of 25 points): median %.2f us "
           "(target 20)\n",
           median_us(t_pose, POSES));
    printf("hand: iterative solve with 2 lookup tables (100x100) + linear rows: median %.2f us "
           "(target 200); "
           "%d/%d converged to 1e-6, mean %.1f Newton steps, worst residual %.2g\n",
           median_us(t_lut, POSES), converged, POSES, (double)iterations / POSES, worst_residual);
    printf("hand: lookup table build from %d samples: %.2f ms per pair\n", N, build_ms);

    /* stick figures: the default two-view 800 x 480 picture from a layout fitted once */
    enum { DRAWS = 200 };
    static double t_draw[DRAWS];
    sk_hand_relaxed(&skel, q);
    sk_hand_draw_layout layout;
    if (sk_hand_draw_layout_fit(&skel, q, 1, NULL, &layout, &err) != SK_OK) fail(&err);
    for (int p = 0; p < DRAWS; p++) {
        make_input(&in, p);
        if (sk_hand_solve(solver, &in, q, NULL, &err) != SK_OK) fail(&err);
        sk_image img;
        double t0 = sk_time_seconds();
        if (sk_hand_draw(&skel, q, NULL, &layout, &img, &err) != SK_OK) fail(&err);
        t_draw[p] = sk_time_seconds() - t0;
        checksum += img.data[(size_t)img.width * 3 * (img.height / 2)];
        sk_image_free(&img);
    }
    printf("hand: stick figure, 2 views, 800 x 480 (sk_hand_draw): median %.2f ms\n",
           median_us(t_draw, DRAWS) / 1e3);
    /* the calibrated potential of the shipped synthetic recordings: fit, and slider
       solves blended over its mixture components */
    sk_hand_samples samples;
    sk_hand_samples_desc read_desc = {.group_column = "person", .ignore_columns = "trial"};
    if (sk_hand_samples_read(SK_BENCH_PRESET_DIR "/hand/samples/synthetic-grasps.csv", &read_desc,
                             &samples, &err) != SK_OK)
        fail(&err);
    sk_hand_potential pot;
    sk_hand_potential_desc pd = {.base = &c, .seed = 1};
    double tf0 = sk_time_seconds();
    if (sk_hand_potential_fit(&pot, &skel, &samples, NULL, 0, &pd, &err) != SK_OK) fail(&err);
    double fit_s = sk_time_seconds() - tf0;
    sk_hand_potential_solver *ps;
    if (sk_hand_potential_solver_create(&ps, &skel, &pot, NULL, &err) != SK_OK) fail(&err);
    static double t_pot[POSES];
    for (int p = 0; p < POSES; p++) {
        sk_hand_input pin = {0};
        int d = sk_hand_dof_find("I.MCP.flex");
        pin.pinned[d] = true;
        pin.pin_value[d] = samples.column[d][(p * 7) % samples.count];
        double t0 = sk_time_seconds();
        if (sk_hand_potential_solve(ps, &pin, q, NULL, NULL, &err) != SK_OK) fail(&err);
        t_pot[p] = sk_time_seconds() - t0;
        checksum += q[16];
    }
    printf(
        "hand: calibrated potential from %d samples (%d DOFs, %d components chosen): fit %.2f s; "
        "solve with one pin, blended over the components: median %.2f us\n",
        samples.count, pot.dof_count, pot.component_count, fit_s, median_us(t_pot, POSES));
    sk_hand_potential_solver_destroy(ps);
    sk_hand_potential_free(&pot);
    sk_hand_samples_free(&samples);
    printf("hand: (checksum %.6f)\n", checksum);
    sk_hand_solver_destroy(lsolver);
    sk_hand_solver_destroy(solver);
    sk_hand_lut_free(&luts[0]);
    sk_hand_lut_free(&luts[1]);
    return 0;
}
