/* Progress reporting: the library-side sink and a terminal bar with percent and ETA
 * (drawn on stderr only when it is a terminal). */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "shitsukan/core.h"

double sk_time_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

void sk_progress_report(const sk_progress *progress, double fraction)
{
    if (progress && progress->fn) progress->fn(progress->user, sk_clampd(fraction, 0.0, 1.0));
}

void sk_progress_bar_begin(sk_progress_bar *bar, const char *label, bool enabled)
{
    memset(bar, 0, sizeof *bar);
    snprintf(bar->label, sizeof bar->label, "%s", label ? label : "");
    bar->active = enabled && isatty(STDERR_FILENO);
    bar->start_seconds = sk_time_seconds();
    bar->last_draw_seconds = -1.0;
    bar->last_percent = -1;
}

static void format_duration(double seconds, char *out, size_t size)
{
    if (seconds < 0 || seconds > 360000) {
        snprintf(out, size, "--:--");
        return;
    }
    int s = (int)(seconds + 0.5);
    if (s >= 3600)
        snprintf(out, size, "%d:%02d:%02d", s / 3600, (s / 60) % 60, s % 60);
    else
        snprintf(out, size, "%02d:%02d", s / 60, s % 60);
}

static void draw(sk_progress_bar *bar, double fraction, double now)
{
    enum { WIDTH = 30 };
    char cells[WIDTH + 1];
    int filled = (int)(fraction * WIDTH + 0.5);
    for (int i = 0; i < WIDTH; i++) cells[i] = i < filled ? '#' : '.';
    cells[WIDTH] = '\0';
    double elapsed = now - bar->start_seconds;
    double eta = fraction > 0.001 ? elapsed * (1.0 - fraction) / fraction : -1.0;
    char eta_text[32];
    format_duration(eta, eta_text, sizeof eta_text);
    fprintf(stderr, "\r%s [%s] %3d%% ETA %s ", bar->label, cells, (int)(fraction * 100.0),
            eta_text);
    fflush(stderr);
}

void sk_progress_bar_update(sk_progress_bar *bar, double fraction)
{
    if (!bar->active) return;
    double now = sk_time_seconds();
    int percent = (int)(fraction * 100.0);
    if (percent == bar->last_percent) return;
    if (bar->last_draw_seconds >= 0.0 && now - bar->last_draw_seconds < 0.1 && percent < 100)
        return;
    bar->last_percent = percent;
    bar->last_draw_seconds = now;
    draw(bar, sk_clampd(fraction, 0.0, 1.0), now);
}

void sk_progress_bar_end(sk_progress_bar *bar)
{
    if (!bar->active) return;
    double now = sk_time_seconds();
    draw(bar, 1.0, now);
    char took[32];
    format_duration(now - bar->start_seconds, took, sizeof took);
    fprintf(stderr, "\r%s done in %s%*s\n", bar->label, took, 40, "");
    bar->active = false;
}

static void bar_sink(void *user, double fraction) { sk_progress_bar_update(user, fraction); }

sk_progress sk_progress_bar_sink(sk_progress_bar *bar)
{
    sk_progress p = {bar_sink, bar};
    return p;
}
