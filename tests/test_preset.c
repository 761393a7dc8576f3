/* Tests of presets: JSON parsing, --set edits, schema binding with key-path errors, and
 * the desc -> JSON inverse. */
#include <math.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include "shitsukan/io.h"
#include "shitsukan/preset.h"
#include "test_support.h"

/* A schema shaped like the skin module's: levels of profiles of points. */
typedef struct t_point {
    float xz[2];
} t_point;
typedef struct t_segment {
    int point_count;
    t_point points[4];
} t_segment;
typedef struct t_level {
    int layout;
    float jitter;
    float angle; /* radians; JSON angle_deg */
    int segment_count;
    t_segment profile[3];
} t_level;
typedef struct t_noise {
    int octaves;
    double gain;
} t_noise;
typedef struct t_desc {
    uint64_t seed;
    bool tile;
    char name[8];
    int light_count;
    float light[3];
    t_noise noise;
    int level_count;
    t_level levels[3];
} t_desc;

static const sk_schema_field k_point_fields[] = {
    {.key = NULL,
     .type = SK_FIELD_FLOATS,
     .offset = offsetof(t_point, xz),
     .min = 0,
     .max = 10,
     .count = 2,
     .count_offset = SK_FIELD_FIXED,
     .doc = "control point (x, z)"},
};
static const sk_schema k_point_schema = {"point", k_point_fields, 1, NULL};

static const sk_schema_field k_segment_fields[] = {
    {.key = "points",
     .type = SK_FIELD_ARRAY,
     .offset = offsetof(t_segment, points),
     .count = 4,
     .min_count = 4,
     .count_offset = offsetof(t_segment, point_count),
     .elem_size = sizeof(t_point),
     .schema = &k_point_schema,
     .doc = "4 Bezier control points"},
};
static const sk_schema k_segment_schema = {"segment", k_segment_fields, 1, NULL};

static const char *const k_layouts[] = {"default", "triangular", "square", "random", NULL};
static const sk_schema_field k_level_fields[] = {
    {.key = "layout",
     .type = SK_FIELD_ENUM,
     .offset = offsetof(t_level, layout),
     .names = k_layouts},
    {.key = "jitter",
     .type = SK_FIELD_FLOAT,
     .offset = offsetof(t_level, jitter),
     .min = 0,
     .max = 1},
    {.key = "angle_deg",
     .type = SK_FIELD_FLOAT,
     .offset = offsetof(t_level, angle),
     .min = -180,
     .max = 180,
     .scale = SK_DEG_TO_RAD},
    {.key = "profile",
     .type = SK_FIELD_ARRAY,
     .offset = offsetof(t_level, profile),
     .count = 3,
     .min_count = 1,
     .count_offset = offsetof(t_level, segment_count),
     .elem_size = sizeof(t_segment),
     .schema = &k_segment_schema},
};
static const sk_schema k_level_schema = {"level", k_level_fields, 4, NULL};

static const sk_schema_field k_noise_fields[] = {
    {.key = "octaves",
     .type = SK_FIELD_INT,
     .offset = offsetof(t_noise, octaves),
     .min = 1,
     .max = 16},
    {.key = "gain", .type = SK_FIELD_DOUBLE, .offset = offsetof(t_noise, gain), .min = 0, .max = 1},
};
static const sk_schema k_noise_schema = {"noise", k_noise_fields, 2, NULL};

static const sk_schema_field k_desc_fields[] = {
    {.key = "seed", .type = SK_FIELD_SEED, .offset = offsetof(t_desc, seed)},
    {.key = "tile", .type = SK_FIELD_BOOL, .offset = offsetof(t_desc, tile)},
    {.key = "name", .type = SK_FIELD_STRING, .offset = offsetof(t_desc, name), .count = 8},
    {.key = "light",
     .type = SK_FIELD_FLOATS,
     .offset = offsetof(t_desc, light),
     .min = -1,
     .max = 1,
     .count = 3,
     .count_offset = SK_FIELD_FIXED},
    {.key = "noise",
     .type = SK_FIELD_OBJECT,
     .offset = offsetof(t_desc, noise),
     .schema = &k_noise_schema},
    {.key = "levels",
     .type = SK_FIELD_ARRAY,
     .offset = offsetof(t_desc, levels),
     .count = 3,
     .min_count = 1,
     .count_offset = offsetof(t_desc, level_count),
     .elem_size = sizeof(t_level),
     .schema = &k_level_schema},
};
static const sk_schema k_desc_schema = {"test", k_desc_fields, 6, NULL};

static const char *k_good =
    "{\n"
    "  \"description\": \"a test preset\",\n"
    "  \"source\": [\"one\", \"two\"],\n"
    "  \"seed\": 1234,\n"
    "  \"tile\": true,\n"
    "  \"name\": \"abc\",\n"
    "  \"light\": [0.5, -0.5, 1],\n"
    "  \"noise\": {\"octaves\": 4, \"gain\": 0.25, \"notes\": \"why\"},\n"
    "  \"levels\": [\n"
    "    {\"layout\": \"square\", \"jitter\": 0.5, \"angle_deg\": 90,\n"
    "     \"profile\": [{\"points\": [[0,3],[2,3],[4,3],[8,3]]}]},\n"
    "    {\"jitter\": 0.25, \"profile\": [{\"points\": [[0,5],[5,5],[7,3],[10,0]]},\n"
    "                                   {\"points\": [[0,1],[5,1],[7,0.7],[10,0]]}]}\n"
    "  ]\n"
    "}\n";

static sk_result bind_text(const char *text, t_desc *desc, sk_error *err)
{
    sk_preset *p = NULL;
    memset(desc, 0, sizeof *desc);
    sk_result r = sk_preset_parse(&p, text, strlen(text), "test.json", err);
    if (r != SK_OK) return r;
    r = sk_preset_bind(p, &k_desc_schema, desc, err);
    sk_preset_free(p);
    return r;
}

static sk_result bind_with_set(const char *text, const char *assignment, t_desc *desc,
                               sk_error *err)
{
    sk_preset *p = NULL;
    memset(desc, 0, sizeof *desc);
    sk_result r = sk_preset_parse(&p, text, strlen(text), "test.json", err);
    if (r == SK_OK) r = sk_preset_set(p, assignment, err);
    if (r == SK_OK) r = sk_preset_bind(p, &k_desc_schema, desc, err);
    sk_preset_free(p);
    return r;
}

static void test_bind_good_preset(void **state)
{
    (void)state;
    t_desc d;
    sk_error err = {0};
    assert_int_equal(bind_text(k_good, &d, &err), SK_OK);
    assert_true(d.seed == 1234);
    assert_true(d.tile);
    assert_string_equal(d.name, "abc");
    assert_true(d.light[0] == 0.5f && d.light[1] == -0.5f && d.light[2] == 1.0f);
    assert_int_equal(d.noise.octaves, 4);
    assert_true(d.noise.gain == 0.25);
    assert_int_equal(d.level_count, 2);
    assert_int_equal(d.levels[0].layout, 2);
    assert_true(fabsf(d.levels[0].angle - (float)(SK_PI / 2)) < 1e-6f);
    assert_int_equal(d.levels[0].segment_count, 1);
    assert_int_equal(d.levels[0].profile[0].point_count, 4);
    assert_true(d.levels[0].profile[0].points[3].xz[0] == 8.0f);
    assert_int_equal(d.levels[1].layout, 0); /* absent: default */
    assert_int_equal(d.levels[1].segment_count, 2);
    assert_true(d.levels[1].profile[1].points[2].xz[1] == 0.7f);
}

typedef struct bad_case {
    const char *json;
    const char *message; /* expected substring */
} bad_case;

static void test_bind_errors_name_key_path(void **state)
{
    (void)state;
    const bad_case cases[] = {
        {"{\"levels\": [{\"profile\": [{\"points\": [[0,3],[2,3],[12,3],[8,3]]}]}]}",
         "levels[0].profile[0].points[2][0] = 12 is out of range [0, 10]"},
        {"{\"levels\": [{\"jiter\": 0.5}]}",
         "levels[0].jiter: unknown key (did you mean 'jitter'?)"},
        {"{\"zzzzzzzzz\": 1}", "zzzzzzzzz: unknown key; accepted keys: seed, tile, name, light"},
        {"{\"levels\": [{\"jitter\": \"high\"}]}",
         "levels[0].jitter: expected a number, got the string \"high\""},
        {"{\"levels\": [{\"jitter\": 1e999}]}", "levels[0].jitter is not a finite number"},
        {"{\"levels\": []}", "levels: array length 0 is out of range [1, 3]"},
        {"{\"levels\": [{}, {}, {}, {}]}", "levels: array length 4 is out of range [1, 3]"},
        {"{\"light\": [1, 2]}", "light: expected an array of exactly 3 elements, got 2"},
        {"{\"light\": [1, 0, 2]}", "light[2] = 2 is out of range [-1, 1]"},
        {"{\"levels\": [{\"layout\": \"hex\"}]}",
         "levels[0].layout = \"hex\" is not one of: default, triangular, square, random"},
        {"{\"noise\": {\"octaves\": 2.5}}", "noise.octaves = 2.5 is not an integer"},
        {"{\"noise\": {\"octaves\": 40}}", "noise.octaves = 40 is out of range [1, 16]"},
        {"{\"noise\": 3}", "noise: expected an object, got a number"},
        {"{\"seed\": -1}", "seed = -1 must be an integer in [0, 9007199254740992]"},
        {"{\"tile\": 1}", "tile: expected true or false, got a number"},
        {"{\"name\": \"much too long\"}", "name: string of 13 characters is longer than 7"},
        {"{\"tile\": true, \"tile\": false}", "tile: key given twice"},
        {"{\"description\": 5}", "description: expected a string or an array of strings"},
        {"{\"levels\": [{\"profile\": [{\"points\": [[0,3],[2,3],[4,3]]}]}]}",
         "levels[0].profile[0].points: expected an array of exactly 4 elements, got 3"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        t_desc d;
        sk_error err = {0};
        sk_result r = bind_text(cases[i].json, &d, &err);
        if (r != SK_ERROR_INVALID_ARGUMENT || !strstr(err.message, cases[i].message))
            fail_msg("case %zu: got %d '%s', expected '%s'", i, r, err.message, cases[i].message);
    }
}

static void test_parse_errors(void **state)
{
    (void)state;
    sk_preset *p = NULL;
    sk_error err = {0};
    const char *broken = "{\n  \"a\": 1,\n  \"b\": ]\n}";
    assert_int_equal(sk_preset_parse(&p, broken, strlen(broken), "x.json", &err), SK_ERROR_PARSE);
    assert_null(p);
    assert_non_null(strstr(err.message, "x.json:3:"));
    assert_int_equal(sk_preset_parse(&p, "[1,2]", 5, "y.json", &err), SK_ERROR_PARSE);
    assert_non_null(strstr(err.message, "must be a JSON object"));
    assert_int_equal(sk_preset_parse(&p, "{} x", 4, "z.json", &err), SK_ERROR_PARSE);
    assert_non_null(strstr(err.message, "unexpected text"));
    assert_int_equal(sk_preset_parse(&p, "{\"a\"\0:1}", 8, "n.json", &err), SK_ERROR_PARSE);
    assert_int_equal(sk_preset_load_file(&p, sk_test_path("preset/none.json"), &err),
                     SK_ERROR_NOT_FOUND);
}

static void test_set_overrides(void **state)
{
    (void)state;
    t_desc d;
    sk_error err = {0};
    assert_int_equal(bind_with_set(k_good, "levels[1].jitter=0.75", &d, &err), SK_OK);
    assert_true(d.levels[1].jitter == 0.75f);
    assert_int_equal(bind_with_set(k_good, "noise.gain=0.5", &d, &err), SK_OK);
    assert_true(d.noise.gain == 0.5);
    assert_int_equal(bind_with_set(k_good, "levels[0].layout=random", &d, &err), SK_OK);
    assert_int_equal(d.levels[0].layout, 3); /* bare word taken as a string */
    assert_int_equal(bind_with_set(k_good, "light=[0,0,1]", &d, &err), SK_OK);
    assert_true(d.light[2] == 1.0f && d.light[0] == 0.0f);
    assert_int_equal(
        bind_with_set(
            k_good,
            "levels[2]={\"jitter\":0.1,\"profile\":[{\"points\":[[0,1],[1,1],[2,1],[10,0]]}]}", &d,
            &err),
        SK_OK);
    assert_int_equal(d.level_count, 3);
    assert_int_equal(bind_with_set(k_good, "levels[1].profile[0].points[3][1]=2", &d, &err), SK_OK);
    assert_true(d.levels[1].profile[0].points[3].xz[1] == 2.0f);
    assert_int_equal(bind_with_set("{}", "noise.octaves=3", &d, &err), SK_OK); /* creates object */
    assert_int_equal(d.noise.octaves, 3);
    assert_int_equal(bind_with_set(k_good, "tile=null", &d, &err), SK_OK); /* back to default */
    assert_false(d.tile);
    /* NaN and out-of-range values are reported with the key path */
    assert_int_equal(bind_with_set(k_good, "levels[0].jitter=nan", &d, &err),
                     SK_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(err.message, "levels[0].jitter is not a finite number"));
    assert_int_equal(bind_with_set(k_good, "levels[0].jitter=2", &d, &err),
                     SK_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(err.message, "levels[0].jitter = 2 is out of range [0, 1]"));
    /* bad assignments */
    assert_int_equal(bind_with_set(k_good, "levels[5].jitter=0.1", &d, &err),
                     SK_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(err.message, "index 5 is out of range [0, 2]"));
    assert_int_equal(bind_with_set(k_good, "jitter", &d, &err), SK_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(err.message, "expected key.path=value"));
    assert_int_equal(bind_with_set(k_good, "levels[x]=1", &d, &err), SK_ERROR_INVALID_ARGUMENT);
    assert_int_equal(bind_with_set(k_good, "seed[0]=1", &d, &err), SK_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(err.message, "not an array"));
    assert_int_equal(bind_with_set(k_good, "=1", &d, &err), SK_ERROR_INVALID_ARGUMENT);
}

static void test_desc_to_json_round_trip(void **state)
{
    (void)state;
    t_desc a, b;
    sk_error err = {0};
    assert_int_equal(bind_text(k_good, &a, &err), SK_OK);
    char *json = sk_schema_to_json(&k_desc_schema, &a);
    assert_non_null(json);
    assert_int_equal(bind_text(json, &b, &err), SK_OK);
    free(json);
    assert_true(a.seed == b.seed && a.tile == b.tile);
    assert_string_equal(a.name, b.name);
    assert_memory_equal(a.light, b.light, sizeof a.light);
    assert_int_equal(a.level_count, b.level_count);
    for (int l = 0; l < a.level_count; l++) {
        assert_int_equal(a.levels[l].layout, b.levels[l].layout);
        assert_true(fabsf(a.levels[l].angle - b.levels[l].angle) < 1e-6f);
        assert_int_equal(a.levels[l].segment_count, b.levels[l].segment_count);
        assert_memory_equal(a.levels[l].profile, b.levels[l].profile,
                            sizeof(t_segment) * (size_t)a.levels[l].segment_count);
    }
    sk_preset *p;
    assert_int_equal(sk_preset_parse(&p, k_good, strlen(k_good), "g", &err), SK_OK);
    assert_string_equal(sk_preset_get_string(p, "description"), "a test preset");
    assert_null(sk_preset_get_string(p, "seed"));
    sk_preset_free(p);
}

static void test_schema_print_lists_paths(void **state)
{
    (void)state;
    const char *path = sk_test_path("preset/keys.txt");
    FILE *fp = fopen(path, "w");
    assert_non_null(fp);
    sk_schema_print(&k_desc_schema, fp);
    fclose(fp);
    char *text;
    assert_int_equal(sk_read_file(path, 0, &text, NULL, NULL), SK_OK);
    assert_non_null(strstr(text, "levels[].profile[].points"));
    assert_non_null(strstr(text, "levels[].jitter"));
    assert_non_null(strstr(text, "[0, 1]"));
    assert_non_null(strstr(text, "default|triangular|square|random"));
    assert_non_null(strstr(text, "noise.octaves"));
    free(text);
}

/* The JSON description walks the same tree: every nested key with its type and range. */
static void test_schema_describe_json(void **state)
{
    (void)state;
    char *text = sk_schema_describe_json(&k_desc_schema);
    assert_non_null(text);
    sk_preset *p;
    sk_error err = {0};
    /* it is JSON the preset reader takes */
    assert_int_equal(sk_preset_parse(&p, text, strlen(text), "describe", &err), SK_OK);
    sk_preset_free(p);
    assert_non_null(strstr(text, "\"key\":\"levels\",\"type\":\"array\""));
    assert_non_null(strstr(text, "\"names\":[\"default\",\"triangular\",\"square\",\"random\"]"));
    assert_non_null(strstr(text, "\"key\":\"jitter\",\"type\":\"float\",\"min\":0,\"max\":1"));
    assert_non_null(strstr(text, "\"key\":\"octaves\",\"type\":\"int\""));
    assert_non_null(strstr(text, "\"key\":null"));
    free(text);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_bind_good_preset),
        cmocka_unit_test(test_bind_errors_name_key_path),
        cmocka_unit_test(test_parse_errors),
        cmocka_unit_test(test_set_overrides),
        cmocka_unit_test(test_desc_to_json_round_trip),
        cmocka_unit_test(test_schema_print_lists_paths),
        cmocka_unit_test(test_schema_describe_json),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
