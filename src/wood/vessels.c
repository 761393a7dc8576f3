/* Vessels (Kawai 2000 sec. 5): diffuse-porous (5.3) uniform over the end grain with
 * n = rho x area: one vessel uniformly placed in each cell of a square grid of cell area
 * 1 / rho (stratified, so vessels are spread like real ones rather than clumped, radius
 * ~ Normal); ring-porous (5.4) in rows after
 * every ring boundary, ring j holding round(P R(j)) vessels per row (R(j) = j d for round
 * rings) at theta_k = 2 pi k / N_j, jittered, placed in space through R(t, theta). A query
 * visits only the cells and (ring, angle) buckets a vessel of the largest radius could
 * reach, never a list of all vessels. */
#include "wood/vessels.h"

#include "wood/numeric.h"

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
    double z = v->normal_quantile[i] + (x - i) * (v->normal_quantile[i + 1] - v->normal_quantile[i]);
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
static inline double cell_cover(const sk__vessels *v, int64_t cx, int64_t cz, double x0,
                                double z0, double reach2, double fw)
{
    double x, z;
    uint64_t h;
    cell_vessel(v, cx, cz, &x, &z, &h);
    double d2 = (x - x0) * (x - x0) + (z - z0) * (z - z0);
    if (d2 >= reach2) return 0.0;
    return sk__vessel_cover(sqrt(d2), cell_radius(v, h), fw);
}

static double diffuse_coverage(const sk__vessels *v, double x0, double z0, double fw)
{
    const sk__diffuse_index *di = &v->diffuse;
    double reach = sk__vessel_reach(di->size.hi, fw), reach2 = reach * reach, best = 0.0;
    double ux = x0 * di->inv_cell, uz = z0 * di->inv_cell;
    int64_t hx = sk__floor_i64(ux), hz = sk__floor_i64(uz);
    if (reach <= 0.5 * di->cell) {
        /* A vessel of the home cell's neighbours can reach the point only from the side of
           the point's quadrant: the 2 x 2 block of cells around that corner is all. */
        int64_t nx = hx + (ux - (double)hx < 0.5 ? -1 : 1);
        int64_t nz = hz + (uz - (double)hz < 0.5 ? -1 : 1);
        double c[4] = {cell_cover(v, hx, hz, x0, z0, reach2, fw), cell_cover(v, nx, hz, x0, z0, reach2, fw),
                       cell_cover(v, hx, nz, x0, z0, reach2, fw), cell_cover(v, nx, nz, x0, z0, reach2, fw)};
        double a = c[0] > c[1] ? c[0] : c[1], b = c[2] > c[3] ? c[2] : c[3];
        return a > b ? a : b;
    }
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

int sk__ring_vessel_count(const sk__ring_index *ri, const sk__rings *rings, int j)
{
    if (!ri->on || j <= 0) return 0;
    return (int)(ri->density * sk__rings_mean(rings, j) + 0.5); /* round; both >= 0 */
}

/* The angle of vessel k (of n) in a row of ring j; `h` receives its hash. */
static inline double ring_vessel_angle(const sk__ring_index *ri, int n, int j, int row, int k,
                                       uint64_t *h)
{
    *h = sk__wood_hash(ri->seed, j, row, k);
    return 2.0 * SK_PI * ((double)k + ri->jitter * (unit_hi(*h) - 0.5)) / n;
}

/* The rest of a ring vessel: its distance past the ring boundary, centre and radius. */
static inline void ring_vessel_place(const sk__vessels *v, const sk__rings *rings, int j, int row,
                                     uint64_t h, double theta, sk__vessel *out)
{
    const sk__ring_index *ri = &v->ring;
    double offset = ri->pitch * (row + 0.5) + ri->jitter * (unit_lo(h) - 0.5) * ri->pitch * 0.5;
    double radial = sk__rings_R(rings, (double)j, theta) + offset, s, c;
    sk__sincos(theta, &s, &c);
    out->x = radial * c;
    out->z = radial * s;
    out->radius = draw_radius(v, &ri->size, sk_u64_to_unit_d(sk_mix64(h ^ 0x5851f42d4c957f2dULL)));
}

void sk__ring_vessel(const sk__vessels *v, const sk__rings *rings, int j, int row, int k,
                     sk__vessel *out)
{
    uint64_t h;
    int n = sk__ring_vessel_count(&v->ring, rings, j);
    double theta = ring_vessel_angle(&v->ring, n, j, row, k, &h);
    ring_vessel_place(v, rings, j, row, h, theta, out);
}

/* Coverage from ring j's rows for vessels within `window` radians of theta0. */
static double ring_coverage(const sk__vessels *v, const sk__rings *rings, int j, double x0,
                            double z0, double theta0, double window, double reach, double fw)
{
    const sk__ring_index *ri = &v->ring;
    int n = sk__ring_vessel_count(ri, rings, j);
    if (n == 0) return 0.0;
    double per = n / (2.0 * SK_PI), half = 0.5 * ri->jitter;
    int64_t first = -sk__floor_i64(-((theta0 - window) * per - half)); /* ceil */
    int64_t last = sk__floor_i64((theta0 + window) * per + half);
    if (last - first + 1 >= n) {
        first = 0;
        last = n - 1;
    }
    double best = 0.0;
    for (int row = 0; row < ri->rows; row++)
        for (int64_t kk = first; kk <= last; kk++) {
            int k = (int)(((kk % n) + n) % n);
            uint64_t h;
            double theta = ring_vessel_angle(ri, n, j, row, k, &h);
            /* a vessel that could reach p0 lies within `window` of its angle */
            double d = theta - theta0;
            d -= 2.0 * SK_PI * sk__floor_d(d * (0.5 / SK_PI) + 0.5);
            if (d > window || d < -window) continue;
            sk__vessel vs;
            ring_vessel_place(v, rings, j, row, h, theta, &vs);
            double d2 = (vs.x - x0) * (vs.x - x0) + (vs.z - z0) * (vs.z - z0);
            if (d2 >= reach * reach) continue;
            double c = sk__vessel_cover(sqrt(d2), vs.radius, fw);
            if (c > best) best = c;
        }
    return best;
}

/* Bounds on R(j, theta) for |theta - theta0| <= window: the Lipschitz bound around
 * R(j, theta0), never wider than the ring's own extent. */
static void ring_reach(const sk__rings *rings, int j, double theta0, double window, double *lo,
                       double *hi)
{
    double Rj = sk__rings_R(rings, (double)j, theta0);
    double slack = sk__rings_lipschitz(rings, j) * window, ymin, ymax;
    sk__rings_year_bounds(rings, j, &ymin, &ymax);
    *lo = Rj - slack > ymin ? Rj - slack : ymin;
    *hi = Rj + slack < ymax ? Rj + slack : ymax;
}

static double ring_porous_coverage(const sk__vessels *v, const sk__rings *rings, double x0,
                                   double z0, double r0, double theta0, double t, double fw)
{
    const sk__ring_index *ri = &v->ring;
    double reach = sk__vessel_reach(ri->size.hi, fw);
    /* every point within `reach` of p0 lies within asin(reach / r0) of its angle; for
       reach / r0 <= 1/2 that is below 1.05 reach / r0 */
    double q = reach / r0;
    double window = r0 > 2.0 * reach ? 1.05 * q + 1e-12 : SK_PI;
    double best = 0.0;
    int j0 = (int)t; /* t >= 0 */
    if (j0 < 1) j0 = 1;
    /* Downwards: R(j', theta) <= R(j, theta) for j' <= j, so once ring j's centres fall
       short of r0 - reach no lower ring can reach p0. */
    for (int j = j0; j >= 1; j--) {
        double lo, hi;
        ring_reach(rings, j, theta0, window, &lo, &hi);
        if (hi + ri->offset_max < r0 - reach) break;
        if (lo + ri->offset_min > r0 + reach) continue;
        double c = ring_coverage(v, rings, j, x0, z0, theta0, window, reach, fw);
        if (c > best) best = c;
        if (best >= 1.0) return 1.0;
    }
    /* Upwards: likewise centres of rings j' >= j lie beyond ring j's lower bound. */
    for (int j = j0 + 1;; j++) {
        double lo, hi;
        ring_reach(rings, j, theta0, window, &lo, &hi);
        if (lo + ri->offset_min > r0 + reach) break;
        double c = ring_coverage(v, rings, j, x0, z0, theta0, window, reach, fw);
        if (c > best) best = c;
        if (best >= 1.0) return 1.0;
    }
    return best;
}

double sk__vessels_coverage(const sk__vessels *v, const sk__rings *rings, double x0, double z0,
                            double r0, double theta0, double t, double fw)
{
    double c = 0.0;
    if (v->ring.on) c = ring_porous_coverage(v, rings, x0, z0, r0, theta0, t, fw);
    if (c < 1.0 && v->diffuse.on) {
        double d = diffuse_coverage(v, x0, z0, fw);
        if (d > c) c = d;
    }
    return c;
}
