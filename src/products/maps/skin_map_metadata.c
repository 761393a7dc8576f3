/* The metadata of skin images and of each file of a skin map set: what the pixels cover
 * (seed, tile, pixel size, whether it tiles) and how each map's codes decode. */
#include <stdio.h>

#include "products/maps/maps_internal.h"

/* Sets each key/value pair in order; the first failure is returned. */
static sk_result set(sk_image_metadata *meta, const char *key, const char *value, sk_result r,
                     sk_error *err)
{
    return r != SK_OK ? r : sk_image_metadata_set(meta, key, value, err);
}

sk_result sk_skin_image_metadata(const sk_skin *skin, int width, const char *software,
                                 sk_image_metadata *meta, sk_error *err)
{
    if (!skin || !meta || width < 1)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "skin and meta must not be NULL and width (%d) at least 1", width);
    const sk_skin_desc *d = sk_skin_get_desc(skin);
    char v[128];
    double tw, th;
    sk_skin_tile_size(skin, &tw, &th);
    snprintf(v, sizeof v, "%llu", (unsigned long long)d->seed);
    sk_result r = set(meta, "shitsukan:seed", v, SK_OK, err);
    snprintf(v, sizeof v, "%.9g x %.9g", tw, th);
    r = set(meta, "shitsukan:tile_mm", v, r, err);
    snprintf(v, sizeof v, "%.9g", tw / width);
    r = set(meta, SK_IMAGE_KEY_MM_PER_PIXEL, v, r, err);
    r = set(meta, "shitsukan:seamless", d->aperiodic ? "false" : "true", r, err);
    if (software) r = set(meta, "Software", software, r, err);
    return r;
}

sk_result sk_skin_maps_metadata(const sk_skin_maps *maps, sk_skin_map map, const char *software,
                                sk_image_metadata *meta, sk_error *err)
{
    if (!sk_skin_maps_holds(maps, map))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "map %d is not one the set holds", (int)map);
    sk_result r = sk_skin_image_metadata(maps->skin, maps->desc.width, software, meta, err);
    char v[160];
    float lo, hi;
    sk_skin_height_range(maps->skin, &lo, &hi);
    if (map == SK_SKIN_MAP_HEIGHT_MM || map == SK_SKIN_MAP_HEIGHT) {
        r = set(meta, "shitsukan:units", "mm", r, err);
        snprintf(v, sizeof v, "%.9g", lo);
        r = set(meta, "shitsukan:height_min_mm", v, r, err);
        snprintf(v, sizeof v, "%.9g", hi);
        r = set(meta, "shitsukan:height_max_mm", v, r, err);
    }
    if (map == SK_SKIN_MAP_HEIGHT) {
        /* height.png: 16-bit over the skin's height range (height.exr keeps mm) */
        snprintf(v, sizeof v, "height_mm = %.9g + value * %.9g (value = code / 65535)", lo,
                 hi - lo);
        r = set(meta, "shitsukan:decode", v, r, err);
    }
    if (map == SK_SKIN_MAP_FURROW) {
        snprintf(v, sizeof v, "%d", maps->desc.furrow_level);
        r = set(meta, "shitsukan:furrow_level", v, r, err);
        snprintf(v, sizeof v, "distance_mm = value * %.9g (clamped there)", maps->furrow_span);
        r = set(meta, "shitsukan:decode", v, r, err);
    }
    if (map == SK_SKIN_MAP_NORMAL)
        r = set(meta, "shitsukan:normal_convention", maps->desc.directx ? "directx" : "opengl", r,
                err);
    return r;
}
