/* Shared calls of the studio bridge: errors, memory, schemas, resolved presets and the
 * integer codes of image files. */
#include <stdlib.h>
#include <string.h>

#include "shitsukan/image.h"
#include "shitsukan/preset.h"
#include "shitsukan/skin.h"
#include "shitsukan/tissue.h"
#include "shitsukan/wood.h"
#include "studio.h"

STUDIO_API sk_error *studio_error_new(void) { return calloc(1, sizeof(sk_error)); }
STUDIO_API const char *studio_error_message(const sk_error *err) { return err->message; }
STUDIO_API int studio_error_result(const sk_error *err) { return (int)err->result; }
STUDIO_API void studio_free(void *p) { free(p); }
STUDIO_API void *studio_alloc(size_t bytes) { return calloc(1, bytes ? bytes : 1); }

sk_result studio_bind_json(const char *json, const sk_schema *schema, void *desc, sk_error *err)
{
    sk_preset *preset;
    sk_result r = sk_preset_parse(&preset, json, strlen(json), "state", err);
    if (r != SK_OK) return r;
    r = sk_preset_bind(preset, schema, desc, err);
    sk_preset_free(preset);
    return r;
}

static const sk_schema *schema_of(const char *module)
{
    if (strcmp(module, "skin") == 0) return &sk_skin_schema;
    if (strcmp(module, "wood") == 0) return &sk_wood_schema;
    if (strcmp(module, "tissue") == 0) return &sk_tissue_character_schema;
    return NULL;
}

/* The schema of "skin", "wood" or "tissue" (a character file) as JSON (sk_schema_describe_json). */
STUDIO_API char *studio_schema(const char *module)
{
    const sk_schema *schema = schema_of(module);
    return schema ? sk_schema_describe_json(schema) : NULL;
}

/* The values the model uses for a preset text: bound, every default filled in, checked,
 * as JSON (NULL with the error on a bad preset). */
STUDIO_API char *studio_resolved(const char *module, const char *json, sk_error *err)
{
    if (strcmp(module, "skin") == 0) {
        sk_skin_desc d;
        memset(&d, 0, sizeof d);
        if (studio_bind_json(json, &sk_skin_schema, &d, err) != SK_OK) return NULL;
        sk_skin_desc r = sk_skin_desc_resolved(&d);
        if (sk_skin_desc_validate(&r, err) != SK_OK) return NULL;
        return sk_schema_to_json(&sk_skin_schema, &r);
    }
    if (strcmp(module, "wood") == 0) {
        sk_wood_desc d;
        memset(&d, 0, sizeof d);
        if (studio_bind_json(json, &sk_wood_schema, &d, err) != SK_OK) return NULL;
        sk_wood_desc r = sk_wood_desc_resolved(&d);
        if (sk_wood_desc_validate(&r, err) != SK_OK) return NULL;
        return sk_schema_to_json(&sk_wood_schema, &r);
    }
    if (strcmp(module, "tissue") == 0) return studio_tissue_resolved(json, err);
    sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "unknown module '%s' (skin, wood, tissue)", module);
    return NULL;
}

/* RGBA 8-bit for a canvas from 1- or 3-channel floats, with the PNG writer's codes
 * (srgb: sRGB curve, else linear); alpha 255. `scratch` holds pixels x channels bytes. */
STUDIO_API void studio_rgba8(const float *samples, int pixels, int channels, int srgb,
                             uint8_t *scratch, uint8_t *rgba)
{
    sk_image_codes8(samples, (size_t)pixels, channels,
                    srgb ? SK_PNG_ENCODING_SRGB : SK_PNG_ENCODING_LINEAR, scratch);
    for (int i = 0; i < pixels; i++) {
        for (int c = 0; c < 3; c++)
            rgba[4 * i + c] = scratch[i * channels + (channels == 3 ? c : 0)];
        rgba[4 * i + 3] = 255;
    }
}

/* 16-bit linear codes (the 16-bit PNG maps). */
STUDIO_API void studio_codes16(const float *samples, int count, uint16_t *codes)
{
    sk_image_codes16(samples, (size_t)count, 1, SK_PNG_ENCODING_LINEAR, codes);
}
