/* Vessels (Kawai 2000 sec. 5): diffuse-porous (5.3) uniform over the end grain with
 * n = rho x area: one vessel uniformly placed in each cell of a square grid of cell area
 * 1 / rho (stratified, so vessels are spread like real ones rather than clumped, radius
 * ~ Normal); ring-porous (5.4) in rows after
 * every ring boundary, ring j holding round(P R(j)) vessels per row (R(j) = j d for round
 * rings) at theta_k = 2 pi k / N_j, jittered, placed in space through R(t, theta). A query
 * visits only the cells and (ring, angle) buckets a vessel of the largest radius could
 * reach, never a list of all vessels. */
#include "models/wood/vessels.h"

#include "models/wood/numeric.h"

#include <math.h>
#include <string.h>

static sk__vessel_size make_size(double mean, double sd)
{
    sk__vessel_size s;
    s.mean = mean;
    s.sd = sd;
    s.lo = fmax(mean - 3.0 * sd, 0.1 * mean);
    s.hi = mean + 3.0 * sd;
    return s;
}

static inline double unit_hi(uint64_t h) { return (double)(h >> 32) * 0x1.0p-32; }
static inline double unit_lo(uint64_t h) { return (double)(h & 0xffffffffu) * 0x1.0p-32; }

/* Standard normal quantile cut to [-3, 3] by Newton's method on the CDF (set-up only). */
static double normal_cdf(double z) { return 0.5 * erfc(-z / sqrt(2.0)); }
static double normal_quantile(double u)
{
    if (u <= normal_cdf(-3.0)) return -3.0;
    if (u >= normal_cdf(3.0)) return 3.0;
    double z = 0.0;
    for (int i = 0; i < 40; i++) {
        double step = (normal_cdf(z) - u) / (exp(-0.5 * z * z) / sqrt(2.0 * SK_PI));
        z -= step;
        z = sk_clampd(z, -3.0, 3.0);
        if (fabs(step) < 1e-13) break;
    }
    return z;
}

/* Radius ~ Normal(mean, sd) cut at 3 sd (and at least size->lo), by the tabulated
 * quantile of the uniform u. */
static inline double draw_radius(const sk__vessels *v, const sk__vessel_size *s, double u)
{
    if (s->sd == 0.0) return s->mean;
    double x = u * SK__NORMAL_TABLE;
    int i = (int)x;
    if (i >= SK__NORMAL_TABLE) i = SK__NORMAL_TABLE - 1;
    double z =
        v->normal_quantile[i] + (x - i) * (v->normal_quantile[i + 1] - v->normal_quantile[i]);
    double r = s->mean + s->sd * z;
    return r > s->lo ? r : s->lo;
}

void sk__vessels_init(sk__vessels *v, const sk_wood_desc *desc)
{
    memset(v, 0, sizeof *v);
    if (desc->vessels.diffuse.radius_sd_mm > 0.0f || desc->vessels.ring.radius_sd_mm > 0.0f)
        for (int k = 0; k <= SK__NORMAL_TABLE; k++)
            v->normal_quantile[k] = (float)normal_quantile((double)k / SK__NORMAL_TABLE);
    const sk_wood_diffuse_vessels *dd = &desc->vessels.diffuse;
    sk__diffuse_index *di = &v->diffuse;
    if (dd->density_per_mm2 > 0.0f) {
        di->on = true;
        di->seed = sk_hash(desc->seed, 0x76657373ULL /* "vess" */, 1, 0);
        di->size = make_size(dd->radius_mm, dd->radius_sd_mm);
        di->cell = 1.0 / sqrt(dd->density_per_mm2);
        di->inv_cell = 1.0 / di->cell;
    }
    const sk_wood_ring_vessels *rd = &desc->vessels.ring;
    sk__ring_index *ri = &v->ring;
    if (rd->linear_density > 0.0f) {
        ri->on = true;
        ri->seed = sk_hash(desc->seed, 0x76657373ULL, 2, 0);
        ri->size = make_size(rd->radius_mm, rd->radius_sd_mm);
        ri->density = rd->linear_density;
        ri->jitter = rd->jitter;
        ri->rows = rd->rows;
        ri->pitch = 2.2 * rd->radius_mm; /* a vessel diameter and a thin wall between rows */
        ri->offset_min = ri->pitch * 0.5 - ri->jitter * ri->pitch * 0.25;
        ri->offset_max = ri->pitch * (ri->rows - 0.5) + ri->jitter * ri->pitch * 0.25;
    }
}

/* ------------------------------------------------------------ diffuse-porous */

/* Centre and radius of the vessel of cell (cx, cz). */
static inline void cell_vessel(const sk__vessels *v, int64_t cx, int64_t cz, double *x, double *z,
                               uint64_t *h)
{
    const sk__diffuse_index *di = &v->diffuse;
    *h = sk__wood_hash(di->seed, cx, cz, 0);
    *x = ((double)cx + unit_hi(*h)) * di->cell;
    *z = ((double)cz + unit_lo(*h)) * di->cell;
}

static inline double cell_radius(const sk__vessels *v, uint64_t h)
{
    return draw_radius(v, &v->diffuse.size, sk_u64_to_unit_d(sk_mix64(h ^ 0x5851f42d4c957f2dULL)));
}

bool sk__diffuse_cell_vessel(const sk__vessels *v, int64_t cx, int64_t cz, sk__vessel *out)
{
    if (!v->diffuse.on) return false;
    uint64_t h;
    cell_vessel(v, cx, cz, &out->x, &out->z, &h);
    out->radius = cell_radius(v, h);
    return true;
}

/* Coverage contribution of the vessel of cell (cx, cz) at (x0, z0). */
static inline double cell_cover(const sk__vessels *v, int64_t cx, int64_t cz, double x0, double z0,
                                double reach2, double fw)
{
    double x, z;
    uint64_t h;
    cell_vessel(v, cx, cz, &x, &z, &h);
    double d2 = (x - x0) * (x - x0) + (z - z0) * (z - z0);
    if (d2 >= reach2) return 0.0;
    return sk__vessel_cover(sqrt(d2), cell_radius(v, h), fw);
}

/* Squared distance from (x0, z0) to the vessel of the cell with hash h whose indices as
 * doubles are (cxd, czd) (cell_vessel's arithmetic). */
static inline double cell_d2(const sk__diffuse_index *di, uint64_t h, double cxd, double czd,
                             double x0, double z0)
{
    double x = (cxd + unit_hi(h)) * di->cell, z = (czd + unit_lo(h)) * di->cell;
    return (x - x0) * (x - x0) + (z - z0) * (z - z0);
}

/* Coverage of the vessel of hash h at squared distance d2 (0 beyond reach2). */
static inline double cell_cover_d2(const sk__vessels *v, uint64_t h, double d2, double reach2,
                                   double fw)
{
    double c = sk__vessel_cover(sqrt(d2), cell_radius(v, h), fw);
    return d2 < reach2 ? c : 0.0;
}

/* cell_cover for the cell of hash key `key` (the sum that sk__wood_hash mixes) whose
 * indices as doubles are (cxd, czd); `best` is raised to the coverage. */
static inline double cell_cover_key(const sk__vessels *v, uint64_t key, double cxd, double czd,
                                    double x0, double z0, double reach2, double fw, double best)
{
    uint64_t h = sk_mix64(key);
    double d2 = cell_d2(&v->diffuse, h, cxd, czd, x0, z0);
    if (d2 >= reach2) return best;
    double c = sk__vessel_cover(sqrt(d2), cell_radius(v, h), fw);
    return c > best ? c : best;
}

/* Diffuse-porous coverage at (x0, z0) when a vessel can reach further than half a cell:
 * every cell within reach. (Nearer reaches take the 2 x 2 blocks of diffuse_block_batch.) */
static double diffuse_coverage(const sk__vessels *v, double x0, double z0, double fw)
{
    const sk__diffuse_index *di = &v->diffuse;
    double reach = sk__vessel_reach(di->size.hi, fw), reach2 = reach * reach, best = 0.0;
    int64_t cx0 = sk__floor_i64((x0 - reach) * di->inv_cell);
    int64_t cx1 = sk__floor_i64((x0 + reach) * di->inv_cell);
    int64_t cz0 = sk__floor_i64((z0 - reach) * di->inv_cell);
    int64_t cz1 = sk__floor_i64((z0 + reach) * di->inv_cell);
    for (int64_t cx = cx0; cx <= cx1; cx++)
        for (int64_t cz = cz0; cz <= cz1; cz++) {
            double c = cell_cover(v, cx, cz, x0, z0, reach2, fw);
            if (c > best) best = c;
        }
    return best;
}

/* ------------------------------------------------------------- ring-porous */

static inline int ring_vessel_count(const sk__ring_index *ri, const sk__rings *rings, int j)
{
    if (!ri->on || j <= 0) return 0;
    int i = j * rings->per_year;
    /* the mean radius at the whole year j: a knot of the table inside it */
    double mean = i < rings->nt - 1 ? (double)rings->mean[i] : sk__rings_mean(rings, j);
    return (int)(ri->density * mean + 0.5); /* round; both >= 0 */
}

int sk__ring_vessel_count(const sk__ring_index *ri, const sk__rings *rings, int j)
{
    return ring_vessel_count(ri, rings, j);
}

/* The angle of vessel k (of n) in a row of ring j; `h` receives its hash. */
static inline double ring_vessel_angle(const sk__ring_index *ri, int n, int j, int row, int k,
                                       uint64_t *h)
{
    *h = sk__wood_hash(ri->seed, j, row, k);
    return 2.0 * SK_PI * ((double)k + ri->jitter * (unit_hi(*h) - 0.5)) / n;
}

/* The distance of a ring vessel from the pith: the ring boundary at its angle plus its
 * distance past the boundary. */
static inline double ring_vessel_radial(const sk__ring_index *ri, const sk__rings *rings, int j,
                                        int row, uint64_t h, double theta)
{
    double offset = ri->pitch * (row + 0.5) + ri->jitter * (unit_lo(h) - 0.5) * ri->pitch * 0.5;
    sk__rings_at at = sk__rings_at_angle(rings, theta);
    return sk__rings_R_year_at(rings, &at, j) + offset;
}

static inline double ring_vessel_radius(const sk__vessels *v, uint64_t h)
{
    return draw_radius(v, &v->ring.size, sk_u64_to_unit_d(sk_mix64(h ^ 0x5851f42d4c957f2dULL)));
}

void sk__ring_vessel(const sk__vessels *v, const sk__rings *rings, int j, int row, int k,
                     sk__vessel *out)
{
    uint64_t h;
    int n = ring_vessel_count(&v->ring, rings, j);
    double theta = ring_vessel_angle(&v->ring, n, j, row, k, &h), s, c;
    double radial = ring_vessel_radial(&v->ring, rings, j, row, h, theta);
    sk__sincos(theta, &s, &c);
    out->x = radial * c;
    out->z = radial * s;
    out->radius = ring_vessel_radius(v, h);
}

/* Bounds on R(j, theta) for |theta - theta0| <= window: the Lipschitz bound around
 * R(j, theta0) (`at0` the table columns of theta0), never wider than the ring's own
 * extent. */
static inline void ring_reach(const sk__rings *rings, const sk__rings_at *at0, int j, double window,
                              double *lo, double *hi)
{
    double Rj = sk__rings_R_year_at(rings, at0, j);
    double slack = sk__rings_lipschitz(rings, j) * window, ymin, ymax;
    sk__rings_year_bounds(rings, j, &ymin, &ymax);
    *lo = Rj - slack > ymin ? Rj - slack : ymin;
    *hi = Rj + slack < ymax ? Rj + slack : ymax;
}

/* Ring-porous candidates of a batch of points, tested in stages over all of them (so that
 * no stage waits on an unpredictable branch): a candidate is vessel k of row `row` of
 * ring j for point `point`. */
#define RING_CANDIDATES (8 * SK__WOOD_BATCH)

typedef struct ring_candidates {
    int count; /* waiting */
    int point[RING_CANDIDATES], j[RING_CANDIDATES], row[RING_CANDIDATES];
    int n[RING_CANDIDATES], k[RING_CANDIDATES];
} ring_candidates;

typedef struct ring_stream {
    const sk__vessels *v;
    const sk__rings *rings;
    const double *x0, *z0, *r0, *theta0;
    const double *window; /* per point: the angles around theta0 a vessel can reach from */
    double reach, reach2, fw;
    double *cover; /* per point: the largest coverage so far */
    ring_candidates *cand;
} ring_stream;

/* Tests the waiting candidates: first their angle against the window, then their distance
 * from the pith against r0 +- reach, then their distance from p0 (each test is exact:
 * a candidate dropped by one is beyond `reach` by the final one); the survivors' coverage
 * raises their point's. */
static void ring_stream_flush(ring_stream *s)
{
    const sk__ring_index *ri = &s->v->ring;
    ring_candidates *cd = s->cand;
    int idx[RING_CANDIDATES], m = 0;
    uint64_t h[RING_CANDIDATES];
    double theta[RING_CANDIDATES], radial[RING_CANDIDATES], d2[RING_CANDIDATES];
    for (int c = 0; c < cd->count; c++) {
        theta[c] = ring_vessel_angle(ri, cd->n[c], cd->j[c], cd->row[c], cd->k[c], &h[c]);
        double d = theta[c] - s->theta0[cd->point[c]], w = s->window[cd->point[c]];
        d -= 2.0 * SK_PI * sk__floor_d(d * (0.5 / SK_PI) + 0.5);
        idx[m] = c;
        m += !(d > w || d < -w);
    }
    int m2 = 0;
    for (int a = 0; a < m; a++) {
        /* a centre whose distance from the pith differs from r0 by `reach` or more is at
           least that far from p0; the margin covers the rounding of the centres */
        int c = idx[a];
        double r0 = s->r0[cd->point[c]];
        radial[c] = ring_vessel_radial(ri, s->rings, cd->j[c], cd->row[c], h[c], theta[c]);
        idx[m2] = c;
        m2 += !(fabs(radial[c] - r0) >= s->reach * (1.0 + 1e-9) + 1e-12 * r0);
    }
    int m3 = 0;
    for (int a = 0; a < m2; a++) {
        int c = idx[a], i = cd->point[c];
        double sn, cs;
        sk__sincos(theta[c], &sn, &cs);
        double x = radial[c] * cs, z = radial[c] * sn;
        d2[c] = (x - s->x0[i]) * (x - s->x0[i]) + (z - s->z0[i]) * (z - s->z0[i]);
        idx[m3] = c;
        m3 += !(d2[c] >= s->reach2);
    }
    for (int a = 0; a < m3; a++) {
        int c = idx[a], i = cd->point[c];
        double cover = sk__vessel_cover(sqrt(d2[c]), ring_vessel_radius(s->v, h[c]), s->fw);
        if (cover > s->cover[i]) s->cover[i] = cover;
    }
    cd->count = 0;
}

/* The candidates of ring j for point i: every vessel whose jittered angle can fall in the
 * window, in the rows not radially out of reach (R(j, theta) in [lo, hi] there). */
static void ring_stream_add(ring_stream *s, int i, int j, double lo, double hi)
{
    const sk__ring_index *ri = &s->v->ring;
    int n = ring_vessel_count(ri, s->rings, j);
    if (n == 0) return;
    double per = n / (2.0 * SK_PI), half = 0.5 * ri->jitter;
    double theta0 = s->theta0[i], window = s->window[i], r0 = s->r0[i];
    int64_t first = -sk__floor_i64(-((theta0 - window) * per - half)); /* ceil */
    int64_t last = sk__floor_i64((theta0 + window) * per + half);
    if (last - first + 1 >= n) {
        first = 0;
        last = n - 1;
    }
    double radial_reach = s->reach * (1.0 + 1e-9) + 1e-12 * r0;
    double jitter_offset = ri->jitter * ri->pitch * 0.25;
    for (int row = 0; row < ri->rows; row++) {
        /* the row's centres lie R(j, theta) + [offset - jitter_offset, offset +
           jitter_offset] from the pith: a row out of radial reach has no candidate */
        double offset = ri->pitch * (row + 0.5);
        if (lo + offset - jitter_offset >= r0 + radial_reach ||
            hi + offset + jitter_offset <= r0 - radial_reach)
            continue;
        for (int64_t kk = first; kk <= last; kk++) {
            ring_candidates *cd = s->cand;
            if (cd->count == RING_CANDIDATES) ring_stream_flush(s);
            int64_t kw = kk < 0 ? kk + n : (kk >= n ? kk - n : kk); /* kk in [-n, 2n) */
            int c = cd->count++;
            cd->point[c] = i;
            cd->j[c] = j;
            cd->row[c] = row;
            cd->n[c] = n;
            cd->k[c] = (int)(kw >= 0 && kw < n ? kw : ((kk % n) + n) % n);
        }
    }
}

/* The ring-porous coverage of a batch of end-grain points into cover[]. For each point,
 * the rings whose vessels can reach it: from ring floor(t) down while the ring's centres
 * can still reach (R(j', theta) <= R(j, theta) for j' <= j), and up while they can. */
static void ring_porous_batch(const sk__vessels *v, const sk__rings *rings, int count,
                              const sk__rings_at *at0, const double *x0, const double *z0,
                              const double *r0, const double *theta0, const double *t, double fw,
                              double *cover)
{
    const sk__ring_index *ri = &v->ring;
    double window[SK__WOOD_BATCH], reach = sk__vessel_reach(ri->size.hi, fw);
    ring_candidates cand;
    cand.count = 0;
    ring_stream s = {.v = v,
                     .rings = rings,
                     .x0 = x0,
                     .z0 = z0,
                     .r0 = r0,
                     .theta0 = theta0,
                     .window = window,
                     .reach = reach,
                     .reach2 = reach * reach,
                     .fw = fw,
                     .cover = cover,
                     .cand = &cand};
    for (int i = 0; i < count; i++) {
        cover[i] = 0.0;
        /* every point within `reach` of p0 lies within asin(reach / r0) of its angle; for
           reach / r0 <= 1/2 that is below 1.05 reach / r0 */
        double q = reach / r0[i];
        window[i] = r0[i] > 2.0 * reach ? 1.05 * q + 1e-12 : SK_PI;
        int j0 = (int)t[i]; /* t >= 0 */
        if (j0 < 1) j0 = 1;
        /* Most points are far from both ring j0's vessels and ring j0 + 1's: the walks
           below would stop at once, as the same bounds without the clamp to the rings'
           extent tell (ring_reach's hi <= R + slack and lo >= R - slack). */
        if (sk__rings_R_year_at(rings, &at0[i], j0) + sk__rings_lipschitz(rings, j0) * window[i] +
                    ri->offset_max <
                r0[i] - reach &&
            sk__rings_R_year_at(rings, &at0[i], j0 + 1) -
                    sk__rings_lipschitz(rings, j0 + 1) * window[i] + ri->offset_min >
                r0[i] + reach)
            continue;
        for (int j = j0; j >= 1; j--) {
            double lo, hi;
            ring_reach(rings, &at0[i], j, window[i], &lo, &hi);
            if (hi + ri->offset_max < r0[i] - reach) break;
            if (lo + ri->offset_min > r0[i] + reach) continue;
            ring_stream_add(&s, i, j, lo, hi);
        }
        for (int j = j0 + 1;; j++) {
            double lo, hi;
            ring_reach(rings, &at0[i], j, window[i], &lo, &hi);
            if (lo + ri->offset_min > r0[i] + reach) break;
            ring_stream_add(&s, i, j, lo, hi);
        }
    }
    ring_stream_flush(&s);
}

/* The diffuse-porous coverage of a batch of end-grain points when a vessel reaches no
 * further than half a cell: a vessel of the home cell's neighbours can then reach a point
 * only from the side of the point's quadrant, so the 2 x 2 block of cells around that
 * corner is all. Stage by stage: the cells; then, with neighbours mostly within reach,
 * all four hashes, the distances of their vessels and the nearest vessel's coverage
 * (unless, rarely, more than one is in reach); or else the home cell and the neighbours
 * nearer than `reach` (with a margin for the rounding of the centres, which then fail the
 * distance test anyway). */
static void diffuse_block_batch(const sk__vessels *v, int count, const double *x0, const double *z0,
                                double fw, double *cover)
{
    const sk__diffuse_index *di = &v->diffuse;
    double reach = sk__vessel_reach(di->size.hi, fw), reach2 = reach * reach;
    double cell = di->cell, inv_cell = di->inv_cell;
    double cx[2][SK__WOOD_BATCH], cz[2][SK__WOOD_BATCH]; /* home and neighbour indices */
    double ex[SK__WOOD_BATCH], ez[SK__WOOD_BATCH];       /* distances to the neighbours */
    double uh[4][SK__WOOD_BATCH], ul[4][SK__WOOD_BATCH], d2[4][SK__WOOD_BATCH];
    uint64_t h[4][SK__WOOD_BATCH];
    uint32_t hi[4][SK__WOOD_BATCH], lo[4][SK__WOOD_BATCH];
#pragma omp simd
    for (int i = 0; i < count; i++) {
        double ux = x0[i] * inv_cell, uz = z0[i] * inv_cell;
        double hx = sk__floor_vec(ux), hz = sk__floor_vec(uz), fx = ux - hx, fz = uz - hz;
        double gx = 1.0 - fx, gz = 1.0 - fz;
        cx[0][i] = hx;
        cz[0][i] = hz;
        cx[1][i] = fx >= 0.5 ? hx + 1.0 : hx - 1.0;
        cz[1][i] = fz >= 0.5 ? hz + 1.0 : hz - 1.0;
        ex[i] = (fx < gx ? fx : gx) * cell - 1e-9 * cell;
        ez[i] = (fz < gz ? fz : gz) * cell - 1e-9 * cell;
    }
    if (reach <= 0.125 * cell) {
        /* neighbours rarely within reach: the home cell, and the others when near */
        for (int i = 0; i < count; i++) {
            uint64_t kh = di->seed + (uint64_t)(int64_t)cx[0][i] * SK__WOOD_HASH_A;
            uint64_t lh = (uint64_t)(int64_t)cz[0][i] * SK__WOOD_HASH_B;
            double best =
                cell_cover_key(v, kh + lh, cx[0][i], cz[0][i], x0[i], z0[i], reach2, fw, 0.0);
            if (ex[i] < reach || ez[i] < reach) {
                uint64_t kn = di->seed + (uint64_t)(int64_t)cx[1][i] * SK__WOOD_HASH_A;
                uint64_t ln = (uint64_t)(int64_t)cz[1][i] * SK__WOOD_HASH_B;
                if (ex[i] < reach)
                    best = cell_cover_key(v, kn + lh, cx[1][i], cz[0][i], x0[i], z0[i], reach2, fw,
                                          best);
                if (ez[i] < reach) {
                    best = cell_cover_key(v, kh + ln, cx[0][i], cz[1][i], x0[i], z0[i], reach2, fw,
                                          best);
                    if (ex[i] < reach && ex[i] * ex[i] + ez[i] * ez[i] < reach2)
                        best = cell_cover_key(v, kn + ln, cx[1][i], cz[1][i], x0[i], z0[i], reach2,
                                              fw, best);
                }
            }
            cover[i] = best;
        }
        return;
    }
    for (int i = 0; i < count; i++) {
        /* the hash keys of the block's columns and rows (sk__wood_hash's sum); the cells
           in the order home, x neighbour, z neighbour, diagonal */
        uint64_t kh = di->seed + (uint64_t)(int64_t)cx[0][i] * SK__WOOD_HASH_A;
        uint64_t kn = di->seed + (uint64_t)(int64_t)cx[1][i] * SK__WOOD_HASH_A;
        uint64_t lh = (uint64_t)(int64_t)cz[0][i] * SK__WOOD_HASH_B;
        uint64_t ln = (uint64_t)(int64_t)cz[1][i] * SK__WOOD_HASH_B;
        h[0][i] = sk_mix64(kh + lh);
        h[1][i] = sk_mix64(kn + lh);
        h[2][i] = sk_mix64(kh + ln);
        h[3][i] = sk_mix64(kn + ln);
        for (int c = 0; c < 4; c++) {
            hi[c][i] = (uint32_t)(h[c][i] >> 32);
            lo[c][i] = (uint32_t)h[c][i];
        }
    }
    /* unit_hi and unit_lo of the hashes */
    for (int c = 0; c < 4; c++) {
#pragma omp simd
        for (int i = 0; i < count; i++) {
            uh[c][i] = (double)hi[c][i] * 0x1.0p-32;
            ul[c][i] = (double)lo[c][i] * 0x1.0p-32;
        }
    }
    /* the distances (cell_d2), how many are in reach, and the nearest */
    double in[SK__WOOD_BATCH], nearest[SK__WOOD_BATCH];
#pragma omp simd
    for (int i = 0; i < count; i++) {
        double xh = cx[0][i], xn = cx[1][i], zh = cz[0][i], zn = cz[1][i];
        double x, z;
        x = (xh + uh[0][i]) * cell, z = (zh + ul[0][i]) * cell;
        double e0 = d2[0][i] = (x - x0[i]) * (x - x0[i]) + (z - z0[i]) * (z - z0[i]);
        x = (xn + uh[1][i]) * cell, z = (zh + ul[1][i]) * cell;
        double e1 = d2[1][i] = (x - x0[i]) * (x - x0[i]) + (z - z0[i]) * (z - z0[i]);
        x = (xh + uh[2][i]) * cell, z = (zn + ul[2][i]) * cell;
        double e2 = d2[2][i] = (x - x0[i]) * (x - x0[i]) + (z - z0[i]) * (z - z0[i]);
        x = (xn + uh[3][i]) * cell, z = (zn + ul[3][i]) * cell;
        double e3 = d2[3][i] = (x - x0[i]) * (x - x0[i]) + (z - z0[i]) * (z - z0[i]);
        in[i] = (e0 < reach2 ? 1.0 : 0.0) + (e1 < reach2 ? 1.0 : 0.0) + (e2 < reach2 ? 1.0 : 0.0) +
                (e3 < reach2 ? 1.0 : 0.0);
        double dm = e0, km = 0.0;
        km = e1 < dm ? 1.0 : km;
        dm = e1 < dm ? e1 : dm;
        km = e2 < dm ? 2.0 : km;
        dm = e2 < dm ? e2 : dm;
        km = e3 < dm ? 3.0 : km;
        nearest[i] = km;
    }
    for (int i = 0; i < count; i++) {
        double best = 0.0;
        if (in[i] > 1.0) {
            for (int c = 0; c < 4; c++)
                if (d2[c][i] < reach2) {
                    double cc = cell_cover_d2(v, h[c][i], d2[c][i], reach2, fw);
                    if (cc > best) best = cc;
                }
        } else {
            /* at most one vessel in reach: the nearest one's coverage (0 beyond reach) */
            int c = (int)nearest[i];
            best = cell_cover_d2(v, h[c][i], d2[c][i], reach2, fw);
        }
        cover[i] = best;
    }
}

void sk__vessels_coverage_batch(const sk__vessels *v, const sk__rings *rings, int count,
                                const sk__rings_at *at0, const double *x0, const double *z0,
                                const double *r0, const double *theta0, const double *t, double fw,
                                double *cover)
{
    if (v->ring.on) {
        ring_porous_batch(v, rings, count, at0, x0, z0, r0, theta0, t, fw, cover);
    } else {
        for (int i = 0; i < count; i++) cover[i] = 0.0;
    }
    if (!v->diffuse.on) return;
    const sk__diffuse_index *di = &v->diffuse;
    double reach = sk__vessel_reach(di->size.hi, fw), d[SK__WOOD_BATCH];
    if (reach <= 0.5 * di->cell) {
        diffuse_block_batch(v, count, x0, z0, fw, d);
    } else {
        for (int i = 0; i < count; i++) d[i] = diffuse_coverage(v, x0[i], z0[i], fw);
    }
    /* the larger of the two (both in [0, 1]) */
    for (int i = 0; i < count; i++) cover[i] = d[i] > cover[i] ? d[i] : cover[i];
}

double sk__vessels_coverage_at(const sk__vessels *v, const sk__rings *rings,
                               const sk__rings_at *at0, double x0, double z0, double r0,
                               double theta0, double t, double fw)
{
    double c;
    sk__vessels_coverage_batch(v, rings, 1, at0, &x0, &z0, &r0, &theta0, &t, fw, &c);
    return c;
}

double sk__vessels_coverage(const sk__vessels *v, const sk__rings *rings, double x0, double z0,
                            double r0, double theta0, double t, double fw)
{
    sk__rings_at at0 = sk__rings_at_angle(rings, theta0);
    return sk__vessels_coverage_at(v, rings, &at0, x0, z0, r0, theta0, t, fw);
}
