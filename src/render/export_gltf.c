/* The scene export as binary glTF: the export's materials and meshes, one node per object
 * with the object's transform as translation, rotation and scale (glTF's T R S is the
 * renderer's T Rz Ry Rx S), under a root node that scales scene units to metres. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "render/export_internal.h"
#include "shitsukan/gltf.h"

/* The object's transform as glTF TRS (rotation x, y, z, w). */
static void object_trs(const sk_render_transform *t, sk_gltf_node_desc *n)
{
    sk_mat3d rot = sk_m3d_mul(sk_m3d_rot_z(t->rotate[2]),
                              sk_m3d_mul(sk_m3d_rot_y(t->rotate[1]), sk_m3d_rot_x(t->rotate[0])));
    sk_quatd q = sk_qd_normalize(sk_m3d_to_qd(rot));
    for (int c = 0; c < 3; c++) n->translation[c] = t->translate[c];
    n->rotation[0] = q.x, n->rotation[1] = q.y, n->rotation[2] = q.z, n->rotation[3] = q.w;
    bool unit = t->scale[0] == 0 && t->scale[1] == 0 && t->scale[2] == 0;
    for (int c = 0; c < 3; c++) n->scale[c] = unit ? 1.0 : t->scale[c];
}

static sk_result add_materials(sk_gltf *g, const sk__export *e, int *index, sk_error *err)
{
    for (int i = 0; i < e->material_count; i++) {
        const sk__export_material *m = &e->materials[i];
        sk_gltf_material_desc d = {
            .name = m->name,
            .base_color = {m->base_color[0], m->base_color[1], m->base_color[2], 1.0f},
            .roughness = m->roughness,
            .base_color_texture = m->base_texture.data ? &m->base_texture : NULL,
            .normal_texture = m->normal_texture.data ? &m->normal_texture : NULL,
            .normal_scale = m->normal_scale,
            /* the renderer shades both sides of every surface */
            .double_sided = true,
        };
        sk_result r = sk_gltf_add_material(g, &d, &index[i], err);
        if (r != SK_OK) return r;
    }
    return SK_OK;
}

static sk_result build(const sk_render_scene *scene, const sk__export *e, sk_gltf *g, sk_error *err)
{
    int materials[SK_RENDER_MAX_MATERIALS + SK_RENDER_MAX_OBJECTS + 1],
        meshes[SK_RENDER_MAX_OBJECTS];
    sk_result r = add_materials(g, e, materials, err);
    for (int i = 0; r == SK_OK && i < e->mesh_count; i++) {
        const sk__export_mesh *m = &e->meshes[i];
        sk_gltf_mesh_desc d = {.name = m->name,
                               .mesh = &m->mesh,
                               .uv_origin_bottom_left = true,
                               .material = materials[m->material]};
        r = sk_gltf_add_mesh(g, &d, &meshes[i], err);
        if (r != SK_OK) sk_error_prefix(err, r, "mesh \"%s\"", m->name);
    }
    if (r != SK_OK) return r;
    int root;
    sk_gltf_node_desc n = sk_gltf_node_desc_default();
    n.name = "scene";
    double metres = scene->desc.unit_mm / 1000.0; /* glTF's unit */
    n.scale[0] = n.scale[1] = n.scale[2] = metres;
    if ((r = sk_gltf_add_node(g, &n, &root, err)) != SK_OK) return r;
    for (int i = 0; i < e->object_count && r == SK_OK; i++) {
        char name[SK_RENDER_NAME_SIZE + 16];
        int node;
        sk__export_object_name(scene, i, name, sizeof name);
        n = sk_gltf_node_desc_default();
        n.name = name;
        n.parent = root;
        n.mesh = meshes[e->object_mesh[i]];
        object_trs(&scene->desc.objects[i].transform, &n);
        r = sk_gltf_add_node(g, &n, &node, err);
    }
    return r;
}

sk_result sk__export_write_glb(const sk_render_scene *scene, const sk__export *e, const char *path,
                               sk_error *err)
{
    sk_gltf *g;
    sk_result r = sk_gltf_create(&g, err);
    if (r != SK_OK) return r;
    if ((r = build(scene, e, g, err)) == SK_OK) r = sk_gltf_write_glb(g, path, NULL, err);
    sk_gltf_destroy(g);
    return r;
}
