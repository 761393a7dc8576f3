/* Renderer radiometry and shading: exact radiance of a Lambertian plane, shadows, point
 * and area light irradiance against closed forms, the environment with ambient occlusion,
 * Blinn-Phong energy, bump and normal maps against tilted planes, the texture/shading
 * blend, tone curves, stratified sampling and thread-count independence. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "test_support.h"
#include "render/render_internal.h"
#include "render/sampling.h"
#include "shitsukan/render.h"

static void assert_near(double a, double b, double eps)
{
    if (!(fabs(a - b) <= eps)) fail_msg("%.9g != %.9g (eps %g)", a, b, eps);
}

/* A large plane (y = 0) seen straight down by an orthographic camera of view height
 * `view` around the origin; lights and more objects are added by the caller. */
static sk_render_scene_desc *plane_scene(int size, int spp, float view)
{
    sk_render_scene_desc *d = calloc(1, sizeof *d);
    assert_non_null(d);
    d->image.width = d->image.height = size;
    d->image.samples = spp;
    d->camera.projection = SK_RENDER_PROJECTION_ORTHOGRAPHIC;
    d->camera.position[1] = 10;
    d->camera.up[2] = -1;
    d->camera.ortho_height = view;
    d->material_count = 1;
    sk_render_material_desc *m = &d->materials[0];
    snprintf(m->name, sizeof m->name, "matte");
    m->albedo[0] = 0.5f, m->albedo[1] = 0.25f, m->albedo[2] = 0.125f;
    d->object_count = 1;
    d->objects[0].shape = SK_RENDER_SHAPE_PLANE;
    d->objects[0].size[0] = d->objects[0].size[2] = 100;
    snprintf(d->objects[0].material, sizeof d->objects[0].material, "matte");
    return d;
}

static void render(const sk_render_scene_desc *d, sk_image *img)
{
    sk_render_scene *s = NULL;
    sk_error err = {0};
    if (sk_render_scene_create(d, &s, &err) != SK_OK) fail_msg("scene: %s", err.message);
    if (sk_render_scene_render(s, NULL, img, NULL, &err) != SK_OK)
        fail_msg("render: %s", err.message);
    sk_render_scene_destroy(s);
}

static void add_directional(sk_render_scene_desc *d, sk_vec3f to_light, float irradiance)
{
    sk_render_light_desc *l = &d->lights[d->light_count++];
    l->type = SK_RENDER_LIGHT_DIRECTIONAL;
    sk_vec3f dir = sk_v3f_neg(sk_v3f_normalize(to_light));
    l->direction[0] = dir.x, l->direction[1] = dir.y, l->direction[2] = dir.z;
    l->intensity = irradiance;
}

static const float *pixel(const sk_image *img, int x, int y) { return sk_image_pixel(img, x, y); }

/* rho E cos(theta) / pi, in every pixel, in memory and in the EXR written to disk. */
static void test_lambertian_plane_exact(void **state)
{
    (void)state;
    sk_render_scene_desc *d = plane_scene(8, 4, 1);
    double theta = 60 * SK_DEG_TO_RAD;
    add_directional(d, sk_v3f((float)sin(theta), (float)cos(theta), 0), 1.0f);
    sk_image img;
    render(d, &img);
    const char *path = sk_test_path("lambert.exr");
    sk_error err = {0};
    assert_int_equal(sk_render_write(&img, &d->film, path, NULL, &err), SK_OK);
    sk_image back;
    assert_int_equal(sk_image_read_exr(&back, path, NULL, &err), SK_OK);
    assert_int_equal(back.channels, 4);
    for (int y = 0; y < 8; y++)
        for (int x = 0; x < 8; x++)
            for (int c = 0; c < 3; c++) {
                double expect = d->materials[0].albedo[c] * cos(theta) / SK_PI;
                assert_near(pixel(&img, x, y)[c], expect, 1e-6);
                assert_near(pixel(&back, x, y)[c], expect, 1e-6);
                assert_near(pixel(&img, x, y)[3], 1, 0);
            }
    sk_image_free(&img);
    sk_image_free(&back);
    free(d);
}

/* A box between the light and the plane: the points it hides get exactly nothing. */
static void test_shadowed_point_gets_no_light(void **state)
{
    (void)state;
    sk_render_scene_desc *d = plane_scene(16, 4, 10);
    add_directional(d, sk_v3f(0, 1, 0), 2.0f);
    sk_render_object_desc *box = &d->objects[d->object_count++];
    box->shape = SK_RENDER_SHAPE_BOX;
    box->size[0] = 4, box->size[1] = 0.5f, box->size[2] = 4;
    box->transform.translate[1] = 3;
    /* the camera sits above the box: look from below the box, i.e. move the camera down */
    d->camera.position[1] = 1;
    sk_image img;
    render(d, &img);
    /* the centre (inside the shadow) is black; a corner gets rho E / pi */
    for (int c = 0; c < 3; c++) {
        assert_near(pixel(&img, 7, 8)[c], 0, 0);
        assert_near(pixel(&img, 8, 7)[c], 0, 0);
        assert_near(pixel(&img, 0, 0)[c], d->materials[0].albedo[c] * 2 / SK_PI, 1e-6);
    }
    sk_image_free(&img);
    free(d);
}

/* Point light: E = I / h^2 straight below; rect light: the closed-form irradiance of a
 * parallel square above the point (sum of four corner form factors). */
static void test_point_and_area_light_irradiance(void **state)
{
    (void)state;
    sk_render_scene_desc *d = plane_scene(2, 4, 1e-4f);
    sk_render_light_desc *l = &d->lights[d->light_count++];
    l->type = SK_RENDER_LIGHT_POINT;
    l->position[1] = 2;
    l->intensity = 8;
    sk_image img;
    render(d, &img);
    assert_near(pixel(&img, 0, 0)[0], 0.5 * (8.0 / 4.0) / SK_PI, 1e-6);
    sk_image_free(&img);

    l->type = SK_RENDER_LIGHT_RECT;
    l->intensity = 3; /* radiance */
    l->size[0] = l->size[1] = 2;
    l->direction[1] = -1;
    l->samples = 16;
    d->image.samples = 64;
    render(d, &img);
    double a = 1.0 / 2.0, c = 2.0; /* quarter of the square: 1 x 1 at distance 2 */
    double A = a * 2 / c, B = A;
    double corner = A / sqrt(1 + A * A) * atan(B / sqrt(1 + A * A)) +
                    B / sqrt(1 + B * B) * atan(A / sqrt(1 + B * B));
    double E = 3.0 * 4.0 * 0.5 * corner; /* Le pi F with F = corner / (2 pi), four corners */
    double expect = 0.5 * E / SK_PI;
    /* 1024 stratified area samples */
    assert_near(pixel(&img, 0, 0)[0], expect, 0.005 * expect);
    assert_near(pixel(&img, 1, 1)[0], expect, 0.005 * expect);
    sk_image_free(&img);
    free(d);
}

/* Environment radiance L: an open plane reflects rho L with or without occlusion rays; at
 * the foot of a huge wall half the cosine-weighted hemisphere is blocked. */
static void test_environment_and_occlusion(void **state)
{
    (void)state;
    sk_render_scene_desc *d = plane_scene(4, 16, 0.5f);
    d->environment.radiance[0] = d->environment.radiance[1] = d->environment.radiance[2] = 2;
    sk_image img;
    render(d, &img);
    assert_near(pixel(&img, 1, 2)[1], 0.25 * 2, 1e-6);
    sk_image_free(&img);
    d->environment.ambient_occlusion = true;
    d->environment.ao_samples = 4;
    render(d, &img);
    assert_near(pixel(&img, 1, 2)[1], 0.25 * 2, 1e-6);
    sk_image_free(&img);
    /* a wall whose face is at x = -0.26, just left of the view (|x| <= 0.25) */
    sk_render_object_desc *wall = &d->objects[d->object_count++];
    wall->shape = SK_RENDER_SHAPE_BOX;
    wall->size[0] = 10, wall->size[1] = 1000, wall->size[2] = 1000;
    wall->transform.translate[0] = -5.26f;
    d->image.width = d->image.height = 1;
    d->camera.ortho_height = 1e-4f;
    d->camera.position[0] = d->camera.target[0] = -0.25f;
    d->image.samples = 256;
    render(d, &img);
    assert_near(pixel(&img, 0, 0)[1] / (0.25 * 2), 0.5, 0.02);
    sk_image_free(&img);
    free(d);
}

/* Directional albedo of the normalised Blinn-Phong lobe (ks = 1) by numerical
 * integration: 1 at normal incidence, never above 1. */
static void test_blinn_phong_energy(void **state)
{
    (void)state;
    const float exponents[] = {1, 8, 64, 1000};
    const double view_deg[] = {0, 45, 75};
    for (int e = 0; e < 4; e++) {
        for (int v = 0; v < 3; v++) {
            sk__shading sh;
            sk__material blinn_phong;
            memset(&sh, 0, sizeof sh);
            memset(&blinn_phong, 0, sizeof blinn_phong);
            sh.material = &blinn_phong;
            sh.shading_normal = sk_v3f(0, 0, 1);
            double a = view_deg[v] * SK_DEG_TO_RAD;
            sh.to_viewer = sk_v3f((float)sin(a), 0, (float)cos(a));
            sh.texel.specular = 1;
            sh.texel.shininess = exponents[e];
            sh.lobe_norm = sk__blinn_phong_norm(exponents[e]);
            /* midpoint rule in (cos theta, phi): d omega = d(cos theta) d phi */
            const int nt = 2000, np = 400;
            double sum = 0;
            for (int i = 0; i < nt; i++) {
                double ct = (i + 0.5) / nt, st = sqrt(1 - ct * ct);
                for (int j = 0; j < np; j++) {
                    double phi = 2 * SK_PI * (j + 0.5) / np;
                    sk_vec3f wi = sk_v3f((float)(st * cos(phi)), (float)(st * sin(phi)), (float)ct);
                    sum += sk__material_reflect(&sh, wi).x;
                }
            }
            double albedo = sum * (1.0 / nt) * (2 * SK_PI / np);
            if (albedo > 1.0 + 1e-3)
                fail_msg("n = %g, view %g deg: albedo %g > 1", exponents[e], view_deg[v], albedo);
            if (v == 0 && fabs(albedo - 1) > 0.01)
                fail_msg("n = %g: normal-incidence albedo %g", exponents[e], albedo);
        }
    }
}

/* A procedural texture with a constant height gradient. */
static void constant_slope(void *user, const sk_render_surface *surface, sk_render_texel *texel)
{
    (void)surface;
    const float *g = user;
    texel->slope = sk_v2f(g[0], g[1]);
}

/* Shades the plane's centre under a light from the side, seen straight down. */
static void centre_radiance(sk_render_scene_desc *d, float out[3])
{
    d->image.width = d->image.height = 1;
    d->camera.ortho_height = 1e-3f;
    sk_image img;
    render(d, &img);
    for (int c = 0; c < 3; c++) out[c] = pixel(&img, 0, 0)[c];
    sk_image_free(&img);
}

/* Bump mapping a constant-slope height field shades like the correspondingly tilted
 * plane: slope g along u (the plane's +x) tilts the normal by atan(g) about z; along v
 * (-z) by atan(g) about x; uv_scale steepens the slope in proportion. */
static void test_bump_matches_tilted_plane(void **state)
{
    (void)state;
    struct {
        float g[2], uv_scale;
        float rot_deg[3];
    } cases[] = {
        {{0.4f, 0}, 1, {0, 0, 21.801409f}},  /* atan(0.4) */
        {{0, 0.3f}, 1, {16.699244f, 0, 0}},  /* atan(0.3) */
        {{0.25f, 0}, 2, {0, 0, 26.565051f}}, /* atan(0.5) */
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        float bumped[3], tilted[3];
        sk_render_scene_desc *d = plane_scene(1, 4, 1);
        d->materials[0].specular = 0.5f;
        d->materials[0].shininess = 20;
        add_directional(d, sk_v3f(-0.6f, 1, -0.4f), 1);
        d->materials[0].texture = constant_slope;
        d->materials[0].texture_user = cases[i].g;
        d->materials[0].uv_scale[0] = d->materials[0].uv_scale[1] = cases[i].uv_scale;
        centre_radiance(d, bumped);
        d->materials[0].texture = NULL;
        for (int k = 0; k < 3; k++)
            d->objects[0].transform.rotate[k] = (float)(cases[i].rot_deg[k] * SK_DEG_TO_RAD);
        centre_radiance(d, tilted);
        for (int c = 0; c < 3; c++) assert_near(bumped[c], tilted[c], 2e-5 + 1e-4 * tilted[c]);
        /* and the bump did change the shading */
        d->objects[0].transform.rotate[0] = d->objects[0].transform.rotate[2] = 0;
        float flat[3];
        centre_radiance(d, flat);
        assert_true(fabsf(flat[0] - tilted[0]) > 1e-3f);
        free(d);
    }
}

/* The shadow terminator: a bumped surface lit almost edge-on to its actual plane fades to
 * black continuously as the light reaches the geometric horizon (no hard edge of light),
 * and is exact again (equal to the tilted plane) once the light is 0.15 in cosine above it. */
static void test_bump_terminator_is_soft(void **state)
{
    (void)state;
    float g[2] = {0.5f, 0}; /* normal tilted by atan(0.5) towards -x */
    const float cosines[] = {0.001f, 0.01f, 0.05f, 0.1f, 0.15f, 0.2f};
    float prev = -1, first = 0, last = 0;
    for (size_t i = 0; i < sizeof cosines / sizeof cosines[0]; i++) {
        float c = cosines[i];
        sk_render_scene_desc *d = plane_scene(1, 1, 1);
        add_directional(d, sk_v3f(-sqrtf(1 - c * c), c, 0), 1);
        d->materials[0].texture = constant_slope;
        d->materials[0].texture_user = g;
        float rad[3];
        centre_radiance(d, rad);
        assert_true(rad[0] > prev); /* rises steadily from the horizon */
        prev = rad[0];
        if (i == 0) first = rad[0];
        last = rad[0];
        if (c >= 0.15f) { /* beyond the fade: the exact tilted-plane value */
            float tilted[3];
            d->materials[0].texture = NULL;
            d->objects[0].transform.rotate[2] = (float)atan(0.5);
            centre_radiance(d, tilted);
            assert_near(rad[0], tilted[0], 2e-5 + 1e-4 * tilted[0]);
        }
        free(d);
    }
    assert_true(first < 0.01f * last);
}

/* A constant normal map (16-bit PNG, linear) equals the tilted plane too. */
static void test_normal_map_matches_tilted_plane(void **state)
{
    (void)state;
    sk_image map;
    sk_error err = {0};
    assert_int_equal(sk_image_create(&map, 4, 4, 3, &err), SK_OK);
    sk_vec3f n = sk_v3f_normalize(sk_v3f(-0.4f, 0, 1)); /* tangent-space normal of slope 0.4 */
    for (int i = 0; i < 16; i++) {
        map.data[3 * i] = 0.5f * n.x + 0.5f;
        map.data[3 * i + 1] = 0.5f * n.y + 0.5f;
        map.data[3 * i + 2] = 0.5f * n.z + 0.5f;
    }
    const char *path = sk_test_path("normal_map.png");
    sk_png_write_desc pd = {.bit_depth = 16, .encoding = SK_PNG_ENCODING_LINEAR};
    assert_int_equal(sk_image_write_png(&map, path, &pd, &err), SK_OK);
    sk_image_free(&map);
    sk_render_scene_desc *d = plane_scene(1, 4, 1);
    add_directional(d, sk_v3f(-0.6f, 1, 0.3f), 1);
    snprintf(d->materials[0].normal_map, sizeof d->materials[0].normal_map, "%s", path);
    float mapped[3], tilted[3];
    centre_radiance(d, mapped);
    d->materials[0].normal_map[0] = '\0';
    d->objects[0].transform.rotate[2] = (float)atan(0.4);
    centre_radiance(d, tilted);
    for (int c = 0; c < 3; c++) assert_near(mapped[c], tilted[c], 1e-4);
    free(d);
}

/* The hand thesis blend: (1 - w) (white surface shaded) + w albedo texture_radiance. */
static void test_texture_blend(void **state)
{
    (void)state;
    sk_render_scene_desc *d = plane_scene(2, 4, 1);
    add_directional(d, sk_v3f(0, 1, 0), 2);
    d->materials[0].texture_weight = 0.7f;
    d->materials[0].texture_radiance = 0.5f;
    sk_image img;
    render(d, &img);
    for (int c = 0; c < 3; c++)
        assert_near(pixel(&img, 1, 0)[c], 0.3 * 2 / SK_PI + 0.7 * d->materials[0].albedo[c] * 0.5,
                    1e-6);
    sk_image_free(&img);
    free(d);
}

/* An image texture by UV: texel centres come back exactly (decoded from sRGB), with the
 * image's top row at t = 1 (v runs up the image as OpenGL and Blender have it). */
static void test_albedo_texture_orientation(void **state)
{
    (void)state;
    sk_image tex;
    sk_error err = {0};
    assert_int_equal(sk_image_create(&tex, 2, 2, 3, &err), SK_OK);
    const float texels[12] = {1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1}; /* red green / blue white */
    memcpy(tex.data, texels, sizeof texels);
    const char *path = sk_test_path("albedo.png");
    assert_int_equal(sk_image_write_png(&tex, path, NULL, &err), SK_OK);
    sk_image_free(&tex);
    /* the 100-unit plane with uv_scale 1/100: st = (x + 50, 50 - z) / 100 */
    const struct {
        float x, z;
        float rgb[3];
    } at[] = {
        {-25, -25, {1, 0, 0}}, {25, -25, {0, 1, 0}}, {-25, 25, {0, 0, 1}}, {25, 25, {1, 1, 1}}};
    for (int i = 0; i < 4; i++) {
        sk_render_scene_desc *d = plane_scene(1, 4, 1e-4f);
        add_directional(d, sk_v3f(0, 1, 0), 1);
        sk_render_material_desc *m = &d->materials[0];
        m->albedo[0] = m->albedo[1] = m->albedo[2] = 1;
        snprintf(m->albedo_texture, sizeof m->albedo_texture, "%s", path);
        m->uv_scale[0] = m->uv_scale[1] = 0.01f;
        d->camera.position[0] = d->camera.target[0] = at[i].x;
        d->camera.position[2] = d->camera.target[2] = at[i].z;
        sk_image img;
        render(d, &img);
        for (int c = 0; c < 3; c++) assert_near(pixel(&img, 0, 0)[c], at[i].rgb[c] / SK_PI, 1e-5);
        sk_image_free(&img);
        free(d);
    }
}

/* Far from the origin, tilted, lit at a grazing 85 degrees: every point is lit exactly
 * (no shadow acne from the surface shadowing itself). */
static void test_no_self_shadowing(void **state)
{
    (void)state;
    sk_render_scene_desc *d = plane_scene(32, 2, 2);
    sk_render_object_desc *o = &d->objects[0];
    o->transform.translate[0] = 2000, o->transform.translate[1] = -3000,
    o->transform.translate[2] = 1500;
    o->transform.rotate[0] = 0.3f, o->transform.rotate[1] = 0.7f;
    o->size[0] = o->size[2] = 20;
    sk_mat4f m = sk__transform_matrix(&o->transform);
    sk_vec3f n = sk_v3f_normalize(sk_m4f_apply_dir(m, sk_v3f(0, 1, 0)));
    sk_vec3f t = sk_v3f_normalize(sk_m4f_apply_dir(m, sk_v3f(1, 0, 0)));
    double grazing = 85 * SK_DEG_TO_RAD;
    sk_vec3f to_light =
        sk_v3f_add(sk_v3f_scale(n, (float)cos(grazing)), sk_v3f_scale(t, (float)sin(grazing)));
    add_directional(d, to_light, 1);
    /* look at the plane's centre along its normal */
    sk_vec3f c = sk_v3f_load(o->transform.translate);
    sk_vec3f eye = sk_v3f_add(c, sk_v3f_scale(n, 10));
    memcpy(d->camera.position, &eye, sizeof eye);
    memcpy(d->camera.target, &c, sizeof c);
    d->camera.up[0] = t.x, d->camera.up[1] = t.y, d->camera.up[2] = t.z;
    sk_image img;
    render(d, &img);
    double expect = 0.5 * cos(grazing) / SK_PI;
    for (int y = 0; y < 32; y++)
        for (int x = 0; x < 32; x++)
            assert_near(pixel(&img, x, y)[0], expect, 1e-4 * expect + 1e-7);
    sk_image_free(&img);
    free(d);
}

static void test_tonemap_curves(void **state)
{
    (void)state;
    sk_image lin, out;
    sk_error err = {0};
    assert_int_equal(sk_image_create(&lin, 3, 1, 4, &err), SK_OK);
    const float px[12] = {0.5f, 2, 1, 1, 0.25f, 0.25f, 0.25f, 0.5f, 0, 0, 0, 0};
    memcpy(lin.data, px, sizeof px);
    sk_render_film_desc film = {0};
    assert_int_equal(sk_render_tonemap(&lin, &film, &out, &err), SK_OK);
    assert_near(out.data[0], 0.5, 0), assert_near(out.data[1], 1, 0),
        assert_near(out.data[3], 1, 0);
    assert_near(out.data[4], 0.5, 1e-7); /* un-premultiplied: 0.25 / 0.5 */
    assert_near(out.data[7], 0.5, 0);
    assert_near(out.data[8], 0, 0), assert_near(out.data[11], 0, 0);
    sk_image_free(&out);
    film.tonemap = SK_RENDER_TONEMAP_REINHARD;
    film.exposure = 1; /* grey 0.5 exposed to 1 maps to 1 / (1 + 1) */
    assert_int_equal(sk_render_tonemap(&lin, &film, &out, &err), SK_OK);
    assert_near(out.data[4], 0.5, 1e-6);
    sk_image_free(&out);
    film.tonemap = SK_RENDER_TONEMAP_FILMIC;
    film.exposure = 0;
    film.opaque = true; /* RGB output, alpha ignored */
    assert_int_equal(sk_render_tonemap(&lin, &film, &out, &err), SK_OK);
    assert_int_equal(out.channels, 3);
    double x = 0.25, f = x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14);
    assert_near(out.data[3], f, 1e-6);
    sk_image_free(&out);
    sk_image_free(&lin);
}

/* Multi-jittered patterns: one point in each of the m x n cells and in each of the N
 * columns and rows (N = m n), for several counts; distinct keys give distinct points. */
static void test_stratified_patterns(void **state)
{
    (void)state;
    const uint32_t counts[] = {4, 12, 16, 64, 100};
    for (int k = 0; k < 5; k++) {
        uint32_t n = counts[k];
        uint32_t m = (uint32_t)ceil(sqrt((double)n)), rows = n / m;
        for (uint64_t key = 1; key < 20; key++) {
            int cells[128] = {0}, cols[128] = {0}, rws[128] = {0};
            for (uint32_t i = 0; i < n; i++) {
                sk__pattern pat = sk__pattern_make(key, 77, 3, n);
                sk_vec2f p = sk__pattern_point(&pat, i);
                assert_true(p.x >= 0 && p.x < 1 && p.y >= 0 && p.y < 1);
                int cx = (int)(p.x * (float)m), cy = (int)(p.y * (float)rows);
                cells[cy * (int)m + cx]++;
                cols[(int)(p.x * (float)n)]++;
                rws[(int)(p.y * (float)n)]++;
            }
            for (uint32_t i = 0; i < n; i++) {
                assert_int_equal(cells[i], 1);
                assert_int_equal(cols[i], 1);
                assert_int_equal(rws[i], 1);
            }
        }
        sk__pattern pa = sk__pattern_make(1, 0, 0, n), pb = sk__pattern_make(2, 0, 0, n);
        sk_vec2f a = sk__pattern_point(&pa, 0), b = sk__pattern_point(&pb, 0);
        assert_true(a.x != b.x || a.y != b.y);
    }
    /* permutations are bijections */
    for (uint32_t n = 1; n < 70; n++) {
        int seen[70] = {0};
        for (uint32_t i = 0; i < n; i++) seen[sk__permute(i, n, 12345 + n)]++;
        for (uint32_t i = 0; i < n; i++) assert_int_equal(seen[i], 1);
    }
}

/* A scene with every light type, AO, speculars and textures: the same bytes on 1 and 2
 * threads; another seed changes the noise. */
static void test_same_bytes_any_thread_count(void **state)
{
    (void)state;
    sk_render_scene_desc *d = plane_scene(40, 8, 8);
    d->camera.projection = SK_RENDER_PROJECTION_PERSPECTIVE;
    d->camera.position[0] = 3, d->camera.position[1] = 4, d->camera.position[2] = 6;
    d->materials[0].specular = 0.3f;
    d->environment.radiance[0] = d->environment.radiance[1] = d->environment.radiance[2] = 0.3f;
    d->environment.ambient_occlusion = true;
    sk_render_object_desc *o = &d->objects[d->object_count++];
    o->shape = SK_RENDER_SHAPE_SPHERE;
    o->transform.translate[1] = 0.5f;
    add_directional(d, sk_v3f(1, 2, 1), 1);
    sk_render_light_desc *l = &d->lights[d->light_count++];
    l->type = SK_RENDER_LIGHT_RECT;
    l->position[1] = 3, l->position[0] = -2;
    l->samples = 2;
    sk_image a, b, c;
    sk_threads_set(1);
    render(d, &a);
    sk_threads_set(2);
    render(d, &b);
    sk_threads_set(0);
    assert_memory_equal(a.data, b.data, (size_t)40 * 40 * 4 * sizeof(float));
    d->seed = 7;
    render(d, &c);
    assert_true(memcmp(a.data, c.data, (size_t)40 * 40 * 4 * sizeof(float)) != 0);
    sk_image_free(&a);
    sk_image_free(&b);
    sk_image_free(&c);
    free(d);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_lambertian_plane_exact),
        cmocka_unit_test(test_shadowed_point_gets_no_light),
        cmocka_unit_test(test_point_and_area_light_irradiance),
        cmocka_unit_test(test_environment_and_occlusion),
        cmocka_unit_test(test_blinn_phong_energy),
        cmocka_unit_test(test_bump_matches_tilted_plane),
        cmocka_unit_test(test_bump_terminator_is_soft),
        cmocka_unit_test(test_normal_map_matches_tilted_plane),
        cmocka_unit_test(test_texture_blend),
        cmocka_unit_test(test_albedo_texture_orientation),
        cmocka_unit_test(test_no_self_shadowing),
        cmocka_unit_test(test_tonemap_curves),
        cmocka_unit_test(test_stratified_patterns),
        cmocka_unit_test(test_same_bytes_any_thread_count),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
