/* Thread count control over OpenMP (the only process-wide setting, and it is OpenMP's).
 * Builds without OpenMP (WebAssembly) run every loop on one thread. */
#ifdef _OPENMP
#include <omp.h>
#endif

#include "shitsukan/core.h"

#ifdef _OPENMP
static int default_threads(void) { return omp_get_num_procs() > 0 ? omp_get_num_procs() : 1; }

void sk_threads_set(int count)
{
    omp_set_num_threads(count > 0 ? count : default_threads());
}

int sk_threads_max(void) { return omp_get_max_threads(); }
#else
void sk_threads_set(int count) { (void)count; }

int sk_threads_max(void) { return 1; }
#endif
