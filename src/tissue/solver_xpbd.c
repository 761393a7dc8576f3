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
 * order depends only on the model, so the result is the same for any thread count.
 *
 * Within a run of springs of one colour no two share a point, so two of them are solved
 * at once in the two lanes of an SSE2 vector: each lane does the very operations of the
 * one-spring code (no fused multiply-add, correctly rounded square root and division),
 * so the result is the same bit for bit whichever path a spring takes. */
#include <math.h>
#include <omp.h>
#include <stdlib.h>
#include <string.h>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

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
    size_t *run;    /* first spring of every run of one colour in one slab, then count */
    size_t slab_run[MAX_SLABS + 1]; /* runs of slab s: slab_run[s] .. slab_run[s + 1] */
    size_t parity_before[MAX_SLABS]; /* springs in the slabs of the same parity before s */
    size_t parity_total[2];
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
    free(s->run);
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
    int colours = m->colour_count > 0 ? m->colour_count : 1;
    size_t *colour_count = calloc((size_t)s->slabs * (size_t)colours, sizeof *colour_count);
    if (!colour_count) {
        free(slab);
        destroy(s);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for %zu springs", n);
    }
    int colour = 0;
    for (size_t k = 0; k < n; k++) {
        while (colour + 1 < m->colour_count && k >= m->colour_start[colour + 1]) colour++;
        int a[3], b[3];
        sk__grid_coords(g, m->grid_of[m->spring_i[k]], a);
        sk__grid_coords(g, m->grid_of[m->spring_j[k]], b);
        int low = a[axis] < b[axis] ? a[axis] : b[axis];
        slab[k] = (int)((long)low * s->slabs / cells);
        count[slab[k]]++;
        colour_count[(size_t)slab[k] * (size_t)colours + (size_t)colour]++;
    }
    s->start[0] = 0;
    for (int i = 0; i < s->slabs; i++) {
        s->start[i + 1] = s->start[i] + count[i];
        s->parity_before[i] = s->parity_total[i & 1];
        s->parity_total[i & 1] += count[i];
    }
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
    /* the runs: a slab's springs keep the model's colour order (in a model without colours
       every spring is a run of its own) */
    s->run = malloc(((m->colour_count > 0 ? (size_t)s->slabs * (size_t)colours : n) + 1) * sizeof *s->run);
    if (!s->run) {
        free(colour_count);
        free(slab);
        destroy(s);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for %zu springs", n);
    }
    size_t runs = 0;
    for (int sl = 0; sl < s->slabs; sl++) {
        s->slab_run[sl] = runs;
        size_t k0 = s->start[sl];
        for (int c = 0; c < colours; c++) {
            size_t in_colour = colour_count[(size_t)sl * (size_t)colours + (size_t)c];
            if (m->colour_count == 0)
                for (size_t k = k0; k < k0 + in_colour; k++) s->run[runs++] = k;
            else if (in_colour)
                s->run[runs++] = k0;
            k0 += in_colour;
        }
    }
    s->slab_run[s->slabs] = runs;
    s->run[runs] = n;
    free(colour_count);
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

/* Below this length a spring has no direction and is left as it is. */
#define SHORTEST 1e-12

/* One spring (see the top of the file). The relative motion of the ends over the step
 * along the spring, n . ((x_a - b_a) - (x_b - b_b)), is taken as d . (d - (b_a - b_b)) / |d|
 * with d = x_a - x_b (exactly 0 when nothing moved). `mu`: alpha lambda of the spring
 * when the step iterates, NULL for one iteration. */
static inline void solve_one(const spring *sp, double *x, const double *base, float *mu)
{
    double *xa = x + 3 * (size_t)sp->i, *xb = x + 3 * (size_t)sp->j;
    const double *ba = base + 3 * (size_t)sp->i, *bb = base + 3 * (size_t)sp->j;
    double dx = xa[0] - xb[0], dy = xa[1] - xb[1], dz = xa[2] - xb[2];
    double mx = dx - (ba[0] - bb[0]), my = dy - (ba[1] - bb[1]), mz = dz - (ba[2] - bb[2]);
    double len = sqrt(dx * dx + dy * dy + dz * dz);
    bool has_direction = len > SHORTEST;
    double inv = 1.0 / (has_direction ? len : 1.0);
    double rel = (dx * mx + dy * my + dz * mz) * inv;
    double force = (len - sp->rest) + sp->gamma * rel; /* -dlambda times the denominator */
    if (mu) {
        force += *mu;
        if (has_direction) *mu -= (float)(sp->ca * force);
    }
    double f = has_direction ? force * inv : 0.0;
    double ga = -sp->ci * f, gb = -sp->cj * f;
    xa[0] += ga * dx;
    xa[1] += ga * dy;
    xa[2] += ga * dz;
    xb[0] -= gb * dx;
    xb[1] -= gb * dy;
    xb[2] -= gb * dz;
}

#if defined(__SSE2__)
/* Points p0 and p1 (3 doubles each) as the two lanes of their x, y and z. */
static inline void load_pair(const double *p0, const double *p1, __m128d *x, __m128d *y, __m128d *z)
{
    *x = _mm_setr_pd(p0[0], p1[0]);
    *y = _mm_setr_pd(p0[1], p1[1]);
    *z = _mm_setr_pd(p0[2], p1[2]);
}

static inline void store_pair(double *p0, double *p1, __m128d x, __m128d y, __m128d z)
{
    _mm_storel_pd(p0, x);
    _mm_storel_pd(p0 + 1, y);
    _mm_storel_pd(p0 + 2, z);
    _mm_storeh_pd(p1, x);
    _mm_storeh_pd(p1 + 1, y);
    _mm_storeh_pd(p1 + 2, z);
}

/* Two springs of one run (they share no point) in the two lanes: solve_one's operations. */
static inline void solve_two(const spring *s0, const spring *s1, double *x, const double *base)
{
    double *xa0 = x + 3 * (size_t)s0->i, *xb0 = x + 3 * (size_t)s0->j;
    double *xa1 = x + 3 * (size_t)s1->i, *xb1 = x + 3 * (size_t)s1->j;
    __m128d ax, ay, az, bx, by, bz, bax, bay, baz, bbx, bby, bbz;
    load_pair(xa0, xa1, &ax, &ay, &az);
    load_pair(xb0, xb1, &bx, &by, &bz);
    load_pair(base + 3 * (size_t)s0->i, base + 3 * (size_t)s1->i, &bax, &bay, &baz);
    load_pair(base + 3 * (size_t)s0->j, base + 3 * (size_t)s1->j, &bbx, &bby, &bbz);
    __m128d dx = _mm_sub_pd(ax, bx), dy = _mm_sub_pd(ay, by), dz = _mm_sub_pd(az, bz);
    __m128d mx = _mm_sub_pd(dx, _mm_sub_pd(bax, bbx)), my = _mm_sub_pd(dy, _mm_sub_pd(bay, bby)),
            mz = _mm_sub_pd(dz, _mm_sub_pd(baz, bbz));
    __m128d len = _mm_sqrt_pd(_mm_add_pd(_mm_add_pd(_mm_mul_pd(dx, dx), _mm_mul_pd(dy, dy)), _mm_mul_pd(dz, dz)));
    __m128d has_direction = _mm_cmpgt_pd(len, _mm_set1_pd(SHORTEST));
    __m128d one = _mm_set1_pd(1.0);
    __m128d safe = _mm_or_pd(_mm_and_pd(has_direction, len), _mm_andnot_pd(has_direction, one));
    __m128d inv = _mm_div_pd(one, safe);
    __m128d rel = _mm_mul_pd(_mm_add_pd(_mm_add_pd(_mm_mul_pd(dx, mx), _mm_mul_pd(dy, my)), _mm_mul_pd(dz, mz)), inv);
    __m128d force = _mm_add_pd(_mm_sub_pd(len, _mm_setr_pd(s0->rest, s1->rest)),
                               _mm_mul_pd(_mm_setr_pd(s0->gamma, s1->gamma), rel));
    __m128d f = _mm_and_pd(has_direction, _mm_mul_pd(force, inv));
    __m128d ga = _mm_mul_pd(_mm_setr_pd(-s0->ci, -s1->ci), f), gb = _mm_mul_pd(_mm_setr_pd(-s0->cj, -s1->cj), f);
    store_pair(xa0, xa1, _mm_add_pd(ax, _mm_mul_pd(ga, dx)), _mm_add_pd(ay, _mm_mul_pd(ga, dy)),
               _mm_add_pd(az, _mm_mul_pd(ga, dz)));
    store_pair(xb0, xb1, _mm_sub_pd(bx, _mm_mul_pd(gb, dx)), _mm_sub_pd(by, _mm_mul_pd(gb, dy)),
               _mm_sub_pd(bz, _mm_mul_pd(gb, dz)));
}
#endif

/* One Gauss-Seidel sweep of a slab's springs, run by run; `mu` (alpha lambda per spring)
 * when the step iterates, NULL for a single iteration (lambda starts at 0 each step). */
static void solve_slab(const sk__solver *s, int slab, double *x, const double *base, float *mu)
{
    for (size_t r = s->slab_run[slab]; r < s->slab_run[slab + 1]; r++) {
        size_t k = s->run[r], end = s->run[r + 1];
        if (mu) {
            for (; k < end; k++) solve_one(&s->springs[k], x, base, mu + k);
            continue;
        }
#if defined(__SSE2__)
        for (; k + 1 < end; k += 2) solve_two(&s->springs[k], &s->springs[k + 1], x, base);
#endif
        for (; k < end; k++) solve_one(&s->springs[k], x, base, NULL);
    }
}

/* The thread that solves a slab: each thread takes a run of consecutive slabs of one
 * parity holding about its share of their springs, so the slabs solved side by side lie
 * far apart (no cache line written by two threads at once but at the runs' ends) and a
 * thread's odd slabs lie beside its even ones (their points are already in its cache).
 * Which thread solves a slab does not change the result. */
static int slab_owner(const sk__solver *s, int slab, int threads)
{
    size_t total = s->parity_total[slab & 1];
    if (threads <= 1 || total == 0) return 0;
    double middle = (double)s->parity_before[slab] + 0.5 * (double)(s->start[slab + 1] - s->start[slab]);
    int owner = (int)(middle / (double)total * threads);
    return owner < threads ? owner : threads - 1;
}

static void step(sk__solver *s, double *x, const double *base, const double *target, const double *target_base)
{
    bool iterate = s->iterations > 1;
    int thread = omp_get_thread_num(), threads = omp_get_num_threads();
    if (iterate) {
#pragma omp for schedule(static)
        for (size_t k = 0; k < s->count; k++) s->mu[k] = 0.0f;
#pragma omp for schedule(static)
        for (size_t i = 0; i < 3 * s->free_count; i++) s->tether_mu[i] = 0.0;
    }
    for (int it = 0; it < s->iterations; it++) {
        for (int parity = 0; parity < 2; parity++) {
            for (int slab = parity; slab < s->slabs; slab += 2)
                if (slab_owner(s, slab, threads) == thread) solve_slab(s, slab, x, base, iterate ? s->mu : NULL);
#pragma omp barrier
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
