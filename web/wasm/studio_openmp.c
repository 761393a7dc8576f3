/* The OpenMP runtime calls the library makes outside its pragmas, for the WebAssembly
 * build, which has no OpenMP: one thread, numbered 0 (the pragmas are ignored, so every
 * loop runs on it). */
int omp_get_max_threads(void);
int omp_get_thread_num(void);
int omp_get_num_threads(void);

int omp_get_max_threads(void) { return 1; }
int omp_get_thread_num(void) { return 0; }
int omp_get_num_threads(void) { return 1; }
