/* Evaluation of the wood solid texture at points (Kawai 2000 sec. 6.2, the render steps):
 * into the tree frame, t = T(r, theta) (sec. 4.4), the grain's phase phi = Phi(t, y) /
 * R(t, theta) (eq. 3), back to the end grain at theta0 = theta - phi, where the attribute
 * array C'(t, theta0) (sec. 6.3) and the vessels (sec. 5) are looked up; the fibre
 * direction there gives the dive angle of sec. 7.
 *
 * Points go through in batches, stage by stage over arrays: the arithmetic stages are
 * branch-free loops the compiler vectorizes (#pragma omp simd), the table lookups and
 * hashes are plain loops between them. A single point runs the same loops, so it gets the
 * same arithmetic as a point in a batch. */
#include <math.h>
#include <string.h>

#include "models/wood/fibre.h"
#include "models/wood/numeric.h"
#include "models/wood/wood_internal.h"

sk_vec3f sk__wood_surface_up(const sk_wood *w, sk_vec3f n)
{
    sk_vec3f up = sk_v3f_sub(w->axis, sk_v3f_scale(n, sk_v3f_dot(w->axis, n)));
    float len = sk_v3f_length(up);
    if (len > 1e-6f) return sk_v3f_scale(up, 1.0f / len);
    sk_vec3f b;
    sk_v3f_basis(n, &up, &b);
    return up;
}

static inline bool same_bits(double a, double b)
{
    uint64_t ua, ub;
    memcpy(&ua, &a, sizeof ua);
    memcpy(&ub, &b, sizeof ub);
    return ua == ub;
}

#define B SK__WOOD_BATCH

/* The batch's fibre i turned towards the unit direction d by the weight m (a tissue whose
 * cells run along d covering that share of the point), renormalised. */
static void blend_fibre(sk__wood_batch *out, int i, double m, sk_vec3d d)
{
    sk_vec3d f =
        sk_v3d((1.0 - m) * out->fibre[0][i] + m * d.x, (1.0 - m) * out->fibre[1][i] + m * d.y,
               (1.0 - m) * out->fibre[2][i] + m * d.z);
    double len = sqrt(f.x * f.x + f.y * f.y + f.z * f.z);
    if (len > 1e-9) {
        out->fibre[0][i] = (float)(f.x / len);
        out->fibre[1][i] = (float)(f.y / len);
        out->fibre[2][i] = (float)(f.z / len);
    }
}

void sk__wood_section_eval(const sk_wood *w, int count, const float *x, const float *z,
                           sk_vec3f normal, float footprint_mm, const sk__wood_section *out)
{
    const sk__rings *rg = &w->rings;
    double col[B], col_f[B];
    double *r = out->r, *cos_t = out->cos_t, *sin_t = out->sin_t, *theta = out->theta;
    double *t = out->t, *width = out->width, *dR = out->dR, *half = out->half, *late = out->late;
    double theta_scale = rg->theta_scale;
#pragma omp simd
    for (int i = 0; i < count; i++) {
        double px = x[i], pz = z[i];
        r[i] = sqrt(px * px + pz * pz);
        cos_t[i] = r[i] > 0.0 ? px / r[i] : 1.0;
        sin_t[i] = r[i] > 0.0 ? pz / r[i] : 0.0;
        theta[i] = sk__atan2(pz, px);
        col[i] = sk__rings_column_split(theta_scale, theta[i], &col_f[i]);
    }
    /* t = T(r, theta) (sec. 4.4) */
    for (int i = 0; i < count; i++) {
        sk__rings_at at = sk__rings_at_column(rg, sk__rings_column_wrap(rg, col[i]), col_f[i]);
        t[i] = sk__rings_T_at(rg, &at, r[i], &width[i], &dR[i]);
    }
    /* the ring profile of C'(t, theta0) (sec. 6.3), box-filtered over the footprint's span
       of t along the surface (the radial direction's part in the surface over the ring
       width); it depends on t alone */
    sk_vec3f nt = sk__wood_frame_dir_to_tree(&w->frame, sk_v3f_normalize(normal));
    double half_footprint = footprint_mm > 0.0f ? 0.5 * footprint_mm : 0.0;
    double ntx = nt.x, ntz = nt.z;
#pragma omp simd
    for (int i = 0; i < count; i++) {
        double er_n = cos_t[i] * ntx + sin_t[i] * ntz;
        double tangential = 1.0 - er_n * er_n;
        half[i] = half_footprint * sqrt(tangential > 0.0 ? tangential : 0.0) / width[i];
    }
    for (int i = 0; i < count; i++) late[i] = sk__attributes_latewood(&w->attr, t[i], half[i]);
}

/* The arrays that the stages of sk__wood_eval_section_batch hand on to one another. */
typedef struct stages {
    /* the points as the later stages see them: the section's, or a knot's (knots_deflect) */
    const double *r, *cos_t, *sin_t, *theta, *t, *dR, *late;
    int hit_of[B], hits; /* each point's knot hit, or -1; the number of hits */
    sk__knot_hit hit[B];
    double t_k[B], theta_k[B], cos_k[B], sin_k[B], late_k[B]; /* the stem's values in knots */
    double P[B], G[B], phi[B];
    double dir_x[B], dir_z[B], theta0[B], col0[B], col0_f[B], r0[B];
    sk__rings_at at0[B];
    double cell[B], vessel[B], ray[B];
} stages;

/* What is looked up at the end grain, the same for every point of the tree (passed by
   value, so that the per-point loops see plain values, not loads). need_theta0 is an int:
   GCC vectorizes the select on it in end_grain_direction, not a select on a bool loaded
   from memory. */
typedef struct looks {
    bool round, vessels, turn, shifted, rays;
    int need_theta0;
} looks;

/* knots: near one, the stem is looked up where its deflected fibre comes from and its
   rings merge with a live branch's (knots.c) */
static inline void knots_deflect(const sk_wood *w, int count, const sk__wood_section *sec,
                                 const double *y, float footprint_mm, stages *s)
{
    const sk__rings *rg = &w->rings;
    const sk__attributes *attr = &w->attr;
    const double *r = sec->r, *cos_t = sec->cos_t, *sin_t = sec->sin_t, *theta = sec->theta;
    const double *t = sec->t, *late = sec->late;
    int *hit_of = s->hit_of, hits = 0;
    sk__knot_hit *hit = s->hit;
    double *t_k = s->t_k, *theta_k = s->theta_k, *cos_k = s->cos_k, *sin_k = s->sin_k;
    double *late_k = s->late_k;
    s->r = sec->r, s->cos_t = sec->cos_t, s->sin_t = sec->sin_t, s->theta = sec->theta;
    s->t = sec->t, s->dR = sec->dR, s->late = sec->late;
    s->hits = 0;
    if (w->knots.on) {
        for (int i = 0; i < count; i++) {
            hit_of[i] = -1;
            t_k[i] = t[i];
            theta_k[i] = theta[i];
            cos_k[i] = cos_t[i];
            sin_k[i] = sin_t[i];
            late_k[i] = late[i];
            sk__knot_hit *h = &hit[hits];
            if (!sk__knots_hit(&w->knots, rg, r[i], theta[i], y[i], t[i], footprint_mm, h))
                continue;
            hit_of[i] = hits++;
            double sn, c;
            sk__sincos(h->theta_shift, &sn, &c);
            theta_k[i] = theta[i] + h->theta_shift;
            cos_k[i] = cos_t[i] * c - sin_t[i] * sn;
            sin_k[i] = sin_t[i] * c + cos_t[i] * sn;
            t_k[i] = h->t;
            late_k[i] = sk__attributes_latewood(attr, h->t, sec->half[i]);
        }
        s->hits = hits;
        if (hits > 0) {
            s->t = t_k;
            s->theta = theta_k;
            s->cos_t = cos_k;
            s->sin_t = sin_k;
            s->late = late_k;
        }
    }
}

/* What the tree looks up at the end grain (see looks). */
static inline looks looks_choose(const sk_wood *w)
{
    /* Round rings (no fluctuation) do not depend on theta: their one column makes theta
       irrelevant to T and R, and the end-grain point is the point turned back by phi. */
    bool round = w->rings.ntheta == 1;
    bool need_theta0 = !round || w->vessels.ring.on || w->attr.shift > 0.0 || w->rays.on;
    /* the end-grain direction (theta0 and its unit vector) is needed where something is
       looked up there: the vessels, the cells of the brightness shift, rays, or
       fluctuating rings */
    bool vessels = w->vessels.ring.on || w->vessels.diffuse.on;
    looks lk = {.round = round, .need_theta0 = need_theta0, .vessels = vessels};
    lk.turn = round && (need_theta0 || vessels); /* the point turned back by phi */
    lk.shifted = w->attr.shift > 0.0;
    lk.rays = w->rays.on;
    return lk;
}

/* eq. (3): Phi(t, y) and G'(t, y); the terms that depend on y alone are found once per
   run of equal y (a planar cut along the rings has one y per row) */
static inline void grain_phase(const sk_wood *w, int count, const double *y, stages *s)
{
    const double *t = s->t;
    double *P = s->P, *G = s->G;
    sk__phase_y py = {0};
    for (int i = 0; i < count; i++) {
        if (i == 0 || !same_bits(y[i], y[i - 1])) py = sk__phase_at_y(&w->grain, y[i]);
        P[i] = sk__phase_eval_y(&w->grain, &py, t[i], y[i], &G[i]);
    }
}

/* the fibre's slope through the deflection map: G' = (G - psi_y) / psi_u */
static inline void knots_slope(int count, stages *s)
{
    const int *hit_of = s->hit_of, hits = s->hits;
    const sk__knot_hit *hit = s->hit;
    double *G = s->G;
    for (int i = 0; hits > 0 && i < count; i++)
        if (hit_of[i] >= 0) {
            const sk__knot_hit *h = &hit[hit_of[i]];
            double g = (G[i] - h->psi_y) / (h->psi_u > 0.02 ? h->psi_u : 0.02);
            G[i] = g > 50.0 ? 50.0 : (g < -50.0 ? -50.0 : g);
        }
}

/* phi = Phi / R(t, theta) = Phi / r; the fibre through (r, theta, y) left the end grain
   at theta0 = theta - phi */
static inline void end_grain_direction(const sk_wood *w, int count, looks lk, stages *s)
{
    const double *r = s->r, *cos_t = s->cos_t, *sin_t = s->sin_t, *theta = s->theta;
    const double *P = s->P;
    double *phi = s->phi, *dir_x = s->dir_x, *dir_z = s->dir_z, *theta0 = s->theta0;
    double *col0 = s->col0, *col0_f = s->col0_f;
    double phi_mod[B], k_p[B], sb[B], cb[B], sin_p[B], cos_p[B];
    bool round = lk.round, need_theta0 = lk.need_theta0, turn = lk.turn;
    double theta_scale = w->rings.theta_scale;
#pragma omp simd
    for (int i = 0; i < count; i++) {
        phi[i] = sk__phase_phi(P[i], r[i]);
        phi_mod[i] = phi[i] - 2.0 * SK_PI * sk__floor_vec(phi[i] * (0.5 / SK_PI));
        sk__sincos_reduce(phi_mod[i], &k_p[i], &sb[i], &cb[i]);
    }
    if (turn || !round)
        for (int i = 0; i < count; i++) sk__sincos_join(k_p[i], sb[i], cb[i], &sin_p[i], &cos_p[i]);
    if (turn) {
#pragma omp simd
        for (int i = 0; i < count; i++) {
            dir_x[i] = cos_t[i] * cos_p[i] + sin_t[i] * sin_p[i];
            dir_z[i] = sin_t[i] * cos_p[i] - cos_t[i] * sin_p[i];
            double a = sk__atan2(dir_z[i], dir_x[i]);
            a = a < 0.0 ? a + 2.0 * SK_PI : a;
            theta0[i] = need_theta0 ? a : 0.0;
            col0[i] = sk__rings_column_split(theta_scale, theta0[i], &col0_f[i]);
        }
    } else if (!round) {
#pragma omp simd
        for (int i = 0; i < count; i++) {
            dir_x[i] = cos_t[i] * cos_p[i] + sin_t[i] * sin_p[i];
            dir_z[i] = sin_t[i] * cos_p[i] - cos_t[i] * sin_p[i];
            double a = theta[i] - phi_mod[i];
            theta0[i] = a - 2.0 * SK_PI * sk__floor_vec(a * (0.5 / SK_PI));
            col0[i] = sk__rings_column_split(theta_scale, theta0[i], &col0_f[i]);
        }
    } else {
        for (int i = 0; i < count; i++) theta0[i] = 0.0; /* nothing looks there */
    }
}

/* the end-grain point at R(t, theta0) */
static inline void end_grain_point(const sk_wood *w, int count, looks lk, stages *s)
{
    const sk__rings *rg = &w->rings;
    const double *r = s->r, *t = s->t, *col0 = s->col0, *col0_f = s->col0_f;
    double *r0 = s->r0;
    sk__rings_at *at0 = s->at0;
    bool round = lk.round;
    if (!round || w->vessels.ring.on) {
        for (int i = 0; i < count; i++) {
            at0[i] = sk__rings_at_column(rg, sk__rings_column_wrap(rg, col0[i]), col0_f[i]);
            r0[i] = round ? r[i] : sk__rings_R_at(rg, &at0[i], t[i]);
        }
    } else {
        for (int i = 0; i < count; i++) r0[i] = r[i];
    }
}

/* the cell of C'(t, theta0) whose brightness shift applies (sec. 6.3) */
static inline void cell_shift(const sk_wood *w, int count, const double *y, looks lk, stages *s)
{
    const sk__attributes *attr = &w->attr;
    const double *t = s->t, *theta0 = s->theta0;
    double *cell = s->cell;
    if (lk.shifted)
        for (int i = 0; i < count; i++) cell[i] = sk__attributes_cell(attr, t[i], theta0[i], y[i]);
}

/* vessels (sec. 5) at the end-grain point */
static inline void vessels_at_end_grain(const sk_wood *w, int count, float footprint_mm, looks lk,
                                        stages *s)
{
    const double *r0 = s->r0, *dir_x = s->dir_x, *dir_z = s->dir_z;
    double *vessel = s->vessel;
    if (lk.vessels) {
        double x0[B], z0[B];
#pragma omp simd
        for (int i = 0; i < count; i++) {
            x0[i] = r0[i] * dir_x[i];
            z0[i] = r0[i] * dir_z[i];
        }
        sk__vessels_coverage_batch(&w->vessels, &w->rings, count, s->at0, x0, z0, r0, s->theta0,
                                   s->t, footprint_mm, vessel);
    } else {
        for (int i = 0; i < count; i++) vessel[i] = 0.0;
    }
}

/* broad rays at the end-grain point (they hold no pores): their coverage, which the
   vessels' gives way to */
static inline void rays_at_end_grain(const sk_wood *w, int count, const double *y, sk_vec3f n,
                                     float footprint_mm, looks lk, stages *s)
{
    const sk__rings *rg = &w->rings;
    const double *cos_t = s->cos_t, *sin_t = s->sin_t, *t = s->t, *theta0 = s->theta0;
    const double *r0 = s->r0;
    double *vessel = s->vessel, *ray = s->ray;
    if (lk.rays) {
        sk_vec3f nt = sk__wood_frame_dir_to_tree(&w->frame, n);
        double fw = footprint_mm;
        for (int i = 0; i < count; i++) {
            /* the footprint along the ray's directions that lie in the surface */
            double er = cos_t[i] * nt.x + sin_t[i] * nt.z, et = -sin_t[i] * nt.x + cos_t[i] * nt.z;
            double in_r = 1.0 - er * er, in_t = 1.0 - et * et, in_y = 1.0 - (double)nt.y * nt.y;
            ray[i] = sk__rays_coverage(
                &w->rays, rg, t[i], theta0[i], r0[i], y[i], fw * sqrt(in_t > 0.0 ? in_t : 0.0),
                fw * sqrt(in_y > 0.0 ? in_y : 0.0), fw * sqrt(in_r > 0.0 ? in_r : 0.0));
            vessel[i] *= 1.0 - ray[i];
        }
    }
}

/* a knot's wood has neither stem pores nor rays */
static inline void knots_clear_tissue(int count, looks lk, stages *s)
{
    const int *hit_of = s->hit_of, hits = s->hits;
    const sk__knot_hit *hit = s->hit;
    double *vessel = s->vessel, *ray = s->ray;
    bool rays = lk.rays;
    for (int i = 0; hits > 0 && i < count; i++)
        if (hit_of[i] >= 0) {
            vessel[i] *= 1.0 - hit[hit_of[i]].knot;
            if (rays) ray[i] *= 1.0 - hit[hit_of[i]].knot;
        }
}

/* the knot's own wood: its rings, darker (end grain), in bark where it died */
static inline void knots_albedo(const sk_wood *w, int count, const stages *s, const float ew[3],
                                const float lw[3], sk__wood_batch *out)
{
    const sk__attributes *attr = &w->attr;
    const int *hit_of = s->hit_of, hits = s->hits;
    const sk__knot_hit *hit = s->hit;
    for (int i = 0; hits > 0 && i < count; i++) {
        if (hit_of[i] < 0) continue;
        const sk__knot_hit *h = &hit[hit_of[i]];
        double lk = sk__attributes_latewood(attr, h->t_knot, h->half_knot);
        float dark = (float)(1.0 - w->knots.darkening), m = (float)h->knot, bk = (float)h->bark;
        for (int c = 0; c < 3; c++) {
            float kc = (ew[c] + (lw[c] - ew[c]) * (float)lk) * dark;
            kc = kc + ((&w->knots.bark_color.x)[c] - kc) * bk;
            out->albedo[c][i] = out->albedo[c][i] + (kc - out->albedo[c][i]) * m;
        }
    }
}

/* the albedo: the ring profile's colour with the cell's shift, and an open vessel's
   colour over its coverage (a coverage of 0 leaves the colour as it is); then the knots' */
static inline void albedo(const sk_wood *w, int count, looks lk, const stages *s,
                          sk__wood_batch *out)
{
    const sk__attributes *attr = &w->attr;
    const double *late = s->late, *ray = s->ray, *cell = s->cell, *vessel = s->vessel;
    bool rays = lk.rays, shifted = lk.shifted;
    float ew[3] = {attr->earlywood.x, attr->earlywood.y, attr->earlywood.z};
    float lw[3] = {attr->latewood.x, attr->latewood.y, attr->latewood.z};
    float vc[3] = {attr->vessel.x, attr->vessel.y, attr->vessel.z};
    for (int c = 0; c < 3; c++) {
        float e = ew[c], l = lw[c], vcol = vc[c];
        float *alb = out->albedo[c];
#pragma omp simd
        for (int i = 0; i < count; i++) alb[i] = e + (l - e) * (float)late[i];
        if (rays) { /* the ray tissue in place of the ring's, shifted like the cells round it */
            float rc = (&w->rays.color.x)[c];
            for (int i = 0; i < count; i++) alb[i] = alb[i] + (rc - alb[i]) * (float)ray[i];
        }
        if (shifted)
            for (int i = 0; i < count; i++) alb[i] = sk__attributes_shifted(attr, alb[i], cell[i]);
#pragma omp simd
        for (int i = 0; i < count; i++) alb[i] = alb[i] + (vcol - alb[i]) * (float)vessel[i];
    }
    knots_albedo(w, count, s, ew, lw, out);
}

/* The latewood share, the vessel coverage, the ring coordinate t and the phase; and the
   fibre through the point (sec. 7.1). */
static inline void store_samples(int count, const stages *s, sk__wood_batch *out)
{
    const double *late = s->late, *vessel = s->vessel, *G = s->G, *dR = s->dR, *r = s->r;
    const double *cos_t = s->cos_t, *sin_t = s->sin_t, *t = s->t, *phi = s->phi;
#pragma omp simd
    for (int i = 0; i < count; i++) {
        out->latewood[i] = (float)late[i];
        out->vessel[i] = (float)vessel[i];
    }
    /* the fibre through the point (sec. 7.1) */
#pragma omp simd
    for (int i = 0; i < count; i++) {
        sk_vec3d f = sk__fibre_direction(G[i], dR[i], r[i], cos_t[i], sin_t[i]);
        out->fibre[0][i] = (float)f.x;
        out->fibre[1][i] = (float)f.y;
        out->fibre[2][i] = (float)f.z;
        out->t[i] = (float)t[i];
        out->phase[i] = (float)phi[i];
    }
}

/* The fibre turned towards the cells of a ray or a knot that covers the point. */
static inline void fibre_blends(int count, looks lk, const stages *s, sk__wood_batch *out)
{
    const double *cos_t = s->cos_t, *sin_t = s->sin_t, *ray = s->ray;
    const int *hit_of = s->hit_of, hits = s->hits;
    const sk__knot_hit *hit = s->hit;
    bool rays = lk.rays;
    /* in a ray, its cells' radial direction (the silver figure's sheen on quarter-sawn
       faces, which lie in a ray's plane) */
    for (int i = 0; rays && i < count; i++)
        if (ray[i] > 0.0) blend_fibre(out, i, ray[i], sk_v3d(cos_t[i], 0.0, sin_t[i]));
    /* in a knot, the branch's fibres */
    for (int i = 0; hits > 0 && i < count; i++)
        if (hit_of[i] >= 0) blend_fibre(out, i, hit[hit_of[i]].knot, hit[hit_of[i]].axis);
}

/* The fibre from the tree frame into the scene's. */
static inline void fibre_to_scene(const sk_wood *w, int count, sk__wood_batch *out)
{
    if (!w->frame.identity)
        for (int i = 0; i < count; i++) {
            sk_vec3f f = sk__wood_frame_dir_to_scene(
                &w->frame, sk_v3f(out->fibre[0][i], out->fibre[1][i], out->fibre[2][i]));
            out->fibre[0][i] = f.x;
            out->fibre[1][i] = f.y;
            out->fibre[2][i] = f.z;
        }
}

/* its dive under the surface (sec. 7.1) */
static inline void fibre_dive(int count, sk_vec3f n, unsigned flags, sk__wood_batch *out)
{
    for (int i = 0; i < count; i++)
        out->dive[i] = (flags & SK__WOOD_EVAL_DIVE)
                           ? (float)sk__fibre_dive(
                                 sk_v3f(out->fibre[0][i], out->fibre[1][i], out->fibre[2][i]), n)
                           : 0.0f;
}

void sk__wood_eval_section_batch(const sk_wood *w, int count, const sk__wood_section *sec,
                                 const double *y, sk_vec3f normal, float footprint_mm,
                                 unsigned flags, sk__wood_batch *out)
{
    if (count <= 0) return;
    stages s;
    knots_deflect(w, count, sec, y, footprint_mm, &s);
    sk_vec3f n = sk_v3f_normalize(normal);
    looks lk = looks_choose(w);
    grain_phase(w, count, y, &s);
    knots_slope(count, &s);
    end_grain_direction(w, count, lk, &s);
    end_grain_point(w, count, lk, &s);
    cell_shift(w, count, y, lk, &s);
    vessels_at_end_grain(w, count, footprint_mm, lk, &s);
    /* broad rays at the end-grain point (they hold no pores), and none in a knot */
    rays_at_end_grain(w, count, y, n, footprint_mm, lk, &s);
    knots_clear_tissue(count, lk, &s);
    albedo(w, count, lk, &s, out);
    store_samples(count, &s, out);
    fibre_blends(count, lk, &s, out);
    fibre_to_scene(w, count, out);
    fibre_dive(count, n, flags, out);
    out->up = sk__wood_surface_up(w, n);
}

void sk__wood_eval_batch(const sk_wood *w, int count, const float *const points[3], sk_vec3f normal,
                         float footprint_mm, unsigned flags, sk__wood_batch *out)
{
    if (count <= 0) return;
    /* into the tree frame (sk__wood_frame_point_to_tree) */
    float px[B], pz[B];
    double y[B];
    const float *sx = points[0], *sy = points[1], *sz = points[2];
    if (w->frame.identity) {
        for (int i = 0; i < count; i++) {
            px[i] = sx[i];
            y[i] = sy[i];
            pz[i] = sz[i];
        }
    } else {
        const sk__wood_frame *f = &w->frame;
        sk_vec3f o = f->origin,
                 m0 = sk_v3f(f->to_tree.m[0][0], f->to_tree.m[0][1], f->to_tree.m[0][2]);
        sk_vec3f m1 = sk_v3f(f->to_tree.m[1][0], f->to_tree.m[1][1], f->to_tree.m[1][2]);
        sk_vec3f m2 = sk_v3f(f->to_tree.m[2][0], f->to_tree.m[2][1], f->to_tree.m[2][2]);
#pragma omp simd
        for (int i = 0; i < count; i++) {
            float dx = sx[i] - o.x, dy = sy[i] - o.y, dz = sz[i] - o.z;
            px[i] = m0.x * dx + m0.y * dy + m0.z * dz;
            y[i] = m1.x * dx + m1.y * dy + m1.z * dz;
            pz[i] = m2.x * dx + m2.y * dy + m2.z * dz;
        }
    }
    double r[B], cos_t[B], sin_t[B], theta[B], t[B], width[B], dR[B], half[B], late[B];
    sk__wood_section sec = {r, cos_t, sin_t, theta, t, width, dR, half, late};
    sk__wood_section_eval(w, count, px, pz, normal, footprint_mm, &sec);
    sk__wood_eval_section_batch(w, count, &sec, y, normal, footprint_mm, flags, out);
}

void sk_wood_eval_filtered(const sk_wood *w, sk_vec3f point, sk_vec3f normal, float footprint_mm,
                           sk_wood_sample *s)
{
    sk__wood_batch b;
    const float *p[3] = {&point.x, &point.y, &point.z};
    sk__wood_eval_batch(w, 1, p, normal, footprint_mm, SK__WOOD_EVAL_DIVE, &b);
    s->albedo = sk_v3f(b.albedo[0][0], b.albedo[1][0], b.albedo[2][0]);
    s->vessel = b.vessel[0];
    s->fibre = sk_v3f(b.fibre[0][0], b.fibre[1][0], b.fibre[2][0]);
    s->dive = b.dive[0];
    s->up = b.up;
    s->t = b.t[0];
    s->latewood = b.latewood[0];
    s->phase = b.phase[0];
}

void sk_wood_eval(const sk_wood *wood, sk_vec3f point, sk_vec3f normal, sk_wood_sample *sample)
{
    sk_wood_eval_filtered(wood, point, normal, 0.0f, sample);
}
