/* The hand module's dense symmetric algebra through LAPACK (dpotrf, dpotrs, dpotri,
 * dsyev), or through the portable routines when the build has no LAPACKE. */
#include "models/hand/dense_internal.h"

#ifdef SK_HAVE_LAPACKE
#include <lapacke.h>

int sk__hand_cholesky_at(double *a, int n)
{
    if (n == 0) return 0;
    lapack_int info = LAPACKE_dpotrf_work(LAPACK_COL_MAJOR, 'L', n, a, n);
    return info > 0 ? (int)info : info < 0 ? 1 : 0;
}

/* One right-hand side, as dpotrs solves it with the reference BLAS (its two dtrsm
 * loops: L y = b column by column, then L' x = y row by row from the last), without the
 * library calls: the posture solver does this tens of times a frame, where the calls cost
 * as much as the arithmetic. Whatever BLAS is installed, the result is the reference's. */
static void cholesky_solve_one(const double *l, int n, double *b)
{
    for (int k = 0; k < n; k++) {
        if (b[k] == 0.0) continue;
        b[k] /= l[(size_t)k * n + k];
        const double *col = l + (size_t)k * n;
        for (int i = k + 1; i < n; i++) b[i] -= b[k] * col[i];
    }
    for (int i = n - 1; i >= 0; i--) {
        const double *col = l + (size_t)i * n;
        double t = b[i];
        for (int k = i + 1; k < n; k++) t -= col[k] * b[k];
        b[i] = t / col[i];
    }
}

void sk__hand_cholesky_solve(const double *l, int n, double *b, int nrhs)
{
    if (n == 0 || nrhs == 0) return;
    if (nrhs == 1) {
        cholesky_solve_one(l, n, b);
        return;
    }
    LAPACKE_dpotrs_work(LAPACK_COL_MAJOR, 'L', n, nrhs, l, n, b, n);
}

bool sk__hand_spd_inverse(double *a, int n)
{
    if (n == 0) return true;
    if (LAPACKE_dpotrf_work(LAPACK_COL_MAJOR, 'L', n, a, n) != 0) return false;
    if (LAPACKE_dpotri_work(LAPACK_COL_MAJOR, 'L', n, a, n) != 0) return false;
    for (int j = 0; j < n; j++)
        for (int i = 0; i < j; i++) a[(size_t)j * n + i] = a[(size_t)i * n + j];
    return true;
}

bool sk__hand_sym_eigen(double *a, int n, double *values, bool vectors)
{
    if (n == 0) return true;
    double work[64 * 64];
    return LAPACKE_dsyev_work(LAPACK_COL_MAJOR, vectors ? 'V' : 'N', 'L', n, a, n, values, work,
                              (lapack_int)(sizeof work / sizeof work[0])) == 0;
}

#else

int sk__hand_cholesky_at(double *a, int n) { return sk__hand_portable_cholesky(a, n); }

void sk__hand_cholesky_solve(const double *l, int n, double *b, int nrhs)
{
    sk__hand_portable_cholesky_solve(l, n, b, nrhs);
}

bool sk__hand_spd_inverse(double *a, int n) { return sk__hand_portable_spd_inverse(a, n); }

bool sk__hand_sym_eigen(double *a, int n, double *values, bool vectors)
{
    return sk__hand_portable_sym_eigen(a, n, values, vectors);
}

#endif

bool sk__hand_cholesky(double *a, int n) { return sk__hand_cholesky_at(a, n) == 0; }
