/* The scene export as Wavefront OBJ: every object's mesh moved by its transform into one
 * mesh in metres (OBJ has no hierarchy and no units; Blender reads it as metres), one OBJ
 * object per scene object, an MTL file with each material's Kd and map_Kd, and the baked
 * or copied base colour textures as sRGB PNG files beside it. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "render/export_internal.h"

/* OBJ and MTL names have no white space. */
static void plain_name(const char *src, char *dst, size_t size)
{
    snprintf(dst, size, "%s", src[0] ? src : "unnamed");
    for (char *p = dst; *p; p++)
        if (*p == ' ' || *p == '\t' || *p == '\n' || *p == '\r') *p = '_';
}

/* Appends object i's mesh, moved into the scene frame and scaled to metres. */
static void append_object(const sk_render_scene *scene, const sk__export *e, int i, sk_mesh *out,
                          size_t *v0, size_t *t0)
{
    const sk__instance *in = &scene->instances[i];
    const sk_mesh *m = &e->meshes[e->object_mesh[i]].mesh;
    float metres = scene->desc.unit_mm / 1000.0f;
    for (size_t v = 0; v < m->vertex_count; v++) {
        size_t o = *v0 + v;
        sk_vec3f p = sk_m4f_apply_point(in->to_world, sk_v3f_load(m->positions + 3 * v));
        out->positions[3 * o] = p.x * metres;
        out->positions[3 * o + 1] = p.y * metres;
        out->positions[3 * o + 2] = p.z * metres;
        if (out->normals) {
            sk_vec3f n =
                sk_v3f_normalize(sk_m3f_apply(in->normal_matrix, sk_v3f_load(m->normals + 3 * v)));
            memcpy(out->normals + 3 * o, &n, 3 * sizeof(float));
        }
        if (out->uvs && m->uvs) memcpy(out->uvs + 2 * o, m->uvs + 2 * v, 2 * sizeof(float));
    }
    for (size_t t = 0; t < m->triangle_count; t++) {
        const uint32_t *ix = m->indices + 3 * t;
        uint32_t *ox = out->indices + 3 * (*t0 + t);
        /* a mirroring transform turns the winding round: turn it back */
        bool flip = in->handedness < 0;
        ox[0] = (uint32_t)(*v0 + ix[0]);
        ox[1] = (uint32_t)(*v0 + ix[flip ? 2 : 1]);
        ox[2] = (uint32_t)(*v0 + ix[flip ? 1 : 2]);
    }
    *v0 += m->vertex_count;
    *t0 += m->triangle_count;
}

/* "dir/scene.obj" + "oak" -> "dir/scene-oak.png" (path) and "scene-oak.png" (for map_Kd). */
static void texture_names(const char *obj_path, const char *material, char *path, size_t path_size,
                          char *name, size_t name_size)
{
    const char *slash = strrchr(obj_path, '/');
    const char *base = slash ? slash + 1 : obj_path;
    const char *dot = strrchr(base, '.');
    int stem = dot && dot != base ? (int)(dot - base) : (int)strlen(base);
    snprintf(name, name_size, "%.*s-%s.png", stem, base, material);
    snprintf(path, path_size, "%.*s%s", (int)(base - obj_path), obj_path, name);
}

/* The names the OBJ and its materials file are written with (one per material, texture
 * and object). */
typedef char export_name[SK__EXPORT_NAME_SIZE];
typedef char texture_file[64 + SK__EXPORT_NAME_SIZE];
typedef char group_name[SK_RENDER_NAME_SIZE + 16];

sk_result sk__export_write_obj(const sk_render_scene *scene, const sk__export *e,
                               const sk__export_files *files, sk_error *err)
{
    const char *path = files->path;
    size_t nv = 0, nt = 0;
    bool normals = true, uvs = false;
    for (int i = 0; i < e->object_count; i++) {
        const sk_mesh *m = &e->meshes[e->object_mesh[i]].mesh;
        nv += m->vertex_count, nt += m->triangle_count;
        normals &= m->normals != NULL;
        uvs |= m->uvs != NULL;
    }
    if (nt == 0)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "%s: the scene has no objects to export",
                       path);
    sk_mesh world;
    int flags = (normals ? SK_MESH_NORMALS : 0) | (uvs ? SK_MESH_UVS : 0);
    sk_result r = sk_mesh_create(&world, nv, nt, flags, err);
    if (r != SK_OK) return r;
    size_t material_slots = (size_t)e->material_count + 1;
    size_t object_slots = (size_t)e->object_count + 1;
    sk_obj_material *materials = calloc(material_slots, sizeof *materials);
    sk_obj_group *groups = calloc(object_slots, sizeof *groups);
    export_name *material_names = calloc(material_slots, sizeof *material_names);
    texture_file *texture_files = calloc(material_slots, sizeof *texture_files);
    group_name *group_names = calloc(object_slots, sizeof *group_names);
    if (!materials || !groups || !material_names || !texture_files || !group_names)
        r = sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for the export");
    size_t v0 = 0, t0 = 0;
    for (int i = 0; r == SK_OK && i < e->object_count; i++) {
        append_object(scene, e, i, &world, &v0, &t0);
        char name[SK_RENDER_NAME_SIZE + 16];
        sk__export_object_name(scene, i, name, sizeof name);
        plain_name(name, group_names[i], sizeof group_names[i]);
        groups[i] = (sk_obj_group){group_names[i], e->meshes[e->object_mesh[i]].mesh.triangle_count,
                                   e->meshes[e->object_mesh[i]].material};
    }
    /* textures first, then the MTL and the OBJ naming them */
    for (int k = 0; r == SK_OK && k < e->material_count; k++) {
        const sk__export_material *m = &e->materials[k];
        plain_name(m->name, material_names[k], sizeof material_names[k]);
        materials[k] = (sk_obj_material){
            material_names[k], {m->base_color[0], m->base_color[1], m->base_color[2]}, NULL};
        if (!m->base_texture.data) continue;
        char file[4096];
        const char *staged = NULL;
        texture_names(path, material_names[k], file, sizeof file, texture_files[k],
                      sizeof texture_files[k]);
        materials[k].texture_path = texture_files[k];
        r = sk_output_set_file(files->set, file, &staged, err);
        if (r == SK_OK) r = sk_image_write_png(&m->base_texture, staged, NULL, err);
    }
    if (r == SK_OK) {
        const char *slash = strrchr(files->mtl, '/');
        sk_obj_write_desc d = {.materials = materials,
                               .material_count = e->material_count,
                               .groups = groups,
                               .group_count = e->object_count,
                               .mtl_path = files->staged_mtl,
                               .mtl_name = slash ? slash + 1 : files->mtl};
        r = sk_mesh_write_obj(&world, files->staged, &d, err);
    }
    free(materials);
    free(groups);
    free(material_names);
    free(texture_files);
    free(group_names);
    sk_mesh_free(&world);
    return r;
}
