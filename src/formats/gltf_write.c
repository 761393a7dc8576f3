/* The glTF writer: the document as glTF 2.0 JSON (one scene of every root node, meshes,
 * materials, PNG textures, skins, animations) and its binary chunk, in a GLB container
 * (sec. 4.4: 12-byte header, a JSON chunk padded with spaces, a BIN chunk padded with
 * zeros), the same bytes for the same document; to memory or atomically to a file. */
#define _POSIX_C_SOURCE 200809L
#include <stdlib.h>
#include <string.h>

#include "formats/gltf_internal.h"
#include "shitsukan/io.h"

#define J(call) sk__gltf_json(out, (call))

static void add_number(sk__gltf_out *out, cJSON *obj, const char *key, double v)
{
    J(cJSON_AddNumberToObject(obj, key, v));
}

static void add_doubles(sk__gltf_out *out, cJSON *obj, const char *key, const double *v, int n)
{
    cJSON *a = J(cJSON_AddArrayToObject(obj, key));
    for (int i = 0; a && i < n; i++) cJSON_AddItemToArray(a, J(cJSON_CreateNumber(v[i])));
}

static void add_floats(sk__gltf_out *out, cJSON *obj, const char *key, const float *v, int n)
{
    cJSON *a = J(cJSON_AddArrayToObject(obj, key));
    for (int i = 0; a && i < n; i++) cJSON_AddItemToArray(a, J(cJSON_CreateNumber(v[i])));
}

static void write_asset(sk__gltf_out *out, cJSON *root, const sk_gltf_write_desc *desc)
{
    cJSON *asset = J(cJSON_AddObjectToObject(root, "asset"));
    if (!asset) return;
    const char *generator =
        desc && desc->generator ? desc->generator : "shitsukan " SK_VERSION_STRING;
    J(cJSON_AddStringToObject(asset, "generator", generator));
    if (desc && desc->copyright) J(cJSON_AddStringToObject(asset, "copyright", desc->copyright));
    J(cJSON_AddStringToObject(asset, "version", "2.0"));
}

static void write_nodes(sk__gltf_out *out, cJSON *root, const sk_gltf *g)
{
    if (g->node_count == 0) return;
    add_number(out, root, "scene", 0);
    cJSON *scenes = J(cJSON_AddArrayToObject(root, "scenes"));
    cJSON *scene = J(cJSON_CreateObject());
    if (!scenes || !scene) return;
    cJSON_AddItemToArray(scenes, scene);
    cJSON *roots = J(cJSON_AddArrayToObject(scene, "nodes"));
    cJSON *nodes = J(cJSON_AddArrayToObject(root, "nodes"));
    if (!roots || !nodes) return;
    for (int i = 0; i < g->node_count; i++) {
        const sk__gltf_node *n = &g->nodes[i];
        if (n->parent == SK_GLTF_NONE) cJSON_AddItemToArray(roots, J(cJSON_CreateNumber(i)));
        cJSON *node = J(cJSON_CreateObject());
        if (!node) return;
        cJSON_AddItemToArray(nodes, node);
        J(cJSON_AddStringToObject(node, "name", n->name));
        if (n->has_child) {
            cJSON *children = J(cJSON_AddArrayToObject(node, "children"));
            for (int c = i + 1; children && c < g->node_count; c++)
                if (g->nodes[c].parent == i)
                    cJSON_AddItemToArray(children, J(cJSON_CreateNumber(c)));
        }
        if (n->mesh != SK_GLTF_NONE) add_number(out, node, "mesh", n->mesh);
        if (n->skin != SK_GLTF_NONE) add_number(out, node, "skin", n->skin);
        const double *t = n->translation, *r = n->rotation, *s = n->scale;
        if (t[0] != 0 || t[1] != 0 || t[2] != 0) add_doubles(out, node, "translation", t, 3);
        if (r[0] != 0 || r[1] != 0 || r[2] != 0 || r[3] != 1)
            add_doubles(out, node, "rotation", r, 4);
        if (s[0] != 1 || s[1] != 1 || s[2] != 1) add_doubles(out, node, "scale", s, 3);
    }
}

static void write_targets(sk__gltf_out *out, cJSON *mesh_json, cJSON *primitive,
                          const sk__gltf_mesh *m)
{
    cJSON *targets = J(cJSON_AddArrayToObject(primitive, "targets"));
    size_t per_target = 3 * m->vertex_count;
    for (int t = 0; targets && t < m->target_count; t++) {
        cJSON *target = J(cJSON_CreateObject());
        if (!target) return;
        cJSON_AddItemToArray(targets, target);
        add_number(out, target, "POSITION",
                   sk__gltf_put_floats(out, m->target_positions + per_target * (size_t)t,
                                       m->vertex_count, 3, SK__GLTF_ARRAY_BUFFER, true));
        if (m->target_normals)
            add_number(out, target, "NORMAL",
                       sk__gltf_put_floats(out, m->target_normals + per_target * (size_t)t,
                                           m->vertex_count, 3, SK__GLTF_ARRAY_BUFFER, false));
    }
    bool weighted = false;
    for (int t = 0; m->default_weights && t < m->target_count; t++)
        weighted |= m->default_weights[t] != 0.0f;
    if (weighted) add_floats(out, mesh_json, "weights", m->default_weights, m->target_count);
    if (m->target_names) {
        /* the convention Blender, three.js and Babylon read the target names from */
        cJSON *extras = J(cJSON_AddObjectToObject(mesh_json, "extras"));
        cJSON *names = extras ? J(cJSON_AddArrayToObject(extras, "targetNames")) : NULL;
        for (int t = 0; names && t < m->target_count; t++)
            cJSON_AddItemToArray(names, J(cJSON_CreateString(m->target_names[t])));
    }
}

static void write_meshes(sk__gltf_out *out, cJSON *root, const sk_gltf *g)
{
    if (g->mesh_count == 0) return;
    cJSON *meshes = J(cJSON_AddArrayToObject(root, "meshes"));
    for (int i = 0; meshes && i < g->mesh_count; i++) {
        const sk__gltf_mesh *m = &g->meshes[i];
        size_t n = m->vertex_count;
        cJSON *mesh = J(cJSON_CreateObject());
        if (!mesh) return;
        cJSON_AddItemToArray(meshes, mesh);
        J(cJSON_AddStringToObject(mesh, "name", m->name));
        cJSON *primitives = J(cJSON_AddArrayToObject(mesh, "primitives"));
        cJSON *prim = J(cJSON_CreateObject());
        if (!primitives || !prim) return;
        cJSON_AddItemToArray(primitives, prim);
        cJSON *attr = J(cJSON_AddObjectToObject(prim, "attributes"));
        if (!attr) return;
        int a = SK__GLTF_ARRAY_BUFFER;
        add_number(out, attr, "POSITION", sk__gltf_put_floats(out, m->positions, n, 3, a, true));
        if (m->normals)
            add_number(out, attr, "NORMAL", sk__gltf_put_floats(out, m->normals, n, 3, a, false));
        if (m->tangents)
            add_number(out, attr, "TANGENT", sk__gltf_put_floats(out, m->tangents, n, 4, a, false));
        if (m->uvs)
            add_number(out, attr, "TEXCOORD_0", sk__gltf_put_floats(out, m->uvs, n, 2, a, false));
        if (m->colors)
            add_number(out, attr, "COLOR_0", sk__gltf_put_floats(out, m->colors, n, 3, a, false));
        if (m->joints) {
            add_number(out, attr, "JOINTS_0", sk__gltf_put_joints(out, m->joints, n, m->max_joint));
            add_number(out, attr, "WEIGHTS_0",
                       sk__gltf_put_floats(out, m->weights, n, 4, a, false));
        }
        add_number(out, prim, "indices",
                   sk__gltf_put_indices(out, m->indices, 3 * m->triangle_count, n));
        if (m->material != SK_GLTF_NONE) add_number(out, prim, "material", m->material);
        if (m->target_count > 0) write_targets(out, mesh, prim, m);
    }
}

static bool all_zero3(const float *v) { return v[0] == 0.0f && v[1] == 0.0f && v[2] == 0.0f; }

static void write_materials(sk__gltf_out *out, cJSON *root, const sk_gltf *g)
{
    if (g->image_count > 0) {
        cJSON *images = J(cJSON_AddArrayToObject(root, "images"));
        cJSON *textures = J(cJSON_AddArrayToObject(root, "textures"));
        for (int i = 0; images && textures && i < g->image_count; i++) {
            cJSON *image = J(cJSON_CreateObject()), *texture = J(cJSON_CreateObject());
            cJSON_AddItemToArray(images, image);
            cJSON_AddItemToArray(textures, texture);
            if (!image || !texture) return;
            add_number(out, image, "bufferView",
                       sk__gltf_put_view(out, g->images[i].png, g->images[i].size, 0));
            J(cJSON_AddStringToObject(image, "mimeType", "image/png"));
            add_number(out, texture, "source", i); /* one texture per image, same index */
        }
    }
    if (g->material_count == 0) return;
    cJSON *materials = J(cJSON_AddArrayToObject(root, "materials"));
    for (int i = 0; materials && i < g->material_count; i++) {
        const sk__gltf_material *m = &g->materials[i];
        cJSON *mat = J(cJSON_CreateObject());
        if (!mat) return;
        cJSON_AddItemToArray(materials, mat);
        J(cJSON_AddStringToObject(mat, "name", m->name));
        cJSON *pbr = J(cJSON_AddObjectToObject(mat, "pbrMetallicRoughness"));
        if (!pbr) return;
        const float *c = m->base_color;
        if (c[0] != 1 || c[1] != 1 || c[2] != 1 || c[3] != 1)
            add_floats(out, pbr, "baseColorFactor", c, 4);
        if (m->base_color_image >= 0) {
            cJSON *tex = J(cJSON_AddObjectToObject(pbr, "baseColorTexture"));
            if (tex) add_number(out, tex, "index", m->base_color_image);
        }
        /* glTF's defaults are metallic 1 and roughness 1: always say what is meant */
        add_number(out, pbr, "metallicFactor", m->metallic);
        add_number(out, pbr, "roughnessFactor", m->roughness);
        if (m->normal_image >= 0) {
            cJSON *tex = J(cJSON_AddObjectToObject(mat, "normalTexture"));
            if (tex) add_number(out, tex, "index", m->normal_image);
            if (tex && m->normal_scale != 1.0f) add_number(out, tex, "scale", m->normal_scale);
        }
        if (!all_zero3(m->emissive)) add_floats(out, mat, "emissiveFactor", m->emissive, 3);
        if (m->emissive_image >= 0) {
            cJSON *tex = J(cJSON_AddObjectToObject(mat, "emissiveTexture"));
            if (tex) add_number(out, tex, "index", m->emissive_image);
        }
        bool blend =
            c[3] < 1.0f || (m->base_color_image >= 0 && g->images[m->base_color_image].has_alpha);
        if (blend) J(cJSON_AddStringToObject(mat, "alphaMode", "BLEND"));
        if (m->double_sided) J(cJSON_AddBoolToObject(mat, "doubleSided", 1));
    }
}

static void write_skins(sk__gltf_out *out, cJSON *root, const sk_gltf *g)
{
    if (g->skin_count == 0) return;
    cJSON *skins = J(cJSON_AddArrayToObject(root, "skins"));
    for (int i = 0; skins && i < g->skin_count; i++) {
        const sk__gltf_skin *s = &g->skins[i];
        cJSON *skin = J(cJSON_CreateObject());
        if (!skin) return;
        cJSON_AddItemToArray(skins, skin);
        J(cJSON_AddStringToObject(skin, "name", s->name));
        add_number(out, skin, "inverseBindMatrices",
                   sk__gltf_put_floats(out, s->inverse_bind, (size_t)s->joint_count, 16, 0, false));
        cJSON *joints = J(cJSON_AddArrayToObject(skin, "joints"));
        for (int j = 0; joints && j < s->joint_count; j++)
            cJSON_AddItemToArray(joints, J(cJSON_CreateNumber(s->joints[j])));
    }
}

/* Key times shared between channels: the accessor of an earlier identical time array. */
typedef struct time_key {
    const float *times;
    int key_count, accessor;
} time_key;

static int time_accessor(sk__gltf_out *out, time_key *seen, int *seen_count, const float *times,
                         int key_count)
{
    for (int i = 0; i < *seen_count; i++)
        if (seen[i].key_count == key_count &&
            memcmp(seen[i].times, times, (size_t)key_count * sizeof(float)) == 0)
            return seen[i].accessor;
    int acc = sk__gltf_put_floats(out, times, (size_t)key_count, 1, 0, true);
    seen[*seen_count] = (time_key){times, key_count, acc};
    ++*seen_count;
    return acc;
}

static void write_animations(sk__gltf_out *out, cJSON *root, const sk_gltf *g)
{
    static const char *const paths[] = {"translation", "rotation", "scale", "weights"};
    if (g->animation_count == 0) return;
    size_t total = 0;
    for (int i = 0; i < g->animation_count; i++) total += (size_t)g->animations[i].channel_count;
    time_key *seen = malloc((total ? total : 1) * sizeof *seen);
    int seen_count = 0;
    cJSON *animations = J(cJSON_AddArrayToObject(root, "animations"));
    if (!seen) out->failed = true;
    for (int i = 0; seen && animations && i < g->animation_count; i++) {
        const sk__gltf_animation *a = &g->animations[i];
        cJSON *anim = J(cJSON_CreateObject());
        if (!anim) break;
        cJSON_AddItemToArray(animations, anim);
        J(cJSON_AddStringToObject(anim, "name", a->name));
        cJSON *channels = J(cJSON_AddArrayToObject(anim, "channels"));
        cJSON *samplers = J(cJSON_AddArrayToObject(anim, "samplers"));
        for (int c = 0; channels && samplers && c < a->channel_count; c++) {
            const sk__gltf_channel *ch = &a->channels[c];
            cJSON *channel = J(cJSON_CreateObject()), *sampler = J(cJSON_CreateObject());
            cJSON_AddItemToArray(channels, channel);
            cJSON_AddItemToArray(samplers, sampler);
            if (!channel || !sampler) break;
            add_number(out, channel, "sampler", c);
            cJSON *target = J(cJSON_AddObjectToObject(channel, "target"));
            if (target) {
                add_number(out, target, "node", ch->node);
                J(cJSON_AddStringToObject(target, "path", paths[ch->path]));
            }
            add_number(out, sampler, "input",
                       time_accessor(out, seen, &seen_count, ch->times, ch->key_count));
            J(cJSON_AddStringToObject(sampler, "interpolation",
                                      ch->interpolation == SK_GLTF_INTERPOLATION_STEP ? "STEP"
                                                                                      : "LINEAR"));
            /* morph weights: one scalar per target per key (sec. 3.11.2) */
            bool weights = ch->path == SK_GLTF_PATH_WEIGHTS;
            size_t count = (size_t)ch->key_count * (weights ? (size_t)ch->components : 1);
            add_number(out, sampler, "output",
                       sk__gltf_put_floats(out, ch->values, count, weights ? 1 : ch->components, 0,
                                           false));
        }
    }
    free(seen);
}

static sk_result check_document(const sk_gltf *g, sk_error *err)
{
    for (int i = 0; i < g->animation_count; i++)
        if (g->animations[i].channel_count == 0)
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "animations[%d] (\"%s\") has no channels: glTF requires at least one", i,
                           g->animations[i].name);
    return SK_OK;
}

/* The GLB bytes of the JSON text and the binary chunk. */
static sk_result pack_glb(const char *json, const sk__gltf_out *o, uint8_t **out_data,
                          size_t *out_size, sk_error *err)
{
    size_t json_len = strlen(json), json_padded = (json_len + 3) & ~(size_t)3;
    size_t bin_padded = (o->bin_size + 3) & ~(size_t)3;
    size_t total = SK__GLB_HEADER_BYTES + SK__GLB_CHUNK_HEADER_BYTES + json_padded;
    if (bin_padded) total += SK__GLB_CHUNK_HEADER_BYTES + bin_padded;
    if (total > UINT32_MAX)
        return sk_fail(err, SK_ERROR_LIMIT, "the GLB would be %zu bytes: the format holds < 4 GiB",
                       total);
    uint8_t *p = malloc(total);
    if (!p)
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for a GLB of %zu bytes", total);
    uint32_t words[5] = {SK__GLB_MAGIC, SK__GLB_VERSION, (uint32_t)total, (uint32_t)json_padded,
                         SK__GLB_CHUNK_JSON};
    for (int w = 0; w < 5; w++)
        for (int k = 0; k < 4; k++) p[4 * w + k] = (uint8_t)(words[w] >> (8 * k));
    uint8_t *q = p + 20;
    memcpy(q, json, json_len);
    memset(q + json_len, ' ', json_padded - json_len);
    q += json_padded;
    if (bin_padded) {
        uint32_t chunk[2] = {(uint32_t)bin_padded, SK__GLB_CHUNK_BIN};
        for (int w = 0; w < 2; w++)
            for (int k = 0; k < 4; k++) q[4 * w + k] = (uint8_t)(chunk[w] >> (8 * k));
        q += 8;
        memcpy(q, o->bin, o->bin_size);
        memset(q + o->bin_size, 0, bin_padded - o->bin_size);
    }
    *out_data = p;
    *out_size = total;
    return SK_OK;
}

sk_result sk_gltf_write_glb_memory(const sk_gltf *gltf, const sk_gltf_write_desc *desc,
                                   uint8_t **out_data, size_t *out_size, sk_error *err)
{
    if (!gltf || !out_data || !out_size)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "gltf, out_data or out_size is NULL");
    *out_data = NULL;
    *out_size = 0;
    sk_result r = check_document(gltf, err);
    if (r != SK_OK) return r;
    sk__gltf_out o = {0}, *out = &o;
    cJSON *root = J(cJSON_CreateObject());
    o.accessors = J(cJSON_CreateArray());
    o.views = J(cJSON_CreateArray());
    if (!o.failed) {
        write_asset(out, root, desc);
        write_nodes(out, root, gltf);
        write_meshes(out, root, gltf);
        write_materials(out, root, gltf);
        write_skins(out, root, gltf);
        write_animations(out, root, gltf);
    }
    if (!o.failed && o.bin_size > 0) {
        cJSON_AddItemToObject(root, "accessors", o.accessors);
        cJSON_AddItemToObject(root, "bufferViews", o.views);
        o.accessors = o.views = NULL;
        cJSON *buffers = J(cJSON_AddArrayToObject(root, "buffers"));
        cJSON *buffer = J(cJSON_CreateObject());
        cJSON_AddItemToArray(buffers, buffer);
        if (buffer) add_number(out, buffer, "byteLength", (double)((o.bin_size + 3) & ~(size_t)3));
    }
    char *json = o.failed ? NULL : cJSON_PrintUnformatted(root);
    if (!json)
        r = sk_fail(err,
                    o.bin_size > (size_t)UINT32_MAX / 2 ? SK_ERROR_LIMIT : SK_ERROR_OUT_OF_MEMORY,
                    "out of memory writing glTF (or beyond the 4 GiB GLB limit)");
    else
        r = pack_glb(json, &o, out_data, out_size, err);
    free(json);
    cJSON_Delete(root);
    cJSON_Delete(o.accessors);
    cJSON_Delete(o.views);
    free(o.bin);
    return r;
}

sk_result sk_gltf_write_glb(const sk_gltf *gltf, const char *path, const sk_gltf_write_desc *desc,
                            sk_error *err)
{
    if (!path) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "output path is NULL");
    uint8_t *data = NULL;
    size_t size = 0;
    sk_result r = sk_gltf_write_glb_memory(gltf, desc, &data, &size, err);
    if (r != SK_OK) return sk_error_prefix(err, r, "%s", path);
    sk_atomic_file file;
    if ((r = sk_atomic_file_open(&file, path, err)) == SK_OK) {
        if (fwrite(data, 1, size, file.fp) != size) {
            r = sk_atomic_file_write_failed(&file, err);
        } else {
            r = sk_atomic_file_commit(&file, err);
        }
    }
    free(data);
    return r;
}
