/* Opening regular files for reading, whole-file reading with a size cap, and folder
 * creation. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "shitsukan/io.h"

sk_result sk_open_regular_fd(const char *path, int *out_fd, long long *out_size, sk_error *err)
{
    *out_fd = -1;
    int fd = open(path, O_RDONLY | O_CLOEXEC);
    if (fd < 0)
        return sk_fail(err, errno == ENOENT ? SK_ERROR_NOT_FOUND : SK_ERROR_IO,
                       "%s: cannot open (%s)", path, strerror(errno));
    struct stat st;
    if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        close(fd);
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "%s: not a regular file", path);
    }
    *out_fd = fd;
    if (out_size) *out_size = (long long)st.st_size;
    return SK_OK;
}

sk_result sk_open_regular_file(const char *path, FILE **out, long long *out_size, sk_error *err)
{
    *out = NULL;
    int fd;
    sk_result r = sk_open_regular_fd(path, &fd, out_size, err);
    if (r != SK_OK) return r;
    FILE *fp = fdopen(fd, "rb");
    if (!fp) {
        int e = errno;
        close(fd);
        return sk_fail(err, SK_ERROR_IO, "%s: cannot open (%s)", path, strerror(e));
    }
    *out = fp;
    return SK_OK;
}

sk_result sk_read_file(const char *path, size_t max_bytes, char **out_data, size_t *out_size,
                       sk_error *err)
{
    *out_data = NULL;
    if (out_size) *out_size = 0;
    if (max_bytes == 0) max_bytes = (size_t)256 << 20;
    FILE *fp;
    long long file_size;
    sk_result opened = sk_open_regular_file(path, &fp, &file_size, err);
    if (opened != SK_OK) return opened;
    if ((unsigned long long)file_size > (unsigned long long)max_bytes) {
        fclose(fp);
        return sk_fail(err, SK_ERROR_LIMIT, "%s: file is %lld bytes, more than the cap of %zu",
                       path, file_size, max_bytes);
    }
    size_t size = (size_t)file_size;
    char *data = malloc(size + 1);
    if (!data) {
        fclose(fp);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "%s: out of memory", path);
    }
    size_t got = fread(data, 1, size, fp);
    int bad = ferror(fp) || got != size;
    fclose(fp);
    if (bad) {
        free(data);
        return sk_fail(err, SK_ERROR_IO, "%s: read failed", path);
    }
    data[size] = '\0';
    *out_data = data;
    if (out_size) *out_size = size;
    return SK_OK;
}

sk_result sk_make_dirs(const char *path, sk_error *err)
{
    if (!path || !path[0]) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "empty folder path");
    char *buf = strdup(path);
    if (!buf) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    for (char *p = buf + 1;; p++) {
        char c = *p;
        if (c == '/' || c == '\0') {
            *p = '\0';
            if (mkdir(buf, 0777) != 0 && errno != EEXIST) {
                sk_result r = sk_fail(err, SK_ERROR_IO, "%s: cannot create folder (%s)", buf,
                                      strerror(errno));
                free(buf);
                return r;
            }
            *p = c;
            if (c == '\0') break;
        }
    }
    struct stat st;
    int ok = stat(path, &st) == 0 && S_ISDIR(st.st_mode);
    free(buf);
    if (!ok) return sk_fail(err, SK_ERROR_IO, "%s: not a folder", path);
    return SK_OK;
}
