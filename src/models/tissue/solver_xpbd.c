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
 * order depends only on the model, so the result is the same for any thread count. The
 * slabs of one parity touch disjoint points, so their springs commute: a thread solves
 * its slabs of one parity colour by colour, each colour's springs in all of them as one
 * run (the same result as slab after slab, with runs ten times as long).
 *
 * Within a run of springs of one colour no two share a point, so several are solved at
 * once in the lanes of a vector: two in SSE2, or four in AVX2 where the processor has it
 * (the points then copied for the step into 64-byte records of position and step start,
 * one aligned vector load each; a chunk of a run's springs first computes every spring's
 * factor, reading only, so their square roots and divisions overlap, then moves the
 * ends). Each lane does the very operations of the one-spring code
 * (no fused multiply-add, correctly rounded square root and division, the sums in the
 * same order), so the result is the same bit for bit whichever path a spring takes. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "models/tissue/simd.h"
#include "models/tissue/solver.h"

#define MAX_SLABS 64

/* The springs as the solve reads them, one array per quantity so that consecutive springs
 * load as vectors: their ends, rest length, w_i / denominator, w_j / denominator, gamma
 * and (alpha / h^2) / denominator. They are stored by parity of their slab, then colour,
 * then slab (each cell in the model's order). */
typedef struct spring_arrays {
    uint32_t *i, *j;
    double *rest;
    float *ci, *cj, *gamma, *ca;
} spring_arrays;

struct sk__solver {
    size_t count;
    int slabs, half; /* slabs, and slabs of parity 0 (those of parity 1: slabs - half) */
    int colours;     /* colours of the model (1 if it has none) */
    bool paired;     /* the springs of one run share no point (the model has colours) */
    bool wide;       /* four springs at once (AVX2), on the packed points */
    spring_arrays sp;
    size_t *cell; /* first spring of (parity, colour, slab / 2), in that order, then count */
    size_t parity_before[MAX_SLABS]; /* springs in the slabs of the same parity before s */
    size_t slab_count[MAX_SLABS];
    size_t parity_total[2];
    size_t point_count;
    double *packed; /* wide: per point x, y, z, 0, then its step start, 0 (64-byte aligned) */
    double *w;      /* inverse mass of every point */
    size_t free_count;
    double *tether_coef, *tether_gamma, *tether_ca; /* per free point: w / ((1 + gamma) w + alpha /
                                                       h^2), gamma, (alpha / h^2) / the same */
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
    double k = cls == SK__SPRING_SKIN     ? mat->skin_stiffness
               : cls == SK__SPRING_ANCHOR ? mat->anchor_stiffness
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
    free(s->sp.i);
    free(s->sp.j);
    free(s->sp.rest);
    free(s->sp.ci);
    free(s->sp.cj);
    free(s->sp.gamma);
    free(s->sp.ca);
    free(s->cell);
    free(s->packed);
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
    size_t n = m->spring_count, n1 = n ? n : 1;
    s->count = n;
    s->point_count = m->point_count;
    s->sp.i = malloc(n1 * sizeof *s->sp.i);
    s->sp.j = malloc(n1 * sizeof *s->sp.j);
    s->sp.rest = malloc(n1 * sizeof *s->sp.rest);
    s->sp.ci = malloc(n1 * sizeof *s->sp.ci);
    s->sp.cj = malloc(n1 * sizeof *s->sp.cj);
    s->sp.gamma = malloc(n1 * sizeof *s->sp.gamma);
    s->sp.ca = malloc(n1 * sizeof *s->sp.ca);
    s->w = malloc(m->point_count * sizeof *s->w);
    size_t *place = malloc(n1 * sizeof *place); /* cell of a spring, then its place */
    s->free_count = m->skin_count + m->fat_count;
    s->tether_coef = malloc((s->free_count ? s->free_count : 1) * sizeof *s->tether_coef);
    s->tether_gamma = malloc((s->free_count ? s->free_count : 1) * sizeof *s->tether_gamma);
    s->tether_ca = malloc((s->free_count ? s->free_count : 1) * sizeof *s->tether_ca);
    s->iterations = m->desc.simulation.iterations > 0 ? m->desc.simulation.iterations : 1;
    if (s->iterations > 1) {
        s->mu = calloc(n1, sizeof *s->mu);
        s->tether_mu = calloc(3 * (s->free_count ? s->free_count : 1), sizeof *s->tether_mu);
    }
    /* slabs of at least two cells across the longest axis */
    const sk__grid *g = &m->grid;
    int axis = 0;
    for (int a = 1; a < 3; a++)
        if (g->n[a] > g->n[axis]) axis = a;
    int cells = g->n[axis];
    s->slabs = cells / 2 < MAX_SLABS ? cells / 2 : MAX_SLABS;
    if (s->slabs < 1) s->slabs = 1;
    s->half = (s->slabs + 1) / 2;
    s->paired = m->colour_count > 0;
    s->colours = s->paired ? m->colour_count : 1;
#if defined(SK__HAVE_AVX2_PATH)
    s->wide = s->paired && s->iterations == 1 && sk__have_avx2();
    if (s->wide)
        s->packed = aligned_alloc(64, (m->point_count ? m->point_count : 1) * 8 * sizeof(double));
#endif
    size_t cell_count = 2 * (size_t)s->colours * (size_t)s->half;
    s->cell = calloc(cell_count + 1, sizeof *s->cell);
    size_t *fill = malloc((cell_count ? cell_count : 1) * sizeof *fill);
    if (!s->sp.i || !s->sp.j || !s->sp.rest || !s->sp.ci || !s->sp.cj || !s->sp.gamma ||
        !s->sp.ca || !s->w || !place || !s->cell || !fill || (s->wide && !s->packed) ||
        !s->tether_coef || !s->tether_gamma || !s->tether_ca ||
        (s->iterations > 1 && (!s->mu || !s->tether_mu))) {
        free(place);
        free(fill);
        destroy(s);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for %zu springs", n);
    }
    for (size_t p = 0; p < m->point_count; p++) s->w[p] = m->mass[p] > 0 ? 1.0 / m->mass[p] : 0.0;
    /* every spring's cell (parity, colour, slab / 2), counted */
    int colour = 0;
    for (size_t k = 0; k < n; k++) {
        while (s->paired && colour + 1 < m->colour_count && k >= m->colour_start[colour + 1])
            colour++;
        int a[3], b[3];
        sk__grid_coords(g, m->grid_of[m->spring_i[k]], a);
        sk__grid_coords(g, m->grid_of[m->spring_j[k]], b);
        int low = a[axis] < b[axis] ? a[axis] : b[axis];
        int slab = (int)((long)low * s->slabs / cells);
        s->slab_count[slab]++;
        place[k] = ((size_t)(slab & 1) * (size_t)s->colours + (size_t)colour) * (size_t)s->half +
                   (size_t)(slab / 2);
        s->cell[place[k] + 1]++;
    }
    for (size_t c = 0; c < cell_count; c++) s->cell[c + 1] += s->cell[c];
    for (int i = 0; i < s->slabs; i++) {
        s->parity_before[i] = s->parity_total[i & 1];
        s->parity_total[i & 1] += s->slab_count[i];
    }
    /* a stable counting sort into the cells: each keeps the model's order (by colour) */
    memcpy(fill, s->cell, cell_count * sizeof *fill);
    for (size_t k = 0; k < n; k++) place[k] = fill[place[k]]++;
    free(fill);
    double zeta = m->desc.material.damping_ratio;
    for (size_t k = 0; k < n; k++) {
        double stiffness, damping;
        sk__spring_constants(m, k, &stiffness, &damping);
        double wsum = s->w[m->spring_i[k]] + s->w[m->spring_j[k]]; /* 1 / mu */
        double alpha = 1.0 / stiffness;                            /* compliance, 1 / (N/m) */
        double gamma = damping_gamma(zeta, sqrt(stiffness * wsum) * h);
        double inv_denom = 1.0 / ((1.0 + gamma) * wsum + alpha / (h * h));
        size_t q = place[k];
        s->sp.i[q] = m->spring_i[k];
        s->sp.j[q] = m->spring_j[k];
        s->sp.rest[q] = m->spring_rest[k];
        s->sp.gamma[q] = (float)gamma;
        s->sp.ci[q] = (float)(s->w[m->spring_i[k]] * inv_denom);
        s->sp.cj[q] = (float)(s->w[m->spring_j[k]] * inv_denom);
        s->sp.ca[q] = (float)(alpha / (h * h) * inv_denom);
    }
    free(place);
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

/* Spring k (see the top of the file) with ends at xa and xb, which were at ba and bb at
 * the step's start: returns dlambda / |d| times minus the denominator (0 without a
 * direction) and d = xa - xb. The relative motion of the ends over the step along the
 * spring, n . ((x_a - b_a) - (x_b - b_b)), is taken as d . (d - (b_a - b_b)) / |d|
 * (exactly 0 when nothing moved). `mu`: alpha lambda of the spring when the step
 * iterates, NULL for one iteration. */
static inline double spring_factor(const spring_arrays *sp, size_t k, const double *xa,
                                   const double *ba, const double *xb, const double *bb, float *mu,
                                   double d[3])
{
    double dx = xa[0] - xb[0], dy = xa[1] - xb[1], dz = xa[2] - xb[2];
    double mx = dx - (ba[0] - bb[0]), my = dy - (ba[1] - bb[1]), mz = dz - (ba[2] - bb[2]);
    double len = sqrt(dx * dx + dy * dy + dz * dz);
    bool has_direction = len > SHORTEST;
    double inv = 1.0 / (has_direction ? len : 1.0);
    double rel = (dx * mx + dy * my + dz * mz) * inv;
    double force = (len - sp->rest[k]) + sp->gamma[k] * rel; /* -dlambda times the denominator */
    if (mu) {
        force += *mu;
        if (has_direction) *mu -= (float)(sp->ca[k] * force);
    }
    d[0] = dx, d[1] = dy, d[2] = dz;
    return has_direction ? force * inv : 0.0;
}

/* Spring k solved on x. */
static inline void solve_one(const spring_arrays *sp, size_t k, double *x, const double *base,
                             float *mu)
{
    double *xa = x + 3 * (size_t)sp->i[k], *xb = x + 3 * (size_t)sp->j[k], d[3];
    double f = spring_factor(sp, k, xa, base + 3 * (size_t)sp->i[k], xb,
                             base + 3 * (size_t)sp->j[k], mu, d);
    double ga = -sp->ci[k] * f, gb = -sp->cj[k] * f;
    for (int c = 0; c < 3; c++) {
        xa[c] += ga * d[c];
        xb[c] -= gb * d[c];
    }
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

/* Two floats of an array as doubles. */
static inline __m128d load_two_floats(const float *f)
{
    return _mm_cvtps_pd(_mm_setr_ps(f[0], f[1], 0.0f, 0.0f));
}

/* Springs k and k + 1 of one run (they share no point) in the two lanes: solve_one's
 * operations. */
static inline void solve_two(const spring_arrays *sp, size_t k, double *x, const double *base)
{
    double *xa0 = x + 3 * (size_t)sp->i[k], *xb0 = x + 3 * (size_t)sp->j[k];
    double *xa1 = x + 3 * (size_t)sp->i[k + 1], *xb1 = x + 3 * (size_t)sp->j[k + 1];
    __m128d ax, ay, az, bx, by, bz, bax, bay, baz, bbx, bby, bbz;
    load_pair(xa0, xa1, &ax, &ay, &az);
    load_pair(xb0, xb1, &bx, &by, &bz);
    load_pair(base + 3 * (size_t)sp->i[k], base + 3 * (size_t)sp->i[k + 1], &bax, &bay, &baz);
    load_pair(base + 3 * (size_t)sp->j[k], base + 3 * (size_t)sp->j[k + 1], &bbx, &bby, &bbz);
    __m128d dx = _mm_sub_pd(ax, bx), dy = _mm_sub_pd(ay, by), dz = _mm_sub_pd(az, bz);
    __m128d mx = _mm_sub_pd(dx, _mm_sub_pd(bax, bbx)), my = _mm_sub_pd(dy, _mm_sub_pd(bay, bby)),
            mz = _mm_sub_pd(dz, _mm_sub_pd(baz, bbz));
    __m128d len = _mm_sqrt_pd(
        _mm_add_pd(_mm_add_pd(_mm_mul_pd(dx, dx), _mm_mul_pd(dy, dy)), _mm_mul_pd(dz, dz)));
    __m128d has_direction = _mm_cmpgt_pd(len, _mm_set1_pd(SHORTEST));
    __m128d one = _mm_set1_pd(1.0), sign = _mm_set1_pd(-0.0);
    __m128d safe = _mm_or_pd(_mm_and_pd(has_direction, len), _mm_andnot_pd(has_direction, one));
    __m128d inv = _mm_div_pd(one, safe);
    __m128d rel = _mm_mul_pd(
        _mm_add_pd(_mm_add_pd(_mm_mul_pd(dx, mx), _mm_mul_pd(dy, my)), _mm_mul_pd(dz, mz)), inv);
    __m128d force = _mm_add_pd(_mm_sub_pd(len, _mm_loadu_pd(sp->rest + k)),
                               _mm_mul_pd(load_two_floats(sp->gamma + k), rel));
    __m128d f = _mm_and_pd(has_direction, _mm_mul_pd(force, inv));
    __m128d ga = _mm_mul_pd(_mm_xor_pd(load_two_floats(sp->ci + k), sign), f);
    __m128d gb = _mm_mul_pd(_mm_xor_pd(load_two_floats(sp->cj + k), sign), f);
    store_pair(xa0, xa1, _mm_add_pd(ax, _mm_mul_pd(ga, dx)), _mm_add_pd(ay, _mm_mul_pd(ga, dy)),
               _mm_add_pd(az, _mm_mul_pd(ga, dz)));
    store_pair(xb0, xb1, _mm_sub_pd(bx, _mm_mul_pd(gb, dx)), _mm_sub_pd(by, _mm_mul_pd(gb, dy)),
               _mm_sub_pd(bz, _mm_mul_pd(gb, dz)));
}
#endif

#if defined(SK__HAVE_AVX2_PATH)
/* The lanes x + y and z + w of four points' vectors (x, y, z, w), in point order:
 * hadd gives (a.x + a.y, b.x + b.y, a.z + a.w, b.z + b.w). */
static inline SK__AVX2 __m256d sum_xyz(__m256d a, __m256d b, __m256d c, __m256d d)
{
    __m256d ab = _mm256_hadd_pd(a, b), cd = _mm256_hadd_pd(c, d);
    return _mm256_add_pd(_mm256_permute2f128_pd(ab, cd, 0x20),
                         _mm256_permute2f128_pd(ab, cd, 0x31));
}

/* The factors w_i dlambda / |d| (ga) and w_j dlambda / |d| (gb, both negated) of springs
 * k..k + 3 of one run on the packed points, each point one vector (x, y, z, 0) and its step
 * start the next: solve_one's operations, lane by lane. The sums of three products are
 * (x + y) + (z + 0), which is (x + y) + z exactly (z + 0 is z, or +0 for z = -0, which
 * leaves the force as it is: the damping term then is a zero added to len - rest). */
static inline SK__AVX2 void factors_four(const spring_arrays *sp, size_t k, const double *packed,
                                         double *ga_out, double *gb_out)
{
    __m256d dd[4], dm[4];
    const uint32_t *ends_i = sp->i + k, *ends_j = sp->j + k;
#pragma GCC unroll 4
    for (int l = 0; l < 4; l++) {
        const double *a = packed + 8 * (size_t)ends_i[l], *b = packed + 8 * (size_t)ends_j[l];
        __m256d d = _mm256_sub_pd(_mm256_load_pd(a), _mm256_load_pd(b));
        __m256d m = _mm256_sub_pd(d, _mm256_sub_pd(_mm256_load_pd(a + 4), _mm256_load_pd(b + 4)));
        dd[l] = _mm256_mul_pd(d, d);
        dm[l] = _mm256_mul_pd(d, m);
    }
    __m256d len = _mm256_sqrt_pd(sum_xyz(dd[0], dd[1], dd[2], dd[3]));
    __m256d has_direction = _mm256_cmp_pd(len, _mm256_set1_pd(SHORTEST), _CMP_GT_OQ);
    __m256d one = _mm256_set1_pd(1.0), sign = _mm256_set1_pd(-0.0);
    __m256d inv = _mm256_div_pd(one, _mm256_blendv_pd(one, len, has_direction));
    __m256d rel = _mm256_mul_pd(sum_xyz(dm[0], dm[1], dm[2], dm[3]), inv);
    __m256d force = _mm256_add_pd(_mm256_sub_pd(len, _mm256_loadu_pd(sp->rest + k)),
                                  _mm256_mul_pd(_mm256_cvtps_pd(_mm_loadu_ps(sp->gamma + k)), rel));
    __m256d f = _mm256_and_pd(has_direction, _mm256_mul_pd(force, inv));
    _mm256_storeu_pd(
        ga_out, _mm256_mul_pd(_mm256_xor_pd(_mm256_cvtps_pd(_mm_loadu_ps(sp->ci + k)), sign), f));
    _mm256_storeu_pd(
        gb_out, _mm256_mul_pd(_mm256_xor_pd(_mm256_cvtps_pd(_mm_loadu_ps(sp->cj + k)), sign), f));
}

/* The same for one spring (spring_factor on the records). */
static inline SK__AVX2 void factors_one(const spring_arrays *sp, size_t k, const double *packed,
                                        double *ga, double *gb)
{
    const double *a = packed + 8 * (size_t)sp->i[k], *b = packed + 8 * (size_t)sp->j[k];
    double d[3], f = spring_factor(sp, k, a, a + 4, b, b + 4, NULL, d);
    *ga = -sp->ci[k] * f;
    *gb = -sp->cj[k] * f;
}

#define CHUNK 64

/* A run of springs that share no point on the packed points, a chunk at a time: first
 * every spring's factors (reads only, so the processor overlaps the springs' square roots
 * and divisions), then the moves x_a += ga d, x_b -= gb d (d = x_a - x_b again: the ends
 * have not moved in between). */
static SK__AVX2 void solve_run_wide(const spring_arrays *sp, size_t first, size_t end,
                                    double *packed)
{
    double ga[CHUNK], gb[CHUNK];
    for (size_t k0 = first; k0 < end; k0 += CHUNK) {
        size_t n = end - k0 < CHUNK ? end - k0 : CHUNK, q = 0;
        for (; q + 3 < n; q += 4) factors_four(sp, k0 + q, packed, ga + q, gb + q);
        for (; q < n; q++) factors_one(sp, k0 + q, packed, ga + q, gb + q);
        const uint32_t *ends_i = sp->i + k0, *ends_j = sp->j + k0;
        for (q = 0; q < n; q++) {
            double *a = packed + 8 * (size_t)ends_i[q], *b = packed + 8 * (size_t)ends_j[q];
            __m256d va = _mm256_load_pd(a), vb = _mm256_load_pd(b), d = _mm256_sub_pd(va, vb);
            _mm256_store_pd(a, _mm256_add_pd(va, _mm256_mul_pd(_mm256_broadcast_sd(ga + q), d)));
            _mm256_store_pd(b, _mm256_sub_pd(vb, _mm256_mul_pd(_mm256_broadcast_sd(gb + q), d)));
        }
    }
}
#endif

/* Springs first..end - 1 in order on x; `mu` (alpha lambda per spring) when the step
 * iterates, NULL for a single iteration (lambda starts at 0 each step). */
static void solve_run(const sk__solver *s, size_t first, size_t end, double *x, const double *base,
                      float *mu)
{
    size_t k = first;
    if (mu || !s->paired) {
        for (; k < end; k++) solve_one(&s->sp, k, x, base, mu ? mu + k : NULL);
        return;
    }
#if defined(__SSE2__)
    for (; k + 1 < end; k += 2) solve_two(&s->sp, k, x, base);
#endif
    for (; k < end; k++) solve_one(&s->sp, k, x, base, NULL);
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
    double middle = (double)s->parity_before[slab] + 0.5 * (double)s->slab_count[slab];
    int owner = (int)(middle / (double)total * threads);
    return owner < threads ? owner : threads - 1;
}

/* One sweep of this thread's springs, parity by parity (a slab's owners are consecutive,
 * so a thread's slabs of one parity are 2 lo + parity .. 2 hi + parity - 2). */
static void sweep(sk__solver *s, double *x, const double *base, float *mu)
{
    int thread = sk_thread_index(), threads = sk_thread_team_size();
    for (int parity = 0; parity < 2; parity++) {
        int lo = s->half, hi = 0;
        for (int slab = parity; slab < s->slabs; slab += 2)
            if (slab_owner(s, slab, threads) == thread) {
                if (slab / 2 < lo) lo = slab / 2;
                hi = slab / 2 + 1;
            }
        for (int c = 0; c < s->colours && hi > lo; c++) {
            size_t row = ((size_t)parity * (size_t)s->colours + (size_t)c) * (size_t)s->half;
            size_t first = s->cell[row + (size_t)lo], end = s->cell[row + (size_t)hi];
#if defined(SK__HAVE_AVX2_PATH)
            if (s->wide) {
                solve_run_wide(&s->sp, first, end, s->packed);
                continue;
            }
#endif
            solve_run(s, first, end, x, base, mu);
        }
#pragma omp barrier
    }
}

/* The tethers of free point p (after the springs). */
static inline void tether(const sk__solver *s, size_t p, double *x, const double *base,
                          const double *target, const double *target_base, bool iterate)
{
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

static void step(sk__solver *s, double *x, const double *base, const double *target,
                 const double *target_base)
{
    bool iterate = s->iterations > 1;
    if (s->wide) {
        /* the points into their records, the springs, then back and the tethers */
#pragma omp for schedule(static)
        for (size_t p = 0; p < s->point_count; p++) {
            double *r = s->packed + 8 * p;
            r[0] = x[3 * p], r[1] = x[3 * p + 1], r[2] = x[3 * p + 2], r[3] = 0.0;
            r[4] = base[3 * p], r[5] = base[3 * p + 1], r[6] = base[3 * p + 2], r[7] = 0.0;
        }
        sweep(s, x, base, NULL);
#pragma omp for schedule(static)
        for (size_t p = 0; p < s->point_count; p++) {
            const double *r = s->packed + 8 * p;
            x[3 * p] = r[0], x[3 * p + 1] = r[1], x[3 * p + 2] = r[2];
            if (p < s->free_count) tether(s, p, x, base, target, target_base, false);
        }
        return;
    }
    if (iterate) {
#pragma omp for schedule(static)
        for (size_t k = 0; k < s->count; k++) s->mu[k] = 0.0f;
#pragma omp for schedule(static)
        for (size_t i = 0; i < 3 * s->free_count; i++) s->tether_mu[i] = 0.0;
    }
    for (int it = 0; it < s->iterations; it++) {
        sweep(s, x, base, iterate ? s->mu : NULL);
#pragma omp for schedule(static)
        for (size_t p = 0; p < s->free_count; p++)
            tether(s, p, x, base, target, target_base, iterate);
    }
}

const sk__solver_ops sk__solver_xpbd = {"xpbd", create, destroy, step};

void sk__solver_xpbd_use_vectors(sk__solver *s, bool on) { s->wide = on && s->packed; }
