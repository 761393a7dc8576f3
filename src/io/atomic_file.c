/* Atomic file writing: a temporary file in the destination folder, renamed into place
 * only when everything was written (CONVENTIONS.md, "Errors and files"). */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "shitsukan/io.h"

static void reset(sk_atomic_file *file)
{
    free(file->final_path);
    free(file->temp_path);
    file->fp = NULL;
    file->final_path = NULL;
    file->temp_path = NULL;
}

sk_result sk_atomic_file_open(sk_atomic_file *file, const char *path, sk_error *err)
{
    memset(file, 0, sizeof *file);
    if (!path || !path[0]) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "empty output path");
    size_t len = strlen(path);
    if (path[len - 1] == '/')
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "%s: output path names a folder", path);
    const char *slash = strrchr(path, '/');
    size_t dir_len = slash ? (size_t)(slash - path + 1) : 0;
    const char *base = path + dir_len;
    size_t temp_size = len + 48;
    file->final_path = strdup(path);
    file->temp_path = malloc(temp_size);
    if (!file->final_path || !file->temp_path) {
        reset(file);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    }
    /* Name from pid, address and clock: unique per process and call; O_EXCL retries. */
    uint64_t salt = sk_hash((uint64_t)getpid(), (uint64_t)(uintptr_t)file,
                            (uint64_t)(sk_time_seconds() * 1e9), 0);
    int fd = -1;
    for (int attempt = 0; attempt < 16 && fd < 0; attempt++) {
        snprintf(file->temp_path, temp_size, "%.*s.%s.%08llx.tmp", (int)dir_len, path, base,
                 (unsigned long long)(sk_mix64(salt + (uint64_t)attempt) & 0xffffffffu));
        fd = open(file->temp_path, O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd < 0 && errno != EEXIST) break;
    }
    if (fd < 0) {
        int e = errno;
        sk_result r = sk_fail(err, SK_ERROR_IO, "%s: cannot create file (%s)", path, strerror(e));
        reset(file);
        return r;
    }
    file->fp = fdopen(fd, "wb");
    if (!file->fp) {
        close(fd);
        unlink(file->temp_path);
        reset(file);
        return sk_fail(err, SK_ERROR_IO, "%s: cannot open stream", path);
    }
    return SK_OK;
}

sk_result sk_atomic_file_commit(sk_atomic_file *file, sk_error *err)
{
    if (!file->fp) {
        reset(file);
        return sk_fail(err, SK_ERROR_IO, "file was not open");
    }
    int failed = ferror(file->fp) || fflush(file->fp) != 0;
    int e = failed ? errno : 0;
    if (fclose(file->fp) != 0 && !failed) {
        failed = 1;
        e = errno;
    }
    file->fp = NULL;
    if (!failed && rename(file->temp_path, file->final_path) != 0) {
        failed = 1;
        e = errno;
    }
    sk_result r = SK_OK;
    if (failed) {
        unlink(file->temp_path);
        r = sk_fail(err, SK_ERROR_IO, "%s: write failed (%s)", file->final_path,
                    e ? strerror(e) : "stream error");
    }
    reset(file);
    return r;
}

void sk_atomic_file_abort(sk_atomic_file *file)
{
    if (file->fp) fclose(file->fp);
    if (file->temp_path) unlink(file->temp_path);
    reset(file);
}
