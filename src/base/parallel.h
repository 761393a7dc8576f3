/* When a loop is worth running in parallel (private helper for library modules). Starting
 * a parallel region wakes the other threads, and when it ends they spin before they
 * sleep (OpenMP's default wait policy), taking a core from other work on a busy machine:
 * a loop with less work than this runs on the calling thread, so small jobs never get
 * slower with more threads. */
#ifndef SK_CORE_PARALLEL_H
#define SK_CORE_PARALLEL_H

#include <stdbool.h>

/* About 0.2 ms of work on one core. */
#define SK__PARALLEL_MIN_NS 2e5

/* True when `items` of about `ns_per_item` nanoseconds each make a loop worth sharing. */
static inline bool sk__parallel_worth(double items, double ns_per_item)
{
    return items * ns_per_item >= SK__PARALLEL_MIN_NS;
}

#endif
