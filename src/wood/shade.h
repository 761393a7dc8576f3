/* Reflection models of the wood surface: the figure sheen of Kawai 2000 eq. (4) and the
 * 3D fibre highlight under a clear finish (Marschner et al. 2005). */
#ifndef SK_WOOD_SHADE_H
#define SK_WOOD_SHADE_H

#include "shitsukan/wood.h"
#include "wood/numeric.h"

#define SK__POW_TABLE 4096

typedef struct sk__shading {
    sk_wood_shading_model model;
    double kd, ks, exponent;
    /* ks c^n for c = cos(delta - alpha) in [cos_floor, 1], tabulated (linear between
       entries, relative error < 2e-6); below cos_floor ks c^n < 1e-7 and is dropped */
    double cos_floor, inv_step;
    double ks_pow[SK__POW_TABLE + 1];
    double fibre_strength, fibre_width, ior, finish_exponent;
    sk_vec3f fibre_color; /* linear */
} sk__shading;

void sk__shading_init(sk__shading *shading, const sk_wood_desc *desc);

/* Marschner et al. 2005 fibre model, see sk_wood_shade. */
sk_vec3f sk__shade_fibre(const sk__shading *shading, const sk_wood_sample *sample,
                         sk_vec3f normal, sk_vec3f light, sk_vec3f view);

/* eq. (4), see sk_wood_shade. */
static inline sk_vec3f sk__shade_figure(const sk__shading *s, const sk_wood_sample *sample, sk_vec3f n,
                          sk_vec3f l)
{
    double cos_i = sk_v3f_dot(l, n);
    if (cos_i <= 0.0) return sk_v3f(0, 0, 0);
    /* cos(delta - alpha) with delta = atan2(l . up, l . n) and sin(alpha) = -f . n (the
       dive angle of the sample's fibre under this normal), expanded without trigonometry */
    double l_up = sk_v3f_dot(l, sample->up), h = sqrt(cos_i * cos_i + l_up * l_up);
    double sin_a = -(double)sk_v3f_dot(sample->fibre, n);
    sin_a = sin_a < -1.0 ? -1.0 : (sin_a > 1.0 ? 1.0 : sin_a);
    double c = (cos_i * sqrt(1.0 - sin_a * sin_a) + l_up * sin_a) / h;
    double spec = 0.0;
    if (c > s->cos_floor) {
        double u = (c - s->cos_floor) * s->inv_step;
        int i = (int)u;
        if (i > SK__POW_TABLE - 1) i = SK__POW_TABLE - 1;
        double f = u - i;
        spec = (s->ks_pow[i] + f * (s->ks_pow[i + 1] - s->ks_pow[i])) * (1.0 - sample->vessel);
    }
    float diffuse = (float)(s->kd * cos_i);
    return sk_v3f(sample->albedo.x * diffuse + (float)spec, sample->albedo.y * diffuse + (float)spec,
                  sample->albedo.z * diffuse + (float)spec);
}

static inline sk_vec3f sk__shade(const sk__shading *s, const sk_wood_sample *sample, sk_vec3f n,
                                 sk_vec3f l, sk_vec3f v)
{
    if (s->model == SK_WOOD_SHADING_FIBRE) return sk__shade_fibre(s, sample, n, l, v);
    return sk__shade_figure(s, sample, n, l);
}

/* Fresnel reflectance of unpolarised light at a dielectric boundary of relative index
 * eta, for the cosine of the angle of incidence on the outer side. */
double sk__fresnel_dielectric(double cos_i, double eta);

#endif
