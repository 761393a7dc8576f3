/* The skin panel's calls: a skin from preset JSON (built, or re-profiled when an edit
 * leaves its cells) and its map sets (sk_skin_maps: the maps `shitsukan skin maps`
 * writes, by the same library calls): rendered by parts, read as canvas pixels, 16-bit
 * codes, samples and the files' metadata. */
#include <stdlib.h>
#include <string.h>

#include "shitsukan/maps.h"
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

/* [height min, height max, tile width, tile height, furrow span of `level` (furrow.png's
 * codes, sk_skin_maps_furrow_span), level count] in mm. */
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
    out[4] = sk_skin_maps_furrow_span(skin, level);
    out[5] = d->level_count;
}

/* A map set (sk_skin_maps) of rows [y0, y0 + rows) of a width x height map: the default
 * maps (every file of `shitsukan skin maps` but edges.png), furrow and cell level 1, one
 * sample, OpenGL normals, as the command makes them by default. It reads `skin` as it is
 * when rendered and read (a re-profiled skin too); NULL with the error. */
STUDIO_API sk_skin_maps *studio_skin_maps_create(const sk_skin *skin, int width, int height, int y0,
                                                 int rows, sk_error *err)
{
    sk_skin_maps_desc d = {.width = width, .height = height, .region = {0, y0, width, rows}};
    sk_skin_maps *maps = NULL;
    if (sk_skin_maps_create(&maps, skin, &d, err) != SK_OK) return NULL;
    return maps;
}

STUDIO_API void studio_skin_maps_destroy(sk_skin_maps *maps) { sk_skin_maps_destroy(maps); }

/* Renders what the maps `which` are made from (bit k: sk_skin_map k; 0 = every map). */
STUDIO_API int studio_skin_maps_render(sk_skin_maps *maps, unsigned which, sk_error *err)
{
    return (int)sk_skin_maps_render(maps, which, err);
}

/* Whether the set holds map `map` (its file is part of an export). */
STUDIO_API int studio_skin_maps_holds(const sk_skin_maps *maps, int map)
{
    return sk_skin_maps_holds(maps, (sk_skin_map)map);
}

/* Every row of a map as canvas pixels (rows x width x 4 bytes, alpha 255): its 8-bit
 * codes (sk_skin_maps_codes8: the file's own for the 8-bit maps). Returns 0 or an
 * sk_result with the error. */
STUDIO_API int studio_skin_maps_rgba(const sk_skin_maps *maps, int map, uint8_t *rgba,
                                     sk_error *err)
{
    const sk_skin_maps_desc *d = sk_skin_maps_get_desc(maps);
    const sk_map_info *info = sk_skin_map_info((sk_skin_map)map);
    if (!d || !info) return (int)sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "no such map set or map");
    size_t n = (size_t)d->region[2] * (size_t)d->region[3];
    uint8_t *codes = malloc(n * (size_t)info->channels);
    if (!codes) return (int)sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for the codes");
    sk_result r = sk_skin_maps_codes8(maps, (sk_skin_map)map, 0, d->region[3], codes, err);
    for (size_t i = 0; r == SK_OK && i < n; i++) {
        for (int c = 0; c < 3; c++)
            rgba[4 * i + c] = codes[i * info->channels + (info->channels == 3 ? c : 0)];
        rgba[4 * i + 3] = 255;
    }
    free(codes);
    return (int)r;
}

/* Every row of a 16-bit map as its file's codes (rows x width x channels). */
STUDIO_API int studio_skin_maps_codes16(const sk_skin_maps *maps, int map, uint16_t *codes,
                                        sk_error *err)
{
    const sk_skin_maps_desc *d = sk_skin_maps_get_desc(maps);
    if (!d) return (int)sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "no map set");
    return (int)sk_skin_maps_codes16(maps, (sk_skin_map)map, 0, d->region[3], codes, err);
}

/* Every row of a map as the samples its file codes (height.exr: mm). */
STUDIO_API int studio_skin_maps_samples(const sk_skin_maps *maps, int map, float *samples,
                                        sk_error *err)
{
    const sk_skin_maps_desc *d = sk_skin_maps_get_desc(maps);
    if (!d) return (int)sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "no map set");
    return (int)sk_skin_maps_rows(maps, (sk_skin_map)map, 0, d->region[3], samples, err);
}

/* The metadata of a map's file (sk_skin_maps_metadata, Software = `software`) as a JSON
 * object of its keys in order; NULL with the error. */
STUDIO_API char *studio_skin_maps_metadata(const sk_skin_maps *maps, int map, const char *software,
                                           sk_error *err)
{
    sk_image_metadata meta = {0};
    if (sk_skin_maps_metadata(maps, (sk_skin_map)map, software, &meta, err) != SK_OK) return NULL;
    return studio_metadata_json(&meta);
}
