/* The studio's bridge from JavaScript to the library (WebAssembly build only): plain C
 * calls over numbers, strings and buffers in the module's memory, each a thin wrapper
 * of a library call. Objects made here are freed by their own studio_*_destroy. */
#ifndef SK_STUDIO_H
#define SK_STUDIO_H

#include <emscripten/emscripten.h>

#include "shitsukan/core.h"

#define STUDIO_API EMSCRIPTEN_KEEPALIVE

/* A text from JSON (NUL-terminated) bound through `schema` into `desc`. */
struct sk_schema;
sk_result studio_bind_json(const char *json, const struct sk_schema *schema, void *desc,
                           sk_error *err);

#endif
