/* Importance sampling of the materials' reflection for the path integrator: a mixture of
 * the cosine-weighted diffuse lobe (Malley's method) and, for diffuse + Blinn-Phong, the
 * half vector drawn with density (n + 1) / (2 pi) cos^n(theta_h), turned into a density
 * of wi by 1 / (4 wo.h) (Walter et al. 2007, eq. 14; Pharr, Jakob & Humphreys, PBRT 3rd
 * ed. sec. 14.1). The specular lobe is chosen with probability ks. Wood's reflection is
 * sampled by its diffuse (cosine) part alone. */
#include <math.h>

#include "render/render_internal.h"
#include "render/sampling.h"

static float specular_probability(const sk__shading *sh)
{
    return sh->material->brdf == SK__BRDF_WOOD ? 0.0f : sh->texel.specular;
}

/* Density of the Blinn-Phong lobe's sampler for wi (0 below the shading horizon). */
static float lobe_pdf(const sk__shading *sh, sk_vec3f wi)
{
    sk_vec3f h = sk_v3f_add(wi, sh->to_viewer);
    float len = sk_v3f_length(h);
    if (!(len > 0)) return 0.0f;
    h = sk_v3f_scale(h, 1.0f / len);
    float nh = sk_v3f_dot(sh->shading_normal, h), oh = sk_v3f_dot(sh->to_viewer, h);
    if (nh <= 0 || oh <= 0) return 0.0f;
    float n = sh->texel.shininess;
    return (n + 1.0f) / (2.0f * SK_PI_F) * powf(nh, n) / (4.0f * oh);
}

float sk__material_pdf(const sk__shading *sh, sk_vec3f wi)
{
    float cos_i = sk_v3f_dot(sh->shading_normal, wi);
    if (cos_i <= 0) return 0.0f;
    float ps = specular_probability(sh);
    float pdf = (1.0f - ps) * cos_i / SK_PI_F;
    if (ps > 0) pdf += ps * lobe_pdf(sh, wi);
    return pdf;
}

bool sk__material_sample(const sk__shading *sh, sk_vec2f u, float u_lobe, sk_vec3f *wi, float *pdf)
{
    sk_vec3f n = sh->shading_normal;
    float ps = specular_probability(sh);
    if (u_lobe < ps) {
        float e = sh->texel.shininess;
        float cos_h = powf(u.x, 1.0f / (e + 1.0f));
        float sin_h = sqrtf(fmaxf(0.0f, 1.0f - cos_h * cos_h)), phi = 2.0f * SK_PI_F * u.y;
        sk_vec3f t, b;
        sk_v3f_basis(n, &t, &b);
        sk_vec3f h =
            sk_v3f_add(sk_v3f_scale(n, cos_h), sk_v3f_add(sk_v3f_scale(t, sin_h * cosf(phi)),
                                                          sk_v3f_scale(b, sin_h * sinf(phi))));
        sk_vec3f wo = sh->to_viewer;
        *wi = sk_v3f_sub(sk_v3f_scale(h, 2.0f * sk_v3f_dot(wo, h)), wo);
    } else {
        *wi = sk__cosine_hemisphere(n, u);
    }
    *pdf = sk__material_pdf(sh, *wi);
    return *pdf > 0;
}
