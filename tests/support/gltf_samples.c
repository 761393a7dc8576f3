/* Sample glTF documents (see gltf_samples.h): the renderer's primitives as meshes, small
 * procedural textures, a skinned chain and a morphing grid. */
#define _POSIX_C_SOURCE 200809L
#include "gltf_samples.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "shitsukan/render.h"

#define CHECK(call)                                                                                \
    do {                                                                                           \
        sk_result r_ = (call);                                                                     \
        if (r_ != SK_OK) return r_;                                                                \
    } while (0)

static sk_result primitive(sk_render_shape shape, int segments, int rings, sk_mesh *mesh,
                           sk_error *err)
{
    sk_render_object_desc o;
    memset(&o, 0, sizeof o);
    o.shape = shape;
    o.segments = segments;
    o.rings = rings;
    o.uv = SK_RENDER_UV_UNIT;
    return sk_render_make_primitive(&o, mesh, err);
}

/* A checker base colour and a normal map of bumps, 64 x 64 (powers of two). */
static sk_result textures(sk_image *colour, sk_image *normal, sk_error *err)
{
    CHECK(sk_image_create(colour, 64, 64, 3, err));
    CHECK(sk_image_create(normal, 64, 64, 3, err));
    for (int y = 0; y < 64; y++)
        for (int x = 0; x < 64; x++) {
            float *c = sk_image_pixel(colour, x, y), *n = sk_image_pixel(normal, x, y);
            bool dark = ((x / 8) + (y / 8)) % 2 == 0;
            c[0] = dark ? 0.2f : 0.9f, c[1] = 0.5f, c[2] = dark ? 0.8f : 0.1f;
            double sx = 0.4 * sin(x * 2 * SK_PI / 16), sy = 0.4 * sin(y * 2 * SK_PI / 16);
            double len = sqrt(sx * sx + sy * sy + 1);
            n[0] = (float)(sx / len), n[1] = (float)(sy / len), n[2] = (float)(1 / len);
        }
    return SK_OK;
}

static sk_result make_static(sk_gltf *g, sk_error *err)
{
    sk_mesh sphere = {0}, box = {0};
    sk_image colour = {0}, normal = {0};
    sk_result r = primitive(SK_RENDER_SHAPE_SPHERE, 32, 16, &sphere, err);
    if (r == SK_OK) r = primitive(SK_RENDER_SHAPE_BOX, 0, 0, &box, err);
    if (r == SK_OK) r = textures(&colour, &normal, err);
    if (r == SK_OK && !(box.colors = calloc(3 * box.vertex_count, sizeof(float))))
        r = SK_ERROR_OUT_OF_MEMORY;
    /* UVs without a texture that reads them would be reported as possibly unused */
    free(box.uvs);
    box.uvs = NULL;
    for (size_t v = 0; r == SK_OK && v < box.vertex_count; v++)
        for (int c = 0; c < 3; c++) box.colors[3 * v + c] = box.positions[3 * v + c] + 0.5f;
    int textured = 0, plain = 0, m0 = 0, m1 = 0, node;
    sk_gltf_material_desc md = {.name = "checker",
                                .roughness = 0.6f,
                                .base_color_texture = &colour,
                                .normal_texture = &normal,
                                .normal_scale = 0.8f};
    if (r == SK_OK) r = sk_gltf_add_material(g, &md, &textured, err);
    sk_gltf_material_desc pd = {.name = "painted",
                                .base_color = {0.8f, 0.8f, 0.8f, 1.0f},
                                .roughness = 0.3f,
                                .double_sided = true};
    if (r == SK_OK) r = sk_gltf_add_material(g, &pd, &plain, err);
    sk_gltf_mesh_desc a = {
        .name = "sphere", .mesh = &sphere, .uv_origin_bottom_left = true, .material = textured};
    sk_gltf_mesh_desc b = {
        .name = "box", .mesh = &box, .uv_origin_bottom_left = true, .material = plain};
    if (r == SK_OK) r = sk_gltf_add_mesh(g, &a, &m0, err);
    if (r == SK_OK) r = sk_gltf_add_mesh(g, &b, &m1, err);
    sk_gltf_node_desc n = sk_gltf_node_desc_default();
    n.name = "sphere";
    n.mesh = m0;
    n.translation[0] = -0.8;
    if (r == SK_OK) r = sk_gltf_add_node(g, &n, &node, err);
    n.name = "box";
    n.mesh = m1;
    n.translation[0] = 0.8;
    n.rotation[1] = sin(0.3), n.rotation[3] = cos(0.3);
    n.scale[0] = 0.5, n.scale[1] = 0.8, n.scale[2] = 0.5;
    if (r == SK_OK) r = sk_gltf_add_node(g, &n, &node, err);
    sk_mesh_free(&sphere);
    sk_mesh_free(&box);
    sk_image_free(&colour);
    sk_image_free(&normal);
    return r;
}

/* Joint j of the chain sits at y = -0.5 + j / 3 (the cylinder runs from -0.5 to 0.5). */
static void chain_weights(const sk_mesh *m, uint16_t *joints, float *weights)
{
    for (size_t v = 0; v < m->vertex_count; v++) {
        float s = (m->positions[3 * v + 1] + 0.5f) * 3.0f; /* 0..3 along the chain */
        int j = (int)floorf(s - 0.5f);
        float f = (s - 0.5f) - (float)j;
        if (j < 0) j = 0, f = 0.0f;
        if (j >= 2) j = 2, f = 0.0f;
        uint16_t *jv = joints + 4 * v;
        float *wv = weights + 4 * v;
        jv[0] = (uint16_t)j, jv[1] = (uint16_t)(j + 1 < 3 ? j + 1 : 0), jv[2] = jv[3] = 0;
        wv[0] = 1.0f - f, wv[1] = f, wv[2] = wv[3] = 0.0f;
    }
}

static sk_result make_skinned(sk_gltf *g, sk_error *err)
{
    sk_mesh cyl = {0};
    CHECK(primitive(SK_RENDER_SHAPE_CYLINDER, 24, 0, &cyl, err));
    for (size_t v = 0; v < cyl.vertex_count; v++)
        cyl.positions[3 * v] *= 0.3f, cyl.positions[3 * v + 2] *= 0.3f;
    free(cyl.uvs); /* no texture reads them */
    cyl.uvs = NULL;
    sk_result r = SK_OK;
    uint16_t *joints = malloc(4 * cyl.vertex_count * sizeof(uint16_t));
    float *weights = malloc(4 * cyl.vertex_count * sizeof(float));
    if (!joints || !weights) r = SK_ERROR_OUT_OF_MEMORY;
    if (r == SK_OK) chain_weights(&cyl, joints, weights);
    int nodes[3], mesh = 0, skin = 0, body = 0, anim = 0;
    static const char *const names[3] = {"root", "middle", "tip"};
    for (int j = 0; r == SK_OK && j < 3; j++) {
        sk_gltf_node_desc n = sk_gltf_node_desc_default();
        n.name = names[j];
        n.parent = j == 0 ? SK_GLTF_NONE : nodes[j - 1];
        n.translation[1] = j == 0 ? -0.5 + 1.0 / 6.0 : 1.0 / 3.0;
        r = sk_gltf_add_node(g, &n, &nodes[j], err);
    }
    sk_gltf_material_desc md = {.name = "rubber", .base_color = {0.7f, 0.3f, 0.2f, 1}};
    int material = 0;
    if (r == SK_OK) r = sk_gltf_add_material(g, &md, &material, err);
    sk_gltf_mesh_desc d = {.name = "cylinder",
                           .mesh = &cyl,
                           .uv_origin_bottom_left = true,
                           .material = material,
                           .joints = joints,
                           .weights = weights};
    if (r == SK_OK) r = sk_gltf_add_mesh(g, &d, &mesh, err);
    if (r == SK_OK) r = sk_gltf_add_skin(g, "chain", nodes, 3, NULL, &skin, err);
    sk_gltf_node_desc n = sk_gltf_node_desc_default();
    n.name = "cylinder";
    n.mesh = mesh;
    n.skin = skin;
    if (r == SK_OK) r = sk_gltf_add_node(g, &n, &body, err);
    if (r == SK_OK) r = sk_gltf_add_animation(g, "bend", &anim, err);
    float times[5], bend[20], lift[6] = {0, 0, 0, 0, 0.1f, 0};
    float lift_times[2] = {0.0f, 0.5f};
    for (int k = 0; k < 5; k++) {
        times[k] = 0.25f * (float)k;
        double a = 0.5 * sin(k * SK_PI / 2) / 2; /* half angle about z */
        bend[4 * k] = 0, bend[4 * k + 1] = 0, bend[4 * k + 2] = (float)sin(a),
                 bend[4 * k + 3] = (float)cos(a);
    }
    if (r == SK_OK)
        r = sk_gltf_add_channel(g, anim, nodes[1], SK_GLTF_PATH_ROTATION,
                                SK_GLTF_INTERPOLATION_LINEAR, times, 5, bend, err);
    if (r == SK_OK)
        r = sk_gltf_add_channel(g, anim, nodes[2], SK_GLTF_PATH_ROTATION,
                                SK_GLTF_INTERPOLATION_LINEAR, times, 5, bend, err);
    lift[1] = (float)(-0.5 + 1.0 / 6.0), lift[4] += lift[1];
    if (r == SK_OK)
        r = sk_gltf_add_channel(g, anim, nodes[0], SK_GLTF_PATH_TRANSLATION,
                                SK_GLTF_INTERPOLATION_STEP, lift_times, 2, lift, err);
    free(joints);
    free(weights);
    sk_mesh_free(&cyl);
    return r;
}

#define GRID 17

static sk_result make_morph(sk_gltf *g, sk_error *err)
{
    sk_mesh grid = {0};
    CHECK(sk_mesh_create(&grid, GRID * GRID, 2 * (GRID - 1) * (GRID - 1), SK_MESH_NORMALS, err));
    float *targets = calloc(2 * 3 * GRID * GRID, sizeof(float));
    float *target_normals = calloc(2 * 3 * GRID * GRID, sizeof(float));
    sk_result r = targets && target_normals ? SK_OK : SK_ERROR_OUT_OF_MEMORY;
    for (int y = 0; r == SK_OK && y < GRID; y++)
        for (int x = 0; x < GRID; x++) {
            size_t v = (size_t)(y * GRID + x);
            float u = (float)x / (GRID - 1), w = (float)y / (GRID - 1);
            float *p = grid.positions + 3 * v;
            p[0] = u - 0.5f, p[1] = 0.0f, p[2] = 0.5f - w;
            grid.normals[3 * v + 1] = 1.0f;
            double dx = u - 0.5, dz = w - 0.5, bump = exp(-(dx * dx + dz * dz) * 20);
            targets[3 * v + 1] = (float)(0.3 * bump); /* "bulge" */
            target_normals[3 * v] = (float)(0.3 * bump * 40 * dx * 0.5);
            targets[3 * GRID * GRID + 3 * v] = (float)(0.2 * dz); /* "shear" */
            if (x < GRID - 1 && y < GRID - 1) {
                uint32_t *t = grid.indices + 6 * (size_t)(y * (GRID - 1) + x);
                uint32_t a = (uint32_t)v, b = a + 1, c = a + GRID, d = c + 1;
                t[0] = a, t[1] = c, t[2] = b, t[3] = b, t[4] = c, t[5] = d;
            }
        }
    static const char *const target_names[2] = {"bulge", "shear"};
    float defaults[2] = {0.0f, 0.25f};
    sk_gltf_material_desc md = {
        .name = "clay", .base_color = {0.6f, 0.6f, 0.5f, 1}, .roughness = 0.9f};
    int material = 0, mesh = 0, node = 0, linear = 0, step = 0;
    if (r == SK_OK) r = sk_gltf_add_material(g, &md, &material, err);
    sk_gltf_mesh_desc d = {.name = "grid",
                           .mesh = &grid,
                           .uv_origin_bottom_left = true,
                           .material = material,
                           .target_count = 2,
                           .target_positions = targets,
                           .target_normals = target_normals,
                           .default_weights = defaults,
                           .target_names = target_names};
    if (r == SK_OK) r = sk_gltf_add_mesh(g, &d, &mesh, err);
    sk_gltf_node_desc n = sk_gltf_node_desc_default();
    n.name = "grid";
    n.mesh = mesh;
    if (r == SK_OK) r = sk_gltf_add_node(g, &n, &node, err);
    float times[4] = {0.0f, 0.5f, 1.0f, 1.5f};
    float weights[8] = {0, 0, 1, 0, 1, 1, 0, 0.5f};
    if (r == SK_OK) r = sk_gltf_add_animation(g, "morph_linear", &linear, err);
    if (r == SK_OK)
        r = sk_gltf_add_channel(g, linear, node, SK_GLTF_PATH_WEIGHTS, SK_GLTF_INTERPOLATION_LINEAR,
                                times, 4, weights, err);
    if (r == SK_OK) r = sk_gltf_add_animation(g, "morph_step", &step, err);
    if (r == SK_OK)
        r = sk_gltf_add_channel(g, step, node, SK_GLTF_PATH_WEIGHTS, SK_GLTF_INTERPOLATION_STEP,
                                times, 4, weights, err);
    free(targets);
    free(target_normals);
    sk_mesh_free(&grid);
    return r;
}

sk_result sk_test_gltf_sample_make(sk_test_gltf_kind kind, sk_test_gltf_sample *out, sk_error *err)
{
    static const sk_test_gltf_sample expect[SK_TEST_GLTF_KIND_COUNT] = {
        {"static", NULL, 2, 0, 0, 0},
        {"skinned", NULL, 1, 3, 1, 0},
        {"morph", NULL, 1, 0, 2, 2},
    };
    memset(out, 0, sizeof *out);
    if ((unsigned)kind >= SK_TEST_GLTF_KIND_COUNT)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "kind = %d", (int)kind);
    *out = expect[kind];
    CHECK(sk_gltf_create(&out->gltf, err));
    sk_result r = kind == SK_TEST_GLTF_STATIC    ? make_static(out->gltf, err)
                  : kind == SK_TEST_GLTF_SKINNED ? make_skinned(out->gltf, err)
                                                 : make_morph(out->gltf, err);
    if (r != SK_OK) {
        sk_gltf_destroy(out->gltf);
        out->gltf = NULL;
        if (err && err->result == SK_OK) sk_fail(err, r, "sample %s", expect[kind].name);
    }
    return r;
}
