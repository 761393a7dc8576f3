/* Fuzz harness for the glTF reader: any input must give SK_OK or an error, never a crash;
 * a document that reads must keep every promise of the query functions (indices in range,
 * every accessor readable within the cap). */
#define _POSIX_C_SOURCE 200809L
#include <stdint.h>
#include <stdlib.h>

#include "shitsukan/gltf.h"

/* A small cap keeps the fuzzer's memory bounded; the cap logic is under test too. */
#define SK_FUZZ_GLTF_CAP ((size_t)64 << 20)

static void check(bool ok)
{
    if (!ok) abort();
}

static bool index_ok(int index, int count)
{
    return index == SK_GLTF_NONE || (index >= 0 && index < count);
}

static void check_accessor(const sk_gltf_doc *doc, int index, int accessors)
{
    if (index < 0) return;
    check(index < accessors);
    float *v = NULL;
    size_t count = 0;
    int components = 0;
    sk_result r = sk_gltf_doc_read_accessor(doc, index, &v, &count, &components, NULL);
    check(r == SK_OK || r == SK_ERROR_LIMIT || r == SK_ERROR_OUT_OF_MEMORY);
    if (r == SK_OK) check(v && count > 0 && components >= 1 && components <= 16);
    free(v);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const char *const attributes[] = {"POSITION", "NORMAL",   "TANGENT",   "TEXCOORD_0",
                                             "COLOR_0",  "JOINTS_0", "WEIGHTS_0", "indices"};
    sk_gltf_doc *doc = NULL;
    sk_gltf_read_desc desc = {SK_FUZZ_GLTF_CAP};
    if (sk_gltf_read_glb_memory(&doc, data, size, &desc, NULL) != SK_OK) {
        check(doc == NULL);
        return 0;
    }
    sk_gltf_doc_counts c = sk_gltf_doc_count(doc);
    for (int a = 0; a < c.accessors; a++) check_accessor(doc, a, c.accessors);
    for (int n = 0; n < c.nodes; n++) {
        sk_gltf_doc_node node;
        check(sk_gltf_doc_get_node(doc, n, &node, NULL) == SK_OK);
        check(node.name != NULL && index_ok(node.parent, c.nodes) && node.parent != n);
        check(index_ok(node.mesh, c.meshes) && index_ok(node.skin, c.skins));
    }
    for (int m = 0; m < c.meshes; m++) {
        for (size_t k = 0; k < sizeof attributes / sizeof attributes[0]; k++)
            check(index_ok(sk_gltf_doc_mesh_accessor(doc, m, attributes[k]), c.accessors));
        check(sk_gltf_doc_mesh_accessor(doc, m, "POSITION") >= 0);
        int targets = sk_gltf_doc_mesh_target_count(doc, m);
        for (int t = 0; t < targets; t++)
            check(index_ok(sk_gltf_doc_mesh_target_accessor(doc, m, t, "POSITION"), c.accessors));
    }
    for (int s = 0; s < c.skins; s++) {
        const int *joints;
        int count, ibm;
        check(sk_gltf_doc_get_skin(doc, s, &joints, &count, &ibm, NULL) == SK_OK);
        check(count >= 1 && index_ok(ibm, c.accessors));
        for (int j = 0; j < count; j++) check(joints[j] >= 0 && joints[j] < c.nodes);
    }
    for (int a = 0; a < c.animations; a++) {
        int channels = sk_gltf_doc_channel_count(doc, a);
        check(channels >= 1);
        for (int k = 0; k < channels; k++) {
            sk_gltf_doc_channel ch;
            check(sk_gltf_doc_get_channel(doc, a, k, &ch, NULL) == SK_OK);
            check(index_ok(ch.node, c.nodes) && (unsigned)ch.path <= SK_GLTF_PATH_WEIGHTS);
            check(ch.input_accessor >= 0 && ch.input_accessor < c.accessors);
            check(ch.output_accessor >= 0 && ch.output_accessor < c.accessors);
        }
    }
    sk_gltf_doc_free(doc);
    return 0;
}
