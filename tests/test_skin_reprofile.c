/* Tests of sk_skin_reprofile: a built skin given new profiles, roundness, normal model,
 * pores and shading renders the same bytes as a skin built from that desc; a key that
 * places the cells is refused by name and a bad desc by its range, the skin unchanged;
 * sk_skin_desc_changes names what an edit changes, and the maps it does not name stay. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "shitsukan/preset.h"
#include "shitsukan/skin.h"
#include "test_support.h"

#define W 72
#define H 64

/* Every map of a skin at W x H, side by side in one allocation. */
typedef struct maps {
    float height[W * H], normal[3 * W * H], furrow[W * H], preview[3 * W * H], edges[3 * W * H];
    uint32_t ids[W * H];
    float range[2];
} maps;

static void render(const sk_skin *skin, int level, maps *m)
{
    sk_skin_render_desc rd = {.width = W,
                              .height = H,
                              .height_mm = m->height,
                              .normal = m->normal,
                              .furrow = m->furrow,
                              .cell_id = m->ids,
                              .preview = m->preview,
                              .edges = m->edges,
                              .furrow_level = level,
                              .id_level = level};
    sk_error err = {0};
    if (sk_skin_render(skin, &rd, &err) != SK_OK) fail_msg("render: %s", err.message);
    sk_skin_height_range(skin, &m->range[0], &m->range[1]);
}

static sk_skin *make(const sk_skin_desc *d)
{
    sk_skin *skin = NULL;
    sk_error err = {0};
    if (sk_skin_create(&skin, d, &err) != SK_OK) fail_msg("sk_skin_create: %s", err.message);
    return skin;
}

static sk_skin_desc preset(const char *name)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/skin/%s.json", SK_TEST_PRESET_DIR, name);
    sk_preset *p = NULL;
    sk_error err = {0};
    if (sk_preset_load_file(&p, path, &err) != SK_OK) fail_msg("%s: %s", name, err.message);
    sk_skin_desc d = {0};
    if (sk_preset_bind(p, &sk_skin_schema, &d, &err) != SK_OK)
        fail_msg("%s: %s", name, err.message);
    sk_preset_free(p);
    return d;
}

/* `b` differs from `a` in every key that leaves the cells alone. */
static sk_skin_desc reprofiled(const sk_skin_desc *a)
{
    sk_skin_desc b = sk_skin_desc_resolved(a);
    for (int k = 0; k < b.level_count; k++) {
        sk_skin_level *lv = &b.levels[k];
        /* two segments instead of the level's profile: a plateau, then the fall */
        lv->segment_count = 2;
        const float first[4][2] = {{0, 2.5f}, {2, 2.6f}, {4, 2.6f}, {6, 2.2f}};
        const float second[4][2] = {{6, 2.2f}, {7.5f, 1.8f}, {9, 1.2f}, {10, 0.1f * k}};
        memcpy(lv->segments[0].points, first, sizeof first);
        memcpy(lv->segments[1].points, second, sizeof second);
        lv->roundness = 0.55f - 0.1f * k;
    }
    b.normal_model =
        b.normal_model == SK_SKIN_NORMAL_PROFILE ? SK_SKIN_NORMAL_GRADIENT : SK_SKIN_NORMAL_PROFILE;
    b.pores.hair = (sk_skin_pore_kind){.depth_mm = 0.03f, .radius_mm = 0.05f, .density = 0.7f};
    b.pores.sweat = (sk_skin_pore_kind){.depth_mm = 0.01f, .radius_mm = 0.02f, .density = 0.4f};
    b.pores.sweat_level = b.level_count;
    b.shading.light_azimuth = 1.1f;
    b.shading.light_elevation = 0.6f;
    b.shading.albedo[0] = 0.7f, b.shading.albedo[1] = 0.6f, b.shading.albedo[2] = 0.5f;
    b.shading.sun_fraction = 0.7f;
    b.shading.specular = 0.2f;
    b.shading.shininess = 40.5f;
    return b;
}

static void expect_same(const maps *a, const maps *b, const char *what)
{
    if (memcmp(a, b, sizeof *a) != 0) {
        int first = -1;
        for (int i = 0; i < W * H && first < 0; i++)
            if (memcmp(&a->height[i], &b->height[i], sizeof(float)) ||
                memcmp(&a->preview[3 * i], &b->preview[3 * i], 3 * sizeof(float)))
                first = i;
        fail_msg("%s: the maps differ from a freshly built skin's (first height or preview "
                 "pixel %d; range %g..%g vs %g..%g)",
                 what, first, a->range[0], a->range[1], b->range[0], b->range[1]);
    }
}

/* A skin built from `a` and re-profiled to `b` renders every map as the skin built from
 * `b` does, bit for bit; re-profiled back, as the skin built from `a`. The descs differ by
 * `changes` (sk_skin_desc_changes), and the maps those do not name are the same bytes. */
static void check_round_trip(const char *name, const sk_skin_desc *a, const sk_skin_desc *b,
                             unsigned changes)
{
    if (sk_skin_desc_changes(a, b) != changes || sk_skin_desc_changes(b, a) != changes)
        fail_msg("%s: changes %u / %u, want %u", name, sk_skin_desc_changes(a, b),
                 sk_skin_desc_changes(b, a), changes);
    maps *got = malloc(sizeof *got), *want = malloc(sizeof *want);
    sk_skin *fresh_a = make(a), *fresh_b = make(b), *edited = make(a);
    sk_error err = {0};
    int level = b->level_count > 1 ? 2 : 1;
    if (sk_skin_reprofile(edited, b, &err) != SK_OK) fail_msg("%s: %s", name, err.message);
    render(fresh_b, level, want);
    render(edited, level, got);
    expect_same(got, want, name);
    /* the pictures did change (the test would not see a reprofile that does nothing) */
    maps *before = malloc(sizeof *before);
    render(fresh_a, level, before);
    assert_true(memcmp(before->preview, want->preview, sizeof want->preview) != 0);
    /* the cells are the ones the keys place: the cells map and the furrow are the same */
    assert_memory_equal(before->ids, want->ids, sizeof want->ids);
    assert_memory_equal(before->furrow, want->furrow, sizeof want->furrow);
    if (!(changes & SK_SKIN_CHANGE_RELIEF)) {
        /* a shading edit: the same normals, and the preview is their shading */
        assert_memory_equal(before->height, want->height, sizeof want->height);
        assert_memory_equal(before->normal, want->normal, sizeof want->normal);
        for (int i = 0; i < W * H; i++) {
            const float *n = &before->normal[3 * i];
            sk_vec3f c = sk_skin_shade(fresh_b, (sk_vec3f){n[0], n[1], n[2]});
            if (memcmp(&c.x, &want->preview[3 * i], sizeof(float)) ||
                memcmp(&c.y, &want->preview[3 * i + 1], sizeof(float)) ||
                memcmp(&c.z, &want->preview[3 * i + 2], sizeof(float)))
                fail_msg("%s: pixel %d shaded from the normals differs from the render", name, i);
        }
    } else {
        assert_true(memcmp(before->normal, want->normal, sizeof want->normal) != 0);
    }
    if (sk_skin_reprofile(edited, a, &err) != SK_OK) fail_msg("%s back: %s", name, err.message);
    render(edited, level, got);
    expect_same(got, before, name);
    /* the desc reads back as the one given */
    sk_skin_desc ra = sk_skin_desc_resolved(a);
    const sk_skin_desc *now = sk_skin_get_desc(edited);
    assert_int_equal(now->levels[0].segment_count, ra.levels[0].segment_count);
    assert_float_equal(now->levels[0].roundness, ra.levels[0].roundness, 0);
    assert_float_equal(now->shading.light_azimuth, ra.shading.light_azimuth, 0);
    free(got), free(want), free(before);
    sk_skin_destroy(fresh_a), sk_skin_destroy(fresh_b), sk_skin_destroy(edited);
}

static void test_reprofile_equals_build(void **state)
{
    (void)state;
    const char *names[] = {"back-of-hand", "fig13a", "fig17b", "fig19a"};
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++) {
        sk_skin_desc a = preset(names[i]);
        a.size_mm[0] = fminf(a.size_mm[0] ? a.size_mm[0] : 10, 3.0f);
        a.size_mm[1] = fminf(a.size_mm[1] ? a.size_mm[1] : 10, 2.5f);
        sk_skin_desc b = reprofiled(&a);
        check_round_trip(names[i], &a, &b, SK_SKIN_CHANGE_RELIEF | SK_SKIN_CHANGE_SHADING);
    }
}

/* Only the shading, only one level's profile, only the pores: each a fresh skin's bytes. */
static void test_reprofile_single_keys(void **state)
{
    (void)state;
    sk_skin_desc a = preset("back-of-hand");
    a.size_mm[0] = a.size_mm[1] = 2.0f;
    sk_skin_desc shading = sk_skin_desc_resolved(&a);
    shading.shading.no_specular = true;
    shading.shading.light_azimuth = -0.4f;
    check_round_trip("shading", &a, &shading, SK_SKIN_CHANGE_SHADING);
    sk_skin_desc profile = sk_skin_desc_resolved(&a);
    profile.levels[1].segments[0].points[1][1] = 3.4f;
    check_round_trip("levels[1] profile", &a, &profile, SK_SKIN_CHANGE_RELIEF);
    sk_skin_desc model = sk_skin_desc_resolved(&a);
    model.normal_model = SK_SKIN_NORMAL_PROFILE;
    model.levels[2].roundness = 0.7f;
    check_round_trip("normal model and roundness", &a, &model, SK_SKIN_CHANGE_RELIEF);
    sk_skin_desc pores = sk_skin_desc_resolved(&a);
    pores.pores.hair.density = 1.0f;
    pores.pores.sweat.depth_mm = 0.0f;
    check_round_trip("pores", &a, &pores, SK_SKIN_CHANGE_RELIEF);
    /* keys that change nothing: the same desc, resolved or not; a pore kind that digs
       nowhere; the control points past the profile's segments */
    sk_skin_desc same = sk_skin_desc_resolved(&a);
    assert_int_equal(sk_skin_desc_changes(&a, &same), 0);
    same.pores.sweat.depth_mm = 0;
    sk_skin_desc same2 = same;
    same2.pores.sweat.radius_mm = 0.5f;
    same2.pores.sweat.density = 1.0f;
    same2.levels[0].segments[5].points[2][1] = 7.0f;
    assert_int_equal(sk_skin_desc_changes(&same, &same2), 0);
}

/* A desc that differs in a key placing the cells is refused by name, and the skin renders
 * as before. */
static void test_reprofile_refuses_cell_keys(void **state)
{
    (void)state;
    sk_skin_desc a = preset("back-of-hand");
    a.size_mm[0] = a.size_mm[1] = 1.6f;
    sk_skin *skin = make(&a);
    maps *before = malloc(sizeof *before), *after = malloc(sizeof *after);
    render(skin, 1, before);
    struct {
        const char *key;
        sk_skin_desc d;
    } cases[13];
    int n = 0;
    for (int i = 0; i < 13; i++) cases[i].d = sk_skin_desc_resolved(&a);
    cases[n].key = "seed", cases[n++].d.seed += 1;
    cases[n].key = "size_mm", cases[n++].d.size_mm[1] = 1.7f;
    cases[n].key = "aperiodic", cases[n++].d.aperiodic = true;
    cases[n].key = "levels (their count)", cases[n++].d.level_count = 2;
    cases[n].key = "levels[1].layout", cases[n++].d.levels[1].layout = SK_SKIN_LAYOUT_SQUARE;
    cases[n].key = "levels[0].jitter", cases[n++].d.levels[0].jitter = SK_SKIN_JITTER_NORMAL;
    cases[n].key = "levels[2].jitter_rate", cases[n++].d.levels[2].jitter_rate = 0.2f;
    cases[n].key = "levels[1].spacing_mm", cases[n++].d.levels[1].spacing_mm = 0.25f;
    cases[n].key = "levels[0].perturb_rate", cases[n++].d.levels[0].perturb_rate = 0.2f;
    cases[n].key = "levels[0].perturb_decay", cases[n++].d.levels[0].perturb_decay = 0.5f;
    cases[n].key = "levels[2].perturb_depth", cases[n++].d.levels[2].perturb_depth = 3;
    cases[n].key = "levels[1].stretch", cases[n++].d.levels[1].stretch[0] = 1.5f;
    cases[n].key = "levels[0].stretch_angle_deg", cases[n++].d.levels[0].stretch_angle = 0.3f;
    for (int i = 0; i < n; i++) {
        sk_error err = {0};
        /* a profile edit beside it is not applied either */
        cases[i].d.levels[0].roundness = 0.9f;
        assert_int_equal(sk_skin_desc_changes(&a, &cases[i].d), SK_SKIN_CHANGE_CELLS);
        assert_int_equal(sk_skin_reprofile(skin, &cases[i].d, &err), SK_ERROR_UNSUPPORTED);
        char want[96];
        snprintf(want, sizeof want, "%s differs", cases[i].key);
        if (!strstr(err.message, want)) fail_msg("%s: message '%s'", cases[i].key, err.message);
        render(skin, 1, after);
        if (memcmp(before, after, sizeof *before) != 0)
            fail_msg("%s: a refused reprofile changed the skin", cases[i].key);
    }
    /* a bad value: refused with its range, the skin unchanged */
    sk_skin_desc bad = sk_skin_desc_resolved(&a);
    bad.levels[1].roundness = 2.0f;
    sk_error err = {0};
    assert_int_equal(sk_skin_reprofile(skin, &bad, &err), SK_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(err.message, "levels[1].roundness"));
    bad = sk_skin_desc_resolved(&a);
    bad.levels[0].segments[0].points[3][0] = 9.0f;
    assert_int_equal(sk_skin_reprofile(skin, &bad, &err), SK_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(err.message, "levels[0].profile[0].points[3][0]"));
    assert_int_equal(sk_skin_reprofile(NULL, &a, &err), SK_ERROR_INVALID_ARGUMENT);
    assert_int_equal(sk_skin_reprofile(skin, NULL, &err), SK_ERROR_INVALID_ARGUMENT);
    render(skin, 1, after);
    assert_memory_equal(before, after, sizeof *before);
    /* the unresolved desc it was built from is its own cells: accepted */
    assert_int_equal(sk_skin_reprofile(skin, &a, &err), SK_OK);
    render(skin, 1, after);
    assert_memory_equal(before, after, sizeof *before);
    free(before), free(after);
    sk_skin_destroy(skin);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_reprofile_equals_build),
        cmocka_unit_test(test_reprofile_single_keys),
        cmocka_unit_test(test_reprofile_refuses_cell_keys),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
