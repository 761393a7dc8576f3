/* JSON documents to files (json_file.h). */
#include "formats/json_file.h"

#include <stdio.h>
#include <stdlib.h>

#include "shitsukan/io.h"

sk_result sk__json_write_file(cJSON *root, const char *path, sk_error *err)
{
    char *text = root ? cJSON_Print(root) : NULL;
    cJSON_Delete(root);
    if (!text) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for %s", path);
    sk_atomic_file file;
    sk_result r = sk_atomic_file_open(&file, path, err);
    if (r == SK_OK) {
        if (fputs(text, file.fp) < 0 || fputc('\n', file.fp) == EOF) {
            r = sk_atomic_file_write_failed(&file, err);
        } else {
            r = sk_atomic_file_commit(&file, err);
        }
    }
    cJSON_free(text);
    return r;
}
