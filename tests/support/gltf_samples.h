/* Sample glTF documents that exercise every feature of the writer, for the round-trip tests
 * and for the real consumers (the Khronos validator, Blender's importer). */
#ifndef SK_TEST_GLTF_SAMPLES_H
#define SK_TEST_GLTF_SAMPLES_H

#include "shitsukan/gltf.h"

typedef enum sk_test_gltf_kind {
    SK_TEST_GLTF_STATIC = 0, /* two meshes: a sphere with base colour and normal textures, a
                                box with vertex colours and a plain material; node TRS */
    SK_TEST_GLTF_SKINNED,    /* a cylinder skinned to a chain of 3 joints, inverse bind
                                matrices from the hierarchy; rotations LINEAR, the root's
                                translation STEP */
    SK_TEST_GLTF_MORPH,      /* a grid with 2 named morph targets (positions and normals);
                                weights animated LINEAR in one animation, STEP in another */
    SK_TEST_GLTF_KIND_COUNT
} sk_test_gltf_kind;

typedef struct sk_test_gltf_sample {
    const char *name; /* "static", "skinned", "morph": the file's base name */
    sk_gltf *gltf;    /* destroy with sk_gltf_destroy */
    /* what an importer should find */
    int meshes, joints, animations, shape_keys;
} sk_test_gltf_sample;

sk_result sk_test_gltf_sample_make(sk_test_gltf_kind kind, sk_test_gltf_sample *out, sk_error *err);

#endif
