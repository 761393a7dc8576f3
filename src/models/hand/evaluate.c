/* Held-out evaluation of natural-posture models (thesis 3.2: pin some joints, the model
 * poses the rest): cross-validation by contiguous blocks or by groups (trials, people),
 * the model's RMS error on the unpinned joints against three baselines fitted on the
 * same folds: the training mean, linear regression, and a PCA prior with k components. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "models/hand/gaussian_internal.h"
#include "models/hand/potential_internal.h"

#define D_MAX SK_HAND_DOF_COUNT
#define NP_MAX SK_HAND_EVAL_MAX_PIN_SETS
#define SK_HAND_EVAL_MAX_LUTS 64

sk_result sk_hand_parse_pin_set(const char *text, sk_hand_pin_set *out, sk_error *err)
{
    memset(out, 0, sizeof *out);
    const char *p = text;
    while (*p) {
        size_t n = strcspn(p, ",");
        char name[64];
        if (n == 0 || n >= sizeof name)
            return sk_fail(err, SK_ERROR_PARSE,
                           "pins \"%.80s\": expected DOF names separated by commas", text);
        memcpy(name, p, n);
        name[n] = '\0';
        int d = sk_hand_dof_find(name);
        if (d < 0)
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "pins \"%.80s\": unknown DOF \"%s\"",
                           text, name);
        for (int i = 0; i < out->count; i++)
            if (out->dof[i] == d)
                return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "pins \"%.80s\": %s appears twice",
                               text, name);
        if (out->count >= SK_HAND_EVAL_MAX_PINS)
            return sk_fail(err, SK_ERROR_LIMIT, "pins \"%.80s\": more than %d DOFs", text,
                           SK_HAND_EVAL_MAX_PINS);
        out->dof[out->count++] = d;
        p += n;
        if (*p == ',') p++;
        if (*p == '\0' && p[-1] == ',')
            return sk_fail(err, SK_ERROR_PARSE, "pins \"%.80s\": a trailing comma", text);
    }
    if (out->count == 0)
        return sk_fail(err, SK_ERROR_PARSE, "pins: empty (expected e.g. I.MCP.flex,I.PIP.flex)");
    return SK_OK;
}

/* Linear predictor x_u = mu_u + B (x_p - mu_p) from a covariance (conditional mean). */
typedef struct predictor {
    double mu[D_MAX];
    double b[D_MAX * SK_HAND_EVAL_MAX_PINS]; /* nu x np */
    bool ok;
} predictor;

static void predictor_from_cov(predictor *pr, const double *mu, const double *cov, int d,
                               const bool *pinned)
{
    double prec[D_MAX * D_MAX];
    memcpy(prec, cov, sizeof(double) * (size_t)d * d);
    memcpy(pr->mu, mu, sizeof(double) * d);
    pr->ok = sk__hand_spd_inverse(prec, d) && sk__hand_conditional(prec, d, pinned, pr->b);
}

static void predictor_apply(const predictor *pr, int d, const bool *pinned, const double *x,
                            double *out)
{
    int np = 0, q[D_MAX];
    for (int a = 0; a < d; a++)
        if (pinned[a]) q[np++] = a;
    int nu = d - np, u = 0;
    for (int a = 0; a < d; a++) {
        if (pinned[a]) {
            out[a] = x[a];
            continue;
        }
        double v = pr->mu[a];
        if (pr->ok)
            for (int j = 0; j < np; j++) v += pr->b[j * nu + u] * (x[q[j]] - pr->mu[q[j]]);
        out[a] = v;
        u++;
    }
}

/* Probabilistic PCA covariance: top k directions, isotropic rest at the mean discarded
 * eigenvalue (Tipping & Bishop 1999). */
static bool ppca_cov(const double *cov, int d, int k, double *out)
{
    double v[D_MAX * D_MAX], ev[D_MAX];
    memcpy(v, cov, sizeof(double) * (size_t)d * d);
    if (!sk__hand_sym_eigen(v, d, ev, true)) return false;
    double rest = 0.0;
    for (int i = 0; i < d - k; i++) rest += ev[i];
    double s2 = d > k ? rest / (d - k) : 0.0;
    s2 = fmax(s2, 1e-12);
    for (int b = 0; b < d; b++)
        for (int a = 0; a < d; a++) {
            double sum = a == b ? s2 : 0.0;
            for (int i = d - k; i < d; i++) sum += (ev[i] - s2) * v[i * d + a] * v[i * d + b];
            out[b * d + a] = sum;
        }
    return true;
}

/* The model of a fold as a potential: calibrated on the training samples, or a fixed or
 * refitted set as a one-component potential around the built-in relaxed posture. */
static sk_result fold_model(const sk_hand_skeleton *skel, const sk_hand_samples *s, const int *dof,
                            int d, const int *train, int nt, const sk_hand_evaluation_desc *desc,
                            sk_hand_potential *pot, sk_error *err)
{
    if (desc->model == SK_HAND_EVAL_MODEL_CALIBRATED)
        return sk_hand_potential_fit(pot, skel, s, train, nt, &desc->potential, err);
    memset(pot, 0, sizeof *pot);
    pot->component = calloc(1, sizeof *pot->component);
    if (!pot->component) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    pot->component_count = 1;
    pot->dof_count = d;
    memcpy(pot->dof, dof, sizeof(int) * d);
    pot->scale = 1.0;
    pot->sample_count = nt;
    sk_hand_potential_component *c = &pot->component[0];
    c->weight = 1.0;
    for (int i = 0; i < SK_HAND_DOF_COUNT; i++) c->relaxed[i] = skel->dof[i].relaxed;
    sk_result r = SK_OK;
    if (desc->model == SK_HAND_EVAL_MODEL_FIXED) {
        if (desc->fixed) c->constraints = *desc->fixed;
    } else {
        /* the thesis's pair lines on the training samples, with the base set's springs */
        const sk_hand_constraints *base = desc->potential.base;
        for (int i = 0; i < SK_HAND_DOF_COUNT && base; i++) {
            c->constraints.has_stiffness[i] = base->has_stiffness[i];
            c->constraints.stiffness[i] = base->stiffness[i];
        }
        const double *cols[SK_HAND_DOF_COUNT] = {0};
        double *buf = malloc(sizeof(double) * (size_t)nt * d);
        sk_hand_fit *fits = malloc(sizeof *fits * (size_t)desc->pair_count);
        if (!buf || !fits) r = sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
        for (int a = 0; a < d && r == SK_OK; a++) {
            for (int k = 0; k < nt; k++) buf[(size_t)a * nt + k] = s->column[dof[a]][train[k]];
            cols[dof[a]] = buf + (size_t)a * nt;
        }
        if (r == SK_OK)
            r = sk_hand_calibrate(cols, nt, desc->pairs, desc->pair_count, desc->weight_rule, fits,
                                  err);
        double scale = desc->weight_scale > 0 ? desc->weight_scale : 1.0;
        for (int k = 0; k < desc->pair_count && r == SK_OK; k++)
            r = sk_hand_constraints_add_pair(&c->constraints, skel, fits[k].dof_x, fits[k].dof_y,
                                             fits[k].slope, fits[k].intercept,
                                             fits[k].weight * scale, true, err);
        free(buf);
        free(fits);
    }
    /* every stiffness explicit, as in a calibrated component */
    for (int i = 0; i < SK_HAND_DOF_COUNT && r == SK_OK; i++)
        if (!c->constraints.has_stiffness[i]) {
            c->constraints.has_stiffness[i] = true;
            c->constraints.stiffness[i] = skel->dof[i].stiffness;
        }
    if (r != SK_OK) sk_hand_potential_free(pot);
    return r;
}

/* The lookup tables of a fold (3.2.3): one per pair, from the training samples. */
static sk_result fold_luts(const sk_hand_samples *s, const int *train, int nt,
                           const sk_hand_evaluation_desc *desc, sk_hand_lut *luts, int *count,
                           sk_error *err)
{
    *count = 0;
    double *xs = malloc(sizeof(double) * (size_t)nt * 2);
    if (!xs) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    sk_result r = SK_OK;
    for (int k = 0; k < desc->pair_count && r == SK_OK; k++) {
        int x = desc->pairs[k][0], y = desc->pairs[k][1];
        for (int i = 0; i < nt; i++) {
            xs[i] = s->column[x][train[i]];
            xs[nt + i] = s->column[y][train[i]];
        }
        r = sk_hand_lut_build(&luts[k], x, y, xs, xs + nt, nt, &desc->lut, err);
        if (r == SK_OK) (*count)++;
    }
    free(xs);
    if (r != SK_OK)
        for (int k = 0; k < *count; k++) sk_hand_lut_free(&luts[k]);
    return r;
}

/* Squared-error sums of one pin set, per joint (index among the calibrated DOFs). */
typedef struct sums {
    double model[D_MAX], mean[D_MAX], linear[D_MAX], pca[D_MAX];
    long long count;
} sums;

static double rms(double sum, long long n) { return n > 0 ? sqrt(sum / (double)n) : 0.0; }

/* The folds, the PCA baseline's k and the pair model's scale within the ranges
   sk_hand_evaluation_schema states (with groups, 0 folds: one per group). */
static sk_result resolve_counts(sk_hand_evaluation_desc *desc, int pin_set_count, sk_error *err)
{
    const sk_schema *schema = &sk_hand_evaluation_schema;
    const sk_schema_field *folds = sk_schema_find(schema, "folds");
    const sk_schema_field *pca = sk_schema_find(schema, "pca_components");
    if (desc->folds == 0 && !desc->by_group) desc->folds = 5;
    if (desc->pca_components == 0) desc->pca_components = (int)pca->def;
    sk_result r =
        sk_check_range_i(err, "folds", desc->folds, desc->by_group ? 0 : (long long)folds->min,
                         (long long)folds->max);
    if (r == SK_OK) r = sk_check_range_i(err, "pin sets", pin_set_count, 1, NP_MAX);
    if (r == SK_OK) r = sk_schema_check_field(pca, desc, "pca_components", err);
    if (r == SK_OK && desc->model == SK_HAND_EVAL_MODEL_PAIRS)
        r = sk_schema_check_field(sk_schema_find(schema, "weight_scale"), desc, "weight_scale",
                                  err);
    return r;
}

/* The evaluation's settings: the description with its defaults filled in, checked. */
static sk_result eval_settings(const sk_hand_evaluation_desc *desc_in, int pin_set_count,
                               sk_hand_evaluation_desc *out, bool *pairs_model, sk_error *err)
{
    sk_hand_evaluation_desc desc = {0};
    if (desc_in) desc = *desc_in;
    if (desc.model == SK_HAND_EVAL_MODEL_DEFAULT) desc.model = SK_HAND_EVAL_MODEL_CALIBRATED;
    if (desc.model != SK_HAND_EVAL_MODEL_CALIBRATED && desc.model != SK_HAND_EVAL_MODEL_FIXED &&
        desc.model != SK_HAND_EVAL_MODEL_PAIRS && desc.model != SK_HAND_EVAL_MODEL_LUT)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "model = %d is not a model",
                       (int)desc.model);
    bool with_pairs =
        desc.model == SK_HAND_EVAL_MODEL_PAIRS || desc.model == SK_HAND_EVAL_MODEL_LUT;
    if (with_pairs && (desc.pair_count < 1 || !desc.pairs))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "the %s model needs pairs",
                       desc.model == SK_HAND_EVAL_MODEL_LUT ? "lookup-table" : "pair");
    if (with_pairs && desc.pair_count > SK_HAND_EVAL_MAX_LUTS)
        return sk_fail(err, SK_ERROR_LIMIT, "%d pairs; at most %d", desc.pair_count,
                       SK_HAND_EVAL_MAX_LUTS);
    sk_result r = resolve_counts(&desc, pin_set_count, err);
    if (r != SK_OK) return r;
    *out = desc;
    *pairs_model = with_pairs;
    return SK_OK;
}

/* The samples' calibrated DOFs (dof[0..d-1]) and each pin set's mask over them, with the
   pin sets and the pairs checked against the samples' columns. */
static sk_result eval_columns(const sk_hand_samples *s, const sk_hand_pin_set *pin_sets,
                              int pin_set_count, const sk_hand_evaluation_desc *desc,
                              bool with_pairs, int *dof, int *d_out, bool pinned[NP_MAX][D_MAX],
                              sk_error *err)
{
    if (desc->by_group && (!s->group || s->group_count < 2))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "holding out by group needs a group column with at least 2 groups");
    int at[SK_HAND_DOF_COUNT];
    int d = sk__hand_calibrated_dofs(s->present, dof);
    if (d < 2)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "the samples have %d joint-angle columns; need 2 or more", d);
    for (int i = 0; i < SK_HAND_DOF_COUNT; i++) at[i] = -1;
    for (int a = 0; a < d; a++) at[dof[a]] = a;
    memset(pinned, 0, sizeof(bool) * NP_MAX * D_MAX);
    for (int p = 0; p < pin_set_count; p++) {
        if (pin_sets[p].count < 1 || pin_sets[p].count > SK_HAND_EVAL_MAX_PINS)
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "pin set %d has %d DOFs", p + 1,
                           pin_sets[p].count);
        for (int k = 0; k < pin_sets[p].count; k++) {
            int dd = pin_sets[p].dof[k];
            if (!sk_hand_dof(dd) || at[dd] < 0)
                return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                               "pin %s is not a joint-angle column of the samples",
                               sk_hand_dof(dd) ? sk_hand_dof(dd)->name : "?");
            pinned[p][at[dd]] = true;
        }
        if (pin_sets[p].count >= d)
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "pin set %d pins every calibrated DOF",
                           p + 1);
    }
    for (int k = 0; with_pairs && k < desc->pair_count; k++)
        for (int e = 0; e < 2; e++) {
            int dd = desc->pairs[k][e];
            if (!sk_hand_dof(dd) || at[dd] < 0)
                return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                               "pair %d: %s is not a joint-angle column of the samples", k + 1,
                               sk_hand_dof(dd) ? sk_hand_dof(dd)->name : "?");
        }
    *d_out = d;
    return SK_OK;
}

/* folds: each sample's fold (its group's, or contiguous blocks) into a new array *fold_out */
static sk_result eval_folds(const sk_hand_samples *s, const sk_hand_evaluation_desc *desc,
                            int **fold_out, int *k_out, sk_error *err)
{
    int n = s->count;
    int *fold = malloc(sizeof(int) * (size_t)n);
    if (!fold) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    int k_folds;
    if (desc->by_group) {
        k_folds = desc->folds > 0 && desc->folds < s->group_count ? desc->folds : s->group_count;
        for (int i = 0; i < n; i++) fold[i] = s->group[i] % k_folds;
    } else {
        k_folds = desc->folds;
        if (n < 2 * k_folds) {
            free(fold);
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "%d samples are too few for %d folds", n,
                           k_folds);
        }
        for (int i = 0; i < n; i++) fold[i] = (int)((long long)i * k_folds / n);
    }
    *fold_out = fold;
    *k_out = k_folds;
    return SK_OK;
}

/* One evaluation's inputs and work arrays, which its folds share. */
typedef struct eval_run {
    const sk_hand_skeleton *skel;
    const sk_hand_samples *s;
    const sk_hand_pin_set *pin_sets;
    int pin_set_count;
    const sk_hand_evaluation_desc *desc;
    const int *dof; /* the calibrated DOFs, d of them */
    int d, k_pca;
    bool (*pinned)[D_MAX];     /* per pin set, per calibrated DOF */
    int *train, *test, nt, ne; /* the fold's training and held-out samples */
    double *pred;              /* the model's posture per held-out sample and pin set */
    sk_hand_solve_info *infos; /* and its solve's report */
    sums *acc;                 /* per pin set */
} eval_run;

/* model solves: independent per held-out sample, one solver per thread */
static sk_result fold_solve(const eval_run *run, const sk_hand_potential *pot,
                            const sk_hand_lut *luts, int lut_count, sk_error *err)
{
    const sk_hand_skeleton *skel = run->skel;
    const sk_hand_samples *s = run->s;
    const sk_hand_pin_set *pin_sets = run->pin_sets;
    int pin_set_count = run->pin_set_count, ne = run->ne;
    const int *test = run->test;
    double *pred = run->pred;
    sk_hand_solve_info *infos = run->infos;
    int failed = 0;
    sk_error thread_err = {0};
#pragma omp parallel
    {
        sk_hand_potential_solver *ps = NULL;
        sk_hand_solver *ls = NULL;
        sk_error e = {0};
        bool ok = lut_count > 0 ? sk_hand_solver_create(&ls, skel, run->desc->potential.base, luts,
                                                        lut_count, run->desc->solver, &e) == SK_OK
                                : sk_hand_potential_solver_create(&ps, skel, pot, run->desc->solver,
                                                                  &e) == SK_OK;
#pragma omp for schedule(dynamic, 64)
        for (int k = 0; k < ne; k++) {
            if (!ok) continue;
            for (int p = 0; p < pin_set_count; p++) {
                sk_hand_input in = {0};
                for (int j = 0; j < pin_sets[p].count; j++) {
                    int dd = pin_sets[p].dof[j];
                    in.pinned[dd] = true;
                    in.pin_value[dd] = s->column[dd][test[k]];
                }
                double *q = pred + ((size_t)k * pin_set_count + p) * SK_HAND_DOF_COUNT;
                sk_hand_solve_info *info = &infos[(size_t)k * pin_set_count + p];
                if ((ls ? sk_hand_solve(ls, &in, q, info, &e)
                        : sk_hand_potential_solve(ps, &in, q, info, NULL, &e)) != SK_OK)
                    ok = false;
            }
        }
        if (!ok) {
#pragma omp critical
            {
                if (!failed) thread_err = e;
                failed = 1;
            }
        }
        sk_hand_potential_solver_destroy(ps);
        sk_hand_solver_destroy(ls);
    }
    if (failed) {
        if (err) *err = thread_err;
        return thread_err.result != SK_OK ? thread_err.result : SK_ERROR_NUMERIC;
    }
    return SK_OK;
}

/* baselines on the training samples, scored with the model on the held-out samples: the
   squared errors of the unpinned joints, and the model's solves counted into `out` */
static sk_result fold_score(const eval_run *run, int f, sk_hand_evaluation *out, sk_error *err)
{
    const sk_hand_samples *s = run->s;
    const int *dof = run->dof, *test = run->test;
    int d = run->d, nt = run->nt, ne = run->ne, pin_set_count = run->pin_set_count;
    bool(*pinned)[D_MAX] = run->pinned;
    const double *pred = run->pred;
    const sk_hand_solve_info *infos = run->infos;
    double mu[D_MAX], scatter[D_MAX * D_MAX], cov[D_MAX * D_MAX], pcov[D_MAX * D_MAX];
    sk__hand_moments(s, dof, d, run->train, nt, mu, scatter);
    for (int i = 0; i < d * d; i++) cov[i] = scatter[i] / nt;
    for (int a = 0; a < d; a++) cov[a * d + a] += 1e-12;
    if (!ppca_cov(cov, d, run->k_pca, pcov))
        return sk_fail(err, SK_ERROR_NUMERIC, "fold %d: the eigen decomposition failed", f + 1);
    for (int p = 0; p < pin_set_count; p++) {
        predictor lin, pca;
        predictor_from_cov(&lin, mu, cov, d, pinned[p]);
        predictor_from_cov(&pca, mu, pcov, d, pinned[p]);
        sums *sp = &run->acc[p];
        for (int k = 0; k < ne; k++) {
            double x[D_MAX], yl[D_MAX], yp[D_MAX];
            for (int a = 0; a < d; a++) x[a] = s->column[dof[a]][test[k]];
            predictor_apply(&lin, d, pinned[p], x, yl);
            predictor_apply(&pca, d, pinned[p], x, yp);
            const double *q = pred + ((size_t)k * pin_set_count + p) * SK_HAND_DOF_COUNT;
            for (int a = 0; a < d; a++) {
                if (pinned[p][a]) continue;
                double em = q[dof[a]] - x[a], e0 = mu[a] - x[a], el = yl[a] - x[a],
                       ep = yp[a] - x[a];
                sp->model[a] += em * em;
                sp->mean[a] += e0 * e0;
                sp->linear[a] += el * el;
                sp->pca[a] += ep * ep;
            }
            sp->count++;
            const sk_hand_solve_info *inf = &infos[(size_t)k * pin_set_count + p];
            out->result[p].solves++;
            out->result[p].unconverged += !inf->converged;
            out->result[p].max_residual = fmax(out->result[p].max_residual, inf->residual);
        }
    }
    return SK_OK;
}

/* Fold f: its model built on the training samples, solved and scored on the held-out ones.
   *done says whether the fold had held-out samples (an empty fold is skipped); *components
   adds the model's component count. */
static sk_result fold_run(eval_run *run, const int *fold, int f, double *components, bool *done,
                          sk_hand_evaluation *out, sk_error *err)
{
    const sk_hand_evaluation_desc *desc = run->desc;
    int n = run->s->count, nt = 0, ne = 0;
    int *train = run->train, *test = run->test;
    *done = false;
    for (int i = 0; i < n; i++) {
        if (fold[i] == f)
            test[ne++] = i;
        else
            train[nt++] = i;
    }
    if (ne == 0) return SK_OK;
    if (nt < 2)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "fold %d leaves %d training samples", f + 1,
                       nt);
    run->nt = nt, run->ne = ne;
    sk_hand_potential pot;
    sk_hand_lut luts[SK_HAND_EVAL_MAX_LUTS];
    int lut_count = 0;
    sk_result r;
    if (desc->model == SK_HAND_EVAL_MODEL_LUT) {
        memset(&pot, 0, sizeof pot);
        r = fold_luts(run->s, train, nt, desc, luts, &lut_count, err);
    } else {
        r = fold_model(run->skel, run->s, run->dof, run->d, train, nt, desc, &pot, err);
    }
    if (r != SK_OK) return r;
    *components += lut_count > 0 ? 1 : pot.component_count;
    *done = true;
    r = fold_solve(run, &pot, luts, lut_count, err);
    sk_hand_potential_free(&pot);
    for (int k = 0; k < lut_count; k++) sk_hand_lut_free(&luts[k]);
    if (r != SK_OK) return r;
    return fold_score(run, f, out, err);
}

/* The RMS errors of each pin set from the summed squares, per joint and over all. */
static void eval_results(const eval_run *run, int folds_done, double components,
                         sk_hand_evaluation *out)
{
    int d = run->d;
    out->sample_count = run->s->count;
    out->fold_count = folds_done;
    out->dof_count = d;
    out->pca_k = run->k_pca;
    out->mean_components = components / folds_done;
    out->pin_set_count = run->pin_set_count;
    for (int p = 0; p < run->pin_set_count; p++) {
        sk_hand_pin_result *res = &out->result[p];
        const sums *sp = &run->acc[p];
        res->pins = run->pin_sets[p];
        double tm = 0, t0 = 0, tl = 0, tp = 0;
        for (int a = 0; a < d; a++) {
            if (run->pinned[p][a]) continue;
            int j = res->joint_count++;
            res->joint[j] = run->dof[a];
            res->model[j] = rms(sp->model[a], sp->count);
            res->mean[j] = rms(sp->mean[a], sp->count);
            res->linear[j] = rms(sp->linear[a], sp->count);
            res->pca[j] = rms(sp->pca[a], sp->count);
            tm += sp->model[a];
            t0 += sp->mean[a];
            tl += sp->linear[a];
            tp += sp->pca[a];
        }
        long long cells = sp->count * res->joint_count;
        res->model_all = rms(tm, cells);
        res->mean_all = rms(t0, cells);
        res->linear_all = rms(tl, cells);
        res->pca_all = rms(tp, cells);
    }
}

sk_result sk_hand_evaluate(const sk_hand_skeleton *skel, const sk_hand_samples *s,
                           const sk_hand_pin_set *pin_sets, int pin_set_count,
                           const sk_hand_evaluation_desc *desc_in, sk_hand_evaluation *out,
                           sk_error *err)
{
    memset(out, 0, sizeof *out);
    sk_hand_evaluation_desc desc;
    bool with_pairs = false;
    sk_result r = eval_settings(desc_in, pin_set_count, &desc, &with_pairs, err);
    if (r != SK_OK) return r;
    int dof[D_MAX], d = 0;
    bool pinned[NP_MAX][D_MAX];
    r = eval_columns(s, pin_sets, pin_set_count, &desc, with_pairs, dof, &d, pinned, err);
    if (r != SK_OK) return r;
    int *fold = NULL, k_folds = 0;
    r = eval_folds(s, &desc, &fold, &k_folds, err);
    if (r != SK_OK) return r;
    /* the calibrated model's held-out choices are made for these pin sets */
    if (desc.potential.pin_set_count == 0) {
        desc.potential.pin_sets = pin_sets;
        desc.potential.pin_set_count = pin_set_count;
    }
    int n = s->count;
    eval_run run = {.skel = skel,
                    .s = s,
                    .pin_sets = pin_sets,
                    .pin_set_count = pin_set_count,
                    .desc = &desc,
                    .dof = dof,
                    .d = d,
                    .k_pca = desc.pca_components < d ? desc.pca_components : d,
                    .pinned = pinned};
    run.acc = calloc((size_t)pin_set_count, sizeof *run.acc);
    run.train = malloc(sizeof(int) * (size_t)n), run.test = malloc(sizeof(int) * (size_t)n);
    run.pred = malloc(sizeof(double) * (size_t)n * pin_set_count * SK_HAND_DOF_COUNT);
    run.infos = malloc(sizeof *run.infos * (size_t)n * pin_set_count);
    if (!run.acc || !run.train || !run.test || !run.pred || !run.infos)
        r = sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    double components = 0.0;
    int folds_done = 0;
    for (int f = 0; f < k_folds && r == SK_OK; f++) {
        bool done;
        r = fold_run(&run, fold, f, &components, &done, out, err);
        if (r != SK_OK || !done) continue;
        folds_done++;
        sk_progress_report(&desc.progress, (f + 1.0) / k_folds);
    }
    if (r == SK_OK && folds_done < 2)
        r = sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "%d non-empty folds; need at least 2",
                    folds_done);
    if (r == SK_OK) eval_results(&run, folds_done, components, out);
    free(fold);
    free(run.acc);
    free(run.train);
    free(run.test);
    free(run.pred);
    free(run.infos);
    return r;
}
