/* Tests of the calibrated potential of natural posture (thesis 3.2.2, eq. 3.17 fitted to
 * samples) and its evaluation: recovery of a known Gaussian, the conditional mean under
 * pins, held-out errors against their theoretical value, a mixture beating one Gaussian
 * on a nonlinear relation, lookup-table solves converging, the samples CSV options, the
 * strict potential reader, determinism over threads, and the command line. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "shitsukan/hand.h"
#include "shitsukan/io.h"
#include "test_support.h"

#define DEG SK_DEG_TO_RAD

static sk_hand_skeleton skeleton(void)
{
    sk_hand_skeleton s;
    sk_error err;
    assert_int_equal(sk_hand_skeleton_init(&s, NULL, &err), SK_OK);
    return s;
}

/* Lower Cholesky of a small covariance (row-major d x d), in place. */
static void cholesky(double *a, int d)
{
    for (int j = 0; j < d; j++) {
        double s = a[j * d + j];
        for (int k = 0; k < j; k++) s -= a[j * d + k] * a[j * d + k];
        assert_true(s > 0);
        a[j * d + j] = sqrt(s);
        for (int i = j + 1; i < d; i++) {
            double t = a[i * d + j];
            for (int k = 0; k < j; k++) t -= a[i * d + k] * a[j * d + k];
            a[i * d + j] = t / a[j * d + j];
        }
        for (int i = 0; i < j; i++) a[i * d + j] = 0.0;
    }
}

/* Inverse of a small symmetric positive definite matrix (Gauss-Jordan). */
static void invert(const double *a, double *out, int d)
{
    double m[16 * 32];
    for (int i = 0; i < d; i++)
        for (int j = 0; j < 2 * d; j++) m[i * 2 * d + j] = j < d ? a[i * d + j] : (j - d == i);
    for (int c = 0; c < d; c++) {
        double p = m[c * 2 * d + c];
        for (int j = 0; j < 2 * d; j++) m[c * 2 * d + j] /= p;
        for (int i = 0; i < d; i++) {
            if (i == c) continue;
            double f = m[i * 2 * d + c];
            for (int j = 0; j < 2 * d; j++) m[i * 2 * d + j] -= f * m[c * 2 * d + j];
        }
    }
    for (int i = 0; i < d; i++)
        for (int j = 0; j < d; j++) out[i * d + j] = m[i * 2 * d + d + j];
}

/* A known Gaussian over four flexion DOFs (degrees): mean, sds, correlations. */
enum { G_D = 4 };
static const char *const G_NAME[G_D] = {"I.MCP.flex", "I.PIP.flex", "I.DIP.flex", "M.PIP.flex"};
static const double G_MEAN[G_D] = {40, 50, 30, 55}, G_SD[G_D] = {12, 15, 9, 15};
static const double G_R[G_D * G_D] = {1,  .3, .2, .25, .3,  1,   .8, .85,
                                      .2, .8, 1,  .7,  .25, .85, .7, 1};
#define G_NOISE 1.0

/* Covariance of the observed samples (with glove noise), degrees^2, row-major. */
static void known_cov(double *cov)
{
    for (int i = 0; i < G_D; i++)
        for (int j = 0; j < G_D; j++)
            cov[i * G_D + j] =
                G_R[i * G_D + j] * G_SD[i] * G_SD[j] + (i == j ? G_NOISE * G_NOISE : 0.0);
}

/* CSV text of n draws: clamped into the joint limits as a glove's calibrated output is. */
static char *known_csv(int n, uint64_t seed)
{
    double l[G_D * G_D];
    for (int i = 0; i < G_D; i++)
        for (int j = 0; j < G_D; j++) l[i * G_D + j] = G_R[i * G_D + j] * G_SD[i] * G_SD[j];
    cholesky(l, G_D);
    sk_hand_skeleton s = skeleton();
    size_t cap = (size_t)n * 64 + 256, len = 0;
    char *text = malloc(cap);
    len += (size_t)snprintf(text, cap, "%s,%s,%s,%s\n", G_NAME[0], G_NAME[1], G_NAME[2], G_NAME[3]);
    for (int k = 0; k < n; k++) {
        sk_rng r = sk_rng_make(seed, (uint64_t)k, 0, 0);
        double z[G_D], x[G_D];
        for (int i = 0; i < G_D; i++) z[i] = sk_rng_normal(&r);
        for (int i = 0; i < G_D; i++) {
            x[i] = G_MEAN[i] + G_NOISE * sk_rng_normal(&r);
            for (int j = 0; j <= i; j++) x[i] += l[i * G_D + j] * z[j];
            int dof = sk_hand_dof_find(G_NAME[i]);
            x[i] = sk_clampd(x[i], s.dof[dof].min * SK_RAD_TO_DEG, s.dof[dof].max * SK_RAD_TO_DEG);
        }
        len += (size_t)snprintf(text + len, cap - len, "%.6f,%.6f,%.6f,%.6f\n", x[0], x[1], x[2],
                                x[3]);
    }
    return text;
}

static void parse_samples(const char *text, sk_hand_samples *s)
{
    sk_error err;
    assert_int_equal(sk_hand_samples_parse(text, strlen(text), "known.csv", s, &err), SK_OK);
}

/* Samples of n draws: the header, then one line per draw written by `row` (degrees). */
typedef int (*row_writer)(int k, sk_rng *r, char *line, size_t size);
static void drawn_samples(const char *header, int n, uint64_t seed, row_writer row,
                          sk_hand_samples *s)
{
    size_t cap = (size_t)n * 64 + strlen(header) + 2, len = 0;
    char *text = malloc(cap);
    len += (size_t)snprintf(text, cap, "%s\n", header);
    for (int k = 0; k < n; k++) {
        sk_rng r = sk_rng_make(seed, (uint64_t)k, 0, 0);
        len += (size_t)row(k, &r, text + len, cap - len);
    }
    parse_samples(text, s);
    free(text);
}

/* Two clusters: an open and a closed index finger. */
static int open_or_closed(int k, sk_rng *r, char *line, size_t size)
{
    bool closed = k % 2;
    double mcp = (closed ? 70 : 10) + 4 * sk_rng_normal(r),
           pip = (closed ? 90 : 12) + 4 * sk_rng_normal(r);
    return snprintf(line, size, "%.4f,%.4f\n", mcp, pip);
}

/* The DIP a hinge of the PIP (none below 40 degrees), an independent MCP. */
static int dip_hinge(int k, sk_rng *r, char *line, size_t size)
{
    (void)k;
    double pip = sk_rng_range(r, 5, 95);
    double dip = (pip < 40 ? 0.0 : 0.9 * (pip - 40)) + 2.0 * sk_rng_normal(r);
    double mcp = 40 + 10 * sk_rng_normal(r);
    return snprintf(line, size, "%.4f,%.4f,%.4f\n", mcp, pip, dip < 0 ? 0 : dip);
}

static void test_gaussian_recovered(void **state)
{
    (void)state;
    sk_hand_skeleton skel = skeleton();
    char *text = known_csv(12000, 3);
    sk_hand_samples s;
    parse_samples(text, &s);
    free(text);
    sk_hand_potential_desc d = {0};
    d.method = SK_HAND_POTENTIAL_GAUSSIAN;
    d.prior_strength = -1; /* none: the samples' own Gaussian */
    sk_hand_potential p;
    sk_error err;
    assert_int_equal(sk_hand_potential_fit(&p, &skel, &s, NULL, 0, &d, &err), SK_OK);
    assert_int_equal(p.component_count, 1);
    assert_int_equal(p.dof_count, G_D);
    double want[G_D * G_D];
    known_cov(want);
    /* the order of p.dof is the DOF order: I.MCP, I.PIP, I.DIP, M.PIP as listed */
    double mean[G_D], cov[G_D * G_D];
    assert_int_equal(sk_hand_potential_gaussian(&p, 0, mean, cov, &err), SK_OK);
    for (int i = 0; i < G_D; i++) {
        assert_int_equal(p.dof[i], sk_hand_dof_find(G_NAME[i]));
        /* the relaxed posture is the mean: within 4 standard errors */
        assert_true(fabs(mean[i] * SK_RAD_TO_DEG - G_MEAN[i]) < 4 * G_SD[i] / sqrt(12000.0));
        for (int j = 0; j < G_D; j++) {
            double got = cov[i * G_D + j] * SK_RAD_TO_DEG * SK_RAD_TO_DEG;
            assert_true(fabs(got - want[i * G_D + j]) <
                        0.04 * sqrt(want[i * G_D + i] * want[j * G_D + j]));
        }
    }
    /* thesis form: positive springs, rows with b = 0, K + A'WA = scale x precision */
    const sk_hand_potential_component *c = &p.component[0];
    double h[G_D * G_D] = {0}, prec[G_D * G_D];
    for (int i = 0; i < G_D; i++) {
        assert_true(c->constraints.stiffness[p.dof[i]] > 0);
        h[i * G_D + i] = c->constraints.stiffness[p.dof[i]];
    }
    int calibrated_rows = 0;
    for (int k = 0; k < c->constraints.row_count; k++) {
        const sk_hand_row *row = &c->constraints.rows[k];
        int at[8], n = 0;
        for (int t = 0; t < row->term_count; t++)
            for (int i = 0; i < G_D; i++)
                if (row->dof[t] == p.dof[i]) at[n++] = i;
        if (n == 0) continue;
        assert_int_equal(n, row->term_count);
        assert_true(row->b == 0.0);
        calibrated_rows++;
        for (int a = 0; a < n; a++)
            for (int b = 0; b < n; b++)
                h[at[a] * G_D + at[b]] += row->weight * row->coeff[a] * row->coeff[b];
    }
    assert_int_equal(calibrated_rows, G_D);
    invert(cov, prec, G_D);
    for (int i = 0; i < G_D * G_D; i++)
        assert_true(fabs(h[i] - p.scale * prec[i]) < 1e-8 * fabs(h[0]));

    /* pins give the conditional mean of the Gaussian (limits not reached here) */
    sk_hand_potential_solver *ps;
    assert_int_equal(sk_hand_potential_solver_create(&ps, &skel, &p, NULL, &err), SK_OK);
    sk_hand_input in = {0};
    int pin_a = p.dof[0], pin_b = p.dof[1];
    in.pinned[pin_a] = in.pinned[pin_b] = true;
    in.pin_value[pin_a] = 52 * DEG;
    in.pin_value[pin_b] = 58 * DEG;
    double q[SK_HAND_DOF_COUNT];
    sk_hand_solve_info info;
    assert_int_equal(sk_hand_potential_solve(ps, &in, q, &info, NULL, &err), SK_OK);
    assert_true(info.converged);
    /* x_u = mu_u + S_up S_pp^-1 (x_p - mu_p) with the fitted and with the true covariance */
    for (int pass = 0; pass < 2; pass++) {
        double m[G_D], sg[G_D * G_D];
        for (int i = 0; i < G_D; i++) m[i] = pass ? G_MEAN[i] * DEG : mean[i];
        for (int i = 0; i < G_D * G_D; i++) sg[i] = pass ? want[i] * DEG * DEG : cov[i];
        double spp[4] = {sg[0], sg[1], sg[G_D], sg[G_D + 1]}, inv[4];
        invert(spp, inv, 2);
        double dp[2] = {52 * DEG - m[0], 58 * DEG - m[1]};
        for (int u = 2; u < G_D; u++) {
            double w0 = sg[u * G_D] * inv[0] + sg[u * G_D + 1] * inv[2];
            double w1 = sg[u * G_D] * inv[1] + sg[u * G_D + 1] * inv[3];
            double cm = m[u] + w0 * dp[0] + w1 * dp[1];
            double tol = pass ? 0.5 * DEG : 1e-9;
            assert_true(fabs(q[p.dof[u]] - cm) < tol);
        }
    }
    sk_hand_potential_solver_destroy(ps);

    /* held out: the model's error equals the conditional-mean error within sampling noise */
    sk_hand_evaluation *ev = malloc(sizeof *ev);
    sk_hand_evaluation_desc ed = {0};
    ed.potential = d;
    sk_hand_pin_set pins = {1, {pin_b}};
    assert_int_equal(sk_hand_evaluate(&skel, &s, &pins, 1, &ed, ev, &err), SK_OK);
    double condvar = 0.0;
    for (int u = 0; u < G_D; u++) {
        if (u == 1) continue;
        condvar += want[u * G_D + u] - want[u * G_D + 1] * want[u * G_D + 1] / want[G_D + 1];
    }
    double expect = sqrt(condvar / 3) * DEG;
    assert_true(fabs(ev->result[0].model_all / expect - 1.0) < 0.04);
    assert_true(fabs(ev->result[0].linear_all / expect - 1.0) < 0.04);
    assert_true(ev->result[0].model_all <= ev->result[0].linear_all * 1.002);
    assert_int_equal(ev->result[0].unconverged, 0);
    /* the mean baseline: the marginal spread */
    double var = 0.0;
    for (int u = 0; u < G_D; u++)
        if (u != 1) var += want[u * G_D + u];
    assert_true(fabs(ev->result[0].mean_all / (sqrt(var / 3) * DEG) - 1.0) < 0.05);
    free(ev);
    sk_hand_potential_free(&p);
    sk_hand_samples_free(&s);
}

/* The thesis's form calibrated with the pairs and the weight scale chosen on held-out
 * samples: it finds the strong coupling, predicts near the conditional mean, far better
 * than eq. 3.18's weights on the same pair; with a handful of samples it stays the
 * published default (re-centred on the samples). */
static void test_pair_choice(void **state)
{
    (void)state;
    sk_hand_skeleton skel = skeleton();
    static sk_hand_constraints natural;
    sk_error err;
    assert_int_equal(sk_hand_constraints_load_file(SK_TEST_PRESET_DIR "/hand/natural.json", &skel,
                                                   &natural, &err),
                     SK_OK);
    char *text = known_csv(4000, 11);
    sk_hand_samples s;
    parse_samples(text, &s);
    sk_hand_pin_set pins = {1, {sk_hand_dof_find("M.PIP.flex")}};
    sk_hand_potential_desc d = {
        .method = SK_HAND_POTENTIAL_PAIRS, .base = &natural, .pin_sets = &pins, .pin_set_count = 1};
    sk_hand_potential p;
    assert_int_equal(sk_hand_potential_fit(&p, &skel, &s, NULL, 0, &d, &err), SK_OK);
    assert_int_equal(p.component_count, 1);
    assert_true(p.pair_count >= 1 && p.pair_count <= 16);
    assert_true(p.weight_scale >= 0.25 && p.weight_scale <= 64);
    const sk_hand_constraints *c = &p.component[0].constraints;
    bool strongest = false;
    for (int k = c->row_count - p.pair_count; k < c->row_count; k++) {
        const sk_hand_row *row = &c->rows[k];
        assert_int_equal(row->term_count, 2);
        assert_true(row->weight > 0 && row->b == 0.0);
        bool ip = row->dof[0] == sk_hand_dof_find("I.PIP.flex") ||
                  row->dof[1] == sk_hand_dof_find("I.PIP.flex");
        bool mp = row->dof[0] == pins.dof[0] || row->dof[1] == pins.dof[0];
        strongest |= ip && mp;
    }
    assert_true(strongest);
    /* the relaxed posture is the samples' mean (shrunk a little toward the default) */
    for (int i = 0; i < G_D; i++)
        assert_true(fabs(p.component[0].relaxed[sk_hand_dof_find(G_NAME[i])] * SK_RAD_TO_DEG -
                         G_MEAN[i]) < 2.0);
    sk_hand_potential_free(&p);

    /* held out: near the conditional mean, far better than the eq. 3.18 line */
    sk_hand_evaluation *ev = malloc(sizeof *ev), *thesis = malloc(sizeof *thesis);
    sk_hand_evaluation_desc ed = {.potential = d};
    ed.potential.pin_sets = NULL;
    ed.potential.pin_set_count = 0;
    assert_int_equal(sk_hand_evaluate(&skel, &s, &pins, 1, &ed, ev, &err), SK_OK);
    double want[G_D * G_D], condvar = 0.0;
    known_cov(want);
    for (int u = 0; u < G_D; u++)
        if (u != 3)
            condvar +=
                want[u * G_D + u] - want[u * G_D + 3] * want[u * G_D + 3] / want[3 * G_D + 3];
    double expect = sqrt(condvar / 3) * DEG;
    assert_true(ev->result[0].model_all < 1.08 * expect);
    assert_true(ev->result[0].model_all < 0.8 * ev->result[0].mean_all);
    assert_int_equal(ev->result[0].unconverged, 0);
    int pair[1][2] = {{sk_hand_dof_find("I.PIP.flex"), pins.dof[0]}};
    sk_hand_evaluation_desc td = {
        .model = SK_HAND_EVAL_MODEL_PAIRS, .pairs = (const int(*)[2])pair, .pair_count = 1};
    td.potential.base = &natural;
    assert_int_equal(sk_hand_evaluate(&skel, &s, &pins, 1, &td, thesis, &err), SK_OK);
    assert_true(ev->result[0].model_all < 0.8 * thesis->result[0].model_all);
    free(ev);
    free(thesis);

    /* only the given candidates; a candidate outside the samples is an error naming it */
    int one[1][2] = {{sk_hand_dof_find("I.MCP.flex"), sk_hand_dof_find("I.DIP.flex")}};
    d.pairs = (const int(*)[2])one;
    d.pair_count = 1;
    assert_int_equal(sk_hand_potential_fit(&p, &skel, &s, NULL, 0, &d, &err), SK_OK);
    assert_true(p.pair_count <= 1);
    if (p.pair_count == 1)
        assert_string_equal(
            p.component[0].constraints.rows[p.component[0].constraints.row_count - 1].label,
            "I.MCP.flex:I.DIP.flex");
    sk_hand_potential_free(&p);
    one[0][1] = sk_hand_dof_find("L.PIP.flex");
    assert_int_equal(sk_hand_potential_fit(&p, &skel, &s, NULL, 0, &d, &err),
                     SK_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(err.message, "L.PIP.flex"));
    d.pairs = NULL;
    d.pair_count = 0;
    sk_hand_samples_free(&s);

    /* six samples: no fitted rows, the published rows, a relaxed posture between the
       default and the samples' mean */
    char *end = text;
    for (int line = 0; line < 7; line++) end = strchr(end, '\n') + 1;
    *end = '\0';
    parse_samples(text, &s);
    free(text);
    d.pin_sets = NULL;
    d.pin_set_count = 0;
    d.prior_strength = 16;
    assert_int_equal(sk_hand_potential_fit(&p, &skel, &s, NULL, 0, &d, &err), SK_OK);
    assert_int_equal(p.pair_count, 0);
    assert_int_equal(p.component[0].constraints.row_count, natural.row_count);
    for (int i = 0; i < G_D; i++) {
        int dof = sk_hand_dof_find(G_NAME[i]);
        double mean = 0.0;
        for (int k = 0; k < s.count; k++) mean += s.column[dof][k] / s.count;
        double lo = fmin(mean, skel.dof[dof].relaxed), hi = fmax(mean, skel.dof[dof].relaxed);
        double got = p.component[0].relaxed[dof];
        assert_true(got >= lo - 1e-9 && got <= hi + 1e-9);
        /* 16 pseudo-samples against 6: nearer the default */
        assert_true(fabs(got - skel.dof[dof].relaxed) <= fabs(got - mean) + 1e-9);
    }
    sk_hand_potential_free(&p);
    sk_hand_samples_free(&s);
}

/* Torques with a mixture: they tilt each component's Gaussian, so pushing a joint into
 * flexion moves the blend toward the closed-hand component, smoothly and monotonically. */
static void test_mixture_torques(void **state)
{
    (void)state;
    sk_hand_skeleton skel = skeleton();
    sk_hand_samples s;
    drawn_samples("I.MCP.flex,I.PIP.flex", 1200, 21, open_or_closed, &s);
    sk_hand_potential_desc d = {
        .method = SK_HAND_POTENTIAL_MIXTURE, .components = 2, .prior_strength = -1};
    sk_hand_potential p;
    sk_error err;
    assert_int_equal(sk_hand_potential_fit(&p, &skel, &s, NULL, 0, &d, &err), SK_OK);
    assert_int_equal(p.component_count, 2);
    int closed = p.component[1].relaxed[p.dof[0]] > p.component[0].relaxed[p.dof[0]];
    sk_hand_potential_solver *ps;
    assert_int_equal(sk_hand_potential_solver_create(&ps, &skel, &p, NULL, &err), SK_OK);
    int pip = sk_hand_dof_find("I.PIP.flex"), mcp = sk_hand_dof_find("I.MCP.flex");
    double last_resp = -1.0, last_mcp = -1.0;
    for (int k = 0; k <= 20; k++) {
        sk_hand_input in = {0};
        in.torque[pip] = (k - 10) * 0.004;
        double q[SK_HAND_DOF_COUNT], resp[2];
        sk_hand_solve_info info;
        assert_int_equal(sk_hand_potential_solve(ps, &in, q, &info, resp, &err), SK_OK);
        assert_true(info.converged);
        assert_true(resp[closed] > last_resp);
        assert_true(q[mcp] > last_mcp);
        if (k == 0) assert_true(resp[closed] < 0.05);
        if (k == 10) assert_true(fabs(resp[closed] - p.component[closed].weight) < 1e-12);
        if (k == 20) assert_true(resp[closed] > 0.95);
        last_resp = resp[closed];
        last_mcp = q[mcp];
    }
    sk_hand_potential_solver_destroy(ps);
    sk_hand_potential_free(&p);
    sk_hand_samples_free(&s);
}

/* DIP = a hinge of PIP (none below 40 degrees): one Gaussian fits a line, a mixture the
 * two pieces; a lookup table of the pair follows the hinge only to the noise. */
static void test_mixture_beats_gaussian_on_nonlinear_relation(void **state)
{
    (void)state;
    sk_hand_skeleton skel = skeleton();
    sk_hand_samples s;
    drawn_samples("I.MCP.flex,I.PIP.flex,I.DIP.flex", 2000, 5, dip_hinge, &s);
    sk_hand_pin_set pins = {1, {sk_hand_dof_find("I.PIP.flex")}};
    sk_hand_evaluation *g = malloc(sizeof *g), *m = malloc(sizeof *m);
    sk_hand_evaluation_desc ed = {0};
    sk_error err;
    ed.potential.method = SK_HAND_POTENTIAL_GAUSSIAN;
    assert_int_equal(sk_hand_evaluate(&skel, &s, &pins, 1, &ed, g, &err), SK_OK);
    ed.potential.method = SK_HAND_POTENTIAL_MIXTURE;
    ed.potential.max_components = 4;
    assert_int_equal(sk_hand_evaluate(&skel, &s, &pins, 1, &ed, m, &err), SK_OK);
    assert_true(m->mean_components > 1.0);
    /* joint 1 of the result is the DIP (the unpinned DOFs in DOF order: MCP, DIP) */
    assert_int_equal(m->result[0].joint[1], sk_hand_dof_find("I.DIP.flex"));
    double dip_g = g->result[0].model[1], dip_m = m->result[0].model[1];
    assert_true(dip_m < 0.7 * dip_g);
    assert_true(dip_m < 0.8 * m->result[0].linear[1]);
    assert_true(m->result[0].model_all < g->result[0].model_all);
    /* the lookup table of the pair (3.2.3), built per fold, strong against the springs:
       the DIP follows the hinge too, and every solve converges */
    int pair[1][2] = {{pins.dof[0], sk_hand_dof_find("I.DIP.flex")}};
    sk_hand_evaluation_desc td = {
        .model = SK_HAND_EVAL_MODEL_LUT, .pairs = (const int(*)[2])pair, .pair_count = 1};
    td.lut.weight = 100;
    sk_hand_evaluation *t = malloc(sizeof *t);
    assert_int_equal(sk_hand_evaluate(&skel, &s, &pins, 1, &td, t, &err), SK_OK);
    sk_hand_evaluation_desc fd = {.model = SK_HAND_EVAL_MODEL_FIXED};
    sk_hand_evaluation *f = malloc(sizeof *f);
    assert_int_equal(sk_hand_evaluate(&skel, &s, &pins, 1, &fd, f, &err), SK_OK);
    /* measured: Gaussian 4.9, mixture 1.7, tables 4.8, springs alone 17.2 degrees; the
       table's potential (squared distance to the nearest sample) is flat inside the noisy
       band of samples, so the springs hold the DIP at the band's edge, about the noise
       away from the hinge */
    assert_true(t->result[0].model[1] < 0.35 * f->result[0].model[1]);
    assert_true(t->result[0].model[1] < 1.05 * dip_g);
    assert_true(dip_m < 0.5 * t->result[0].model[1]);
    free(f);
    assert_int_equal(t->result[0].unconverged, 0);
    assert_int_equal(t->result[0].solves, s.count);
    /* a pair outside the samples */
    pair[0][1] = sk_hand_dof_find("L.DIP.flex");
    assert_int_equal(sk_hand_evaluate(&skel, &s, &pins, 1, &td, t, &err),
                     SK_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(err.message, "L.DIP.flex is not a joint-angle column"));
    free(t);
    free(g);
    free(m);
    sk_hand_samples_free(&s);
}

/* The reported case: tables from about 1,900 samples, one MCP pinned: every solve
 * converges within the default step limit. */
static void test_lut_solves_converge(void **state)
{
    (void)state;
    sk_hand_skeleton skel = skeleton();
    sk_hand_synthetic_desc sd = {.people = 2, .trials = 2, .frames = 48, .seed = 9};
    char *text;
    size_t len;
    sk_error err;
    assert_int_equal(sk_hand_synthetic_grasps_csv(&sd, &text, &len, &err), SK_OK);
    sk_hand_samples s;
    sk_hand_samples_desc rd = {.group_column = "person", .ignore_columns = "trial"};
    assert_int_equal(sk_hand_samples_parse_desc(text, len, "synthetic", &rd, &s, &err), SK_OK);
    free(text);
    assert_int_equal(s.count, 1920);
    static sk_hand_constraints c;
    assert_int_equal(
        sk_hand_constraints_load_file(SK_TEST_PRESET_DIR "/hand/natural.json", &skel, &c, &err),
        SK_OK);
    int pairs[5][2], np;
    assert_int_equal(
        sk_hand_parse_pairs("I.MCP.flex:I.PIP.flex,I.PIP.flex:I.DIP.flex,M.MCP.flex:M.PIP.flex,"
                            "R.MCP.flex:L.MCP.flex,M.PIP.flex:R.PIP.flex",
                            pairs, 5, &np, &err),
        SK_OK);
    sk_hand_lut luts[5];
    for (int k = 0; k < np; k++)
        assert_int_equal(sk_hand_lut_build(&luts[k], pairs[k][0], pairs[k][1],
                                           s.column[pairs[k][0]], s.column[pairs[k][1]], s.count,
                                           NULL, &err),
                         SK_OK);
    sk_hand_solver *solver;
    assert_int_equal(sk_hand_solver_create(&solver, &skel, &c, luts, np, NULL, &err), SK_OK);
    const char *mcp[4] = {"I.MCP.flex", "M.MCP.flex", "R.MCP.flex", "L.MCP.flex"};
    int solves = 0, worst_steps = 0;
    for (int f = 0; f < 4; f++) {
        int dof = sk_hand_dof_find(mcp[f]);
        for (int i = 0; i < s.count; i += 6) {
            sk_hand_input in = {0};
            in.pinned[dof] = true;
            in.pin_value[dof] = s.column[dof][i];
            double q[SK_HAND_DOF_COUNT];
            sk_hand_solve_info info;
            assert_int_equal(sk_hand_solve(solver, &in, q, &info, &err), SK_OK);
            assert_true(info.converged);
            assert_true(info.residual <= 1e-6);
            worst_steps =
                info.newton_iterations > worst_steps ? info.newton_iterations : worst_steps;
            solves++;
        }
    }
    assert_true(solves > 1000);
    assert_true(worst_steps < 100);
    sk_hand_solver_destroy(solver);
    for (int k = 0; k < np; k++) sk_hand_lut_free(&luts[k]);
    sk_hand_samples_free(&s);
}

static void test_samples_csv_options(void **state)
{
    (void)state;
    sk_hand_samples s;
    sk_error err;
    const char *text = "person,trial,frame,I.MCP.flex,I.PIP.flex\np1,a,0,0.5,1.0\np2,b,1,0.25,0."
                       "75\np1,c,2,0.1,0.2\n";
    sk_hand_samples_desc d = {
        .units = SK_HAND_UNIT_RAD, .group_column = "person", .ignore_columns = "trial"};
    assert_int_equal(sk_hand_samples_parse_desc(text, strlen(text), "s.csv", &d, &s, &err), SK_OK);
    assert_int_equal(s.count, 3);
    assert_int_equal(s.group_count, 2);
    assert_int_equal(s.group[0], 0);
    assert_int_equal(s.group[1], 1);
    assert_int_equal(s.group[2], 0);
    assert_string_equal(s.group_name[1], "p2");
    assert_true(fabs(s.column[sk_hand_dof_find("I.PIP.flex")][1] - 0.75) < 1e-15);
    assert_false(s.units_suspect);
    sk_hand_samples_free(&s);
    /* the same numbers read as degrees: every angle within +-pi looks like radians */
    d.units = SK_HAND_UNIT_DEG;
    assert_int_equal(sk_hand_samples_parse_desc(text, strlen(text), "s.csv", &d, &s, &err), SK_OK);
    assert_true(s.units_suspect);
    sk_hand_samples_free(&s);
    /* a column that is neither a DOF nor ignored */
    d.ignore_columns = NULL;
    assert_int_equal(sk_hand_samples_parse_desc(text, strlen(text), "s.csv", &d, &s, &err),
                     SK_ERROR_PARSE);
    assert_non_null(strstr(err.message, "unknown DOF \"trial\""));
    d.ignore_columns = "trial,nosuch";
    assert_int_equal(sk_hand_samples_parse_desc(text, strlen(text), "s.csv", &d, &s, &err),
                     SK_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(err.message, "\"nosuch\" is not a column"));
    d.ignore_columns = "trial,person";
    d.group_column = "subject";
    assert_int_equal(sk_hand_samples_parse_desc(text, strlen(text), "s.csv", &d, &s, &err),
                     SK_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(err.message, "group column \"subject\""));
    const char *huge = "I.MCP.flex\n1e308\n";
    assert_int_equal(sk_hand_samples_parse(huge, strlen(huge), "s.csv", &s, &err), SK_ERROR_PARSE);
    assert_non_null(strstr(err.message, "line 2, column 1 (I.MCP.flex)"));
    const char *empty_group = "person,I.MCP.flex\n,10\n";
    d.group_column = "person";
    d.ignore_columns = NULL;
    assert_int_equal(
        sk_hand_samples_parse_desc(empty_group, strlen(empty_group), "s.csv", &d, &s, &err),
        SK_ERROR_PARSE);
}

static void test_potential_file_round_trip_and_errors(void **state)
{
    (void)state;
    sk_hand_skeleton skel = skeleton();
    char *text = known_csv(2000, 11);
    sk_hand_samples s;
    parse_samples(text, &s);
    free(text);
    static sk_hand_constraints base;
    sk_error err;
    assert_int_equal(
        sk_hand_constraints_load_file(SK_TEST_PRESET_DIR "/hand/natural.json", &skel, &base, &err),
        SK_OK);
    sk_hand_potential_desc d = {.components = 2, .base = &base, .seed = 4};
    sk_hand_potential p, back;
    assert_int_equal(sk_hand_potential_fit(&p, &skel, &s, NULL, 0, &d, &err), SK_OK);
    assert_int_equal(p.component_count, 2);
    const char *path = sk_test_path("prior/potential.json");
    assert_int_equal(sk_hand_potential_write_json(&p, "test", path, &err), SK_OK);
    assert_int_equal(sk_hand_potential_load_file(path, &skel, &back, &err), SK_OK);
    assert_int_equal(back.component_count, 2);
    assert_int_equal(back.dof_count, p.dof_count);
    /* the same poses from the file as from the fit */
    sk_hand_potential_solver *a, *b;
    assert_int_equal(sk_hand_potential_solver_create(&a, &skel, &p, NULL, &err), SK_OK);
    assert_int_equal(sk_hand_potential_solver_create(&b, &skel, &back, NULL, &err), SK_OK);
    sk_hand_input in = {0};
    int pin = sk_hand_dof_find("I.PIP.flex");
    in.pinned[pin] = true;
    in.pin_value[pin] = 70 * DEG;
    double qa[SK_HAND_DOF_COUNT], qb[SK_HAND_DOF_COUNT], ra[2], rb[2];
    assert_int_equal(sk_hand_potential_solve(a, &in, qa, NULL, ra, &err), SK_OK);
    assert_int_equal(sk_hand_potential_solve(b, &in, qb, NULL, rb, &err), SK_OK);
    for (int i = 0; i < SK_HAND_DOF_COUNT; i++) assert_true(fabs(qa[i] - qb[i]) < 1e-9);
    assert_true(fabs(ra[0] + ra[1] - 1.0) < 1e-12);
    /* DOFs outside the samples keep the base set: the thumb's rows are still there */
    bool thumb_row = false;
    for (int k = 0; k < back.component[0].constraints.row_count; k++)
        thumb_row |= back.component[0].constraints.rows[k].dof[0] == sk_hand_dof_find("T.MCP.flex");
    assert_true(thumb_row);
    sk_hand_potential_solver_destroy(a);
    sk_hand_potential_solver_destroy(b);
    sk_hand_potential_free(&back);
    sk_hand_potential_free(&p);
    sk_hand_samples_free(&s);

    /* strict reader: each broken file fails with its reason */
    const char *ok = "{\"dofs\": [\"I.MCP.flex\", \"I.PIP.flex\"], \"scale\": 1, \"components\": "
                     "[{\"weight\": 1, "
                     "\"relaxed_deg\": {\"I.MCP.flex\": 30, \"I.PIP.flex\": 40}, \"rows\": []}]}";
    assert_int_equal(sk_hand_potential_parse(ok, strlen(ok), "p.json", &skel, &p, &err), SK_OK);
    assert_true(fabs(p.component[0].relaxed[sk_hand_dof_find("I.PIP.flex")] - 40 * DEG) < 1e-12);
    sk_hand_potential_free(&p);
    static const struct {
        const char *text, *needle;
    } bad[] = {
        {"{\"dofs\": [\"I.MCP.flex\"], \"scale\": 1, \"components\": []} x",
         "text after the JSON value"},
        {"{\"dofs\": [\"I.MCP.flex\"], \"dofs\": [\"I.MCP.flex\"], \"scale\": 1, \"components\": "
         "[]}",
         "given twice"},
        {"{\"dofs\": [\"I.MCP.flex\"], \"scale\": 1e999, \"components\": []}", "too large"},
        {"{\"dofs\": [\"I.MCP.flex\"], \"scale\": 1, \"components\": [], \"extra\": 1}",
         "extra: unknown key"},
        {"{\"dofs\": [\"I.MCP.flex\"], \"scale\": 1, \"components\": []}", "components: 0 entries"},
        {"{\"dofs\": [\"wrist.tx\"], \"scale\": 1, \"components\": []}", "wrist DOF"},
        {"{\"dofs\": [\"I.MCP.flex\"], \"scale\": 1, \"components\": [{\"weight\": 0.5, "
         "\"relaxed_deg\": "
         "{\"I.MCP.flex\": 30}, \"rows\": []}]}",
         "sum to 0.5"},
        {"{\"dofs\": [\"I.MCP.flex\"], \"scale\": 1, \"components\": [{\"weight\": 1, "
         "\"relaxed_deg\": "
         "{\"I.MCP.flex\": 130}, \"rows\": []}]}",
         "outside the joint limits"},
        {"{\"dofs\": [\"I.MCP.flex\"], \"scale\": 1, \"components\": [{\"weight\": 1, "
         "\"relaxed_deg\": {}, "
         "\"rows\": []}]}",
         "relaxed_deg.I.MCP.flex: missing"},
        {"{\"dofs\": [\"I.MCP.flex\"], \"scale\": 1, \"components\": [{\"weight\": 1, "
         "\"relaxed_deg\": "
         "{\"I.MCP.flex\": 30}, \"rows\": [{\"terms\": {\"I.MCP.flex\": 1}, \"W\": -5}]}]}",
         "not positive definite"},
        {"{\"dofs\": [\"I.MCP.flex\"], \"scale\": 1, \"components\": [{\"weight\": 1, "
         "\"relaxed_deg\": "
         "{\"I.MCP.flex\": 30}, \"rows\": [{\"terms\": {\"I.MCP.flex\": 1}, \"W\": 1, \"q\": "
         "1}]}]}",
         "components[0]: rows[0].q: unknown key"},
        {"[1, 2", "malformed JSON"},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        sk_result r =
            sk_hand_potential_parse(bad[i].text, strlen(bad[i].text), "p.json", &skel, &p, &err);
        if (r == SK_OK || !strstr(err.message, bad[i].needle))
            fprintf(stderr, "case %zu: %s\n", i, err.message);
        assert_int_not_equal(r, SK_OK);
        assert_non_null(strstr(err.message, bad[i].needle));
        assert_null(p.component);
    }
}

/* The same numbers for one thread and for two. */
static void test_evaluation_deterministic_over_threads(void **state)
{
    (void)state;
    sk_hand_skeleton skel = skeleton();
    sk_hand_synthetic_desc sd = {.people = 3, .trials = 1, .frames = 30};
    char *text;
    size_t len;
    sk_error err;
    assert_int_equal(sk_hand_synthetic_grasps_csv(&sd, &text, &len, &err), SK_OK);
    char *again;
    size_t len2;
    assert_int_equal(sk_hand_synthetic_grasps_csv(&sd, &again, &len2, &err), SK_OK);
    assert_int_equal(len, len2);
    assert_memory_equal(text, again, len);
    free(again);
    sk_hand_samples s;
    sk_hand_samples_desc rd = {.group_column = "person", .ignore_columns = "trial"};
    assert_int_equal(sk_hand_samples_parse_desc(text, len, "synthetic", &rd, &s, &err), SK_OK);
    free(text);
    sk_hand_pin_set pins[2];
    assert_int_equal(sk_hand_parse_pin_set("I.MCP.flex,I.PIP.flex", &pins[0], &err), SK_OK);
    assert_int_equal(sk_hand_parse_pin_set("L.MCP.flex", &pins[1], &err), SK_OK);
    sk_hand_evaluation *one = malloc(sizeof *one), *two = malloc(sizeof *two);
    sk_hand_evaluation_desc ed = {.by_group = true, .potential = {.max_components = 4}};
    sk_threads_set(1);
    assert_int_equal(sk_hand_evaluate(&skel, &s, pins, 2, &ed, one, &err), SK_OK);
    sk_threads_set(2);
    assert_int_equal(sk_hand_evaluate(&skel, &s, pins, 2, &ed, two, &err), SK_OK);
    sk_threads_set(0);
    assert_int_equal(one->fold_count, 3);
    assert_memory_equal(one, two, sizeof *one);
    /* the model beats the mean; every solve converged */
    assert_true(one->result[0].model_all < one->result[0].mean_all);
    assert_int_equal(one->result[0].unconverged, 0);
    assert_int_equal(one->result[0].joint_count, 10);
    /* the same for the thesis's form with the pairs chosen and for lookup tables */
    int pair[2][2] = {{sk_hand_dof_find("R.MCP.flex"), sk_hand_dof_find("L.MCP.flex")},
                      {sk_hand_dof_find("I.PIP.flex"), sk_hand_dof_find("M.PIP.flex")}};
    sk_hand_evaluation_desc other[2] = {{.by_group = true,
                                         .potential = {.method = SK_HAND_POTENTIAL_PAIRS,
                                                       .pairs = (const int(*)[2])pair,
                                                       .pair_count = 2}},
                                        {.by_group = true,
                                         .model = SK_HAND_EVAL_MODEL_LUT,
                                         .pairs = (const int(*)[2])pair,
                                         .pair_count = 2,
                                         .lut = {.resolution = 24}}};
    for (int m = 0; m < 2; m++) {
        sk_threads_set(1);
        assert_int_equal(sk_hand_evaluate(&skel, &s, pins, 2, &other[m], one, &err), SK_OK);
        sk_threads_set(2);
        assert_int_equal(sk_hand_evaluate(&skel, &s, pins, 2, &other[m], two, &err), SK_OK);
        sk_threads_set(0);
        assert_memory_equal(one, two, sizeof *one);
        assert_int_equal(one->result[1].unconverged, 0);
    }
    free(one);
    free(two);
    sk_hand_samples_free(&s);
}

/* The shipped data set is what the generator makes with its defaults. */
static void test_shipped_data_set_is_generated(void **state)
{
    (void)state;
    char *text, *shipped;
    size_t len, size;
    sk_error err;
    assert_int_equal(
        sk_hand_synthetic_grasps_csv(&(sk_hand_synthetic_desc){.seed = 1}, &text, &len, &err),
        SK_OK);
    assert_int_equal(sk_read_file(SK_TEST_PRESET_DIR "/hand/samples/synthetic-grasps.csv", 0,
                                  &shipped, &size, &err),
                     SK_OK);
    assert_int_equal(len, size);
    assert_memory_equal(text, shipped, len);
    free(text);
    free(shipped);
}

static void test_cli_evaluate(void **state)
{
    (void)state;
    sk_test_run *run = malloc(sizeof *run);
    char csv[1024], pot[1024]; /* kept: sk_test_path reuses its buffers */
    snprintf(csv, sizeof csv, "%s", sk_test_path("prior/cli-samples.csv"));
    snprintf(pot, sizeof pot, "%s", sk_test_path("prior/cli-potential.json"));
    assert_int_equal(
        sk_test_cli(run, "hand synthesize --people 3 --trials 1 --frames 20 -o '%s'", csv), 0);
    const char *report = sk_test_path("prior/cli-report.json"),
               *plot = sk_test_path("prior/cli-plot.png");
    assert_int_equal(
        sk_test_cli(
            run,
            "hand evaluate '%s' --pins I.MCP.flex,I.PIP.flex --pins L.MCP.flex --group person "
            "--ignore-columns trial --report '%s' --plot '%s' --method gaussian",
            csv, report, plot),
        0);
    assert_non_null(strstr(run->out, "pins L.MCP.flex: held-out RMS error"));
    assert_true(sk_test_file_exists(plot));
    char *text;
    size_t size;
    sk_error err;
    assert_int_equal(sk_read_file(report, 0, &text, &size, &err), SK_OK);
    /* the layout: a list, one entry per pin set, exactly these keys */
    assert_true(text[0] == '[');
    assert_non_null(strstr(text, "\"pins\":\t[\"I.MCP.flex\", \"I.PIP.flex\"]"));
    assert_non_null(strstr(text, "\"model_rms_deg\":"));
    assert_non_null(strstr(text, "\"per_joint\":\t{\n\t\t\t\"I.DIP.flex\":"));
    assert_non_null(strstr(text, "\"baselines\":\t{\n\t\t\t\"mean\":"));
    assert_non_null(strstr(text, "\"pca\":\t{\n\t\t\t\t\"k\":\t6,\n\t\t\t\t\"rms_deg\":"));
    assert_non_null(
        strstr(text, "\"solves\":\t{\n\t\t\t\"count\":\t600,\n\t\t\t\"not_converged\":\t0,"));
    free(text);
    /* the lookup-table model (3.2.3) */
    assert_int_equal(
        sk_test_cli(run,
                    "hand evaluate '%s' --pins L.MCP.flex --group person --ignore-columns trial "
                    "--model lookup-tables --pairs R.MCP.flex:L.MCP.flex --lut-resolution 60",
                    csv),
        0);
    assert_non_null(strstr(run->out, "tables"));
    assert_non_null(strstr(run->out, "0 not converged"));
    assert_int_equal(
        sk_test_cli(run,
                    "hand evaluate '%s' --pins L.MCP.flex --ignore-columns trial,person "
                    "--model lookup-tables",
                    csv),
        2);
    assert_non_null(strstr(run->err, "--model lookup-tables needs --pairs"));
    /* calibrate a potential and pose with it */
    const char *pose = sk_test_path("prior/cli-pose.json");
    assert_int_equal(
        sk_test_cli(
            run,
            "hand calibrate '%s' --group person --ignore-columns trial --components 3 -o '%s' -q",
            csv, pot),
        0);
    assert_int_equal(
        sk_test_cli(run, "hand pose --potential '%s' --pin I.MCP.flex=60 -o '%s'", pot, pose), 0);
    assert_true(sk_test_file_exists(pose));
    /* animation and the surface with a calibrated potential (a mixture: pins and torques) */
    const char *angles = sk_test_path("prior/cli-angles.csv"),
               *mesh = sk_test_path("prior/cli-mesh.obj");
    assert_int_equal(
        sk_test_cli(run, "hand animate '%s/hand/piano-key.json' --potential '%s' --angles '%s' -q",
                    SK_TEST_PRESET_DIR, pot, angles),
        0);
    assert_true(sk_test_file_exists(angles));
    assert_int_equal(sk_test_cli(run,
                                 "hand animate '%s/hand/little-mcp.json' --potential '%s' "
                                 "--constraints natural --angles '%s'",
                                 SK_TEST_PRESET_DIR, pot, angles),
                     2);
    assert_non_null(strstr(run->err, "--potential does not go with --constraints"));
    assert_int_equal(
        sk_test_cli(run, "hand mesh --potential '%s' --pin I.MCP.flex=60 --lod 2 -o '%s' -q", pot,
                    mesh),
        0);
    assert_true(sk_test_file_exists(mesh));
    /* the thesis's form with the pairs chosen, written as a potential */
    const char *pairs_pot = sk_test_path("prior/cli-pairs.json");
    assert_int_equal(
        sk_test_cli(
            run,
            "hand calibrate '%s' --group person --ignore-columns trial --method pairs "
            "--pairs R.MCP.flex:L.MCP.flex,L.MCP.flex:L.PIP.flex,I.PIP.flex:M.PIP.flex -o '%s'",
            csv, pairs_pot),
        0);
    assert_non_null(strstr(run->out, "weight scale"));
    assert_int_equal(
        sk_test_cli(run, "hand pose --potential '%s' --pin L.MCP.flex=70 -o '%s'", pairs_pot, pose),
        0);
    assert_int_equal(
        sk_test_cli(run, "hand calibrate '%s' --ignore-columns trial,person --max-pairs 3 -o '%s'",
                    csv, pairs_pot),
        2);
    assert_non_null(strstr(run->err, "--max-pairs needs --method pairs"));
    assert_int_equal(
        sk_test_cli(
            run,
            "hand evaluate '%s' --pins L.MCP.flex --group person --ignore-columns trial "
            "--method pairs --pairs R.MCP.flex:L.MCP.flex,I.PIP.flex:M.PIP.flex --max-pairs 2",
            csv),
        0);
    assert_non_null(strstr(run->out, "pins L.MCP.flex: held-out RMS error"));
    /* the group's help lists its commands; an unknown one is a one-line error */
    assert_int_equal(sk_test_cli(run, "hand --help"), 0);
    assert_non_null(strstr(run->out, "hand evaluate"));
    assert_non_null(strstr(run->out, "hand calibrate"));
    assert_int_equal(sk_test_cli(run, "hand evalute"), 2);
    assert_int_equal(sk_test_count_lines(run->err), 1);
    assert_non_null(strstr(run->err, "unknown command 'hand evalute'"));
    /* errors: one line, exit 2, no report */
    const char *none = sk_test_path("prior/cli-none.json");
    assert_int_equal(
        sk_test_cli(
            run, "hand evaluate '%s' --pins T.MCP.flex --ignore-columns trial,person --report '%s'",
            csv, none),
        2);
    assert_int_equal(sk_test_count_lines(run->err), 1);
    assert_non_null(strstr(run->err, "T.MCP.flex is not a joint-angle column"));
    assert_false(sk_test_file_exists(none));
    assert_int_equal(sk_test_cli(run, "hand evaluate '%s' --ignore-columns trial,person", csv), 2);
    assert_non_null(strstr(run->err, "--pins is required"));
    assert_int_equal(
        sk_test_cli(run, "hand evaluate '%s' --pins L.MCP.flx --ignore-columns trial,person", csv),
        2);
    assert_int_equal(sk_test_cli(run, "hand evaluate '%s' --pins L.MCP.flex --group subject", csv),
                     2);
    /* radians read as degrees: a warning */
    const char *rad = sk_test_path("prior/cli-rad.csv");
    const char *rad_text =
        "I.MCP.flex,I.PIP.flex\n0.1,0.2\n0.5,0.9\n0.3,0.4\n0.7,1.1\n0.2,0.3\n0.6,1.0\n";
    sk_test_write_file(rad, rad_text, strlen(rad_text));
    assert_int_equal(
        sk_test_cli(run, "hand evaluate '%s' --pins I.MCP.flex --folds 2 --method gaussian", rad),
        0);
    assert_non_null(strstr(run->err, "look like radians"));
    assert_int_equal(
        sk_test_cli(run,
                    "hand evaluate '%s' --pins I.MCP.flex --folds 2 --method gaussian --units rad",
                    rad),
        0);
    assert_null(strstr(run->err, "warning"));
    free(run);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_gaussian_recovered),
        cmocka_unit_test(test_pair_choice),
        cmocka_unit_test(test_mixture_torques),
        cmocka_unit_test(test_mixture_beats_gaussian_on_nonlinear_relation),
        cmocka_unit_test(test_lut_solves_converge),
        cmocka_unit_test(test_samples_csv_options),
        cmocka_unit_test(test_potential_file_round_trip_and_errors),
        cmocka_unit_test(test_evaluation_deterministic_over_threads),
        cmocka_unit_test(test_shipped_data_set_is_generated),
        cmocka_unit_test(test_cli_evaluate),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
