/* The skin panel's calls: a skin from preset JSON (built, or re-profiled when an edit
 * leaves its cells), its maps rendered into buffers, and the live maps as canvas pixels.
 * The map set is the one `shitsukan skin maps` writes, computed by the same library
 * calls. */
#include <stdlib.h>
#include <string.h>

#include "shitsukan/skin.h"
#include "studio.h"

STUDIO_API sk_skin *studio_skin_create(const char *json, sk_error *err)
{
    sk_skin_desc d;
    memset(&d, 0, sizeof d);
    if (studio_bind_json(json, &sk_skin_schema, &d, err) != SK_OK) return NULL;
    sk_skin *skin = NULL;
    if (sk_skin_create(&skin, &d, err) != SK_OK) return NULL;
    return skin;
}

/* The skin of a new preset text and what the edit changed (*changes, the
 * sk_skin_change flags): `skin` itself re-profiled when the text changes only keys that
 * leave the cells, else a new skin with `skin` destroyed (SK_SKIN_CHANGE_CELLS; also
 * when `skin` is NULL). NULL with the error on a bad text, `skin` then left as it was. */
STUDIO_API sk_skin *studio_skin_update(sk_skin *skin, const char *json, unsigned *changes,
                                       sk_error *err)
{
    sk_skin_desc d;
    memset(&d, 0, sizeof d);
    *changes = 0;
    if (studio_bind_json(json, &sk_skin_schema, &d, err) != SK_OK) return NULL;
    if (sk_skin_desc_validate(&d, err) != SK_OK) return NULL;
    unsigned c = skin ? sk_skin_desc_changes(sk_skin_get_desc(skin), &d) : SK_SKIN_CHANGE_CELLS;
    if (!(c & SK_SKIN_CHANGE_CELLS)) {
        if (sk_skin_reprofile(skin, &d, err) != SK_OK) return NULL;
        *changes = c;
        return skin;
    }
    sk_skin *fresh = NULL;
    if (sk_skin_create(&fresh, &d, err) != SK_OK) return NULL;
    sk_skin_destroy(skin);
    *changes = c;
    return fresh;
}

STUDIO_API void studio_skin_destroy(sk_skin *skin) { sk_skin_destroy(skin); }

/* Renders rows [y0, y0 + rows) of a width x height map; each output NULL or
 * width x rows (x3 for normal and preview) floats, cells 32-bit ids. */
STUDIO_API int studio_skin_render(const sk_skin *skin, int width, int height, int y0, int rows,
                                  float *height_mm, float *normal, float *furrow, uint32_t *cells,
                                  float *preview, int furrow_level, int id_level, sk_error *err)
{
    sk_skin_render_desc rd = {
        .width = width,
        .height = height,
        .region = {0, y0, width, rows},
        .height_mm = height_mm,
        .normal = normal,
        .furrow = furrow,
        .cell_id = cells,
        .preview = preview,
        .furrow_level = furrow_level,
        .id_level = id_level,
    };
    return (int)sk_skin_render(skin, &rd, err);
}

/* [height min, height max, tile width, tile height, furrow map span of `level`] in mm. */
STUDIO_API void studio_skin_info(const sk_skin *skin, int level, double *out)
{
    float lo, hi;
    sk_skin_height_range(skin, &lo, &hi);
    double tw, th;
    sk_skin_tile_size(skin, &tw, &th);
    const sk_skin_desc *d = sk_skin_get_desc(skin);
    if (level < 1 || level > d->level_count) level = 1;
    out[0] = lo;
    out[1] = hi;
    out[2] = tw;
    out[3] = th;
    out[4] = 0.5 * d->levels[level - 1].spacing_mm;
    out[5] = d->level_count;
}

/* The cells map's colours (linear RGB) of `count` cell ids. */
STUDIO_API void studio_skin_cell_colors(const uint32_t *ids, int count, float *rgb)
{
    for (int i = 0; i < count; i++) sk_skin_cell_color(ids[i], rgb + 3 * i);
}

/* The maps of `count` pixels scaled in place to [0, 1] as the map files encode them:
 * the height over the height range [lo, hi] mm, the normal as 0.5 n + 0.5, the furrow
 * distance over `furrow_span` mm (clamped at 1); each NULL or skipped. */
STUDIO_API void studio_skin_scale_maps(int count, float *height_mm, float *normal, float *furrow,
                                       double lo, double hi, double furrow_span)
{
    size_t n = count > 0 ? (size_t)count : 0;
    for (size_t i = 0; height_mm && i < n; i++)
        height_mm[i] = (float)((height_mm[i] - lo) / (hi - lo));
    for (size_t i = 0; normal && i < 3 * n; i++) normal[i] = (float)(0.5 * normal[i] + 0.5);
    for (size_t i = 0; furrow && i < n; i++) {
        double v = furrow[i] / furrow_span;
        furrow[i] = (float)(v < 1.0 ? v : 1.0);
    }
}

/* The live maps of the skin panel, in the order of the bits of `maps`; LIVE_RESHADE asks
 * for the preview shaded from the normals held (after a shading edit). */
enum {
    LIVE_PREVIEW,
    LIVE_HEIGHT,
    LIVE_NORMAL,
    LIVE_FURROW,
    LIVE_CELLS,
    LIVE_COUNT,
    LIVE_RESHADE = LIVE_COUNT
};

/* Rows [y0, y0 + rows) of the live maps of a width x height render as canvas pixels,
 * each map that bit (1 << k) of `maps` asks for into rgba[k] (width x rows x 4 bytes):
 * 0 the shaded preview (sRGB codes), 1 the height, 2 the normal, 3 the furrow distance
 * (each scaled by studio_skin_scale_maps), 4 the cells' colours; the others in linear
 * codes, as the map files encode them. `normals` (NULL or width x rows x 3 floats)
 * receives the float normals the render finds when it makes the preview, height or normal
 * map (asked for only the furrow and cells maps, the render evaluates no relief and leaves
 * them as they were); with bit LIVE_RESHADE the preview alone is
 * shaded from the normals it holds, with no render (sk_skin_shade: the bytes the render's
 * preview has, as the shading is all a shading edit changes). Returns 0, or an sk_result
 * with the error. */
STUDIO_API int studio_skin_live_rgba(const sk_skin *skin, int width, int height, int y0, int rows,
                                     unsigned maps, uint8_t **rgba, float *normals, sk_error *err)
{
    size_t n = (size_t)width * (size_t)rows;
    bool reshade = maps >> LIVE_RESHADE & 1u;
    if (reshade && !normals)
        return (int)sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "no normals to shade the preview from");
    bool want[LIVE_COUNT];
    for (int k = 0; k < LIVE_COUNT; k++) want[k] = (maps >> k & 1u) && rgba[k] && !reshade;
    want[LIVE_PREVIEW] = (maps & 1u) && rgba[LIVE_PREVIEW];
    float *height_mm = want[LIVE_HEIGHT] ? malloc(n * sizeof(float)) : NULL;
    float *furrow = want[LIVE_FURROW] ? malloc(n * sizeof(float)) : NULL;
    /* the normals: kept for the caller, or for the normal map; a render of only the
       furrow and cells maps evaluates no relief (sk_skin_render) */
    bool relief = want[LIVE_PREVIEW] || want[LIVE_HEIGHT] || want[LIVE_NORMAL];
    float *normal = normals && relief   ? normals
                    : want[LIVE_NORMAL] ? malloc(3 * n * sizeof(float))
                                        : NULL;
    float *colour = malloc(3 * n * sizeof(float)); /* preview, then the normal scaled, the cells */
    uint32_t *cells = want[LIVE_CELLS] ? malloc(n * sizeof(uint32_t)) : NULL;
    uint8_t *scratch = malloc(3 * n);
    int r = 0;
    if ((want[LIVE_HEIGHT] && !height_mm) || (want[LIVE_FURROW] && !furrow) ||
        (want[LIVE_NORMAL] && !normal) || !colour || (want[LIVE_CELLS] && !cells) || !scratch)
        r = (int)sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for the live maps");
    else if (reshade)
        for (size_t i = 0; i < n; i++) {
            sk_vec3f c = sk_skin_shade(
                skin, (sk_vec3f){normal[3 * i], normal[3 * i + 1], normal[3 * i + 2]});
            colour[3 * i] = c.x, colour[3 * i + 1] = c.y, colour[3 * i + 2] = c.z;
        }
    else
        r = studio_skin_render(skin, width, height, y0, rows, height_mm, normal, furrow, cells,
                               want[LIVE_PREVIEW] ? colour : NULL, 1, 1, err);
    if (r == 0 && want[LIVE_PREVIEW])
        studio_rgba8(colour, (int)n, 3, 1, scratch, rgba[LIVE_PREVIEW]);
    if (r == 0 && (want[LIVE_HEIGHT] || want[LIVE_NORMAL] || want[LIVE_FURROW])) {
        float lo, hi;
        sk_skin_height_range(skin, &lo, &hi);
        if (want[LIVE_NORMAL]) memcpy(colour, normal, 3 * n * sizeof(float));
        studio_skin_scale_maps((int)n, height_mm, want[LIVE_NORMAL] ? colour : NULL, furrow, lo, hi,
                               0.5 * sk_skin_get_desc(skin)->levels[0].spacing_mm);
        if (want[LIVE_HEIGHT]) studio_rgba8(height_mm, (int)n, 1, 0, scratch, rgba[LIVE_HEIGHT]);
        if (want[LIVE_NORMAL]) studio_rgba8(colour, (int)n, 3, 0, scratch, rgba[LIVE_NORMAL]);
        if (want[LIVE_FURROW]) studio_rgba8(furrow, (int)n, 1, 0, scratch, rgba[LIVE_FURROW]);
    }
    if (r == 0 && want[LIVE_CELLS]) {
        for (size_t i = 0; i < n; i++) sk_skin_cell_color(cells[i], colour + 3 * i);
        studio_rgba8(colour, (int)n, 3, 0, scratch, rgba[LIVE_CELLS]);
    }
    free(height_mm), free(furrow), free(colour), free(cells), free(scratch);
    if (normal != normals) free(normal);
    return r;
}
