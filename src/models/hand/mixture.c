/* Mixtures of Gaussians for the calibrated potential (thesis 3.2.3 read as poses that
 * cluster by grasp type, each cluster a Gaussian of eq. 3.17): EM with a deterministic
 * k-means++ start, and the held-out error of the prediction a mixture gives from pinned
 * joints (each component's conditional mean, weighted by the probability of the pins). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "models/hand/gaussian_internal.h"
#include "models/hand/mixture_internal.h"

#define D_MAX SK_HAND_DOF_COUNT

static bool mixture_factor(sk__hand_mixture *g)
{
    for (int c = 0; c < g->m; c++) {
        memcpy(g->chol[c], g->cov[c], sizeof(double) * (size_t)g->d * g->d);
        if (!sk__hand_cholesky(g->chol[c], g->d)) return false;
        g->logdet[c] = sk__hand_cholesky_logdet(g->chol[c], g->d);
    }
    return true;
}

/* log sum_c pi_c N(x; mu_c, Sigma_c); writes the responsibilities if resp != NULL. */
static double mixture_logpdf(const sk__hand_mixture *g, const double *x, double *resp)
{
    double l[SK_HAND_POTENTIAL_MAX_COMPONENTS], top = -INFINITY;
    for (int c = 0; c < g->m; c++) {
        l[c] = log(g->weight[c]) +
               sk__hand_gauss_logpdf(x, g->mean[c], g->chol[c], g->logdet[c], g->d);
        top = fmax(top, l[c]);
    }
    double sum = 0.0;
    for (int c = 0; c < g->m; c++) sum += exp(l[c] - top);
    if (resp)
        for (int c = 0; c < g->m; c++) resp[c] = exp(l[c] - top) / sum;
    return top + log(sum);
}

/* M-step: weights, means and covariances from responsibilities, each covariance shrunk
 * toward `pooled` by `nu` pseudo-samples (components of few samples stay sane). */
static void mixture_m_step(sk__hand_mixture *g, const double *x, int n, const double *resp,
                           const double *pooled, double nu)
{
    int d = g->d, m = g->m;
#pragma omp parallel for schedule(static) if (n * m > 20000)
    for (int c = 0; c < m; c++) {
        double w = 0.0, mu[D_MAX] = {0};
        for (int i = 0; i < n; i++) {
            double r = resp[(size_t)i * m + c];
            w += r;
            for (int a = 0; a < d; a++) mu[a] += r * x[(size_t)i * d + a];
        }
        for (int a = 0; a < d; a++) mu[a] = w > 0 ? mu[a] / w : 0.0;
        double s[D_MAX * D_MAX] = {0};
        for (int i = 0; i < n; i++) {
            double r = resp[(size_t)i * m + c];
            if (r < 1e-12) continue;
            const double *xi = x + (size_t)i * d;
            for (int b = 0; b < d; b++) {
                double vb = r * (xi[b] - mu[b]);
                for (int a = b; a < d; a++) s[b * d + a] += vb * (xi[a] - mu[a]);
            }
        }
        for (int b = 0; b < d; b++)
            for (int a = b; a < d; a++) {
                double v = (s[b * d + a] + nu * pooled[b * d + a]) / (w + nu);
                g->cov[c][b * d + a] = g->cov[c][a * d + b] = v;
            }
        for (int a = 0; a < d; a++) g->cov[c][a * d + a] += SK_HAND__VARIANCE_FLOOR;
        for (int a = 0; a < d; a++) g->mean[c][a] = mu[a];
        g->weight[c] = fmax(w / n, 1e-6);
    }
    double total = 0.0;
    for (int c = 0; c < m; c++) total += g->weight[c];
    for (int c = 0; c < m; c++) g->weight[c] /= total;
}

/* E-step; returns the total log-likelihood. */
static double mixture_e_step(const sk__hand_mixture *g, const double *x, int n, double *resp)
{
    double total = 0.0;
#pragma omp parallel for schedule(static) reduction(+ : total) if (n * g->m > 20000)
    for (int i = 0; i < n; i++)
        total += mixture_logpdf(g, x + (size_t)i * g->d, resp + (size_t)i * g->m);
    return total;
}

static double sq_distance(const double *a, const double *b, int d)
{
    double q = 0.0;
    for (int k = 0; k < d; k++) q += (a[k] - b[k]) * (a[k] - b[k]);
    return q;
}

/* k-means++ seeding (deterministic from the seed), a few Lloyd steps, then EM. The
 * log-likelihood sum above is a reduction whose order depends on the threads, so the
 * stopping test uses a relative tolerance far above rounding. */
bool sk__hand_mixture_fit(sk__hand_mixture *g, const double *x, int n, int d, int m,
                          const double *pooled, double nu, uint64_t seed, double *resp)
{
    memset(g, 0, sizeof *g);
    g->m = m;
    g->d = d;
    sk_rng rng = sk_rng_make(seed, 0x6d6978, (uint64_t)m, 0);
    double *dist = malloc(sizeof(double) * (size_t)n);
    int *label = malloc(sizeof(int) * (size_t)n);
    if (!dist || !label) {
        free(dist);
        free(label);
        return false;
    }
    int first = (int)sk_rng_below(&rng, (uint32_t)n);
    memcpy(g->mean[0], x + (size_t)first * d, sizeof(double) * d);
    for (int c = 1; c < m; c++) {
        double total = 0.0;
        for (int i = 0; i < n; i++) {
            double best = INFINITY;
            for (int k = 0; k < c; k++)
                best = fmin(best, sq_distance(x + (size_t)i * d, g->mean[k], d));
            dist[i] = best;
            total += best;
        }
        double u = sk_rng_uniform(&rng) * total, acc = 0.0;
        int pick = n - 1;
        for (int i = 0; i < n; i++) {
            acc += dist[i];
            if (acc >= u) {
                pick = i;
                break;
            }
        }
        memcpy(g->mean[c], x + (size_t)pick * d, sizeof(double) * d);
    }
    for (int it = 0; it < 10; it++) {
        for (int i = 0; i < n; i++) {
            double best = INFINITY;
            for (int k = 0; k < m; k++) {
                double q = sq_distance(x + (size_t)i * d, g->mean[k], d);
                if (q < best) {
                    best = q;
                    label[i] = k;
                }
            }
        }
        for (int i = 0; i < n; i++)
            for (int k = 0; k < m; k++) resp[(size_t)i * m + k] = label[i] == k;
        mixture_m_step(g, x, n, resp, pooled, nu);
    }
    free(dist);
    free(label);
    double last = -INFINITY;
    for (int it = 0; it < 150; it++) {
        if (!mixture_factor(g)) return false;
        double ll = mixture_e_step(g, x, n, resp);
        if (ll - last < 1e-6 * fabs(ll) + 1e-9) break;
        last = ll;
        mixture_m_step(g, x, n, resp, pooled, nu);
    }
    return mixture_factor(g);
}

/* Held-out error of the way the potential is used: pin some calibrated DOFs at their
 * measured values, predict the others (the components' conditional means weighted by
 * the probability of the pinned values under each), summed over the pin patterns
 * (`masks`, one bool per calibrated DOF each) and the validation samples. Limits are left
 * out here (a closed form). */
double sk__hand_mixture_validation_error(const sk__hand_mixture *g, const double *x, int n,
                                         bool (*masks)[D_MAX], int mask_count)
{
    int d = g->d, m = g->m;
    double total = 0.0;
    for (int p = 0; p < mask_count; p++) {
        int q[D_MAX], u[D_MAX], np = 0, nu = 0;
        for (int a = 0; a < d; a++) {
            if (masks[p][a])
                q[np++] = a;
            else
                u[nu++] = a;
        }
        if (np == 0 || nu == 0) continue;
        /* per component: Cholesky of Sigma_pp and B = Sigma_up Sigma_pp^-1 (nu x np) */
        static const int M = SK_HAND_POTENTIAL_MAX_COMPONENTS;
        double chol[SK_HAND_POTENTIAL_MAX_COMPONENTS]
                   [SK_HAND_EVAL_MAX_PINS * SK_HAND_EVAL_MAX_PINS];
        double logdet[SK_HAND_POTENTIAL_MAX_COMPONENTS];
        double b[SK_HAND_POTENTIAL_MAX_COMPONENTS][D_MAX * SK_HAND_EVAL_MAX_PINS];
        (void)M;
        if (np > SK_HAND_EVAL_MAX_PINS) continue;
        bool ok = true;
        for (int c = 0; c < m && ok; c++) {
            for (int j = 0; j < np; j++)
                for (int i = 0; i < np; i++) chol[c][j * np + i] = g->cov[c][q[j] * d + q[i]];
            ok = sk__hand_cholesky(chol[c], np);
            if (!ok) break;
            logdet[c] = sk__hand_cholesky_logdet(chol[c], np);
            /* solve Sigma_pp X = Sigma_pu (np x nu), then B = X' */
            double xpu[SK_HAND_EVAL_MAX_PINS * D_MAX];
            for (int k = 0; k < nu; k++)
                for (int i = 0; i < np; i++) xpu[k * np + i] = g->cov[c][u[k] * d + q[i]];
            sk__hand_cholesky_solve(chol[c], np, xpu, nu);
            for (int k = 0; k < nu; k++)
                for (int j = 0; j < np; j++) b[c][j * nu + k] = xpu[k * np + j];
        }
        if (!ok) return INFINITY;
        for (int i = 0; i < n; i++) {
            const double *xi = x + (size_t)i * d;
            double xp[SK_HAND_EVAL_MAX_PINS], mp[SK_HAND_EVAL_MAX_PINS];
            double l[SK_HAND_POTENTIAL_MAX_COMPONENTS], top = -INFINITY, sum = 0.0;
            for (int j = 0; j < np; j++) xp[j] = xi[q[j]];
            for (int c = 0; c < m; c++) {
                for (int j = 0; j < np; j++) mp[j] = g->mean[c][q[j]];
                l[c] = log(g->weight[c]) + sk__hand_gauss_logpdf(xp, mp, chol[c], logdet[c], np);
                top = fmax(top, l[c]);
            }
            for (int c = 0; c < m; c++) sum += (l[c] = exp(l[c] - top));
            for (int k = 0; k < nu; k++) {
                double pred = 0.0;
                for (int c = 0; c < m; c++) {
                    double v = g->mean[c][u[k]];
                    for (int j = 0; j < np; j++) v += b[c][j * nu + k] * (xp[j] - g->mean[c][q[j]]);
                    pred += l[c] / sum * v;
                }
                total += (pred - xi[u[k]]) * (pred - xi[u[k]]);
            }
        }
    }
    return total;
}

void sk__hand_mixture_single(sk__hand_mixture *g, int d, const double *mu, const double *sigma)
{
    g->m = 1;
    g->d = d;
    g->weight[0] = 1.0;
    memcpy(g->mean[0], mu, sizeof(double) * d);
    memcpy(g->cov[0], sigma, sizeof(double) * (size_t)d * d);
}
