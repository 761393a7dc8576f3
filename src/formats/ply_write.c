/* Binary little-endian PLY writer: float x y z, nx ny nz, s t and attributes, uchar sRGB
 * colours, "list uchar uint vertex_indices" faces; byte order set explicitly, so any host
 * writes the same file. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <string.h>

#include "base/image_internal.h"
#include "shitsukan/io.h"
#include "shitsukan/mesh.h"

/* Property names the writer gives the standard arrays (and the reader looks for). */
static const char *const reserved[] = {
    "x",           "y",         "z",   "nx",    "ny",        "nz",
    "s",           "t",         "u",   "v",     "texture_u", "texture_v",
    "texture_s",   "texture_t", "red", "green", "blue",      "vertex_indices",
    "vertex_index"};

static sk_result check_attribute_name(const char *name, sk_error *err)
{
    for (const char *c = name; *c; c++)
        if ((unsigned char)*c <= ' ' || *c == 0x7f)
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "attribute \"%s\": PLY property names cannot hold white space or "
                           "control characters",
                           name);
    for (size_t i = 0; i < sizeof reserved / sizeof reserved[0]; i++)
        if (strcmp(name, reserved[i]) == 0)
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "attribute \"%s\" would read back as a standard PLY property", name);
    return SK_OK;
}

static unsigned char *put_u32(unsigned char *p, uint32_t v)
{
    p[0] = (unsigned char)v;
    p[1] = (unsigned char)(v >> 8);
    p[2] = (unsigned char)(v >> 16);
    p[3] = (unsigned char)(v >> 24);
    return p + 4;
}

static unsigned char *put_f32(unsigned char *p, float f)
{
    uint32_t bits;
    memcpy(&bits, &f, sizeof bits);
    return put_u32(p, bits);
}

/* The 8-bit sRGB code of a linear colour component: tools (Blender, MeshLab) read PLY
 * colours as sRGB, so a linear 0.5 is written as 188, not 128. */
static unsigned char color_code(float c)
{
    if (!(c > 0.0f)) return 0;
    if (c >= 1.0f) return 255;
    return (unsigned char)floor(sk__srgb_encode(c) * 255.0 + 0.5);
}

static void write_header(FILE *fp, const sk_mesh *m)
{
    fputs("ply\nformat binary_little_endian 1.0\n", fp);
    fprintf(fp, "comment written by shitsukan %s\n", SK_VERSION_STRING);
    fprintf(fp, "element vertex %zu\n", m->vertex_count);
    fputs("property float x\nproperty float y\nproperty float z\n", fp);
    if (m->normals) fputs("property float nx\nproperty float ny\nproperty float nz\n", fp);
    /* "s t" is what Blender writes and reads; the reader also accepts "u v". */
    if (m->uvs) fputs("property float s\nproperty float t\n", fp);
    if (m->colors) fputs("property uchar red\nproperty uchar green\nproperty uchar blue\n", fp);
    for (int a = 0; a < m->attribute_count; a++) {
        const sk_mesh_attribute *attr = &m->attributes[a];
        if (attr->components == 1)
            fprintf(fp, "property float %s\n", attr->name);
        else
            for (int c = 0; c < attr->components; c++)
                fprintf(fp, "property float %s_%d\n", attr->name, c);
    }
    if (m->triangle_count) {
        fprintf(fp, "element face %zu\n", m->triangle_count);
        fputs("property list uchar uint vertex_indices\n", fp);
    }
    fputs("end_header\n", fp);
}

static void write_body(FILE *fp, const sk_mesh *m)
{
    /* Largest record: 3 + 3 + 2 floats, 3 colour bytes, 8 attributes of 4 floats. */
    unsigned char record[4 * 8 + 3 + 4 * 4 * SK_MESH_MAX_ATTRIBUTES];
    for (size_t i = 0; i < m->vertex_count; i++) {
        unsigned char *p = record;
        for (int k = 0; k < 3; k++) p = put_f32(p, m->positions[3 * i + (size_t)k]);
        for (int k = 0; m->normals && k < 3; k++) p = put_f32(p, m->normals[3 * i + (size_t)k]);
        for (int k = 0; m->uvs && k < 2; k++) p = put_f32(p, m->uvs[2 * i + (size_t)k]);
        for (int k = 0; m->colors && k < 3; k++) *p++ = color_code(m->colors[3 * i + (size_t)k]);
        for (int a = 0; a < m->attribute_count; a++) {
            const sk_mesh_attribute *attr = &m->attributes[a];
            for (int c = 0; c < attr->components; c++)
                p = put_f32(p, attr->data[i * (size_t)attr->components + (size_t)c]);
        }
        fwrite(record, 1, (size_t)(p - record), fp);
    }
    for (size_t t = 0; t < m->triangle_count; t++) {
        unsigned char *p = record;
        *p++ = 3;
        for (int k = 0; k < 3; k++) p = put_u32(p, m->indices[3 * t + (size_t)k]);
        fwrite(record, 1, (size_t)(p - record), fp);
    }
}

sk_result sk_mesh_write_ply(const sk_mesh *mesh, const char *path, sk_error *err)
{
    sk_result res = sk_mesh_validate(mesh, err);
    if (res != SK_OK) return res;
    if (!path) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "output path is NULL");
    for (int a = 0; a < mesh->attribute_count; a++) {
        res = check_attribute_name(mesh->attributes[a].name, err);
        if (res != SK_OK) return res;
    }
    sk_atomic_file file;
    res = sk_atomic_file_open(&file, path, err);
    if (res != SK_OK) return res;
    write_header(file.fp, mesh);
    write_body(file.fp, mesh);
    return sk_atomic_file_commit(&file, err);
}
