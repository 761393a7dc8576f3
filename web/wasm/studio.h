/* The studio's bridge from JavaScript to the library (WebAssembly build only): plain C
 * calls over numbers, strings and buffers in the module's memory, each a thin wrapper
 * of a library call. Objects made here are freed by their own studio_*_destroy. */
#ifndef SK_STUDIO_H
#define SK_STUDIO_H

#include <stdint.h>

#include <emscripten/emscripten.h>

#include "shitsukan/core.h"

#define STUDIO_API EMSCRIPTEN_KEEPALIVE

/* The hand panel's hand (studio_hand.c): its skeleton and the frames of its last pose. */
struct sk_hand_skeleton;
struct sk_hand_frames;
typedef struct studio_hand studio_hand;
const struct sk_hand_skeleton *studio_hand_skeleton(const studio_hand *h);
const struct sk_hand_frames *studio_hand_frames(const studio_hand *h);

/* A text from JSON (NUL-terminated) bound through `schema` into `desc`. */
struct sk_schema;
sk_result studio_bind_json(const char *json, const struct sk_schema *schema, void *desc,
                           sk_error *err);

/* A tissue character file's text resolved (every default filled in), as JSON
 * (studio_tissue.c); NULL with the error on a bad file. */
char *studio_tissue_resolved(const char *json, sk_error *err);

/* An image's metadata as a JSON object of its keys in order (studio_maps.c). */
struct sk_image_metadata;
char *studio_metadata_json(const struct sk_image_metadata *meta);

/* RGBA 8-bit for a canvas from 1- or 3-channel floats with the PNG writer's codes
 * (studio_common.c). */
void studio_rgba8(const float *samples, int pixels, int channels, int srgb, uint8_t *scratch,
                  uint8_t *rgba);

#endif
