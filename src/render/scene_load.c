/* Scene files: a JSON tree (with any --set edits) bound onto the scene desc through the
 * schema, then validated; relative file names resolve against the scene file's folder. */
#include <stdbool.h>
#include <stdio.h>
#include <string.h>

#include "render/render_internal.h"

/* Folder part of a path ("" for a bare file name). */
static void folder_of(const char *path, char *out, size_t size)
{
    out[0] = '\0';
    if (!path) return;
    const char *slash = strrchr(path, '/');
    if (!slash) return;
    size_t n = (size_t)(slash - path);
    if (n == 0) n = 1; /* "/scene.json" -> "/" */
    if (n >= size) n = size - 1;
    memcpy(out, path, n);
    out[n] = '\0';
}

sk_result sk_render_scene_desc_bind(const sk_preset *scene, const sk_render_load_desc *load,
                                    sk_render_scene_desc *desc, sk_error *err)
{
    memset(desc, 0, sizeof *desc);
    sk_result r = sk_preset_bind(scene, &sk_render_schema, desc, err);
    if (r != SK_OK) return r;
    const char *scene_path = load ? load->scene_path : NULL;
    folder_of(scene_path, desc->base_dir, sizeof desc->base_dir);
    if (scene_path && strlen(scene_path) >= sizeof desc->base_dir)
        return sk_fail(err, SK_ERROR_LIMIT, "scene path \"%s\" is longer than %zu characters",
                       scene_path, sizeof desc->base_dir - 1);
    return sk_render_scene_desc_validate(desc, err);
}

sk_result sk_render_scene_desc_load(const char *path, sk_render_scene_desc *desc, sk_error *err)
{
    sk_preset *preset = NULL;
    sk_result r = sk_preset_load_file(&preset, path, err);
    if (r != SK_OK) return r;
    sk_render_load_desc load = {.scene_path = path};
    r = sk_render_scene_desc_bind(preset, &load, desc, err);
    sk_preset_free(preset);
    return r;
}
