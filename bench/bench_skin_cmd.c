/* Skin commands end to end, as a user runs them: `shitsukan skin --preset fig19a --size 400
 * -o f.png` and `shitsukan skin maps --preset back-of-hand --size 4096 -o DIR` (files
 * written included), with wall time, CPU time and peak memory of the process, and the
 * split the command itself reports (SHITSUKAN_TIMINGS): building the cells (model),
 * rendering (shading) and encoding and writing the files. SHITSUKAN_BENCH_CLI runs
 * another build of the command instead (to compare). */
#define _DEFAULT_SOURCE /* wait4 */
#include <spawn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

extern char **environ;

typedef struct run {
    double wall, cpu, model, shading, files;
    double cpu_model, cpu_shading, cpu_files; /* the command's own CPU split */
    long peak_kib;
} run;

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* Runs the CLI with argv (NULL-terminated, after the program name); the command's own
 * timing line comes back through a temporary file. */
static int run_cli(const char *const *argv, const char *threads, run *out)
{
    char log[] = "/tmp/bench_skin_cmd_XXXXXX";
    int fd = mkstemp(log);
    if (fd < 0) return 1;
    const char *cli = getenv("SHITSUKAN_BENCH_CLI") ? getenv("SHITSUKAN_BENCH_CLI") : SK_BENCH_CLI;
    const char *args[32];
    int n = 0;
    args[n++] = cli;
    for (int i = 0; argv[i] && n < 28; i++) args[n++] = argv[i];
    args[n++] = "--threads", args[n++] = threads, args[n] = NULL;
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_adddup2(&fa, fd, 2);
    setenv("SHITSUKAN_TIMINGS", "1", 1);
    pid_t pid;
    double t0 = now();
    int rc = posix_spawn(&pid, cli, &fa, NULL, (char *const *)args, environ);
    posix_spawn_file_actions_destroy(&fa);
    if (rc != 0) {
        close(fd);
        unlink(log);
        return 1;
    }
    int status;
    struct rusage ru;
    wait4(pid, &status, 0, &ru);
    out->wall = now() - t0;
    out->cpu = (double)ru.ru_utime.tv_sec + 1e-6 * (double)ru.ru_utime.tv_usec +
               (double)ru.ru_stime.tv_sec + 1e-6 * (double)ru.ru_stime.tv_usec;
    out->peak_kib = ru.ru_maxrss;
    char text[4096] = {0};
    lseek(fd, 0, SEEK_SET);
    ssize_t got = read(fd, text, sizeof text - 1);
    close(fd);
    unlink(log);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        fprintf(stderr, "bench_skin_cmd: %s failed: %s\n", argv[0], got > 0 ? text : "");
        return 1;
    }
    /* a build without the timing line (an older one, to compare) leaves the split at -1 */
    const char *line = got > 0 ? strstr(text, "timings:") : NULL;
    if (!line || sscanf(line, "timings: model %lf ms, shading %lf ms, files %lf ms", &out->model,
                        &out->shading, &out->files) != 3)
        out->model = out->shading = out->files = -1;
    const char *cpu = line ? strstr(line, "(CPU ") : NULL;
    if (!cpu || sscanf(cpu, "(CPU %lf, %lf, %lf ms)", &out->cpu_model, &out->cpu_shading,
                       &out->cpu_files) != 3)
        out->cpu_model = out->cpu_shading = out->cpu_files = -1;
    return 0;
}

/* Best wall time of `runs` runs (on a shared machine the best is the least disturbed). */
static int best_of(const char *const *argv, const char *threads, int runs, run *best)
{
    best->wall = 1e30;
    for (int r = 0; r < runs; r++) {
        run one;
        if (run_cli(argv, threads, &one)) return 1;
        if (one.wall < best->wall) *best = one;
    }
    return 0;
}

static void print_run(const char *label, const run *r, const char *target)
{
    printf("    %-10s %7.1f ms wall, %7.1f ms CPU, peak %5.0f MiB   (model %.1f, shading %.1f, "
           "files %.1f ms; CPU %.1f, %.1f, %.1f ms)%s\n",
           label, r->wall * 1e3, r->cpu * 1e3, r->peak_kib / 1024.0, r->model, r->shading, r->files,
           r->cpu_model, r->cpu_shading, r->cpu_files, target);
}

int main(void)
{
    double load[3] = {0, 0, 0};
    FILE *f = fopen("/proc/loadavg", "r");
    if (f) {
        if (fscanf(f, "%lf %lf %lf", &load[0], &load[1], &load[2]) != 3) load[0] = -1;
        fclose(f);
    }
    printf("skin commands end to end (load average %.2f %.2f %.2f; best of several runs)\n",
           load[0], load[1], load[2]);
    char dir[] = "/tmp/bench_skin_cmd_dir_XXXXXX";
    if (!mkdtemp(dir)) return 1;
    char png[1024], maps[1024];
    snprintf(png, sizeof png, "%s/f.png", dir);
    snprintf(maps, sizeof maps, "%s/maps", dir);

    const char *preview[] = {"skin", "--preset", "fig19a", "--size", "400", "-q", "-o", png, NULL};
    printf("  skin --preset fig19a --size 400 -o f.png\n");
    run one, two;
    if (best_of(preview, "1", 9, &one) || best_of(preview, "2", 9, &two)) return 1;
    print_run("1 thread", &one, "");
    print_run("2 threads", &two, "   target <= 60 ms wall");

    const char *big[] = {"skin", "maps", "--preset", "back-of-hand", "--size",
                         "4096", "-q",   "-o",       maps,           NULL};
    printf("  skin maps --preset back-of-hand --size 4096 (six files)\n");
    if (best_of(big, "2", 2, &two)) return 1;
    print_run("2 threads", &two, "   target <= 4 s wall, <= 400 MiB");
    const char *rm[] = {"rm", "-rf", dir, NULL};
    pid_t pid;
    if (posix_spawnp(&pid, "rm", NULL, NULL, (char *const *)rm, environ) == 0)
        waitpid(pid, NULL, 0);
    return 0;
}
