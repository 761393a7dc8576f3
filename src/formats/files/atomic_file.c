/* Atomic file writing: a temporary file in the destination folder, renamed into place
 * only when everything was written (CONTRIBUTING.md, "Errors and files"). What the path
 * names decides how: a symbolic link is followed (the temporary file goes beside the
 * link's target, which is replaced, and the link stays); a character device or FIFO is
 * written in place (-o /dev/null, a pipe); a folder, block device or socket is refused.
 * Temporary files are removed on failure and, through the signal cleanup table, when
 * SIGINT, SIGTERM or SIGHUP stops the process. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "base/io_internal.h"
#include "shitsukan/io.h"

#ifndef NAME_MAX
#define NAME_MAX 255
#endif

/* ------------------------------------------------------------ path rules */

/* The folder part of `path` including its slash ("" for a bare name). */
static size_t dir_length(const char *path)
{
    const char *slash = strrchr(path, '/');
    return slash ? (size_t)(slash - path + 1) : 0;
}

sk_result sk__output_folder_exists(const char *path, sk_error *err)
{
    size_t dir_len = dir_length(path);
    if (dir_len == 0) return SK_OK;
    char *folder = strndup(path, dir_len);
    if (!folder) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    struct stat st;
    int e = stat(folder, &st) != 0 ? errno : S_ISDIR(st.st_mode) ? 0 : ENOTDIR;
    free(folder);
    if (e) return sk_fail(err, SK_ERROR_IO, "%s: cannot create file (%s)", path, strerror(e));
    return SK_OK;
}

char *sk__sibling_name(const char *path, const char *suffix, uint64_t salt)
{
    size_t dir_len = dir_length(path);
    const char *base = path + dir_len;
    /* "." + base + "." + 8 hex + suffix must fit in NAME_MAX */
    size_t fixed = 1 + 1 + 8 + strlen(suffix);
    size_t base_len = strlen(base);
    if (base_len + fixed > NAME_MAX) base_len = NAME_MAX > fixed ? NAME_MAX - fixed : 0;
    size_t size = dir_len + base_len + fixed + 1;
    char *out = malloc(size);
    if (!out) return NULL;
    snprintf(out, size, "%.*s.%.*s.%08llx%s", (int)dir_len, path, (int)base_len, base,
             (unsigned long long)(salt & 0xffffffffu), suffix);
    return out;
}

/* The target of a symbolic link, relative targets taken from the link's folder. */
static char *link_target(const char *path)
{
    char target[PATH_MAX];
    ssize_t n = readlink(path, target, sizeof target - 1);
    if (n <= 0) return NULL;
    target[n] = '\0';
    if (target[0] == '/') return strdup(target);
    size_t dir_len = dir_length(path);
    size_t size = dir_len + (size_t)n + 1;
    char *out = malloc(size);
    if (out) snprintf(out, size, "%.*s%s", (int)dir_len, path, target);
    return out;
}

sk_result sk__output_resolve(const char *path, char **resolved, sk__output_kind *kind,
                             sk_error *err)
{
    *resolved = NULL;
    *kind = SK__OUTPUT_FILE;
    if (!path || !path[0]) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "empty output path");
    size_t len = strlen(path);
    if (path[len - 1] == '/')
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "%s: output path names a folder", path);
    /* what the path names, links followed by the system: a stream is written as named
       (/dev/stdout is a link to a pipe that has no path) */
    struct stat st;
    if (stat(path, &st) == 0 && (S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode))) {
        *kind = SK__OUTPUT_STREAM;
        *resolved = strdup(path);
        return *resolved ? SK_OK : sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    }
    char *target = strdup(path);
    if (!target) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    /* follow links (a chain of at most 16) to the file they name */
    for (int hops = 0; lstat(target, &st) == 0 && S_ISLNK(st.st_mode); hops++) {
        char *next = hops < 16 ? link_target(target) : NULL;
        free(target);
        if (!next)
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "%s: symbolic link that cannot be followed (a loop?)", path);
        target = next;
    }
    if (lstat(target, &st) == 0) {
        const char *refused = S_ISDIR(st.st_mode)    ? "a folder"
                              : S_ISBLK(st.st_mode)  ? "a block device"
                              : S_ISSOCK(st.st_mode) ? "a socket"
                                                     : NULL;
        if (refused) {
            free(target);
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "%s: output path names %s (give a file name)", path, refused);
        }
    }
    *resolved = target;
    return SK_OK;
}

/* ------------------------------------------------------------ the file */

static void reset(sk_atomic_file *file)
{
    if (file->signal_slot > 0) sk__cleanup_unregister(file->signal_slot - 1);
    free(file->final_path);
    free(file->temp_path);
    file->fp = NULL;
    file->final_path = NULL;
    file->temp_path = NULL;
    file->signal_slot = 0;
}

/* "<path>: <what> (<reason>)" with the reason of errno `e`. */
static sk_result io_failure(sk_error *err, const char *path, const char *what, int e)
{
    return sk_fail(err, SK_ERROR_IO, "%s: %s (%s)", path, what, e ? strerror(e) : "stream error");
}

sk_result sk_atomic_file_open(sk_atomic_file *file, const char *path, sk_error *err)
{
    memset(file, 0, sizeof *file);
    sk__output_kind kind;
    sk_result r = sk__output_resolve(path, &file->final_path, &kind, err);
    if (r != SK_OK) return r;
    int fd = -1;
    if (kind == SK__OUTPUT_STREAM) {
        /* a device or FIFO is written in place: there is nothing to rename onto */
        fd = open(file->final_path, O_WRONLY | O_CLOEXEC);
        if (fd < 0) {
            r = io_failure(err, path, "cannot open for writing", errno);
            reset(file);
            return r;
        }
    } else {
        /* name from pid, address and clock: unique per process and call; O_EXCL retries */
        uint64_t salt = sk_hash((uint64_t)getpid(), (uint64_t)(uintptr_t)file,
                                (uint64_t)(sk_time_seconds() * 1e9), 0);
        for (int attempt = 0; attempt < 16 && fd < 0; attempt++) {
            free(file->temp_path);
            file->temp_path =
                sk__sibling_name(file->final_path, ".tmp", sk_mix64(salt + (uint64_t)attempt));
            if (!file->temp_path) {
                reset(file);
                return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
            }
            fd = open(file->temp_path, O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
            if (fd < 0 && errno != EEXIST) break;
        }
        if (fd < 0) {
            r = io_failure(err, path, "cannot create file", errno);
            reset(file);
            return r;
        }
        file->signal_slot = sk__cleanup_register(file->temp_path, false) + 1;
    }
    file->fp = fdopen(fd, "wb");
    if (!file->fp) {
        int e = errno;
        close(fd);
        if (file->temp_path) unlink(file->temp_path);
        reset(file);
        return io_failure(err, path, "cannot open stream", e);
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
    if (!failed && file->temp_path && rename(file->temp_path, file->final_path) != 0) {
        failed = 1;
        e = errno;
    }
    sk_result r = SK_OK;
    if (failed) {
        if (file->temp_path) unlink(file->temp_path);
        r = io_failure(err, file->final_path, "write failed", e);
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

sk_result sk_atomic_file_write_failed(sk_atomic_file *file, sk_error *err)
{
    int e = errno;
    const char *path = file->final_path ? file->final_path : "output";
    sk_result r = io_failure(err, path, "write failed", file->fp && ferror(file->fp) ? e : 0);
    sk_atomic_file_abort(file);
    return r;
}
