/* Calibration of the whole quadratic potential of eq. 3.17 from joint-angle samples
 * (thesis 3.2.2, steps 2 and 6, done for every joint at once): the relaxed posture
 * theta_bar (eq. 3.7) is the samples' mean and K + A'WA their precision matrix, so the
 * potential is the samples' Gaussian; both shrink toward the base set's Gaussian by a
 * prior strength chosen on held-out samples. Beyond linear (3.2.3): a mixture of such
 * Gaussians fitted by EM (poses cluster by grasp type). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "models/hand/gaussian_internal.h"
#include "models/hand/mixture_internal.h"
#include "models/hand/potential_internal.h"
#include "models/hand/solver_internal.h"

#define D_MAX SK_HAND_DOF_COUNT

void sk_hand_potential_free(sk_hand_potential *p)
{
    if (!p) return;
    free(p->component);
    memset(p, 0, sizeof *p);
}

int sk__hand_calibrated_dofs(const bool *present, int *dof)
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
#define PRIOR_SPREAD SK_HAND__PRIOR_SPREAD

static bool base_gaussian(const sk_hand_skeleton *skel, const sk_hand_constraints *base,
                          const int *dof, int d, double *mu0, double *sigma0, double *base_diag)
{
    double h[SK_HAND_DOF_COUNT * SK_HAND_DOF_COUNT];
    sk__hand_equilibrium_matrix(skel, base, h);
    for (int a = 0; a < d; a++) base_diag[a] = h[(size_t)dof[a] * SK_HAND_DOF_COUNT + dof[a]];
    if (!sk__hand_spd_inverse(h, SK_HAND_DOF_COUNT)) return false;
    for (int b = 0; b < d; b++) {
        mu0[b] = skel->dof[dof[b]].relaxed;
        for (int a = 0; a < d; a++)
            sigma0[b * d + a] =
                PRIOR_SPREAD * PRIOR_SPREAD * h[(size_t)dof[b] * SK_HAND_DOF_COUNT + dof[a]];
    }
    return true;
}

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
            double v =
                s[b * d + a] + nu * sigma0[b * d + a] + c * (xbar[a] - mu0[a]) * (xbar[b] - mu0[b]);
            sigma[b * d + a] = v / (t > 0 ? t : 1.0);
        }
    for (int a = 0; a < d; a++) sigma[a * d + a] += SK_HAND__VARIANCE_FLOOR;
}

/* --------------------------------------------------- held-out split */

/* Validation samples for model choices inside a fit: a fifth of 100 contiguous blocks
 * (frames next to each other are nearly the same pose), or a fifth of the groups when
 * there are at least ten (fewer make a noisy choice). Which blocks or groups is decided
 * by a hash of their number: recordings are usually ordered (person by person, grasp by
 * grasp), and every fifth block of an ordered file would always hold the same grasps. */
static bool is_validation(const sk_hand_samples *s, int k, int i, int n)
{
    if (s->group && s->group_count >= 10)
        return sk_hash(0x76616c, (uint64_t)s->group[i], 1, 0) % 5 == 0;
    long long block = (long long)k * 100 / n;
    return sk_hash(0x76616c, (uint64_t)block, 0, 0) % 5 == 0;
}

/* ------------------------------------------------------- thesis form */

/* Springs and rows of one component from its precision H = scale x Sigma^-1 (over the
 * calibrated DOFs): springs K = half the part of H that no coupling explains (K_i =
 * lambda_min / 2 x H_ii, lambda_min the smallest eigenvalue of H scaled to unit
 * diagonal), and rows from the Cholesky factor of H - K = L L': row j relates DOF j to
 * the DOFs after it, theta_j + sum_k (L_kj / L_jj) theta_k = 0 with weight L_jj^2, so
 * K + A'WA = H exactly and b = 0. */
static sk_result to_thesis_form(const sk_hand_skeleton *skel, const sk_hand_constraints *base,
                                const int *dof, int d, const double *mean, const double *cov,
                                double scale, sk_hand_potential_component *out, sk_error *err)
{
    double h[D_MAX * D_MAX], r[D_MAX * D_MAX], ev[D_MAX];
    memcpy(h, cov, sizeof(double) * (size_t)d * d);
    if (!sk__hand_spd_inverse(h, d))
        return sk_fail(err, SK_ERROR_NUMERIC, "the samples' covariance is not positive definite");
    for (int i = 0; i < d * d; i++) h[i] *= scale;
    for (int b = 0; b < d; b++)
        for (int a = 0; a < d; a++) r[b * d + a] = h[b * d + a] / sqrt(h[a * d + a] * h[b * d + b]);
    if (!sk__hand_sym_eigen(r, d, ev, false) || !(ev[0] > 0))
        return sk_fail(err, SK_ERROR_NUMERIC,
                       "the samples' precision matrix is not positive definite");
    bool calibrated[SK_HAND_DOF_COUNT] = {false};
    for (int a = 0; a < d; a++) calibrated[dof[a]] = true;
    sk_hand_constraints *c = &out->constraints;
    memset(c, 0, sizeof *c);
    for (int i = 0; i < SK_HAND_DOF_COUNT; i++) {
        out->relaxed[i] = skel->dof[i].relaxed;
        c->has_stiffness[i] = true;
        c->stiffness[i] =
            base && base->has_stiffness[i] ? base->stiffness[i] : skel->dof[i].stiffness;
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
    if (!sk__hand_cholesky(l, d))
        return sk_fail(err, SK_ERROR_NUMERIC,
                       "the coupling part of the precision is not positive definite");
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
        snprintf(row->label, sizeof row->label, "%s on the joints after it",
                 sk_hand_dof(dof[j])->name);
        if (row->term_count == 1)
            snprintf(row->label, sizeof row->label, "%s alone", sk_hand_dof(dof[j])->name);
        c->row_count++;
    }
    return SK_OK;
}

/* ------------------------------------------------------------------ fit */

static const double PRIOR_GRID[] = {1, 4, 16, 64, 256};

/* One key of the desc within the range sk_hand_potential_schema states. */
static sk_result check_key(const sk_hand_potential_desc *d, const char *key, sk_error *err)
{
    return sk_schema_check_field(sk_schema_find(&sk_hand_potential_schema, key), d, key, err);
}

void sk__hand_fit_data_free(sk__hand_fit_data *fd)
{
    free(fd->x);
    fd->x = NULL;
}

sk_result sk__hand_fit_prepare(sk__hand_fit_data *fd, const sk_hand_skeleton *skel,
                               const sk_hand_samples *s, const int *idx, int n,
                               const sk_hand_potential_desc *desc, sk_error *err)
{
    memset(fd, 0, sizeof *fd);
    const sk_hand_potential_desc dd = *desc;
    sk_result r = check_key(&dd, "prior_strength", err);
    if (r == SK_OK)
        r = sk_check_range_i(err, "pin_set_count", dd.pin_set_count, 0, SK_HAND_EVAL_MAX_PIN_SETS);
    if (r != SK_OK) return r;
    if (!idx) n = s->count;
    if (n < 1 || n > s->count)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "%d samples to fit (need 1 to %d)", n,
                       s->count);
    int d = fd->d = sk__hand_calibrated_dofs(s->present, fd->dof);
    const int *dof = fd->dof;
    if (d == 0)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "the samples have no joint-angle column");
    for (int k = 0; k < n; k++)
        if (idx && (idx[k] < 0 || idx[k] >= s->count))
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "sample index %d is out of range",
                           idx[k]);

    /* the pin patterns of the held-out choices: the given ones, or each DOF alone */
    if (dd.pin_set_count > 0) {
        for (int p = 0; p < dd.pin_set_count; p++, fd->mask_count++)
            for (int k = 0; k < dd.pin_sets[p].count && k < SK_HAND_EVAL_MAX_PINS; k++)
                for (int a = 0; a < d; a++)
                    if (dof[a] == dd.pin_sets[p].dof[k]) fd->masks[fd->mask_count][a] = true;
    } else {
        for (int a = 0; a < d; a++) fd->masks[fd->mask_count++][a] = true;
    }
    if (!base_gaussian(skel, dd.base, dof, d, fd->mu0, fd->sigma0, fd->base_diag))
        return sk_fail(err, SK_ERROR_NUMERIC, "the base set's K + A'WA is not positive definite");

    /* samples as rows, training part first, validation part after */
    fd->x = malloc(sizeof(double) * (size_t)n * d);
    int *order = malloc(sizeof(int) * (size_t)n);
    sk__hand_mixture *g = malloc(sizeof *g);
    if (!fd->x || !order || !g) {
        free(order);
        free(g);
        sk__hand_fit_data_free(fd);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for %d samples", n);
    }
    int nt = 0;
    for (int pass = 0; pass < 2; pass++)
        for (int k = 0; k < n; k++) {
            int i = idx ? idx[k] : k;
            if (is_validation(s, k, i, n) == (pass == 1)) order[nt++] = i;
        }
    fd->n = n;
    for (int k = 0; k < n; k++) fd->n_train += !is_validation(s, k, idx ? idx[k] : k, n);
    for (int k = 0; k < n; k++)
        for (int a = 0; a < d; a++) fd->x[(size_t)k * d + a] = s->column[dof[a]][order[k]];
    fd->n_val = n - fd->n_train;
    fd->can_validate = fd->n_train >= 2 && fd->n_val >= 2;

    /* the prior strength: given, or the one whose Gaussian best predicts held-out samples */
    double xbar[D_MAX], scatter[D_MAX * D_MAX];
    sk__hand_moments(s, dof, d, order, fd->n_train, xbar, scatter);
    fd->nu = dd.prior_strength < 0 ? 0.0 : dd.prior_strength;
    if (dd.prior_strength == 0.0) {
        fd->nu = PRIOR_GRID[2];
        if (fd->can_validate) {
            double best = INFINITY;
            for (size_t k = 0; k < sizeof PRIOR_GRID / sizeof PRIOR_GRID[0]; k++) {
                shrink(d, fd->n_train, xbar, scatter, PRIOR_GRID[k], fd->mu0, fd->sigma0,
                       fd->mu_train, fd->sigma_train);
                sk__hand_mixture_single(g, d, fd->mu_train, fd->sigma_train);
                double e = sk__hand_mixture_validation_error(g, fd->x + (size_t)fd->n_train * d,
                                                             fd->n_val, fd->masks, fd->mask_count);
                if (e < best) {
                    best = e;
                    fd->nu = PRIOR_GRID[k];
                }
            }
        }
    }
    shrink(d, fd->n_train, xbar, scatter, fd->nu, fd->mu0, fd->sigma0, fd->mu_train,
           fd->sigma_train);
    sk__hand_moments(s, dof, d, order, n, xbar, scatter);
    shrink(d, n, xbar, scatter, fd->nu, fd->mu0, fd->sigma0, fd->mu, fd->sigma);
    free(order);
    free(g);
    return SK_OK;
}

/* The mixture (one Gaussian or more) on prepared samples. */
static sk_result mixture_fit(sk_hand_potential *out, const sk_hand_skeleton *skel,
                             sk__hand_fit_data *fd, const sk_hand_potential_desc *dd, sk_error *err)
{
    int d = fd->d, n = fd->n;
    const double *x = fd->x;
    /* the scale that keeps the base set's units: the mean diagonal of K + A'WA equals the
       base set's on these DOFs */
    double prec[D_MAX * D_MAX];
    memcpy(prec, fd->sigma, sizeof prec);
    if (!sk__hand_spd_inverse(prec, d))
        return sk_fail(err, SK_ERROR_NUMERIC, "the samples' covariance is not positive definite");
    double tr_base = 0.0, tr_prec = 0.0;
    for (int a = 0; a < d; a++) {
        tr_base += fd->base_diag[a];
        tr_prec += prec[a * d + a];
    }
    double scale = tr_base / tr_prec;

    sk__hand_mixture *g = malloc(sizeof *g);
    double *resp = malloc(sizeof(double) * (size_t)n * SK_HAND_POTENTIAL_MAX_COMPONENTS);
    if (!g || !resp) {
        free(g);
        free(resp);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for %d samples", n);
    }
    /* the component count by held-out prediction error, then refitted on all */
    const double nu_component = 2.0 * d;
    int m = dd->components;
    if (m == 0) {
        m = 1;
        if (fd->can_validate && dd->max_components > 1) {
            sk__hand_mixture_single(g, d, fd->mu_train, fd->sigma_train);
            const double *xv = x + (size_t)fd->n_train * d;
            double best =
                sk__hand_mixture_validation_error(g, xv, fd->n_val, fd->masks, fd->mask_count);
            /* counts on a coarse grid: each EM fit costs about its count */
            static const int COUNTS[] = {2, 3, 4, 6, 8, 12, 16};
            for (size_t ci = 0; ci < sizeof COUNTS / sizeof COUNTS[0]; ci++) {
                int c = COUNTS[ci];
                if (c > dd->max_components || c > fd->n_train / (2 * d + 2)) break;
                if (!sk__hand_mixture_fit(g, x, fd->n_train, d, c, fd->sigma_train, nu_component,
                                          dd->seed, resp))
                    continue;
                double e =
                    sk__hand_mixture_validation_error(g, xv, fd->n_val, fd->masks, fd->mask_count);
                if (e < best) {
                    best = e;
                    m = c;
                }
            }
        }
    }
    if (m > 1 && (n < m * (d + 1) ||
                  !sk__hand_mixture_fit(g, x, n, d, m, fd->sigma, nu_component, dd->seed, resp)))
        m = 1;
    if (m < 1 || m > SK_HAND_POTENTIAL_MAX_COMPONENTS) m = 1;
    if (m == 1) sk__hand_mixture_single(g, d, fd->mu, fd->sigma);
    free(resp);

    out->component = calloc((size_t)m, sizeof *out->component);
    if (!out->component) {
        free(g);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    }
    out->scale = scale;
    out->component_count = m;
    sk_result r = SK_OK;
    for (int c = 0; c < m && r == SK_OK; c++) {
        out->component[c].weight = g->weight[c];
        r = to_thesis_form(skel, dd->base, fd->dof, d, g->mean[c], g->cov[c], scale,
                           &out->component[c], err);
    }
    free(g);
    return r;
}

sk_result sk_hand_potential_fit(sk_hand_potential *out, const sk_hand_skeleton *skel,
                                const sk_hand_samples *s, const int *idx, int n,
                                const sk_hand_potential_desc *desc, sk_error *err)
{
    memset(out, 0, sizeof *out);
    sk_hand_potential_desc dd = {0};
    if (desc) dd = *desc;
    if (dd.method == SK_HAND_POTENTIAL_DEFAULT) dd.method = SK_HAND_POTENTIAL_MIXTURE;
    if (dd.method != SK_HAND_POTENTIAL_GAUSSIAN && dd.method != SK_HAND_POTENTIAL_MIXTURE &&
        dd.method != SK_HAND_POTENTIAL_PAIRS)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "method = %d is not gaussian, mixture or pairs", (int)dd.method);
    if (dd.max_components == 0)
        dd.max_components = (int)sk_schema_find(&sk_hand_potential_schema, "max_components")->def;
    sk_result r = check_key(&dd, "max_components", err);
    if (r == SK_OK) r = check_key(&dd, "components", err);
    if (r != SK_OK) return r;
    if (dd.method != SK_HAND_POTENTIAL_MIXTURE) dd.components = 1;
    sk__hand_fit_data *fd = malloc(sizeof *fd);
    if (!fd) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    r = sk__hand_fit_prepare(fd, skel, s, idx, n, &dd, err);
    if (r == SK_OK) {
        if (dd.method == SK_HAND_POTENTIAL_PAIRS)
            r = sk__hand_pairs_fit(out, skel, fd, &dd, err);
        else
            r = mixture_fit(out, skel, fd, &dd, err);
        out->dof_count = fd->d;
        memcpy(out->dof, fd->dof, sizeof(int) * (size_t)fd->d);
        out->sample_count = fd->n;
        out->prior_strength = fd->nu;
        sk__hand_fit_data_free(fd);
    }
    free(fd);
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
    if (!sk__hand_spd_inverse(h, d))
        return sk_fail(err, SK_ERROR_NUMERIC, "component %d: K + A'WA is not positive definite", m);
    for (int i = 0; i < d * d; i++) cov[i] = h[i] * p->scale;
    return SK_OK;
}
