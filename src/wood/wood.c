/* The wood solid texture (Kawai 2000): tree set-up and the per-point evaluation that a
 * renderer calls. A point goes through the render steps of sec. 6.2: into the tree frame,
 * t = T(r, theta) (sec. 4.4), the grain's phase phi = Phi(t, y) / R(t, theta) (eq. 3),
 * back to the end grain at theta0 = theta - phi, where the attribute array C'(t, theta0)
 * (sec. 6.3) and the vessels (sec. 5) are looked up; the fibre direction there gives the
 * dive angle of sec. 7. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "wood/fibre.h"
#include "wood/numeric.h"
#include "wood/wood_internal.h"

const sk_wood_desc *sk_wood_get_desc(const sk_wood *wood) { return &wood->desc; }

void sk_wood_get_stats(const sk_wood *wood, sk_wood_stats *stats) { *stats = wood->stats; }

void sk_wood_destroy(sk_wood *wood)
{
    if (!wood) return;
    sk__rings_free(&wood->rings);
    sk__grain_free(&wood->grain);
    free(wood);
}

sk_result sk_wood_create(const sk_wood_desc *desc, sk_wood **out, sk_error *err)
{
    if (!out) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "wood: no output pointer");
    *out = NULL;
    double start = sk_time_seconds();
    sk_wood_desc resolved = sk_wood_desc_resolved(desc);
    sk_result r = sk_wood_desc_validate(&resolved, err);
    if (r != SK_OK) return r;
    sk_wood *w = calloc(1, sizeof *w);
    if (!w) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "wood: out of memory");
    w->desc = resolved;
    sk__wood_frame_init(&w->frame, &resolved.transform);
    w->axis = sk__wood_frame_dir_to_scene(&w->frame, sk_v3f(0, 1, 0));
    r = sk__rings_build(&w->rings, &resolved, err);
    if (r == SK_OK) r = sk__grain_build(&w->grain, &resolved, w->rings.t_max, err);
    if (r != SK_OK) {
        sk_wood_destroy(w);
        return r;
    }
    sk__vessels_init(&w->vessels, &resolved);
    sk__attributes_init(&w->attr, &resolved);
    sk__shading_init(&w->shading, &resolved);
    w->stats.memory_bytes = sizeof *w + sk__rings_memory(&w->rings) + sk__grain_memory(&w->grain);
    w->stats.ring_count = w->rings.years;
    w->stats.ring_table_size[0] = w->rings.nt;
    w->stats.ring_table_size[1] = w->rings.ntheta + 1;
    w->stats.phase_table_size[0] = w->grain.dg ? w->grain.nt : 0;
    w->stats.phase_table_size[1] = w->grain.dg ? w->grain.ny + 1 : 0;
    w->stats.setup_seconds = sk_time_seconds() - start;
    *out = w;
    return SK_OK;
}

/* Evaluates `count` (<= SK__WOOD_BATCH) points sharing one normal stage by stage: each
 * stage's loop has no dependence between points, so the processor overlaps them. One
 * point or many, every point gets the same arithmetic. */
void sk__wood_eval_batch(const sk_wood *w, int count, const sk_vec3f *points, sk_vec3f normal,
                         float footprint_mm, sk_wood_sample *out)
{
    double r[SK__WOOD_BATCH], y[SK__WOOD_BATCH], cos_t[SK__WOOD_BATCH], sin_t[SK__WOOD_BATCH];
    double t[SK__WOOD_BATCH], width[SK__WOOD_BATCH], dR[SK__WOOD_BATCH], theta[SK__WOOD_BATCH];
    double G[SK__WOOD_BATCH], phi[SK__WOOD_BATCH], theta0[SK__WOOD_BATCH], r0[SK__WOOD_BATCH];
    double x0[SK__WOOD_BATCH], z0[SK__WOOD_BATCH];
    sk_vec3f n = sk_v3f_normalize(normal);
    sk_vec3f nt = sk__wood_frame_dir_to_tree(&w->frame, n);
    /* Round rings (no fluctuation) do not depend on theta: no angle is needed, and the
       end-grain point is the point turned back by phi. */
    bool round = w->rings.ntheta == 1;
    bool need_theta0 = !round || w->vessels.ring.on || w->attr.shift > 0.0;

    /* into the tree frame; t = T(r, theta) (sec. 4.4) */
    for (int i = 0; i < count; i++) {
        sk_vec3f p = sk__wood_frame_point_to_tree(&w->frame, points[i]);
        double x = p.x, z = p.z;
        y[i] = p.y;
        r[i] = sqrt(x * x + z * z);
        cos_t[i] = r[i] > 0.0 ? x / r[i] : 1.0;
        sin_t[i] = r[i] > 0.0 ? z / r[i] : 0.0;
        theta[i] = round ? 0.0 : sk__atan2(z, x);
        t[i] = sk__rings_T(&w->rings, r[i], theta[i], &width[i], &dR[i]);
    }
    /* eq. (3): the fibre through (r, theta, y) left the end grain at theta0 = theta - phi */
    for (int i = 0; i < count; i++) {
        phi[i] = sk__phase_phi(sk__phase_eval(&w->grain, t[i], y[i], &G[i]), r[i]);
        double phi_mod = phi[i] - 2.0 * SK_PI * sk__floor_d(phi[i] * (0.5 / SK_PI));
        double sin_p, cos_p;
        sk__sincos(phi_mod, &sin_p, &cos_p);
        double dir_x = cos_t[i] * cos_p + sin_t[i] * sin_p;
        double dir_z = sin_t[i] * cos_p - cos_t[i] * sin_p;
        if (round) {
            r0[i] = r[i];
            theta0[i] = need_theta0 ? sk__atan2(dir_z, dir_x) : 0.0;
            if (theta0[i] < 0.0) theta0[i] += 2.0 * SK_PI;
        } else {
            double a = theta[i] - phi_mod;
            theta0[i] = a - 2.0 * SK_PI * sk__floor_d(a * (0.5 / SK_PI));
            r0[i] = sk__rings_R(&w->rings, t[i], theta0[i]);
        }
        x0[i] = r0[i] * dir_x;
        z0[i] = r0[i] * dir_z;
    }
    /* C'(t, theta0): the ring profile, box-filtered over the footprint's span of t along
       the surface (the radial direction's part in the surface over the ring width), and
       the cell's brightness shift (sec. 6.3) */
    for (int i = 0; i < count; i++) {
        double half = 0.0;
        if (footprint_mm > 0.0f) {
            double er_n = cos_t[i] * nt.x + sin_t[i] * nt.z;
            double tangential = 1.0 - er_n * er_n;
            half = 0.5 * footprint_mm * sqrt(tangential > 0.0 ? tangential : 0.0) / width[i];
        }
        double late = sk__attributes_latewood(&w->attr, t[i], half);
        double shift = sk__attributes_shift(&w->attr, t[i], theta0[i], y[i]);
        sk_vec3f ring = sk_v3f_lerp(w->attr.earlywood, w->attr.latewood, (float)late);
        out[i].albedo = sk_v3f_scale(ring, (float)shift);
        out[i].latewood = (float)late;
    }
    /* vessels (sec. 5) */
    for (int i = 0; i < count; i++) {
        double vessel = sk__vessels_coverage(&w->vessels, &w->rings, x0[i], z0[i], r0[i],
                                             theta0[i], t[i], footprint_mm);
        out[i].albedo = sk_v3f_lerp(out[i].albedo, w->attr.vessel, (float)vessel);
        out[i].vessel = (float)vessel;
    }
    /* the fibre through the point and its dive under the surface (sec. 7.1) */
    sk_vec3f up = sk_v3f_sub(w->axis, sk_v3f_scale(n, sk_v3f_dot(w->axis, n)));
    float len = sk_v3f_length(up);
    if (len > 1e-6f) {
        up = sk_v3f_scale(up, 1.0f / len);
    } else {
        sk_vec3f b;
        sk_v3f_basis(n, &up, &b);
    }
    for (int i = 0; i < count; i++) {
        sk_vec3d f = sk__fibre_direction(G[i], dR[i], r[i], cos_t[i], sin_t[i]);
        out[i].fibre = sk__wood_frame_dir_to_scene(&w->frame, sk_v3d_to_f(f));
        out[i].dive = (float)sk__fibre_dive(out[i].fibre, n);
        out[i].up = up;
        out[i].t = (float)t[i];
        out[i].phase = (float)phi[i];
    }
}

void sk_wood_eval_filtered(const sk_wood *w, sk_vec3f point, sk_vec3f normal, float footprint_mm,
                           sk_wood_sample *s)
{
    sk__wood_eval_batch(w, 1, &point, normal, footprint_mm, s);
}

void sk_wood_eval(const sk_wood *wood, sk_vec3f point, sk_vec3f normal, sk_wood_sample *sample)
{
    sk_wood_eval_filtered(wood, point, normal, 0.0f, sample);
}
