/* Scene desc defaults and validation: the ranges and defaults sk_render_schema states, for
 * C callers (the JSON binder checks the same ranges for files), and the cross-references a
 * schema cannot state. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "render/render_internal.h"

#define PATH 96

/* The defaults sk_render_schema states (its parts one by one), and those computed. */
void sk__material_desc_resolve(sk_render_material_desc *m)
{
    sk_schema_apply_defaults(&sk__render_material_schema, m);
}

static void object_resolve(sk_render_object_desc *o)
{
    sk_schema_apply_defaults(&sk__render_object_schema, o);
}

static void light_resolve(sk_render_light_desc *l)
{
    if (l->type == SK_RENDER_LIGHT_DIRECTIONAL && sk__v3f_is_zero(l->direction))
        l->direction[1] = -1.0f;
    sk_schema_apply_defaults(&sk__render_light_schema, l);
}

static void film_resolve(sk_render_film_desc *film)
{
    sk_schema_apply_defaults(&sk__render_film_schema, film);
}

static void image_resolve(sk_render_image_desc *image)
{
    sk_schema_apply_defaults(&sk__render_image_schema, image);
}

static void camera_resolve(sk_render_camera_desc *camera)
{
    sk_schema_apply_defaults(&sk__render_camera_schema, camera);
}

static void environment_resolve(sk_render_environment_desc *env)
{
    sk_schema_apply_defaults(&sk__render_environment_schema, env);
}

void sk_render_scene_desc_resolve(const sk_render_scene_desc *desc, sk_render_scene_desc *out)
{
    if (out != desc) memcpy(out, desc, sizeof *out);
    const sk_schema_field *unit = sk_schema_find(&sk_render_schema, "unit_mm");
    if (out->unit_mm == 0) out->unit_mm = (float)unit->def;
    image_resolve(&out->image);
    camera_resolve(&out->camera);
    film_resolve(&out->film);
    environment_resolve(&out->environment);
    for (int i = 0; i < out->material_count && i < SK_RENDER_MAX_MATERIALS; i++)
        sk__material_desc_resolve(&out->materials[i]);
    for (int i = 0; i < out->object_count && i < SK_RENDER_MAX_OBJECTS; i++)
        object_resolve(&out->objects[i]);
    for (int i = 0; i < out->light_count && i < SK_RENDER_MAX_LIGHTS; i++)
        light_resolve(&out->lights[i]);
}

/* ---- checks */

static bool bounded_string(const char *s, size_t size) { return memchr(s, '\0', size) != NULL; }

#define TRY(expr)                                                                                  \
    do {                                                                                           \
        sk_result r_ = (expr);                                                                     \
        if (r_ != SK_OK) return r_;                                                                \
    } while (0)

static sk_result validate_transform(const sk_render_transform *t, const char *prefix, sk_error *err)
{
    for (int i = 0; i < 3; i++)
        if (t->scale[i] == 0)
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "%s.scale[%d] = 0: a scale must not be 0 (all three 0 mean 1)", prefix,
                           i);
    return SK_OK;
}

static int find_material(const sk_render_scene_desc *d, const char *name)
{
    for (int i = 0; i < d->material_count; i++)
        if (strcmp(d->materials[i].name, name) == 0) return i;
    return -1;
}

static sk_result validate_material(const sk_render_material_desc *given, int i, sk_error *err)
{
    char p[PATH];
    sk_render_material_desc resolved = *given, *m = &resolved;
    sk__material_desc_resolve(m);
    if (!bounded_string(m->name, sizeof m->name) ||
        !bounded_string(m->albedo_texture, sizeof m->albedo_texture) ||
        !bounded_string(m->normal_map, sizeof m->normal_map))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "materials[%d]: a string is not terminated",
                       i);
    if (m->name[0] == '\0')
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "materials[%d].name is empty (objects refer to materials by name)", i);
    if (!bounded_string(m->skin_preset, sizeof m->skin_preset) ||
        !bounded_string(m->wood_preset, sizeof m->wood_preset))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "materials[%d]: a preset name is not terminated", i);
    snprintf(p, sizeof p, "materials[%d]", i);
    TRY(sk_schema_check(&sk__render_material_schema, m, p, err));
    sk_result r;
    if (m->type == SK_RENDER_MATERIAL_SKIN && (r = sk_skin_desc_validate(&m->skin, err)) != SK_OK)
        return sk_error_prefix(err, r, "materials[%d].skin", i);
    if (m->type == SK_RENDER_MATERIAL_WOOD && !m->wood_tree &&
        (r = sk_wood_desc_validate(&m->wood, err)) != SK_OK)
        return sk_error_prefix(err, r, "materials[%d].wood", i);
    const sk_image *images[2] = {m->albedo_image, m->normal_image};
    const char *image_names[2] = {"albedo_image", "normal_image"};
    for (int k = 0; k < 2; k++)
        if (images[k] && (!images[k]->data || images[k]->width < 1 || images[k]->height < 1 ||
                          images[k]->channels < 1 || images[k]->channels > 4))
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "materials[%d].%s is not an image (%d x %d, %d channels; needs 1-4 "
                           "channels and pixels)",
                           i, image_names[k], images[k]->width, images[k]->height,
                           images[k]->channels);
    return SK_OK;
}

static sk_result validate_object(const sk_render_scene_desc *d, const sk_render_object_desc *given,
                                 int i, sk_error *err)
{
    char p[PATH];
    sk_render_object_desc resolved = *given, *o = &resolved;
    object_resolve(o);
    if (!bounded_string(o->name, sizeof o->name) || !bounded_string(o->file, sizeof o->file) ||
        !bounded_string(o->material, sizeof o->material))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "objects[%d]: a string is not terminated",
                       i);
    snprintf(p, sizeof p, "objects[%d]", i);
    TRY(sk_schema_check(&sk__render_object_schema, o, p, err));
    if (o->shape == SK_RENDER_SHAPE_MESH && o->file[0] == '\0' && !o->mesh)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "objects[%d].file is empty: shape \"mesh\" needs a mesh file (or choose a "
                       "shape: plane, box, sphere, cylinder, capsule)",
                       i);
    if (o->shape == SK_RENDER_SHAPE_PLANE && !(o->size[0] > 0 && o->size[2] > 0))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "objects[%d].size = [%g, %g, %g]: a plane needs size[0] > 0 and size[2] > 0",
                       i, o->size[0], o->size[1], o->size[2]);
    if (o->shape == SK_RENDER_SHAPE_BOX && !(o->size[0] > 0 && o->size[1] > 0 && o->size[2] > 0))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "objects[%d].size = [%g, %g, %g]: a box needs every edge > 0", i, o->size[0],
                       o->size[1], o->size[2]);
    if (o->material[0] && find_material(d, o->material) < 0) {
        char names[256] = "";
        size_t used = 0;
        for (int k = 0; k < d->material_count; k++) {
            int n = snprintf(names + used, sizeof names - used, "%s%s", k ? ", " : "",
                             d->materials[k].name);
            if (n < 0 || (size_t)n >= sizeof names - used) break;
            used += (size_t)n;
        }
        return sk_fail(
            err, SK_ERROR_INVALID_ARGUMENT,
            "objects[%d].material = \"%s\" is not a material of the scene (materials: %s)", i,
            o->material, d->material_count ? names : "none");
    }
    snprintf(p, sizeof p, "objects[%d].transform", i);
    return validate_transform(&o->transform, p, err);
}

static sk_result validate_light(const sk_render_light_desc *given, int i, sk_error *err)
{
    char p[PATH];
    sk_render_light_desc resolved = *given, *l = &resolved;
    light_resolve(l);
    snprintf(p, sizeof p, "lights[%d]", i);
    TRY(sk_schema_check(&sk__render_light_schema, l, p, err));
    if (l->type == SK_RENDER_LIGHT_DIRECTIONAL && sk__v3f_is_zero(l->direction))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "lights[%d].direction is zero", i);
    if (l->type == SK_RENDER_LIGHT_RECT) {
        if (!(l->size[0] > 0 && l->size[1] > 0))
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "lights[%d].size = [%g, %g]: a rect light needs both sides > 0", i,
                           l->size[0], l->size[1]);
        if (sk__v3f_is_zero(l->up))
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "lights[%d].up is zero", i);
    }
    return SK_OK;
}

/* The rules between the map and sky keys (resolved; their ranges are the schema's). */
static sk_result validate_environment(const sk_render_environment_desc *e, sk_error *err)
{
    if (!bounded_string(e->map, sizeof e->map))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "environment.map is not terminated");
    if (e->type == SK_RENDER_ENVIRONMENT_MAP && e->map[0] == '\0')
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "environment.map is empty: type \"map\" needs a lat-long EXR file");
    if (e->type == SK_RENDER_ENVIRONMENT_SKY && sk__v3f_is_zero(e->sun_direction))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "environment.sun_direction is zero");
    return SK_OK;
}

sk_result sk_render_scene_desc_validate(const sk_render_scene_desc *desc, sk_error *err)
{
    /* resolved part by part on the stack (the whole desc is large) */
    const sk_render_scene_desc *d = desc;
    float unit_mm = d->unit_mm == 0 ? 1.0f : d->unit_mm;
    sk_render_image_desc image = d->image;
    sk_render_camera_desc camera = d->camera;
    sk_render_environment_desc environment = d->environment;
    sk_render_film_desc film = d->film;
    image_resolve(&image);
    camera_resolve(&camera);
    environment_resolve(&environment);
    film_resolve(&film);
    /* every range, as sk_render_schema states it */
    const sk_schema_field *unit = sk_schema_find(&sk_render_schema, "unit_mm");
    TRY(sk_check_range_f(err, "unit_mm", unit_mm, unit->min, unit->max));
    TRY(sk_schema_check(&sk__render_image_schema, &image, "image", err));
    TRY(sk_schema_check(&sk__render_film_schema, &film, "film", err));

    const sk_render_camera_desc *c = &camera;
    TRY(sk_schema_check(&sk__render_camera_schema, c, "camera", err));
    bool auto_frame = sk__v3f_is_zero(c->position) && sk__v3f_is_zero(c->target);
    sk_vec3f forward = sk_v3f_sub(sk_v3f_load(c->target), sk_v3f_load(c->position));
    if (!auto_frame && sk_v3f_length(forward) == 0)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "camera.position = camera.target = [%g, %g, %g]: the camera has no view "
                       "direction",
                       c->position[0], c->position[1], c->position[2]);
    if (!auto_frame) {
        sk_vec3f f = sk_v3f_normalize(forward), up = sk_v3f_normalize(sk_v3f_load(c->up));
        if (sk_v3f_length(sk_v3f_cross(f, up)) < 1e-6f)
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "camera.up = [%g, %g, %g] is parallel to the view direction", c->up[0],
                           c->up[1], c->up[2]);
    }

    const sk_render_environment_desc *e = &environment;
    TRY(sk_schema_check(&sk__render_environment_schema, e, "environment", err));
    TRY(validate_environment(e, err));

    TRY(sk_check_range_i(err, "materials (count)", d->material_count, 0, SK_RENDER_MAX_MATERIALS));
    TRY(sk_check_range_i(err, "objects (count)", d->object_count, 0, SK_RENDER_MAX_OBJECTS));
    TRY(sk_check_range_i(err, "lights (count)", d->light_count, 0, SK_RENDER_MAX_LIGHTS));
    for (int i = 0; i < d->material_count; i++) {
        TRY(validate_material(&d->materials[i], i, err));
        for (int k = 0; k < i; k++)
            if (strcmp(d->materials[k].name, d->materials[i].name) == 0)
                return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                               "materials[%d].name = \"%s\" is already the name of materials[%d]",
                               i, d->materials[i].name, k);
    }
    for (int i = 0; i < d->object_count; i++) TRY(validate_object(d, &d->objects[i], i, err));
    for (int i = 0; i < d->light_count; i++) TRY(validate_light(&d->lights[i], i, err));
    if (!bounded_string(d->base_dir, sizeof d->base_dir))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "base_dir is not terminated");
    return SK_OK;
}
