/* Dense symmetric linear algebra of the hand module (the equilibrium of eq. 3.17 and the
 * Gaussian of the calibrated potential): small column-major matrices, n <= 64. LAPACK
 * does the work where the build has it (SK_HAVE_LAPACKE, dense_lapack.c); builds without
 * it (WebAssembly) use the portable routines of dense_portable.c behind the same calls,
 * which the native tests check against LAPACK to rounding. */
#ifndef SK_HAND_DENSE_INTERNAL_H
#define SK_HAND_DENSE_INTERNAL_H

#include <stdbool.h>

/* Lower Cholesky factor of the symmetric matrix `a` (n x n, leading dimension n) in
 * place; the strict upper triangle is left as is. Returns 0, or the 1-based column whose
 * pivot is not positive (LAPACK dpotrf's info). */
int sk__hand_cholesky_at(double *a, int n);
/* true when sk__hand_cholesky_at succeeds. */
bool sk__hand_cholesky(double *a, int n);
/* Solves L L' x = b in place for `nrhs` columns of b (leading dimension n). */
void sk__hand_cholesky_solve(const double *l, int n, double *b, int nrhs);
/* Inverse of a symmetric positive definite matrix in place (the full matrix); false if
 * not positive definite. */
bool sk__hand_spd_inverse(double *a, int n);
/* Eigenvalues in ascending order and, if `vectors`, unit eigenvectors as the columns of
 * `a` (in place); false on failure. Only the lower triangle of `a` is read. */
bool sk__hand_sym_eigen(double *a, int n, double *values, bool vectors);

/* The portable routines (always built, so native tests compare them with LAPACK). Same
 * contracts as above; the eigen solver is cyclic Jacobi. */
int sk__hand_portable_cholesky(double *a, int n);
void sk__hand_portable_cholesky_solve(const double *l, int n, double *b, int nrhs);
bool sk__hand_portable_spd_inverse(double *a, int n);
bool sk__hand_portable_sym_eigen(double *a, int n, double *values, bool vectors);

#endif /* SK_HAND_DENSE_INTERNAL_H */
