/* shitsukan point caches: per-frame vertex positions of a mesh whose topology does not
 * change, in the PC2 format that Blender's Mesh Cache modifier (and 3ds Max's Point Cache)
 * plays on the rest mesh. Layout, little-endian: char[12] "POINTCACHE2\0", int32 version
 * 1, int32 point count, float32 start frame, float32 sample rate (frames per sample; 1 =
 * a sample every frame), int32 sample count, then float32 x y z per point per sample.
 *
 * Thread-safety: a writer belongs to one thread; reading is thread-safe. */
#ifndef SHITSUKAN_POINTCACHE_H
#define SHITSUKAN_POINTCACHE_H

#include <stddef.h>

#include "shitsukan/core.h"
#include "shitsukan/io.h"

#ifdef __cplusplus
extern "C" {
#endif

#define SK_PC2_HEADER_BYTES 32

/* A PC2 file being written sample by sample (atomically: nothing appears under the final
 * name until every announced sample is written and the file is closed). */
typedef struct sk_pc2_writer {
    sk_atomic_file file;
    int points, samples, written;
} sk_pc2_writer;

/* Opens `path` for `samples` samples of `points` points. */
sk_result sk_pc2_open(sk_pc2_writer *w, const char *path, int points, float start_frame,
                      float sample_rate, int samples, sk_error *err);
/* Appends one sample: 3 floats per point (finite). */
sk_result sk_pc2_append(sk_pc2_writer *w, const float *xyz, sk_error *err);
/* Commits the file; fails (leaving no file) unless every sample was written. */
sk_result sk_pc2_close(sk_pc2_writer *w, sk_error *err);
/* Drops an unfinished file. */
void sk_pc2_abort(sk_pc2_writer *w);

/* A PC2 file read back. */
typedef struct sk_pc2 {
    int points, samples;
    float start_frame, sample_rate;
    float *xyz; /* samples x points x 3 */
} sk_pc2;

/* Reads a whole PC2 file of at most max_bytes (0 = 1 GiB). A header whose counts the file
 * cannot hold, a wrong signature or version, non-finite values or trailing bytes fail
 * with SK_ERROR_PARSE naming what is wrong. */
sk_result sk_pc2_read(const char *path, size_t max_bytes, sk_pc2 *out, sk_error *err);
sk_result sk_pc2_parse(const void *data, size_t size, const char *source_name, sk_pc2 *out,
                       sk_error *err);
void sk_pc2_free(sk_pc2 *pc2);

#ifdef __cplusplus
}
#endif

#endif /* SHITSUKAN_POINTCACHE_H */
