/* The maps of a wood cut (`shitsukan wood cut --maps`, Kawai 2000's solid texture seen on
 * a plane): their files, the cut output each is, and how their samples are encoded. */
#include <stddef.h>

#include "products/maps/maps_internal.h"

static const sk_map_info k_wood_maps[SK_WOOD_MAP_COUNT] = {
    [SK_WOOD_MAP_ALBEDO] = {"albedo.png", "albedo", 3, 8, true, NULL},
    [SK_WOOD_MAP_FIBRE] = {"fibre.png", "fibre", 3, 16, false,
                           "rgb = 0.5 + 0.5 f, f = unit fibre direction up the tree in the image "
                           "frame (x right, y up, z towards the viewer); linear"},
    [SK_WOOD_MAP_PORES] = {"pores.png", "pores", 1, 8, false, "vessel (pore) coverage 0-1; linear"},
};

const sk_map_info *sk_wood_map_info(sk_wood_map map)
{
    return (unsigned)map < SK_WOOD_MAP_COUNT ? &k_wood_maps[map] : NULL;
}

float **sk_wood_maps_cut_output(sk_wood_cut_desc *cut, sk_wood_map map)
{
    if (!cut) return NULL;
    switch (map) {
    case SK_WOOD_MAP_ALBEDO:
        return &cut->albedo;
    case SK_WOOD_MAP_FIBRE:
        return &cut->fibre;
    case SK_WOOD_MAP_PORES:
        return &cut->vessel;
    default:
        return NULL;
    }
}

sk_result sk_wood_maps_metadata(sk_wood_map map, sk_image_metadata *meta, sk_error *err)
{
    const sk_map_info *info = sk_wood_map_info(map);
    if (!info || !meta)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "map = %d is out of range [0, %d] or meta is NULL", (int)map,
                       SK_WOOD_MAP_COUNT - 1);
    return info->encoding ? sk_image_metadata_set(meta, "shitsukan:encoding", info->encoding, err)
                          : SK_OK;
}
