/* Reading a written glTF back in the tests: the document through the writer and the
 * strict reader in memory, and an accessor's floats with their count checked. */
#ifndef SK_TEST_GLTF_READ_BACK_H
#define SK_TEST_GLTF_READ_BACK_H

#include <stddef.h>
#include <stdint.h>

#include "shitsukan/gltf.h"

/* `g` written as GLB into memory and read back (the test fails on an error); the bytes
 * are handed out in *bytes / *size when bytes is not NULL (free them), else freed. */
sk_gltf_doc *sk_test_gltf_read_back(const sk_gltf *g, uint8_t **bytes, size_t *size);
/* Accessor `index` of `doc` as floats (free them); the test fails unless it has
 * want_count elements of want_components. */
float *sk_test_gltf_accessor(const sk_gltf_doc *doc, int index, size_t want_count,
                             int want_components);

#endif
