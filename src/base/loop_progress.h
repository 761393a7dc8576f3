/* Progress of a parallel loop (private helper for library modules): items finish on any
 * thread; whichever thread sees the whole percent advance reports it, under a try-lock,
 * so calls to the sink are serialised, never decrease, and happen at most 101 times.
 * Sinks therefore need not be thread-safe (but may be called from any thread). */
#ifndef SK_CORE_LOOP_PROGRESS_H
#define SK_CORE_LOOP_PROGRESS_H

#include <stdatomic.h>

#include "shitsukan/core.h"

typedef struct sk__loop_progress {
    const sk_progress *sink; /* NULL when there is no sink */
    long total;
    atomic_long done;
    atomic_int reported_percent; /* written only under `busy` */
    atomic_flag busy;
} sk__loop_progress;

static inline void sk__loop_progress_init(sk__loop_progress *lp, const sk_progress *sink,
                                          long total)
{
    lp->sink = (sink && sink->fn) ? sink : NULL;
    lp->total = total > 0 ? total : 1;
    atomic_init(&lp->done, 0);
    atomic_init(&lp->reported_percent, -1);
    atomic_flag_clear(&lp->busy);
}

/* Call once per finished item, from inside the parallel loop. */
static inline void sk__loop_progress_tick(sk__loop_progress *lp)
{
    if (!lp->sink) return;
    long d = atomic_fetch_add_explicit(&lp->done, 1, memory_order_relaxed) + 1;
    int percent = (int)(100 * d / lp->total);
    if (percent <= atomic_load_explicit(&lp->reported_percent, memory_order_relaxed)) return;
    if (atomic_flag_test_and_set_explicit(&lp->busy, memory_order_acquire)) return;
    /* re-read under the lock: another thread may have reported a later percent */
    long now = atomic_load_explicit(&lp->done, memory_order_relaxed);
    int p = (int)(100 * now / lp->total);
    if (p > atomic_load_explicit(&lp->reported_percent, memory_order_relaxed)) {
        atomic_store_explicit(&lp->reported_percent, p, memory_order_relaxed);
        sk_progress_report(lp->sink, (double)now / (double)lp->total);
    }
    atomic_flag_clear_explicit(&lp->busy, memory_order_release);
}

#endif /* SK_CORE_LOOP_PROGRESS_H */
