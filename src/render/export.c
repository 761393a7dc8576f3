/* The scene export (render.h, sk_render_scene_export): each object's mesh as the renderer
 * built it, with uvs in the frame its material's textures use, paired with an approximation
 * of its material; objects of one mesh and material share an export mesh, wood objects get
 * their own (the bake depends on the object). Written as .glb or .obj by extension. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "render/export_internal.h"

#define DEFAULT_TEXTURE_SIZE 1024

void sk__export_object_name(const sk_render_scene *scene, int object, char *out, size_t size)
{
    const char *name = scene->desc.objects[object].name;
    if (name[0])
        snprintf(out, size, "%s", name);
    else
        snprintf(out, size, "object%d", object);
}

void sk__export_free(sk__export *e)
{
    for (int i = 0; i < e->material_count; i++) sk__export_material_free(&e->materials[i]);
    for (int i = 0; i < e->mesh_count; i++) sk_mesh_free(&e->meshes[i].mesh);
    free(e->materials);
    free(e->meshes);
    memset(e, 0, sizeof *e);
}

/* A copy of scene mesh `index` with uvs mapped to its material's textures (and tangents,
 * turned with that map, for a normal texture). */
static sk_result copy_mesh(const sk_render_scene *scene, int index, int material, bool textures,
                           bool tangents, sk_mesh *out, sk_error *err)
{
    const sk_mesh *src = &scene->meshes[index].mesh;
    int flags = (src->normals ? SK_MESH_NORMALS : 0) | (src->uvs ? SK_MESH_UVS : 0);
    sk_result r = sk_mesh_create(out, src->vertex_count, src->triangle_count, flags, err);
    if (r != SK_OK) return r;
    size_t n = src->vertex_count;
    memcpy(out->positions, src->positions, 3 * n * sizeof(float));
    memcpy(out->indices, src->indices, 3 * src->triangle_count * sizeof(uint32_t));
    if (src->normals) memcpy(out->normals, src->normals, 3 * n * sizeof(float));
    float scale[2], offset[2];
    sk__export_material_uv_frame(scene, material, textures, scale, offset);
    for (size_t v = 0; src->uvs && v < n; v++)
        for (int c = 0; c < 2; c++)
            out->uvs[2 * v + c] = src->uvs[2 * v + c] * scale[c] + offset[c];
    if (!tangents) return SK_OK;
    float *t;
    if ((r = sk_mesh_add_attribute(out, "tangent", 4, &t, err)) != SK_OK) {
        sk_mesh_free(out);
        return r;
    }
    /* the tangent follows +u and the bitangent +v: a negative scale turns them round */
    float su = scale[0] < 0 ? -1.0f : 1.0f, sv = scale[1] < 0 ? -1.0f : 1.0f;
    const float *src_t = scene->meshes[index].tangents;
    for (size_t v = 0; v < n; v++) {
        for (int c = 0; c < 3; c++) t[4 * v + c] = su * src_t[4 * v + c];
        t[4 * v + 3] = su * sv * src_t[4 * v + 3];
    }
    return SK_OK;
}

/* A wood object: its own material and mesh, the albedo baked onto an atlas (or its mean). */
static sk_result add_wood(const sk_render_scene *scene, int object, bool textures, int size,
                          sk__export *e, sk_error *err)
{
    const sk__instance *in = &scene->instances[object];
    sk__export_material *mat = &e->materials[e->material_count];
    sk__export_mesh *mesh = &e->meshes[e->mesh_count];
    sk_result r = sk__export_material_make(scene, in->material, textures, size, mat, err);
    if (r != SK_OK) return r;
    char object_name[SK_RENDER_NAME_SIZE + 16];
    sk__export_object_name(scene, object, object_name, sizeof object_name);
    char material_name[SK__EXPORT_NAME_SIZE];
    snprintf(material_name, sizeof material_name, "%s", mat->name);
    snprintf(mat->name, sizeof mat->name, "%s-%s", material_name, object_name);
    e->material_count++;
    bool baked = false;
    if (textures) {
        sk_error limit = {0};
        r = sk__export_bake_wood(scene, object, size, &mesh->mesh, &mat->base_texture, &limit);
        /* too many triangles for the texture's cells: the mean colour stands in */
        if (r != SK_OK && r != SK_ERROR_LIMIT) return sk_fail(err, r, "%s", limit.message);
        baked = r == SK_OK;
        if (baked) sk__export_material_fold_factor(mat);
    }
    if (!baked) {
        if ((r = copy_mesh(scene, in->mesh, in->material, false, false, &mesh->mesh, err)) != SK_OK)
            return r;
        sk_vec3f mean = sk__export_wood_mean(scene, object);
        mat->base_color[0] *= mean.x, mat->base_color[1] *= mean.y, mat->base_color[2] *= mean.z;
    }
    snprintf(mesh->name, sizeof mesh->name, "%s", object_name);
    mesh->material = e->material_count - 1;
    mesh->scene_mesh = in->mesh;
    mesh->scene_material = in->material;
    mesh->per_object = true;
    e->object_mesh[object] = e->mesh_count++;
    return SK_OK;
}

/* Any other object: the material once per scene material, the mesh once per pair. */
static sk_result add_shared(const sk_render_scene *scene, int object, bool textures, int size,
                            int *material_of, sk__export *e, sk_error *err)
{
    const sk__instance *in = &scene->instances[object];
    sk_result r;
    if (material_of[in->material] < 0) {
        r = sk__export_material_make(scene, in->material, textures, size,
                                     &e->materials[e->material_count], err);
        if (r != SK_OK) return r;
        material_of[in->material] = e->material_count++;
    }
    for (int k = 0; k < e->mesh_count; k++) {
        const sk__export_mesh *m = &e->meshes[k];
        if (!m->per_object && m->scene_mesh == in->mesh && m->scene_material == in->material) {
            e->object_mesh[object] = k;
            return SK_OK;
        }
    }
    sk__export_mesh *mesh = &e->meshes[e->mesh_count];
    const sk__export_material *mat = &e->materials[material_of[in->material]];
    r = copy_mesh(scene, in->mesh, in->material, textures, mat->normal_texture.data != NULL,
                  &mesh->mesh, err);
    if (r != SK_OK) return r;
    sk__export_object_name(scene, object, mesh->name, sizeof mesh->name);
    mesh->material = material_of[in->material];
    mesh->scene_mesh = in->mesh;
    mesh->scene_material = in->material;
    e->object_mesh[object] = e->mesh_count++;
    return SK_OK;
}

/* The side of a wood object's texture: texture_size scaled by the square root of its area
 * relative to the largest wood object's, up to a power of two (at least 64). */
static int wood_texture_size(int size, double area, double largest)
{
    double want = largest > 0 ? size * sqrt(area / largest) : size;
    int side = 64 < size ? 64 : size;
    while (side < size && side < want) side *= 2;
    return side < size ? side : size;
}

sk_result sk__export_build(const sk_render_scene *scene, const sk_render_export_desc *desc,
                           sk__export *out, sk_error *err)
{
    memset(out, 0, sizeof *out);
    int size = desc->texture_size ? desc->texture_size : DEFAULT_TEXTURE_SIZE;
    sk_result r = sk_check_range_i(err, "texture_size", size, 16, 8192);
    if (r != SK_OK) return r;
    bool textures = !desc->no_textures;
    int objects = scene->instance_count;
    out->object_count = objects;
    out->materials = calloc((size_t)(scene->material_count + objects), sizeof *out->materials);
    out->meshes = calloc((size_t)(objects > 0 ? objects : 1), sizeof *out->meshes);
    if (!out->materials || !out->meshes) {
        sk__export_free(out);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for the export");
    }
    int material_of[SK_RENDER_MAX_MATERIALS + 1];
    for (int i = 0; i <= SK_RENDER_MAX_MATERIALS; i++) material_of[i] = -1;
    /* wood textures share one density: the largest wood object gets texture_size */
    double area[SK_RENDER_MAX_OBJECTS], largest = 0;
    for (int i = 0; i < objects; i++) {
        area[i] = scene->materials[scene->instances[i].material].wood
                      ? sk__export_surface_mm2(scene, i)
                      : 0;
        if (area[i] > largest) largest = area[i];
    }
    for (int i = 0; i < objects && r == SK_OK; i++) {
        if (scene->materials[scene->instances[i].material].wood)
            r = add_wood(scene, i, textures, wood_texture_size(size, area[i], largest), out, err);
        else
            r = add_shared(scene, i, textures, size, material_of, out, err);
        if (r != SK_OK) sk_error_prefix(err, r, "objects[%d]", i);
        sk_progress_report(&desc->progress, (double)(i + 1) / objects);
    }
    if (r != SK_OK) {
        sk__export_free(out);
        return r;
    }
    /* tools find materials by name (MTL always, glTF importers often): keep them distinct */
    for (int k = 1; k < out->material_count; k++)
        for (int j = 0; j < k; j++)
            if (strcmp(out->materials[j].name, out->materials[k].name) == 0) {
                char base[SK__EXPORT_NAME_SIZE];
                snprintf(base, sizeof base, "%s", out->materials[k].name);
                snprintf(out->materials[k].name, sizeof out->materials[k].name, "%.*s-%d",
                         (int)sizeof base - 8, base, k);
                break;
            }
    return SK_OK;
}

/* Bytes of an export copy of a mesh of v vertices and t triangles: positions, normals,
   uvs and tangents, and the indices. */
static double mesh_bytes(double v, double t) { return v * (12 + 12 + 8 + 16) + t * 12; }

double sk_render_scene_export_memory(const sk_render_scene *scene,
                                     const sk_render_export_desc *desc)
{
    double size = desc && desc->texture_size > 0 ? desc->texture_size : DEFAULT_TEXTURE_SIZE;
    bool textures = !(desc && desc->no_textures);
    double texels = size * size, bytes = 0;
    for (int i = 0; i < scene->instance_count; i++) {
        const sk__instance *in = &scene->instances[i];
        const sk_mesh *m = &scene->meshes[in->mesh].mesh;
        double v = (double)m->vertex_count, t = (double)m->triangle_count;
        if (textures && scene->materials[in->material].wood)
            /* unwelded onto the atlas; the texture and the texel owners while baking */
            bytes += mesh_bytes(3 * t, t) + texels * (12 + 8);
        else
            bytes += mesh_bytes(v, t);
    }
    for (int k = 0; textures && k < scene->material_count; k++) {
        const sk__material *m = &scene->materials[k];
        if (m->skin) bytes += texels * (12 + 16); /* the normal tile and the skin's pixels */
        int maps[2] = {m->albedo_texture, m->normal_map};
        for (int j = 0; j < 2 && !m->skin; j++)
            if (maps[j] >= 0)
                bytes += 12.0 * scene->textures[maps[j]].image.width *
                         scene->textures[maps[j]].image.height;
    }
    /* the writers put the meshes together once more (one OBJ mesh, the GLB buffer), with the
       encoded textures */
    return 2 * bytes;
}

sk_result sk_render_scene_export(const sk_render_scene *scene, const char *path,
                                 const sk_render_export_desc *desc, sk_error *err)
{
    if (!scene || !path) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "scene or path is NULL");
    bool glb = sk__has_extension(path, ".glb"), obj = sk__has_extension(path, ".obj");
    if (!glb && !obj)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "%s: the export format follows the extension, .glb or .obj", path);
    sk_render_export_desc d = {0};
    if (desc) d = *desc;
    /* the files are reserved (their paths checked) before the baking */
    sk_output_set *own = NULL, *set = d.outputs;
    sk_result r = set ? SK_OK : sk_output_set_create(&own, err);
    if (!set) set = own;
    sk__export_files files = {.set = set, .path = path};
    if (r == SK_OK) r = sk_output_set_file(set, path, &files.staged, err);
    char *mtl = obj && r == SK_OK ? sk_obj_mtl_path(path) : NULL;
    if (obj && r == SK_OK && !mtl) r = sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    if (mtl && r == SK_OK) r = sk_output_set_file(set, mtl, &files.staged_mtl, err);
    files.mtl = mtl;
    sk__export e;
    if (r == SK_OK && (r = sk__export_build(scene, &d, &e, err)) == SK_OK) {
        r = glb ? sk__export_write_glb(scene, &e, files.staged, err)
                : sk__export_write_obj(scene, &e, &files, err);
        sk__export_free(&e);
    }
    free(mtl);
    if (own && r == SK_OK)
        r = sk_output_set_commit(own, err);
    else if (own)
        sk_output_set_abort(own);
    return r;
}
