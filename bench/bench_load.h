/* The machine's load average for the benchmarks' figures ("?" where /proc has none), and
 * CPU time (on a shared machine the CPU a stage takes says more than its wall time). */
#ifndef SK_BENCH_LOAD_H
#define SK_BENCH_LOAD_H

#include <stdio.h>
#include <string.h>
#include <time.h>

/* The three load averages and the run queue of /proc/loadavg into buf, one line. */
static inline void bench_load_average(char *buf, size_t size)
{
    snprintf(buf, size, "?");
    FILE *f = fopen("/proc/loadavg", "r");
    if (!f) return;
    if (!fgets(buf, (int)size, f)) buf[0] = '\0';
    fclose(f);
    buf[strcspn(buf, "\n")] = '\0';
}

/* CPU seconds of a clock: CLOCK_PROCESS_CPUTIME_ID (every thread of the process) or
   CLOCK_THREAD_CPUTIME_ID (the calling thread). */
static inline double bench_cpu_seconds(clockid_t clock)
{
    struct timespec ts;
    if (clock_gettime(clock, &ts) != 0) return 0;
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

#endif
