/* Reflection models of the wood surface: the figure sheen of Kawai 2000 eq. (4) and the
 * 3D fibre highlight under a clear finish (Marschner et al. 2005). */
#ifndef SK_WOOD_SHADE_H
#define SK_WOOD_SHADE_H

#include "shitsukan/wood.h"
#include "models/wood/numeric.h"

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
sk_vec3f sk__shade_fibre(const sk__shading *shading, const sk_wood_sample *sample, sk_vec3f normal,
                         sk_vec3f light, sk_vec3f view);

/* The parts of eq. (4) that depend only on the light, the normal and the direction `up`
 * towards the tree top (one set for a whole planar cut). */
typedef struct sk__figure_light {
    double cos_i;  /* l . n: cos(delta) seen in the surface's up-normal plane */
    double l_up;   /* l . up */
    double h;      /* length of (l . n, l . up) */
    float diffuse; /* kd cos_i */
} sk__figure_light;

static inline sk__figure_light sk__figure_light_make(const sk__shading *s, sk_vec3f n, sk_vec3f up,
                                                     sk_vec3f l)
{
    sk__figure_light fl;
    fl.cos_i = sk_v3f_dot(l, n);
    fl.l_up = sk_v3f_dot(l, up);
    fl.h = sqrt(fl.cos_i * fl.cos_i + fl.l_up * fl.l_up);
    fl.diffuse = (float)(s->kd * fl.cos_i);
    return fl;
}

/* cos(delta - alpha) of eq. (4) for sin(alpha) = -f . n, as a position in the cos^n
 * table (-1 below the table, where ks cos^n is dropped); branch-free. With delta =
 * atan2(l . up, l . n) and alpha the dive angle of the sample's fibre under this normal,
 * expanded without trigonometry. */
static inline double sk__figure_position(const sk__shading *s, const sk__figure_light *fl,
                                         double sin_a)
{
    sin_a = sin_a < -1.0 ? -1.0 : sin_a;
    sin_a = sin_a > 1.0 ? 1.0 : sin_a;
    double c = (fl->cos_i * sqrt(1.0 - sin_a * sin_a) + fl->l_up * sin_a) / fl->h;
    double position = (c - s->cos_floor) * s->inv_step;
    return c > s->cos_floor ? position : -1.0;
}

/* ks cos^n at table position u (0 below the table), on the share 1 - vessel of the
 * surface that has cell walls to reflect. */
static inline double sk__figure_specular(const sk__shading *s, double u, float vessel)
{
    if (u < 0.0) return 0.0;
    int i = (int)u;
    if (i > SK__POW_TABLE - 1) i = SK__POW_TABLE - 1;
    double f = u - i;
    return (s->ks_pow[i] + f * (s->ks_pow[i + 1] - s->ks_pow[i])) * (1.0 - vessel);
}

/* eq. (4) for a sample of the given albedo, vessel coverage and sin(alpha) = -f . n;
 * the light must be above the surface (fl->cos_i > 0). */
static inline sk_vec3f sk__shade_figure_lit(const sk__shading *s, const sk__figure_light *fl,
                                            sk_vec3f albedo, float vessel, double sin_a)
{
    float spec = (float)sk__figure_specular(s, sk__figure_position(s, fl, sin_a), vessel);
    return sk_v3f(albedo.x * fl->diffuse + spec, albedo.y * fl->diffuse + spec,
                  albedo.z * fl->diffuse + spec);
}

/* eq. (4), see sk_wood_shade. */
static inline sk_vec3f sk__shade_figure(const sk__shading *s, const sk_wood_sample *sample,
                                        sk_vec3f n, sk_vec3f l)
{
    sk__figure_light fl = sk__figure_light_make(s, n, sample->up, l);
    if (fl.cos_i <= 0.0) return sk_v3f(0, 0, 0);
    return sk__shade_figure_lit(s, &fl, sample->albedo, sample->vessel,
                                -(double)sk_v3f_dot(sample->fibre, n));
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
