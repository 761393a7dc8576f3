/* Reflection models (Kawai 2000 sec. 7.3, eq. (4); Marschner et al. 2005).
 *
 * FIGURE, eq. (4): L_O = k_d L_I cos(delta) + k_s L_I cos^n(delta - alpha). delta is the
 * light's incidence angle measured towards the tree top, alpha the fibre dive angle: the
 * specular normal is the surface normal tilted by alpha, the diffuse one the true normal.
 * The diffuse term carries the albedo; an open vessel has no cell walls to reflect, so
 * the specular term is weighted by 1 - vessel coverage.
 *
 * FIBRE (beyond the paper's 1-DOF model): light and view refract into a clear finish of
 * index eta; a fibre of 3D direction u reflects on the cone around u, which Marschner et
 * al. write with psi_i = asin(w_i' . u), psi_r = asin(w_r' . u) (both refracted vectors
 * pointing out of the surface), psi_h = psi_i + psi_r, psi_d = psi_r - psi_i and
 * f_f = k_f g(beta, psi_h) / cos^2(psi_d / 2), g the unit-area Gaussian of standard
 * deviation beta, exp(-psi^2 / (2 beta^2)) / (beta sqrt(2 pi)). The subsurface light is
 * weighted by the Fresnel transmittances T_i T_r in and out; the fibre lobe, a radiance
 * inside the finish, also by 1 / eta^2, while the diffuse albedo is taken as the colour
 * seen through the finish. The finish adds its own Fresnel-weighted, normalised
 * Blinn-Phong highlight ((e + 8) / (8 pi) (n . h)^e).
 *
 * Both return reflected radiance for an irradiance of pi at normal incidence, so a white
 * diffuse surface lit along its normal gives 1 in either model. */
#include "models/wood/shade.h"

#include <math.h>

#include "models/wood/attributes.h"
#include "models/wood/numeric.h"
#include "models/wood/wood_internal.h"

void sk__shading_init(sk__shading *s, const sk_wood_desc *desc)
{
    const sk_wood_shading_desc *d = &desc->shading;
    s->model = d->model;
    s->kd = d->diffuse;
    s->ks = d->specular;
    s->exponent = d->exponent;
    /* ks c^n >= 1e-7 needs c >= (1e-7 / ks)^(1 / n); with no specular term, never */
    s->cos_floor = s->ks > 0.0 ? pow(1e-7 / s->ks, 1.0 / s->exponent) : 2.0;
    double step = (1.0 - (s->cos_floor < 1.0 ? s->cos_floor : 0.0)) / SK__POW_TABLE;
    s->inv_step = 1.0 / step;
    for (int i = 0; i <= SK__POW_TABLE; i++)
        s->ks_pow[i] = s->ks > 0.0 ? s->ks * pow(s->cos_floor + i * step, s->exponent) : 0.0;
    s->fibre_strength = d->fibre_strength;
    s->fibre_width = d->fibre_width;
    s->ior = d->finish_ior;
    s->finish_exponent = d->finish_exponent;
    s->fibre_color = sk__linear_from_srgb3(d->fibre_srgb);
}

double sk__fresnel_dielectric(double cos_i, double eta)
{
    cos_i = sk_clampd(cos_i, 0.0, 1.0);
    double sin_t2 = (1.0 - cos_i * cos_i) / (eta * eta);
    if (sin_t2 >= 1.0) return 1.0;
    double cos_t = sqrt(1.0 - sin_t2);
    double rs = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    double rp = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    return 0.5 * (rs * rs + rp * rp);
}

/* Direction inside the finish of the outward unit vector w (refraction by Snell's law),
 * again pointing out of the surface. */
static sk_vec3d refract_out(sk_vec3d w, sk_vec3d n, double eta)
{
    double c = sk_v3d_dot(w, n);
    sk_vec3d tangential = sk_v3d_scale(sk_v3d_sub(w, sk_v3d_scale(n, c)), 1.0 / eta);
    double t2 = sk_v3d_dot(tangential, tangential);
    return sk_v3d_add(tangential, sk_v3d_scale(n, sqrt(fmax(0.0, 1.0 - t2))));
}

sk_vec3f sk__shade_fibre(const sk__shading *s, const sk_wood_sample *sample, sk_vec3f nf,
                         sk_vec3f lf, sk_vec3f vf)
{
    sk_vec3d n = sk_v3f_to_d(nf), l = sk_v3f_to_d(lf), v = sk_v3f_to_d(vf);
    double cos_i = sk_v3d_dot(l, n), cos_o = sk_v3d_dot(v, n);
    if (cos_i <= 0.0 || cos_o <= 0.0) return sk_v3f(0, 0, 0);
    double eta = s->ior;
    /* the finish's own highlight */
    sk_vec3d h = sk_v3d_normalize(sk_v3d_add(l, v));
    double nh = fmax(0.0, sk_v3d_dot(n, h));
    double surface = sk__fresnel_dielectric(sk_v3d_dot(l, h), eta) * (s->finish_exponent + 8.0) /
                     (8.0 * SK_PI) * pow(nh, s->finish_exponent);
    /* through the finish */
    double trans =
        (1.0 - sk__fresnel_dielectric(cos_i, eta)) * (1.0 - sk__fresnel_dielectric(cos_o, eta));
    sk_vec3d li = refract_out(l, n, eta), vi = refract_out(v, n, eta);
    sk_vec3d u = sk_v3f_to_d(sample->fibre);
    double psi_i = asin(sk_clampd(sk_v3d_dot(li, u), -1.0, 1.0));
    double psi_r = asin(sk_clampd(sk_v3d_dot(vi, u), -1.0, 1.0));
    double psi_h = psi_i + psi_r, psi_d = psi_r - psi_i;
    double beta = s->fibre_width;
    double g = exp(-psi_h * psi_h / (2.0 * beta * beta)) / (beta * sqrt(2.0 * SK_PI));
    double cd = cos(0.5 * psi_d);
    double fibre = s->fibre_strength * g / (cd * cd) / (eta * eta) * (1.0 - sample->vessel);
    /* radiance for irradiance pi at normal incidence: pi f_r cos_i */
    double k = SK_PI * cos_i;
    double diffuse = k * trans / SK_PI, lobe = k * trans * fibre, spec = k * surface;
    return sk_v3f((float)(sample->albedo.x * diffuse + s->fibre_color.x * lobe + spec),
                  (float)(sample->albedo.y * diffuse + s->fibre_color.y * lobe + spec),
                  (float)(sample->albedo.z * diffuse + s->fibre_color.z * lobe + spec));
}

sk_vec3f sk_wood_shade(const sk_wood *wood, const sk_wood_sample *sample, sk_vec3f normal,
                       sk_vec3f light, sk_vec3f view)
{
    return sk__shade(&wood->shading, sample, normal, light, view);
}
