/* Fuzz harness: the tissue character reader (JSON bound through sk_tissue_character_schema,
 * then the checks between joints, bones, muscles and fat regions). A character that passes
 * must have a root, bones on existing joints, and muscles and fat on existing bones. */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#include "shitsukan/tissue.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    sk_preset *p = NULL;
    if (sk_preset_parse(&p, (const char *)data, size, "fuzz", NULL) != SK_OK) return 0;
    sk_tissue_character_desc *d = malloc(sizeof *d);
    if (!d) abort();
    if (sk_tissue_character_bind(p, d, NULL) == SK_OK) {
        if (d->joint_count < 1 || d->bone_count < 1 || d->skin.spacing_mm < 0.5f) abort();
        if (sk_tissue_character_desc_validate(d, NULL) != SK_OK) abort(); /* binding validated it */
    }
    free(d);
    sk_preset_free(p);
    return 0;
}
