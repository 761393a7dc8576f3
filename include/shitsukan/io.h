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
    FILE *fp;          /* open for binary writing on the temporary file */
    char *final_path;  /* owned copies */
    char *temp_path;
} sk_atomic_file;

/* Creates "<dir>/.<name>.<random>.tmp" beside `path` (mode 0666 less the umask). */
sk_result sk_atomic_file_open(sk_atomic_file *file, const char *path, sk_error *err);
/* Flushes, closes and renames the temporary file onto the final path. On any failure
 * the temporary file is removed and the final path is left untouched. The struct is
 * reset either way. */
sk_result sk_atomic_file_commit(sk_atomic_file *file, sk_error *err);
/* Closes and removes the temporary file (safe on a zeroed or already finished struct). */
void sk_atomic_file_abort(sk_atomic_file *file);

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
