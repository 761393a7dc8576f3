/* Materials: albedo from a constant, an image texture by UV or a procedural callback;
 * bump mapping from height gradients in texture space and from tangent-space normal maps;
 * and the reflectance, Lambertian diffuse plus an energy-normalised Blinn-Phong lobe:
 *   f(wi, wo) = (1 - ks) albedo / pi + ks K(n) (N.H)^n,
 *   K(n) = (n + 2) (n + 4) / (8 pi (n + 2^(-n/2)))
 * K(n) makes the lobe's directional albedo exactly 1 at normal incidence (integrate
 * cos^n(theta/2) cos(theta) over the hemisphere); away from it the albedo falls as the lobe
 * dips under the horizon. So with albedo <= 1 the surface never reflects more light than
 * it receives (tested numerically). The common approximation (n + 8) / (8 pi) exceeds 1
 * by 2 % at n = 1. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "render/render_internal.h"

/* Sets *index to the texture loaded from `name` (loading it on first use). */
static sk_result texture_index(sk_render_scene *scene, const char *name, bool srgb, int *index,
                               sk_error *err)
{
    for (int i = 0; i < scene->texture_count; i++)
        if (strcmp(scene->textures[i].name, name) == 0 && scene->textures[i].srgb == srgb) {
            *index = i;
            return SK_OK;
        }
    char path[2 * SK_RENDER_PATH_SIZE];
    sk__join_path(scene->desc.base_dir, name, path, sizeof path);
    sk__texture *tex = &scene->textures[scene->texture_count];
    sk_result r = sk__texture_load(tex, path, srgb, err);
    if (r != SK_OK) return r;
    snprintf(tex->name, sizeof tex->name, "%s", name);
    tex->srgb = srgb;
    *index = scene->texture_count++;
    return SK_OK;
}

/* Sets *index to a new texture entry that borrows the caller's image. */
static void borrowed_texture(sk_render_scene *scene, const sk_image *image, int *index)
{
    sk__texture *tex = &scene->textures[scene->texture_count];
    memset(tex, 0, sizeof *tex);
    tex->image = *image;
    tex->borrowed = true;
    *index = scene->texture_count++;
}

sk_result sk__materials_build(sk_render_scene *scene, sk_error *err)
{
    const sk_render_scene_desc *d = &scene->desc;
    int max_textures = 2 * d->material_count;
    size_t texture_slots = (size_t)(max_textures > 0 ? max_textures : 1);
    scene->textures = calloc(texture_slots, sizeof *scene->textures);
    if (!scene->textures) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for textures");
    sk_result r = SK_OK;
    for (int i = 0; i < d->material_count && r == SK_OK; i++) {
        sk__material *m = &scene->materials[i];
        scene->material_count = i + 1; /* so that a failure destroys what was built */
        m->desc = d->materials[i];
        m->brdf = SK__BRDF_BLINN_PHONG;
        m->albedo_texture = m->normal_map = -1;
        if (m->desc.albedo_image)
            borrowed_texture(scene, m->desc.albedo_image, &m->albedo_texture);
        else if (m->desc.albedo_texture[0] &&
                 (r = texture_index(scene, m->desc.albedo_texture, true, &m->albedo_texture,
                                    err)) != SK_OK)
            sk_error_prefix(err, r, "materials[%d].albedo_texture = \"%s\"", i,
                            m->desc.albedo_texture);
        if (r == SK_OK && m->desc.normal_image)
            borrowed_texture(scene, m->desc.normal_image, &m->normal_map);
        else if (r == SK_OK && m->desc.normal_map[0] &&
                 (r = texture_index(scene, m->desc.normal_map, false, &m->normal_map, err)) !=
                     SK_OK)
            sk_error_prefix(err, r, "materials[%d].normal_map = \"%s\"", i, m->desc.normal_map);
        if (r == SK_OK && m->desc.type == SK_RENDER_MATERIAL_SKIN)
            r = sk__skin_material_build(m, i, err);
        if (r == SK_OK && m->desc.type == SK_RENDER_MATERIAL_WOOD)
            r = sk__wood_material_build(m, i, err);
    }
    if (r != SK_OK) return r;
    /* the default material of objects without one: grey diffuse */
    sk__material *def = &scene->materials[d->material_count];
    memset(def, 0, sizeof *def);
    sk__material_desc_resolve(&def->desc);
    def->albedo_texture = def->normal_map = -1;
    scene->material_count = d->material_count + 1;
    return SK_OK;
}

void sk__materials_destroy(sk_render_scene *scene)
{
    for (int i = 0; i < scene->material_count; i++) {
        sk__skin_material_destroy(&scene->materials[i]);
        sk__wood_material_destroy(&scene->materials[i]);
    }
    for (int i = 0; i < scene->texture_count; i++)
        if (!scene->textures[i].borrowed) sk_image_free(&scene->textures[i].image);
    free(scene->textures);
}

void sk__material_eval(const sk_render_scene *scene, sk__shading *sh)
{
    const sk__material *m = sh->material;
    const sk_render_material_desc *d = &m->desc;
    sk_render_surface *s = &sh->surface;
    s->st = sk_v2f(s->uv.x * d->uv_scale[0] + d->uv_offset[0],
                   s->uv.y * d->uv_scale[1] + d->uv_offset[1]);
    float unit = scene->desc.unit_mm;
    s->st_per_mm = sk_v2f(sh->du_len > 0 ? d->uv_scale[0] / (sh->du_len * unit) : 0.0f,
                          sh->dv_len > 0 ? d->uv_scale[1] / (sh->dv_len * unit) : 0.0f);
    sk_render_texel *tx = &sh->texel;
    tx->albedo = sk_v3f_load(d->albedo);
    tx->specular = d->specular;
    tx->shininess = d->shininess;
    tx->slope = sk_v2f(0, 0);
    if (m->albedo_texture >= 0) {
        float c[4];
        sk__texture_sample(&scene->textures[m->albedo_texture], s->st, c);
        tx->albedo = sk_v3f_mul(tx->albedo, sk_v3f(c[0], c[1], c[2]));
    }
    /* surface slope (dimensionless) along tangent and bitangent */
    sk_vec2f tilt = sk_v2f(0, 0);
    if (m->normal_map >= 0) {
        float c[4];
        sk__texture_sample(&scene->textures[m->normal_map], s->st, c);
        float nx = 2 * c[0] - 1, ny = 2 * c[1] - 1, nz = 2 * c[2] - 1;
        if (nz > 1e-3f) tilt = sk_v2f(-nx / nz, -ny / nz);
    }
    if (m->skin) sk__skin_material_texel(m, s, tx);
    if (m->wood) sk__wood_material_texel(scene, sh);
    if (d->texture) d->texture(d->texture_user, s, tx);
    tilt.x += tx->slope.x * s->st_per_mm.x;
    tilt.y += tx->slope.y * s->st_per_mm.y;
    sk_vec3f n = s->normal;
    if (tilt.x != 0 || tilt.y != 0) {
        float k = d->bump_scale;
        n = sk_v3f_normalize(sk_v3f_sub(n, sk_v3f_add(sk_v3f_scale(s->tangent, k * tilt.x),
                                                      sk_v3f_scale(s->bitangent, k * tilt.y))));
        /* a bumped normal must still face the viewer, or the point would shade black */
        float facing = sk_v3f_dot(n, sh->to_viewer);
        const float min_facing = 0.01f;
        if (facing < min_facing)
            n = sk_v3f_normalize(sk_v3f_add(n, sk_v3f_scale(sh->to_viewer, min_facing - facing)));
    }
    sh->shading_normal = n;
    sh->lobe_norm = sk__blinn_phong_norm(tx->shininess);
    /* the hand thesis blend: shade a white surface, add the unlit texture afterwards */
    sh->texture_color = tx->albedo;
    if (d->texture_weight > 0) tx->albedo = sh->wood.albedo = sk_v3f(1, 1, 1);
}

float sk__blinn_phong_norm(float n)
{
    return (n + 2.0f) * (n + 4.0f) / (8.0f * SK_PI_F * (n + exp2f(-0.5f * n)));
}

sk_vec3f sk__material_reflect(const sk__shading *sh, sk_vec3f wi)
{
    if (sh->material->brdf == SK__BRDF_WOOD) return sk__wood_material_reflect(sh, wi);
    sk_vec3f n = sh->shading_normal;
    float cos_i = sk_v3f_dot(n, wi);
    if (cos_i <= 0) return sk_v3f(0, 0, 0);
    const sk_render_texel *tx = &sh->texel;
    float ks = tx->specular;
    sk_vec3f f = sk_v3f_scale(tx->albedo, (1.0f - ks) / SK_PI_F);
    if (ks > 0) {
        sk_vec3f h = sk_v3f_normalize(sk_v3f_add(wi, sh->to_viewer));
        float nh = sk_v3f_dot(n, h);
        if (nh > 0) {
            float e = tx->shininess;
            float lobe = ks * sh->lobe_norm * powf(nh, e);
            f = sk_v3f_add(f, sk_v3f(lobe, lobe, lobe));
        }
    }
    return sk_v3f_scale(f, cos_i);
}

sk_vec3f sk__material_ambient_albedo(const sk__shading *sh)
{
    const sk_render_texel *tx = &sh->texel;
    if (sh->material->brdf == SK__BRDF_WOOD) return sk_v3f_scale(tx->albedo, sh->material->wood_kd);
    float ks = tx->specular;
    sk_vec3f a = sk_v3f_scale(tx->albedo, 1.0f - ks);
    return sk_v3f_add(a, sk_v3f(ks, ks, ks));
}
