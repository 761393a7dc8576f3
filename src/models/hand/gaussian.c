/* Dense linear algebra and Gaussian statistics for the calibrated potential (thesis
 * 3.2.2 read as a Gaussian of the joint angles, eq. 3.17): Cholesky, inverses, eigen
 * decompositions of small symmetric matrices (dense_internal.h), sample moments and
 * conditional means. */
#include <math.h>
#include <string.h>

#include "models/hand/gaussian_internal.h"

double sk__hand_cholesky_logdet(const double *l, int n)
{
    double s = 0.0;
    for (int i = 0; i < n; i++) s += 2.0 * log(l[(size_t)i * n + i]);
    return s;
}

void sk__hand_moments(const sk_hand_samples *s, const int *dofs, int d, const int *idx, int n,
                      double *mean, double *scatter)
{
    for (int a = 0; a < d; a++) {
        const double *col = s->column[dofs[a]];
        double m = 0.0;
        for (int k = 0; k < n; k++) m += col[idx ? idx[k] : k];
        mean[a] = n > 0 ? m / n : 0.0;
    }
    for (int b = 0; b < d; b++) {
        const double *cb = s->column[dofs[b]];
        for (int a = b; a < d; a++) {
            const double *ca = s->column[dofs[a]];
            double sum = 0.0;
            for (int k = 0; k < n; k++) {
                int i = idx ? idx[k] : k;
                sum += (ca[i] - mean[a]) * (cb[i] - mean[b]);
            }
            scatter[(size_t)b * d + a] = scatter[(size_t)a * d + b] = sum;
        }
    }
}

bool sk__hand_conditional(const double *p, int d, const bool *pinned, double *b)
{
    int u[SK_HAND_DOF_COUNT], q[SK_HAND_DOF_COUNT], nu = 0, np = 0;
    for (int i = 0; i < d; i++) {
        if (pinned[i])
            q[np++] = i;
        else
            u[nu++] = i;
    }
    double puu[SK_HAND_DOF_COUNT * SK_HAND_DOF_COUNT];
    for (int j = 0; j < nu; j++)
        for (int i = 0; i < nu; i++) puu[j * nu + i] = p[(size_t)u[j] * d + u[i]];
    for (int j = 0; j < np; j++)
        for (int i = 0; i < nu; i++) b[j * nu + i] = -p[(size_t)q[j] * d + u[i]];
    if (!sk__hand_cholesky(puu, nu)) return false;
    sk__hand_cholesky_solve(puu, nu, b, np);
    return true;
}

double sk__hand_gauss_logpdf(const double *x, const double *mu, const double *chol, double logdet,
                             int d)
{
    /* forward substitution L z = x - mu; log N = -1/2 (|z|^2 + log det + d log 2 pi) */
    double z[SK_HAND_DOF_COUNT];
    double q = 0.0;
    for (int i = 0; i < d; i++) {
        double v = x[i] - mu[i];
        for (int k = 0; k < i; k++) v -= chol[(size_t)k * d + i] * z[k];
        z[i] = v / chol[(size_t)i * d + i];
        q += z[i] * z[i];
    }
    return -0.5 * (q + logdet + d * log(2.0 * SK_PI));
}
