/* Private: the parsed preset tree shared by the preset parser/editor and the schema
 * binder. */
#ifndef SK_IO_PRESET_TREE_H
#define SK_IO_PRESET_TREE_H

#include <cjson/cJSON.h>

#include "shitsukan/preset.h"

struct sk_preset {
    cJSON *root; /* always an object */
};

#endif
