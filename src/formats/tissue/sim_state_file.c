/* The simulation state saved to and restored from a file (the bytes of sk_tissue_sim_save_state,
 * written atomically). */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "shitsukan/io.h"
#include "models/tissue/sim_internal.h"

sk_result sk_tissue_sim_save_state_file(const sk_tissue_sim *s, const char *path, sk_error *err)
{
    size_t size = sk_tissue_sim_state_size(s);
    void *buf = malloc(size);
    if (!buf) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for the state");
    sk_result r = sk_tissue_sim_save_state(s, buf, size, err);
    sk_atomic_file f;
    if (r == SK_OK) r = sk_atomic_file_open(&f, path, err);
    if (r == SK_OK) {
        if (fwrite(buf, 1, size, f.fp) != size) {
            r = sk_atomic_file_write_failed(&f, err);
        } else {
            r = sk_atomic_file_commit(&f, err);
        }
    }
    free(buf);
    return r;
}

sk_result sk_tissue_sim_load_state_file(sk_tissue_sim *s, const char *path, sk_error *err)
{
    char *data = NULL;
    size_t size = 0;
    sk_result r = sk_read_file(path, sk_tissue_sim_state_size(s) + 1, &data, &size, err);
    if (r == SK_ERROR_LIMIT)
        return sk_fail(err, SK_ERROR_PARSE, "%s: larger than a state of this simulation", path);
    if (r != SK_OK) return r;
    r = sk_tissue_sim_load_state(s, data, size, err);
    free(data);
    if (r != SK_OK) sk_error_prefix(err, r, "%s", path);
    return r;
}
