/* Fuzz harness: "--set key.path=value" assignments on the real schemas (skin, wood, noise,
 * render scene): the first byte picks the schema, the rest is a list of assignments, one
 * per line, applied to an empty preset that is then bound and validated. */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "shitsukan/noise_map.h"
#include "shitsukan/preset.h"
#include "shitsukan/render.h"
#include "shitsukan/skin.h"
#include "shitsukan/wood.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 1 || size > 4096) return 0;
    char *text = malloc(size);
    if (!text) abort();
    memcpy(text, data + 1, size - 1);
    text[size - 1] = '\0';
    sk_preset *p = NULL;
    if (sk_preset_create(&p, NULL) != SK_OK) abort();
    bool ok = true;
    for (char *line = text, *next; line && ok; line = next) {
        next = strchr(line, '\n');
        if (next) *next++ = '\0';
        if (line[0]) ok = sk_preset_set(p, line, NULL) == SK_OK;
    }
    if (ok) {
        switch (data[0] % 4) {
        case 0: {
            sk_skin_desc d;
            memset(&d, 0, sizeof d);
            if (sk_preset_bind(p, &sk_skin_schema, &d, NULL) == SK_OK)
                sk_skin_desc_validate(&d, NULL);
            break;
        }
        case 1: {
            sk_wood_desc d;
            memset(&d, 0, sizeof d);
            if (sk_preset_bind(p, &sk_wood_schema, &d, NULL) == SK_OK)
                sk_wood_desc_validate(&d, NULL);
            break;
        }
        case 2: {
            sk_noise_map_desc d;
            memset(&d, 0, sizeof d);
            if (sk_preset_bind(p, &sk_noise_map_schema, &d, NULL) == SK_OK) {
                sk_noise_map_desc r = sk_noise_map_desc_resolved(&d);
                sk_noise_map_desc_validate(&r, NULL);
            }
            break;
        }
        default: {
            sk_render_scene_desc *d = calloc(1, sizeof *d);
            if (!d) abort();
            if (sk_preset_bind(p, &sk_render_schema, d, NULL) == SK_OK)
                sk_render_scene_desc_validate(d, NULL);
            free(d);
            break;
        }
        }
    }
    sk_preset_free(p);
    free(text);
    return 0;
}
