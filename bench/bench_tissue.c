/* Benchmarks of the fat model (Shigemori & Kawai): skin generation (voxels, distance,
 * dilation, isosurface, classification, springs) for the arm at 2 mm and the full body at
 * 5 mm (targets 1 s and 3 s); the simulation of a character of about 20,000 fat and skin
 * points (target 120 simulated 60 fps frames per second on 2 cores), its springs per
 * second, and in the same run a plain explicit mass-spring step over the same springs and
 * one solve of the prefactored matrix of implicit Euler (projective dynamics, CHOLMOD)
 * for comparison; and the whole `shitsukan tissue run` command as a user runs it. Best of
 * several runs; the load average is printed beside (the machine may be shared), and the
 * CPU time beside the wall time (on a shared machine the wall time is inflated by the
 * other work; the CPU time is what the work itself cost). */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <time.h>

#include "bench_load.h"
#include "shitsukan/preset.h"
#include "models/tissue/sim_internal.h"
#ifdef SK_BENCH_CHOLMOD
#include <suitesparse/cholmod.h>
#endif

static void fail(const sk_error *err)
{
    fprintf(stderr, "bench_tissue: %s\n", err->message);
    exit(1);
}

static void load_average(void)
{
    char buf[128];
    bench_load_average(buf, sizeof buf);
    printf("load average: %s (on %d cores)\n", buf, omp_get_num_procs());
}

static sk_tissue_character_desc *character(const char *name, double spacing)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/tissue/%s.json", SK_BENCH_PRESET_DIR, name);
    sk_tissue_character_desc *d = malloc(sizeof *d);
    sk_error err = {0};
    if (sk_tissue_character_load(path, d, &err) != SK_OK) fail(&err);
    if (spacing > 0) {
        /* the same shape at another spacing: the dilation keeps its reach in mm */
        d->skin.spacing_mm = (float)spacing;
    }
    return d;
}

/* CPU seconds of a clock (CLOCK_PROCESS_CPUTIME_ID: every thread of the process,
   CLOCK_THREAD_CPUTIME_ID: the calling thread). */
static double cpu_seconds(clockid_t clock)
{
    struct timespec t;
    clock_gettime(clock, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* CPU seconds of the finished child processes. */
static double children_cpu_seconds(void)
{
    struct rusage u;
    getrusage(RUSAGE_CHILDREN, &u);
    return (double)u.ru_utime.tv_sec + 1e-6 * (double)u.ru_utime.tv_usec +
           (double)u.ru_stime.tv_sec + 1e-6 * (double)u.ru_stime.tv_usec;
}

/* ------------------------------------------------------------ skin generation */
static void bench_skin(const char *name, double spacing, double target)
{
    sk_tissue_character_desc *d = character(name, spacing);
    sk_tissue_model_stats best = {0};
    double best_cpu = 0.0;
    for (int run = 0; run < 3; run++) {
        sk_tissue_model *m = NULL;
        sk_error err = {0};
        double c0 = cpu_seconds(CLOCK_PROCESS_CPUTIME_ID);
        if (sk_tissue_model_build(d, NULL, &m, &err) != SK_OK) fail(&err);
        double cpu = cpu_seconds(CLOCK_PROCESS_CPUTIME_ID) - c0;
        sk_tissue_model_stats s = sk_tissue_model_get_stats(m);
        if (run == 0 || s.seconds_total < best.seconds_total) best = s;
        if (run == 0 || cpu < best_cpu) best_cpu = cpu;
        sk_tissue_model_destroy(m);
    }
    printf(
        "skin generation, %s at %g mm: grid %d x %d x %d, %zu skin + %zu fat points, %zu springs\n",
        name, spacing, best.grid[0], best.grid[1], best.grid[2], best.skin_points, best.fat_points,
        best.springs);
    printf("  CPU %.3f s (every thread)\n", best_cpu);
    printf("  wall %.3f s (target %.0f s): voxelise %.3f, fat regions %.3f, dilate %.3f, "
           "isosurface %.3f, classify %.3f, "
           "springs %.3f\n",
           best.seconds_total, target, best.seconds_voxelise, best.seconds_fat, best.seconds_dilate,
           best.seconds_extract, best.seconds_classify, best.seconds_springs);
    free(d);
}

/* ------------------------------------------------------------ simulation */
static void still(void *user, double t, sk_quatd *local, sk_vec3d *root)
{
    (void)user;
    /* an arm that swings at the shoulder and bends at the elbow, never still */
    local[0] = sk_qd_axis_angle(sk_v3d(1, 0, 0), -0.6 * sin(2 * SK_PI * 0.7 * t));
    local[1] = sk_qd_axis_angle(sk_v3d(1, 0, 0), -1.0 - 0.9 * sin(2 * SK_PI * 1.3 * t));
    *root = sk_v3d(0, 0, 0);
}

typedef struct sim_figures {
    double steps_per_second, solver_seconds_per_step;
    double cpu_per_step;        /* CPU seconds of every thread per whole step */
    double solver_cpu_per_step; /* the spring solver alone: the busiest thread's CPU seconds */
} sim_figures;

static sim_figures bench_sim(const sk_tissue_model *m, int threads, int steps)
{
    sk_tissue_motion motion = {still, NULL, 100.0};
    sim_figures best = {0};
    sk_threads_set(threads);
    for (int run = 0; run < 3; run++) {
        sk_tissue_sim *s = NULL;
        sk_error err = {0};
        if (sk_tissue_sim_create(m, &motion, &s, &err) != SK_OK) fail(&err);
        s->parallel_points = threads > 1 ? 0 : s->parallel_points;
        double c0 = cpu_seconds(CLOCK_PROCESS_CPUTIME_ID), t0 = sk_time_seconds();
        if (sk_tissue_sim_advance(s, (double)steps / s->step_hz, &err) != SK_OK) fail(&err);
        double t1 = sk_time_seconds(), cpu = (cpu_seconds(CLOCK_PROCESS_CPUTIME_ID) - c0) / steps;
        /* the spring solver alone, on the same state, on `threads` threads (the busiest
           thread's CPU time: the wall time of an idle machine but for the waits) */
        int reps = steps / 4;
        double busiest = 0.0;
        double t2 = sk_time_seconds();
#pragma omp parallel num_threads(threads)
        {
            double own = cpu_seconds(CLOCK_THREAD_CPUTIME_ID);
            for (int k = 0; k < reps; k++)
                s->ops->step(s->solver, s->x, s->base, s->target, s->target_base);
            own = cpu_seconds(CLOCK_THREAD_CPUTIME_ID) - own;
#pragma omp critical(bench_busiest)
            busiest = fmax(busiest, own);
        }
        double t3 = sk_time_seconds();
        double sps = steps / (t1 - t0);
        if (sps > best.steps_per_second) best.steps_per_second = sps;
        if (run == 0 || cpu < best.cpu_per_step) best.cpu_per_step = cpu;
        double solver = (t3 - t2) / reps;
        if (run == 0 || solver < best.solver_seconds_per_step)
            best.solver_seconds_per_step = solver;
        if (run == 0 || busiest / reps < best.solver_cpu_per_step)
            best.solver_cpu_per_step = busiest / reps;
        sk_tissue_sim_destroy(s);
    }
    sk_threads_set(0);
    return best;
}

/* A plain explicit mass-spring step over the same springs: spring forces (Hooke and a
 * dashpot along the spring) gathered per point, then symplectic Euler. */
typedef struct explicit_system {
    size_t n, nfree;
    size_t *start; /* CSR of each free point's springs */
    uint32_t *other;
    double *k, *c, *rest;
    double *x, *v, *inv_m;
} explicit_system;

static explicit_system make_explicit(const sk_tissue_model *m)
{
    explicit_system e = {0};
    e.n = m->point_count;
    e.nfree = m->skin_count + m->fat_count;
    e.start = calloc(e.nfree + 1, sizeof *e.start);
    for (size_t s = 0; s < m->spring_count; s++) {
        if (m->spring_i[s] < e.nfree) e.start[m->spring_i[s] + 1]++;
        if (m->spring_j[s] < e.nfree) e.start[m->spring_j[s] + 1]++;
    }
    for (size_t p = 0; p < e.nfree; p++) e.start[p + 1] += e.start[p];
    size_t total = e.start[e.nfree];
    e.other = malloc(total * sizeof *e.other);
    e.k = malloc(total * sizeof *e.k);
    e.c = malloc(total * sizeof *e.c);
    e.rest = malloc(total * sizeof *e.rest);
    size_t *fill = malloc(e.nfree * sizeof *fill);
    memcpy(fill, e.start, e.nfree * sizeof *fill);
    for (size_t s = 0; s < m->spring_count; s++) {
        double k, c;
        sk__spring_constants(m, s, &k, &c);
        uint32_t ends[2] = {m->spring_i[s], m->spring_j[s]};
        for (int a = 0; a < 2; a++) {
            if (ends[a] >= e.nfree) continue;
            size_t o = fill[ends[a]]++;
            e.other[o] = ends[1 - a];
            e.k[o] = k;
            e.c[o] = c;
            e.rest[o] = m->spring_rest[s];
        }
    }
    free(fill);
    e.x = malloc(3 * e.n * sizeof *e.x);
    e.v = calloc(3 * e.n, sizeof *e.v);
    e.inv_m = malloc(e.nfree * sizeof *e.inv_m);
    for (size_t p = 0; p < e.n; p++) {
        e.x[3 * p] = m->rest[p].x + 0.1 * sin((double)p);
        e.x[3 * p + 1] = m->rest[p].y;
        e.x[3 * p + 2] = m->rest[p].z;
    }
    for (size_t p = 0; p < e.nfree; p++) e.inv_m[p] = 1.0 / m->mass[p];
    return e;
}

static void explicit_step(explicit_system *e, double h, double *a)
{
#pragma omp for schedule(static)
    for (size_t p = 0; p < e->nfree; p++) {
        double f[3] = {0, 0, 0};
        const double *xp = e->x + 3 * p, *vp = e->v + 3 * p;
        for (size_t o = e->start[p]; o < e->start[p + 1]; o++) {
            const double *xq = e->x + 3 * e->other[o], *vq = e->v + 3 * e->other[o];
            double d[3] = {xq[0] - xp[0], xq[1] - xp[1], xq[2] - xp[2]};
            double len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]), inv = 1.0 / len;
            double rel =
                ((vq[0] - vp[0]) * d[0] + (vq[1] - vp[1]) * d[1] + (vq[2] - vp[2]) * d[2]) * inv;
            double mag =
                e->k[o] * (len - e->rest[o]) + e->c[o] * rel; /* mm and mm/s with N/m: mN */
            for (int c = 0; c < 3; c++) f[c] += mag * d[c] * inv;
        }
        for (int c = 0; c < 3; c++) a[3 * p + (size_t)c] = f[c] * e->inv_m[p];
    }
#pragma omp for schedule(static)
    for (size_t i = 0; i < 3 * e->nfree; i++) {
        e->v[i] += h * a[i];
        e->x[i] += h * e->v[i];
    }
}

static void bench_explicit(const sk_tissue_model *m, int threads, double xpbd_steps_per_second)
{
    explicit_system e = make_explicit(m);
    double *a = malloc(3 * e.nfree * sizeof *a);
    /* its stable step: h < 2 / omega_max, omega_max^2 <= max over points of sum(k) / m
       (Gershgorin) */
    double wmax2 = 0.0;
    for (size_t p = 0; p < e.nfree; p++) {
        double ksum = 0.0;
        for (size_t o = e.start[p]; o < e.start[p + 1]; o++) ksum += 2.0 * e.k[o];
        wmax2 = fmax(wmax2, ksum * e.inv_m[p]);
    }
    double h_stable = 2.0 / sqrt(wmax2);
    int steps = 200;
    double best = 1e30;
    for (int run = 0; run < 3; run++) {
        double t0 = sk_time_seconds();
#pragma omp parallel num_threads(threads)
        for (int k = 0; k < steps; k++) explicit_step(&e, 1e-7, a);
        best = fmin(best, (sk_time_seconds() - t0) / steps);
    }
    size_t springs = m->spring_count;
    printf("  explicit mass-spring step, %d thread%s: %.3f ms/step, %.1f M springs/s (every spring "
           "is visited twice, once "
           "per end); stable only below h = %.2e s, so %.0f steps per simulated second: %.2f s per "
           "simulated second "
           "against XPBD's %.2f s\n",
           threads, threads > 1 ? "s" : "", best * 1e3, springs / best * 1e-6, h_stable,
           1.0 / h_stable, best / h_stable, m->desc.simulation.step_hz / xpbd_steps_per_second);
    free(a);
    free(e.start);
    free(e.other);
    free(e.k);
    free(e.c);
    free(e.rest);
    free(e.x);
    free(e.v);
    free(e.inv_m);
}

#ifdef SK_BENCH_CHOLMOD
/* Implicit Euler as projective dynamics (Liu et al. 2013) factors M / h^2 + L once; every
 * iteration then solves it for x, y and z. The time of that solve decided the method. */
static void bench_cholmod(const sk_tissue_model *m)
{
    size_t nfree = m->skin_count + m->fat_count;
    double h = 1.0 / m->desc.simulation.step_hz;
    cholmod_common cc;
    cholmod_start(&cc);
    cholmod_triplet *t =
        cholmod_allocate_triplet(nfree, nfree, nfree + m->spring_count, -1, CHOLMOD_REAL, &cc);
    double *diag = calloc(nfree, sizeof *diag);
    for (size_t p = 0; p < nfree; p++) diag[p] = m->mass[p] / (h * h);
    for (size_t s = 0; s < m->spring_count; s++) {
        double k, c;
        sk__spring_constants(m, s, &k, &c);
        size_t i = m->spring_i[s], j = m->spring_j[s];
        if (i < nfree) diag[i] += k;
        if (j < nfree) diag[j] += k;
        if (i < nfree && j < nfree) {
            size_t n = t->nnz++;
            ((int *)t->i)[n] = (int)(i > j ? i : j);
            ((int *)t->j)[n] = (int)(i > j ? j : i);
            ((double *)t->x)[n] = -k;
        }
    }
    for (size_t p = 0; p < nfree; p++) {
        size_t n = t->nnz++;
        ((int *)t->i)[n] = ((int *)t->j)[n] = (int)p;
        ((double *)t->x)[n] = diag[p];
    }
    cholmod_sparse *a = cholmod_triplet_to_sparse(t, 0, &cc);
    double t0 = sk_time_seconds();
    cholmod_factor *l = cholmod_analyze(a, &cc);
    cholmod_factorize(a, l, &cc);
    double t1 = sk_time_seconds();
    cholmod_dense *b = cholmod_ones(nfree, 3, CHOLMOD_REAL, &cc);
    double best = 1e30;
    for (int r = 0; r < 10; r++) {
        double s0 = sk_time_seconds();
        cholmod_dense *x = cholmod_solve(CHOLMOD_A, l, b, &cc);
        best = fmin(best, sk_time_seconds() - s0);
        cholmod_free_dense(&x, &cc);
    }
    printf("  projective dynamics' prefactored matrix (CHOLMOD): factor %.2f s, %.0f nonzeros in "
           "L, one solve for "
           "x, y, z %.2f ms: %.2f s per simulated second at one iteration per step\n",
           t1 - t0, cc.lnz, best * 1e3, best * m->desc.simulation.step_hz);
    cholmod_free_dense(&b, &cc);
    cholmod_free_factor(&l, &cc);
    cholmod_free_sparse(&a, &cc);
    cholmod_free_triplet(&t, &cc);
    cholmod_finish(&cc);
    free(diag);
}
#endif

/* ------------------------------------------------------------ the command */
static void bench_command(const char *args, const char *label)
{
    char cmd[4096];
    double best = 1e30, best_cpu = 1e30;
    for (int run = 0; run < 2; run++) {
        snprintf(cmd, sizeof cmd, "'%s' %s -q > /dev/null", SK_BENCH_CLI, args);
        double c0 = children_cpu_seconds(), t0 = sk_time_seconds();
        if (system(cmd) != 0) {
            fprintf(stderr, "bench_tissue: '%s' failed\n", cmd);
            exit(1);
        }
        best = fmin(best, sk_time_seconds() - t0);
        best_cpu = fmin(best_cpu, children_cpu_seconds() - c0);
    }
    printf("  %s: wall %.2f s, CPU %.2f s\n", label, best, best_cpu);
}

int main(int argc, char **argv)
{
    bool quick = argc > 1 && strcmp(argv[1], "--quick") == 0;
    load_average();
    bench_skin("arm", 2.0, 1.0);
    bench_skin("body", 5.0, 3.0);

    /* the arm at the spacing that gives about 20,000 fat and skin points */
    sk_tissue_character_desc *d = character("arm", 5.0);
    sk_tissue_model *m = NULL;
    sk_error err = {0};
    if (sk_tissue_model_build(d, NULL, &m, &err) != SK_OK) fail(&err);
    size_t nfree = m->skin_count + m->fat_count;
    int hz = m->desc.simulation.step_hz, steps = quick ? hz / 4 : hz;
    printf("simulation, arm at 5 mm: %zu fat and skin points, %zu muscle and bone points, %zu "
           "springs, %d steps/s\n",
           nfree, m->muscle_count + m->bone_count, m->spring_count, hz);
    double two = 0.0;
    for (int threads = 1; threads <= 2; threads++) {
        sim_figures f = bench_sim(m, threads, steps);
        double frames = f.steps_per_second / (hz / 60.0);
        printf("  %d thread%s: %.0f steps/s = %.1f simulated 60 fps frames per second (target 120 "
               "on 2 cores); "
               "springs %.1f M/s in the whole step, the XPBD solve alone %.3f ms/step (%.1f M "
               "springs/s)\n",
               threads, threads > 1 ? "s" : "", f.steps_per_second, frames,
               f.steps_per_second * m->spring_count * 1e-6, f.solver_seconds_per_step * 1e3,
               m->spring_count / f.solver_seconds_per_step * 1e-6);
        printf("    CPU: %.3f ms a whole step (every thread), the XPBD solve alone %.3f ms on the "
               "busiest thread\n",
               f.cpu_per_step * 1e3, f.solver_cpu_per_step * 1e3);
        if (threads == 2) two = f.steps_per_second;
    }
    bench_explicit(m, 2, two);
#ifdef SK_BENCH_CHOLMOD
    bench_cholmod(m);
#endif
    sk_tissue_model_destroy(m);
    free(d);

    printf("the whole command, files written (best of 2):\n");
    const char *tmp = getenv("TMPDIR");
    char args[2048];
    snprintf(args, sizeof args,
             "tissue run --character arm --motion curl -o '%s/sk-bench-tissue-curl'",
             tmp && tmp[0] ? tmp : "/tmp");
    bench_command(args, "tissue run --character arm --motion curl (5 s, 30 fps: rest.obj, "
                        "skin.pc2, skin.glb, stats)");
    if (!quick) {
        snprintf(args, sizeof args,
                 "tissue run --character body --motion jump -o '%s/sk-bench-tissue-jump'",
                 tmp && tmp[0] ? tmp : "/tmp");
        bench_command(args, "tissue run --character body --motion jump (3.2 s, 30 fps)");
    }
    load_average();
    return 0;
}
