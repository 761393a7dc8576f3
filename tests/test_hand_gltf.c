/* Tests of the hand's glTF export (the skinned surface of thesis 4.1 with the skeleton,
 * its levels of detail and a keyframe animation), read back with the project's own glTF
 * reader: the joints and their tree, the bind pose, the skin weights, the frame count and
 * timing, and the joint frames of every frame against the skeleton's forward kinematics;
 * the left hand; the desc's errors; the commands. The Khronos validator and Blender check
 * the command's files (tests/gltf/CMakeLists.txt). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gltf_read_back.h"
#include "shitsukan/gltf.h"
#include "shitsukan/hand.h"
#include "shitsukan/io.h"
#include "test_result.h"
#include "test_support.h"

#define FRAMES 13
#define FPS 24.0

typedef struct fixture {
    sk_hand_skeleton right, left;
    sk_hand_surface *fine, *coarse, *mirror;
    double dofs[FRAMES * SK_HAND_DOF_COUNT];
} fixture;

static fixture *fx;

static int setup(void **state)
{
    (void)state;
    fx = calloc(1, sizeof *fx);
    sk_hand_skeleton_desc d = {0};
    sk_error err = {0};
    if (sk_hand_skeleton_init(&fx->right, &d, &err) != SK_OK) return -1;
    d.side = SK_HAND_SIDE_LEFT;
    if (sk_hand_skeleton_init(&fx->left, &d, &err) != SK_OK) return -1;
    /* small surfaces keep the test fast; the export does not depend on the size */
    sk_hand_surface_desc sd = {.triangles = 2000, .cell_mm = 3.0};
    if (sk_hand_surface_create(&fx->fine, &fx->right, &sd, &err) != SK_OK ||
        sk_hand_surface_simplify(&fx->coarse, fx->fine, 500, &err) != SK_OK ||
        sk_hand_surface_create(&fx->mirror, &fx->left, &sd, &err) != SK_OK) {
        fprintf(stderr, "%s\n", err.message);
        return -1;
    }
    /* a motion of every kind: the wrist moving and rolling past +-180 degrees (the
       quaternions must stay in one hemisphere from key to key), fingers curling */
    double rest[SK_HAND_DOF_COUNT];
    sk_hand_relaxed(&fx->right, rest);
    for (int f = 0; f < FRAMES; f++) {
        double t = f / (double)(FRAMES - 1), *q = fx->dofs + f * SK_HAND_DOF_COUNT;
        memcpy(q, rest, sizeof rest);
        q[0] = 30 * t, q[1] = -12 * t, q[2] = 50 * sin(3 * t);
        q[sk_hand_dof_find("wrist.roll")] = (150 + 60 * t) * SK_DEG_TO_RAD;
        q[sk_hand_dof_find("wrist.flex")] = 40 * t * SK_DEG_TO_RAD;
        q[sk_hand_dof_find("I.MCP.flex")] = 80 * t * SK_DEG_TO_RAD;
        q[sk_hand_dof_find("I.PIP.flex")] = 95 * t * SK_DEG_TO_RAD;
        q[sk_hand_dof_find("T.CMC.abd")] = (20 + 40 * t) * SK_DEG_TO_RAD;
        q[sk_hand_dof_find("L.MCP.abd")] = 15 * t * SK_DEG_TO_RAD;
    }
    return 0;
}

static int teardown(void **state)
{
    (void)state;
    sk_hand_surface_destroy(fx->fine);
    sk_hand_surface_destroy(fx->coarse);
    sk_hand_surface_destroy(fx->mirror);
    free(fx);
    return 0;
}

/* The desc written to memory and read back. */
static sk_gltf_doc *write_and_read(const sk_hand_gltf_desc *d, uint8_t **bytes, size_t *size)
{
    sk_gltf *g;
    SK_ASSERT_OK(sk_gltf_create(&g, &e_));
    SK_ASSERT_OK(sk_hand_gltf_add(g, d, &e_));
    sk_gltf_doc *doc = sk_test_gltf_read_back(g, bytes, size);
    sk_gltf_destroy(g);
    return doc;
}

/* Rotation matrix of a unit quaternion (x, y, z, w). */
static sk_mat3d quat_matrix(const double q[4])
{
    sk_quatd u = sk_qd(q[3], q[0], q[1], q[2]);
    sk_mat3d m;
    double x = u.x, y = u.y, z = u.z, w = u.w;
    m.m[0][0] = 1 - 2 * (y * y + z * z), m.m[0][1] = 2 * (x * y - w * z),
    m.m[0][2] = 2 * (x * z + w * y);
    m.m[1][0] = 2 * (x * y + w * z), m.m[1][1] = 1 - 2 * (x * x + z * z),
    m.m[1][2] = 2 * (y * z - w * x);
    m.m[2][0] = 2 * (x * z - w * y), m.m[2][1] = 2 * (y * z + w * x),
    m.m[2][2] = 1 - 2 * (x * x + y * y);
    return m;
}

/* World frames of the joint nodes from local translations and rotations (parents first),
 * positions back in mm, compared with the skeleton's forward kinematics. */
static void assert_joints_match(const sk_hand_skeleton *s, const double *dofs, const double t[][3],
                                const double q[][4])
{
    sk_hand_frames fk;
    sk_hand_forward(s, dofs, &fk);
    sk_mat3d R[SK_HAND_LINK_COUNT];
    sk_vec3d P[SK_HAND_LINK_COUNT];
    for (int j = 0; j < SK_HAND_LINK_COUNT; j++) {
        sk_mat3d r = quat_matrix(q[j]);
        sk_vec3d p = sk_v3d(t[j][0], t[j][1], t[j][2]);
        int parent = s->parent[j];
        if (parent >= 0) {
            assert_true(parent < j);
            r = sk_m3d_mul(R[parent], r);
            p = sk_v3d_add(P[parent], sk_m3d_apply(R[parent], p));
        }
        R[j] = r, P[j] = p;
        sk_vec3d want = fk.point[sk_hand_link_point(j)];
        /* float metres: a few ulps of 0.2 m over a chain of five links */
        assert_float_equal(p.x * 1000, want.x, 2e-4);
        assert_float_equal(p.y * 1000, want.y, 2e-4);
        assert_float_equal(p.z * 1000, want.z, 2e-4);
        for (int a = 0; a < 3; a++)
            for (int b = 0; b < 3; b++) assert_float_equal(r.m[a][b], fk.rotation[j].m[a][b], 2e-6);
    }
}

/* ------------------------------------------------------------------ tests */

static void test_animation_reads_back(void **state)
{
    (void)state;
    const sk_hand_surface *lods[2] = {fx->fine, fx->coarse};
    sk_hand_gltf_desc d = {.lods = lods,
                           .lod_count = 2,
                           .dofs = fx->dofs,
                           .frame_count = FRAMES,
                           .animation = true,
                           .fps = FPS};
    sk_gltf_doc *doc = write_and_read(&d, NULL, NULL);
    sk_gltf_doc_counts c = sk_gltf_doc_count(doc);
    assert_int_equal(c.nodes, SK_HAND_LINK_COUNT + 2);
    assert_int_equal(c.meshes, 2);
    assert_int_equal(c.skins, 1);
    assert_int_equal(c.animations, 1);
    /* the joints: named as the BVH names them, in the link tree */
    const int *joints;
    int joint_count, ibm;
    SK_ASSERT_OK(sk_gltf_doc_get_skin(doc, 0, &joints, &joint_count, &ibm, &e_));
    assert_int_equal(joint_count, SK_HAND_LINK_COUNT);
    for (int j = 0; j < SK_HAND_LINK_COUNT; j++) {
        sk_gltf_doc_node n;
        SK_ASSERT_OK(sk_gltf_doc_get_node(doc, joints[j], &n, &e_));
        assert_string_equal(n.name, sk_hand_link_name(j));
        assert_int_equal(n.parent,
                         fx->right.parent[j] >= 0 ? joints[fx->right.parent[j]] : SK_GLTF_NONE);
    }
    /* without the animation the joints stand in the bind pose: the inverse bind matrices
       undo their world transforms */
    double t[SK_HAND_LINK_COUNT][3], q[SK_HAND_LINK_COUNT][4], rest[SK_HAND_DOF_COUNT];
    for (int j = 0; j < SK_HAND_LINK_COUNT; j++) {
        sk_gltf_doc_node n;
        SK_ASSERT_OK(sk_gltf_doc_get_node(doc, joints[j], &n, &e_));
        memcpy(t[j], n.translation, sizeof t[j]);
        memcpy(q[j], n.rotation, sizeof q[j]);
    }
    sk_hand_relaxed(&fx->right, rest);
    assert_joints_match(&fx->right, rest, (const double(*)[3])t, (const double(*)[4])q);
    float *inv = sk_test_gltf_accessor(doc, ibm, SK_HAND_LINK_COUNT, 16);
    sk_hand_frames bind;
    sk_hand_forward(&fx->right, rest, &bind);
    for (int j = 0; j < SK_HAND_LINK_COUNT; j++) {
        const float *m = inv + 16 * j;
        sk_vec3d p = sk_v3d_scale(bind.point[sk_hand_link_point(j)], 1e-3);
        /* inverse(bind) * (joint centre) = origin, inverse(bind) * (centre + R e_y) = e_y */
        sk_vec3d y = sk_v3d_add(p, sk_v3d(bind.rotation[j].m[0][1], bind.rotation[j].m[1][1],
                                          bind.rotation[j].m[2][1]));
        for (int row = 0; row < 3; row++) {
            double o = m[row] * p.x + m[4 + row] * p.y + m[8 + row] * p.z + m[12 + row];
            double e = m[row] * y.x + m[4 + row] * y.y + m[8 + row] * y.z + m[12 + row];
            assert_float_equal(o, 0.0, 1e-6);
            assert_float_equal(e, row == 1 ? 1.0 : 0.0, 1e-6);
        }
    }
    free(inv);
    /* the animation: a rotation channel per joint and the root's translation, one key per
       frame at frame / fps seconds, as the BVH export has them */
    int channels = sk_gltf_doc_channel_count(doc, 0);
    assert_int_equal(channels, SK_HAND_LINK_COUNT + 1);
    float *rot[SK_HAND_LINK_COUNT] = {NULL}, *root = NULL;
    for (int k = 0; k < channels; k++) {
        sk_gltf_doc_channel ch;
        SK_ASSERT_OK(sk_gltf_doc_get_channel(doc, 0, k, &ch, &e_));
        assert_int_equal(ch.interpolation, SK_GLTF_INTERPOLATION_LINEAR);
        float *times = sk_test_gltf_accessor(doc, ch.input_accessor, FRAMES, 1);
        for (int f = 0; f < FRAMES; f++) assert_float_equal(times[f], f / FPS, 1e-6);
        free(times);
        int j = -1;
        for (int i = 0; i < SK_HAND_LINK_COUNT; i++)
            if (joints[i] == ch.node) j = i;
        assert_true(j >= 0);
        if (ch.path == SK_GLTF_PATH_ROTATION) {
            assert_null(rot[j]);
            rot[j] = sk_test_gltf_accessor(doc, ch.output_accessor, FRAMES, 4);
        } else {
            assert_int_equal(ch.path, SK_GLTF_PATH_TRANSLATION);
            assert_int_equal(j, 0);
            root = sk_test_gltf_accessor(doc, ch.output_accessor, FRAMES, 3);
        }
    }
    assert_non_null(root);
    for (int f = 0; f < FRAMES; f++) {
        for (int j = 0; j < SK_HAND_LINK_COUNT; j++) {
            assert_non_null(rot[j]);
            for (int k = 0; k < 4; k++) q[j][k] = rot[j][4 * f + k];
            if (f > 0) {
                /* consecutive keys in one hemisphere: interpolation takes the short way */
                const float *a = rot[j] + 4 * (f - 1), *b = rot[j] + 4 * f;
                assert_true(a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3] > 0.0f);
            }
        }
        for (int k = 0; k < 3; k++) t[0][k] = root[3 * f + k];
        assert_joints_match(&fx->right, fx->dofs + f * SK_HAND_DOF_COUNT, (const double(*)[3])t,
                            (const double(*)[4])q);
    }
    for (int j = 0; j < SK_HAND_LINK_COUNT; j++) free(rot[j]);
    free(root);
    /* each level: the rest mesh in metres and the surface's smooth weights */
    for (int l = 0; l < 2; l++) {
        size_t n;
        const uint32_t *map = sk_hand_surface_export_map(lods[l], &n);
        const uint16_t *links;
        const float *w;
        sk_hand_surface_weights(lods[l], SK_HAND_WEIGHTS_SMOOTH, &links, &w);
        const sk_mesh *m = sk_hand_surface_mesh(lods[l]);
        float *pos =
            sk_test_gltf_accessor(doc, sk_gltf_doc_mesh_accessor(doc, l, "POSITION"), n, 3);
        float *jw = sk_test_gltf_accessor(doc, sk_gltf_doc_mesh_accessor(doc, l, "JOINTS_0"), n, 4);
        float *ww =
            sk_test_gltf_accessor(doc, sk_gltf_doc_mesh_accessor(doc, l, "WEIGHTS_0"), n, 4);
        for (size_t e = 0; e < n; e++) {
            size_t v = map[e];
            for (int k = 0; k < 3; k++)
                assert_float_equal(pos[3 * e + k], m->positions[3 * v + k] * 1e-3, 1e-9);
            for (int k = 0; k < 4; k++) {
                assert_float_equal(ww[4 * e + k], w[4 * v + k], 1e-6);
                if (w[4 * v + k] > 0) assert_int_equal((int)jw[4 * e + k], links[4 * v + k]);
            }
        }
        free(pos), free(jw), free(ww);
    }
    sk_gltf_doc_free(doc);
}

static void test_posed_left_hand_and_material(void **state)
{
    (void)state;
    /* one pose, no animation: the joints stand in it; the left hand's nodes are the
       mirrored skeleton's frames */
    const sk_hand_surface *lods[1] = {fx->mirror};
    const double *pose = fx->dofs + (FRAMES - 1) * SK_HAND_DOF_COUNT;
    sk_image albedo, normal;
    sk_hand_texture_desc td = {.size = 64};
    SK_ASSERT_OK(sk_hand_texture_bake(fx->mirror, &td, &albedo, &normal, &e_));
    sk_hand_gltf_desc d = {.lods = lods,
                           .lod_count = 1,
                           .dofs = pose,
                           .frame_count = 1,
                           .weights = SK_HAND_WEIGHTS_NEAREST,
                           .albedo = &albedo,
                           .normal_map = &normal};
    uint8_t *bytes;
    size_t size;
    sk_gltf_doc *doc = write_and_read(&d, &bytes, &size);
    assert_int_equal(sk_gltf_doc_count(doc).animations, 0);
    assert_int_equal(sk_gltf_doc_count(doc).images, 2);
    double t[SK_HAND_LINK_COUNT][3], q[SK_HAND_LINK_COUNT][4];
    for (int j = 0; j < SK_HAND_LINK_COUNT; j++) {
        sk_gltf_doc_node n;
        SK_ASSERT_OK(sk_gltf_doc_get_node(doc, j, &n, &e_));
        memcpy(t[j], n.translation, sizeof t[j]);
        memcpy(q[j], n.rotation, sizeof q[j]);
    }
    assert_joints_match(&fx->left, pose, (const double(*)[3])t, (const double(*)[4])q);
    /* rigid links: one joint per vertex, the nearest link */
    size_t n;
    const uint32_t *map = sk_hand_surface_export_map(fx->mirror, &n);
    const uint16_t *nearest;
    sk_hand_surface_weights(fx->mirror, SK_HAND_WEIGHTS_NEAREST, &nearest, NULL);
    float *jw = sk_test_gltf_accessor(doc, sk_gltf_doc_mesh_accessor(doc, 0, "JOINTS_0"), n, 4);
    float *ww = sk_test_gltf_accessor(doc, sk_gltf_doc_mesh_accessor(doc, 0, "WEIGHTS_0"), n, 4);
    for (size_t e = 0; e < n; e++) {
        assert_true(ww[4 * e] == 1.0f && ww[4 * e + 1] == 0.0f);
        assert_int_equal((int)jw[4 * e], nearest[4 * map[e]]);
    }
    free(jw), free(ww);
    assert_true(sk_gltf_doc_mesh_accessor(doc, 0, "TANGENT") >= 0);
    assert_true(sk_gltf_doc_mesh_accessor(doc, 0, "TEXCOORD_0") >= 0);
    sk_gltf_doc_free(doc);
    /* the thesis's blend: lit white at 0.3, the texture unlit (emissive) at 0.7 */
    uint32_t json_length;
    memcpy(&json_length, bytes + 12, 4);
    char *json = calloc(1, json_length + 1);
    memcpy(json, bytes + 20, json_length);
    assert_non_null(strstr(json, "\"emissiveTexture\""));
    assert_non_null(
        strstr(json, "\"emissiveFactor\":[0.699999988079071,0.699999988079071,0.699999988079071]"));
    assert_non_null(strstr(
        json, "\"baseColorFactor\":[0.300000011920929,0.300000011920929,0.300000011920929,1]"));
    free(json);
    free(bytes);
    /* PBR: the albedo is the lit base colour, nothing emitted */
    d.material = SK_HAND_GLTF_MATERIAL_PBR;
    doc = write_and_read(&d, &bytes, &size);
    sk_gltf_doc_free(doc);
    memcpy(&json_length, bytes + 12, 4);
    json = calloc(1, json_length + 1);
    memcpy(json, bytes + 20, json_length);
    assert_null(strstr(json, "emissive"));
    assert_non_null(strstr(json, "\"baseColorTexture\""));
    free(json);
    free(bytes);
    /* without a texture: a plain colour and no uvs (nothing would read them) */
    d.albedo = d.normal_map = NULL;
    doc = write_and_read(&d, NULL, NULL);
    assert_int_equal(sk_gltf_doc_mesh_accessor(doc, 0, "TEXCOORD_0"), -1);
    assert_int_equal(sk_gltf_doc_count(doc).images, 0);
    sk_gltf_doc_free(doc);
    sk_image_free(&albedo);
    sk_image_free(&normal);
}

static void test_desc_errors(void **state)
{
    (void)state;
    const sk_hand_surface *lods[2] = {fx->fine, fx->mirror};
    double nan_pose[SK_HAND_DOF_COUNT];
    memcpy(nan_pose, fx->dofs, sizeof nan_pose);
    nan_pose[sk_hand_dof_find("R.PIP.flex")] = NAN;
    sk_image img = {0};
    struct {
        sk_hand_gltf_desc d;
        const char *needle;
    } bad[] = {
        {{.lods = NULL, .lod_count = 1, .dofs = fx->dofs, .frame_count = 1}, "lods"},
        {{.lods = lods, .lod_count = 0, .dofs = fx->dofs, .frame_count = 1}, "lod_count"},
        {{.lods = lods, .lod_count = 2, .dofs = fx->dofs, .frame_count = 1}, "another skeleton"},
        {{.lods = lods, .lod_count = 1, .dofs = fx->dofs, .frame_count = 0}, "frame_count"},
        {{.lods = lods, .lod_count = 1, .dofs = fx->dofs, .frame_count = 2}, "without animation"},
        {{.lods = lods, .lod_count = 1, .dofs = nan_pose, .frame_count = 1}, "R.PIP.flex"},
        {{.lods = lods, .lod_count = 1, .dofs = NULL, .frame_count = 1}, "dofs"},
        {{.lods = lods, .lod_count = 1, .dofs = fx->dofs, .frame_count = 1, .fps = -1}, "fps"},
        {{.lods = lods, .lod_count = 1, .dofs = fx->dofs, .frame_count = 1, .texture_weight = 1.5},
         "texture_weight"},
        {{.lods = lods, .lod_count = 1, .dofs = fx->dofs, .frame_count = 1, .material = 7},
         "material"},
        {{.lods = lods, .lod_count = 1, .dofs = fx->dofs, .frame_count = 1, .normal_map = &img},
         "normal_map"},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        sk_gltf *g;
        SK_ASSERT_OK(sk_gltf_create(&g, &e_));
        sk_error err = {0};
        sk_test_expect_failure(sk_hand_gltf_add(g, &bad[i].d, &err), &err,
                               SK_ERROR_INVALID_ARGUMENT, bad[i].needle);
        /* nothing added: the document still writes as an empty one */
        uint8_t *data;
        size_t size;
        SK_ASSERT_OK(sk_gltf_write_glb_memory(g, NULL, &data, &size, &e_));
        sk_gltf_doc *doc;
        SK_ASSERT_OK(sk_gltf_read_glb_memory(&doc, data, size, NULL, &e_));
        assert_int_equal(sk_gltf_doc_count(doc).nodes, 0);
        sk_gltf_doc_free(doc);
        free(data);
        sk_gltf_destroy(g);
    }
}

/* The commands: `hand mesh -o x.glb` (a pose, three levels), `hand animate --glb` (the
 * frames of the BVH export), bad options refused with no file. */
static void test_commands(void **state)
{
    (void)state;
    sk_test_run run;
    const char *glb = sk_test_path("cli/hand.glb");
    assert_int_equal(
        sk_test_cli(&run, "hand mesh -q --pin I.PIP.flex=90 --texture-size 64 -o %s", glb), 0);
    sk_gltf_doc *doc;
    SK_ASSERT_OK(sk_gltf_read_glb(&doc, glb, NULL, &e_));
    assert_int_equal(sk_gltf_doc_count(doc).meshes, SK_HAND_LOD_COUNT);
    assert_int_equal(sk_gltf_doc_count(doc).nodes, SK_HAND_LINK_COUNT + SK_HAND_LOD_COUNT);
    assert_int_equal(sk_gltf_doc_count(doc).animations, 0);
    sk_gltf_doc_free(doc);
    const char *one = sk_test_path("cli/lod2.glb");
    assert_int_equal(
        sk_test_cli(&run, "hand mesh -q --lod 2 --left --material pbr --texture-size 64 -o %s",
                    one),
        0);
    SK_ASSERT_OK(sk_gltf_read_glb(&doc, one, NULL, &e_));
    assert_int_equal(sk_gltf_doc_count(doc).meshes, 1);
    sk_gltf_doc_free(doc);

    const char *anim = sk_test_path("cli/anim.glb"), *bvh = sk_test_path("cli/anim.bvh");
    assert_int_equal(
        sk_test_cli(&run,
                    "hand animate -q %s/hand/little-mcp.json --glb %s --bvh %s --texture-size 64",
                    SK_TEST_PRESET_DIR, anim, bvh),
        0);
    sk_bvh b;
    SK_ASSERT_OK(sk_bvh_load_file(bvh, &b, &e_));
    SK_ASSERT_OK(sk_gltf_read_glb(&doc, anim, NULL, &e_));
    assert_int_equal(sk_gltf_doc_count(doc).animations, 1);
    sk_gltf_doc_channel ch;
    SK_ASSERT_OK(sk_gltf_doc_get_channel(doc, 0, 0, &ch, &e_));
    float *times = sk_test_gltf_accessor(doc, ch.input_accessor, (size_t)b.frame_count, 1);
    assert_float_equal(times[b.frame_count - 1], (b.frame_count - 1) * b.frame_time, 1e-5);
    free(times);
    sk_gltf_doc_free(doc);
    sk_bvh_free(&b);

    const char *none = sk_test_path("cli/none.glb");
    assert_int_equal(sk_test_cli(&run, "hand mesh --material shiny -o %s", none), 2);
    assert_int_equal(sk_test_count_lines(run.err), 1);
    assert_non_null(strstr(run.err, "--material"));
    assert_int_equal(sk_test_cli(&run, "hand mesh --texture-size 10 -o %s", none), 2);
    assert_false(sk_test_file_exists(none));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_animation_reads_back),
        cmocka_unit_test(test_posed_left_hand_and_material),
        cmocka_unit_test(test_desc_errors),
        cmocka_unit_test(test_commands),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
