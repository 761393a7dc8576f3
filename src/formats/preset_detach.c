/* A preset split in two: one top-level key moved into a preset of its own (a command whose
 * tree holds two descs, e.g. the showcase's own keys under "showcase" beside its stage
 * scene). */
#include <stdlib.h>

#include "formats/preset_tree.h"

sk_result sk_preset_detach(sk_preset *preset, const char *key, sk_preset **out, sk_error *err)
{
    *out = NULL;
    sk_result r = sk_preset_create(out, err);
    if (r != SK_OK) return r;
    cJSON *item = cJSON_DetachItemFromObjectCaseSensitive(preset->root, key);
    if (item) cJSON_AddItemToObject((*out)->root, key, item);
    return SK_OK;
}
