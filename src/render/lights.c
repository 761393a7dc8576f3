/* Lights: directional (irradiance E), point (intensity I), one-sided rectangles
 * (radiance Le, sampled uniformly by area for soft shadows), spheres and discs (radiance
 * Le, sampled by area_lights.c). A sample returns the
 * incident light already divided by its sampling density, so the reflected radiance is
 * f cos(theta_i) times that weight. */
#include <math.h>

#include "render/render_internal.h"

/* The unit normal of a rect or disc (towards `direction`, or the target) and its edges:
 * full-length for a rect, unit for a disc. */
static void facing_frame(const sk_render_light_desc *d, sk_vec3f target, sk__light *l)
{
    sk_vec3f n =
        sk__v3f_is_zero(d->direction) ? sk_v3f_sub(target, l->position) : sk_v3f_load(d->direction);
    n = sk_v3f_normalize(n);
    if (sk_v3f_dot(n, n) == 0) n = sk_v3f(0, -1, 0);
    sk_vec3f up = sk_v3f_load(d->up);
    sk_vec3f ev = sk_v3f_sub(up, sk_v3f_scale(n, sk_v3f_dot(n, up)));
    if (sk_v3f_length(ev) < 1e-6f * sk_v3f_length(up)) {
        /* facing along `up`: take +z (or +x) as the height direction */
        up = fabsf(n.z) < 0.9f ? sk_v3f(0, 0, 1) : sk_v3f(1, 0, 0);
        ev = sk_v3f_sub(up, sk_v3f_scale(n, sk_v3f_dot(n, up)));
    }
    ev = sk_v3f_normalize(ev);
    sk_vec3f eu = sk_v3f_cross(ev, n);
    bool rect = d->type == SK_RENDER_LIGHT_RECT;
    l->direction = n;
    l->edge_u = rect ? sk_v3f_scale(eu, d->size[0]) : eu;
    l->edge_v = rect ? sk_v3f_scale(ev, d->size[1]) : ev;
}

void sk__lights_setup(sk_render_scene *scene)
{
    sk_vec3f target = sk_v3f_load(scene->desc.camera.target);
    scene->light_count = scene->desc.light_count;
    for (int i = 0; i < scene->light_count; i++) {
        sk_render_light_desc *d = &scene->desc.lights[i];
        sk__light *l = &scene->lights[i];
        l->type = d->type;
        l->position = sk_v3f_load(d->position);
        l->samples = sk__light_is_area(d->type) ? d->samples : 1;
        l->shadows = !d->no_shadows;
        float distance = sk_v3f_length(sk_v3f_sub(target, l->position));
        if (!(distance > 0)) distance = 1.0f;
        switch (d->type) {
        case SK_RENDER_LIGHT_POINT:
            if (d->intensity == 0) d->intensity = SK_PI_F * distance * distance;
            break;
        case SK_RENDER_LIGHT_RECT:
            facing_frame(d, target, l);
            l->area = d->size[0] * d->size[1];
            if (d->intensity == 0) d->intensity = SK_PI_F * distance * distance / l->area;
            break;
        case SK_RENDER_LIGHT_DISC:
        case SK_RENDER_LIGHT_SPHERE:
            if (d->type == SK_RENDER_LIGHT_DISC) facing_frame(d, target, l);
            l->radius = d->radius;
            l->area = SK_PI_F * d->radius * d->radius;
            if (d->intensity == 0) d->intensity = distance * distance / (d->radius * d->radius);
            break;
        default:
            l->direction = sk_v3f_normalize(sk_v3f_load(d->direction));
            if (d->intensity == 0) d->intensity = SK_PI_F;
            break;
        }
        l->power = sk_v3f_scale(sk_v3f_load(d->color), d->intensity);
    }
}

bool sk__light_sample(const sk__light *l, sk_vec3f p, sk_vec2f u, sk_vec3f *wi, float *dist,
                      sk_vec3f *weight)
{
    if (l->type == SK_RENDER_LIGHT_DIRECTIONAL) {
        *wi = sk_v3f_neg(l->direction);
        *dist = INFINITY;
        *weight = l->power;
        return true;
    }
    if (l->type == SK_RENDER_LIGHT_SPHERE || l->type == SK_RENDER_LIGHT_DISC) {
        float pdf;
        if (!sk__area_light_sample(l, p, u, wi, dist, &pdf)) return false;
        *weight = sk_v3f_scale(l->power, 1.0f / pdf);
        return true;
    }
    sk_vec3f q = l->position;
    if (l->type == SK_RENDER_LIGHT_RECT)
        q = sk_v3f_add(q, sk_v3f_add(sk_v3f_scale(l->edge_u, u.x - 0.5f),
                                     sk_v3f_scale(l->edge_v, u.y - 0.5f)));
    sk_vec3f d = sk_v3f_sub(q, p);
    float r2 = sk_v3f_dot(d, d);
    if (!(r2 > 0)) return false;
    float r = sqrtf(r2);
    *wi = sk_v3f_scale(d, 1.0f / r);
    *dist = r;
    if (l->type == SK_RENDER_LIGHT_POINT) {
        *weight = sk_v3f_scale(l->power, 1.0f / r2);
        return true;
    }
    /* area sampling: pdf 1/A over the rectangle, dA -> d(omega) by cos(theta_l) / r^2 */
    float cos_l = -sk_v3f_dot(l->direction, *wi);
    if (cos_l <= 0) return false;
    *weight = sk_v3f_scale(l->power, cos_l * l->area / r2);
    return true;
}
