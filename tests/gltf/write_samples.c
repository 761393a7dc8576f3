/* Writes the sample glTF documents (tests/support/gltf_samples.h) as FOLDER/<name>.glb, for
 * the checks by the Khronos validator and Blender's importer.
 *
 *   gltf_write_samples FOLDER */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>

#include "gltf_samples.h"
#include "shitsukan/io.h"

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: %s FOLDER\n", argv[0]);
        return 2;
    }
    sk_error err = {0};
    if (sk_make_dirs(argv[1], &err) != SK_OK) {
        fprintf(stderr, "gltf_write_samples: %s\n", err.message);
        return 1;
    }
    for (int k = 0; k < SK_TEST_GLTF_KIND_COUNT; k++) {
        sk_test_gltf_sample s;
        char path[4096];
        if (sk_test_gltf_sample_make((sk_test_gltf_kind)k, &s, &err) != SK_OK) {
            fprintf(stderr, "gltf_write_samples: %s\n", err.message);
            return 1;
        }
        snprintf(path, sizeof path, "%s/%s.glb", argv[1], s.name);
        sk_result r = sk_gltf_write_glb(s.gltf, path, NULL, &err);
        sk_gltf_destroy(s.gltf);
        if (r != SK_OK) {
            fprintf(stderr, "gltf_write_samples: %s\n", err.message);
            return 1;
        }
        printf("%s meshes=%d joints=%d animations=%d shape_keys=%d\n", path, s.meshes, s.joints,
               s.animations, s.shape_keys);
    }
    return 0;
}
