/* Calibration of the whole quadratic potential of eq. 3.17 from joint-angle samples
 * (thesis 3.2.2, steps 2 and 6, done for every joint at once): the relaxed posture
 * theta_bar (eq. 3.7) is the samples' mean and K + A'WA their precision matrix, so the
 * potential is the samples' Gaussian; both shrink toward the base set's Gaussian by a
 * prior strength chosen on held-out samples. Beyond linear (3.2.3): a mixture of such
 * Gaussians fitted by EM (poses cluster by grasp type). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "hand/gaussian_private.h"
#include "hand/potential_private.h"
#include "hand/solver_private.h"

#define D_MAX SK_HAND_DOF_COUNT

void sk_hand_potential_free(sk_hand_potential *p)
{
    if (!p) return;
    free(p->component);
    memset(p, 0, sizeof *p);
}

int sk_hand__calibrated_dofs(const bool *present, int *dof)
{
    int d = 0;
    for (int i = SK_HAND_WRIST_DOF_COUNT; i < SK_HAND_DOF_COUNT; i++)
        if (present[i] && !sk_hand_dof(i)->translation) dof[d++] = i;
    return d;
}

/* ------------------------------------------------------------ the prior */

/* The base set read as a Gaussian: K + A'WA is its precision in units of the prior
 * temperature, a spring of stiffness 1 alone giving a spread of 20 degrees (about the
 * spread of functional flexion, Hume et al. 1990, Bain et al. 2015); mean the relaxed
 * posture. Marginal on the calibrated DOFs. */
#define PRIOR_SPREAD (20.0 * SK_DEG_TO_RAD)

static bool base_gaussian(const sk_hand_skeleton *skel, const sk_hand_constraints *base,
                          const int *dof, int d, double *mu0, double *sigma0, double *base_diag)
{
    double h[SK_HAND_DOF_COUNT * SK_HAND_DOF_COUNT];
    sk_hand__equilibrium_matrix(skel, base, h);
    for (int a = 0; a < d; a++) base_diag[a] = h[(size_t)dof[a] * SK_HAND_DOF_COUNT + dof[a]];
    if (!sk_hand__spd_inverse(h, SK_HAND_DOF_COUNT)) return false;
    for (int b = 0; b < d; b++) {
        mu0[b] = skel->dof[dof[b]].relaxed;
        for (int a = 0; a < d; a++)
            sigma0[b * d + a] = PRIOR_SPREAD * PRIOR_SPREAD * h[(size_t)dof[b] * SK_HAND_DOF_COUNT + dof[a]];
    }
    return true;
}

/* Smallest variance kept on any DOF (a joint that never moved in the samples), rad^2. */
#define VARIANCE_FLOOR ((0.25 * SK_DEG_TO_RAD) * (0.25 * SK_DEG_TO_RAD))

/* Posterior mean and covariance of a normal-inverse-Wishart prior of strength nu
 * (pseudo-samples) around (mu0, sigma0) given n samples with mean xbar and scatter s. */
static void shrink(int d, int n, const double *xbar, const double *s, double nu, const double *mu0,
                   const double *sigma0, double *mu, double *sigma)
{
    double t = n + nu;
    for (int a = 0; a < d; a++) mu[a] = (n * xbar[a] + nu * mu0[a]) / t;
    double c = t > 0 ? n * nu / t : 0.0;
    for (int b = 0; b < d; b++)
        for (int a = 0; a < d; a++) {
            double v = s[b * d + a] + nu * sigma0[b * d + a] + c * (xbar[a] - mu0[a]) * (xbar[b] - mu0[b]);
            sigma[b * d + a] = v / (t > 0 ? t : 1.0);
        }
    for (int a = 0; a < d; a++) sigma[a * d + a] += VARIANCE_FLOOR;
}

/* --------------------------------------------------- held-out split */

/* Validation samples for model choices inside a fit: every fifth of 25 contiguous blocks
 * (frames next to each other are nearly the same pose), or every fifth group when there
 * are at least ten (fewer make a noisy choice). */
static bool is_validation(const sk_hand_samples *s, int k, int i, int n)
{
    if (s->group && s->group_count >= 10) return s->group[i] % 5 == 4;
    return ((long long)k * 25 / n) % 5 == 4;
}

/* ---------------------------------------------------------- mixture (EM) */

typedef struct mixture {
    int m, d;
    double weight[SK_HAND_POTENTIAL_MAX_COMPONENTS];
    double mean[SK_HAND_POTENTIAL_MAX_COMPONENTS][D_MAX];
    double cov[SK_HAND_POTENTIAL_MAX_COMPONENTS][D_MAX * D_MAX];
    double chol[SK_HAND_POTENTIAL_MAX_COMPONENTS][D_MAX * D_MAX];
    double logdet[SK_HAND_POTENTIAL_MAX_COMPONENTS];
} mixture;

static bool mixture_factor(mixture *g)
{
    for (int c = 0; c < g->m; c++) {
        memcpy(g->chol[c], g->cov[c], sizeof(double) * (size_t)g->d * g->d);
        if (!sk_hand__cholesky(g->chol[c], g->d)) return false;
        g->logdet[c] = sk_hand__cholesky_logdet(g->chol[c], g->d);
    }
    return true;
}

/* log sum_c pi_c N(x; mu_c, Sigma_c); writes the responsibilities if resp != NULL. */
static double mixture_logpdf(const mixture *g, const double *x, double *resp)
{
    double l[SK_HAND_POTENTIAL_MAX_COMPONENTS], top = -INFINITY;
    for (int c = 0; c < g->m; c++) {
        l[c] = log(g->weight[c]) + sk_hand__gauss_logpdf(x, g->mean[c], g->chol[c], g->logdet[c], g->d);
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
static void mixture_m_step(mixture *g, const double *x, int n, const double *resp, const double *pooled,
                           double nu)
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
        for (int a = 0; a < d; a++) g->cov[c][a * d + a] += VARIANCE_FLOOR;
        for (int a = 0; a < d; a++) g->mean[c][a] = mu[a];
        g->weight[c] = fmax(w / n, 1e-6);
    }
    double total = 0.0;
    for (int c = 0; c < m; c++) total += g->weight[c];
    for (int c = 0; c < m; c++) g->weight[c] /= total;
}

/* E-step; returns the total log-likelihood. */
static double mixture_e_step(const mixture *g, const double *x, int n, double *resp)
{
    double total = 0.0;
#pragma omp parallel for schedule(static) reduction(+ : total) if (n * g->m > 20000)
    for (int i = 0; i < n; i++) total += mixture_logpdf(g, x + (size_t)i * g->d, resp + (size_t)i * g->m);
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
static bool mixture_fit(mixture *g, const double *x, int n, int d, int m, const double *pooled, double nu,
                        uint64_t seed, double *resp)
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
            for (int k = 0; k < c; k++) best = fmin(best, sq_distance(x + (size_t)i * d, g->mean[k], d));
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
static double validation_error(const mixture *g, const double *x, int n, bool (*masks)[D_MAX],
                               int mask_count)
{
    int d = g->d, m = g->m;
    double total = 0.0;
    for (int p = 0; p < mask_count; p++) {
        int q[D_MAX], u[D_MAX], np = 0, nu = 0;
        for (int a = 0; a < d; a++) {
            if (masks[p][a]) q[np++] = a;
            else u[nu++] = a;
        }
        if (np == 0 || nu == 0) continue;
        /* per component: Cholesky of Sigma_pp and B = Sigma_up Sigma_pp^-1 (nu x np) */
        static const int M = SK_HAND_POTENTIAL_MAX_COMPONENTS;
        double chol[SK_HAND_POTENTIAL_MAX_COMPONENTS][SK_HAND_EVAL_MAX_PINS * SK_HAND_EVAL_MAX_PINS];
        double logdet[SK_HAND_POTENTIAL_MAX_COMPONENTS];
        double b[SK_HAND_POTENTIAL_MAX_COMPONENTS][D_MAX * SK_HAND_EVAL_MAX_PINS];
        (void)M;
        if (np > SK_HAND_EVAL_MAX_PINS) continue;
        bool ok = true;
        for (int c = 0; c < m && ok; c++) {
            for (int j = 0; j < np; j++)
                for (int i = 0; i < np; i++) chol[c][j * np + i] = g->cov[c][q[j] * d + q[i]];
            ok = sk_hand__cholesky(chol[c], np);
            if (!ok) break;
            logdet[c] = sk_hand__cholesky_logdet(chol[c], np);
            /* solve Sigma_pp X = Sigma_pu (np x nu), then B = X' */
            double xpu[SK_HAND_EVAL_MAX_PINS * D_MAX];
            for (int k = 0; k < nu; k++)
                for (int i = 0; i < np; i++) xpu[k * np + i] = g->cov[c][u[k] * d + q[i]];
            sk_hand__cholesky_solve(chol[c], np, xpu, nu);
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
                l[c] = log(g->weight[c]) + sk_hand__gauss_logpdf(xp, mp, chol[c], logdet[c], np);
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

static void mixture_single(mixture *g, int d, const double *mu, const double *sigma)
{
    g->m = 1;
    g->d = d;
    g->weight[0] = 1.0;
    memcpy(g->mean[0], mu, sizeof(double) * d);
    memcpy(g->cov[0], sigma, sizeof(double) * (size_t)d * d);
}

/* ------------------------------------------------------- thesis form */

/* Springs and rows of one component from its precision H = scale x Sigma^-1 (over the
 * calibrated DOFs): springs K = half the part of H that no coupling explains (K_i =
 * lambda_min / 2 x H_ii, lambda_min the smallest eigenvalue of H scaled to unit
 * diagonal), and rows from the Cholesky factor of H - K = L L': row j relates DOF j to
 * the DOFs after it, theta_j + sum_k (L_kj / L_jj) theta_k = 0 with weight L_jj^2, so
 * K + A'WA = H exactly and b = 0. */
static sk_result to_thesis_form(const sk_hand_skeleton *skel, const sk_hand_constraints *base, const int *dof,
                                int d, const double *mean, const double *cov, double scale,
                                sk_hand_potential_component *out, sk_error *err)
{
    double h[D_MAX * D_MAX], r[D_MAX * D_MAX], ev[D_MAX];
    memcpy(h, cov, sizeof(double) * (size_t)d * d);
    if (!sk_hand__spd_inverse(h, d))
        return sk_fail(err, SK_ERROR_NUMERIC, "the samples' covariance is not positive definite");
    for (int i = 0; i < d * d; i++) h[i] *= scale;
    for (int b = 0; b < d; b++)
        for (int a = 0; a < d; a++) r[b * d + a] = h[b * d + a] / sqrt(h[a * d + a] * h[b * d + b]);
    if (!sk_hand__sym_eigen(r, d, ev, false) || !(ev[0] > 0))
        return sk_fail(err, SK_ERROR_NUMERIC, "the samples' precision matrix is not positive definite");
    bool calibrated[SK_HAND_DOF_COUNT] = {false};
    for (int a = 0; a < d; a++) calibrated[dof[a]] = true;
    sk_hand_constraints *c = &out->constraints;
    memset(c, 0, sizeof *c);
    for (int i = 0; i < SK_HAND_DOF_COUNT; i++) {
        out->relaxed[i] = skel->dof[i].relaxed;
        c->has_stiffness[i] = true;
        c->stiffness[i] = base && base->has_stiffness[i] ? base->stiffness[i] : skel->dof[i].stiffness;
    }
    /* the base rows that stay: those among DOFs outside the samples */
    for (int k = 0; base && k < base->row_count; k++) {
        const sk_hand_row *row = &base->rows[k];
        bool outside = true;
        for (int t = 0; t < row->term_count; t++) outside &= !calibrated[row->dof[t]];
        if (outside) c->rows[c->row_count++] = *row;
    }
    double l[D_MAX * D_MAX];
    for (int a = 0; a < d; a++) {
        double k = 0.5 * ev[0] * h[a * d + a];
        c->stiffness[dof[a]] = k;
        out->relaxed[dof[a]] = sk_clampd(mean[a], skel->dof[dof[a]].min, skel->dof[dof[a]].max);
        for (int b = 0; b < d; b++) l[b * d + a] = h[b * d + a] - (a == b ? k : 0.0);
    }
    if (!sk_hand__cholesky(l, d))
        return sk_fail(err, SK_ERROR_NUMERIC, "the coupling part of the precision is not positive definite");
    for (int j = 0; j < d; j++) {
        if (c->row_count >= SK_HAND_MAX_ROWS)
            return sk_fail(err, SK_ERROR_LIMIT, "more than %d rows", SK_HAND_MAX_ROWS);
        double ljj = l[j * d + j];
        sk_hand_row *row = &c->rows[c->row_count];
        memset(row, 0, sizeof *row);
        for (int k = j; k < d; k++) {
            double v = l[j * d + k] / ljj;
            if (k > j && v == 0.0) continue;
            row->dof[row->term_count] = dof[k];
            row->coeff[row->term_count++] = v;
        }
        row->b = 0.0;
        row->weight = ljj * ljj;
        snprintf(row->label, sizeof row->label, "%s on the joints after it", sk_hand_dof(dof[j])->name);
        if (row->term_count == 1) snprintf(row->label, sizeof row->label, "%s alone", sk_hand_dof(dof[j])->name);
        c->row_count++;
    }
    return SK_OK;
}

/* ------------------------------------------------------------------ fit */

static const double PRIOR_GRID[] = {1, 4, 16, 64, 256};

sk_result sk_hand_potential_fit(sk_hand_potential *out, const sk_hand_skeleton *skel,
                                const sk_hand_samples *s, const int *idx, int n,
                                const sk_hand_potential_desc *desc, sk_error *err)
{
    memset(out, 0, sizeof *out);
    sk_hand_potential_desc dd = {0};
    if (desc) dd = *desc;
    if (dd.method == SK_HAND_POTENTIAL_DEFAULT) dd.method = SK_HAND_POTENTIAL_MIXTURE;
    if (dd.method != SK_HAND_POTENTIAL_GAUSSIAN && dd.method != SK_HAND_POTENTIAL_MIXTURE)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "method = %d is not gaussian or mixture", (int)dd.method);
    if (dd.max_components == 0) dd.max_components = 6;
    sk_result r = sk_check_range_i(err, "max_components", dd.max_components, 1, SK_HAND_POTENTIAL_MAX_COMPONENTS);
    if (r == SK_OK) r = sk_check_range_i(err, "components", dd.components, 0, SK_HAND_POTENTIAL_MAX_COMPONENTS);
    if (r == SK_OK && !isnan(dd.prior_strength) && dd.prior_strength > 1e7)
        r = sk_check_range_f(err, "prior_strength", dd.prior_strength, -INFINITY, 1e7);
    if (r == SK_OK && isnan(dd.prior_strength))
        r = sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "prior_strength is not a number");
    if (r != SK_OK) return r;
    if (dd.method == SK_HAND_POTENTIAL_GAUSSIAN) dd.components = 1;
    if (!idx) n = s->count;
    if (n < 1 || n > s->count) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "%d samples to fit (need 1 to %d)", n, s->count);
    int dof[D_MAX];
    int d = sk_hand__calibrated_dofs(s->present, dof);
    if (d == 0) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "the samples have no joint-angle column");
    for (int k = 0; k < n; k++)
        if (idx && (idx[k] < 0 || idx[k] >= s->count))
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "sample index %d is out of range", idx[k]);

    /* the pin patterns of the held-out choices: the given ones, or each DOF alone */
    bool masks[SK_HAND_EVAL_MAX_PIN_SETS > D_MAX ? SK_HAND_EVAL_MAX_PIN_SETS : D_MAX][D_MAX];
    memset(masks, 0, sizeof masks);
    int mask_count = 0;
    if (dd.pin_set_count > 0) {
        r = sk_check_range_i(err, "pin_set_count", dd.pin_set_count, 0, SK_HAND_EVAL_MAX_PIN_SETS);
        if (r != SK_OK) return r;
        for (int p = 0; p < dd.pin_set_count; p++, mask_count++)
            for (int k = 0; k < dd.pin_sets[p].count && k < SK_HAND_EVAL_MAX_PINS; k++)
                for (int a = 0; a < d; a++)
                    if (dof[a] == dd.pin_sets[p].dof[k]) masks[mask_count][a] = true;
    } else {
        for (int a = 0; a < d; a++) masks[mask_count++][a] = true;
    }
    double mu0[D_MAX], sigma0[D_MAX * D_MAX], base_diag[D_MAX];
    if (!base_gaussian(skel, dd.base, dof, d, mu0, sigma0, base_diag))
        return sk_fail(err, SK_ERROR_NUMERIC, "the base set's K + A'WA is not positive definite");

    /* samples as rows, training part first, validation part after */
    double *x = malloc(sizeof(double) * (size_t)n * d);
    int *order = malloc(sizeof(int) * (size_t)n);
    if (!x || !order) {
        free(x);
        free(order);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for %d samples", n);
    }
    int nt = 0;
    for (int pass = 0; pass < 2; pass++)
        for (int k = 0; k < n; k++) {
            int i = idx ? idx[k] : k;
            if (is_validation(s, k, i, n) == (pass == 1)) order[nt++] = i;
        }
    int n_train = 0;
    for (int k = 0; k < n; k++) n_train += !is_validation(s, k, idx ? idx[k] : k, n);
    for (int k = 0; k < n; k++)
        for (int a = 0; a < d; a++) x[(size_t)k * d + a] = s->column[dof[a]][order[k]];
    int n_val = n - n_train;
    bool can_validate = n_train >= 2 && n_val >= 2;

    double xbar[D_MAX], scatter[D_MAX * D_MAX], mu[D_MAX], sigma[D_MAX * D_MAX];
    /* the prior strength: given, or the one whose Gaussian best predicts held-out samples */
    double nu = dd.prior_strength < 0 ? 0.0 : dd.prior_strength;
    mixture *g = malloc(sizeof *g);
    double *resp = malloc(sizeof(double) * (size_t)n * SK_HAND_POTENTIAL_MAX_COMPONENTS);
    if (!g || !resp) {
        free(x);
        free(order);
        free(g);
        free(resp);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for %d samples", n);
    }
    if (dd.prior_strength == 0.0) {
        nu = PRIOR_GRID[2];
        if (can_validate) {
            sk_hand__moments(s, dof, d, order, n_train, xbar, scatter);
            double best = INFINITY;
            for (size_t k = 0; k < sizeof PRIOR_GRID / sizeof PRIOR_GRID[0]; k++) {
                shrink(d, n_train, xbar, scatter, PRIOR_GRID[k], mu0, sigma0, mu, sigma);
                mixture_single(g, d, mu, sigma);
                double e = validation_error(g, x + (size_t)n_train * d, n_val, masks, mask_count);
                if (e < best) {
                    best = e;
                    nu = PRIOR_GRID[k];
                }
            }
        }
    }
    /* the single Gaussian on all samples, and the scale that keeps the base set's units:
       the mean diagonal of K + A'WA equals the base set's on these DOFs */
    sk_hand__moments(s, dof, d, order, n, xbar, scatter);
    shrink(d, n, xbar, scatter, nu, mu0, sigma0, mu, sigma);
    double prec[D_MAX * D_MAX];
    memcpy(prec, sigma, sizeof prec);
    if (!sk_hand__spd_inverse(prec, d)) {
        free(x);
        free(order);
        return sk_fail(err, SK_ERROR_NUMERIC, "the samples' covariance is not positive definite");
    }
    double tr_base = 0.0, tr_prec = 0.0;
    for (int a = 0; a < d; a++) {
        tr_base += base_diag[a];
        tr_prec += prec[a * d + a];
    }
    double scale = tr_base / tr_prec;

    /* the mixture: component count by held-out prediction error, then refitted on all */
    const double nu_component = 2.0 * d;
    int m = dd.components;
    if (m == 0) {
        m = 1;
        if (can_validate && dd.max_components > 1) {
            double pooled_t[D_MAX * D_MAX], mu_t[D_MAX];
            sk_hand__moments(s, dof, d, order, n_train, xbar, scatter);
            shrink(d, n_train, xbar, scatter, nu, mu0, sigma0, mu_t, pooled_t);
            mixture_single(g, d, mu_t, pooled_t);
            double best = validation_error(g, x + (size_t)n_train * d, n_val, masks, mask_count);
            for (int c = 2; c <= dd.max_components && c <= n_train / (2 * d + 2); c++) {
                if (!mixture_fit(g, x, n_train, d, c, pooled_t, nu_component, dd.seed, resp)) continue;
                double e = validation_error(g, x + (size_t)n_train * d, n_val, masks, mask_count);
                if (e < best) {
                    best = e;
                    m = c;
                }
            }
        }
    }
    if (m > 1 && (n < m * (d + 1) || !mixture_fit(g, x, n, d, m, sigma, nu_component, dd.seed, resp))) m = 1;
    if (m == 1) mixture_single(g, d, mu, sigma);
    free(x);
    free(order);
    free(resp);

    out->component = calloc((size_t)m, sizeof *out->component);
    if (!out->component) {
        free(g);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    }
    out->dof_count = d;
    memcpy(out->dof, dof, sizeof(int) * d);
    out->scale = scale;
    out->sample_count = n;
    out->prior_strength = nu;
    out->component_count = m;
    for (int c = 0; c < m && r == SK_OK; c++) {
        out->component[c].weight = g->weight[c];
        r = to_thesis_form(skel, dd.base, dof, d, g->mean[c], g->cov[c], scale, &out->component[c], err);
    }
    free(g);
    if (r != SK_OK) sk_hand_potential_free(out);
    return r;
}

sk_result sk_hand_potential_gaussian(const sk_hand_potential *p, int m, double *mean, double *cov,
                                     sk_error *err)
{
    if (m < 0 || m >= p->component_count)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "component %d is out of range [0, %d]", m,
                       p->component_count - 1);
    int d = p->dof_count;
    const sk_hand_potential_component *c = &p->component[m];
    int at[SK_HAND_DOF_COUNT];
    for (int i = 0; i < SK_HAND_DOF_COUNT; i++) at[i] = -1;
    for (int a = 0; a < d; a++) at[p->dof[a]] = a;
    double h[D_MAX * D_MAX] = {0};
    for (int a = 0; a < d; a++) {
        h[a * d + a] = c->constraints.stiffness[p->dof[a]];
        mean[a] = c->relaxed[p->dof[a]];
    }
    for (int k = 0; k < c->constraints.row_count; k++) {
        const sk_hand_row *row = &c->constraints.rows[k];
        for (int s = 0; s < row->term_count; s++)
            for (int t = 0; t < row->term_count; t++) {
                int i = at[row->dof[s]], j = at[row->dof[t]];
                if (i < 0 || j < 0) continue;
                h[j * d + i] += row->weight * row->coeff[s] * row->coeff[t];
            }
    }
    if (!sk_hand__spd_inverse(h, d))
        return sk_fail(err, SK_ERROR_NUMERIC, "component %d: K + A'WA is not positive definite", m);
    for (int i = 0; i < d * d; i++) cov[i] = h[i] * p->scale;
    return SK_OK;
}
