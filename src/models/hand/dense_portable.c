/* Portable dense symmetric algebra for builds without LAPACK (WebAssembly): Cholesky
 * by columns (the order of dpotf2), triangular solves, the inverse from the factor, and
 * cyclic Jacobi for eigenvalues (Golub and Van Loan, sec. 8.5), for the hand's small
 * systems (n <= 64). */
#include <math.h>
#include <string.h>

#include "models/hand/dense_internal.h"

#define MAX_N 64

int sk__hand_portable_cholesky(double *a, int n)
{
    for (int j = 0; j < n; j++) {
        double *cj = a + (size_t)j * n;
        double d = cj[j];
        for (int k = 0; k < j; k++) d -= a[(size_t)k * n + j] * a[(size_t)k * n + j];
        if (!(d > 0.0)) {
            cj[j] = d;
            return j + 1;
        }
        d = sqrt(d);
        cj[j] = d;
        for (int i = j + 1; i < n; i++) {
            double s = cj[i];
            for (int k = 0; k < j; k++) s -= a[(size_t)k * n + i] * a[(size_t)k * n + j];
            cj[i] = s / d;
        }
    }
    return 0;
}

/* Forward then backward substitution with the lower factor, column by column of b. */
void sk__hand_portable_cholesky_solve(const double *l, int n, double *b, int nrhs)
{
    for (int c = 0; c < nrhs; c++) {
        double *x = b + (size_t)c * n;
        for (int i = 0; i < n; i++) {
            double s = x[i];
            for (int k = 0; k < i; k++) s -= l[(size_t)k * n + i] * x[k];
            x[i] = s / l[(size_t)i * n + i];
        }
        for (int i = n - 1; i >= 0; i--) {
            double s = x[i];
            for (int k = i + 1; k < n; k++) s -= l[(size_t)i * n + k] * x[k];
            x[i] = s / l[(size_t)i * n + i];
        }
    }
}

bool sk__hand_portable_spd_inverse(double *a, int n)
{
    if (n > MAX_N) return false;
    if (sk__hand_portable_cholesky(a, n) != 0) return false;
    double l[MAX_N * MAX_N];
    memcpy(l, a, sizeof(double) * (size_t)n * n);
    memset(a, 0, sizeof(double) * (size_t)n * n);
    for (int i = 0; i < n; i++) a[(size_t)i * n + i] = 1.0;
    sk__hand_portable_cholesky_solve(l, n, a, n);
    /* symmetric up to rounding: make it exactly so, as dpotri's mirrored triangle is */
    for (int j = 0; j < n; j++)
        for (int i = j + 1; i < n; i++) a[(size_t)i * n + j] = a[(size_t)j * n + i];
    return true;
}

bool sk__hand_portable_sym_eigen(double *a, int n, double *values, bool vectors)
{
    if (n > MAX_N) return false;
    if (n == 0) return true;
    double m[MAX_N * MAX_N], v[MAX_N * MAX_N];
    for (int j = 0; j < n; j++)
        for (int i = j; i < n; i++) {
            double x = a[(size_t)j * n + i];
            if (!isfinite(x)) return false;
            m[(size_t)j * n + i] = m[(size_t)i * n + j] = x;
        }
    memset(v, 0, sizeof(double) * (size_t)n * n);
    for (int i = 0; i < n; i++) v[(size_t)i * n + i] = 1.0;
    bool converged = false;
    for (int sweep = 0; sweep < 100 && !converged; sweep++) {
        double off = 0.0, diag = 0.0;
        for (int j = 0; j < n; j++) {
            diag += m[(size_t)j * n + j] * m[(size_t)j * n + j];
            for (int i = j + 1; i < n; i++) off += m[(size_t)j * n + i] * m[(size_t)j * n + i];
        }
        if (off <= 1e-32 * diag || off == 0.0) {
            converged = true;
            break;
        }
        for (int p = 0; p < n - 1; p++)
            for (int q = p + 1; q < n; q++) {
                double apq = m[(size_t)q * n + p];
                if (apq == 0.0) continue;
                double app = m[(size_t)p * n + p], aqq = m[(size_t)q * n + q];
                double theta = (aqq - app) / (2.0 * apq);
                double t = (theta >= 0 ? 1.0 : -1.0) / (fabs(theta) + sqrt(theta * theta + 1.0));
                double c = 1.0 / sqrt(t * t + 1.0), s = t * c;
                for (int k = 0; k < n; k++) {
                    /* columns p, q of M G */
                    double mkp = m[(size_t)p * n + k], mkq = m[(size_t)q * n + k];
                    m[(size_t)p * n + k] = c * mkp - s * mkq;
                    m[(size_t)q * n + k] = s * mkp + c * mkq;
                }
                for (int k = 0; k < n; k++) {
                    /* rows p, q of G' (M G) */
                    double mpk = m[(size_t)k * n + p], mqk = m[(size_t)k * n + q];
                    m[(size_t)k * n + p] = c * mpk - s * mqk;
                    m[(size_t)k * n + q] = s * mpk + c * mqk;
                }
                m[(size_t)q * n + p] = m[(size_t)p * n + q] = 0.0;
                for (int k = 0; k < n; k++) {
                    double vkp = v[(size_t)p * n + k], vkq = v[(size_t)q * n + k];
                    v[(size_t)p * n + k] = c * vkp - s * vkq;
                    v[(size_t)q * n + k] = s * vkp + c * vkq;
                }
            }
    }
    if (!converged) return false;
    /* ascending order (selection sort keeps the vectors with their values) */
    int order[MAX_N];
    for (int i = 0; i < n; i++) order[i] = i;
    for (int i = 0; i < n; i++) {
        int best = i;
        for (int k = i + 1; k < n; k++)
            if (m[(size_t)order[k] * n + order[k]] < m[(size_t)order[best] * n + order[best]])
                best = k;
        int tmp = order[i];
        order[i] = order[best];
        order[best] = tmp;
    }
    for (int i = 0; i < n; i++) values[i] = m[(size_t)order[i] * n + order[i]];
    if (vectors) {
        for (int i = 0; i < n; i++) {
            const double *col = v + (size_t)order[i] * n;
            /* LAPACK leaves the sign free; fix it so the largest entry is positive */
            int big = 0;
            for (int k = 1; k < n; k++)
                if (fabs(col[k]) > fabs(col[big])) big = k;
            double sign = col[big] < 0 ? -1.0 : 1.0;
            for (int k = 0; k < n; k++) a[(size_t)i * n + k] = sign * col[k];
        }
    }
    return true;
}
