/* The skinned hand as glTF 2.0 (thesis 4.1.5-4.1.6 and 4.2 as a file others import): the
 * link tree as joint nodes, the relaxed pose as the bind pose, the levels of detail as
 * skinned meshes sharing one skin, the thesis's texture/shading blend as far as glTF's
 * material expresses it, and a keyframe animation of the joints. Metres, the hand frame
 * kept as glTF's axes (Y distal = up, Z palmar = front). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "models/hand_surface/surface_internal.h"

#define MAX_LODS 8
#define MAX_FRAMES 1000000
#define MM_TO_M 1e-3

/* A plain skin colour (linear) for a hand without a texture: between the generated
   texture's back and palm colours. */
static const float plain_skin[3] = {0.62f, 0.385f, 0.30f};

/* The joint node of a link: its frame in its parent link's frame (the root: in the world),
 * translation in metres, rotation as a unit quaternion (x, y, z, w). */
static void local_transform(const sk_hand_skeleton *s, const sk_hand_frames *fr, int link,
                            double t[3], double q[4])
{
    int parent = s->parent[link];
    sk_vec3d p = fr->point[sk_hand_link_point(link)];
    sk_mat3d r = fr->rotation[link];
    if (parent >= 0) {
        sk_mat3d rpt = sk_m3d_transpose(fr->rotation[parent]);
        p = sk_m3d_apply(rpt, sk_v3d_sub(p, fr->point[sk_hand_link_point(parent)]));
        r = sk_m3d_mul(rpt, r);
    }
    sk_quatd u = sk_qd_normalize(sk_m3d_to_qd(r));
    t[0] = p.x * MM_TO_M, t[1] = p.y * MM_TO_M, t[2] = p.z * MM_TO_M;
    q[0] = u.x, q[1] = u.y, q[2] = u.z, q[3] = u.w;
}

static sk_result check_desc(const sk_hand_gltf_desc *d, sk_error *err)
{
    if (!d->lods) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "lods is NULL");
    sk_result r = sk_check_range_i(err, "lod_count", d->lod_count, 1, MAX_LODS);
    if (r == SK_OK) r = sk_check_range_i(err, "frame_count", d->frame_count, 1, MAX_FRAMES);
    if (r != SK_OK) return r;
    for (int l = 0; l < d->lod_count; l++) {
        if (!d->lods[l]) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "lods[%d] is NULL", l);
        if (memcmp(&d->lods[l]->skeleton, &d->lods[0]->skeleton, sizeof(sk_hand_skeleton)) != 0)
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "lods[%d] is built on another skeleton than lods[0]: "
                           "the levels share one skin",
                           l);
    }
    if (!d->dofs) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "dofs is NULL");
    if (!d->animation && d->frame_count != 1)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "frame_count = %d without animation: a posed hand has 1 frame",
                       d->frame_count);
    for (size_t i = 0; i < (size_t)d->frame_count * SK_HAND_DOF_COUNT; i++)
        if (!isfinite(d->dofs[i]))
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "dofs[%zu] (frame %zu, %s) is not a finite number", i,
                           i / SK_HAND_DOF_COUNT, sk_hand_dof((int)(i % SK_HAND_DOF_COUNT))->name);
    if (d->fps != 0.0) r = sk_check_range_f(err, "fps", d->fps, 1e-3, 1000.0);
    if (r == SK_OK)
        r = sk_check_range_i(err, "weights", (int)d->weights, SK_HAND_WEIGHTS_DEFAULT,
                             SK_HAND_WEIGHTS_SMOOTH);
    if (r == SK_OK)
        r = sk_check_range_i(err, "material", (int)d->material, SK_HAND_GLTF_MATERIAL_DEFAULT,
                             SK_HAND_GLTF_MATERIAL_PBR);
    if (r == SK_OK) r = sk_check_range_f(err, "texture_weight", d->texture_weight, 0.0, 1.0);
    if (r == SK_OK && d->normal_map && !d->albedo)
        r = sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                    "normal_map without albedo: give both maps of the atlas");
    return r;
}

/* The skin material: the thesis renders a white surface with weak specular blended with
 * the unlit texture, (1 - w) L(white) + w albedo (4.1.6). glTF's emission is exactly an
 * unlit term, so the blend is base colour 1 - w (lit, bent by the normal map) plus the
 * albedo as emissive at w; PBR puts the albedo into the lit base colour instead. */
static sk_result add_material(sk_gltf *g, const sk_hand_gltf_desc *d, int *out, sk_error *err)
{
    float w = d->texture_weight != 0.0 ? (float)d->texture_weight : 0.7f;
    sk_gltf_material_desc m = {.name = "skin", .roughness = 0.6f, .normal_texture = d->normal_map};
    if (d->material == SK_HAND_GLTF_MATERIAL_PBR) {
        m.base_color_texture = d->albedo;
        if (!d->albedo) memcpy(m.base_color, plain_skin, sizeof plain_skin);
        m.base_color[3] = 1.0f;
        if (d->albedo) m.base_color[0] = m.base_color[1] = m.base_color[2] = 1.0f;
    } else {
        /* an all-zero base colour would mean the default white: keep a trace of it */
        float lit = fmaxf(1.0f - w, 1e-6f);
        m.base_color[0] = m.base_color[1] = m.base_color[2] = lit, m.base_color[3] = 1.0f;
        for (int c = 0; c < 3; c++) m.emissive[c] = d->albedo ? w : w * plain_skin[c];
        if (w == 0.0f)
            memset(m.emissive, 0, sizeof m.emissive);
        else
            m.emissive_texture = d->albedo;
    }
    return sk_gltf_add_material(g, &m, out, err);
}

/* One level of detail as a skinned glTF mesh: the rest mesh in metres with the atlas UVs,
 * the chosen weights per export vertex, tangents for the normal map. */
static sk_result add_lod(sk_gltf *g, const sk_hand_gltf_desc *d, const sk_hand_surface *s,
                         int level, int material, int skin, sk_error *err)
{
    sk_mesh m;
    sk_result r = sk_hand_surface_export_mesh(s, NULL, NULL, false, &m, err);
    if (r != SK_OK) return r;
    size_t n = m.vertex_count;
    uint16_t *joints = malloc(4 * n * sizeof *joints);
    float *weights = malloc(4 * n * sizeof *weights);
    if (!joints || !weights)
        r = sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for the skin weights of lods[%d]",
                    level);
    if (r == SK_OK) {
        const uint16_t *links;
        const float *lw;
        sk_hand_surface_weights(s,
                                d->weights == SK_HAND_WEIGHTS_NEAREST ? SK_HAND_WEIGHTS_NEAREST
                                                                      : SK_HAND_WEIGHTS_SMOOTH,
                                &links, &lw);
        for (size_t e = 0; e < n; e++) {
            size_t v = s->export_map[e];
            for (int k = 0; k < 4; k++) {
                weights[4 * e + k] = lw[4 * v + k];
                joints[4 * e + k] = lw[4 * v + k] > 0.0f ? links[4 * v + k] : 0;
            }
        }
        for (size_t i = 0; i < 3 * n; i++) m.positions[i] = (float)(m.positions[i] * MM_TO_M);
        if (d->normal_map) r = sk_mesh_compute_tangents(&m, err);
    }
    float *uvs = m.uvs;
    if (!d->albedo) m.uvs = NULL; /* nothing reads them: the validator would report them */
    char name[32];
    snprintf(name, sizeof name, "hand_LOD%d", level);
    int mesh = SK_GLTF_NONE, node;
    if (r == SK_OK) {
        sk_gltf_mesh_desc md = {.name = name,
                                .mesh = &m,
                                .uv_origin_bottom_left = true,
                                .material = material,
                                .joints = joints,
                                .weights = weights};
        r = sk_gltf_add_mesh(g, &md, &mesh, err);
    }
    m.uvs = uvs;
    if (r == SK_OK) {
        sk_gltf_node_desc nd = sk_gltf_node_desc_default();
        nd.name = name;
        nd.mesh = mesh;
        nd.skin = skin;
        r = sk_gltf_add_node(g, &nd, &node, err);
    }
    free(joints);
    free(weights);
    sk_mesh_free(&m);
    return r;
}

/* Every joint's rotation and the root's translation, one key per frame. Consecutive
 * quaternions are kept in one hemisphere so that interpolating between keys takes the
 * short way. */
static sk_result add_animation(sk_gltf *g, const sk_hand_gltf_desc *d, const sk_hand_skeleton *s,
                               const int *nodes, sk_error *err)
{
    int F = d->frame_count;
    double fps = d->fps != 0.0 ? d->fps : 30.0;
    float *times = malloc((size_t)F * sizeof *times);
    float *rot = malloc((size_t)F * SK_HAND_LINK_COUNT * 4 * sizeof *rot);
    float *root = malloc((size_t)F * 3 * sizeof *root);
    sk_result r = SK_OK;
    if (!times || !rot || !root)
        r = sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for %d frames", F);
    for (int f = 0; f < F && r == SK_OK; f++) {
        times[f] = (float)(f / fps);
        sk_hand_frames fr;
        sk_hand_forward(s, d->dofs + (size_t)f * SK_HAND_DOF_COUNT, &fr);
        for (int j = 0; j < SK_HAND_LINK_COUNT; j++) {
            double t[3], q[4];
            local_transform(s, &fr, j, t, q);
            float *out = rot + ((size_t)j * F + f) * 4;
            const float *prev = f > 0 ? out - 4 : NULL;
            double sign =
                prev && prev[0] * q[0] + prev[1] * q[1] + prev[2] * q[2] + prev[3] * q[3] < 0.0
                    ? -1.0
                    : 1.0;
            for (int k = 0; k < 4; k++) out[k] = (float)(sign * q[k]);
            if (j == 0)
                for (int k = 0; k < 3; k++) root[3 * f + k] = (float)t[k];
        }
    }
    int anim = SK_GLTF_NONE;
    if (r == SK_OK) r = sk_gltf_add_animation(g, "hand", &anim, err);
    for (int j = 0; j < SK_HAND_LINK_COUNT && r == SK_OK; j++)
        r = sk_gltf_add_channel(g, anim, nodes[j], SK_GLTF_PATH_ROTATION,
                                SK_GLTF_INTERPOLATION_LINEAR, times, F, rot + (size_t)j * F * 4,
                                err);
    if (r == SK_OK)
        r = sk_gltf_add_channel(g, anim, nodes[0], SK_GLTF_PATH_TRANSLATION,
                                SK_GLTF_INTERPOLATION_LINEAR, times, F, root, err);
    free(times);
    free(rot);
    free(root);
    return r;
}

sk_result sk_hand_gltf_add(sk_gltf *g, const sk_hand_gltf_desc *desc, sk_error *err)
{
    if (!g || !desc) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "gltf or desc is NULL");
    sk_result r = check_desc(desc, err);
    if (r != SK_OK) return r;
    const sk_hand_surface *base = desc->lods[0];
    const sk_hand_skeleton *s = &base->skeleton;
    /* the joints stand in the bind pose under an animation, else in the pose */
    sk_hand_frames pose;
    if (desc->animation)
        pose = base->bind;
    else
        sk_hand_forward(s, desc->dofs, &pose);
    int nodes[SK_HAND_LINK_COUNT];
    float inverse_bind[SK_HAND_LINK_COUNT][16];
    for (int j = 0; j < SK_HAND_LINK_COUNT && r == SK_OK; j++) {
        sk_gltf_node_desc nd = sk_gltf_node_desc_default();
        nd.name = sk_hand_link_name(j);
        nd.parent = s->parent[j] >= 0 ? nodes[s->parent[j]] : SK_GLTF_NONE;
        local_transform(s, &pose, j, nd.translation, nd.rotation);
        r = sk_gltf_add_node(g, &nd, &nodes[j], err);
        /* the inverse of the bind-pose world transform [R | p]: [R^T | -R^T p], column-major */
        sk_mat3d rt = sk_m3d_transpose(base->bind.rotation[j]);
        sk_vec3d t =
            sk_v3d_scale(sk_m3d_apply(rt, base->bind.point[sk_hand_link_point(j)]), -MM_TO_M);
        float *m = inverse_bind[j];
        for (int c = 0; c < 3; c++)
            for (int row = 0; row < 3; row++) m[4 * c + row] = (float)rt.m[row][c];
        m[3] = m[7] = m[11] = 0.0f;
        m[12] = (float)t.x, m[13] = (float)t.y, m[14] = (float)t.z, m[15] = 1.0f;
    }
    int skin = SK_GLTF_NONE, material = SK_GLTF_NONE;
    if (r == SK_OK)
        r = sk_gltf_add_skin(g, "hand", nodes, SK_HAND_LINK_COUNT, &inverse_bind[0][0], &skin, err);
    if (r == SK_OK) r = add_material(g, desc, &material, err);
    for (int l = 0; l < desc->lod_count && r == SK_OK; l++)
        r = add_lod(g, desc, desc->lods[l], l, material, skin, err);
    if (r == SK_OK && desc->animation) r = add_animation(g, desc, s, nodes, err);
    return r;
}

sk_result sk_hand_gltf_write(const sk_hand_gltf_desc *desc, const char *path, sk_error *err)
{
    sk_gltf *g;
    sk_result r = sk_gltf_create(&g, err);
    if (r != SK_OK) return r;
    r = sk_hand_gltf_add(g, desc, err);
    if (r == SK_OK) r = sk_gltf_write_glb(g, path, NULL, err);
    sk_gltf_destroy(g);
    return r;
}
