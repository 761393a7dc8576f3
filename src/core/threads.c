/* Thread count control over OpenMP (the only process-wide setting, and it is OpenMP's). */
#include <omp.h>

#include "shitsukan/core.h"

static int default_threads(void) { return omp_get_num_procs() > 0 ? omp_get_num_procs() : 1; }

void sk_threads_set(int count)
{
    omp_set_num_threads(count > 0 ? count : default_threads());
}

int sk_threads_max(void) { return omp_get_max_threads(); }
