/* A character description from a preset file or tree: the keys of the character schema bound into
 * sk_tissue_character_desc, then validated. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "shitsukan/io.h"
#include "models/tissue/tissue_internal.h"

sk_result sk_tissue_character_bind(const sk_preset *preset, sk_tissue_character_desc *d,
                                   sk_error *err)
{
    memset(d, 0, sizeof *d);
    sk_result r = sk_preset_bind(preset, &sk_tissue_character_schema, d, err);
    if (r != SK_OK) return r;
    sk_tissue_character_desc_resolve(d);
    return sk_tissue_character_desc_validate(d, err);
}

sk_result sk_tissue_character_load(const char *path, sk_tissue_character_desc *d, sk_error *err)
{
    sk_preset *preset = NULL;
    sk_result r = sk_preset_load_file(&preset, path, err);
    if (r == SK_OK) r = sk_tissue_character_bind(preset, d, err);
    sk_preset_free(preset);
    if (r != SK_OK && err && !strstr(err->message, path)) sk_error_prefix(err, r, "%s", path);
    return r;
}
