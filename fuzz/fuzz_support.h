/* Shared by the fuzz harnesses: the readers take paths, so each input is written to a
 * temporary file first (header only; every harness is its own program). */
#ifndef SK_FUZZ_SUPPORT_H
#define SK_FUZZ_SUPPORT_H

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

#include "shitsukan/image.h"
#include "shitsukan/mesh.h"

/* Writes `data` to a fresh file under $TMPDIR (or /tmp), calls `read(path)`, removes the
 * file. An input that cannot be staged is skipped. */
static inline void sk_fuzz_with_file(const uint8_t *data, size_t size,
                                     void (*read)(const char *path))
{
    const char *dir = getenv("TMPDIR");
    char path[4096];
    snprintf(path, sizeof path, "%s/sk_fuzz_XXXXXX", dir && dir[0] ? dir : "/tmp");
    int fd = mkstemp(path);
    if (fd < 0) return;
    size_t done = 0;
    while (done < size) {
        ssize_t n = write(fd, data + done, size - done);
        if (n <= 0) break;
        done += (size_t)n;
    }
    close(fd);
    if (done == size) read(path);
    unlink(path);
}

/* What any read must guarantee: on success an image within the caps, on failure no
 * pixels handed out. A violation aborts, which the fuzzer reports as a crash. */
static inline void sk_fuzz_check_image(sk_result result, sk_image *image,
                                       const sk_image_metadata *meta)
{
    if (result != SK_OK) {
        if (image->data) abort();
        return;
    }
    if (image->width < 1 || image->width > SK_IMAGE_MAX_DIMENSION || image->height < 1 ||
        image->height > SK_IMAGE_MAX_DIMENSION || image->channels < 1 || image->channels > 4 ||
        !image->data || meta->count < 0 || meta->count > SK_IMAGE_MAX_METADATA)
        abort();
    sk_image_free(image);
}

/* On success a mesh that passes sk_mesh_validate, on failure nothing allocated. */
static inline void sk_fuzz_check_mesh(sk_result result, sk_mesh *mesh)
{
    if (result != SK_OK) {
        if (mesh->positions || mesh->indices) abort();
        return;
    }
    if (sk_mesh_validate(mesh, NULL) != SK_OK) abort();
    sk_mesh_free(mesh);
}

/* A small cap keeps the fuzzer's memory bounded; the cap logic is under test too. */
#define SK_FUZZ_MESH_CAP ((size_t)64 << 20)

#endif
