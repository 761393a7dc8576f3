/* The layout of the map sets for the page (include/shitsukan/maps.h): each file of the
 * skin and the wood map sets with its channels, bits and codes, as JSON, and a file's
 * metadata as a JSON object, so the page restates none of it. */
#include <stdlib.h>
#include <string.h>

#include <cjson/cJSON.h>

#include "shitsukan/maps.h"
#include "studio.h"

char *studio_metadata_json(const sk_image_metadata *meta)
{
    cJSON *root = cJSON_CreateObject();
    for (int i = 0; i < meta->count; i++)
        cJSON_AddStringToObject(root, meta->entries[i].key, meta->entries[i].value);
    char *text = cJSON_PrintUnformatted(root);
    cJSON_Delete(root);
    return text;
}

static cJSON *map_json(const sk_map_info *info, int index)
{
    cJSON *o = cJSON_CreateObject();
    cJSON_AddNumberToObject(o, "map", index);
    cJSON_AddStringToObject(o, "file", info->file);
    cJSON_AddStringToObject(o, "name", info->name);
    cJSON_AddNumberToObject(o, "channels", info->channels);
    cJSON_AddNumberToObject(o, "bit_depth", info->bit_depth);
    cJSON_AddBoolToObject(o, "srgb", info->srgb);
    return o;
}

/* The maps of "skin" (sk_skin_map order; `band_rows` the rows of a render's band) or
 * "wood" (sk_wood_map order, each with its files' own metadata) as JSON:
 * {"maps": [{"map", "file", "name", "channels", "bit_depth", "srgb"[, "metadata"]}...]};
 * NULL for another module. */
STUDIO_API char *studio_maps_layout(const char *module)
{
    bool skin = strcmp(module, "skin") == 0;
    if (!skin && strcmp(module, "wood") != 0) return NULL;
    cJSON *root = cJSON_CreateObject();
    cJSON *maps = cJSON_AddArrayToObject(root, "maps");
    int count = skin ? SK_SKIN_MAP_COUNT : SK_WOOD_MAP_COUNT;
    for (int k = 0; k < count; k++) {
        const sk_map_info *info =
            skin ? sk_skin_map_info((sk_skin_map)k) : sk_wood_map_info((sk_wood_map)k);
        cJSON *o = map_json(info, k);
        if (!skin) {
            sk_image_metadata meta = {0};
            sk_wood_maps_metadata((sk_wood_map)k, &meta, NULL);
            cJSON *m = cJSON_AddObjectToObject(o, "metadata");
            for (int i = 0; i < meta.count; i++)
                cJSON_AddStringToObject(m, meta.entries[i].key, meta.entries[i].value);
        }
        cJSON_AddItemToArray(maps, o);
    }
    if (skin) cJSON_AddNumberToObject(root, "band_rows", SK_SKIN_MAPS_BAND_ROWS);
    char *text = cJSON_PrintUnformatted(root);
    cJSON_Delete(root);
    return text;
}
