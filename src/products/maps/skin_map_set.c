/* A skin map set: its desc checked and resolved, its store allocated for the maps it
 * holds, and freed part by part as the files are written. */
#include <stdlib.h>
#include <string.h>

#include "products/maps/maps_internal.h"

/* The desc with its defaults filled in, or an error naming the field. */
static sk_result resolve(const sk_skin *skin, const sk_skin_maps_desc *in, sk_skin_maps_desc *d,
                         sk_error *err)
{
    *d = *in;
    sk_result r;
    if ((r = sk_check_range_i(err, "width", d->width, 1, SK_IMAGE_MAX_DIMENSION)) != SK_OK ||
        (r = sk_check_range_i(err, "height", d->height, 1, SK_IMAGE_MAX_DIMENSION)) != SK_OK)
        return r;
    int *g = d->region;
    if (g[0] == 0 && g[1] == 0 && g[2] == 0 && g[3] == 0) g[2] = d->width, g[3] = d->height;
    if (g[0] < 0 || g[1] < 0 || g[2] < 1 || g[3] < 1 || g[0] > d->width - g[2] ||
        g[1] > d->height - g[3])
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "region %d,%d,%d,%d is not inside the %d x %d map", g[0], g[1], g[2], g[3],
                       d->width, d->height);
    if (d->maps == 0) d->maps = SK_SKIN_MAPS_DEFAULT;
    if (d->maps >> SK_SKIN_MAP_COUNT)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "maps = 0x%x names maps beyond the %d of a skin map set", d->maps,
                       SK_SKIN_MAP_COUNT);
    int levels = sk_skin_get_desc(skin)->level_count;
    if (d->furrow_level == 0) d->furrow_level = 1;
    if (d->id_level == 0) d->id_level = 1;
    if (d->samples == 0) d->samples = 1;
    if ((r = sk_check_range_i(err, "furrow_level", d->furrow_level, 1, levels)) != SK_OK ||
        (r = sk_check_range_i(err, "id_level", d->id_level, 1, levels)) != SK_OK ||
        (r = sk_check_range_i(err, "samples", d->samples, 1, 8)) != SK_OK)
        return r;
    return SK_OK;
}

/* Frees the parts `parts` of the store. */
static void free_parts(sk_skin_maps *m, unsigned parts)
{
    if (parts & SK__STORE_HEIGHT) sk_image_free(&m->height);
    if (parts & SK__STORE_NORMAL) free(m->normal), m->normal = NULL;
    if (parts & SK__STORE_FURROW) free(m->furrow), m->furrow = NULL;
    if (parts & SK__STORE_IDS) free(m->ids), m->ids = NULL;
    if (parts & SK__STORE_PREVIEW) sk_image_free(&m->preview);
    if (parts & SK__STORE_EDGES) sk_image_free(&m->edges);
    m->parts &= ~parts;
    m->rendered &= ~parts;
}

static sk_result allocate(sk_skin_maps *m, sk_error *err)
{
    const sk_skin_maps_desc *d = &m->desc;
    int rw = d->region[2], rh = d->region[3];
    for (int k = 0; k < SK_SKIN_MAP_COUNT; k++)
        if (d->maps & SK_SKIN_MAP_BIT(k))
            m->parts |= sk__skin_map_parts((sk_skin_map)k, d->samples);
    /* a 32-bit size_t (the studio's WebAssembly) must hold every part's bytes */
    double bytes = (double)m->n * sk_skin_maps_bytes_per_pixel(d);
    if (bytes > (double)SK_IMAGE_MAX_BYTES || bytes > (double)SIZE_MAX / 2)
        return sk_fail(err, SK_ERROR_LIMIT, "a %d x %d skin map set needs %.0f bytes, over the cap",
                       rw, rh, bytes);
    sk_result r = SK_OK;
    if (m->parts & SK__STORE_HEIGHT) r = sk_image_create(&m->height, rw, rh, 1, err);
    if (r == SK_OK && (m->parts & SK__STORE_PREVIEW))
        r = sk_image_create(&m->preview, rw, rh, 3, err);
    if (r == SK_OK && (m->parts & SK__STORE_EDGES)) r = sk_image_create(&m->edges, rw, rh, 3, err);
    if (r != SK_OK) return r;
    if (m->parts & SK__STORE_NORMAL) m->normal = malloc(sizeof(int16_t) * 2 * m->n);
    if (m->parts & SK__STORE_FURROW) m->furrow = malloc(sizeof(uint16_t) * m->n);
    if (m->parts & SK__STORE_IDS) m->ids = malloc(sizeof(uint32_t) * m->n);
    if (((m->parts & SK__STORE_NORMAL) && !m->normal) ||
        ((m->parts & SK__STORE_FURROW) && !m->furrow) || ((m->parts & SK__STORE_IDS) && !m->ids))
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for the maps");
    return SK_OK;
}

sk_result sk_skin_maps_create(sk_skin_maps **out, const sk_skin *skin,
                              const sk_skin_maps_desc *desc, sk_error *err)
{
    if (!out || !skin || !desc)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "out, skin and desc must not be NULL");
    *out = NULL;
    sk_skin_maps_desc d;
    sk_result r = resolve(skin, desc, &d, err);
    if (r != SK_OK) return r;
    sk_skin_maps *m = calloc(1, sizeof *m);
    if (!m) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for the maps");
    m->skin = skin;
    m->desc = d;
    m->n = (size_t)d.region[2] * (size_t)d.region[3];
    m->furrow_span = sk_skin_maps_furrow_span(skin, d.furrow_level);
    if ((r = allocate(m, err)) != SK_OK) {
        sk_skin_maps_destroy(m);
        return r;
    }
    *out = m;
    return SK_OK;
}

void sk_skin_maps_destroy(sk_skin_maps *maps)
{
    if (!maps) return;
    free_parts(maps, ~0u);
    free(maps);
}

const sk_skin_maps_desc *sk_skin_maps_get_desc(const sk_skin_maps *maps)
{
    return maps ? &maps->desc : NULL;
}

const sk_image *sk_skin_maps_image(const sk_skin_maps *maps, sk_skin_map map)
{
    if (!sk_skin_maps_holds(maps, map)) return NULL;
    const sk_image *image = map == SK_SKIN_MAP_HEIGHT_MM                           ? &maps->height
                            : map == SK_SKIN_MAP_PREVIEW && maps->desc.samples > 1 ? &maps->preview
                            : map == SK_SKIN_MAP_EDGES                             ? &maps->edges
                                                                                   : NULL;
    return image && image->data ? image : NULL;
}

void sk_skin_maps_release(sk_skin_maps *maps, sk_skin_map map)
{
    if (!maps) return;
    unsigned later = 0;
    for (int k = (int)map + 1; k < SK_SKIN_MAP_COUNT; k++)
        if (maps->desc.maps & SK_SKIN_MAP_BIT(k))
            later |= sk__skin_map_parts((sk_skin_map)k, maps->desc.samples);
    free_parts(maps, maps->parts & ~later);
}
