/* The path integrator: unidirectional path tracing (Kajiya 1986) with next-event
 * estimation at every vertex (one sample of every light and of the environment) combined
 * with BSDF sampling by multiple importance sampling, power heuristic beta = 2 (Veach
 * 1997, ch. 9, eq. 9.13), and Russian roulette after the third vertex (Arvo & Kirk
 * 1990). Point and directional lights are sampled alone (no BSDF ray can find them), with
 * the preview's terminator fade. Area lights are not scene geometry: a ray passing one
 * collects its radiance and goes on, and shadow rays do not see them, so both strategies
 * estimate the same integral. Every random number comes from the scrambled Sobol pairs of
 * sequence.h keyed by (seed, pixel, sample, vertex, use). */
#include <math.h>

#include "render/integrator.h"
#include "render/ray_offset.h"
#include "render/sequence.h"

/* Dimension pairs per vertex: BSDF direction, (lobe, roulette), environment, lights. */
enum { PAIR_BSDF = 0, PAIR_LOBE = 1, PAIR_ENV = 2, PAIR_LIGHT = 3 };
#define PAIRS_PER_VERTEX (PAIR_LIGHT + SK_RENDER_MAX_LIGHTS)
#define ROULETTE_START 3

typedef struct path_ctx {
    const sk_render_scene *scene;
    sk__worker *w;
    uint64_t seed, pixel;
    uint32_t sample;
    bool nee; /* sample area lights and the environment (false: BSDF sampling alone) */
} path_ctx;

static sk_vec2f dims(const path_ctx *c, int vertex, int use)
{
    return sk__sobol_pair(c->seed, c->pixel, c->sample,
                          1u + (uint32_t)(vertex * PAIRS_PER_VERTEX + use));
}

/* Veach's power heuristic for the strategy of density a against b. */
static float power_heuristic(float a, float b)
{
    if (isinf(a)) return 1.0f;
    float a2 = a * a, b2 = b * b;
    return a2 + b2 > 0 ? a2 / (a2 + b2) : 0.0f;
}

static bool is_black(sk_vec3f v) { return v.x == 0 && v.y == 0 && v.z == 0; }

static float max3(sk_vec3f v) { return fmaxf(v.x, fmaxf(v.y, v.z)); }

/* Light of one point or directional light (a delta light: light sampling alone). */
static sk_vec3f delta_light(const path_ctx *c, const sk__light *l, const sk__shading *sh)
{
    sk_vec3f wi, weight;
    float dist;
    sk_vec3f p = sh->surface.point, ng = sh->geometric_normal;
    if (!sk__light_sample(l, p, sk_v2f(0.5f, 0.5f), &wi, &dist, &weight)) return sk_v3f(0, 0, 0);
    float cos_g = sk_v3f_dot(ng, wi);
    if (cos_g <= 0) return sk_v3f(0, 0, 0);
    sk_vec3f f = sk_v3f_scale(sk__material_reflect(sh, wi),
                              sk__terminator_fade(cos_g, sh->shading_normal, ng));
    if (is_black(f)) return f;
    float tfar = isinf(dist) ? INFINITY : dist * (1.0f - 1e-4f);
    if (l->shadows && sk__worker_occluded(c->scene, c->w, sk__offset_origin(p, ng, wi), wi, tfar))
        return sk_v3f(0, 0, 0);
    return sk_v3f_mul(f, weight);
}

/* f cos / pdf times the MIS weight against BSDF sampling, for a light sample wi of
 * density pdf carrying radiance Le from distance dist; 0 if blocked. */
static sk_vec3f light_sample_term(const path_ctx *c, const sk__shading *sh, sk_vec3f wi, float dist,
                                  float pdf, sk_vec3f Le, bool shadows)
{
    sk_vec3f p = sh->surface.point, ng = sh->geometric_normal;
    if (!(pdf > 0) || sk_v3f_dot(ng, wi) <= 0) return sk_v3f(0, 0, 0);
    sk_vec3f f = sk__material_reflect(sh, wi);
    if (is_black(f) || is_black(Le)) return sk_v3f(0, 0, 0);
    float tfar = isinf(dist) ? INFINITY : dist * (1.0f - 1e-4f);
    if (shadows && sk__worker_occluded(c->scene, c->w, sk__offset_origin(p, ng, wi), wi, tfar))
        return sk_v3f(0, 0, 0);
    float weight = power_heuristic(pdf, sk__material_pdf(sh, wi)) / pdf;
    return sk_v3f_scale(sk_v3f_mul(f, Le), weight);
}

/* Next-event estimation at a vertex: every light once, and the environment. */
static sk_vec3f next_event(const path_ctx *c, const sk__shading *sh, int vertex)
{
    const sk_render_scene *scene = c->scene;
    sk_vec3f sum = sk_v3f(0, 0, 0);
    for (int li = 0; li < scene->light_count; li++) {
        const sk__light *l = &scene->lights[li];
        if (!sk__light_is_area(l->type)) {
            sum = sk_v3f_add(sum, delta_light(c, l, sh));
            continue;
        }
        if (!c->nee) continue;
        sk_vec3f wi;
        float dist, pdf;
        if (!sk__area_light_sample(l, sh->surface.point, dims(c, vertex, PAIR_LIGHT + li), &wi,
                                   &dist, &pdf))
            continue;
        sum = sk_v3f_add(sum, light_sample_term(c, sh, wi, dist, pdf, l->power, l->shadows));
    }
    const sk__environment *env = &scene->env;
    if (c->nee && !sk__environment_is_black(env)) {
        float pdf;
        sk_vec3f wi = sk__environment_sample(env, dims(c, vertex, PAIR_ENV), &pdf);
        sum = sk_v3f_add(
            sum, light_sample_term(c, sh, wi, INFINITY, pdf, sk__environment_eval(env, wi), true));
    }
    return sum;
}

/* Radiance of the area lights the ray o + t d passes before t_max, each weighted against
 * its light sampler from the previous vertex (pdf_bsdf 0: a camera ray, weight 1). */
static sk_vec3f emitters_on_ray(const path_ctx *c, sk_vec3f o, sk_vec3f d, float t_max,
                                float pdf_bsdf)
{
    const sk_render_scene *scene = c->scene;
    sk_vec3f sum = sk_v3f(0, 0, 0);
    for (int li = 0; li < scene->light_count; li++) {
        const sk__light *l = &scene->lights[li];
        float t;
        if (!sk__area_light_hit(l, o, d, t_max, &t)) continue;
        float weight = 1.0f;
        if (c->nee && pdf_bsdf > 0)
            weight = power_heuristic(pdf_bsdf, sk__area_light_pdf(l, o, d, t));
        sum = sk_v3f_add(sum, sk_v3f_scale(l->power, weight));
    }
    return sum;
}

/* The shading record of a hit, with the preview's footprint at path length `length`. */
static void shade_hit(const path_ctx *c, const struct RTCRayHit *rh, sk_vec3f d, float length,
                      int vertex, sk__shading *sh)
{
    const sk_render_scene *scene = c->scene;
    sk__geometry_hit(scene, rh->hit.instID[0], rh->hit.primID, rh->hit.u, rh->hit.v, sh);
    sk__shading_face(sh, d);
    sh->surface.footprint_mm = sk__camera_footprint(&scene->camera, length) * scene->desc.unit_mm /
                               sqrtf((float)scene->desc.image.samples);
    sk__material_eval(scene, sh);
    /* the texture/shading blend holds at the camera's vertex; beyond it the surface
       reflects its texture colour */
    if (vertex > 0 && sh->material->desc.texture_weight > 0) sh->texel.albedo = sh->texture_color;
}

float sk__path_sample(const sk_render_scene *scene, sk__worker *w, uint64_t pixel, uint32_t sample,
                      float x, float y, sk_vec3f *radiance)
{
    const sk_render_scene_desc *desc = &scene->desc;
    path_ctx c = {scene, w,      desc->seed,
                  pixel, sample, desc->film.integrator != SK_RENDER_INTEGRATOR_PATH_BSDF};
    sk_vec3f o, d;
    sk__camera_ray(&scene->camera, x, y, &o, &d);
    sk_vec3f L = sk_v3f(0, 0, 0), beta = sk_v3f(1, 1, 1);
    float alpha = 0, pdf_bsdf = 0, length = 0;
    for (int vertex = 0;; vertex++) {
        struct RTCRayHit rh;
        sk__rtc_ray(&rh.ray, o, d, 0.0f, INFINITY);
        bool hit = sk__worker_trace(scene, w, &rh);
        float t_hit = hit ? rh.ray.tfar : INFINITY;
        sk_vec3f Le = emitters_on_ray(&c, o, d, t_hit, pdf_bsdf);
        if (!is_black(Le)) alpha = 1.0f;
        L = sk_v3f_add(L, sk_v3f_mul(beta, Le));
        if (!hit) {
            if (vertex == 0) {
                const sk_render_film_desc *film = &desc->film;
                if (film->opaque) L = sk_v3f_add(L, sk_v3f_load(film->background)), alpha = 1;
            } else if (!sk__environment_is_black(&scene->env)) {
                float weight =
                    c.nee ? power_heuristic(pdf_bsdf, sk__environment_pdf(&scene->env, d)) : 1.0f;
                sk_vec3f env = sk__environment_eval(&scene->env, d);
                L = sk_v3f_add(L, sk_v3f_scale(sk_v3f_mul(beta, env), weight));
            }
            break;
        }
        if (vertex == 0) alpha = 1.0f;
        length += t_hit;
        sk__shading sh;
        shade_hit(&c, &rh, d, length, vertex, &sh);
        if (vertex >= desc->film.max_bounces) break;
        float tw = sh.material->desc.texture_weight;
        if (vertex == 0 && tw > 0) {
            sk_vec3f tex = sk_v3f_scale(sh.texture_color, tw * sh.material->desc.texture_radiance);
            L = sk_v3f_add(L, tex);
            beta = sk_v3f_scale(beta, 1.0f - tw);
        }
        L = sk_v3f_add(L, sk_v3f_mul(beta, next_event(&c, &sh, vertex)));
        sk_vec2f lobe = dims(&c, vertex, PAIR_LOBE);
        sk_vec3f wi;
        if (!sk__material_sample(&sh, dims(&c, vertex, PAIR_BSDF), lobe.x, &wi, &pdf_bsdf)) break;
        sk_vec3f ng = sh.geometric_normal;
        if (sk_v3f_dot(ng, wi) <= 0) break; /* into the actual surface */
        sk_vec3f f = sk__material_reflect(&sh, wi);
        if (is_black(f)) break;
        beta = sk_v3f_mul(beta, sk_v3f_scale(f, 1.0f / pdf_bsdf));
        if (vertex + 1 >= ROULETTE_START) {
            float q = fminf(0.95f, max3(beta));
            if (!(lobe.y < q)) break;
            beta = sk_v3f_scale(beta, 1.0f / q);
        }
        o = sk__offset_origin(sh.surface.point, ng, wi);
        d = wi;
    }
    *radiance = L;
    return alpha;
}
