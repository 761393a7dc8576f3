/* Area lights for the path integrator and the preview: one-sided rectangles and discs
 * (sampled uniformly by area, the density turned into solid angle by r^2 / cos(theta_l))
 * and spheres (sampled uniformly in the cone they subtend, Pharr, Jakob & Humphreys,
 * PBRT 3rd ed. sec. 14.2.2). Each also answers where a ray hits it and the solid-angle
 * density its sampler gives that direction, for multiple importance sampling. Emitted
 * radiance is the light's power (color * intensity), constant over the surface. */
#include <math.h>

#include "render/render_internal.h"
#include "render/sampling.h"

/* Point on a rectangle or disc for the uniform square sample u. */
static sk_vec3f flat_point(const sk__light *l, sk_vec2f u)
{
    if (l->type == SK_RENDER_LIGHT_RECT)
        return sk_v3f_add(l->position, sk_v3f_add(sk_v3f_scale(l->edge_u, u.x - 0.5f),
                                                  sk_v3f_scale(l->edge_v, u.y - 0.5f)));
    sk_vec2f d = sk__square_to_disk(u);
    return sk_v3f_add(l->position, sk_v3f_add(sk_v3f_scale(l->edge_u, d.x * l->radius),
                                              sk_v3f_scale(l->edge_v, d.y * l->radius)));
}

/* sin^2 and 1 - cos of the half angle of the cone a sphere subtends from distance^2 d2. */
static float cone_one_minus_cos(float r2, float d2)
{
    float s2 = r2 / d2;
    return s2 / (1.0f + sqrtf(fmaxf(0.0f, 1.0f - s2)));
}

bool sk__area_light_sample(const sk__light *l, sk_vec3f p, sk_vec2f u, sk_vec3f *wi, float *dist,
                           float *pdf)
{
    if (l->type == SK_RENDER_LIGHT_SPHERE) {
        sk_vec3f c = sk_v3f_sub(l->position, p);
        float d2 = sk_v3f_dot(c, c), r2 = l->radius * l->radius;
        if (!(d2 > r2)) return false; /* inside the sphere: no light from this sampler */
        float d = sqrtf(d2);
        sk_vec3f w = sk_v3f_scale(c, 1.0f / d);
        float omc = cone_one_minus_cos(r2, d2);
        float one_minus = u.x * omc; /* 1 - cos(theta), uniform in the cone */
        float cos_t = 1.0f - one_minus;
        float sin_t = sqrtf(fmaxf(0.0f, one_minus * (2.0f - one_minus)));
        float phi = 2.0f * SK_PI_F * u.y;
        sk_vec3f t, b;
        sk_v3f_basis(w, &t, &b);
        *wi = sk_v3f_normalize(
            sk_v3f_add(sk_v3f_scale(w, cos_t), sk_v3f_add(sk_v3f_scale(t, sin_t * cosf(phi)),
                                                          sk_v3f_scale(b, sin_t * sinf(phi)))));
        /* nearest intersection along wi: d cos - sqrt(r^2 - d^2 sin^2) */
        float proj = d * cos_t, disc = r2 - d2 * (1.0f - cos_t * cos_t);
        *dist = fmaxf(0.0f, proj - sqrtf(fmaxf(0.0f, disc)));
        *pdf = 1.0f / (2.0f * SK_PI_F * omc);
        return true;
    }
    sk_vec3f q = flat_point(l, u);
    sk_vec3f dv = sk_v3f_sub(q, p);
    float r2 = sk_v3f_dot(dv, dv);
    if (!(r2 > 0)) return false;
    float r = sqrtf(r2);
    *wi = sk_v3f_scale(dv, 1.0f / r);
    float cos_l = -sk_v3f_dot(l->direction, *wi);
    if (cos_l <= 0) return false; /* its back: rects and discs emit from the front only */
    *dist = r;
    *pdf = r2 / (l->area * cos_l);
    return true;
}

float sk__area_light_pdf(const sk__light *l, sk_vec3f p, sk_vec3f wi, float t)
{
    if (l->type == SK_RENDER_LIGHT_SPHERE) {
        sk_vec3f c = sk_v3f_sub(l->position, p);
        float d2 = sk_v3f_dot(c, c), r2 = l->radius * l->radius;
        if (!(d2 > r2)) return 0.0f;
        return 1.0f / (2.0f * SK_PI_F * cone_one_minus_cos(r2, d2));
    }
    float cos_l = -sk_v3f_dot(l->direction, wi);
    if (cos_l <= 0) return 0.0f;
    return t * t / (l->area * cos_l);
}

bool sk__area_light_hit(const sk__light *l, sk_vec3f o, sk_vec3f d, float tmax, float *t)
{
    if (l->type == SK_RENDER_LIGHT_SPHERE) {
        sk_vec3f oc = sk_v3f_sub(o, l->position);
        float b = sk_v3f_dot(oc, d), c = sk_v3f_dot(oc, oc) - l->radius * l->radius;
        if (c <= 0) return false; /* from inside: the sphere emits outwards only */
        float disc = b * b - c;
        if (disc < 0 || b > 0) return false;
        float th = -b - sqrtf(disc);
        if (!(th > 0 && th < tmax)) return false;
        *t = th;
        return true;
    }
    float dn = sk_v3f_dot(d, l->direction);
    if (dn >= 0) return false; /* parallel or arriving at the back */
    float th = sk_v3f_dot(sk_v3f_sub(l->position, o), l->direction) / dn;
    if (!(th > 0 && th < tmax)) return false;
    sk_vec3f q = sk_v3f_sub(sk_v3f_add(o, sk_v3f_scale(d, th)), l->position);
    float a = sk_v3f_dot(q, l->edge_u), bb = sk_v3f_dot(q, l->edge_v);
    if (l->type == SK_RENDER_LIGHT_RECT) {
        /* edges are full-length vectors: |q . e| <= |e|^2 / 2 */
        if (fabsf(a) > 0.5f * sk_v3f_dot(l->edge_u, l->edge_u) ||
            fabsf(bb) > 0.5f * sk_v3f_dot(l->edge_v, l->edge_v))
            return false;
    } else if (a * a + bb * bb > l->radius * l->radius) {
        return false; /* disc: unit edges */
    }
    *t = th;
    return true;
}
