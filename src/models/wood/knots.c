/* Knots as branches (after Larsson et al. 2022): whorls of branches along the stem, each
 * branch a strand from the pith whose own formation time at a point is its distance rho
 * from the branch's axis over the branch's ring width w a year. The stem's time is
 * t = T(r, theta); a live branch's wood is where rho / w < t, a cone from the pith, and
 * its growth layers continue the stem's: the two times are merged by a smooth minimum
 * (over a width of `collar` times the knot's age), so the rings curve into the knot. A
 * branch that died after D years keeps the radius a = w D: further out it is a dead knot
 * in a ring of bark, reaching stub_mm out of the stem as it was then. The stub's field is
 * (a + its distance from the stub) / w, so the stem's later rings wrap round the stub,
 * and round its broken end once it is overgrown; at the branch's death the two fields
 * agree, so the rings have no seam there.
 *
 * The grain flows round every knot. In the ring surface, with u the distance around the
 * tree from where the branch's axis crosses it and v the distance along the axis (scaled
 * by the cosine of the branch's rise, so the knot's cross-section is a circle of radius
 * a), fibres follow the streamlines of a potential flow past a cylinder, stream function
 * psi = u (1 - a^2 W(rho) / rho^2), with W a smooth window from 1 at the knot to 0 at
 * deflection_reach knot radii: a fibre through (u, v) comes from u_far = psi far below,
 * so the stem's texture is looked up there. The map is continuous and smooth outside the
 * knot, every knot's edge is a streamline, and beyond the reach nothing moves. The
 * fibre's tangent follows the same map (its slope G becomes (G - psi_y) / psi_u). */
#include "models/wood/knots.h"

#include <math.h>

#include "models/wood/attributes.h"
#include "models/wood/numeric.h"

/* A jittered rise kept off the vertical (the desc allows up to 80 degrees, jitter 10 more). */
static double clamp_rise(double rise)
{
    const double lo = -80.0 * SK_DEG_TO_RAD, hi = 85.0 * SK_DEG_TO_RAD;
    return rise < lo ? lo : (rise > hi ? hi : rise);
}

void sk__knots_init(sk__knots *k, const sk_wood_desc *desc)
{
    const sk_wood_knots_desc *kd = &desc->knots;
    *k = (sk__knots){0};
    if (kd->whorl_spacing_mm <= 0.0f) return;
    k->on = true;
    k->seed = sk_hash(desc->seed, 0x6b6e6f74ULL /* "knot" */, 0, 0);
    k->spacing = kd->whorl_spacing_mm;
    k->inv_spacing = 1.0 / k->spacing;
    k->phase = sk__hash_unit16(k->seed, 0);
    double j = kd->jitter;
    k->y_jitter = 0.25 * j * k->spacing;
    k->per_whorl = kd->per_whorl;
    k->rise = kd->rise;
    k->rise_jitter = j * 10.0 * SK_DEG_TO_RAD;
    k->tan_lo = tan(clamp_rise(k->rise - k->rise_jitter));
    k->tan_hi = tan(clamp_rise(k->rise + k->rise_jitter));
    k->growth = kd->growth * desc->rings.width_mm;
    k->size_jitter = 0.25 * j;
    k->dead = kd->dead_after_years;
    k->stub = kd->stub_mm;
    k->darkening = kd->darkening;
    k->bark = kd->bark_mm;
    k->collar = kd->collar;
    k->reach = kd->deflection_reach;
    k->azimuth_jitter = 0.2 * j;
    k->bark_color = sk__linear_from_srgb3(kd->bark_srgb);
}

/* One branch of one whorl. */
typedef struct branch {
    double y0, theta, cos_b, sin_b, tan_b, w, dead;
} branch;

static branch make_branch(const sk__knots *k, double y_whorl, double rotation, int64_t whorl, int i)
{
    uint64_t h = sk__wood_hash(k->seed, whorl, i + 1, 1);
    branch b;
    b.y0 = y_whorl;
    b.theta = rotation + 2.0 * SK_PI *
                             (i + k->azimuth_jitter * (2.0 * sk__hash_unit16(h, 0) - 1.0)) /
                             k->per_whorl;
    double rise = clamp_rise(k->rise + k->rise_jitter * (2.0 * sk__hash_unit16(h, 1) - 1.0));
    b.cos_b = cos(rise);
    b.sin_b = sin(rise);
    b.tan_b = b.sin_b / b.cos_b;
    b.w = k->growth * (1.0 + k->size_jitter * (2.0 * sk__hash_unit16(h, 2) - 1.0));
    b.dead = k->dead * (1.0 + k->size_jitter * (2.0 * sk__hash_unit16(h, 3) - 1.0));
    return b;
}

/* The smooth minimum of a and b over a width of k (polynomial, C1). */
static inline double smooth_min(double a, double b, double k)
{
    double d = a - b, h = k - (d < 0.0 ? -d : d);
    h = h > 0.0 ? h / k : 0.0;
    return (a < b ? a : b) - 0.25 * h * h * k;
}

/* The effect of branch b at the point, given (u, v) in its ring surface; false out of
 * its reach. */
static bool branch_effect(const sk__knots *k, const sk__rings *rings, const branch *b, double r,
                          double u, double v, double t_stem, double footprint, sk__knot_hit *hit)
{
    bool alive = b->dead <= 0.0 || t_stem <= b->dead;
    double rho2 = u * u + v * v, rho = sqrt(rho2);
    double a, beyond = 0.0; /* knot radius for the flow; how far past a dead stub's end */
    if (alive) {
        a = b->w * t_stem;
    } else {
        a = b->w * b->dead;
        /* a dead stub reaches stub_mm out of the stem as it was when the branch died */
        beyond = r - (sk__rings_mean(rings, b->dead) + k->stub);
    }
    double reach = k->reach * a;
    if (!(a > 0.0) || rho >= reach || beyond >= reach) return false;
    /* the grain flows round the knot (fading out past a dead stub's end) */
    double a_flow = beyond > 0.0 ? a * (1.0 - beyond / reach) : a;
    double reach_flow = k->reach * a_flow;
    if (rho <= a_flow) {
        hit->theta_shift = -u / r; /* the knot's edge, where the stem's fibres part */
        hit->psi_u = 1.0;
        hit->psi_y = 0.0;
    } else if (rho < reach_flow) {
        double x = (rho - a_flow) / (reach_flow - a_flow), s = 1.0 - x * x, W = s * s;
        double dW = -4.0 * x * s / (reach_flow - a_flow);
        double q = a_flow * a_flow * W / rho2;
        double dq = a_flow * a_flow * (dW / rho2 - 2.0 * W / (rho2 * rho)); /* dq / drho */
        hit->theta_shift = -u * q / r; /* psi - u, psi = u (1 - q) */
        hit->psi_u = (1.0 - q) - u * dq * u / rho;
        hit->psi_y = -u * dq * v / rho * b->cos_b; /* v = (y - centre) cos(rise) */
    } else {
        hit->theta_shift = 0.0;
        hit->psi_u = 1.0;
        hit->psi_y = 0.0;
    }
    /* the branch's time field (a dead stub's from its surface and its end), merged with
       the stem's */
    double t_branch;
    if (alive) {
        t_branch = rho / b->w;
    } else {
        double out = rho > a ? rho - a : 0.0, past = beyond > 0.0 ? beyond : 0.0;
        t_branch = (a + sqrt(out * out + past * past)) / b->w;
    }
    double age = alive ? t_stem : b->dead;
    hit->t = smooth_min(t_stem, t_branch, k->collar * age);
    /* the knot's own wood: a live branch where its time is below the stem's (a cone from
       the pith), a dead one inside its frozen radius, with a ring of bark */
    if (alive) {
        hit->knot = sk__edge_ramp((t_stem - t_branch) * b->w, footprint);
        hit->bark = 0.0;
    } else {
        hit->knot = sk__edge_ramp(a - rho, footprint) * sk__edge_ramp(-beyond, footprint);
        /* the bark closes over the year after the branch died */
        double closing = t_stem - b->dead;
        hit->bark = sk__edge_ramp(rho - (a - k->bark), footprint) * (closing < 1.0 ? closing : 1.0);
    }
    hit->t_knot = rho / b->w;
    hit->half_knot = 0.5 * footprint / b->w;
    hit->axis = sk_v3d(b->cos_b * cos(b->theta), b->sin_b, b->cos_b * sin(b->theta));
    return true;
}

bool sk__knots_hit(const sk__knots *k, const sk__rings *rings, double r, double theta, double y,
                   double t_stem, double footprint, sk__knot_hit *hit)
{
    if (!k->on || !(r > 1e-6) || !(t_stem > 0.0)) return false;
    /* the largest knot radius any branch can have here bounds the reach */
    double w_max = k->growth * (1.0 + k->size_jitter);
    double t_max = k->dead > 0.0 ? fmin(t_stem, k->dead * (1.0 + k->size_jitter)) : t_stem;
    double cos_min = 1.0 / sqrt(1.0 + fmax(k->tan_lo * k->tan_lo, k->tan_hi * k->tan_hi));
    double ext = k->reach * w_max * t_max / cos_min;
    /* whorls whose branches can cross this ring surface near y */
    double y_lo = y - r * k->tan_hi - ext - k->y_jitter,
           y_hi = y - r * k->tan_lo + ext + k->y_jitter;
    int64_t first = -sk__floor_i64(-(y_lo * k->inv_spacing - k->phase)),
            last = sk__floor_i64(y_hi * k->inv_spacing - k->phase);
    double best = INFINITY;
    bool found = false;
    for (int64_t whorl = first; whorl <= last; whorl++) {
        uint64_t h = sk__wood_hash(k->seed, whorl, 0, 0);
        double y_whorl =
            (whorl + k->phase) * k->spacing + k->y_jitter * (2.0 * sk__hash_unit16(h, 0) - 1.0);
        double dy = y - y_whorl;
        if (dy - r * k->tan_hi > ext || dy - r * k->tan_lo < -ext) continue;
        double rotation = 2.0 * SK_PI * sk__hash_unit16(h, 1);
        /* the branch nearest in azimuth and its neighbour on that side */
        double x = (theta - rotation) * k->per_whorl / (2.0 * SK_PI);
        int64_t nearest = sk__floor_i64(x + 0.5);
        int64_t other = x - nearest > 0.0 ? nearest + 1 : nearest - 1;
        int64_t candidates[2] = {nearest, other};
        for (int c = 0; c < (k->per_whorl > 1 ? 2 : 1); c++) {
            int i = (int)(((candidates[c] % k->per_whorl) + k->per_whorl) % k->per_whorl);
            branch b = make_branch(k, y_whorl, rotation, whorl, i);
            double d = theta - b.theta;
            d -= 2.0 * SK_PI * sk__floor_d(d / (2.0 * SK_PI) + 0.5);
            double u = r * d, v = (dy - r * b.tan_b) * b.cos_b;
            sk__knot_hit candidate;
            if (!branch_effect(k, rings, &b, r, u, v, t_stem, footprint, &candidate)) continue;
            /* the strongest knot wins where two reach */
            double a = candidate.t_knot * b.w; /* = rho */
            double closeness = a / (k->reach * b.w * t_max);
            if (closeness < best) {
                best = closeness;
                *hit = candidate;
                found = true;
            }
        }
    }
    return found;
}
