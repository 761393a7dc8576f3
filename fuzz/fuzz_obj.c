/* Fuzz harness for the OBJ reader: any input must give SK_OK or an error, never a crash,
 * and a mesh that reads must be valid. */
#define _POSIX_C_SOURCE 200809L
#include "fuzz_support.h"

static void read_obj(const char *path)
{
    sk_mesh mesh;
    sk_mesh_read_desc desc = {SK_FUZZ_MESH_CAP};
    sk_fuzz_check_mesh(sk_mesh_read_obj(&mesh, path, &desc, NULL), &mesh);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    sk_fuzz_with_file(data, size, read_obj);
    return 0;
}
