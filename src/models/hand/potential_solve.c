/* Posing with a calibrated potential: each component is a thesis-form set with its own
 * relaxed posture (eqs. 3.7, 3.17), solved within the joint limits by the equilibrium
 * solver; with a mixture the components' equilibria are blended by the probability of
 * the pinned values under each component (the grasp type the pins suggest). Torques on
 * free DOFs tilt the components' Gaussians (the energy minus the torques' work, read as
 * a density at the potential's temperature `scale`), which moves the probabilities
 * toward the components the torques push into (limits left out of the probabilities). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "models/hand/gaussian_internal.h"
#include "models/hand/potential_internal.h"

#define M_MAX SK_HAND_POTENTIAL_MAX_COMPONENTS
#define D_MAX SK_HAND_DOF_COUNT

struct sk_hand_potential_solver {
    int m, d;
    double temperature; /* the potential's scale: K + A'WA = scale x precision */
    int dof[D_MAX];
    int at[SK_HAND_DOF_COUNT]; /* index among the calibrated DOFs, or -1 */
    double min[SK_HAND_DOF_COUNT], max[SK_HAND_DOF_COUNT];
    double log_weight[M_MAX];
    double mean[M_MAX][D_MAX];
    double cov[M_MAX][D_MAX * D_MAX];
    double prec[M_MAX][D_MAX * D_MAX];
    sk_hand_solver *solver[M_MAX];
};

void sk_hand_potential_solver_destroy(sk_hand_potential_solver *ps)
{
    if (!ps) return;
    for (int c = 0; c < ps->m; c++) sk_hand_solver_destroy(ps->solver[c]);
    free(ps);
}

sk_result sk_hand_potential_solver_create(sk_hand_potential_solver **out,
                                          const sk_hand_skeleton *skel, const sk_hand_potential *p,
                                          const sk_hand_solver_desc *desc, sk_error *err)
{
    *out = NULL;
    if (p->component_count < 1 || p->component_count > M_MAX || !p->component)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "the potential has no components");
    sk_hand_potential_solver *ps = calloc(1, sizeof *ps);
    if (!ps) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    ps->m = p->component_count;
    ps->d = p->dof_count;
    ps->temperature = p->scale;
    memcpy(ps->dof, p->dof, sizeof(int) * (size_t)p->dof_count);
    for (int i = 0; i < SK_HAND_DOF_COUNT; i++) {
        ps->at[i] = -1;
        ps->min[i] = skel->dof[i].min;
        ps->max[i] = skel->dof[i].max;
    }
    for (int a = 0; a < ps->d; a++) ps->at[ps->dof[a]] = a;
    sk_result r = SK_OK;
    for (int c = 0; c < ps->m && r == SK_OK; c++) {
        const sk_hand_potential_component *comp = &p->component[c];
        ps->log_weight[c] = log(comp->weight);
        r = sk_hand_potential_gaussian(p, c, ps->mean[c], ps->cov[c], err);
        memcpy(ps->prec[c], ps->cov[c], sizeof(double) * (size_t)ps->d * ps->d);
        if (r == SK_OK && !sk__hand_spd_inverse(ps->prec[c], ps->d))
            r = sk_fail(err, SK_ERROR_NUMERIC,
                        "component %d: the covariance is not positive definite", c);
        /* the component's relaxed posture replaces the skeleton's (eq. 3.7) */
        sk_hand_skeleton own = *skel;
        for (int i = 0; i < SK_HAND_DOF_COUNT; i++) own.dof[i].relaxed = comp->relaxed[i];
        if (r == SK_OK)
            r = sk_hand_solver_create(&ps->solver[c], &own, &comp->constraints, NULL, 0, desc, err);
    }
    if (r != SK_OK) {
        sk_hand_potential_solver_destroy(ps);
        return r;
    }
    *out = ps;
    return SK_OK;
}

/* log of the tilt of component c by torques t = tau / temperature on the free calibrated
 * DOFs u given the pins p: log E[exp(t'x_u) | x_p] = t'mu_u|p + t'Sigma_u|p t / 2, with
 * Sigma_u|p = P_uu^-1 and mu_u|p = mu_u - P_uu^-1 P_up (x_p - mu_p). */
static double tilt(const sk_hand_potential_solver *ps, int c, const sk_hand_input *in)
{
    int d = ps->d, u[D_MAX], nu = 0;
    double t[D_MAX], z[D_MAX], rr[D_MAX], puu[D_MAX * D_MAX];
    for (int a = 0; a < d; a++)
        if (!in->pinned[ps->dof[a]]) u[nu++] = a;
    double result = 0.0;
    for (int i = 0; i < nu; i++) {
        int a = u[i];
        t[i] = in->torque[ps->dof[a]] / ps->temperature;
        rr[i] = 0.0;
        for (int b = 0; b < d; b++) {
            int dof = ps->dof[b];
            if (!in->pinned[dof]) continue;
            double v = sk_clampd(in->pin_value[dof], ps->min[dof], ps->max[dof]);
            rr[i] += ps->prec[c][b * d + a] * (v - ps->mean[c][b]);
        }
        for (int j = 0; j < nu; j++) puu[j * nu + i] = ps->prec[c][u[j] * d + a];
        result += t[i] * ps->mean[c][a];
    }
    if (nu == 0 || !sk__hand_cholesky(puu, nu)) return 0.0;
    memcpy(z, t, sizeof(double) * (size_t)nu);
    sk__hand_cholesky_solve(puu, nu, z, 1);
    for (int i = 0; i < nu; i++) result += z[i] * (0.5 * t[i] - rr[i]);
    return result;
}

/* Probability of each component given the pinned calibrated DOFs (their marginal
 * Gaussian under the component times its weight) and tilted by the torques; the prior
 * weights without inputs. */
static void responsibilities(const sk_hand_potential_solver *ps, const sk_hand_input *in,
                             double *resp)
{
    bool torques = false;
    for (int a = 0; a < ps->d; a++)
        torques |= !in->pinned[ps->dof[a]] && in->torque[ps->dof[a]] != 0.0;
    int pin[D_MAX], np = 0;
    double v[D_MAX];
    for (int a = 0; a < ps->d; a++) {
        int dof = ps->dof[a];
        if (!in->pinned[dof]) continue;
        pin[np] = a;
        v[np++] = sk_clampd(in->pin_value[dof], ps->min[dof], ps->max[dof]);
    }
    double l[M_MAX], top = -INFINITY;
    for (int c = 0; c < ps->m; c++) {
        l[c] = ps->log_weight[c];
        if (np > 0) {
            double s[D_MAX * D_MAX], mu[D_MAX];
            for (int j = 0; j < np; j++) {
                mu[j] = ps->mean[c][pin[j]];
                for (int i = 0; i < np; i++) s[j * np + i] = ps->cov[c][pin[j] * ps->d + pin[i]];
            }
            if (sk__hand_cholesky(s, np))
                l[c] += sk__hand_gauss_logpdf(v, mu, s, sk__hand_cholesky_logdet(s, np), np);
            else
                l[c] = -INFINITY;
        }
        if (torques && isfinite(l[c])) l[c] += tilt(ps, c, in);
        top = fmax(top, l[c]);
    }
    double sum = 0.0;
    for (int c = 0; c < ps->m; c++) {
        resp[c] = isfinite(top) ? exp(l[c] - top) : 1.0;
        sum += resp[c];
    }
    for (int c = 0; c < ps->m; c++) resp[c] /= sum;
}

sk_result sk_hand_potential_solve(sk_hand_potential_solver *ps, const sk_hand_input *in,
                                  double dofs[SK_HAND_DOF_COUNT], sk_hand_solve_info *info,
                                  double *resp_out, sk_error *err)
{
    double resp[M_MAX];
    if (ps->m == 1)
        resp[0] = 1.0;
    else
        responsibilities(ps, in, resp);
    int best = 0;
    for (int c = 1; c < ps->m; c++)
        if (resp[c] > resp[best]) best = c;
    double acc[SK_HAND_DOF_COUNT] = {0}, used = 0.0;
    bool converged = true;
    sk_hand_solve_info best_info = {0};
    for (int c = 0; c < ps->m; c++) {
        /* components far less probable than the best change nothing visible */
        if (c != best && resp[c] < 1e-9) continue;
        double q[SK_HAND_DOF_COUNT];
        sk_hand_solve_info ci;
        sk_result r = sk_hand_solve(ps->solver[c], in, q, &ci, err);
        if (r != SK_OK) return r;
        converged &= ci.converged;
        if (c == best) best_info = ci;
        for (int i = 0; i < SK_HAND_DOF_COUNT; i++) acc[i] += resp[c] * q[i];
        used += resp[c];
    }
    for (int i = 0; i < SK_HAND_DOF_COUNT; i++) {
        double v = acc[i] / used;
        /* the blend of values within the limits stays within them (up to rounding) */
        dofs[i] = sk_clampd(v, ps->min[i], ps->max[i]);
    }
    for (int i = 0; i < SK_HAND_DOF_COUNT; i++)
        if (in->pinned[i]) dofs[i] = sk_clampd(in->pin_value[i], ps->min[i], ps->max[i]);
    if (info) {
        *info = best_info;
        info->converged = converged;
    }
    if (resp_out)
        for (int c = 0; c < ps->m; c++) resp_out[c] = resp[c];
    return SK_OK;
}
