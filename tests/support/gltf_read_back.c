/* Reading a written glTF back in the tests (see gltf_read_back.h). */
#include "gltf_read_back.h"

#include <stdlib.h>

#include "test_result.h"

sk_gltf_doc *sk_test_gltf_read_back(const sk_gltf *g, uint8_t **bytes, size_t *size)
{
    uint8_t *data;
    size_t n;
    SK_ASSERT_OK(sk_gltf_write_glb_memory(g, NULL, &data, &n, &e_));
    sk_gltf_doc *doc = NULL;
    SK_ASSERT_OK(sk_gltf_read_glb_memory(&doc, data, n, NULL, &e_));
    if (bytes) {
        *bytes = data;
        *size = n;
    } else {
        free(data);
    }
    return doc;
}

float *sk_test_gltf_accessor(const sk_gltf_doc *doc, int index, size_t want_count,
                             int want_components)
{
    float *v = NULL;
    size_t count = 0;
    int components = 0;
    assert_true(index >= 0);
    SK_ASSERT_OK(sk_gltf_doc_read_accessor(doc, index, &v, &count, &components, &e_));
    assert_int_equal(count, want_count);
    assert_int_equal(components, want_components);
    return v;
}
