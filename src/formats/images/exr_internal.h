/* Private OpenEXR (C API) glue shared by the EXR reader and writer (not installed). */
#ifndef SK_IO_EXR_INTERNAL_H
#define SK_IO_EXR_INTERNAL_H

#include <openexr.h>

#include "shitsukan/core.h"

/* The user data of every context we create: our own file descriptor (so that reading
 * distinguishes a missing file, and writing goes to the atomic temporary file) and the
 * first error message the library reported (it would print to stderr otherwise). */
typedef struct sk__exr_io {
    int fd;
    int64_t size; /* file size for reading */
    int io_errno; /* errno of a failed pread/pwrite, 0 if none */
    char message[256];
} sk__exr_io;

/* A context initializer wired to `io`: silent error capture plus pread/pwrite on io->fd. */
exr_context_initializer_t sk__exr_initializer(sk__exr_io *io, bool writing);

/* Records an OpenEXR failure in `err` as "<path>: <what> (<library message>)" with
 * the sk_result matching `rv` (`fallback` for format errors); returns that result. */
sk_result sk__exr_fail(sk_error *err, const sk__exr_io *io, exr_result_t rv, sk_result fallback,
                       const char *path, const char *what);

/* ZIP and ZIPS chunk compression by libdeflate, an exr_encode_pipeline_t compress_fn
 * (exr_zip.c): the format's byte split and predictor, then a zlib stream at the level
 * of the sk__exr_zip given as the pipeline's encoding_user_data. The compressed chunk
 * is malloc'ed and handed to the caller in `chunk` (the pipeline does not own it). */
typedef struct sk__exr_zip {
    struct libdeflate_compressor *compressor;
    uint8_t *scratch;
    size_t scratch_size;
    uint8_t *chunk; /* the last chunk's bytes, for the caller to take */
    size_t chunk_size;
} sk__exr_zip;
exr_result_t sk__exr_zip_compress(exr_encode_pipeline_t *encode);

#endif
