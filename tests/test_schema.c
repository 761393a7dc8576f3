/* Tests of schemas (shitsukan/schema.h): the range checks, defaults and key paths every
 * model reads from its schema, and that each model's desc check and defaults are those
 * its schema states. */
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "shitsukan/hand_scan.h"
#include "shitsukan/noise_map.h"
#include "shitsukan/render.h"
#include "shitsukan/schema.h"
#include "shitsukan/showcase.h"
#include "shitsukan/skin.h"
#include "shitsukan/tissue.h"
#include "shitsukan/wood.h"
#include "struct_comments.h"
#include "test_support.h"

typedef struct t_item {
    float xy[2];
} t_item;
typedef struct t_inner {
    int rows;
    float colour[3];
} t_inner;
typedef struct t_desc {
    float size;   /* 0 = 4; [1, 10] */
    double ratio; /* (0, 2]; required */
    float angle;  /* radians, key angle_deg; [-90, 90] degrees */
    int mode;
    float stretch[2]; /* 0 = 1 each */
    t_inner inner;
    int item_count;
    t_item items[3];
} t_desc;

static const char *const k_modes[] = {"default", "a", "b", NULL};
static const double k_grey[3] = {0.5, 0.5, 0.5};

static const sk_schema_field k_item_fields[] = {
    SK_SCHEMA_ELEMENT_FLOATS(2, -5, 5, .doc = "a point"),
};
static const sk_schema k_item_schema = {"item", k_item_fields, 1, NULL};

static const sk_schema_field k_inner_fields[] = {
    SK_SCHEMA_INT(t_inner, rows, "rows", 1, 8, .flags = SK_FIELD_ZERO, .def = 2, .doc = "rows"),
    SK_SCHEMA_FLOATS(t_inner, colour, "colour", 3, 0, 1, .defs = k_grey, .doc = "a colour"),
};
static const sk_schema k_inner_schema = SK_SCHEMA_OF("inner", t_inner, k_inner_fields);

static const sk_schema_field k_fields[] = {
    SK_SCHEMA_FLOAT(t_desc, size, "size", 1, 10, .flags = SK_FIELD_ZERO, .def = 4, .doc = "size"),
    SK_SCHEMA_DOUBLE(t_desc, ratio, "ratio", 0, 2, .flags = SK_FIELD_OPEN_MIN, .doc = "ratio"),
    SK_SCHEMA_DEG(t_desc, angle, "angle_deg", -90, 90, .doc = "angle"),
    SK_SCHEMA_ENUM(t_desc, mode, "mode", k_modes, .def = 1, .doc = "mode"),
    SK_SCHEMA_FLOATS(t_desc, stretch, "stretch", 2, 0, 100, .def = 1, .doc = "stretch"),
    SK_SCHEMA_OBJECT(t_desc, inner, "inner", k_inner_schema, .doc = "inner"),
    SK_SCHEMA_ARRAY(t_desc, items, "items", item_count, 0, k_item_schema, .doc = "items"),
};
static const sk_schema k_schema = SK_SCHEMA_OF("test", t_desc, k_fields);

static void assert_check(const t_desc *d, const char *message)
{
    sk_error err = {0};
    sk_result r = sk_schema_check(&k_schema, d, "", &err);
    if (!message) {
        if (r != SK_OK) fail_msg("unexpected error: %s", err.message);
        return;
    }
    assert_int_equal(r, SK_ERROR_INVALID_ARGUMENT);
    assert_string_equal(err.message, message);
}

static void test_check_ranges(void **state)
{
    (void)state;
    t_desc d = {.ratio = 1, .inner.colour = {0.1f, 0.2f, 0.3f}};
    assert_check(&d, NULL); /* size 0 = default, accepted besides [1, 10] */
    d.size = 0.5f;
    assert_check(&d, "size = 0.5 is out of range [1, 10]");
    d.size = 4;
    d.ratio = 0;
    assert_check(&d, "ratio = 0 is out of range (0, 2] (required)");
    d.ratio = 3;
    assert_check(&d, "ratio = 3 is out of range (0, 2]");
    d.ratio = NAN;
    assert_check(&d, "ratio = nan is out of range (0, 2]");
    d.ratio = 2;
    d.angle = (float)(100 * SK_DEG_TO_RAD); /* reported in degrees, as the preset writes it */
    assert_check(&d, "angle_deg = 100 is out of range [-90, 90]");
    d.angle = (float)(90 * SK_DEG_TO_RAD);
    assert_check(&d, NULL);
    d.mode = 3;
    assert_check(&d, "mode = 3 is out of range [0, 2]");
    d.mode = 2;
    d.stretch[1] = 101;
    assert_check(&d, "stretch[1] = 101 is out of range [0, 100]");
    d.stretch[1] = 0;
    d.inner.rows = 9;
    assert_check(&d, "inner.rows = 9 is out of range [1, 8]");
    d.inner.rows = 0;
    d.inner.colour[2] = -1;
    assert_check(&d, "inner.colour[2] = -1 is out of range [0, 1]");
    d.inner.colour[2] = 1;
    d.item_count = 2;
    d.items[1].xy[0] = 6;
    assert_check(&d, "items[1][0] = 6 is out of range [-5, 5]");
    d.items[1].xy[0] = 0;
    d.item_count = 4;
    assert_check(&d, "items (count) = 4 is out of range [0, 3]");
    d.item_count = 0;
    sk_error err = {0};
    d.size = 20;
    assert_int_equal(sk_schema_check(&k_schema, &d, "things[2]", &err), SK_ERROR_INVALID_ARGUMENT);
    assert_string_equal(err.message, "things[2].size = 20 is out of range [1, 10]");
}

static void test_defaults(void **state)
{
    (void)state;
    t_desc d = {.stretch = {0, 3}, .item_count = 1};
    sk_schema_apply_defaults(&k_schema, &d);
    assert_float_equal(d.size, 4, 0);
    assert_int_equal(d.mode, 1);
    assert_float_equal(d.stretch[0], 1, 0); /* per element */
    assert_float_equal(d.stretch[1], 3, 0);
    assert_int_equal(d.inner.rows, 2);
    for (int i = 0; i < 3; i++) assert_float_equal(d.inner.colour[i], 0.5, 0);
    t_desc c = {.inner.colour = {0, 0.7f, 0}};
    sk_schema_apply_defaults(&k_schema, &c); /* a colour is replaced only when all 0 */
    assert_float_equal(c.inner.colour[0], 0, 0);
    assert_float_equal(c.inner.colour[1], 0.7f, 0);
}

static void test_find_and_json_range(void **state)
{
    (void)state;
    const sk_schema_field *f = sk_schema_find(&k_schema, "inner.rows");
    assert_non_null(f);
    assert_string_equal(f->key, "rows");
    double lo, hi;
    sk_schema_field_json_range(f, &lo, &hi);
    assert_float_equal(lo, 0, 0); /* 0 = the default */
    assert_float_equal(hi, 8, 0);
    sk_schema_field_json_range(sk_schema_find(&k_schema, "ratio"), &lo, &hi);
    assert_float_equal(lo, 0, 0);
    assert_non_null(sk_schema_find(&k_schema, "items[]"));
    assert_null(sk_schema_find(&k_schema, "inner.colour.x"));
    assert_null(sk_schema_find(&k_schema, "nope"));
    assert_non_null(sk_schema_find(&sk_skin_schema, "levels[].jitter_rate"));
    assert_non_null(sk_schema_find(&sk_wood_schema, "shading.fibre_width_deg"));
    assert_non_null(sk_schema_find(&sk_render_schema, "materials[].skin.levels[].profile"));
}

/* The models' checks read their ranges from their schemas: a value one step beyond a
 * stated bound fails with the key path, the bound itself passes. */
static void test_models_check_schema_ranges(void **state)
{
    (void)state;
    sk_error err = {0};
    sk_wood_desc w = {0};
    w.knots.collar = 2.5f;
    assert_int_equal(sk_wood_desc_validate(&w, &err), SK_ERROR_INVALID_ARGUMENT);
    assert_string_equal(err.message, "knots.collar = 2.5 is out of range [0.01, 2]");
    w.knots.collar = 2;
    assert_int_equal(sk_wood_desc_validate(&w, &err), SK_OK);
    sk_skin_desc s = {0};
    s.shading.light_elevation = (float)(100 * SK_DEG_TO_RAD);
    assert_int_equal(sk_skin_desc_validate(&s, &err), SK_ERROR_INVALID_ARGUMENT);
    assert_string_equal(err.message, "shading.light_elevation_deg = 100 is out of range [0, 90]");
    s.shading.light_elevation = (float)(SK_PI / 2);
    assert_int_equal(sk_skin_desc_validate(&s, &err), SK_OK);
}

/* A resolved all-zero desc holds every default its schema states as a number. */
static void check_defaults(const sk_schema *schema, const unsigned char *resolved, const char *path)
{
    for (int i = 0; i < schema->field_count; i++) {
        const sk_schema_field *f = &schema->fields[i];
        const unsigned char *p = resolved + f->offset;
        double scale = f->scale != 0 ? f->scale : 1;
        char key[256];
        snprintf(key, sizeof key, "%s%s%s", path, path[0] ? "." : "", f->key ? f->key : "");
        if (f->def_text || (f->flags & SK_FIELD_OWN)) continue;
        if (f->type == SK_FIELD_FLOAT) {
            float v;
            memcpy(&v, p, sizeof v);
            if (fabs(v - (float)(f->def * scale)) > 0)
                fail_msg("%s: %g, schema %g", key, v, f->def);
        } else if (f->type == SK_FIELD_INT || f->type == SK_FIELD_ENUM) {
            int v;
            memcpy(&v, p, sizeof v);
            if (v != (int)f->def) fail_msg("%s: %d, schema %g", key, v, f->def);
        } else if (f->type == SK_FIELD_FLOATS && f->count_offset == SK_FIELD_FIXED) {
            for (int k = 0; k < f->count; k++) {
                float v;
                memcpy(&v, p + k * sizeof v, sizeof v);
                double want = f->defs ? f->defs[k] : f->def;
                if (v != (float)(want * scale)) fail_msg("%s[%d]: %g, schema %g", key, k, v, want);
            }
        } else if (f->type == SK_FIELD_OBJECT) {
            check_defaults(f->schema, p, key);
        }
    }
}

static void test_models_resolve_schema_defaults(void **state)
{
    (void)state;
    sk_wood_desc w = sk_wood_desc_resolved(NULL);
    check_defaults(&sk_wood_schema, (const unsigned char *)&w, "");
    sk_skin_desc s = sk_skin_desc_resolved(NULL);
    /* the default levels are Fig. 19a's, not the zero level's: check the rest */
    check_defaults(sk_schema_find(&sk_skin_schema, "shading")->schema,
                   (const unsigned char *)&s.shading, "shading");
    check_defaults(sk_schema_find(&sk_skin_schema, "pores")->schema,
                   (const unsigned char *)&s.pores, "pores");
    sk_tissue_character_desc *t = calloc(1, sizeof *t);
    assert_non_null(t);
    sk_tissue_character_desc_resolve(t);
    check_defaults(&sk_tissue_character_schema, (const unsigned char *)t, "");
    free(t);
}

/* ---------------------------------------------------------------- header comments */

/* Every schema a command binds (the nested ones are reached from these). */
static const sk_schema *const k_schemas[] = {
    &sk_skin_schema,
    &sk_wood_schema,
    &sk_tissue_character_schema,
    &sk_render_schema,
    &sk_noise_map_schema,
    &sk_hand_skeleton_schema,
    &sk_hand_lut_schema,
    &sk_hand_solver_schema,
    &sk_hand_potential_schema,
    &sk_hand_evaluation_schema,
    &sk_hand_synthetic_schema,
    &sk_hand_scan_schema,
    &sk_hand_surface_schema,
    &sk_hand_texture_schema,
    &sk_showcase_schema,
};

/* The accepted values of a range as a normal form: [lo, hi] with its open ends, and
 * whether 0 is accepted (the all-zero desc's default). An integer range {0} + [1, n] is
 * [0, n]; (0, hi] with 0 accepted is [0, hi]. */
typedef struct norm_range {
    double lo, hi;
    bool lo_open, hi_open, zero;
} norm_range;

static norm_range normalise(double lo, double hi, bool lo_open, bool hi_open, bool zero_means,
                            bool integer)
{
    norm_range r = {lo, hi, lo_open, hi_open, false};
    bool inside = (lo < 0 || (lo == 0 && !lo_open)) && (hi > 0 || (hi == 0 && !hi_open));
    r.zero = inside || zero_means;
    if (r.zero && lo == 0) r.lo_open = false;
    if (r.zero && integer && lo == 1 && !lo_open) r.lo = 0;
    return r;
}

static bool same_number(double a, double b) { return fabs(a - b) <= 1e-9 * fmax(1, fabs(b)); }

static bool same_range(norm_range a, norm_range b)
{
    return same_number(a.lo, b.lo) && same_number(a.hi, b.hi) && a.lo_open == b.lo_open &&
           a.hi_open == b.hi_open && a.zero == b.zero;
}

static const sk_schema_field *member_field(const sk_schema *schema, const sk_test_member *m)
{
    char key[64];
    if (sk_test_comment_key(m->comment, key, sizeof key))
        for (int i = 0; i < schema->field_count; i++)
            if (schema->fields[i].key && strcmp(schema->fields[i].key, key) == 0)
                return &schema->fields[i];
    char deg[80];
    snprintf(deg, sizeof deg, "%s_deg", m->name);
    for (int i = 0; i < schema->field_count; i++) {
        const char *k = schema->fields[i].key;
        if (k && (strcmp(k, m->name) == 0 || strcmp(k, deg) == 0)) return &schema->fields[i];
    }
    return NULL;
}

/* One member's comment against its field: the range and the default it states, if any.
 * Returns the number of disagreements (each printed). */
static int check_member(const sk_schema *schema, const sk_test_member *m)
{
    const sk_schema_field *f = member_field(schema, m);
    if (!f) return 0;
    int bad = 0;
    bool number = f->type == SK_FIELD_FLOAT || f->type == SK_FIELD_DOUBLE ||
                  f->type == SK_FIELD_INT || f->type == SK_FIELD_FLOATS;
    sk_test_range hr;
    if (number && sk_test_comment_range(m->comment, &hr)) {
        bool integer = f->type == SK_FIELD_INT;
        norm_range h = normalise(hr.lo, hr.hi, hr.lo_open, hr.hi_open,
                                 sk_test_comment_zero_means(m->comment), integer);
        /* a desc's 0 means the default when the schema says what it becomes */
        bool zero = (f->flags & SK_FIELD_ZERO) || f->def != 0 || f->defs || f->def_text;
        norm_range k =
            normalise(f->min, f->max, (f->flags & SK_FIELD_OPEN_MIN) != 0, false, zero, integer);
        if (!same_range(h, k)) {
            char range[96];
            sk_schema_field_range_text(f, range, sizeof range);
            print_error("%s.%s: the header states %c%g, %g%c, the schema %s\n", schema->c_type,
                        m->name, hr.lo_open ? '(' : '[', hr.lo, hr.hi, hr.hi_open ? ')' : ']',
                        range);
            bad++;
        }
    }
    double d, ds[4];
    if (number && !f->def_text && !m->shared && f->type != SK_FIELD_FLOATS &&
        sk_test_comment_default(m->comment, &d) && !same_number(d, f->def)) {
        print_error("%s.%s: the header states the default %g, the schema %g\n", schema->c_type,
                    m->name, d, f->def);
        bad++;
    }
    if (f->type == SK_FIELD_FLOATS && f->defs && f->count <= 4 &&
        sk_test_comment_defaults(m->comment, ds, f->count))
        for (int i = 0; i < f->count; i++)
            if (!same_number(ds[i], f->defs[i])) {
                print_error("%s.%s[%d]: the header states the default %g, the schema %g\n",
                            schema->c_type, m->name, i, ds[i], f->defs[i]);
                bad++;
            }
    return bad;
}

static int check_schema_comments(const sk_schema *schema, const sk_schema **seen, int *seen_count)
{
    for (int i = 0; i < *seen_count; i++)
        if (seen[i] == schema) return 0;
    seen[(*seen_count)++] = schema;
    int bad = 0;
    sk_test_member members[SK_TEST_MAX_MEMBERS];
    int n =
        schema->c_type ? sk_test_struct_members(schema->c_type, members, SK_TEST_MAX_MEMBERS) : -1;
    for (int i = 0; i < n; i++) bad += check_member(schema, &members[i]);
    for (int i = 0; i < schema->field_count; i++)
        if (schema->fields[i].schema)
            bad += check_schema_comments(schema->fields[i].schema, seen, seen_count);
    return bad;
}

/* Where a public header's comment states a key's range or default, it is the schema's. */
static void test_header_comments_agree(void **state)
{
    (void)state;
    const sk_schema *seen[256];
    int seen_count = 0, bad = 0;
    for (size_t i = 0; i < sizeof k_schemas / sizeof k_schemas[0]; i++)
        bad += check_schema_comments(k_schemas[i], seen, &seen_count);
    assert_int_equal(bad, 0);
    /* the reader finds what it should: a range and a default of a known member */
    sk_test_member m[SK_TEST_MAX_MEMBERS];
    int n = sk_test_struct_members("sk_wood_log_desc", m, SK_TEST_MAX_MEMBERS);
    assert_int_equal(n, 2);
    assert_string_equal(m[0].name, "radius_mm");
    sk_test_range r;
    double d;
    assert_true(sk_test_comment_range(m[0].comment, &r));
    assert_float_equal(r.lo, 1, 0);
    assert_float_equal(r.hi, 2000, 0);
    assert_true(sk_test_comment_default(m[0].comment, &d));
    assert_float_equal(d, 150, 0);
}

/* ---------------------------------------------------------------- docs key tables */

/* Each block of a doc between "<!-- keys: COMMAND -->" and "<!-- end keys -->" against
 * `shitsukan COMMAND --help-keys=markdown`; returns the number of blocks, -1 on a
 * difference (printed). */
static int check_doc_tables(const char *name)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/docs/%s", SK_TEST_SOURCE_DIR, name);
    char *text = sk_test_read_file(path);
    assert_non_null(text);
    static const char open_tag[] = "<!-- keys: ", close_tag[] = "<!-- end keys -->";
    int blocks = 0;
    for (char *at = strstr(text, open_tag); at; at = strstr(at, open_tag)) {
        char *eol = strchr(at, '\n'), *close = strstr(at, close_tag);
        assert_non_null(eol);
        assert_non_null(close);
        char command[256];
        snprintf(command, sizeof command, "%.*s", (int)(eol - at - strlen(open_tag) - 4),
                 at + strlen(open_tag));
        static sk_test_run run;
        assert_int_equal(sk_test_cli(&run, "%s --help-keys=markdown", command), 0);
        size_t len = (size_t)(close - (eol + 1));
        if (strlen(run.out) != len || strncmp(run.out, eol + 1, len) != 0) {
            print_error("docs/%s: the key table of '%s' is not the schema's; run "
                        "scripts/docs-keys.sh build/shitsukan\n",
                        name, command);
            free(text);
            return -1;
        }
        blocks++;
        at = close;
    }
    free(text);
    return blocks;
}

/* The docs' key tables are the schemas' (generated by scripts/docs-keys.sh). */
static void test_docs_key_tables(void **state)
{
    (void)state;
    static const struct {
        const char *name;
        int tables;
    } docs[] = {{"skin.md", 1}, {"wood.md", 1},      {"tissue.md", 1},  {"render.md", 1},
                {"hand.md", 5}, {"hand-scan.md", 1}, {"showcase.md", 1}};
    for (size_t i = 0; i < sizeof docs / sizeof docs[0]; i++)
        assert_int_equal(check_doc_tables(docs[i].name), docs[i].tables);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_check_ranges),
        cmocka_unit_test(test_defaults),
        cmocka_unit_test(test_find_and_json_range),
        cmocka_unit_test(test_models_check_schema_ranges),
        cmocka_unit_test(test_models_resolve_schema_defaults),
        cmocka_unit_test(test_header_comments_agree),
        cmocka_unit_test(test_docs_key_tables),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
