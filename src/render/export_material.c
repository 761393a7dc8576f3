/* The renderer's materials approximated for other tools (glTF metallic-roughness, MTL):
 * the diffuse part of the Blinn-Phong model as base colour, its exponent as roughness,
 * image textures and normal maps as they are, the skin microrelief (Ishii 1991) as a
 * normal texture of one periodic skin tile, the wood (Kawai 2000) by its diffuse weight
 * (its albedo is baked per object in export_bake.c). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "render/export_internal.h"

float sk__export_roughness(float ks, float n)
{
    if (!(ks > 0.0f)) return 1.0f;
    return powf(2.0f / (n + 2.0f), 0.25f);
}

void sk__export_material_fold_factor(sk__export_material *m)
{
    sk_image *t = &m->base_texture;
    if (!t->data) return;
    size_t n = (size_t)t->width * (size_t)t->height;
    for (size_t i = 0; i < n; i++)
        for (int c = 0; c < 3; c++) t->data[3 * i + (size_t)c] *= m->base_color[c];
    m->base_color[0] = m->base_color[1] = m->base_color[2] = 1.0f;
}

void sk__export_material_free(sk__export_material *m)
{
    sk_image_free(&m->base_texture);
    sk_image_free(&m->normal_texture);
}

/* An image texture as RGB in [0, 1] (grey replicated, alpha dropped: the renderer reads
 * only the colour), or with `normal` the components 2 c - 1 of a normal map's codes. */
static sk_result texture_rgb(const sk_image *src, bool normal, sk_image *dst, sk_error *err)
{
    sk_result r = sk_image_create(dst, src->width, src->height, 3, err);
    if (r != SK_OK) return r;
    size_t n = (size_t)src->width * (size_t)src->height;
    for (size_t i = 0; i < n; i++) {
        const float *p = src->data + i * (size_t)src->channels;
        for (int c = 0; c < 3; c++) {
            float v = src->channels >= 3 ? p[c] : p[0];
            v = sk_clampf(v, 0.0f, 1.0f); /* also EXR values above 1 */
            dst->data[3 * i + (size_t)c] = normal ? 2.0f * v - 1.0f : v;
        }
    }
    return SK_OK;
}

/* One tile of the skin's normals, size x size pixels (rows top first, +y up the tile). */
static sk_result skin_normal_tile(const sk_skin *skin, int size, sk_image *out, sk_error *err)
{
    sk_result r = sk_image_create(out, size, size, 3, err);
    if (r != SK_OK) return r;
    sk_skin_render_desc d = {.width = size, .height = size, .normal = out->data};
    if ((r = sk_skin_render(skin, &d, err)) != SK_OK) sk_image_free(out);
    return r;
}

static bool skin_has_tile(const sk__material *m, bool textures)
{
    return textures && m->skin && !sk_skin_get_desc(m->skin)->aperiodic;
}

void sk__export_material_uv_frame(const sk_render_scene *scene, int index, bool textures,
                                  float scale[2], float offset[2])
{
    const sk__material *m = &scene->materials[index];
    const sk_render_material_desc *d = &m->desc;
    scale[0] = scale[1] = 1.0f;
    offset[0] = offset[1] = 0.0f;
    bool textured = textures && (m->albedo_texture >= 0 || m->normal_map >= 0);
    if (!textured && !skin_has_tile(m, textures)) return; /* the mesh's own uvs */
    double tw = 1.0, th = 1.0;
    if (m->skin && skin_has_tile(m, textures)) sk_skin_tile_size(m->skin, &tw, &th);
    scale[0] = (float)(d->uv_scale[0] / tw), scale[1] = (float)(d->uv_scale[1] / th);
    offset[0] = (float)(d->uv_offset[0] / tw), offset[1] = (float)(d->uv_offset[1] / th);
}

sk_result sk__export_material_make(const sk_render_scene *scene, int index, bool textures,
                                   int texture_size, sk__export_material *out, sk_error *err)
{
    const sk__material *m = &scene->materials[index];
    const sk_render_material_desc *d = &m->desc;
    memset(out, 0, sizeof *out);
    snprintf(out->name, sizeof out->name, "%s", d->name[0] ? d->name : "default");
    out->normal_scale = d->bump_scale;
    float diffuse = 1.0f - d->specular;
    out->roughness = sk__export_roughness(d->specular, d->shininess);
    if (m->wood) {
        const sk_wood_shading_desc *sh = &sk_wood_get_desc(m->wood)->shading;
        diffuse = m->wood_kd;
        out->roughness = sh->model == SK_WOOD_SHADING_FIBRE
                             ? sk__export_roughness(1.0f, sh->finish_exponent)
                             : sk__export_roughness(sh->specular, sh->exponent);
        for (int c = 0; c < 3; c++) out->base_color[c] = diffuse; /* times the baked albedo */
        return SK_OK;
    }
    for (int c = 0; c < 3; c++) out->base_color[c] = sk_clampf(diffuse * d->albedo[c], 0.0f, 1.0f);
    sk_result r = SK_OK;
    if (textures && m->albedo_texture >= 0 && !m->skin)
        r = texture_rgb(&scene->textures[m->albedo_texture].image, false, &out->base_texture, err);
    if (r == SK_OK && textures && m->normal_map >= 0 && !m->skin &&
        scene->textures[m->normal_map].image.channels >= 3)
        r = texture_rgb(&scene->textures[m->normal_map].image, true, &out->normal_texture, err);
    if (r == SK_OK && m->skin) {
        /* an albedo texture would need uvs of its own next to the skin tile's: its mean
           colour joins the factor instead */
        if (m->albedo_texture >= 0) {
            const sk_image *t = &scene->textures[m->albedo_texture].image;
            size_t n = (size_t)t->width * (size_t)t->height;
            for (int c = 0; c < 3; c++) {
                double sum = 0.0;
                for (size_t i = 0; i < n; i++)
                    sum += t->data[i * (size_t)t->channels + (size_t)(t->channels >= 3 ? c : 0)];
                out->base_color[c] =
                    sk_clampf(out->base_color[c] * (float)(sum / (double)n), 0.0f, 1.0f);
            }
        }
        if (skin_has_tile(m, textures))
            r = skin_normal_tile(m->skin, texture_size, &out->normal_texture, err);
    }
    if (r != SK_OK) {
        sk__export_material_free(out);
        return sk_error_prefix(err, r, "materials[%d] (\"%s\")", index, out->name);
    }
    sk__export_material_fold_factor(out);
    return SK_OK;
}
