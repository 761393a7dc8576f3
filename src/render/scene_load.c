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

/* A material's reference to another module's preset ("skin_preset": "fig19f"). */
typedef struct preset_ref {
    const char *module; /* folder of the shipped presets, and the key prefix */
    const sk_schema *schema;
    const char *name;
    int set_count;
    const sk_render_preset_set *sets;
    void *desc;
    size_t desc_size;
} preset_ref;

static bool all_zero(const void *p, size_t n)
{
    const unsigned char *b = p;
    for (size_t i = 0; i < n; i++)
        if (b[i]) return false;
    return true;
}

/* Finds the preset file: a path (with '/' or ending in .json) relative to the scene, else a
 * shipped name through the loader's lookup or <scene folder>/../<module>/<name>.json. */
static bool find_preset_file(const sk_render_load_desc *load, const char *base_dir,
                             const char *module, const char *name, char *path, size_t size)
{
    size_t n = strlen(name);
    if (strchr(name, '/') || (n > 5 && strcmp(name + n - 5, ".json") == 0)) {
        sk__join_path(base_dir, name, path, size);
        return true;
    }
    if (load && load->find_preset)
        return load->find_preset(load->find_preset_user, module, name, path, size);
    char rel[SK_RENDER_PATH_SIZE + 64];
    snprintf(rel, sizeof rel, "../%s/%s.json", module, name);
    sk__join_path(base_dir[0] ? base_dir : ".", rel, path, size);
    FILE *fp = fopen(path, "rb");
    if (fp) fclose(fp);
    return fp != NULL;
}

static sk_result resolve_preset(const sk_render_load_desc *load, const char *base_dir, int index,
                                const preset_ref *ref, sk_error *err)
{
    const char *m = ref->module;
    if (!ref->name[0]) {
        if (ref->set_count > 0)
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "materials[%d].%s_set needs materials[%d].%s_preset (edit the %s keys "
                           "directly otherwise)",
                           index, m, index, m, m);
        return SK_OK;
    }
    if (!all_zero(ref->desc, ref->desc_size))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "materials[%d]: give either %s_preset or %s, not both (use %s_set to edit "
                       "a preset)",
                       index, m, m, m);
    char path[2 * SK_RENDER_PATH_SIZE + 64];
    if (!find_preset_file(load, base_dir, m, ref->name, path, sizeof path))
        return sk_fail(err, SK_ERROR_NOT_FOUND,
                       "materials[%d].%s_preset = \"%s\" is not a shipped %s preset (see "
                       "'shitsukan presets %s')",
                       index, m, ref->name, m, m);
    sk_preset *preset = NULL;
    sk_result r = sk_preset_load_file(&preset, path, err);
    if (r != SK_OK)
        return sk_error_prefix(err, r, "materials[%d].%s_preset = \"%s\"", index, m, ref->name);
    for (int k = 0; r == SK_OK && k < ref->set_count; k++)
        if ((r = sk_preset_set(preset, ref->sets[k].text, err)) != SK_OK)
            sk_error_prefix(err, r, "materials[%d].%s_set[%d]", index, m, k);
    if (r == SK_OK && (r = sk_preset_bind(preset, ref->schema, ref->desc, err)) != SK_OK)
        sk_error_prefix(err, r, "materials[%d].%s_preset = \"%s\"", index, m, ref->name);
    sk_preset_free(preset);
    return r;
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
    for (int i = 0; i < desc->material_count; i++) {
        sk_render_material_desc *m = &desc->materials[i];
        preset_ref skin = {"skin",      &sk_skin_schema, m->skin_preset, m->skin_set_count,
                           m->skin_set, &m->skin,        sizeof m->skin};
        if ((r = resolve_preset(load, desc->base_dir, i, &skin, err)) != SK_OK) return r;
        preset_ref wood = {"wood",      &sk_wood_schema, m->wood_preset, m->wood_set_count,
                           m->wood_set, &m->wood,        sizeof m->wood};
        if ((r = resolve_preset(load, desc->base_dir, i, &wood, err)) != SK_OK) return r;
    }
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
