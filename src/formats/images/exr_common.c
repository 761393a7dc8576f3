/* OpenEXR C API glue shared by the EXR reader and writer: positional I/O on our own file
 * descriptor, error capture, and mapping of exr_result_t to sk_result. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "formats/images/exr_internal.h"

/* The I/O state of the context this thread set up last. The error handler cannot ask the
   context for its user data: OpenEXRCore reports write errors with the context's lock held,
   and exr_get_user_data takes that lock again (a deadlock on a full disk). Every context is
   made from sk__exr_initializer on the thread that uses it, so this names its state. */
static _Thread_local sk__exr_io *t_io;

static void on_error(exr_const_context_t ctxt, exr_result_t code, const char *msg)
{
    (void)ctxt;
    (void)code;
    sk__exr_io *io = t_io;
    if (!io) return;
    /* The first message names the root cause; later ones only echo the failure. */
    if (!io->message[0]) snprintf(io->message, sizeof io->message, "%s", msg ? msg : "");
}

static int64_t io_read(exr_const_context_t ctxt, void *user, void *buffer, uint64_t size,
                       uint64_t offset, exr_stream_error_func_ptr_t error_cb)
{
    sk__exr_io *io = user;
    uint64_t done = 0;
    while (done < size) {
        ssize_t n =
            pread(io->fd, (char *)buffer + done, (size_t)(size - done), (off_t)(offset + done));
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) {
            io->io_errno = errno;
            error_cb(ctxt, EXR_ERR_READ_IO, "read failed: %s", strerror(errno));
            return -1;
        }
        if (n == 0) break; /* end of file: the library reports the short read */
        done += (uint64_t)n;
    }
    return (int64_t)done;
}

static int64_t io_size(exr_const_context_t ctxt, void *user)
{
    (void)ctxt;
    return ((sk__exr_io *)user)->size;
}

static int64_t io_write(exr_const_context_t ctxt, void *user, const void *buffer, uint64_t size,
                        uint64_t offset, exr_stream_error_func_ptr_t error_cb)
{
    sk__exr_io *io = user;
    uint64_t done = 0;
    while (done < size) {
        ssize_t n = pwrite(io->fd, (const char *)buffer + done, (size_t)(size - done),
                           (off_t)(offset + done));
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            io->io_errno = n < 0 ? errno : EIO;
            error_cb(ctxt, EXR_ERR_WRITE_IO, "write failed: %s", strerror(io->io_errno));
            return -1;
        }
        done += (uint64_t)n;
    }
    return (int64_t)done;
}

exr_context_initializer_t sk__exr_initializer(sk__exr_io *io, bool writing)
{
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    t_io = io;
    init.error_handler_fn = on_error;
    init.user_data = io;
    if (writing) {
        init.write_fn = io_write;
    } else {
        init.read_fn = io_read;
        init.size_fn = io_size;
        /* A truncated file is an error, not something to patch up from what is left. */
        init.flags = EXR_CONTEXT_FLAG_DISABLE_CHUNK_RECONSTRUCTION;
    }
    return init;
}

sk_result sk__exr_fail(sk_error *err, const sk__exr_io *io, exr_result_t rv, sk_result fallback,
                       const char *path, const char *what)
{
    sk_result result = fallback;
    if (rv == EXR_ERR_OUT_OF_MEMORY)
        result = SK_ERROR_OUT_OF_MEMORY;
    else if (io->io_errno != 0)
        result = SK_ERROR_IO;
    const char *detail = io->message[0] ? io->message : exr_get_default_error_message(rv);
    return sk_fail(err, result, "%s: %s (%s)", path, what, detail);
}
