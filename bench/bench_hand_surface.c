/* Benchmarks of the hand surface (thesis 4.1): meshing the skeleton's flesh (target 1 s),
 * a pose update + skinning + normals of the 8000-triangle hand on one thread (targets:
 * 50 us LBS, 100 us DQS; MANO's 778-vertex LBS is the usual comparison, hence ns per
 * vertex), the levels of detail, the thesis's defect per method (4.1.5) on a fully
 * flexed index finger, and the whole `hand mesh` command with its files. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <time.h>

#include "bench_load.h"
#include "shitsukan/hand.h"

static void fail(const sk_error *err)
{
    fprintf(stderr, "bench_hand_surface: %s\n", err->message);
    exit(1);
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

static double min_of(const double *t, int n)
{
    double m = t[0];
    for (int i = 1; i < n; i++) m = t[i] < m ? t[i] : m;
    return m;
}

int main(void)
{
    sk_error err = {0};
    sk_hand_skeleton skel;
    if (sk_hand_skeleton_init(&skel, NULL, &err) != SK_OK) fail(&err);
    char load[64];
    bench_load_average(load, sizeof load);
    printf("load average: %s; threads: %d\n", load, sk_threads_max());
    /* meshing: best of 3 on all threads, and on one */
    sk_hand_surface *s = NULL;
    for (int threads = 0; threads <= 1; threads++) {
        sk_threads_set(threads);
        double t[3], cpu[3];
        for (int i = 0; i < 3; i++) {
            sk_hand_surface_destroy(s);
            double t0 = sk_time_seconds();
            clock_t c0 = clock();
            if (sk_hand_surface_create(&s, &skel, NULL, &err) != SK_OK) fail(&err);
            t[i] = sk_time_seconds() - t0;
            cpu[i] = (double)(clock() - c0) / CLOCKS_PER_SEC;
        }
        printf("mesh generation (%s): best %.3f s wall of 3, %.3f s of CPU (target 1 s)\n",
               threads ? "1 thread" : "all threads", min_of(t, 3), min_of(cpu, 3));
    }
    sk_threads_set(0);
    const sk_mesh *m = sk_hand_surface_mesh(s);
    printf("mesh: %zu vertices, %zu triangles\n", m->vertex_count, m->triangle_count);
    /* pose update + skinning + normals, one thread (the deform is single-threaded below
       20000 vertices) */
    float *pos = malloc(3 * m->vertex_count * sizeof *pos),
          *nrm = malloc(3 * m->vertex_count * sizeof *nrm);
    const int poses = 2000;
    double *t = malloc(poses * sizeof *t);
    static const char *const names[] = {"rigid", "lbs", "dqs"};
    double q[SK_HAND_DOF_COUNT];
    for (int method = SK_HAND_SKINNING_RIGID; method <= SK_HAND_SKINNING_DQS; method++) {
        double sink = 0;
        for (int i = 0; i < poses; i++) {
            sk_hand_relaxed(&skel, q);
            sk_rng rng = sk_rng_make(5, (uint64_t)i, 0, 0);
            for (int d = SK_HAND_WRIST_DOF_COUNT; d < SK_HAND_DOF_COUNT; d++)
                q[d] = sk_rng_range(&rng, skel.dof[d].min, skel.dof[d].max);
            double t0 = sk_time_seconds();
            sk_hand_frames fr;
            sk_hand_forward(&skel, q, &fr);
            sk_hand_surface_deform(s, &fr, (sk_hand_skinning)method, pos, nrm);
            t[i] = sk_time_seconds() - t0;
            sink += pos[3 * (i % m->vertex_count)];
        }
        qsort(t, poses, sizeof *t, cmp_double);
        double us = t[poses / 2] * 1e6;
        printf("pose update + skinning + normals, %s: median %.1f us per pose, %.2f ns per vertex "
               "(best %.1f us)%s\n",
               names[method - 1], us, us * 1e3 / (double)m->vertex_count, t[0] * 1e6,
               sink == 12345.678 ? "" : "");
    }
    /* where the time of a pose goes: the forward kinematics alone (the rest is the
       link transforms and the per-vertex loop) */
    for (int i = 0; i < poses; i++) {
        sk_hand_relaxed(&skel, q);
        q[15] = 1e-4 * i;
        double t0 = sk_time_seconds();
        sk_hand_frames fr;
        sk_hand_forward(&skel, q, &fr);
        t[i] = sk_time_seconds() - t0;
        if (fr.point[9].x == 12345.678) printf("\n");
    }
    qsort(t, poses, sizeof *t, cmp_double);
    printf("  of which forward kinematics (20 links): median %.2f us\n", t[poses / 2] * 1e6);
    /* levels of detail */
    for (int l = 1; l < SK_HAND_LOD_COUNT; l++) {
        sk_hand_surface *c;
        double t0 = sk_time_seconds();
        if (sk_hand_surface_simplify(&c, s, sk_hand_lod_triangles[l], &err) != SK_OK) fail(&err);
        const sk_mesh *cm = sk_hand_surface_mesh(c);
        printf("LOD %d: %zu vertices, %zu triangles (target %d) in %.3f s\n", l, cm->vertex_count,
               cm->triangle_count, sk_hand_lod_triangles[l], sk_time_seconds() - t0);
        sk_hand_surface_destroy(c);
    }
    /* the defect of the thesis on a fully flexed index (MCP 90, PIP 100, DIP 80 deg) */
    sk_hand_relaxed(&skel, q);
    q[sk_hand_dof_find("I.MCP.flex")] = 90 * SK_DEG_TO_RAD;
    q[sk_hand_dof_find("I.PIP.flex")] = 100 * SK_DEG_TO_RAD;
    q[sk_hand_dof_find("I.DIP.flex")] = 80 * SK_DEG_TO_RAD;
    printf("defect, fully flexed index (%s):\n  method  volume lost mm^3  %% of finger  inside "
           "neighbour  max depth mm\n",
           "4.1.5");
    for (int method = SK_HAND_SKINNING_RIGID; method <= SK_HAND_SKINNING_DQS; method++) {
        sk_hand_defect d;
        if (sk_hand_surface_defect(s, q, (sk_hand_skinning)method, SK_HAND_INDEX, &d, &err) !=
            SK_OK)
            fail(&err);
        printf("  %-6s  %16.0f  %11.1f  %9d / %4d  %12.2f\n", names[method - 1], d.volume_lost_mm3,
               d.volume_lost_percent, d.inside_count, d.vertex_count, d.max_depth_mm);
    }
    /* the whole commands as a user runs them, files written; wall and CPU time (the
       machine may be shared: the CPU time of the command is the steadier figure) */
    static const char *const commands[][3] = {
        {"hand mesh --pin I.PIP.flex=90 -o %s/bench-hand.obj -q",
         "hand mesh --pin I.PIP.flex=90 -o hand.obj", "mesh generation, solve, skinning, OBJ"},
        {"hand mesh --pin I.PIP.flex=90 -o %s/bench-hand.glb -q",
         "hand mesh --pin I.PIP.flex=90 -o hand.glb",
         "the same, 3 levels of detail, 1024 texture, GLB"},
        {"hand animate " SK_BENCH_PRESET_DIR
         "/hand/fig4.18-keys.json --glb %s/bench-fig4.18.glb -q",
         "hand animate fig4.18-keys.json --glb fig4.18.glb",
         "81 frames solved, 3 levels, texture, animation, GLB"},
    };
    for (size_t c = 0; c < sizeof commands / sizeof commands[0]; c++) {
        char cmd[1024], args[768];
        snprintf(args, sizeof args, commands[c][0], SK_BENCH_TMP);
        snprintf(cmd, sizeof cmd, "%s %s", SK_BENCH_CLI, args);
        double best = 1e9, best_cpu = 1e9;
        for (int i = 0; i < 3; i++) {
            struct rusage r0, r1;
            getrusage(RUSAGE_CHILDREN, &r0);
            double t0 = sk_time_seconds();
            if (system(cmd) != 0) {
                fprintf(stderr, "bench_hand_surface: %s failed\n", cmd);
                return 1;
            }
            double dt = sk_time_seconds() - t0;
            getrusage(RUSAGE_CHILDREN, &r1);
            double cpu = (double)(r1.ru_utime.tv_sec - r0.ru_utime.tv_sec + r1.ru_stime.tv_sec -
                                  r0.ru_stime.tv_sec) +
                         1e-6 * (double)(r1.ru_utime.tv_usec - r0.ru_utime.tv_usec +
                                         r1.ru_stime.tv_usec - r0.ru_stime.tv_usec);
            best = dt < best ? dt : best;
            best_cpu = cpu < best_cpu ? cpu : best_cpu;
        }
        printf("shitsukan %s: best %.3f s wall, %.3f s CPU of 3 (%s)\n", commands[c][1], best,
               best_cpu, commands[c][2]);
    }
    free(pos), free(nrm), free(t);
    sk_hand_surface_destroy(s);
    return 0;
}
