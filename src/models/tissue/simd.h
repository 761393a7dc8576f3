/* The tissue module's vector paths: where the compiler can build AVX2 code for one
 * function (GCC and Clang on x86-64), the hot loops have an AVX2 version, taken when the
 * processor has it. Each vector lane does the operations of the scalar code in the same
 * order (the target enables no fused multiply-add), so either path gives the same bits. */
#ifndef SK_TISSUE_SIMD_H
#define SK_TISSUE_SIMD_H

#include <stdbool.h>

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#define SK__HAVE_AVX2_PATH 1
#define SK__AVX2 __attribute__((target("avx2")))
/* Whether this processor runs AVX2 (the run-time library's answer, read, not computed). */
static inline bool sk__have_avx2(void) { return __builtin_cpu_supports("avx2"); }
#else
static inline bool sk__have_avx2(void) { return false; }
#endif

#endif
