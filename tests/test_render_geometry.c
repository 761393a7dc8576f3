/* Renderer geometry: ray hits on the built-in primitives at known distances, normals, UVs
 * and tangent frames at known points, transforms, instancing and mesh tangents. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "test_support.h"
#include "shitsukan/render.h"

#define EPS 1e-4f

static sk_render_scene *make_scene(const sk_render_object_desc *objects, int count)
{
    sk_render_scene_desc *d = calloc(1, sizeof *d);
    assert_non_null(d);
    d->object_count = count;
    for (int i = 0; i < count; i++) d->objects[i] = objects[i];
    sk_render_scene *scene = NULL;
    sk_error err = {0};
    sk_result r = sk_render_scene_create(d, &scene, &err);
    if (r != SK_OK) fail_msg("scene: %s", err.message);
    free(d);
    return scene;
}

static sk_render_hit cast(const sk_render_scene *s, sk_vec3f o, sk_vec3f d)
{
    sk_render_hit h;
    sk_render_scene_intersect(s, o, d, 0, &h);
    return h;
}

static void assert_vec(sk_vec3f a, float x, float y, float z, float eps)
{
    if (fabsf(a.x - x) > eps || fabsf(a.y - y) > eps || fabsf(a.z - z) > eps)
        fail_msg("(%g, %g, %g) != (%g, %g, %g)", a.x, a.y, a.z, x, y, z);
}

static void assert_near(double a, double b, double eps)
{
    if (!(fabs(a - b) <= eps)) fail_msg("%.9g != %.9g (eps %g)", a, b, eps);
}

static void test_sphere_hits(void **state)
{
    (void)state;
    sk_render_object_desc o = {.shape = SK_RENDER_SHAPE_SPHERE, .radius = 2};
    sk_render_scene *s = make_scene(&o, 1);
    /* front pole of the equator (a vertex): distance 10 - 2, normal +z, tangent +x */
    sk_render_hit h = cast(s, sk_v3f(0, 0, 10), sk_v3f(0, 0, -1));
    assert_true(h.hit);
    assert_near(h.distance, 8.0, EPS);
    assert_vec(h.point, 0, 0, 2, EPS);
    assert_vec(h.normal, 0, 0, 1, EPS);
    assert_vec(h.tangent, 1, 0, 0, EPS);
    /* length UVs: u = (phi + pi) r, v = (latitude + pi/2) r */
    assert_near(h.uv.x, SK_PI * 2, 1e-4);
    assert_near(h.uv.y, SK_PI, 1e-4);
    /* the top pole: v = pi r, normal +y */
    h = cast(s, sk_v3f(0, 5, 0), sk_v3f(0, -1, 0));
    assert_near(h.distance, 3.0, EPS);
    assert_vec(h.normal, 0, 1, 0, 1e-3f);
    assert_near(h.uv.y, 2 * SK_PI, 1e-4);
    /* a ray that misses, and one that starts beyond max distance */
    h = cast(s, sk_v3f(0, 3, 10), sk_v3f(0, 0, -1));
    assert_false(h.hit);
    sk_render_scene_intersect(s, sk_v3f(0, 0, 10), sk_v3f(0, 0, -1), 7.5f, &h);
    assert_false(h.hit);
    /* the direction need not be unit: distance is the ray parameter */
    h = cast(s, sk_v3f(0, 0, 10), sk_v3f(0, 0, -2));
    assert_near(h.distance, 4.0, EPS);
    sk_render_scene_destroy(s);
}

static void test_box_faces(void **state)
{
    (void)state;
    sk_render_object_desc o = {.shape = SK_RENDER_SHAPE_BOX, .size = {2, 4, 6}};
    sk_render_scene *s = make_scene(&o, 1);
    struct {
        sk_vec3f o, d, n, t;
        float dist, u, v;
    } cases[] = {
        /* +x face: tangent -z, v up; the point (1, 1, 1) has u = 3 - 1, v = 2 + 1 */
        {{5, 1, 1}, {-1, 0, 0}, {1, 0, 0}, {0, 0, -1}, 4, 2, 3},
        {{-5, 1, 1}, {1, 0, 0}, {-1, 0, 0}, {0, 0, 1}, 4, 4, 3},
        {{0.5f, 9, -1}, {0, -1, 0}, {0, 1, 0}, {1, 0, 0}, 7, 1.5f, 4},
        {{0.5f, -9, -1}, {0, 1, 0}, {0, -1, 0}, {1, 0, 0}, 7, 1.5f, 2},
        {{0.5f, 1, 9}, {0, 0, -1}, {0, 0, 1}, {1, 0, 0}, 6, 1.5f, 3},
        {{0.5f, 1, -9}, {0, 0, 1}, {0, 0, -1}, {-1, 0, 0}, 6, 0.5f, 3},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        sk_render_hit h = cast(s, cases[i].o, cases[i].d);
        assert_true(h.hit);
        assert_near(h.distance, cases[i].dist, EPS);
        assert_vec(h.normal, cases[i].n.x, cases[i].n.y, cases[i].n.z, EPS);
        assert_vec(h.geometric_normal, cases[i].n.x, cases[i].n.y, cases[i].n.z, EPS);
        assert_vec(h.tangent, cases[i].t.x, cases[i].t.y, cases[i].t.z, EPS);
        assert_near(h.uv.x, cases[i].u, EPS);
        assert_near(h.uv.y, cases[i].v, EPS);
    }
    sk_render_scene_destroy(s);
}

static void test_cylinder_and_capsule(void **state)
{
    (void)state;
    sk_render_object_desc o[2] = {
        {.shape = SK_RENDER_SHAPE_CYLINDER, .radius = 1, .height = 4, .uv = SK_RENDER_UV_UNIT},
        {.shape = SK_RENDER_SHAPE_CAPSULE,
         .radius = 1,
         .height = 4,
         .transform = {.translate = {10, 0, 0}}},
    };
    sk_render_scene *s = make_scene(o, 2);
    /* cylinder side at its front (a vertex line), half way up: unit UVs (0.5, 0.75) */
    sk_render_hit h = cast(s, sk_v3f(0, 1, 5), sk_v3f(0, 0, -1));
    assert_int_equal(h.object, 0);
    assert_near(h.distance, 4, EPS);
    assert_vec(h.normal, 0, 0, 1, EPS);
    assert_near(h.uv.x, 0.5, EPS);
    assert_near(h.uv.y, 0.75, EPS);
    /* the flat cap */
    h = cast(s, sk_v3f(0.3f, 10, 0.2f), sk_v3f(0, -1, 0));
    assert_near(h.distance, 8, EPS);
    assert_vec(h.normal, 0, 1, 0, EPS);
    assert_vec(h.geometric_normal, 0, 1, 0, EPS);
    /* capsule: the tip of its top cap at y = h/2 + r, and arc-length v along the profile */
    h = cast(s, sk_v3f(10, 10, 0), sk_v3f(0, -1, 0));
    assert_int_equal(h.object, 1);
    assert_near(h.distance, 7, EPS);
    assert_near(h.uv.y, SK_PI + 4, 1e-4);
    h = cast(s, sk_v3f(10, -1, 5), sk_v3f(0, 0, -1));
    assert_near(h.distance, 4, EPS);
    assert_near(h.uv.y, SK_PI / 2 + 1, 1e-4); /* quarter circle plus 1 of the straight part */
    assert_near(h.uv.x, SK_PI, 1e-4);         /* half way round: u = pi r */
    sk_render_scene_destroy(s);
}

/* A plane scaled non-uniformly, rotated and moved: hits and normals follow the transform. */
static void test_transformed_instances(void **state)
{
    (void)state;
    sk_render_object_desc o[2] = {
        {.shape = SK_RENDER_SHAPE_PLANE,
         .size = {2, 0, 2},
         .transform = {.translate = {0, 0, -3}, .rotate = {(float)(SK_PI / 2), 0, 0}}},
        /* a sphere squashed to half height: the normal of a slanted point is not radial */
        {.shape = SK_RENDER_SHAPE_SPHERE,
         .radius = 1,
         .segments = 512,
         .rings = 256,
         .transform = {.translate = {5, 0, 0}, .scale = {1, 0.5f, 1}}},
    };
    sk_render_scene *s = make_scene(o, 2);
    /* the plane's +y normal turned by 90 degrees about x points to +z */
    sk_render_hit h = cast(s, sk_v3f(0.2f, 0.3f, 0), sk_v3f(0, 0, -1));
    assert_true(h.hit);
    assert_near(h.distance, 3, EPS);
    assert_vec(h.normal, 0, 0, 1, EPS);
    /* ellipsoid x^2 + (y / 0.5)^2 + z^2 = 1: above (0.5, 0.25) its front is at z = sqrt(0.5)
       with the normal along the gradient (x, y / 0.25, z) */
    float z = sqrtf(0.5f);
    h = cast(s, sk_v3f(5.5f, 0.25f, 5), sk_v3f(0, 0, -1));
    assert_true(h.hit);
    assert_near(h.distance, 5 - z, 2e-3);
    sk_vec3f expect = sk_v3f_normalize(sk_v3f(0.5f, 1.0f, z));
    assert_vec(h.normal, expect.x, expect.y, expect.z, 2e-3f);
    sk_render_scene_destroy(s);
}

/* Every built-in primitive: unit normals that agree with the winding, right-handed unit
 * tangent frames, and length UVs whose steps match the surface distances. */
static void test_primitive_meshes(void **state)
{
    (void)state;
    for (int shape = SK_RENDER_SHAPE_PLANE; shape < SK_RENDER_SHAPE_COUNT; shape++) {
        sk_render_object_desc o = {.shape = shape,
                                   .size = {2, 3, 4},
                                   .radius = 1.5f,
                                   .height = 2,
                                   .segments = 48,
                                   .rings = 24};
        sk_mesh m;
        sk_error err = {0};
        assert_int_equal(sk_render_make_primitive(&o, &m, &err), SK_OK);
        const sk_mesh_attribute *tan = sk_mesh_find_attribute(&m, "tangent");
        assert_non_null(tan);
        assert_int_equal(sk_mesh_validate(&m, &err), SK_OK);
        for (size_t i = 0; i < m.vertex_count; i++) {
            sk_vec3f n = sk_v3f(m.normals[3 * i], m.normals[3 * i + 1], m.normals[3 * i + 2]);
            sk_vec3f t = sk_v3f(tan->data[4 * i], tan->data[4 * i + 1], tan->data[4 * i + 2]);
            assert_near(sk_v3f_length(n), 1, 1e-5);
            assert_near(sk_v3f_length(t), 1, 1e-5);
            assert_near(sk_v3f_dot(n, t), 0, 1e-5);
            assert_near(tan->data[4 * i + 3], 1, 0);
        }
        for (size_t f = 0; f < m.triangle_count; f++) {
            const uint32_t *ix = m.indices + 3 * f;
            sk_vec3f p[3], nsum = sk_v3f(0, 0, 0);
            sk_vec2f uv[3];
            for (int k = 0; k < 3; k++) {
                p[k] = sk_v3f(m.positions[3 * ix[k]], m.positions[3 * ix[k] + 1],
                              m.positions[3 * ix[k] + 2]);
                uv[k] = sk_v2f(m.uvs[2 * ix[k]], m.uvs[2 * ix[k] + 1]);
                nsum = sk_v3f_add(nsum, sk_v3f(m.normals[3 * ix[k]], m.normals[3 * ix[k] + 1],
                                               m.normals[3 * ix[k] + 2]));
            }
            sk_vec3f face = sk_v3f_cross(sk_v3f_sub(p[1], p[0]), sk_v3f_sub(p[2], p[0]));
            assert_true(sk_v3f_length(face) > 0);
            assert_true(sk_v3f_dot(face, nsum) > 0);
            /* UV is arc length: an edge's UV step is no shorter than its chord and at most
               slightly longer (chord vs arc), except where u shrinks towards the poles */
            if (shape == SK_RENDER_SHAPE_PLANE || shape == SK_RENDER_SHAPE_BOX) {
                for (int k = 0; k < 3; k++) {
                    float chord = sk_v3f_length(sk_v3f_sub(p[(k + 1) % 3], p[k]));
                    float step = sk_v2f_length(sk_v2f_sub(uv[(k + 1) % 3], uv[k]));
                    assert_near(step, chord, 1e-5);
                }
            }
        }
        sk_mesh_free(&m);
    }
}

static void test_compute_tangents(void **state)
{
    (void)state;
    /* a quad in the xz plane (normal +y) with u along +x and v along -x mirrored: the
       tangent follows u, the handedness records the mirror */
    for (int mirrored = 0; mirrored < 2; mirrored++) {
        sk_mesh m;
        sk_error err = {0};
        assert_int_equal(sk_mesh_create(&m, 4, 2, SK_MESH_NORMALS | SK_MESH_UVS, &err), SK_OK);
        const float pos[12] = {0, 0, 0, 1, 0, 0, 1, 0, -1, 0, 0, -1};
        const float uv[8] = {0, 0, 1, 0, 1, 1, 0, 1};
        const uint32_t ix[6] = {0, 1, 2, 0, 2, 3};
        memcpy(m.positions, pos, sizeof pos);
        memcpy(m.indices, ix, sizeof ix);
        for (int i = 0; i < 4; i++) {
            m.normals[3 * i + 1] = 1;
            m.uvs[2 * i] = uv[2 * i];
            m.uvs[2 * i + 1] = mirrored ? 1 - uv[2 * i + 1] : uv[2 * i + 1];
        }
        /* the deprecated render name is the same call: the first pass uses it */
        assert_int_equal(mirrored ? sk_mesh_compute_tangents(&m, &err)
                                  : sk_render_compute_tangents(&m, &err),
                         SK_OK);
        const sk_mesh_attribute *t = sk_mesh_find_attribute(&m, "tangent");
        assert_non_null(t);
        for (int i = 0; i < 4; i++) {
            assert_vec(sk_v3f(t->data[4 * i], t->data[4 * i + 1], t->data[4 * i + 2]), 1, 0, 0,
                       1e-5f);
            /* v along -z: cross(n, t) = (0,1,0) x (1,0,0) = (0,0,-1) agrees (w = +1) */
            assert_near(t->data[4 * i + 3], mirrored ? -1 : 1, 0);
        }
        sk_mesh_free(&m);
    }
}

/* Objects with the same geometry share one mesh; each instance is hit where it is. */
static void test_instances_and_framing(void **state)
{
    (void)state;
    sk_render_object_desc o[3];
    for (int i = 0; i < 3; i++)
        o[i] = (sk_render_object_desc){.shape = SK_RENDER_SHAPE_SPHERE,
                                       .radius = 1,
                                       .transform = {.translate = {3.0f * (float)i, 0, 0}}};
    sk_render_scene *s = make_scene(o, 3);
    for (int i = 0; i < 3; i++) {
        sk_render_hit h = cast(s, sk_v3f(3.0f * (float)i, 0, 5), sk_v3f(0, 0, -1));
        assert_int_equal(h.object, i);
        assert_near(h.distance, 4, EPS);
    }
    sk_vec3f lo, hi;
    assert_true(sk_render_scene_bounds(s, &lo, &hi));
    assert_vec(lo, -1, -1, -1, 1e-5f);
    assert_vec(hi, 7, 1, 1, 1e-5f);
    /* the default camera frames the bounding sphere, looking along -z at its centre */
    const sk_render_scene_desc *d = sk_render_scene_get_desc(s);
    assert_near(d->camera.target[0], 3, 1e-5);
    assert_near(d->camera.position[0], 3, 1e-5);
    assert_true(d->camera.position[2] > 4);
    sk_render_scene_destroy(s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_sphere_hits),           cmocka_unit_test(test_box_faces),
        cmocka_unit_test(test_cylinder_and_capsule),  cmocka_unit_test(test_transformed_instances),
        cmocka_unit_test(test_primitive_meshes),      cmocka_unit_test(test_compute_tangents),
        cmocka_unit_test(test_instances_and_framing),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
