/* Wavefront OBJ writer: v (with the "v x y z r g b" colour extension), vt, vn, f in the
 * slash form the arrays call for, and an MTL file with a diffuse map, both atomic. */
#define _POSIX_C_SOURCE 200809L
#include <stdlib.h>
#include <string.h>

#include "io/io_internal.h"
#include "shitsukan/io.h"
#include "shitsukan/mesh.h"

/* "dir/name.obj" -> "dir/name.mtl" (the extension replaced, or appended if none). */
static char *mtl_path_for(const char *obj_path)
{
    const char *ext = sk__path_extension(obj_path);
    size_t stem = strlen(obj_path) - strlen(ext);
    char *out = malloc(stem + 5);
    if (!out) return NULL;
    memcpy(out, obj_path, stem);
    memcpy(out + stem, ".mtl", 5);
    return out;
}

static bool has_space_or_newline(const char *s, bool spaces)
{
    for (; *s; s++)
        if (*s == '\n' || *s == '\r' || (spaces && (*s == ' ' || *s == '\t'))) return true;
    return false;
}

static void write_mtl(FILE *fp, const char *material, const char *texture)
{
    fprintf(fp, "# written by shitsukan %s\n", SK_VERSION_STRING);
    fprintf(fp, "newmtl %s\n", material);
    fputs("Ka 0 0 0\nKd 1 1 1\nKs 0 0 0\nd 1\nillum 1\n", fp);
    fprintf(fp, "map_Kd %s\n", texture);
}

/* %.9g prints every float so that it reads back bit-exact. */
static void write_obj(FILE *fp, const sk_mesh *m, const char *mtl_name, const char *material)
{
    fprintf(fp, "# written by shitsukan %s\n", SK_VERSION_STRING);
    fprintf(fp, "# %zu vertices, %zu triangles\n", m->vertex_count, m->triangle_count);
    if (mtl_name) fprintf(fp, "mtllib %s\nusemtl %s\n", mtl_name, material);
    for (size_t i = 0; i < m->vertex_count; i++) {
        const float *p = m->positions + 3 * i;
        if (m->colors) {
            const float *c = m->colors + 3 * i;
            fprintf(fp, "v %.9g %.9g %.9g %.9g %.9g %.9g\n", p[0], p[1], p[2], c[0], c[1], c[2]);
        } else {
            fprintf(fp, "v %.9g %.9g %.9g\n", p[0], p[1], p[2]);
        }
    }
    for (size_t i = 0; m->uvs && i < m->vertex_count; i++)
        fprintf(fp, "vt %.9g %.9g\n", m->uvs[2 * i], m->uvs[2 * i + 1]);
    for (size_t i = 0; m->normals && i < m->vertex_count; i++)
        fprintf(fp, "vn %.9g %.9g %.9g\n", m->normals[3 * i], m->normals[3 * i + 1],
                m->normals[3 * i + 2]);
    /* Vertices are unified, so one index serves v, vt and vn alike. */
    const char *form =
        m->uvs ? (m->normals ? " %lu/%lu/%lu" : " %lu/%lu") : (m->normals ? " %lu//%lu" : " %lu");
    for (size_t t = 0; t < m->triangle_count; t++) {
        fputc('f', fp);
        for (int k = 0; k < 3; k++) {
            unsigned long i = (unsigned long)m->indices[3 * t + (size_t)k] + 1;
            fprintf(fp, form, i, i, i);
        }
        fputc('\n', fp);
    }
}

sk_result sk_mesh_write_obj(const sk_mesh *mesh, const char *path, const sk_obj_write_desc *desc,
                            sk_error *err)
{
    sk_result res = sk_mesh_validate(mesh, err);
    if (res != SK_OK) return res;
    if (!path) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "output path is NULL");
    const char *texture = desc ? desc->texture_path : NULL;
    const char *material = (desc && desc->material_name) ? desc->material_name : "material";
    if (texture && (!texture[0] || has_space_or_newline(texture, false)))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "texture_path must be non-empty and on one line");
    if (!material[0] || has_space_or_newline(material, true))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "material_name \"%s\" must be non-empty without white space", material);

    char *mtl_path = texture ? mtl_path_for(path) : NULL;
    if (texture && !mtl_path) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    const char *slash = mtl_path ? strrchr(mtl_path, '/') : NULL;
    const char *mtl_name = mtl_path ? (slash ? slash + 1 : mtl_path) : NULL;
    sk_atomic_file obj = {0}, mtl = {0};
    res = sk_atomic_file_open(&obj, path, err);
    if (res == SK_OK && mtl_path) res = sk_atomic_file_open(&mtl, mtl_path, err);
    if (res == SK_OK) {
        sk__c_locale locale;
        sk__c_locale_push(&locale);
        write_obj(obj.fp, mesh, mtl_name, material);
        if (mtl_path) write_mtl(mtl.fp, material, texture);
        sk__c_locale_pop(&locale);
        /* The material first, so that a written OBJ never names a missing MTL. */
        if (mtl_path) res = sk_atomic_file_commit(&mtl, err);
        if (res == SK_OK) res = sk_atomic_file_commit(&obj, err);
    }
    sk_atomic_file_abort(&mtl);
    sk_atomic_file_abort(&obj);
    free(mtl_path);
    return res;
}
