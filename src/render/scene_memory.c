/* The memory a scene will take, estimated from its desc before anything is built, so a
 * scene of absurd tessellation or meshes is refused up front instead of failing (or
 * swapping) minutes into the build. Upper-bound counts; constants measured per triangle
 * and per pixel (docs/robustness.md). */
#define _POSIX_C_SOURCE 200809L
#include <sys/stat.h>

#include "render/render_internal.h"

/* Per vertex: position, normal, UV, tangent (48 B); per triangle: indices (12 B), the
   Embree build (about 100 B with its temporaries) and the shading records. */
#define BYTES_PER_VERTEX 48.0
#define BYTES_PER_TRIANGLE 160.0
/* A mesh file in memory, per byte of file: the densest files (binary PLY) give about
   12 bytes per vertex and 13 per triangle. */
#define BYTES_PER_FILE_BYTE 16.0
/* Per pixel: the float RGBA film and the tone-mapped copy being written. */
#define BYTES_PER_PIXEL 40.0

static double primitive_bytes(const sk_render_object_desc *o)
{
    double segments = o->segments > 0 ? o->segments : 64;
    double rings = o->rings > 0 ? o->rings : 32;
    double vertices, triangles;
    switch (o->shape) {
    case SK_RENDER_SHAPE_PLANE:
        vertices = 4, triangles = 2;
        break;
    case SK_RENDER_SHAPE_BOX:
        vertices = 24, triangles = 12;
        break;
    default: /* surfaces of revolution: rings of segments, caps */
        vertices = (rings + 4) * (segments + 1) + 2 * (segments + 2);
        triangles = 2 * (rings + 3) * segments + 2 * segments;
        break;
    }
    return vertices * BYTES_PER_VERTEX + triangles * BYTES_PER_TRIANGLE;
}

double sk_render_scene_desc_memory(const sk_render_scene_desc *desc, int *largest_object)
{
    double total = 0, largest = -1;
    if (largest_object) *largest_object = -1;
    for (int i = 0; i < desc->object_count && i < SK_RENDER_MAX_OBJECTS; i++) {
        const sk_render_object_desc *o = &desc->objects[i];
        double bytes = 0;
        if (o->shape != SK_RENDER_SHAPE_MESH) {
            bytes = primitive_bytes(o);
        } else if (o->file[0]) {
            char path[2 * SK_RENDER_PATH_SIZE];
            sk__join_path(desc->base_dir, o->file, path, sizeof path);
            struct stat st;
            if (stat(path, &st) == 0) bytes = (double)st.st_size * BYTES_PER_FILE_BYTE;
        } else if (o->mesh) {
            bytes = o->mesh->vertex_count * BYTES_PER_VERTEX +
                    o->mesh->triangle_count * BYTES_PER_TRIANGLE;
        }
        if (bytes > largest) {
            largest = bytes;
            if (largest_object) *largest_object = i;
        }
        total += bytes;
    }
    double w = desc->image.width > 0 ? desc->image.width : 640;
    double h = desc->image.height > 0 ? desc->image.height : 360;
    return total + w * h * BYTES_PER_PIXEL;
}
