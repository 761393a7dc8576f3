/* The skin panel's calls: a skin from preset JSON, its maps rendered into buffers. The
 * map set is the one `shitsukan skin maps` writes, computed by the same library calls. */
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
