/* Thread count control over OpenMP (the only process-wide setting, and it is OpenMP's).
 * Builds without OpenMP (WebAssembly) run every loop on one thread. */
#ifdef _OPENMP
#include <omp.h>
#endif

#include "shitsukan/core.h"

#ifdef _OPENMP
static int default_threads(void) { return omp_get_num_procs() > 0 ? omp_get_num_procs() : 1; }

void sk_threads_set(int count) { omp_set_num_threads(count > 0 ? count : default_threads()); }

int sk_threads_max(void) { return omp_get_max_threads(); }

int sk_thread_index(void) { return omp_get_thread_num(); }

int sk_thread_team_size(void) { return omp_get_num_threads(); }

void sk_threads_rest(void)
{
    /* libgomp's idle threads spin for some milliseconds before they sleep; pausing the
       host's thread pool ends them now (the next parallel loop starts new ones). */
    if (!omp_in_parallel()) omp_pause_resource_all(omp_pause_soft);
}
#else
void sk_threads_set(int count) { (void)count; }

int sk_threads_max(void) { return 1; }

int sk_thread_index(void) { return 0; }

int sk_thread_team_size(void) { return 1; }

void sk_threads_rest(void) {}
#endif
