/* Renderer skin and wood materials: the skin's bump normal and the wood's albedo and
 * reflection reach the image exactly as the modules define them (frames, units, the 1/pi
 * of eq. (4) read radiometrically), and scenes refer to skin and wood presets by name
 * with edits, errors naming the key path. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "test_support.h"
#include "shitsukan/render.h"

static void assert_near(double a, double b, double eps)
{
    if (!(fabs(a - b) <= eps)) fail_msg("%.9g != %.9g (eps %g)", a, b, eps);
}

/* A plane (y = 0) seen straight down through a tiny orthographic view around `at`, so
 * every sample of the one pixel sees (nearly) the same point; lit by one directional
 * light of irradiance 1 towards `to_light`. */
static sk_render_scene_desc *tiny_view(sk_vec3f at, sk_vec3f to_light)
{
    sk_render_scene_desc *d = calloc(1, sizeof *d);
    assert_non_null(d);
    d->image.width = d->image.height = 1;
    d->image.samples = 4;
    d->camera.projection = SK_RENDER_PROJECTION_ORTHOGRAPHIC;
    d->camera.position[0] = at.x, d->camera.position[1] = 50, d->camera.position[2] = at.z;
    d->camera.target[0] = at.x, d->camera.target[2] = at.z;
    d->camera.up[2] = -1;
    d->camera.ortho_height = 1e-5f;
    d->material_count = 1;
    snprintf(d->materials[0].name, sizeof d->materials[0].name, "m");
    d->object_count = 1;
    d->objects[0].shape = SK_RENDER_SHAPE_PLANE;
    d->objects[0].size[0] = d->objects[0].size[2] = 200;
    snprintf(d->objects[0].material, sizeof d->objects[0].material, "m");
    d->light_count = 1;
    sk_vec3f dir = sk_v3f_neg(sk_v3f_normalize(to_light));
    memcpy(d->lights[0].direction, &dir, sizeof dir);
    d->lights[0].intensity = 1;
    return d;
}

static void render_pixel(const sk_render_scene_desc *d, float rgb[3])
{
    sk_render_scene *s = NULL;
    sk_error err = {0};
    if (sk_render_scene_create(d, &s, &err) != SK_OK) fail_msg("scene: %s", err.message);
    sk_image img;
    if (sk_render_scene_render(s, NULL, &img, NULL, &err) != SK_OK) fail_msg("%s", err.message);
    memcpy(rgb, img.data, 3 * sizeof(float));
    sk_image_free(&img);
    sk_render_scene_destroy(s);
}

/* The skin's normal at st (mm) is (nx, ny, nz) in (tangent, bitangent, normal); the plane
 * has tangent +x, bitangent -z, normal +y, and its length UVs are mm from its corner. */
static void test_skin_normal_reaches_the_image(void **state)
{
    (void)state;
    sk_vec3f to_light = sk_v3f_normalize(sk_v3f(0.5f, 1, -0.3f));
    const float points[][2] = {{101.37f, 97.21f}, {100.05f, 100.6f}, {103.3f, 98.9f}};
    sk_skin *skin = NULL;
    sk_error err = {0};
    sk_skin_desc sd = {0};
    assert_int_equal(sk_skin_create(&skin, &sd, &err), SK_OK);
    int differing = 0;
    for (int i = 0; i < 3; i++) {
        /* uv = (x + 100, 100 - z) on the 200 mm plane */
        sk_vec3f at = sk_v3f(points[i][0] - 100, 0, 100 - points[i][1]);
        sk_render_scene_desc *d = tiny_view(at, to_light);
        d->materials[0].type = SK_RENDER_MATERIAL_SKIN;
        d->materials[0].albedo[0] = d->materials[0].albedo[1] = d->materials[0].albedo[2] = 0.5f;
        float rgb[3];
        render_pixel(d, rgb);
        sk_vec3f n;
        sk_skin_eval(skin, points[i][0], points[i][1], NULL, &n);
        sk_vec3f world = sk_v3f_normalize(sk_v3f(n.x, n.z, -n.y));
        double expect = 0.5 * fmax(0.0, sk_v3f_dot(world, to_light)) / SK_PI;
        assert_near(rgb[0], expect, 2e-3);
        if (fabs(expect - 0.5 * to_light.y / SK_PI) > 0.01) differing++;
        free(d);
    }
    assert_true(differing > 0); /* the relief did tilt the normal somewhere */
    sk_skin_destroy(skin);
}

/* A wood whose rings are one colour, without vessels, fibre shift or sheen, is Lambertian
 * with the wood's albedo: rho E cos / pi, as the standard material. */
static void test_plain_wood_is_lambertian(void **state)
{
    (void)state;
    double theta = 40 * SK_DEG_TO_RAD;
    sk_render_scene_desc *d =
        tiny_view(sk_v3f(3, 0, -2), sk_v3f((float)sin(theta), (float)cos(theta), 0));
    sk_render_material_desc *m = &d->materials[0];
    m->type = SK_RENDER_MATERIAL_WOOD;
    const float c[3] = {0.7f, 0.5f, 0.3f};
    memcpy(m->wood.rings.earlywood_srgb, c, sizeof c);
    memcpy(m->wood.rings.latewood_srgb, c, sizeof c);
    float rgb[3];
    render_pixel(d, rgb);
    for (int k = 0; k < 3; k++)
        assert_near(rgb[k], sk_linear_from_srgb(c[k]) * cos(theta) / SK_PI, 1e-5);
    free(d);
}

/* With the figure sheen on and the board turned, the pixel is sk_wood_shade / pi at the
 * object-frame point and vectors: the adapter's frames and scale are the module's. */
static void test_wood_sheen_matches_the_module(void **state)
{
    (void)state;
    sk_render_scene_desc *d = calloc(1, sizeof *d);
    d->image.width = d->image.height = 1;
    d->image.samples = 4;
    d->camera.projection = SK_RENDER_PROJECTION_ORTHOGRAPHIC;
    d->camera.position[2] = 100;
    d->camera.ortho_height = 1e-5f;
    d->material_count = 1;
    sk_render_material_desc *m = &d->materials[0];
    snprintf(m->name, sizeof m->name, "w");
    m->type = SK_RENDER_MATERIAL_WOOD;
    m->wood.grain.wavy_amplitude = 0.15f;
    m->wood.grain.wavy_wavelength_mm = 20;
    m->wood.shading.specular = 0.3f;
    m->wood.shading.exponent = 20;
    m->wood.transform.translate_mm[0] = -70; /* a quarter-sawn face 70 mm from the pith */
    d->object_count = 1;
    sk_render_object_desc *o = &d->objects[0];
    o->shape = SK_RENDER_SHAPE_BOX;
    o->size[0] = o->size[1] = 100, o->size[2] = 10;
    snprintf(o->material, sizeof o->material, "w");
    /* the box turned by 20 degrees about z and moved: the wood turns with it */
    float angle = (float)(20 * SK_DEG_TO_RAD);
    o->transform.rotate[2] = angle;
    o->transform.translate[0] = 7, o->transform.translate[1] = 13, o->transform.translate[2] = -5;
    d->camera.position[0] = d->camera.target[0] = 7 + 3;
    d->camera.position[1] = d->camera.target[1] = 13 + 11;
    d->light_count = 1;
    sk_vec3f l = sk_v3f_normalize(sk_v3f(0.1f, 0.15f, 1));
    sk_vec3f dir = sk_v3f_neg(l);
    memcpy(d->lights[0].direction, &dir, sizeof dir);
    d->lights[0].intensity = 2;
    float rgb[3];
    render_pixel(d, rgb);

    sk_wood *wood = NULL;
    sk_error err = {0};
    assert_int_equal(sk_wood_create(&m->wood, &wood, &err), SK_OK);
    /* the hit point in the object frame: the scene point (10, 24, 0) minus the translation,
       turned back by -20 degrees about z */
    float c = cosf(angle), s = sinf(angle);
    sk_vec3f q = sk_v3f(3, 11, 5);
    sk_vec3f p = sk_v3f(c * q.x + s * q.y, -s * q.x + c * q.y, q.z);
    sk_vec3f lo = sk_v3f(c * l.x + s * l.y, -s * l.x + c * l.y, l.z);
    sk_wood_sample sample;
    sk_wood_eval(wood, p, sk_v3f(0, 0, 1), &sample);
    sk_vec3f r = sk_wood_shade(wood, &sample, sk_v3f(0, 0, 1), lo, sk_v3f(0, 0, 1));
    for (int k = 0; k < 3; k++) assert_near(rgb[k], 2 * (&r.x)[k] / SK_PI, 1e-4 + 1e-3 * (&r.x)[k]);
    /* and the sheen is there: without it the pixel is darker */
    m->wood.shading.specular = 0;
    float plain[3];
    render_pixel(d, plain);
    assert_true(rgb[0] > plain[0] + 1e-3f);
    sk_wood_destroy(wood);
    free(d);
}

static const char *scene_error(const char *json)
{
    static char message[SK_ERROR_MESSAGE_SIZE];
    const char *path = sk_test_path("materials/scenes/s.json");
    sk_test_write_file(path, json, strlen(json));
    sk_render_scene_desc *d = calloc(1, sizeof *d);
    sk_error err = {0};
    /* shipped presets are found from the source tree's presets folder */
    sk_result r = sk_render_scene_desc_load(path, d, &err);
    free(d);
    if (r == SK_OK) return NULL;
    snprintf(message, sizeof message, "%s", err.message);
    return message;
}

/* Preset references: a shipped name through the loader, a file next to the scene, edits
 * with *_set, and errors with the key path. */
static void test_preset_references(void **state)
{
    (void)state;
    sk_render_scene_desc *d = calloc(1, sizeof *d);
    sk_error err = {0};
    char path[1024];
    snprintf(path, sizeof path, "%s/scenes/wrist.json", SK_TEST_PRESET_DIR);
    if (sk_render_scene_desc_load(path, d, &err) != SK_OK) fail_msg("%s", err.message);
    assert_int_equal(d->materials[0].type, SK_RENDER_MATERIAL_SKIN);
    assert_int_equal(d->materials[0].skin.level_count, 3);
    assert_near(d->materials[0].skin.levels[0].stretch[0], 5, 0);  /* Fig. 19(f) */
    assert_near(d->materials[0].skin.size_mm[0], 23.561945, 1e-5); /* the skin_set edit */
    free(d);

    /* a wood preset file next to the scene (relative path) */
    const char *msg;
    const char *wood = "{\"rings\": {\"width_mm\": 2.5}}";
    sk_test_write_file(sk_test_path("materials/scenes/w.json"), wood, strlen(wood));
    assert_null(scene_error(
        "{\"materials\": [{\"name\": \"w\", \"type\": \"wood\", \"wood_preset\": \"w.json\"}]}"));
    assert_string_equal(
        scene_error(
            "{\"materials\": [{\"name\": \"w\", \"type\": \"wood\", \"wood_preset\": \"w.json\", "
            "\"wood_set\": [\"rings.width_mm=-1\"]}]}"),
        "materials[0].wood_preset = \"w.json\": rings.width_mm = -1 is out of range [0, 50]");
    msg = scene_error(
        "{\"materials\": [{\"name\": \"w\", \"type\": \"wood\", \"wood_preset\": \"w.json\", "
        "\"wood_set\": [\"rings..x=1\"]}]}");
    assert_non_null(msg);
    assert_true(strncmp(msg, "materials[0].wood_set[0]: ", 26) == 0);
    assert_non_null(strstr(msg, "rings..x"));
    msg = scene_error(
        "{\"materials\": [{\"name\": \"s\", \"type\": \"skin\", \"skin_preset\": \"fig99\"}]}");
    assert_non_null(msg);
    assert_non_null(
        strstr(msg, "materials[0].skin_preset = \"fig99\" is not a shipped skin preset"));
    assert_string_equal(
        scene_error(
            "{\"materials\": [{\"name\": \"s\", \"type\": \"skin\", \"skin_set\": [\"seed=2\"]}]}"),
        "materials[0].skin_set needs materials[0].skin_preset (edit the skin keys directly "
        "otherwise)");
    assert_string_equal(
        scene_error(
            "{\"materials\": [{\"name\": \"w\", \"type\": \"wood\", \"wood_preset\": \"w.json\", "
            "\"wood\": {\"seed\": 3}}]}"),
        "materials[0]: give either wood_preset or wood, not both (use wood_set to edit a preset)");
    msg = scene_error(
        "{\"materials\": [{\"name\": \"s\", \"type\": \"skin\", \"skin\": {\"levels\": []}}]}");
    assert_non_null(msg);
    assert_true(strncmp(msg, "materials[0].skin.levels", 24) == 0);
}

static sk_image render_image(const sk_render_scene_desc *d)
{
    sk_render_scene *s = NULL;
    sk_error err = {0};
    if (sk_render_scene_create(d, &s, &err) != SK_OK) fail_msg("scene: %s", err.message);
    sk_image img;
    if (sk_render_scene_render(s, NULL, &img, NULL, &err) != SK_OK) fail_msg("%s", err.message);
    sk_render_scene_destroy(s);
    return img;
}

static bool same_pixels(const sk_image *a, const sk_image *b)
{
    size_t n = (size_t)a->width * (size_t)a->height * (size_t)a->channels;
    return a->width == b->width && a->height == b->height && a->channels == b->channels &&
           memcmp(a->data, b->data, n * sizeof(float)) == 0;
}

/* A tree and images shared from C (wood_tree, albedo_image, normal_image) give the same
 * pixels as the scene building its own from the desc and the files; the scene leaves
 * them to the caller (the sanitizer run checks nothing is freed twice). */
static void test_shared_tree_and_images(void **state)
{
    (void)state;
    sk_render_scene_desc *d = tiny_view(sk_v3f(20, 0, -30), sk_v3f(0.3f, 1, 0.2f));
    d->image.width = d->image.height = 8;
    d->camera.ortho_height = 60;
    d->material_count = 2;
    sk_render_material_desc *wood = &d->materials[0], *tex = &d->materials[1];
    wood->type = SK_RENDER_MATERIAL_WOOD;
    wood->wood.rings.width_mm = 2;
    wood->wood.shading.specular = 0.3f;
    snprintf(tex->name, sizeof tex->name, "t");
    d->object_count = 2;
    d->objects[0].size[0] = 100;
    d->objects[1] = d->objects[0];
    d->objects[1].transform.translate[0] = 100;
    snprintf(d->objects[1].material, sizeof d->objects[1].material, "t");
    /* a small albedo and normal map written as files, read back as the renderer reads them */
    sk_error err = {0};
    sk_image albedo, normal;
    assert_int_equal(sk_image_create(&albedo, 4, 4, 3, &err), SK_OK);
    assert_int_equal(sk_image_create(&normal, 4, 4, 3, &err), SK_OK);
    for (int i = 0; i < 16; i++) {
        float *a = albedo.data + 3 * i, *n = normal.data + 3 * i;
        a[0] = (float)(i % 4) / 3.0f, a[1] = 0.5f, a[2] = (float)(i / 4) / 3.0f;
        float tilt = 0.2f * (float)(i % 3) - 0.2f;
        n[0] = 0.5f + 0.5f * tilt, n[1] = 0.5f, n[2] = 0.5f + 0.5f * sqrtf(1 - tilt * tilt);
    }
    const char *albedo_path = sk_test_path("albedo.png"), *normal_path = sk_test_path("normal.png");
    sk_png_write_desc linear = {.encoding = SK_PNG_ENCODING_LINEAR, .bit_depth = 16};
    assert_int_equal(sk_image_write_png(&albedo, albedo_path, NULL, &err), SK_OK);
    assert_int_equal(sk_image_write_png(&normal, normal_path, &linear, &err), SK_OK);
    snprintf(tex->albedo_texture, sizeof tex->albedo_texture, "%s", albedo_path);
    snprintf(tex->normal_map, sizeof tex->normal_map, "%s", normal_path);
    tex->uv_scale[0] = tex->uv_scale[1] = 0.05f;
    sk_image built = render_image(d);

    sk_image albedo_read, normal_read;
    sk_png_read_desc srgb = {.encoding = SK_PNG_ENCODING_SRGB},
                     lin = {.encoding = SK_PNG_ENCODING_LINEAR};
    assert_int_equal(sk_image_read_png(&albedo_read, albedo_path, &srgb, NULL, NULL, &err), SK_OK);
    assert_int_equal(sk_image_read_png(&normal_read, normal_path, &lin, NULL, NULL, &err), SK_OK);
    sk_wood *tree = NULL;
    assert_int_equal(sk_wood_create(&wood->wood, &tree, &err), SK_OK);
    wood->wood_tree = tree;
    memset(&wood->wood, 0xff, sizeof wood->wood); /* not read when a tree is given */
    tex->albedo_texture[0] = tex->normal_map[0] = '\0';
    tex->albedo_image = &albedo_read;
    tex->normal_image = &normal_read;
    sk_image shared = render_image(d);
    assert_true(same_pixels(&built, &shared));
    sk_image again = render_image(d); /* the tree and images survive a scene */
    assert_true(same_pixels(&built, &again));

    sk_image empty = {0};
    tex->normal_image = &empty;
    sk_render_scene *s = NULL;
    assert_int_equal(sk_render_scene_create(d, &s, &err), SK_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(err.message, "materials[1].normal_image"));
    sk_image_free(&built), sk_image_free(&shared), sk_image_free(&again);
    sk_image_free(&albedo), sk_image_free(&normal), sk_image_free(&albedo_read),
        sk_image_free(&normal_read);
    sk_wood_destroy(tree);
    free(d);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_skin_normal_reaches_the_image),
        cmocka_unit_test(test_plain_wood_is_lambertian),
        cmocka_unit_test(test_wood_sheen_matches_the_module),
        cmocka_unit_test(test_preset_references),
        cmocka_unit_test(test_shared_tree_and_images),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
