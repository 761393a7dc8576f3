/* The light transport of one camera sample: the radiance leaving the first surface hit
 * towards the camera from direct light (each light sampled, with a shadow ray) plus the
 * uniform environment (unoccluded, or weighted by cosine-distributed occlusion rays).
 * No interreflection: this is a direct-lighting (Whitted-style, without mirror and
 * refraction rays) renderer. Samples of area lights and occlusion rays are stratified
 * across the pixel's camera samples. */
#include <math.h>

#include "render/integrator.h"
#include "render/ray_offset.h"
#include "render/sampling.h"

/* Direct light from every light source. */
static sk_vec3f direct_light(const sk_render_scene *scene, sk__worker *w, const sk__shading *sh,
                             const sk__sample_id *id)
{
    sk_vec3f sum = sk_v3f(0, 0, 0);
    sk_vec3f p = sh->surface.point, ng = sh->geometric_normal;
    for (int li = 0; li < scene->light_count; li++) {
        const sk__light *l = &scene->lights[li];
        uint32_t n = (uint32_t)l->samples;
        sk_vec3f light_sum = sk_v3f(0, 0, 0);
        for (uint32_t j = 0; j < n; j++) {
            sk_vec2f u = sk__light_is_area(l->type)
                             ? sk__pattern_point(&id->lights[li], id->sample * n + j)
                             : sk_v2f(0.5f, 0.5f);
            sk_vec3f wi, weight;
            float dist;
            if (!sk__light_sample(l, p, u, &wi, &dist, &weight)) continue;
            float cos_g = sk_v3f_dot(ng, wi);
            if (cos_g <= 0) continue; /* behind the actual surface */
            sk_vec3f f = sk_v3f_scale(sk__material_reflect(sh, wi),
                                      sk__terminator_fade(cos_g, sh->shading_normal, ng));
            if (f.x == 0 && f.y == 0 && f.z == 0) continue;
            if (l->shadows) {
                sk_vec3f o = sk__offset_origin(p, ng, wi);
                float tfar = isinf(dist) ? INFINITY : dist * (1.0f - 1e-4f);
                if (sk__worker_occluded(scene, w, o, wi, tfar)) continue;
            }
            light_sum = sk_v3f_add(light_sum, sk_v3f_mul(f, weight));
        }
        sum = sk_v3f_add(sum, sk_v3f_scale(light_sum, 1.0f / (float)n));
    }
    return sum;
}

/* The uniform environment: albedo L_env times the visible fraction of the hemisphere. */
static sk_vec3f environment_light(const sk_render_scene *scene, sk__worker *w,
                                  const sk__shading *sh, const sk__sample_id *id)
{
    const sk_render_environment_desc *env = &scene->desc.environment;
    sk_vec3f radiance = scene->env.uniform; /* a map's or sky's mean radiance */
    if (radiance.x == 0 && radiance.y == 0 && radiance.z == 0) return radiance;
    float visible = 1.0f;
    if (env->ambient_occlusion) {
        uint32_t n = (uint32_t)env->ao_samples;
        float tfar = env->ao_distance > 0 ? env->ao_distance : INFINITY;
        sk_vec3f p = sh->surface.point, ng = sh->geometric_normal;
        uint32_t open = 0;
        for (uint32_t k = 0; k < n; k++) {
            sk_vec2f u = sk__pattern_point(&id->ao, id->sample * n + k);
            sk_vec3f d = sk__cosine_hemisphere(sh->shading_normal, u);
            if (sk_v3f_dot(d, ng) <= 0) continue; /* into the surface itself */
            if (!sk__worker_occluded(scene, w, sk__offset_origin(p, ng, d), d, tfar)) open++;
        }
        visible = (float)open / (float)n;
    }
    return sk_v3f_scale(sk_v3f_mul(sk__material_ambient_albedo(sh), radiance), visible);
}

void sk__sample_id_init(const sk_render_scene *scene, uint64_t pixel, sk__sample_id *id)
{
    const sk_render_scene_desc *d = &scene->desc;
    uint32_t spp = (uint32_t)d->image.samples;
    id->sample = 0;
    if (d->environment.ambient_occlusion)
        id->ao = sk__pattern_make(d->seed, pixel, SK__SAMPLE_AO,
                                  spp * (uint32_t)d->environment.ao_samples);
    for (int li = 0; li < scene->light_count; li++)
        if (sk__light_is_area(scene->lights[li].type))
            id->lights[li] = sk__pattern_make(d->seed, pixel, SK__SAMPLE_LIGHT + (uint32_t)li,
                                              spp * (uint32_t)scene->lights[li].samples);
}

float sk__camera_sample(const sk_render_scene *scene, sk__worker *w, const sk__sample_id *id,
                        float x, float y, sk_vec3f *radiance)
{
    sk_vec3f o, d;
    sk__camera_ray(&scene->camera, x, y, &o, &d);
    struct RTCRayHit rh;
    sk__rtc_ray(&rh.ray, o, d, 0.0f, INFINITY);
    if (!sk__worker_trace(scene, w, &rh)) {
        const sk_render_film_desc *film = &scene->desc.film;
        *radiance = film->opaque ? sk_v3f_load(film->background) : sk_v3f(0, 0, 0);
        return film->opaque ? 1.0f : 0.0f;
    }
    sk__shading sh;
    sk__geometry_hit(scene, rh.hit.instID[0], rh.hit.primID, rh.hit.u, rh.hit.v, &sh);
    sk__shading_face(&sh, d);
    sh.surface.footprint_mm = sk__camera_footprint(&scene->camera, rh.ray.tfar) *
                              scene->desc.unit_mm / sqrtf((float)scene->desc.image.samples);
    sk__material_eval(scene, &sh);
    sk_vec3f L = sk_v3f_add(direct_light(scene, w, &sh, id), environment_light(scene, w, &sh, id));
    const sk_render_material_desc *m = &sh.material->desc;
    if (m->texture_weight > 0) {
        float tw = m->texture_weight;
        L = sk_v3f_add(sk_v3f_scale(L, 1.0f - tw),
                       sk_v3f_scale(sh.texture_color, tw * m->texture_radiance));
    }
    *radiance = L;
    return 1.0f;
}
