/* Private: the parsed preset tree shared by the preset parser/editor and the schema
 * binder. */
#ifndef SK_IO_PRESET_TREE_H
#define SK_IO_PRESET_TREE_H

#include <cjson/cJSON.h>

#include "shitsukan/preset.h"

struct sk_preset {
    cJSON *root; /* always an object */
};

/* Documentation keys accepted in every object: "description", "source", "notes", "figure". */
bool sk__preset_is_doc_key(const char *key);

#endif
