/* Wavefront OBJ writer: v (with the "v x y z r g b" colour extension, sRGB-encoded), vt, vn,
 * f in the slash form the arrays call for, optionally split into objects with their own
 * materials, and an MTL file with diffuse colours and maps, both atomic. */
#define _POSIX_C_SOURCE 200809L
#include <stdlib.h>
#include <string.h>

#include "base/image_internal.h"
#include "base/io_internal.h"
#include "shitsukan/io.h"
#include "shitsukan/mesh.h"

char *sk_obj_mtl_path(const char *obj_path)
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

static void write_mtl(FILE *fp, const sk_obj_material *materials, int count)
{
    fprintf(fp, "# written by shitsukan %s\n", SK_VERSION_STRING);
    for (int i = 0; i < count; i++) {
        const sk_obj_material *m = &materials[i];
        fprintf(fp, "%snewmtl %s\n", i ? "\n" : "", m->name);
        fprintf(fp, "Ka 0 0 0\nKd %.9g %.9g %.9g\nKs 0 0 0\nd 1\nillum 1\n", m->diffuse[0],
                m->diffuse[1], m->diffuse[2]);
        if (m->texture_path) fprintf(fp, "map_Kd %s\n", m->texture_path);
    }
}

static void write_face(FILE *fp, const sk_mesh *m, size_t t, const char *form)
{
    fputc('f', fp);
    for (int k = 0; k < 3; k++) {
        unsigned long i = (unsigned long)m->indices[3 * t + (size_t)k] + 1;
        fprintf(fp, form, i, i, i);
    }
    fputc('\n', fp);
}

/* %.9g prints every float so that it reads back bit-exact. */
static void write_obj(FILE *fp, const sk_mesh *m, const char *mtl_name, const sk_obj_write_desc *d)
{
    fprintf(fp, "# written by shitsukan %s\n", SK_VERSION_STRING);
    fprintf(fp, "# %zu vertices, %zu triangles\n", m->vertex_count, m->triangle_count);
    if (mtl_name) fprintf(fp, "mtllib %s\n", mtl_name);
    if (mtl_name && d->group_count == 0) fprintf(fp, "usemtl %s\n", d->materials[0].name);
    for (size_t i = 0; i < m->vertex_count; i++) {
        const float *p = m->positions + 3 * i;
        if (m->colors) {
            /* the tools that read this extension (Blender, MeshLab) take it as sRGB */
            const float *c = m->colors + 3 * i;
            fprintf(fp, "v %.9g %.9g %.9g %.9g %.9g %.9g\n", p[0], p[1], p[2],
                    (float)sk__srgb_encode(c[0]), (float)sk__srgb_encode(c[1]),
                    (float)sk__srgb_encode(c[2]));
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
    if (d->group_count == 0) {
        for (size_t t = 0; t < m->triangle_count; t++) write_face(fp, m, t, form);
        return;
    }
    size_t t = 0;
    for (int g = 0; g < d->group_count; g++) {
        const sk_obj_group *group = &d->groups[g];
        fprintf(fp, "o %s\n", group->name);
        if (group->material >= 0) fprintf(fp, "usemtl %s\n", d->materials[group->material].name);
        for (size_t k = 0; k < group->triangle_count; k++, t++) write_face(fp, m, t, form);
    }
}

static bool is_name(const char *s) { return s && s[0] && !has_space_or_newline(s, true); }

/* The materials and groups of a desc (the single-texture form becomes one material). */
static sk_result check_desc(const sk_mesh *mesh, const sk_obj_write_desc *d, sk_error *err)
{
    if (d->texture_path && (!d->texture_path[0] || has_space_or_newline(d->texture_path, false)))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "texture_path must be non-empty and on one line");
    if (d->material_count < 0 || d->group_count < 0 || (d->material_count > 0 && !d->materials) ||
        (d->group_count > 0 && !d->groups))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "material_count / group_count without arrays");
    for (int i = 0; i < d->material_count; i++) {
        const sk_obj_material *m = &d->materials[i];
        if (!is_name(m->name))
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "materials[%d].name \"%s\" must be non-empty without white space", i,
                           m->name ? m->name : "");
        for (int c = 0; c < 3; c++)
            if (!(m->diffuse[c] >= 0.0f && m->diffuse[c] <= 1.0f))
                return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                               "materials[%d].diffuse[%d] = %g is out of range [0, 1]", i, c,
                               (double)m->diffuse[c]);
        if (m->texture_path &&
            (!m->texture_path[0] || has_space_or_newline(m->texture_path, false)))
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "materials[%d].texture_path must be non-empty and on one line", i);
    }
    size_t covered = 0;
    for (int g = 0; g < d->group_count; g++) {
        const sk_obj_group *group = &d->groups[g];
        if (!is_name(group->name))
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "groups[%d].name \"%s\" must be non-empty without white space", g,
                           group->name ? group->name : "");
        if (group->material < -1 || group->material >= d->material_count)
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "groups[%d].material = %d is out of range [-1, %d)", g, group->material,
                           d->material_count);
        covered += group->triangle_count;
    }
    if (d->group_count > 0 && covered != mesh->triangle_count)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "the groups hold %zu triangles, the mesh has %zu", covered,
                       mesh->triangle_count);
    return SK_OK;
}

sk_result sk_mesh_write_obj(const sk_mesh *mesh, const char *path, const sk_obj_write_desc *desc,
                            sk_error *err)
{
    sk_result res = sk_mesh_validate(mesh, err);
    if (res != SK_OK) return res;
    if (!path) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "output path is NULL");
    sk_obj_write_desc d = {0};
    if (desc) d = *desc;
    if ((d.texture_path || d.material_name) && (d.material_count > 0 || d.group_count > 0))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "texture_path / material_name and materials / groups exclude each other");
    /* the single-texture form: one white material with the diffuse map */
    sk_obj_material single = {
        d.material_name ? d.material_name : "material", {1, 1, 1}, d.texture_path};
    if (d.material_name && !is_name(d.material_name))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "material_name \"%s\" must be non-empty without white space",
                       d.material_name);
    if ((res = check_desc(mesh, &d, err)) != SK_OK) return res;
    if (d.texture_path) {
        d.materials = &single;
        d.material_count = 1;
    }
    bool with_mtl = d.material_count > 0;
    if (d.mtl_name && (!d.mtl_name[0] || has_space_or_newline(d.mtl_name, false)))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "mtl_name must be non-empty and on one line");
    char *mtl_path = with_mtl ? (d.mtl_path ? strdup(d.mtl_path) : sk_obj_mtl_path(path)) : NULL;
    if (with_mtl && !mtl_path) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    const char *slash = mtl_path ? strrchr(mtl_path, '/') : NULL;
    const char *mtl_name = !mtl_path    ? NULL
                           : d.mtl_name ? d.mtl_name
                           : slash      ? slash + 1
                                        : mtl_path;
    sk_atomic_file obj = {0}, mtl = {0};
    res = sk_atomic_file_open(&obj, path, err);
    if (res == SK_OK && mtl_path) res = sk_atomic_file_open(&mtl, mtl_path, err);
    if (res == SK_OK) {
        sk__c_locale locale;
        sk__c_locale_push(&locale);
        write_obj(obj.fp, mesh, mtl_name, &d);
        if (mtl_path) write_mtl(mtl.fp, d.materials, d.material_count);
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
