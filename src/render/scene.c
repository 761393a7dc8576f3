/* A renderable scene: validated desc, materials and their textures, geometry in Embree,
 * the camera (framed on the geometry if asked) and the lights. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "render/render_internal.h"

void sk__join_path(const char *base, const char *name, char *out, size_t size)
{
    if (name[0] == '/' || !base[0])
        snprintf(out, size, "%s", name);
    else
        snprintf(out, size, "%s/%s", base, name);
}

bool sk__has_extension(const char *path, const char *ext)
{
    size_t n = strlen(path), e = strlen(ext);
    return n > e && strcasecmp(path + n - e, ext) == 0;
}

sk_result sk_render_scene_create(const sk_render_scene_desc *desc, sk_render_scene **out,
                                 sk_error *err)
{
    *out = NULL;
    sk_result r = sk_render_scene_desc_validate(desc, err);
    if (r != SK_OK) return r;
    sk_render_scene *scene = calloc(1, sizeof *scene);
    if (!scene) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for the scene");
    sk_render_scene_desc_resolve(desc, &scene->desc);
    if ((r = sk__materials_build(scene, err)) == SK_OK &&
        (r = sk__geometry_build(scene, err)) == SK_OK) {
        sk__camera_setup(scene);
        sk__lights_setup(scene);
        if ((r = sk__environment_build(scene, err)) == SK_OK) {
            *out = scene;
            return SK_OK;
        }
    }
    sk_render_scene_destroy(scene);
    return r;
}

void sk_render_scene_destroy(sk_render_scene *scene)
{
    if (!scene) return;
    sk__environment_destroy(scene);
    sk__geometry_destroy(scene);
    sk__materials_destroy(scene);
    free(scene);
}

const sk_render_scene_desc *sk_render_scene_get_desc(const sk_render_scene *scene)
{
    return &scene->desc;
}

bool sk_render_scene_bounds(const sk_render_scene *scene, sk_vec3f *lo, sk_vec3f *hi)
{
    if (!scene->has_bounds) return false;
    *lo = scene->lo;
    *hi = scene->hi;
    return true;
}
