/* How a skin map set's samples are kept and coded: the store's encodings (the normal's x
 * and y in 1/32767, the furrow distance as furrow.png's code), the samples each file
 * codes, made row by row from the store, their integer codes, and the furrow span. */
#include <math.h>
#include <stdlib.h>

#include "products/maps/maps_internal.h"

void sk_skin_maps_store_normal(const float normal[3], int16_t xy[2])
{
    for (int c = 0; c < 2; c++) xy[c] = (int16_t)lrintf(normal[c] * 32767.0f);
}

void sk_skin_maps_load_normal(const int16_t xy[2], float normal[3])
{
    normal[0] = xy[0] / 32767.0f, normal[1] = xy[1] / 32767.0f;
    float zz = 1.0f - normal[0] * normal[0] - normal[1] * normal[1];
    normal[2] = zz > 0.0f ? sqrtf(zz) : 0.0f;
}

uint16_t sk_skin_maps_furrow_code(float distance_mm, float span_mm)
{
    float d = distance_mm / span_mm;
    return (uint16_t)lrint((d > 1.0f ? 1.0f : d) * 65535.0);
}

float sk_skin_maps_furrow_span(const sk_skin *skin, int furrow_level)
{
    const sk_skin_desc *d = skin ? sk_skin_get_desc(skin) : NULL;
    if (furrow_level == 0) furrow_level = 1;
    if (!d || furrow_level < 1 || furrow_level > d->level_count) return 0.0f;
    /* the whole ridge, centre to edge */
    return 0.5f * d->levels[furrow_level - 1].spacing_mm;
}

/* Whether rows [y0, y0 + rows) of `map` can be read. */
static sk_result check_readable(const sk_skin_maps *m, sk_skin_map map, int y0, int rows,
                                sk_error *err)
{
    if (!m) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "maps must not be NULL");
    if (!sk_skin_maps_holds(m, map))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "map %d is not one the set holds", (int)map);
    if (y0 < 0 || rows < 0 || y0 > m->desc.region[3] - rows)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "rows %d..%d are not inside the set's %d rows", y0, y0 + rows - 1,
                       m->desc.region[3]);
    unsigned need = sk__skin_map_parts(map, m->desc.samples);
    if ((m->parts & m->rendered & need) != need)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "%s is not rendered (or was released)",
                       sk_skin_map_info(map)->file);
    return SK_OK;
}

/* Row y of the region as the file codes it (the map's channels per pixel). */
static void map_row(const sk_skin_maps *m, sk_skin_map map, int y, float lo, float span, float *row)
{
    int w = m->desc.region[2];
    size_t i0 = (size_t)y * (size_t)w;
    for (int x = 0; x < w; x++) {
        size_t i = i0 + (size_t)x;
        float *p = row + 3 * x;
        float nv[3];
        switch (map) {
        case SK_SKIN_MAP_HEIGHT_MM:
            row[x] = m->height.data[i];
            break;
        case SK_SKIN_MAP_HEIGHT:
            row[x] = (m->height.data[i] - lo) / span;
            break;
        case SK_SKIN_MAP_FURROW:
            row[x] = m->furrow[i] / 65535.0f;
            break;
        case SK_SKIN_MAP_CELLS:
            sk_skin_cell_color(m->ids[i], p);
            break;
        case SK_SKIN_MAP_NORMAL:
            /* tangent-space normals: OpenGL (green up) or DirectX (green down) */
            sk_skin_maps_load_normal(m->normal + 2 * i, nv);
            if (m->desc.directx) nv[1] = -nv[1];
            for (int c = 0; c < 3; c++) p[c] = 0.5f * nv[c] + 0.5f;
            break;
        case SK_SKIN_MAP_PREVIEW:
            if (m->desc.samples > 1) {
                for (int c = 0; c < 3; c++) p[c] = m->preview.data[3 * i + c];
            } else {
                sk_skin_maps_load_normal(m->normal + 2 * i, nv);
                sk_vec3f c = sk_skin_shade(m->skin, sk_v3f(nv[0], nv[1], nv[2]));
                p[0] = c.x, p[1] = c.y, p[2] = c.z;
            }
            break;
        case SK_SKIN_MAP_EDGES:
            for (int c = 0; c < 3; c++) p[c] = m->edges.data[3 * i + c];
            break;
        default:
            break;
        }
    }
}

sk_result sk_skin_maps_rows(const sk_skin_maps *maps, sk_skin_map map, int y0, int rows,
                            float *samples, sk_error *err)
{
    sk_result r = check_readable(maps, map, y0, rows, err);
    if (r != SK_OK) return r;
    if (!samples) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "samples must not be NULL");
    float lo, hi;
    sk_skin_height_range(maps->skin, &lo, &hi);
    size_t stride = (size_t)maps->desc.region[2] * (size_t)sk_skin_map_info(map)->channels;
    for (int y = 0; y < rows; y++) map_row(maps, map, y0 + y, lo, hi - lo, samples + y * stride);
    return SK_OK;
}

/* Codes of rows [y0, y0 + rows) at 8 or 16 bits, a block of rows at a time. */
static sk_result map_codes(const sk_skin_maps *m, sk_skin_map map, int y0, int rows, int bits,
                           void *codes, sk_error *err)
{
    sk_result r = check_readable(m, map, y0, rows, err);
    if (r != SK_OK) return r;
    const sk_map_info *info = sk_skin_map_info(map);
    if (info->bit_depth > 16 || bits > info->bit_depth)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "%s has no %d-bit codes", info->file, bits);
    if (!codes) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "codes must not be NULL");
    int w = m->desc.region[2], ch = info->channels;
    int block = (1 << 18) / w > 0 ? (1 << 18) / w : 1;
    float *samples = malloc(sizeof(float) * (size_t)w * (size_t)ch * (size_t)block);
    if (!samples) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for the codes");
    sk_png_encoding enc = info->srgb ? SK_PNG_ENCODING_SRGB : SK_PNG_ENCODING_LINEAR;
    for (int y = 0; y < rows; y += block) {
        int n = rows - y < block ? rows - y : block;
        sk_skin_maps_rows(m, map, y0 + y, n, samples, NULL);
        size_t at = (size_t)y * (size_t)w * (size_t)ch, px = (size_t)n * (size_t)w;
        if (bits == 8)
            sk_image_codes8(samples, px, ch, enc, (uint8_t *)codes + at);
        else
            sk_image_codes16(samples, px, ch, enc, (uint16_t *)codes + at);
    }
    free(samples);
    return SK_OK;
}

sk_result sk_skin_maps_codes8(const sk_skin_maps *maps, sk_skin_map map, int y0, int rows,
                              uint8_t *codes, sk_error *err)
{
    return map_codes(maps, map, y0, rows, 8, codes, err);
}

sk_result sk_skin_maps_codes16(const sk_skin_maps *maps, sk_skin_map map, int y0, int rows,
                               uint16_t *codes, sk_error *err)
{
    return map_codes(maps, map, y0, rows, 16, codes, err);
}
