/* The glTF document being built: creation and destruction, growable object arrays,
 * materials (metallic-roughness, glTF 2.0 sec. 3.9) with their textures encoded as PNG
 * when added, and nodes with their TRS transforms (sec. 3.5). */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "formats/gltf_internal.h"
#include "base/image_internal.h"

sk_result sk__gltf_grow(void **data, int count, int *capacity, size_t elem, const char *what,
                        sk_error *err)
{
    if (count < *capacity) return SK_OK;
    if (count >= SK__GLTF_MAX_OBJECTS)
        return sk_fail(err, SK_ERROR_LIMIT, "a document holds at most %d %s", SK__GLTF_MAX_OBJECTS,
                       what);
    int next = *capacity ? 2 * *capacity : 8;
    if (next > SK__GLTF_MAX_OBJECTS) next = SK__GLTF_MAX_OBJECTS;
    void *grown = realloc(*data, (size_t)next * elem);
    if (!grown) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for %s", what);
    memset((char *)grown + (size_t)*capacity * elem, 0, (size_t)(next - *capacity) * elem);
    *data = grown;
    *capacity = next;
    return SK_OK;
}

char *sk__gltf_name(const char *name, const char *prefix, int index)
{
    if (name) return strdup(name);
    char buf[48];
    snprintf(buf, sizeof buf, "%s%d", prefix, index);
    return strdup(buf);
}

sk_result sk_gltf_create(sk_gltf **out, sk_error *err)
{
    if (!out) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "out is NULL");
    *out = calloc(1, sizeof **out);
    return *out ? SK_OK : sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
}

void sk_gltf_destroy(sk_gltf *gltf)
{
    if (!gltf) return;
    for (int i = 0; i < gltf->image_count; i++) free(gltf->images[i].png);
    for (int i = 0; i < gltf->material_count; i++) free(gltf->materials[i].name);
    for (int i = 0; i < gltf->mesh_count; i++) sk__gltf_mesh_free(&gltf->meshes[i]);
    for (int i = 0; i < gltf->node_count; i++) free(gltf->nodes[i].name);
    for (int i = 0; i < gltf->skin_count; i++) {
        free(gltf->skins[i].name);
        free(gltf->skins[i].joints);
        free(gltf->skins[i].inverse_bind);
    }
    for (int i = 0; i < gltf->animation_count; i++) sk__gltf_animation_free(&gltf->animations[i]);
    free(gltf->images);
    free(gltf->materials);
    free(gltf->meshes);
    free(gltf->nodes);
    free(gltf->skins);
    free(gltf->animations);
    free(gltf);
}

/* ------------------------------------------------------------- images */

/* Normal map components n in [-1, 1] as the codes 0.5 n + 0.5 (glTF 2.0 sec. 3.9.3). */
static sk_result normal_map_codes(const sk_image *src, const char *field, sk_image *dst,
                                  sk_error *err)
{
    if (src->channels != 3)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "%s has %d channels: a normal texture needs 3 (x, y, z)", field,
                       src->channels);
    sk_result r = sk_image_create(dst, src->width, src->height, 3, err);
    if (r != SK_OK) return r;
    size_t n = (size_t)src->width * (size_t)src->height * 3;
    for (size_t i = 0; i < n; i++) {
        float v = src->data[i];
        if (!(v >= -1.0f && v <= 1.0f)) {
            sk_image_free(dst);
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "%s: pixel (%zu, %zu) component %zu = %g is out of range [-1, 1]", field,
                           (i / 3) % (size_t)src->width, (i / 3) / (size_t)src->width, i % 3,
                           (double)v);
        }
        dst->data[i] = 0.5f * v + 0.5f;
    }
    return SK_OK;
}

static sk_result check_colour_texture(const sk_image *image, const char *field, sk_error *err)
{
    size_t n = (size_t)image->width * (size_t)image->height * (size_t)image->channels;
    for (size_t i = 0; i < n; i++)
        if (!(image->data[i] >= 0.0f && image->data[i] <= 1.0f)) {
            size_t px = i / (size_t)image->channels;
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "%s: pixel (%zu, %zu) channel %zu = %g is out of range [0, 1]", field,
                           px % (size_t)image->width, px / (size_t)image->width,
                           i % (size_t)image->channels, (double)image->data[i]);
        }
    return SK_OK;
}

sk_result sk__gltf_add_image(sk_gltf *gltf, const sk_image *image, bool normal_map,
                             const char *field, int *out_index, sk_error *err)
{
    sk_result r = sk__image_validate(image, err);
    if (r != SK_OK) return sk_error_prefix(err, r, "%s", field);
    r = sk__gltf_grow((void **)&gltf->images, gltf->image_count, &gltf->image_capacity,
                      sizeof *gltf->images, "images", err);
    if (r != SK_OK) return r;
    sk_image codes = {0};
    sk_png_write_desc png = {.encoding = SK_PNG_ENCODING_SRGB};
    if (normal_map) {
        if ((r = normal_map_codes(image, field, &codes, err)) != SK_OK) return r;
        png.encoding = SK_PNG_ENCODING_LINEAR;
    } else if ((r = check_colour_texture(image, field, err)) != SK_OK) {
        return r;
    }
    sk__gltf_image *im = &gltf->images[gltf->image_count];
    r = sk_image_write_png_memory(normal_map ? &codes : image, &png, &im->png, &im->size, err);
    sk_image_free(&codes);
    if (r != SK_OK) return sk_error_prefix(err, r, "%s", field);
    im->has_alpha = false;
    if (image->channels == 2 || image->channels == 4) {
        size_t n = (size_t)image->width * (size_t)image->height, ch = (size_t)image->channels;
        for (size_t i = 0; i < n && !im->has_alpha; i++)
            im->has_alpha = image->data[i * ch + ch - 1] < 1.0f;
    }
    *out_index = gltf->image_count++;
    return SK_OK;
}

/* ------------------------------------------------------------- materials */

static bool all_zero(const float *v, int n)
{
    for (int i = 0; i < n; i++)
        if (v[i] != 0.0f) return false;
    return true;
}

static sk_result check_material(const sk_gltf_material_desc *d, sk_error *err)
{
    static const char *const channel[4] = {"base_color[0]", "base_color[1]", "base_color[2]",
                                           "base_color[3]"};
    sk_result r = SK_OK;
    for (int c = 0; c < 4 && r == SK_OK; c++)
        r = sk_check_range_f(err, channel[c], d->base_color[c], 0.0, 1.0);
    if (r == SK_OK) r = sk_check_range_f(err, "metallic", d->metallic, 0.0, 1.0);
    if (r == SK_OK) r = sk_check_range_f(err, "roughness", d->roughness, 0.0, 1.0);
    if (r == SK_OK) r = sk_check_range_f(err, "normal_scale", d->normal_scale, -100.0, 100.0);
    static const char *const glow[3] = {"emissive[0]", "emissive[1]", "emissive[2]"};
    for (int c = 0; c < 3 && r == SK_OK; c++)
        r = sk_check_range_f(err, glow[c], d->emissive[c], 0.0, 1.0);
    if (r == SK_OK && d->emissive_texture && all_zero(d->emissive, 3))
        r = sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                    "emissive_texture without an emissive factor: all zero emits nothing");
    return r;
}

sk_result sk_gltf_add_material(sk_gltf *gltf, const sk_gltf_material_desc *desc, int *out_index,
                               sk_error *err)
{
    if (!gltf || !desc || !out_index)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "gltf, desc or out_index is NULL");
    *out_index = SK_GLTF_NONE;
    int index = gltf->material_count;
    sk_result r = check_material(desc, err);
    if (r != SK_OK) return sk_error_prefix(err, r, "materials[%d]", index);
    r = sk__gltf_grow((void **)&gltf->materials, gltf->material_count, &gltf->material_capacity,
                      sizeof *gltf->materials, "materials", err);
    if (r != SK_OK) return r;
    sk__gltf_material m = {0};
    memcpy(m.base_color, desc->base_color, sizeof m.base_color);
    if (all_zero(m.base_color, 4))
        m.base_color[0] = m.base_color[1] = m.base_color[2] = m.base_color[3] = 1.0f;
    m.metallic = desc->metallic;
    m.roughness = desc->roughness > 0.0f ? desc->roughness : 0.5f;
    m.normal_scale = desc->normal_scale != 0.0f ? desc->normal_scale : 1.0f;
    m.double_sided = desc->double_sided;
    memcpy(m.emissive, desc->emissive, sizeof m.emissive);
    m.base_color_image = m.normal_image = m.emissive_image = -1;
    /* images are added only once the material is known to be valid, so a failed call
       leaves no unused image behind (an unused object would make the validator report) */
    int first_image = gltf->image_count;
    char field[64];
    if (desc->base_color_texture) {
        snprintf(field, sizeof field, "materials[%d].base_color_texture", index);
        r = sk__gltf_add_image(gltf, desc->base_color_texture, false, field, &m.base_color_image,
                               err);
    }
    if (r == SK_OK && desc->normal_texture) {
        snprintf(field, sizeof field, "materials[%d].normal_texture", index);
        r = sk__gltf_add_image(gltf, desc->normal_texture, true, field, &m.normal_image, err);
    }
    if (r == SK_OK && desc->emissive_texture) {
        snprintf(field, sizeof field, "materials[%d].emissive_texture", index);
        r = sk__gltf_add_image(gltf, desc->emissive_texture, false, field, &m.emissive_image, err);
    }
    if (r == SK_OK) {
        m.name = sk__gltf_name(desc->name, "material", index);
        if (!m.name) r = sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    }
    if (r != SK_OK) {
        while (gltf->image_count > first_image) free(gltf->images[--gltf->image_count].png);
        return r;
    }
    gltf->materials[index] = m;
    gltf->material_count++;
    *out_index = index;
    return SK_OK;
}

/* ----------------------------------------------------------------- nodes */

sk_gltf_node_desc sk_gltf_node_desc_default(void)
{
    sk_gltf_node_desc d;
    memset(&d, 0, sizeof d);
    d.parent = d.mesh = d.skin = SK_GLTF_NONE;
    d.rotation[3] = 1.0;
    d.scale[0] = d.scale[1] = d.scale[2] = 1.0;
    return d;
}

/* The node's transform, checked and with its zero defaults filled in. */
static sk_result node_transform(const sk_gltf_node_desc *d, sk__gltf_node *n, sk_error *err)
{
    static const char *const names[10] = {
        "translation[0]", "translation[1]", "translation[2]", "rotation[0]", "rotation[1]",
        "rotation[2]",    "rotation[3]",    "scale[0]",       "scale[1]",    "scale[2]"};
    double v[10];
    memcpy(v, d->translation, 3 * sizeof(double));
    memcpy(v + 3, d->rotation, 4 * sizeof(double));
    memcpy(v + 7, d->scale, 3 * sizeof(double));
    for (int i = 0; i < 10; i++) {
        sk_result r = sk_check_finite(err, names[i], v[i]);
        if (r != SK_OK) return r;
    }
    memcpy(n->translation, d->translation, sizeof n->translation);
    double q2 = 0.0;
    for (int i = 0; i < 4; i++) q2 += d->rotation[i] * d->rotation[i];
    if (q2 == 0.0) {
        n->rotation[0] = n->rotation[1] = n->rotation[2] = 0.0;
        n->rotation[3] = 1.0;
    } else {
        double len = sqrt(q2);
        if (fabs(len - 1.0) > SK__GLTF_UNIT_TOLERANCE)
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "rotation has length %.9g: a rotation quaternion must have length 1",
                           len);
        for (int i = 0; i < 4; i++) n->rotation[i] = d->rotation[i] / len;
    }
    if (d->scale[0] == 0.0 && d->scale[1] == 0.0 && d->scale[2] == 0.0)
        n->scale[0] = n->scale[1] = n->scale[2] = 1.0;
    else
        memcpy(n->scale, d->scale, sizeof n->scale);
    return SK_OK;
}

static bool is_identity(const sk__gltf_node *n)
{
    return n->translation[0] == 0 && n->translation[1] == 0 && n->translation[2] == 0 &&
           n->rotation[0] == 0 && n->rotation[1] == 0 && n->rotation[2] == 0 &&
           n->rotation[3] == 1 && n->scale[0] == 1 && n->scale[1] == 1 && n->scale[2] == 1;
}

/* The mesh / skin pairing rules of glTF 2.0 sec. 3.7.3 and the validator's warnings: a
 * skinned mesh needs a skin whose joints cover its joint indices, on a root node without a
 * transform of its own (glTF ignores both there). */
static sk_result check_mesh_and_skin(const sk_gltf *gltf, const sk_gltf_node_desc *d,
                                     const sk__gltf_node *n, sk_error *err)
{
    if (d->mesh != SK_GLTF_NONE && (d->mesh < 0 || d->mesh >= gltf->mesh_count))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "mesh = %d is not a mesh of the document (%d meshes)", d->mesh,
                       gltf->mesh_count);
    if (d->skin != SK_GLTF_NONE && (d->skin < 0 || d->skin >= gltf->skin_count))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "skin = %d is not a skin of the document (%d skins)", d->skin,
                       gltf->skin_count);
    const sk__gltf_mesh *mesh = d->mesh != SK_GLTF_NONE ? &gltf->meshes[d->mesh] : NULL;
    bool skinned = mesh && mesh->joints;
    if (d->skin != SK_GLTF_NONE && !skinned)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "skin = %d needs a mesh with joints and weights", d->skin);
    if (skinned && d->skin == SK_GLTF_NONE)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "mesh = %d is skinned (joints and weights): the node needs a skin", d->mesh);
    if (!skinned) return SK_OK;
    const sk__gltf_skin *skin = &gltf->skins[d->skin];
    if (mesh->max_joint >= skin->joint_count)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "mesh = %d uses joint %d but skin = %d has %d joints", d->mesh,
                       mesh->max_joint, d->skin, skin->joint_count);
    if (d->parent != SK_GLTF_NONE || !is_identity(n))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "a node with a skinned mesh must be a root without translation, "
                       "rotation or scale (glTF ignores them: the joints place the mesh)");
    return SK_OK;
}

sk_result sk_gltf_add_node(sk_gltf *gltf, const sk_gltf_node_desc *desc, int *out_index,
                           sk_error *err)
{
    if (!gltf || !desc || !out_index)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "gltf, desc or out_index is NULL");
    *out_index = SK_GLTF_NONE;
    int index = gltf->node_count;
    if (desc->parent != SK_GLTF_NONE && (desc->parent < 0 || desc->parent >= index))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "nodes[%d].parent = %d is not an earlier node (range [0, %d) or "
                       "SK_GLTF_NONE)",
                       index, desc->parent, index);
    sk__gltf_node n = {0};
    n.parent = desc->parent;
    n.mesh = desc->mesh;
    n.skin = desc->skin;
    sk_result r = node_transform(desc, &n, err);
    if (r == SK_OK) r = check_mesh_and_skin(gltf, desc, &n, err);
    if (r != SK_OK) return sk_error_prefix(err, r, "nodes[%d]", index);
    r = sk__gltf_grow((void **)&gltf->nodes, gltf->node_count, &gltf->node_capacity,
                      sizeof *gltf->nodes, "nodes", err);
    if (r != SK_OK) return r;
    n.name = sk__gltf_name(desc->name, "node", index);
    if (!n.name) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    if (n.parent != SK_GLTF_NONE) gltf->nodes[n.parent].has_child = true;
    gltf->nodes[index] = n;
    gltf->node_count++;
    *out_index = index;
    return SK_OK;
}
