/* Progress of a parallel loop (private helper for library modules): items finish on any
 * thread, the sink is called only from OpenMP thread 0 and only when the whole percent
 * changes, so sinks need not be thread-safe. */
#ifndef SK_CORE_LOOP_PROGRESS_H
#define SK_CORE_LOOP_PROGRESS_H

#include <omp.h>
#include <stdatomic.h>

#include "shitsukan/core.h"

typedef struct sk__loop_progress {
    const sk_progress *sink; /* may be NULL or have a NULL fn */
    long total;
    atomic_long done;
    int last_percent; /* touched by thread 0 only */
} sk__loop_progress;

static inline void sk__loop_progress_init(sk__loop_progress *lp, const sk_progress *sink, long total)
{
    lp->sink = (sink && sink->fn) ? sink : NULL;
    lp->total = total > 0 ? total : 1;
    atomic_init(&lp->done, 0);
    lp->last_percent = -1;
}

/* Call once per finished item, from inside the parallel loop. */
static inline void sk__loop_progress_tick(sk__loop_progress *lp)
{
    if (!lp->sink) return;
    long d = atomic_fetch_add_explicit(&lp->done, 1, memory_order_relaxed) + 1;
    if (omp_get_thread_num() != 0) return;
    int percent = (int)(100 * d / lp->total);
    if (percent != lp->last_percent) {
        lp->last_percent = percent;
        sk_progress_report(lp->sink, (double)d / (double)lp->total);
    }
}

#endif /* SK_CORE_LOOP_PROGRESS_H */
