/* Broad rays as two staggered sets of radial bands: in set s, band b covers the formation
 * times [(b + s / 2) L, (b + 1 + s / 2) L) (L the rays' radial length in years) and is cut
 * round the tree into N_b columns of twice the rays' spacing at the band's mean radius;
 * each column holds a stack of rays along the fibre, each a lens (spindle) of the given
 * width round the tree and height along it, starting and ending at its own radius inside
 * the band. The two sets overlap by half a band, so rays end at staggered radii and the
 * number round a ring grows with the tree. Everything comes from hashes of (seed, set,
 * band, column, row): nothing is stored. */
#include "models/wood/rays.h"

#include <math.h>

#include "models/wood/attributes.h"
#include "models/wood/numeric.h"

void sk__rays_init(sk__rays *r, const sk_wood_desc *desc)
{
    const sk_wood_rays_desc *rd = &desc->rays;
    *r = (sk__rays){0};
    if (rd->spacing_mm <= 0.0f) return;
    r->on = true;
    r->seed = sk_hash(desc->seed, 0x72617973ULL /* "rays" */, 0, 0);
    r->spacing = 2.0 * rd->spacing_mm;
    r->width = rd->width_mm;
    r->height = rd->height_mm;
    r->jitter = rd->jitter;
    r->band_years = rd->length_mm / desc->rings.width_mm;
    r->row = 1.6 * rd->height_mm; /* rows of rays with gaps between them */
    r->color = sk__linear_from_srgb3(rd->color_srgb);
}

/* The coverage by the rays of column c of band b of set s. */
static double column_coverage(const sk__rays *r, int set, int64_t band, int64_t columns, int64_t c,
                              double t, double theta0, double r0, double y, double fw_across,
                              double fw_along, double fw_radial)
{
    int64_t cw = ((c % columns) + columns) % columns;
    uint64_t hc = sk__wood_hash(r->seed, set, band, cw);
    double offset =
        sk__hash_unit16(hc, 0) * r->row; /* the column's rows start at their own height */
    int64_t row = sk__floor_i64((y + offset) / r->row);
    uint64_t h = sk_mix64(hc ^ ((uint64_t)row * 0x9e3779b97f4a7c15ULL));
    double j = r->jitter;
    /* the ray's place: its angle in the column, height in the row, radial extent */
    double centre =
        2.0 * SK_PI * ((double)c + 0.5 + 0.6 * j * (sk__hash_unit16(h, 0) - 0.5)) / (double)columns;
    double yc = ((double)row + 0.5 + 0.3 * j * (sk__hash_unit16(h, 1) - 0.5)) * r->row - offset;
    double height = r->height * (1.0 + j * (sk__hash_unit16(h, 2) - 0.5));
    double width = r->width * (1.0 + j * (sk__hash_unit16(h, 3) - 0.5));
    double band_start = ((double)band + 0.5 * set) * r->band_years;
    uint64_t h2 = sk_mix64(h + 0x5851f42d4c957f2dULL);
    double t0 = band_start + 0.3 * j * sk__hash_unit16(h2, 0) * r->band_years;
    double t1 = band_start + (1.0 - 0.3 * j * sk__hash_unit16(h2, 1)) * r->band_years;
    /* the lens: half width w/2 sqrt(1 - (2 dy / h)^2) round the tree, its tips softened
       along the fibre */
    double dy = 2.0 * (y - yc) / height;
    double tips = sk__edge_ramp(0.5 * height * (1.0 - fabs(dy)), fw_along);
    if (tips <= 0.0) return 0.0;
    double half = 0.5 * width * sqrt(dy < 1.0 && dy > -1.0 ? 1.0 - dy * dy : 0.0);
    double d = theta0 - centre;
    d -= 2.0 * SK_PI * sk__floor_d(d / (2.0 * SK_PI) + 0.5);
    double across = fabs(d) * r0;
    /* the radial ends, in mm at the point's mean growth per year; the ray tapers to them
       over its last fifth (a rounded end, not a cut) */
    double per_year = r0 / t, ends = fmin(t - t0, t1 - t) * per_year;
    double e = ends / (0.2 * (t1 - t0) * per_year);
    e = e < 0.0 ? 0.0 : (e > 1.0 ? 1.0 : e);
    half *= sqrt(e * (2.0 - e));
    return tips * sk__edge_ramp(half - across, fw_across) * sk__edge_ramp(ends, fw_radial);
}

double sk__rays_coverage(const sk__rays *r, const sk__rings *rings, double t, double theta0,
                         double r0, double y, double fw_across, double fw_along, double fw_radial)
{
    if (!r->on || !(t > 0.0) || !(r0 > 0.0)) return 0.0;
    double best = 0.0;
    for (int set = 0; set < 2; set++) {
        int64_t band = sk__floor_i64(t / r->band_years - 0.5 * set);
        double mid = ((double)band + 0.5 + 0.5 * set) * r->band_years;
        int64_t columns =
            (int64_t)(2.0 * SK_PI * sk__rings_mean(rings, mid > 0.0 ? mid : 0.0) / r->spacing +
                      0.5);
        if (columns < 1) columns = 1;
        double x = theta0 * (double)columns / (2.0 * SK_PI);
        int64_t c = sk__floor_i64(x);
        int64_t other = x - (double)c > 0.5 ? c + 1 : c - 1; /* a ray may lean over the edge */
        double a = column_coverage(r, set, band, columns, c, t, theta0, r0, y, fw_across, fw_along,
                                   fw_radial);
        double b = columns > 1 ? column_coverage(r, set, band, columns, other, t, theta0, r0, y,
                                                 fw_across, fw_along, fw_radial)
                               : 0.0;
        best = fmax(best, fmax(a, b));
    }
    return best;
}
