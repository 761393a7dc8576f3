/* A mesh read or written in the format its file name asks for (.obj, .ply). */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include "base/io_internal.h"
#include "base/mesh_internal.h"
#include "shitsukan/mesh.h"

sk_result sk_mesh_read(sk_mesh *mesh, const char *path, const sk_mesh_read_desc *desc,
                       sk_error *err)
{
    if (!mesh || !path)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "mesh and path must not be NULL");
    const char *ext = sk__path_extension(path);
    if (strcasecmp(ext, ".obj") == 0) return sk_mesh_read_obj(mesh, path, desc, err);
    if (strcasecmp(ext, ".ply") == 0) return sk_mesh_read_ply(mesh, path, desc, err);
    memset(mesh, 0, sizeof *mesh);
    return sk_fail(err, SK_ERROR_UNSUPPORTED,
                   "%s: unknown mesh extension \"%s\" (accepted: .obj, .ply)", path, ext);
}

sk_result sk_mesh_write(const sk_mesh *mesh, const char *path, sk_error *err)
{
    if (!path) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "output path is NULL");
    const char *ext = sk__path_extension(path);
    if (strcasecmp(ext, ".obj") == 0) return sk_mesh_write_obj(mesh, path, NULL, err);
    if (strcasecmp(ext, ".ply") == 0) return sk_mesh_write_ply(mesh, path, err);
    return sk_fail(err, SK_ERROR_UNSUPPORTED,
                   "%s: unknown mesh extension \"%s\" (accepted: .obj, .ply)", path, ext);
}
