/* shitsukan file helpers: atomic file writing (temporary file in the same folder, renamed
 * into place on success, removed on failure) and whole-file reading with a size cap.
 *
 * Thread-safety: functions are thread-safe; one sk_atomic_file belongs to one thread. */
#ifndef SHITSUKAN_IO_H
#define SHITSUKAN_IO_H

#include <stdint.h>
#include <stdio.h>

#include "shitsukan/core.h"

#ifdef __cplusplus
extern "C" {
#endif

/* A file being written. Every writer in shitsukan goes through this, so a failed or
 * interrupted run never leaves a truncated file under the final name. */
typedef struct sk_atomic_file {
    FILE *fp;         /* open for binary writing on the temporary file */
    char *final_path; /* owned copies: the file replaced (a link's target) ... */
    char *temp_path;  /* ... and the temporary file, NULL when written in place */
    int signal_slot;  /* private: 1 + the signal cleanup slot, 0 = none */
} sk_atomic_file;

/* Creates "<dir>/.<name>.<random>.tmp" beside `path` (mode 0666 less the umask; the name
 * is shortened to fit however long `path`'s name is). What `path` names decides how:
 *  - nothing yet, or a regular file: written beside it and renamed onto it at commit;
 *  - a symbolic link: followed, so the link stays and its target is replaced;
 *  - a character device or FIFO (/dev/null, a named pipe): written in place, since there
 *    is nothing to rename onto (such output cannot be taken back on failure);
 *  - a folder, block device or socket: refused (SK_ERROR_INVALID_ARGUMENT).
 * The temporary file is removed on failure, on abort, and when SIGINT, SIGTERM or SIGHUP
 * stops the process (for signals the program left at their default). */
sk_result sk_atomic_file_open(sk_atomic_file *file, const char *path, sk_error *err);
/* Flushes, closes and renames the temporary file onto the final path. On any failure
 * the temporary file is removed and the final path is left untouched. The struct is
 * reset either way. */
sk_result sk_atomic_file_commit(sk_atomic_file *file, sk_error *err);
/* Closes and removes the temporary file (safe on a zeroed or already finished struct). */
void sk_atomic_file_abort(sk_atomic_file *file);
/* For a writer whose fwrite/fputs failed: aborts the file and returns SK_ERROR_IO with
 * "<path>: write failed (<reason>)", the reason from errno (e.g. "No space left on
 * device"). */
sk_result sk_atomic_file_write_failed(sk_atomic_file *file, sk_error *err);

/* All-or-nothing output of a run that writes several files or folders: either every
 * output appears, or none does (and no folder the run created stays).
 *
 *   sk_output_set *set;
 *   const char *png, *frames;
 *   sk_output_set_create(&set, err);
 *   // reserve every output before the work: bad paths fail here, before any work
 *   r = sk_output_set_file(set, "out/pose.png", &png, err);
 *   if (r == SK_OK) r = sk_output_set_folder(set, "out/frames", &frames, err);
 *   // ... write `png` with any writer, write files into the folder `frames` ...
 *   if (r == SK_OK) r = sk_output_set_commit(set, err);   // renames all into place
 *   else sk_output_set_abort(set);                        // removes everything staged
 *
 * A reserved file is written under a hidden staged name beside its final place (after
 * the same checks as sk_atomic_file_open: links followed, devices and FIFOs written in
 * place, folders refused); a reserved folder is a hidden staged folder, created with
 * its missing parents, whose files move into the final folder at commit (the folder is
 * renamed whole when it did not exist). Staged outputs are removed on abort, on a failed
 * commit and when SIGINT, SIGTERM or SIGHUP stops the process. The same final path
 * reserved twice is refused. Commit and abort free the set. A set belongs to one thread;
 * the staged paths may be written from any. */
typedef struct sk_output_set sk_output_set;
sk_result sk_output_set_create(sk_output_set **out, sk_error *err);
/* Reserves output file `path`; *staged is the path to write it under (owned by the set).
 * A file directly inside a folder reserved before it is written into that folder's staged
 * copy and placed with the folder (its folder need not exist yet). */
sk_result sk_output_set_file(sk_output_set *set, const char *path, const char **staged,
                             sk_error *err);
/* Reserves output folder `path`; *staged is a folder (created now) to write its files in. */
sk_result sk_output_set_folder(sk_output_set *set, const char *path, const char **staged,
                               sk_error *err);
/* The checks sk_output_set_file makes of `path` (links followed; devices and FIFOs
 * accepted; folders, block devices and sockets refused; its folder must exist), without
 * reserving it: for outputs a library call reserves later, checked before the work. */
sk_result sk_output_check(const char *path, sk_error *err);
/* Moves every staged output into place. A reserved file that was not written is an
 * error. On failure everything is removed as by abort. */
sk_result sk_output_set_commit(sk_output_set *set, sk_error *err);
/* Removes every staged output and the folders the set created (safe on NULL). */
void sk_output_set_abort(sk_output_set *set);

/* Opens `path` for reading when it names a regular file (through symbolic links): a
 * folder, device, FIFO or socket fails with SK_ERROR_INVALID_ARGUMENT ("not a regular
 * file"), a missing file with SK_ERROR_NOT_FOUND. The descriptor is close-on-exec;
 * `out_size` (may be NULL) receives the file's size in bytes. Every reader opens its
 * file through one of these. */
sk_result sk_open_regular_fd(const char *path, int *out_fd, long long *out_size, sk_error *err);
/* The same as a stdio stream (binary mode). */
sk_result sk_open_regular_file(const char *path, FILE **out, long long *out_size, sk_error *err);

/* Reads a whole file into a NUL-terminated buffer (free with free()). Files larger than
 * max_bytes (0 = 256 MiB) fail with SK_ERROR_LIMIT before anything is allocated. */
sk_result sk_read_file(const char *path, size_t max_bytes, char **out_data, size_t *out_size,
                       sk_error *err);

/* Writes a WAV file (RIFF WAVE, 16-bit linear PCM, little-endian) of `frames` sample
 * frames of `channels` interleaved channels (1..8) at `sample_rate` Hz (1000..384000).
 * Samples are in [-1, 1], clipped outside, NaN written as 0, rounded to nearest. */
sk_result sk_wav_write(const char *path, const float *samples, size_t frames, int channels,
                       int sample_rate, sk_error *err);
/* The 16-bit value sk_wav_write stores for a sample. */
int16_t sk_wav_sample_16(float v);

/* Creates a folder and its missing parents (like mkdir -p). */
sk_result sk_make_dirs(const char *path, sk_error *err);

#ifdef __cplusplus
}
#endif

#endif /* SHITSUKAN_IO_H */
