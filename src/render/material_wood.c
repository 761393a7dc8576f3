/* The wood material: Kawai 2000's solid texture evaluated at the shading point in the
 * object's frame (mm), lit by the wood module's own reflection model. sk_wood_shade gives
 * the radiance reflected for an irradiance of pi at normal incidence (eq. (4) read with
 * L_I the radiance of a white diffuser under the light, so kd = 1 is Lambertian), so
 * f cos(theta_i) is that value divided by pi. Its diffuse term uses the true normal and
 * its sheen the normal tilted by the fibre's dive angle (sec. 7.3). */
#include <math.h>

#include "render/render_internal.h"

sk_result sk__wood_material_build(sk__material *m, int index, sk_error *err)
{
    if (m->desc.wood_tree) {
        m->wood = m->desc.wood_tree;
    } else {
        sk_result r = sk_wood_create(&m->desc.wood, &m->owned_wood, err);
        if (r != SK_OK) return sk_error_prefix(err, r, "materials[%d].wood", index);
        m->wood = m->owned_wood;
    }
    m->brdf = SK__BRDF_WOOD;
    m->wood_kd = sk_wood_get_desc(m->wood)->shading.diffuse;
    return SK_OK;
}

void sk__wood_material_destroy(sk__material *m)
{
    if (m->owned_wood) sk_wood_destroy(m->owned_wood);
    m->owned_wood = NULL;
    m->wood = NULL;
}

void sk__wood_material_texel(const sk_render_scene *scene, sk__shading *sh)
{
    const sk_render_surface *s = &sh->surface;
    float mm = scene->desc.unit_mm;
    sk_vec3f p = sk_v3f_scale(s->object_point, mm);
    sk_wood_eval_filtered(sh->material->wood, p, s->object_normal, s->footprint_mm, &sh->wood);
    sh->texel.albedo = sh->wood.albedo;
}

sk_vec3f sk__wood_material_reflect(const sk__shading *sh, sk_vec3f wi)
{
    if (sk_v3f_dot(sh->shading_normal, wi) <= 0) return sk_v3f(0, 0, 0);
    /* into the object frame, where the wood sample's fibre and up vectors live */
    sk_mat3f unrotate = sk_m3f_transpose(sh->instance->rotation);
    sk_vec3f n = sk_m3f_apply(unrotate, sh->shading_normal);
    sk_vec3f l = sk_m3f_apply(unrotate, wi);
    sk_vec3f v = sk_m3f_apply(unrotate, sh->to_viewer);
    sk_vec3f r = sk_wood_shade(sh->material->wood, &sh->wood, n, l, v);
    return sk_v3f_scale(r, 1.0f / SK_PI_F);
}
