/* Tests of the maps module: the layout of the skin and wood map sets, the store's
 * encodings (normals in 1/32767, furrow codes over half the spacing), each map's codes
 * against the skin's own float render, the banded render (every row once, regions equal
 * to the whole map's pixels), releases, errors and the files' metadata. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "shitsukan/maps.h"
#include "test_support.h"

/* A 3-level skin on a small tile (Fig. 19a's kind). */
static sk_skin *make_skin(uint64_t seed)
{
    sk_skin_desc d = {0};
    d.seed = seed;
    d.size_mm[0] = 2.0f;
    d.size_mm[1] = 1.6f;
    d.level_count = 3;
    static const float prof[3][4][2] = {{{0, 4}, {5, 4}, {9, 3}, {10, 0}},
                                        {{0, 2}, {5, 2}, {9, 1.5f}, {10, 0}},
                                        {{0, 0.8f}, {5, 0.8f}, {9, 0.4f}, {10, 0}}};
    const float spacing[3] = {0.8f, 0.32f, 0.13f};
    for (int k = 0; k < 3; k++) {
        sk_skin_level *lv = &d.levels[k];
        lv->jitter_rate = 0.5f;
        lv->spacing_mm = spacing[k];
        lv->perturb_rate = 0.1f;
        lv->perturb_decay = 1.0f;
        lv->segment_count = 1;
        memcpy(lv->segments[0].points, prof[k], sizeof prof[k]);
        lv->roundness = 0.2f;
    }
    sk_skin *skin = NULL;
    sk_error err = {0};
    if (sk_skin_create(&skin, &d, &err) != SK_OK) fail_msg("sk_skin_create: %s", err.message);
    return skin;
}

static sk_skin_maps *make_maps(const sk_skin *skin, const sk_skin_maps_desc *d)
{
    sk_skin_maps *maps = NULL;
    sk_error err = {0};
    if (sk_skin_maps_create(&maps, skin, d, &err) != SK_OK)
        fail_msg("sk_skin_maps_create: %s", err.message);
    if (sk_skin_maps_render(maps, 0, &err) != SK_OK)
        fail_msg("sk_skin_maps_render: %s", err.message);
    return maps;
}

/* The skin's own float maps of a region (the reference the set's codes derive from). */
typedef struct float_maps {
    float *height, *normal, *furrow, *preview;
    uint32_t *ids;
} float_maps;

static float_maps render_floats(const sk_skin *skin, int w, int h, const int region[4],
                                int furrow_level, int id_level)
{
    size_t n = (size_t)region[2] * (size_t)region[3];
    float_maps f = {malloc(n * 4), malloc(n * 12), malloc(n * 4), malloc(n * 12), malloc(n * 4)};
    sk_skin_render_desc rd = {.width = w,
                              .height = h,
                              .region = {region[0], region[1], region[2], region[3]},
                              .height_mm = f.height,
                              .normal = f.normal,
                              .furrow = f.furrow,
                              .cell_id = f.ids,
                              .preview = f.preview,
                              .furrow_level = furrow_level,
                              .id_level = id_level};
    sk_error err = {0};
    assert_int_equal(sk_skin_render(skin, &rd, &err), SK_OK);
    return f;
}

static void free_floats(float_maps *f)
{
    free(f->height), free(f->normal), free(f->furrow), free(f->preview), free(f->ids);
}

static int iabs(int v) { return v < 0 ? -v : v; }

static void test_layout(void **state)
{
    (void)state;
    static const struct {
        const char *file;
        int channels, bits;
        bool srgb;
    } skin[SK_SKIN_MAP_COUNT] = {{"height.exr", 1, 32, false}, {"height.png", 1, 16, false},
                                 {"furrow.png", 1, 16, false}, {"cells.png", 3, 8, false},
                                 {"normal.png", 3, 8, false},  {"preview.png", 3, 8, true},
                                 {"edges.png", 3, 8, true}};
    for (int k = 0; k < SK_SKIN_MAP_COUNT; k++) {
        const sk_map_info *info = sk_skin_map_info((sk_skin_map)k);
        assert_non_null(info);
        assert_string_equal(info->file, skin[k].file);
        assert_int_equal(info->channels, skin[k].channels);
        assert_int_equal(info->bit_depth, skin[k].bits);
        assert_int_equal(info->srgb, skin[k].srgb);
        for (int j = 0; j < k; j++)
            assert_string_not_equal(info->name, sk_skin_map_info((sk_skin_map)j)->name);
    }
    assert_null(sk_skin_map_info(SK_SKIN_MAP_COUNT));
    assert_null(sk_skin_map_info((sk_skin_map)-1));
    /* the default set: every map but edges.png */
    assert_int_equal(SK_SKIN_MAPS_DEFAULT,
                     (1u << SK_SKIN_MAP_COUNT) - 1u - (1u << SK_SKIN_MAP_EDGES));
    /* the store: height 4 + normal 2 x 2 + furrow 2 + id 4 bytes; float RGB previews 12 */
    assert_true(sk_skin_maps_bytes_per_pixel(&(sk_skin_maps_desc){0}) == 14.0);
    assert_true(sk_skin_maps_bytes_per_pixel(&(sk_skin_maps_desc){.samples = 2}) == 26.0);
    assert_true(sk_skin_maps_bytes_per_pixel(&(sk_skin_maps_desc){
                    .samples = 2,
                    .maps = SK_SKIN_MAPS_DEFAULT | SK_SKIN_MAP_BIT(SK_SKIN_MAP_EDGES)}) == 38.0);
    assert_true(sk_skin_maps_bytes_per_pixel(
                    &(sk_skin_maps_desc){.maps = SK_SKIN_MAP_BIT(SK_SKIN_MAP_FURROW) |
                                                 SK_SKIN_MAP_BIT(SK_SKIN_MAP_CELLS)}) == 6.0);

    static const char *const wood[SK_WOOD_MAP_COUNT] = {"albedo.png", "fibre.png", "pores.png"};
    static const int wood_bits[SK_WOOD_MAP_COUNT] = {8, 16, 8},
                     wood_ch[SK_WOOD_MAP_COUNT] = {3, 3, 1};
    sk_wood_cut_desc cut = {0};
    for (int k = 0; k < SK_WOOD_MAP_COUNT; k++) {
        const sk_map_info *info = sk_wood_map_info((sk_wood_map)k);
        assert_string_equal(info->file, wood[k]);
        assert_int_equal(info->bit_depth, wood_bits[k]);
        assert_int_equal(info->channels, wood_ch[k]);
        assert_int_equal(info->srgb, k == SK_WOOD_MAP_ALBEDO);
        assert_int_equal(info->encoding != NULL, k != SK_WOOD_MAP_ALBEDO);
    }
    assert_ptr_equal(sk_wood_maps_cut_output(&cut, SK_WOOD_MAP_ALBEDO), &cut.albedo);
    assert_ptr_equal(sk_wood_maps_cut_output(&cut, SK_WOOD_MAP_FIBRE), &cut.fibre);
    assert_ptr_equal(sk_wood_maps_cut_output(&cut, SK_WOOD_MAP_PORES), &cut.vessel);
    assert_null(sk_wood_maps_cut_output(&cut, SK_WOOD_MAP_COUNT));
    assert_null(sk_wood_map_info(SK_WOOD_MAP_COUNT));
}

static void test_store_encodings(void **state)
{
    (void)state;
    /* x, y in 1/32767: 0.6 x 32767 = 19660.2, -0.8 x 32767 = -26213.6 */
    int16_t xy[2];
    sk_skin_maps_store_normal((const float[3]){0.6f, -0.8f, 0.0f}, xy);
    assert_int_equal(xy[0], 19660);
    assert_int_equal(xy[1], -26214);
    float n[3];
    sk_skin_maps_load_normal(xy, n);
    assert_true(fabsf(n[0] - 19660.0f / 32767) < 1e-7f && fabsf(n[1] + 26214.0f / 32767) < 1e-7f);
    assert_true(n[2] >= 0.0f && n[2] < 0.01f); /* 1 - x^2 - y^2 is (about) 0 */
    sk_skin_maps_store_normal((const float[3]){0.0f, 0.0f, 1.0f}, xy);
    sk_skin_maps_load_normal(xy, n);
    assert_true(xy[0] == 0 && xy[1] == 0 && n[2] == 1.0f);
    /* z of a tilted unit normal comes back from x and y alone */
    float t[3] = {0.28f, 0.48f, sqrtf(1.0f - 0.28f * 0.28f - 0.48f * 0.48f)};
    sk_skin_maps_store_normal(t, xy);
    sk_skin_maps_load_normal(xy, n);
    for (int c = 0; c < 3; c++) assert_true(fabsf(n[c] - t[c]) < 1e-4f);
    /* furrow codes: round(min(d / span, 1) x 65535) */
    assert_int_equal(sk_skin_maps_furrow_code(0.0f, 0.4f), 0);
    assert_int_equal(sk_skin_maps_furrow_code(0.1f, 0.4f), 16384); /* 16383.75 */
    assert_int_equal(sk_skin_maps_furrow_code(0.2f, 0.4f), 32768); /* 32767.5, to even */
    assert_int_equal(sk_skin_maps_furrow_code(0.4f, 0.4f), 65535);
    assert_int_equal(sk_skin_maps_furrow_code(3.0f, 0.4f), 65535); /* clamped */
}

static void test_furrow_span(void **state)
{
    (void)state;
    sk_skin *skin = make_skin(1);
    const sk_skin_desc *d = sk_skin_get_desc(skin);
    /* half each level's spacing: 0.8, 0.32, 0.13 mm */
    assert_true(sk_skin_maps_furrow_span(skin, 1) == 0.4f);
    assert_true(sk_skin_maps_furrow_span(skin, 0) == 0.4f);
    assert_true(sk_skin_maps_furrow_span(skin, 2) == 0.5f * d->levels[1].spacing_mm);
    assert_true(fabsf(sk_skin_maps_furrow_span(skin, 3) - 0.065f) < 1e-7f);
    assert_true(sk_skin_maps_furrow_span(skin, 4) == 0.0f);
    assert_true(sk_skin_maps_furrow_span(NULL, 1) == 0.0f);
    /* the decode rule furrow.png carries states the same span */
    sk_skin_maps *maps =
        make_maps(skin, &(sk_skin_maps_desc){.width = 8, .height = 8, .furrow_level = 2});
    sk_image_metadata meta = {0};
    assert_int_equal(sk_skin_maps_metadata(maps, SK_SKIN_MAP_FURROW, NULL, &meta, NULL), SK_OK);
    char want[96];
    snprintf(want, sizeof want, "distance_mm = value * %.9g (clamped there)",
             0.5f * d->levels[1].spacing_mm);
    assert_string_equal(sk_image_metadata_get(&meta, "shitsukan:decode"), want);
    assert_string_equal(sk_image_metadata_get(&meta, "shitsukan:furrow_level"), "2");
    sk_skin_maps_destroy(maps);
    sk_skin_destroy(skin);
}

/* Every map's codes against the definitions applied to the skin's own float render. */
static void test_codes_match_render(void **state)
{
    (void)state;
    sk_skin *skin = make_skin(2);
    const int w = 48, h = 41, whole[4] = {0, 0, 48, 41};
    sk_skin_maps *maps = make_maps(
        skin, &(sk_skin_maps_desc){
                  .width = w, .height = h, .furrow_level = 2, .id_level = 3, .directx = true});
    float_maps f = render_floats(skin, w, h, whole, 2, 3);
    size_t n = (size_t)w * h;
    float lo, hi;
    sk_skin_height_range(skin, &lo, &hi);
    float span = sk_skin_maps_furrow_span(skin, 2);
    uint16_t *c16 = malloc(n * 2);
    uint8_t *c8 = malloc(n * 3), *want8 = malloc(n * 3);
    float *values = malloc(n * 12);
    sk_error err = {0};

    assert_int_equal(sk_skin_maps_rows(maps, SK_SKIN_MAP_HEIGHT_MM, 0, h, values, &err), SK_OK);
    assert_memory_equal(values, f.height, n * sizeof(float));
    assert_int_equal(sk_skin_maps_codes16(maps, SK_SKIN_MAP_HEIGHT, 0, h, c16, &err), SK_OK);
    for (size_t i = 0; i < n; i++) {
        double v = ((double)f.height[i] - lo) / ((double)hi - lo);
        assert_true(v >= 0.0 && v <= 1.0); /* the range bounds every height */
        assert_true(iabs((int)c16[i] - (int)floor(v * 65535 + 0.5)) <= 1);
    }
    assert_int_equal(sk_skin_maps_codes16(maps, SK_SKIN_MAP_FURROW, 0, h, c16, &err), SK_OK);
    for (size_t i = 0; i < n; i++) {
        double v = fmin(f.furrow[i] / (double)span, 1.0);
        assert_true(iabs((int)c16[i] - (int)floor(v * 65535 + 0.5)) <= 1);
        assert_int_equal(c16[i], sk_skin_maps_furrow_code(f.furrow[i], span));
    }
    /* cells: the colour of the same ids */
    for (size_t i = 0; i < n; i++) sk_skin_cell_color(f.ids[i], values + 3 * i);
    sk_image_codes8(values, n, 3, SK_PNG_ENCODING_LINEAR, want8);
    assert_int_equal(sk_skin_maps_codes8(maps, SK_SKIN_MAP_CELLS, 0, h, c8, &err), SK_OK);
    assert_memory_equal(c8, want8, n * 3);
    /* normals (DirectX: green down) within one code of the float normal's */
    size_t exact = 0;
    assert_int_equal(sk_skin_maps_codes8(maps, SK_SKIN_MAP_NORMAL, 0, h, c8, &err), SK_OK);
    for (size_t i = 0; i < 3 * n; i++) {
        float v = f.normal[i] * (i % 3 == 1 ? -1.0f : 1.0f);
        int want = (int)floor((0.5 * v + 0.5) * 255 + 0.5);
        assert_true(iabs(c8[i] - want) <= 1);
        exact += c8[i] == want;
    }
    assert_true(exact >= 3 * n * 99 / 100);
    /* the preview shaded from the kept normals, within one code of the render's */
    sk_image_codes8(f.preview, n, 3, SK_PNG_ENCODING_SRGB, want8);
    assert_int_equal(sk_skin_maps_codes8(maps, SK_SKIN_MAP_PREVIEW, 0, h, c8, &err), SK_OK);
    exact = 0;
    for (size_t i = 0; i < 3 * n; i++) {
        assert_true(iabs(c8[i] - want8[i]) <= 1);
        exact += c8[i] == want8[i];
    }
    assert_true(exact >= 3 * n * 99 / 100);
    /* 8-bit codes of a 16-bit map: the 8-bit file it would be */
    assert_int_equal(sk_skin_maps_codes8(maps, SK_SKIN_MAP_HEIGHT, 0, h, c8, &err), SK_OK);
    assert_int_equal(sk_skin_maps_rows(maps, SK_SKIN_MAP_HEIGHT, 0, h, values, &err), SK_OK);
    sk_image_codes8(values, n, 1, SK_PNG_ENCODING_LINEAR, want8);
    assert_memory_equal(c8, want8, n);
    free(c16), free(c8), free(want8), free(values);
    free_floats(&f);
    sk_skin_maps_destroy(maps);
    sk_skin_destroy(skin);
}

typedef struct progress_log {
    int calls;
    double last;
    bool increasing;
} progress_log;

static void log_progress(void *user, double fraction)
{
    progress_log *p = user;
    if (fraction <= p->last) p->increasing = false;
    p->last = fraction;
    p->calls++;
}

/* The bands cover every row once: one report per band, ending at 1; a region's pixels are
 * the whole map's, bands that straddle its edge included. */
static void test_bands_cover_every_row_once(void **state)
{
    (void)state;
    sk_skin *skin = make_skin(3);
    const int w = 60, h = 50, region[4] = {7, 5, 30, 41}; /* 41 rows: 10 bands and 1 row */
    progress_log log = {0, 0.0, true};
    sk_skin_maps_desc d = {.width = w,
                           .height = h,
                           .region = {region[0], region[1], region[2], region[3]},
                           .progress = {log_progress, &log}};
    sk_skin_maps *part = make_maps(skin, &d);
    assert_int_equal(log.calls, (region[3] + SK_SKIN_MAPS_BAND_ROWS - 1) / SK_SKIN_MAPS_BAND_ROWS);
    assert_true(log.increasing && log.last == 1.0);
    sk_skin_maps *whole = make_maps(skin, &(sk_skin_maps_desc){.width = w, .height = h});
    float_maps f = render_floats(skin, w, h, region, 1, 1);
    float *a = malloc(sizeof(float) * 3 * w), *b = malloc(sizeof(float) * 3 * w);
    sk_error err = {0};
    for (int k = 0; k < SK_SKIN_MAP_EDGES; k++) {
        int ch = sk_skin_map_info((sk_skin_map)k)->channels;
        for (int y = 0; y < region[3]; y++) {
            assert_int_equal(sk_skin_maps_rows(part, (sk_skin_map)k, y, 1, a, &err), SK_OK);
            assert_int_equal(sk_skin_maps_rows(whole, (sk_skin_map)k, region[1] + y, 1, b, &err),
                             SK_OK);
            assert_memory_equal(a, b + region[0] * ch, sizeof(float) * region[2] * ch);
        }
    }
    /* each row holds the render of that row (not another band's) */
    for (int y = 0; y < region[3]; y++) {
        assert_int_equal(sk_skin_maps_rows(part, SK_SKIN_MAP_HEIGHT_MM, y, 1, a, &err), SK_OK);
        assert_memory_equal(a, f.height + (size_t)y * region[2], sizeof(float) * region[2]);
    }
    free(a), free(b);
    free_floats(&f);
    sk_skin_maps_destroy(part);
    sk_skin_maps_destroy(whole);
    sk_skin_destroy(skin);
}

/* Rendering some maps leaves the others unreadable; the furrow and cells maps alone (no
 * relief) are the bytes of a full render; released parts are gone. */
static void test_partial_render_and_release(void **state)
{
    (void)state;
    sk_skin *skin = make_skin(4);
    sk_skin_maps_desc d = {.width = 32, .height = 24, .samples = 2};
    sk_skin_maps *full = make_maps(skin, &d), *part = NULL;
    sk_error err = {0};
    assert_int_equal(sk_skin_maps_create(&part, skin, &d, &err), SK_OK);
    uint16_t a[32 * 24], b[32 * 24];
    uint8_t c[32 * 24 * 3], e[32 * 24 * 3];
    assert_int_equal(sk_skin_maps_codes16(part, SK_SKIN_MAP_FURROW, 0, 24, a, &err),
                     SK_ERROR_INVALID_ARGUMENT);
    unsigned cheap = SK_SKIN_MAP_BIT(SK_SKIN_MAP_FURROW) | SK_SKIN_MAP_BIT(SK_SKIN_MAP_CELLS);
    assert_int_equal(sk_skin_maps_render(part, cheap, &err), SK_OK);
    assert_int_equal(sk_skin_maps_codes16(part, SK_SKIN_MAP_FURROW, 0, 24, a, &err), SK_OK);
    assert_int_equal(sk_skin_maps_codes16(full, SK_SKIN_MAP_FURROW, 0, 24, b, &err), SK_OK);
    assert_memory_equal(a, b, sizeof a);
    assert_int_equal(sk_skin_maps_codes8(part, SK_SKIN_MAP_CELLS, 0, 24, c, &err), SK_OK);
    assert_int_equal(sk_skin_maps_codes8(full, SK_SKIN_MAP_CELLS, 0, 24, e, &err), SK_OK);
    assert_memory_equal(c, e, sizeof c);
    assert_int_equal(sk_skin_maps_codes8(part, SK_SKIN_MAP_NORMAL, 0, 24, c, &err),
                     SK_ERROR_INVALID_ARGUMENT);
    /* with 2 samples the preview is rendered and held as a float image */
    assert_non_null(sk_skin_maps_image(full, SK_SKIN_MAP_PREVIEW));
    assert_non_null(sk_skin_maps_image(full, SK_SKIN_MAP_HEIGHT_MM));
    assert_null(sk_skin_maps_image(full, SK_SKIN_MAP_NORMAL));
    assert_null(sk_skin_maps_image(full, SK_SKIN_MAP_EDGES)); /* not held */
    /* released in file order: height.png drops the heights, the rest stays */
    sk_skin_maps_release(full, SK_SKIN_MAP_HEIGHT);
    assert_null(sk_skin_maps_image(full, SK_SKIN_MAP_HEIGHT_MM));
    assert_int_equal(sk_skin_maps_codes16(full, SK_SKIN_MAP_HEIGHT, 0, 24, a, &err),
                     SK_ERROR_INVALID_ARGUMENT);
    assert_int_equal(sk_skin_maps_codes16(full, SK_SKIN_MAP_FURROW, 0, 24, a, &err), SK_OK);
    assert_int_equal(sk_skin_maps_render(full, SK_SKIN_MAP_BIT(SK_SKIN_MAP_HEIGHT), &err),
                     SK_ERROR_INVALID_ARGUMENT);
    sk_skin_maps_release(full, SK_SKIN_MAP_PREVIEW);
    assert_null(sk_skin_maps_image(full, SK_SKIN_MAP_PREVIEW));
    sk_skin_maps_destroy(part);
    sk_skin_maps_destroy(full);
    sk_skin_destroy(skin);
}

static void test_errors(void **state)
{
    (void)state;
    sk_skin *skin = make_skin(5);
    sk_skin_maps *maps = NULL;
    sk_error err = {0};
    const sk_skin_maps_desc bad[] = {
        {.width = 0, .height = 8},
        {.width = 8, .height = 70000},
        {.width = 8, .height = 8, .region = {4, 0, 8, 8}},
        {.width = 8, .height = 8, .furrow_level = 4},
        {.width = 8, .height = 8, .id_level = -1},
        {.width = 8, .height = 8, .samples = 9},
        {.width = 8, .height = 8, .maps = 1u << SK_SKIN_MAP_COUNT},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        assert_int_equal(sk_skin_maps_create(&maps, skin, &bad[i], &err),
                         SK_ERROR_INVALID_ARGUMENT);
        assert_null(maps);
        assert_true(err.message[0] != '\0');
    }
    assert_int_equal(sk_skin_maps_create(&maps, NULL, &bad[0], &err), SK_ERROR_INVALID_ARGUMENT);
    maps = make_maps(skin, &(sk_skin_maps_desc){.width = 8, .height = 8});
    uint16_t codes[64];
    float samples[64 * 3];
    assert_int_equal(sk_skin_maps_codes16(maps, SK_SKIN_MAP_NORMAL, 0, 8, codes, &err),
                     SK_ERROR_INVALID_ARGUMENT); /* an 8-bit map */
    assert_int_equal(sk_skin_maps_codes16(maps, SK_SKIN_MAP_HEIGHT_MM, 0, 8, codes, &err),
                     SK_ERROR_INVALID_ARGUMENT); /* floats */
    assert_int_equal(sk_skin_maps_rows(maps, SK_SKIN_MAP_EDGES, 0, 1, samples, &err),
                     SK_ERROR_INVALID_ARGUMENT); /* not held */
    assert_int_equal(sk_skin_maps_rows(maps, SK_SKIN_MAP_HEIGHT, 4, 5, samples, &err),
                     SK_ERROR_INVALID_ARGUMENT); /* rows 4..8 of 8 */
    assert_int_equal(sk_skin_maps_render(maps, SK_SKIN_MAP_BIT(SK_SKIN_MAP_EDGES), &err),
                     SK_ERROR_INVALID_ARGUMENT);
    assert_false(sk_skin_maps_holds(maps, SK_SKIN_MAP_EDGES));
    assert_true(sk_skin_maps_holds(maps, SK_SKIN_MAP_PREVIEW));
    sk_skin_maps_destroy(maps);
    sk_skin_destroy(skin);
}

static void test_metadata(void **state)
{
    (void)state;
    sk_skin *skin = make_skin(6);
    sk_skin_maps *maps = make_maps(skin, &(sk_skin_maps_desc){.width = 40, .height = 32});
    sk_image_metadata meta = {0};
    assert_int_equal(sk_skin_maps_metadata(maps, SK_SKIN_MAP_HEIGHT, "me", &meta, NULL), SK_OK);
    static const char *const keys[] = {"shitsukan:seed",
                                       "shitsukan:tile_mm",
                                       SK_IMAGE_KEY_MM_PER_PIXEL,
                                       "shitsukan:seamless",
                                       "Software",
                                       "shitsukan:units",
                                       "shitsukan:height_min_mm",
                                       "shitsukan:height_max_mm",
                                       "shitsukan:decode"};
    assert_int_equal(meta.count, 9);
    for (int i = 0; i < 9; i++) assert_string_equal(meta.entries[i].key, keys[i]);
    assert_string_equal(meta.entries[0].value, "6");
    assert_string_equal(meta.entries[1].value, "2 x 1.60000002");
    assert_string_equal(meta.entries[2].value, "0.05"); /* 2 mm over 40 pixels */
    assert_string_equal(meta.entries[3].value, "true");
    float lo, hi;
    sk_skin_height_range(skin, &lo, &hi);
    char want[128];
    snprintf(want, sizeof want, "height_mm = %.9g + value * %.9g (value = code / 65535)", lo,
             hi - lo);
    assert_string_equal(meta.entries[8].value, want);
    /* the EXR: the heights' keys without the codes' decode rule */
    sk_image_metadata exr = {0};
    assert_int_equal(sk_skin_maps_metadata(maps, SK_SKIN_MAP_HEIGHT_MM, NULL, &exr, NULL), SK_OK);
    assert_int_equal(exr.count, 7);
    assert_string_equal(sk_image_metadata_get(&exr, "shitsukan:units"), "mm");
    assert_null(sk_image_metadata_get(&exr, "shitsukan:decode"));
    sk_image_metadata normal = {0};
    assert_int_equal(sk_skin_maps_metadata(maps, SK_SKIN_MAP_NORMAL, NULL, &normal, NULL), SK_OK);
    assert_string_equal(sk_image_metadata_get(&normal, "shitsukan:normal_convention"), "opengl");
    /* the wood maps' encodings */
    sk_image_metadata wood = {0};
    assert_int_equal(sk_wood_maps_metadata(SK_WOOD_MAP_ALBEDO, &wood, NULL), SK_OK);
    assert_int_equal(wood.count, 0);
    assert_int_equal(sk_wood_maps_metadata(SK_WOOD_MAP_FIBRE, &wood, NULL), SK_OK);
    assert_string_equal(sk_image_metadata_get(&wood, "shitsukan:encoding"),
                        sk_wood_map_info(SK_WOOD_MAP_FIBRE)->encoding);
    assert_int_equal(sk_wood_maps_metadata(SK_WOOD_MAP_COUNT, &wood, NULL),
                     SK_ERROR_INVALID_ARGUMENT);
    sk_skin_maps_destroy(maps);
    sk_skin_destroy(skin);
}

/* fibre.png's samples are 0.5 + 0.5 f of a unit f: decoded, unit vectors. */
static void test_wood_fibre_encoding(void **state)
{
    (void)state;
    sk_wood_desc desc = {0};
    desc.grain.spiral_slope = 0.1f;
    sk_wood *wood = NULL;
    sk_error err = {0};
    assert_int_equal(sk_wood_create(&desc, &wood, &err), SK_OK);
    sk_wood_cut_desc cut = {0};
    sk_wood_view_cut(wood, &sk_wood_get_desc(wood)->view, &cut);
    cut.width = 24, cut.height = 16;
    float *maps[SK_WOOD_MAP_COUNT];
    for (int k = 0; k < SK_WOOD_MAP_COUNT; k++) {
        maps[k] = malloc(sizeof(float) * 24 * 16 * sk_wood_map_info((sk_wood_map)k)->channels);
        *sk_wood_maps_cut_output(&cut, (sk_wood_map)k) = maps[k];
    }
    assert_int_equal(sk_wood_cut(wood, &cut, &err), SK_OK);
    for (int i = 0; i < 24 * 16; i++) {
        const float *c = maps[SK_WOOD_MAP_FIBRE] + 3 * i;
        double f[3] = {2.0 * c[0] - 1, 2.0 * c[1] - 1, 2.0 * c[2] - 1};
        assert_true(fabs(sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]) - 1.0) < 1e-5);
        float pores = maps[SK_WOOD_MAP_PORES][i];
        assert_true(pores >= 0.0f && pores <= 1.0f);
    }
    for (int k = 0; k < SK_WOOD_MAP_COUNT; k++) free(maps[k]);
    sk_wood_destroy(wood);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_layout),
        cmocka_unit_test(test_store_encodings),
        cmocka_unit_test(test_furrow_span),
        cmocka_unit_test(test_codes_match_render),
        cmocka_unit_test(test_bands_cover_every_row_once),
        cmocka_unit_test(test_partial_render_and_release),
        cmocka_unit_test(test_errors),
        cmocka_unit_test(test_metadata),
        cmocka_unit_test(test_wood_fibre_encoding),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
