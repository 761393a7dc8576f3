/* Scene geometry: meshes from files, the caller or the built-in primitives, one Embree
 * scene per unique mesh, instanced by every object with its transform; and the hit record
 * rebuilt from a hit (position from barycentrics in the object frame, interpolated normal,
 * UV and tangent frame). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "render/render_internal.h"

sk_mat3f sk__transform_rotation(const sk_render_transform *t)
{
    sk_mat3d rot = sk_m3d_mul(sk_m3d_rot_z(t->rotate[2]),
                              sk_m3d_mul(sk_m3d_rot_y(t->rotate[1]), sk_m3d_rot_x(t->rotate[0])));
    return sk_m3d_to_f(rot);
}

sk_mat4f sk__transform_matrix(const sk_render_transform *t)
{
    float sx = t->scale[0], sy = t->scale[1], sz = t->scale[2];
    if (sx == 0 && sy == 0 && sz == 0) sx = sy = sz = 1.0f;
    sk_mat3f lin = sk__transform_rotation(t);
    for (int i = 0; i < 3; i++) {
        lin.m[i][0] *= sx;
        lin.m[i][1] *= sy;
        lin.m[i][2] *= sz;
    }
    return sk_m4f_from_rt(lin, sk_v3f_load(t->translate));
}

static sk_vec3f apply_linear(const sk_mat4f *m, sk_vec3f v) { return sk_m4f_apply_dir(*m, v); }

/* Copies the arrays the renderer uses from a caller's mesh. */
static sk_result copy_mesh(const sk_mesh *src, sk_mesh *dst, sk_error *err)
{
    int flags = (src->normals ? SK_MESH_NORMALS : 0) | (src->uvs ? SK_MESH_UVS : 0);
    sk_result r = sk_mesh_create(dst, src->vertex_count, src->triangle_count, flags, err);
    if (r != SK_OK) return r;
    memcpy(dst->positions, src->positions, src->vertex_count * 3 * sizeof(float));
    if (src->normals) memcpy(dst->normals, src->normals, src->vertex_count * 3 * sizeof(float));
    if (src->uvs) memcpy(dst->uvs, src->uvs, src->vertex_count * 2 * sizeof(float));
    memcpy(dst->indices, src->indices, src->triangle_count * 3 * sizeof(uint32_t));
    const sk_mesh_attribute *tan = sk_mesh_find_attribute(src, "tangent");
    if (tan && tan->components == 4) {
        float *data;
        if ((r = sk_mesh_add_attribute(dst, "tangent", 4, &data, err)) != SK_OK) return r;
        memcpy(data, tan->data, src->vertex_count * 4 * sizeof(float));
    }
    return SK_OK;
}

/* Loads or builds the mesh of object i into `mesh`, with tangents. */
static sk_result object_mesh(const sk_render_scene *scene, int i, sk_mesh *mesh, sk_error *err)
{
    const sk_render_object_desc *o = &scene->desc.objects[i];
    sk_result r;
    if (o->shape != SK_RENDER_SHAPE_MESH) {
        r = sk_render_make_primitive(o, mesh, err);
        return r == SK_OK ? r : sk_error_prefix(err, r, "objects[%d]", i);
    }
    if (o->file[0]) {
        char path[2 * SK_RENDER_PATH_SIZE];
        sk__join_path(scene->desc.base_dir, o->file, path, sizeof path);
        r = sk_mesh_read(mesh, path, NULL, err);
        if (r != SK_OK) return sk_error_prefix(err, r, "objects[%d].file = \"%s\"", i, o->file);
        if (mesh->triangle_count == 0) {
            sk_mesh_free(mesh);
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "objects[%d].file = \"%s\" has no triangles", i, o->file);
        }
    } else {
        if ((r = sk_mesh_validate(o->mesh, err)) != SK_OK)
            return sk_error_prefix(err, r, "objects[%d].mesh", i);
        if (o->mesh->triangle_count == 0)
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "objects[%d].mesh has no triangles", i);
        if ((r = copy_mesh(o->mesh, mesh, err)) != SK_OK) {
            sk_mesh_free(mesh);
            return sk_error_prefix(err, r, "objects[%d].mesh", i);
        }
    }
    if (mesh->vertex_count > UINT32_MAX) {
        sk_mesh_free(mesh);
        return sk_fail(err, SK_ERROR_LIMIT, "objects[%d]: %zu vertices exceed 2^32", i,
                       mesh->vertex_count);
    }
    if ((r = sk_mesh_compute_tangents(mesh, err)) != SK_OK) {
        sk_mesh_free(mesh);
        return sk_error_prefix(err, r, "objects[%d]", i);
    }
    return SK_OK;
}

/* Objects with identical geometry settings share one mesh. */
static bool same_geometry(const sk_render_object_desc *a, const sk_render_object_desc *b)
{
    return a->shape == b->shape && strcmp(a->file, b->file) == 0 && a->mesh == b->mesh &&
           memcmp(a->size, b->size, sizeof a->size) == 0 && a->radius == b->radius &&
           a->height == b->height && a->segments == b->segments && a->rings == b->rings &&
           a->uv == b->uv;
}

static void rtc_error_handler(void *user, enum RTCError code, const char *message)
{
    sk_render_scene *scene = user;
    if (scene->rtc_error == RTC_ERROR_NONE) {
        scene->rtc_error = code;
        snprintf(scene->rtc_message, sizeof scene->rtc_message, "%s", message ? message : "");
    }
}

static sk_result rtc_check(sk_render_scene *scene, const char *what, sk_error *err)
{
    enum RTCError code = rtcGetDeviceError(scene->device);
    if (code == RTC_ERROR_NONE && scene->rtc_error == RTC_ERROR_NONE) return SK_OK;
    if (scene->rtc_error != RTC_ERROR_NONE) code = scene->rtc_error;
    sk_result r = code == RTC_ERROR_OUT_OF_MEMORY     ? SK_ERROR_OUT_OF_MEMORY
                  : code == RTC_ERROR_UNSUPPORTED_CPU ? SK_ERROR_UNSUPPORTED
                                                      : SK_ERROR_INVALID_ARGUMENT;
    return sk_fail(err, r, "%s: Embree error %d (%s)", what, (int)code, scene->rtc_message);
}

static sk_result build_mesh(sk_render_scene *scene, sk__rmesh *m, sk_error *err)
{
    sk_mesh *mesh = &m->mesh;
    const sk_mesh_attribute *tan = sk_mesh_find_attribute(mesh, "tangent");
    m->tangents = tan->data;
    sk_mesh_bounds(mesh, &m->lo, &m->hi);
    RTCGeometry g = rtcNewGeometry(scene->device, RTC_GEOMETRY_TYPE_TRIANGLE);
    if (!g) return rtc_check(scene, "creating a mesh", err);
    float *vb = rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                        3 * sizeof(float), mesh->vertex_count);
    unsigned *ib = rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                           3 * sizeof(unsigned), mesh->triangle_count);
    if (!vb || !ib) {
        rtcReleaseGeometry(g);
        return rtc_check(scene, "allocating mesh buffers", err);
    }
    memcpy(vb, mesh->positions, mesh->vertex_count * 3 * sizeof(float));
    memcpy(ib, mesh->indices, mesh->triangle_count * 3 * sizeof(unsigned));
    rtcCommitGeometry(g);
    m->rtc = rtcNewScene(scene->device);
    if (!m->rtc) {
        rtcReleaseGeometry(g);
        return rtc_check(scene, "creating a mesh scene", err);
    }
    rtcSetSceneBuildQuality(m->rtc, RTC_BUILD_QUALITY_HIGH);
    rtcAttachGeometryByID(m->rtc, g, 0);
    rtcReleaseGeometry(g);
    rtcCommitScene(m->rtc);
    return rtc_check(scene, "building a mesh", err);
}

static void grow_bounds(sk_render_scene *scene, const sk__instance *in, const sk__rmesh *m)
{
    for (int c = 0; c < 8; c++) {
        sk_vec3f p =
            sk_v3f(c & 1 ? m->hi.x : m->lo.x, c & 2 ? m->hi.y : m->lo.y, c & 4 ? m->hi.z : m->lo.z);
        p = sk_m4f_apply_point(in->to_world, p);
        if (!scene->has_bounds) {
            scene->lo = scene->hi = p;
            scene->has_bounds = true;
        }
        scene->lo =
            sk_v3f(fminf(scene->lo.x, p.x), fminf(scene->lo.y, p.y), fminf(scene->lo.z, p.z));
        scene->hi =
            sk_v3f(fmaxf(scene->hi.x, p.x), fmaxf(scene->hi.y, p.y), fmaxf(scene->hi.z, p.z));
    }
}

static int material_index(const sk_render_scene *scene, const char *name)
{
    if (name[0])
        for (int i = 0; i < scene->desc.material_count; i++)
            if (strcmp(scene->desc.materials[i].name, name) == 0) return i;
    return scene->material_count - 1; /* the default material */
}

sk_result sk__geometry_build(sk_render_scene *scene, sk_error *err)
{
    const sk_render_scene_desc *d = &scene->desc;
    /* Embree's own thread pool (used for the BVH build) gets the same cap as the
       renderer's loops, so --threads limits the whole run. */
    char config[32];
    snprintf(config, sizeof config, "threads=%d", sk_threads_max());
    scene->device = rtcNewDevice(config);
    if (!scene->device)
        return sk_fail(err, SK_ERROR_UNSUPPORTED, "Embree device: error %d",
                       (int)rtcGetDeviceError(NULL));
    rtcSetDeviceErrorFunction(scene->device, rtc_error_handler, scene);
    size_t mesh_slots = (size_t)(d->object_count > 0 ? d->object_count : 1);
    scene->meshes = calloc(mesh_slots, sizeof *scene->meshes);
    if (!scene->meshes) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for meshes");
    int mesh_of[SK_RENDER_MAX_OBJECTS];
    for (int i = 0; i < d->object_count; i++) {
        mesh_of[i] = -1;
        for (int k = 0; k < i; k++)
            if (same_geometry(&d->objects[k], &d->objects[i])) mesh_of[i] = mesh_of[k];
        if (mesh_of[i] >= 0) continue;
        sk__rmesh *m = &scene->meshes[scene->mesh_count];
        sk_result r = object_mesh(scene, i, &m->mesh, err);
        if (r != SK_OK) return r;
        scene->mesh_count++;
        if ((r = build_mesh(scene, m, err)) != SK_OK)
            return sk_error_prefix(err, r, "objects[%d]", i);
        mesh_of[i] = scene->mesh_count - 1;
    }
    scene->top = rtcNewScene(scene->device);
    if (!scene->top) return rtc_check(scene, "creating the scene", err);
    rtcSetSceneBuildQuality(scene->top, RTC_BUILD_QUALITY_HIGH);
    for (int i = 0; i < d->object_count; i++) {
        sk__instance *in = &scene->instances[i];
        in->mesh = mesh_of[i];
        in->material = material_index(scene, d->objects[i].material);
        in->to_world = sk__transform_matrix(&d->objects[i].transform);
        in->rotation = sk__transform_rotation(&d->objects[i].transform);
        if (!sk_m4f_affine_inverse(in->to_world, &in->to_object))
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "objects[%d].transform is singular", i);
        sk_mat3f inv;
        for (int r = 0; r < 3; r++)
            for (int c = 0; c < 3; c++) inv.m[r][c] = in->to_object.m[r][c];
        in->normal_matrix = sk_m3f_transpose(inv);
        sk_mat3d lin;
        for (int r = 0; r < 3; r++)
            for (int c = 0; c < 3; c++) lin.m[r][c] = in->to_world.m[r][c];
        in->handedness = sk_m3d_det(lin) < 0 ? -1.0f : 1.0f;
        RTCGeometry g = rtcNewGeometry(scene->device, RTC_GEOMETRY_TYPE_INSTANCE);
        if (!g) return rtc_check(scene, "creating an instance", err);
        rtcSetGeometryInstancedScene(g, scene->meshes[in->mesh].rtc);
        float xfm[12];
        for (int r = 0; r < 3; r++)
            for (int c = 0; c < 4; c++) xfm[4 * r + c] = in->to_world.m[r][c];
        rtcSetGeometryTransform(g, 0, RTC_FORMAT_FLOAT3X4_ROW_MAJOR, xfm);
        rtcCommitGeometry(g);
        rtcAttachGeometryByID(scene->top, g, (unsigned)i);
        rtcReleaseGeometry(g);
        grow_bounds(scene, in, &scene->meshes[in->mesh]);
    }
    scene->instance_count = d->object_count;
    rtcCommitScene(scene->top);
    return rtc_check(scene, "building the scene", err);
}

void sk__geometry_destroy(sk_render_scene *scene)
{
    if (scene->top) rtcReleaseScene(scene->top);
    for (int i = 0; i < scene->mesh_count; i++) {
        if (scene->meshes[i].rtc) rtcReleaseScene(scene->meshes[i].rtc);
        sk_mesh_free(&scene->meshes[i].mesh);
    }
    free(scene->meshes);
    if (scene->device) rtcReleaseDevice(scene->device);
}

void sk__geometry_hit(const sk_render_scene *scene, unsigned instance, unsigned triangle, float u,
                      float v, sk__shading *sh)
{
    const sk__instance *in = &scene->instances[instance];
    const sk__rmesh *m = &scene->meshes[in->mesh];
    const sk_mesh *mesh = &m->mesh;
    const uint32_t *ix = mesh->indices + 3 * (size_t)triangle;
    float b0 = 1.0f - u - v;
    const float *P = mesh->positions;
    sk_vec3f p0 = sk_v3f_load(P + 3 * ix[0]), p1 = sk_v3f_load(P + 3 * ix[1]),
             p2 = sk_v3f_load(P + 3 * ix[2]);
    sk_vec3f e1 = sk_v3f_sub(p1, p0), e2 = sk_v3f_sub(p2, p0);
    sk_vec3f p_obj = sk_v3f_add(p0, sk_v3f_add(sk_v3f_scale(e1, u), sk_v3f_scale(e2, v)));
    sk_vec3f ng_obj = sk_v3f_normalize(sk_v3f_cross(e1, e2));
    sk_vec3f n_obj = ng_obj;
    if (mesh->normals) {
        const float *N = mesh->normals;
        sk_vec3f n = sk_v3f_add(sk_v3f_scale(sk_v3f_load(N + 3 * ix[0]), b0),
                                sk_v3f_add(sk_v3f_scale(sk_v3f_load(N + 3 * ix[1]), u),
                                           sk_v3f_scale(sk_v3f_load(N + 3 * ix[2]), v)));
        if (sk_v3f_dot(n, n) > 0) n_obj = sk_v3f_normalize(n);
    }
    sk_vec2f uv = sk_v2f(0, 0);
    float du_len = 0, dv_len = 0;
    sk_vec3f dpdu = sk_v3f(0, 0, 0);
    if (mesh->uvs) {
        const float *T = mesh->uvs;
        sk_vec2f t0 = sk_v2f(T[2 * ix[0]], T[2 * ix[0] + 1]);
        sk_vec2f t1 = sk_v2f(T[2 * ix[1]], T[2 * ix[1] + 1]);
        sk_vec2f t2 = sk_v2f(T[2 * ix[2]], T[2 * ix[2] + 1]);
        uv = sk_v2f(b0 * t0.x + u * t1.x + v * t2.x, b0 * t0.y + u * t1.y + v * t2.y);
        /* the triangle's dP/du, dP/dv give the surface length per unit of u and v */
        float a1 = t1.x - t0.x, c1 = t1.y - t0.y, a2 = t2.x - t0.x, c2 = t2.y - t0.y;
        float det = a1 * c2 - a2 * c1;
        if (det != 0.0f && isfinite(det)) {
            dpdu = sk_v3f_scale(sk_v3f_sub(sk_v3f_scale(e1, c2), sk_v3f_scale(e2, c1)), 1.0f / det);
            sk_vec3f dpdv =
                sk_v3f_scale(sk_v3f_sub(sk_v3f_scale(e2, a1), sk_v3f_scale(e1, a2)), 1.0f / det);
            du_len = sk_v3f_length(apply_linear(&in->to_world, dpdu));
            dv_len = sk_v3f_length(apply_linear(&in->to_world, dpdv));
        }
    }
    const float *TG = m->tangents;
    sk_vec3f t_obj = sk_v3f_add(sk_v3f_scale(sk_v3f_load(TG + 4 * ix[0]), b0),
                                sk_v3f_add(sk_v3f_scale(sk_v3f_load(TG + 4 * ix[1]), u),
                                           sk_v3f_scale(sk_v3f_load(TG + 4 * ix[2]), v)));
    float w = TG[4 * ix[0] + 3];

    sk_render_surface *s = &sh->surface;
    s->point = sk_m4f_apply_point(in->to_world, p_obj);
    s->normal = sk_v3f_normalize(sk_m3f_apply(in->normal_matrix, n_obj));
    /* the object frame of solid textures: translation and rotation undone, scale kept */
    sk_mat3f unrotate = sk_m3f_transpose(in->rotation);
    s->object_point = sk_m3f_apply(unrotate, sk_v3f(s->point.x - in->to_world.m[0][3],
                                                    s->point.y - in->to_world.m[1][3],
                                                    s->point.z - in->to_world.m[2][3]));
    s->object_normal = sk_m3f_apply(unrotate, s->normal);
    sh->geometric_normal = sk_v3f_normalize(sk_m3f_apply(in->normal_matrix, ng_obj));
    sk_vec3f t = apply_linear(&in->to_world, t_obj);
    t = sk_v3f_sub(t, sk_v3f_scale(s->normal, sk_v3f_dot(s->normal, t)));
    if (!(sk_v3f_dot(t, t) > 1e-20f)) {
        sk_vec3f b;
        sk_v3f_basis(s->normal, &t, &b);
    }
    s->tangent = sk_v3f_normalize(t);
    s->bitangent = sk_v3f_scale(sk_v3f_cross(s->normal, s->tangent), w * in->handedness);
    s->uv = uv;
    s->object = (int)instance;
    sh->du_len = du_len;
    sh->dv_len = dv_len;
    sh->instance = in;
    sh->material = &scene->materials[in->material];
}

void sk__shading_face(sk__shading *sh, sk_vec3f ray_dir)
{
    sh->to_viewer = sk_v3f_neg(sk_v3f_normalize(ray_dir));
    if (sk_v3f_dot(sh->geometric_normal, sh->to_viewer) < 0.0f) {
        /* the back of the surface: the same height field seen from behind */
        sh->geometric_normal = sk_v3f_neg(sh->geometric_normal);
        sk_render_surface *s = &sh->surface;
        s->normal = sk_v3f_neg(s->normal);
        s->object_normal = sk_v3f_neg(s->object_normal);
        s->tangent = sk_v3f_neg(s->tangent);
        s->bitangent = sk_v3f_neg(s->bitangent);
    }
}

void sk_render_scene_intersect(const sk_render_scene *scene, sk_vec3f origin, sk_vec3f direction,
                               float max_distance, sk_render_hit *hit)
{
    memset(hit, 0, sizeof *hit);
    hit->object = -1;
    struct RTCRayHit rh;
    sk__rtc_ray(&rh.ray, origin, direction, 0.0f, max_distance > 0 ? max_distance : INFINITY);
    if (!sk__trace(scene, &rh)) return;
    sk__shading sh;
    sk__geometry_hit(scene, rh.hit.instID[0], rh.hit.primID, rh.hit.u, rh.hit.v, &sh);
    hit->hit = true;
    hit->distance = rh.ray.tfar;
    hit->point = sh.surface.point;
    hit->normal = sh.surface.normal;
    hit->geometric_normal = sh.geometric_normal;
    hit->tangent = sh.surface.tangent;
    hit->uv = sh.surface.uv;
    hit->object = sh.surface.object;
    hit->triangle = rh.hit.primID;
}
