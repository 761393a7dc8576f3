/* Scene desc defaults and validation: ranges and NaN for C callers (the JSON binder checks
 * them for files), and the cross-references a schema cannot state. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "render/render_internal.h"

#define BIG 1e9
#define PATH 96

void sk__material_desc_resolve(sk_render_material_desc *m)
{
    if (sk__v3f_is_zero(m->albedo)) m->albedo[0] = m->albedo[1] = m->albedo[2] = 0.8f;
    if (m->shininess == 0) m->shininess = 64.0f;
    if (m->bump_scale == 0) m->bump_scale = 1.0f;
    if (m->uv_scale[0] == 0 && m->uv_scale[1] == 0) m->uv_scale[0] = m->uv_scale[1] = 1.0f;
    if (m->texture_radiance == 0) m->texture_radiance = 1.0f;
}

static void object_resolve(sk_render_object_desc *o)
{
    if (sk__v3f_is_zero(o->size)) o->size[0] = o->size[1] = o->size[2] = 1.0f;
    if (o->radius == 0) o->radius = 0.5f;
    if (o->height == 0) o->height = 1.0f;
    if (o->segments == 0) o->segments = 64;
    if (o->rings == 0) o->rings = 32;
    float *s = o->transform.scale;
    if (sk__v3f_is_zero(s)) s[0] = s[1] = s[2] = 1.0f;
}

static void light_resolve(sk_render_light_desc *l)
{
    if (sk__v3f_is_zero(l->color)) l->color[0] = l->color[1] = l->color[2] = 1.0f;
    if (l->type == SK_RENDER_LIGHT_DIRECTIONAL && sk__v3f_is_zero(l->direction))
        l->direction[1] = -1.0f;
    if (l->size[0] == 0 && l->size[1] == 0) l->size[0] = l->size[1] = 1.0f;
    if (sk__v3f_is_zero(l->up)) l->up[1] = 1.0f;
    if (l->samples == 0) l->samples = 1;
}

static void image_resolve(sk_render_image_desc *image)
{
    if (image->width == 0) image->width = 640;
    if (image->height == 0) image->height = 360;
    if (image->samples == 0) image->samples = 16;
}

static void camera_resolve(sk_render_camera_desc *camera)
{
    if (sk__v3f_is_zero(camera->up)) camera->up[1] = 1.0f;
    if (camera->fov == 0) camera->fov = (float)(40.0 * SK_DEG_TO_RAD);
}

static void environment_resolve(sk_render_environment_desc *env)
{
    if (env->ao_samples == 0) env->ao_samples = 1;
}

void sk_render_scene_desc_resolve(const sk_render_scene_desc *desc, sk_render_scene_desc *out)
{
    if (out != desc) memcpy(out, desc, sizeof *out);
    if (out->unit_mm == 0) out->unit_mm = 1.0f;
    image_resolve(&out->image);
    camera_resolve(&out->camera);
    environment_resolve(&out->environment);
    for (int i = 0; i < out->material_count && i < SK_RENDER_MAX_MATERIALS; i++)
        sk__material_desc_resolve(&out->materials[i]);
    for (int i = 0; i < out->object_count && i < SK_RENDER_MAX_OBJECTS; i++)
        object_resolve(&out->objects[i]);
    for (int i = 0; i < out->light_count && i < SK_RENDER_MAX_LIGHTS; i++)
        light_resolve(&out->lights[i]);
}

/* ---- checks with formatted key paths */

/* Range and NaN check of an int or float value; the key path is formatted only on failure. */
static sk_result check_f(sk_error *err, double v, double lo, double hi, const char *fmt, ...)
    __attribute__((format(printf, 5, 6)));
static sk_result check_f(sk_error *err, double v, double lo, double hi, const char *fmt, ...)
{
    if (sk_in_range_f(v, lo, hi)) return SK_OK;
    char name[PATH];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(name, sizeof name, fmt, ap);
    va_end(ap);
    return sk_check_range_f(err, name, v, lo, hi);
}

static sk_result check_v(sk_error *err, const float *v, int n, double lo, double hi,
                         const char *prefix)
{
    for (int i = 0; i < n; i++) {
        sk_result r = check_f(err, v[i], lo, hi, "%s[%d]", prefix, i);
        if (r != SK_OK) return r;
    }
    return SK_OK;
}

static bool bounded_string(const char *s, size_t size) { return memchr(s, '\0', size) != NULL; }

#define TRY(expr)                                                                                  \
    do {                                                                                           \
        sk_result r_ = (expr);                                                                     \
        if (r_ != SK_OK) return r_;                                                                \
    } while (0)

static sk_result validate_transform(const sk_render_transform *t, const char *prefix, sk_error *err)
{
    char p[PATH];
    snprintf(p, sizeof p, "%s.translate", prefix);
    TRY(check_v(err, t->translate, 3, -BIG, BIG, p));
    snprintf(p, sizeof p, "%s.rotate_deg", prefix);
    for (int i = 0; i < 3; i++)
        TRY(check_f(err, t->rotate[i] * SK_RAD_TO_DEG, -3600, 3600, "%s[%d]", p, i));
    snprintf(p, sizeof p, "%s.scale", prefix);
    TRY(check_v(err, t->scale, 3, -BIG, BIG, p));
    for (int i = 0; i < 3; i++)
        if (t->scale[i] == 0)
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "%s[%d] = 0: a scale must not be 0 (all three 0 mean 1)", p, i);
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
    TRY(check_f(err, m->type, 0, SK_RENDER_MATERIAL_TYPE_COUNT - 1, "materials[%d].type", i));
    snprintf(p, sizeof p, "materials[%d].albedo", i);
    TRY(check_v(err, m->albedo, 3, 0, 1, p));
    TRY(check_f(err, m->specular, 0, 1, "materials[%d].specular", i));
    TRY(check_f(err, m->shininess, 1, 100000, "materials[%d].shininess", i));
    TRY(check_f(err, m->bump_scale, 0, 100, "materials[%d].bump_scale", i));
    snprintf(p, sizeof p, "materials[%d].uv_scale", i);
    TRY(check_v(err, m->uv_scale, 2, -BIG, BIG, p));
    snprintf(p, sizeof p, "materials[%d].uv_offset", i);
    TRY(check_v(err, m->uv_offset, 2, -BIG, BIG, p));
    TRY(check_f(err, m->texture_weight, 0, 1, "materials[%d].texture_weight", i));
    TRY(check_f(err, m->texture_radiance, 0, BIG, "materials[%d].texture_radiance", i));
    if (!bounded_string(m->skin_preset, sizeof m->skin_preset) ||
        !bounded_string(m->wood_preset, sizeof m->wood_preset))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "materials[%d]: a preset name is not terminated", i);
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
    TRY(check_f(err, o->shape, 0, SK_RENDER_SHAPE_COUNT - 1, "objects[%d].shape", i));
    TRY(check_f(err, o->uv, 0, SK_RENDER_UV_COUNT - 1, "objects[%d].uv", i));
    if (o->shape == SK_RENDER_SHAPE_MESH && o->file[0] == '\0' && !o->mesh)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "objects[%d].file is empty: shape \"mesh\" needs a mesh file (or choose a "
                       "shape: plane, box, sphere, cylinder, capsule)",
                       i);
    snprintf(p, sizeof p, "objects[%d].size", i);
    TRY(check_v(err, o->size, 3, 0, BIG, p));
    if (o->shape == SK_RENDER_SHAPE_PLANE && !(o->size[0] > 0 && o->size[2] > 0))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "objects[%d].size = [%g, %g, %g]: a plane needs size[0] > 0 and size[2] > 0",
                       i, o->size[0], o->size[1], o->size[2]);
    if (o->shape == SK_RENDER_SHAPE_BOX && !(o->size[0] > 0 && o->size[1] > 0 && o->size[2] > 0))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "objects[%d].size = [%g, %g, %g]: a box needs every edge > 0", i, o->size[0],
                       o->size[1], o->size[2]);
    TRY(check_f(err, o->radius, 1e-30, BIG, "objects[%d].radius", i));
    TRY(check_f(err, o->height, 1e-30, BIG, "objects[%d].height", i));
    TRY(check_f(err, o->segments, 3, 4096, "objects[%d].segments", i));
    TRY(check_f(err, o->rings, 2, 4096, "objects[%d].rings", i));
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
    TRY(check_f(err, l->type, 0, SK_RENDER_LIGHT_COUNT - 1, "lights[%d].type", i));
    snprintf(p, sizeof p, "lights[%d].color", i);
    TRY(check_v(err, l->color, 3, 0, BIG, p));
    TRY(check_f(err, l->intensity, 0, BIG, "lights[%d].intensity", i));
    snprintf(p, sizeof p, "lights[%d].position", i);
    TRY(check_v(err, l->position, 3, -BIG, BIG, p));
    snprintf(p, sizeof p, "lights[%d].direction", i);
    TRY(check_v(err, l->direction, 3, -BIG, BIG, p));
    snprintf(p, sizeof p, "lights[%d].size", i);
    TRY(check_v(err, l->size, 2, 0, BIG, p));
    snprintf(p, sizeof p, "lights[%d].up", i);
    TRY(check_v(err, l->up, 3, -BIG, BIG, p));
    TRY(check_f(err, l->samples, 1, 256, "lights[%d].samples", i));
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

sk_result sk_render_scene_desc_validate(const sk_render_scene_desc *desc, sk_error *err)
{
    /* resolved part by part on the stack (the whole desc is large) */
    const sk_render_scene_desc *d = desc;
    float unit_mm = d->unit_mm == 0 ? 1.0f : d->unit_mm;
    sk_render_image_desc image = d->image;
    sk_render_camera_desc camera = d->camera;
    sk_render_environment_desc environment = d->environment;
    image_resolve(&image);
    camera_resolve(&camera);
    environment_resolve(&environment);
    TRY(check_f(err, unit_mm, 1e-6, 1e9, "unit_mm"));
    TRY(check_f(err, image.width, 1, SK_RENDER_MAX_DIMENSION, "image.width"));
    TRY(check_f(err, image.height, 1, SK_RENDER_MAX_DIMENSION, "image.height"));
    TRY(check_f(err, image.samples, 1, SK_RENDER_MAX_SAMPLES, "image.samples"));
    TRY(check_f(err, d->film.exposure, -30, 30, "film.exposure"));
    TRY(check_f(err, d->film.tonemap, 0, SK_RENDER_TONEMAP_COUNT - 1, "film.tonemap"));
    TRY(check_f(err, d->film.white, 0, 1e6, "film.white"));
    TRY(check_v(err, d->film.background, 3, 0, BIG, "film.background"));

    const sk_render_camera_desc *c = &camera;
    TRY(check_f(err, c->projection, 0, SK_RENDER_PROJECTION_COUNT - 1, "camera.projection"));
    TRY(check_v(err, c->position, 3, -BIG, BIG, "camera.position"));
    TRY(check_v(err, c->target, 3, -BIG, BIG, "camera.target"));
    TRY(check_v(err, c->up, 3, -BIG, BIG, "camera.up"));
    TRY(check_f(err, c->fov * SK_RAD_TO_DEG, 0.001, 179, "camera.fov_deg"));
    TRY(check_f(err, c->ortho_height, 0, BIG, "camera.ortho_height"));
    bool auto_frame = sk__v3f_is_zero(c->position) && sk__v3f_is_zero(c->target);
    sk_vec3f forward = sk_v3f_sub(sk__v3f_from(c->target), sk__v3f_from(c->position));
    if (!auto_frame && sk_v3f_length(forward) == 0)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "camera.position = camera.target = [%g, %g, %g]: the camera has no view "
                       "direction",
                       c->position[0], c->position[1], c->position[2]);
    if (!auto_frame) {
        sk_vec3f f = sk_v3f_normalize(forward), up = sk_v3f_normalize(sk__v3f_from(c->up));
        if (sk_v3f_length(sk_v3f_cross(f, up)) < 1e-6f)
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "camera.up = [%g, %g, %g] is parallel to the view direction", c->up[0],
                           c->up[1], c->up[2]);
    }

    const sk_render_environment_desc *e = &environment;
    TRY(check_v(err, e->radiance, 3, 0, BIG, "environment.radiance"));
    TRY(check_f(err, e->ao_distance, 0, BIG, "environment.ao_distance"));
    TRY(check_f(err, e->ao_samples, 1, 256, "environment.ao_samples"));

    TRY(check_f(err, d->material_count, 0, SK_RENDER_MAX_MATERIALS, "materials (count)"));
    TRY(check_f(err, d->object_count, 0, SK_RENDER_MAX_OBJECTS, "objects (count)"));
    TRY(check_f(err, d->light_count, 0, SK_RENDER_MAX_LIGHTS, "lights (count)"));
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
