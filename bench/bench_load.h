/* The machine's load average for the benchmarks' figures ("?" where /proc has none). */
#ifndef SK_BENCH_LOAD_H
#define SK_BENCH_LOAD_H

#include <stdio.h>
#include <string.h>

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

#endif
