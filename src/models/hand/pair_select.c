/* The thesis's own form of the potential calibrated from samples (thesis 3.2.2): springs
 * K (eq. 3.8) around the relaxed posture theta_bar measured from the samples (step 2, eq.
 * 3.7), and pair rows y = A x + b fitted as least-squares lines (step 6, eq. 3.13) with
 * weights W (eq. 3.14, 3.18), where which pairs get a row and how strongly the rows pull
 * (a scale on every fitted weight) are chosen by the held-out error of the prediction
 * from pinned joints. The choice starts from the published default (the base set's rows,
 * re-centred on the measured relaxed posture) and moves away from it only where held-out
 * samples say it helps; the lines are fitted on the samples' moments shrunk toward the
 * base set's Gaussian, so that a few samples give lines near the default's. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "models/hand/gaussian_internal.h"
#include "models/hand/mixture_internal.h"
#include "models/hand/potential_internal.h"
#include "models/hand/solver_internal.h"

#define D_MAX SK_HAND_DOF_COUNT

static const double SCALE_GRID[] = {0.25, 0.5, 1, 2, 4, 8, 16, 32, 64};

/* A candidate row: y = a x + b through the mean, x and y indices among the calibrated
 * DOFs, ms the mean squared distance of the samples from the line (the l_i^2 of eq.
 * 3.18). */
typedef struct line {
    int x, y;
    double a, ms;
} line;

static void fit_line(const double *sigma, int d, line *l)
{
    double sxx = sigma[l->x * d + l->x], sxy = sigma[l->x * d + l->y], syy = sigma[l->y * d + l->y];
    l->a = sxy / sxx;
    l->ms = fmax((syy - 2.0 * l->a * sxy + l->a * l->a * sxx) / (1.0 + l->a * l->a),
                 SK_HAND__VARIANCE_FLOOR);
}

/* The pair model being chosen. */
typedef struct model {
    bool keep[SK_HAND_MAX_ROWS]; /* base rows on calibrated DOFs */
    int sel[64];                 /* candidate indices of the fitted rows */
    int nsel;
    double scale;
} model;

typedef struct chooser {
    const sk__hand_fit_data *fd;
    const sk_hand_constraints *base; /* may be NULL */
    sk_hand_weight_rule rule;
    double h_fixed[D_MAX * D_MAX];   /* springs and the base rows outside the samples */
    bool optional[SK_HAND_MAX_ROWS]; /* base rows that touch a calibrated DOF */
    line *cand;
    int cand_count;
    sk__hand_mixture *g; /* scratch */
} chooser;

static double row_weight(const chooser *ch, const model *m, int k)
{
    const line *l = &ch->cand[m->sel[k]];
    if (ch->rule == SK_HAND_WEIGHT_THESIS) {
        double top = 0.0;
        for (int j = 0; j < m->nsel; j++) top = fmax(top, ch->cand[m->sel[j]].ms);
        return m->scale * l->ms / top;
    }
    return m->scale * SK_HAND__PRIOR_SPREAD * SK_HAND__PRIOR_SPREAD / l->ms;
}

/* The model read as a Gaussian over the calibrated DOFs: K + A'WA its precision (over all
 * DOFs, the others marginalised), the minimum of the energy its mean. False if K + A'WA
 * is not positive definite. */
static bool model_gaussian(const chooser *ch, const model *m, const double *relaxed, double *mean,
                           double *cov)
{
    const sk__hand_fit_data *fd = ch->fd;
    int d = fd->d;
    double h[D_MAX * D_MAX], g[D_MAX] = {0};
    memcpy(h, ch->h_fixed, sizeof h);
    for (int k = 0; ch->base && k < ch->base->row_count; k++) {
        if (!ch->optional[k] || !m->keep[k]) continue;
        const sk_hand_row *row = &ch->base->rows[k];
        for (int a = 0; a < row->term_count; a++) {
            g[row->dof[a]] += row->weight * row->coeff[a] * row->b;
            for (int b = 0; b < row->term_count; b++)
                h[row->dof[b] * D_MAX + row->dof[a]] += row->weight * row->coeff[a] * row->coeff[b];
        }
    }
    for (int k = 0; k < m->nsel; k++) {
        const line *l = &ch->cand[m->sel[k]];
        int i = fd->dof[l->x], j = fd->dof[l->y];
        double w = row_weight(ch, m, k);
        h[i * D_MAX + i] += w * l->a * l->a;
        h[j * D_MAX + j] += w;
        h[i * D_MAX + j] -= w * l->a;
        h[j * D_MAX + i] -= w * l->a;
    }
    if (!sk__hand_spd_inverse(h, D_MAX)) return false;
    /* the minimum: displacement -H^-1 g from the relaxed posture */
    for (int a = 0; a < d; a++) {
        double v = 0.0;
        for (int i = 0; i < D_MAX; i++) v -= h[i * D_MAX + fd->dof[a]] * g[i];
        mean[a] = relaxed[a] + v;
        for (int b = 0; b < d; b++) cov[b * d + a] = h[fd->dof[b] * D_MAX + fd->dof[a]];
    }
    return true;
}

static double validation_error(chooser *ch, const model *m)
{
    const sk__hand_fit_data *fd = ch->fd;
    double mean[D_MAX], cov[D_MAX * D_MAX];
    if (!model_gaussian(ch, m, fd->mu_train, mean, cov)) return INFINITY;
    sk__hand_mixture_single(ch->g, fd->d, mean, cov);
    return sk__hand_mixture_validation_error(ch->g, fd->x + (size_t)fd->n_train * fd->d, fd->n_val,
                                             (bool(*)[D_MAX])fd->masks, fd->mask_count);
}

static bool selected(const chooser *ch, const model *m, int c)
{
    for (int k = 0; k < m->nsel; k++) {
        const line *l = &ch->cand[m->sel[k]];
        if (m->sel[k] == c || (l->x == ch->cand[c].y && l->y == ch->cand[c].x)) return true;
    }
    return false;
}

/* Greedy moves from the published default: add a fitted row, drop a base row or a fitted
 * one, whichever lowers the held-out error most (by at least 0.1 %), then the scale anew. */
static void choose(chooser *ch, model *m, bool choose_scale, int max_pairs)
{
    double best = validation_error(ch, m);
    const sk_hand_constraints *base = ch->base;
    for (int step = 0; step < 4 * max_pairs; step++) {
        model trial = *m, best_model = *m;
        double target = best * (1.0 - 1e-3);
        bool moved = false;
        for (int c = 0; c < ch->cand_count && m->nsel < max_pairs; c++) {
            if (selected(ch, m, c)) continue;
            trial = *m;
            trial.sel[trial.nsel++] = c;
            double e = validation_error(ch, &trial);
            if (e < target) {
                target = e;
                best_model = trial;
                moved = true;
            }
        }
        for (int k = 0; base && k < base->row_count; k++) {
            if (!ch->optional[k] || !m->keep[k]) continue;
            trial = *m;
            trial.keep[k] = false;
            double e = validation_error(ch, &trial);
            if (e < target) {
                target = e;
                best_model = trial;
                moved = true;
            }
        }
        for (int k = 0; k < m->nsel; k++) {
            trial = *m;
            trial.sel[k] = trial.sel[--trial.nsel];
            double e = validation_error(ch, &trial);
            if (e < target) {
                target = e;
                best_model = trial;
                moved = true;
            }
        }
        if (!moved) break;
        *m = best_model;
        best = target;
        if (!choose_scale || m->nsel == 0) continue;
        for (size_t s = 0; s < sizeof SCALE_GRID / sizeof SCALE_GRID[0]; s++) {
            trial = *m;
            trial.scale = SCALE_GRID[s];
            double e = validation_error(ch, &trial);
            if (e < best) {
                best = e;
                *m = trial;
            }
        }
    }
}

sk_result sk__hand_pairs_fit(sk_hand_potential *out, const sk_hand_skeleton *skel,
                             const sk__hand_fit_data *fd, const sk_hand_potential_desc *desc,
                             sk_error *err)
{
    int d = fd->d;
    sk_hand_weight_rule rule =
        desc->weight_rule ? desc->weight_rule : SK_HAND_WEIGHT_INVERSE_VARIANCE;
    if (rule != SK_HAND_WEIGHT_THESIS && rule != SK_HAND_WEIGHT_INVERSE_VARIANCE)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "weight rule %d is unknown", (int)rule);
    const sk_schema *schema = &sk_hand_potential_schema;
    const sk_schema_field *pairs_field = sk_schema_find(schema, "max_pairs");
    sk_hand_potential_desc dd = *desc;
    if (dd.max_pairs == 0) dd.max_pairs = (int)pairs_field->def;
    int max_pairs = dd.max_pairs;
    sk_result r = sk_schema_check_field(pairs_field, &dd, "max_pairs", err);
    if (r == SK_OK) r = sk_check_range_i(err, "pair_count", desc->pair_count, 0, 256);
    if (r == SK_OK)
        r = sk_schema_check_field(sk_schema_find(schema, "weight_scale"), &dd, "weight_scale", err);
    if (r != SK_OK) return r;
    int at[SK_HAND_DOF_COUNT];
    for (int i = 0; i < SK_HAND_DOF_COUNT; i++) at[i] = -1;
    for (int a = 0; a < d; a++) at[fd->dof[a]] = a;

    chooser *ch = calloc(1, sizeof *ch);
    model *m = calloc(1, sizeof *m);
    int cand_cap = desc->pairs ? desc->pair_count : d * (d - 1);
    if (ch) ch->cand = malloc(sizeof(line) * (size_t)(cand_cap > 0 ? cand_cap : 1));
    if (ch) ch->g = malloc(sizeof *ch->g);
    sk_hand_constraints *fixed = malloc(sizeof *fixed);
    if (!ch || !m || !ch->cand || !ch->g || !fixed) {
        r = sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
        goto done;
    }
    ch->fd = fd;
    ch->base = desc->base;
    ch->rule = rule;
    if (desc->pairs) {
        for (int k = 0; k < desc->pair_count; k++) {
            int x = desc->pairs[k][0], y = desc->pairs[k][1];
            if (!sk_hand_dof(x) || !sk_hand_dof(y) || x == y) {
                r = sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "pair %d: not two different DOFs",
                            k + 1);
                goto done;
            }
            if (at[x] < 0 || at[y] < 0) {
                r = sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                            "pair %s:%s: %s is not a joint-angle column of the samples",
                            sk_hand_dof(x)->name, sk_hand_dof(y)->name,
                            sk_hand_dof(at[x] < 0 ? x : y)->name);
                goto done;
            }
            ch->cand[ch->cand_count++] = (line){at[x], at[y], 0.0, 0.0};
        }
    } else {
        for (int a = 0; a < d; a++)
            for (int b = 0; b < d; b++)
                if (a != b) ch->cand[ch->cand_count++] = (line){a, b, 0.0, 0.0};
    }
    /* springs and the base rows that only relate DOFs outside the samples: always kept */
    memset(fixed, 0, sizeof *fixed);
    for (int i = 0; i < SK_HAND_DOF_COUNT; i++) {
        fixed->has_stiffness[i] = true;
        fixed->stiffness[i] = desc->base && desc->base->has_stiffness[i] ? desc->base->stiffness[i]
                                                                         : skel->dof[i].stiffness;
    }
    for (int k = 0; desc->base && k < desc->base->row_count; k++) {
        const sk_hand_row *row = &desc->base->rows[k];
        for (int t = 0; t < row->term_count; t++) ch->optional[k] |= at[row->dof[t]] >= 0;
        if (!ch->optional[k]) fixed->rows[fixed->row_count++] = *row;
        m->keep[k] = true;
    }
    sk__hand_equilibrium_matrix(skel, fixed, ch->h_fixed);
    m->scale = desc->weight_scale > 0 ? desc->weight_scale : 1.0;

    /* the choice on the training part, the lines refitted on all samples after */
    if (fd->can_validate) {
        for (int c = 0; c < ch->cand_count; c++) fit_line(fd->sigma_train, d, &ch->cand[c]);
        choose(ch, m, desc->weight_scale == 0.0, max_pairs);
    }
    for (int c = 0; c < ch->cand_count; c++) fit_line(fd->sigma, d, &ch->cand[c]);

    out->component = calloc(1, sizeof *out->component);
    if (!out->component) {
        r = sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
        goto done;
    }
    out->component_count = 1;
    out->scale = SK_HAND__PRIOR_SPREAD * SK_HAND__PRIOR_SPREAD;
    out->weight_scale = m->scale;
    out->pair_count = m->nsel;
    sk_hand_potential_component *comp = &out->component[0];
    comp->weight = 1.0;
    sk_hand_constraints *c = &comp->constraints;
    *c = *fixed;
    for (int k = 0; desc->base && k < desc->base->row_count; k++)
        if (ch->optional[k] && m->keep[k]) c->rows[c->row_count++] = desc->base->rows[k];
    for (int i = 0; i < SK_HAND_DOF_COUNT; i++) comp->relaxed[i] = skel->dof[i].relaxed;
    for (int a = 0; a < d; a++)
        comp->relaxed[fd->dof[a]] =
            sk_clampd(fd->mu[a], skel->dof[fd->dof[a]].min, skel->dof[fd->dof[a]].max);
    for (int k = 0; k < m->nsel && r == SK_OK; k++) {
        const line *l = &ch->cand[m->sel[k]];
        r = sk_hand_constraints_add_pair(c, skel, fd->dof[l->x], fd->dof[l->y], l->a, 0.0,
                                         row_weight(ch, m, k), false, err);
    }
    if (r == SK_OK) r = sk__hand_check_positive_definite(skel, c, err);
done:
    if (ch) {
        free(ch->cand);
        free(ch->g);
    }
    free(ch);
    free(m);
    free(fixed);
    return r;
}
