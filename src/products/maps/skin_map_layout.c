/* The layout of a skin map set (the maps of `shitsukan skin maps`, Ishii et al. 1991's
 * relief for a renderer): its files, how each is coded, which part of the store each is
 * made from and what the store costs per pixel. */
#include "products/maps/maps_internal.h"

static const sk_map_info k_skin_maps[SK_SKIN_MAP_COUNT] = {
    [SK_SKIN_MAP_HEIGHT_MM] = {"height.exr", "height_mm", 1, 32, false, NULL},
    [SK_SKIN_MAP_HEIGHT] = {"height.png", "height", 1, 16, false, NULL},
    [SK_SKIN_MAP_FURROW] = {"furrow.png", "furrow", 1, 16, false, NULL},
    [SK_SKIN_MAP_CELLS] = {"cells.png", "cells", 3, 8, false, NULL},
    [SK_SKIN_MAP_NORMAL] = {"normal.png", "normal", 3, 8, false, NULL},
    [SK_SKIN_MAP_PREVIEW] = {"preview.png", "preview", 3, 8, true, NULL},
    [SK_SKIN_MAP_EDGES] = {"edges.png", "edges", 3, 8, true, NULL},
};

const sk_map_info *sk_skin_map_info(sk_skin_map map)
{
    return (unsigned)map < SK_SKIN_MAP_COUNT ? &k_skin_maps[map] : NULL;
}

unsigned sk__skin_map_parts(sk_skin_map map, int samples)
{
    switch (map) {
    case SK_SKIN_MAP_HEIGHT_MM:
    case SK_SKIN_MAP_HEIGHT:
        return SK__STORE_HEIGHT;
    case SK_SKIN_MAP_FURROW:
        return SK__STORE_FURROW;
    case SK_SKIN_MAP_CELLS:
        return SK__STORE_IDS;
    case SK_SKIN_MAP_NORMAL:
        return SK__STORE_NORMAL;
    case SK_SKIN_MAP_PREVIEW:
        /* one sample: shaded from the kept normal as the file is made; more: rendered */
        return samples > 1 ? SK__STORE_PREVIEW : SK__STORE_NORMAL;
    case SK_SKIN_MAP_EDGES:
        return SK__STORE_EDGES;
    default:
        return 0;
    }
}

double sk_skin_maps_bytes_per_pixel(const sk_skin_maps_desc *desc)
{
    unsigned maps = desc && desc->maps ? desc->maps : SK_SKIN_MAPS_DEFAULT;
    int samples = desc && desc->samples > 0 ? desc->samples : 1;
    unsigned parts = 0;
    for (int k = 0; k < SK_SKIN_MAP_COUNT; k++)
        if (maps & SK_SKIN_MAP_BIT(k)) parts |= sk__skin_map_parts((sk_skin_map)k, samples);
    /* height float, normal 2 x int16, furrow uint16, id uint32, float RGB images */
    return 4.0 * !!(parts & SK__STORE_HEIGHT) + 4.0 * !!(parts & SK__STORE_NORMAL) +
           2.0 * !!(parts & SK__STORE_FURROW) + 4.0 * !!(parts & SK__STORE_IDS) +
           12.0 * !!(parts & SK__STORE_PREVIEW) + 12.0 * !!(parts & SK__STORE_EDGES);
}

bool sk_skin_maps_holds(const sk_skin_maps *maps, sk_skin_map map)
{
    return maps && (unsigned)map < SK_SKIN_MAP_COUNT && (maps->desc.maps & SK_SKIN_MAP_BIT(map));
}
