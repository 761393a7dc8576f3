/* The springs solved by XPBD (Macklin, Mueller & Chentanez 2016, "XPBD: position-based
 * simulation of compliant constrained dynamics"; one iteration per substep as in Macklin
 * et al. 2019, "Small steps in physics simulation"). A spring of stiffness k is a distance
 * constraint C = |x_i - x_j| - r of compliance alpha = 1/k, with the damping of eq. (26):
 *   dlambda = -(C + gamma dC . (x - x_n)) / ((1 + gamma)(w_i + w_j) + alpha / h^2),
 *   gamma = alpha c / h,   x_i += w_i dlambda n,  x_j -= w_j dlambda n,
 * w the inverse masses (0 for muscle and bone points). With x in mm and k, c, m in SI the
 * update is in mm (only the ratios alpha / w and gamma enter).
 *
 * Damping that means what it says: a mass on a spring stepped this way decays per step by
 * |lambda|^2 = 1 / (1 + (1 + gamma) (omega h)^2), omega = sqrt(k / mu) (mu the reduced
 * mass): gamma = 2 zeta / (omega h) gives zeta + omega h / 2, the implicit step's own
 * damping added to the one asked for. So gamma is chosen to give exactly zeta:
 * (1 + gamma) (omega h)^2 = exp(2 zeta omega h) - 1, and never below 0 (a spring whose
 * own frequency is above 2 zeta / h keeps some of the step's damping; none is ever
 * taken away, so the scheme stays dissipative). The tethers are the same
 * constraint with rest length 0 to a driven target, one per axis (a zero-length spring is
 * isotropic), solved after the springs.
 *
 * Order (Gauss-Seidel): the grid is cut into slabs across its longest axis; a spring
 * belongs to the slab of its lower end. Springs join grid neighbours, so two slabs with a
 * slab between them share no point: all even slabs are solved side by side, then all odd
 * ones (two synchronisations per step), each slab's springs in a fixed order (by lattice
 * direction, so consecutive springs share no point and overlap in the processor). The
 * order depends only on the model, so the result is the same for any thread count. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "tissue/solver.h"

#define MAX_SLABS 64

/* One spring as the solve reads it: its ends, rest length, w_i / denominator,
 * w_j / denominator, gamma and (alpha / h^2) / denominator (32 bytes, two springs per
 * cache line). */
typedef struct spring {
    uint32_t i, j;
    double rest;
    float ci, cj, gamma, ca;
} spring;

struct sk__solver {
    size_t count;
    int slabs;
    size_t start[MAX_SLABS + 1]; /* springs of slab s: start[s] .. start[s + 1] */
    spring *springs;
    double *w; /* inverse mass of every point */
    size_t free_count;
    double *tether_coef, *tether_gamma, *tether_ca; /* per free point: w / ((1 + gamma) w + alpha / h^2),
                                                       gamma, (alpha / h^2) / the same */
    int iterations;
    /* with more than one iteration: alpha lambda of every spring and tether axis (lambda
       accumulates over a step's iterations, eq. 18) */
    float *mu;
    double *tether_mu;
};

void sk__spring_constants(const sk_tissue_model *m, size_t s, double *stiffness, double *damping)
{
    const sk_tissue_material_desc *mat = &m->desc.material;
    int cls = m->spring_class[s];
    double k = cls == SK__SPRING_SKIN ? mat->skin_stiffness : cls == SK__SPRING_ANCHOR ? mat->anchor_stiffness
                                                                                       : mat->fat_stiffness;
    double mi = m->mass[m->spring_i[s]], mj = m->mass[m->spring_j[s]];
    double mu = mi > 0 && mj > 0 ? mi * mj / (mi + mj) : (mi > 0 ? mi : mj);
    *stiffness = k;
    *damping = 2.0 * mat->damping_ratio * sqrt(k * mu);
}

/* The damping parameter that gives a spring of frequency omega (omega h = oh) exactly the
 * damping ratio zeta (see above). */
static double damping_gamma(double zeta, double oh)
{
    double g = expm1(2.0 * zeta * oh) / (oh * oh) - 1.0;
    return g > 0.0 ? g : 0.0;
}

static void destroy(sk__solver *s)
{
    if (!s) return;
    free(s->springs);
    free(s->w);
    free(s->tether_coef);
    free(s->tether_gamma);
    free(s->tether_ca);
    free(s->mu);
    free(s->tether_mu);
    free(s);
}

static sk_result create(const sk_tissue_model *m, double h, sk__solver **out, sk_error *err)
{
    sk__solver *s = calloc(1, sizeof *s);
    if (!s) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    size_t n = m->spring_count;
    s->count = n;
    s->springs = malloc((n ? n : 1) * sizeof *s->springs);
    s->w = malloc(m->point_count * sizeof *s->w);
    int *slab = malloc((n ? n : 1) * sizeof *slab);
    s->free_count = m->skin_count + m->fat_count;
    s->tether_coef = malloc((s->free_count ? s->free_count : 1) * sizeof *s->tether_coef);
    s->tether_gamma = malloc((s->free_count ? s->free_count : 1) * sizeof *s->tether_gamma);
    s->tether_ca = malloc((s->free_count ? s->free_count : 1) * sizeof *s->tether_ca);
    s->iterations = m->desc.simulation.iterations > 0 ? m->desc.simulation.iterations : 1;
    if (s->iterations > 1) {
        s->mu = calloc(n ? n : 1, sizeof *s->mu);
        s->tether_mu = calloc(3 * (s->free_count ? s->free_count : 1), sizeof *s->tether_mu);
    }
    if (!s->springs || !s->w || !slab || !s->tether_coef || !s->tether_gamma || !s->tether_ca ||
        (s->iterations > 1 && (!s->mu || !s->tether_mu))) {
        free(slab);
        destroy(s);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for %zu springs", n);
    }
    for (size_t p = 0; p < m->point_count; p++) s->w[p] = m->mass[p] > 0 ? 1.0 / m->mass[p] : 0.0;
    /* slabs of at least two cells across the longest axis */
    const sk__grid *g = &m->grid;
    int axis = 0;
    for (int a = 1; a < 3; a++)
        if (g->n[a] > g->n[axis]) axis = a;
    int cells = g->n[axis];
    s->slabs = cells / 2 < MAX_SLABS ? cells / 2 : MAX_SLABS;
    if (s->slabs < 1) s->slabs = 1;
    size_t count[MAX_SLABS] = {0};
    for (size_t k = 0; k < n; k++) {
        int a[3], b[3];
        sk__grid_coords(g, m->grid_of[m->spring_i[k]], a);
        sk__grid_coords(g, m->grid_of[m->spring_j[k]], b);
        int low = a[axis] < b[axis] ? a[axis] : b[axis];
        slab[k] = (int)((long)low * s->slabs / cells);
        count[slab[k]]++;
    }
    s->start[0] = 0;
    for (int i = 0; i < s->slabs; i++) s->start[i + 1] = s->start[i] + count[i];
    size_t fill[MAX_SLABS];
    memcpy(fill, s->start, sizeof fill);
    /* the model's springs are sorted by colour: a stable split into slabs keeps that order */
    double zeta = m->desc.material.damping_ratio;
    for (size_t k = 0; k < n; k++) {
        double stiffness, damping;
        sk__spring_constants(m, k, &stiffness, &damping);
        double wsum = s->w[m->spring_i[k]] + s->w[m->spring_j[k]]; /* 1 / mu */
        double alpha = 1.0 / stiffness;                             /* compliance, 1 / (N/m) */
        double gamma = damping_gamma(zeta, sqrt(stiffness * wsum) * h);
        spring *sp = &s->springs[fill[slab[k]]++];
        sp->i = m->spring_i[k];
        sp->j = m->spring_j[k];
        sp->rest = m->spring_rest[k];
        double inv_denom = 1.0 / ((1.0 + gamma) * wsum + alpha / (h * h));
        sp->gamma = (float)gamma;
        sp->ci = (float)(s->w[m->spring_i[k]] * inv_denom);
        sp->cj = (float)(s->w[m->spring_j[k]] * inv_denom);
        sp->ca = (float)(alpha / (h * h) * inv_denom);
    }
    free(slab);
    const sk_tissue_material_desc *mat = &m->desc.material;
    for (size_t p = 0; p < s->free_count; p++) {
        double k = mat->tether_stiffness, w = s->w[p];
        double alpha = 1.0 / k, gamma = damping_gamma(zeta, sqrt(k * w) * h);
        s->tether_gamma[p] = gamma;
        s->tether_coef[p] = w / ((1.0 + gamma) * w + alpha / (h * h));
        s->tether_ca[p] = alpha / (h * h) / ((1.0 + gamma) * w + alpha / (h * h));
    }
    *out = s;
    return SK_OK;
}

/* One Gauss-Seidel sweep of a slab's springs; `mu` (alpha lambda per spring) when the step
 * iterates, NULL for a single iteration (lambda starts at 0 each step). */
static void solve_slab(const sk__solver *s, int slab, double *x, const double *base, float *mu)
{
    for (size_t k = s->start[slab]; k < s->start[slab + 1]; k++) {
        const spring *sp = &s->springs[k];
        size_t a = sp->i, b = sp->j;
        double *xa = x + 3 * a, *xb = x + 3 * b;
        double dx = xa[0] - xb[0], dy = xa[1] - xb[1], dz = xa[2] - xb[2];
        double len = sqrt(dx * dx + dy * dy + dz * dz);
        if (!(len > 1e-12)) continue;
        double inv = 1.0 / len;
        dx *= inv;
        dy *= inv;
        dz *= inv;
        const double *ba = base + 3 * a, *bb = base + 3 * b;
        double rel = dx * ((xa[0] - ba[0]) - (xb[0] - bb[0])) + dy * ((xa[1] - ba[1]) - (xb[1] - bb[1])) +
                     dz * ((xa[2] - ba[2]) - (xb[2] - bb[2]));
        double force = (len - sp->rest) + sp->gamma * rel; /* -dlambda times the denominator */
        if (mu) {
            force += mu[k];
            mu[k] -= (float)(sp->ca * force);
        }
        double ga = -sp->ci * force, gb = -sp->cj * force;
        xa[0] += ga * dx;
        xa[1] += ga * dy;
        xa[2] += ga * dz;
        xb[0] -= gb * dx;
        xb[1] -= gb * dy;
        xb[2] -= gb * dz;
    }
}

static void step(sk__solver *s, double *x, const double *base, const double *target, const double *target_base)
{
    bool iterate = s->iterations > 1;
    if (iterate) {
#pragma omp for schedule(static)
        for (size_t k = 0; k < s->count; k++) s->mu[k] = 0.0f;
#pragma omp for schedule(static)
        for (size_t i = 0; i < 3 * s->free_count; i++) s->tether_mu[i] = 0.0;
    }
    for (int it = 0; it < s->iterations; it++) {
        for (int parity = 0; parity < 2; parity++) {
#pragma omp for schedule(dynamic, 1)
            for (int slab = parity; slab < s->slabs; slab += 2) solve_slab(s, slab, x, base, iterate ? s->mu : NULL);
        }
#pragma omp for schedule(static)
        for (size_t p = 0; p < s->free_count; p++) {
            double a = s->tether_coef[p], g = s->tether_gamma[p], ca = s->tether_ca[p];
            for (int c = 0; c < 3; c++) {
                size_t i = 3 * p + (size_t)c;
                double d = x[i] - target[i], rel = (x[i] - base[i]) - (target[i] - target_base[i]);
                double force = d + g * rel;
                if (iterate) {
                    force += s->tether_mu[i];
                    s->tether_mu[i] -= ca * force;
                }
                x[i] -= a * force;
            }
        }
    }
}

const sk__solver_ops sk__solver_xpbd = {"xpbd", create, destroy, step};
