/* Wavefront OBJ reader: v (with optional sRGB colour, decoded to linear), vt, vn and f statements
 * with strict validation; (v, vt, vn) corner triples unified into single-index vertices by a hash
 * map; polygons triangulated. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/image_internal.h"
#include "base/io_internal.h"
#include "base/mesh_internal.h"
#include "base/polygon_triangulate.h"
#include "shitsukan/io.h"
#include "shitsukan/mesh.h"

#define NO_INDEX UINT32_MAX

/* A unified vertex: indices into the v, vt and vn lists (NO_INDEX when absent). */
typedef struct corner {
    uint32_t v, t, n;
} corner;

typedef struct obj_reader {
    const char *path;
    sk_error *err;
    size_t line;
    sk__budget budget;
    sk__array v;        /* float x3 */
    sk__array colors;   /* float x3, parallel to v once any vertex has a colour */
    sk__array vt;       /* float x2 */
    sk__array vn;       /* float x3 */
    sk__array corners;  /* corner, one per output vertex */
    sk__array tris;     /* uint32 x3, output vertex indices */
    uint32_t *slots;    /* hash table over corners: index + 1, 0 = empty */
    size_t slot_count;  /* power of two */
    sk__array face;     /* uint32: output vertex of each corner of the current face */
    sk__array face_pos; /* uint32: v index of each corner of the current face */
    sk__array face_tri; /* uint32 x3: local corner numbers from the triangulator */
    sk__triangulator triangulator;
    bool any_face;
} obj_reader;

static sk_result fail_line(obj_reader *r, sk_result result, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;
static sk_result fail_line(obj_reader *r, sk_result result, const char *fmt, ...)
{
    va_list args;
    va_start(args, fmt);
    sk__fail_at(r->err, result, r->path, r->line, fmt, args);
    va_end(args);
    return result;
}

static sk_result fail_alloc(obj_reader *r, sk_result result)
{
    if (result == SK_ERROR_LIMIT)
        return fail_line(r, result, "the mesh needs more memory than the cap of %zu bytes",
                         r->budget.max);
    return fail_line(r, result, "out of memory");
}

/* Appends `count` items to an array (charged to the budget). */
static sk_result push(obj_reader *r, sk__array *a, const void *items, size_t count)
{
    sk_result res = sk__array_reserve(a, count, &r->budget);
    if (res != SK_OK) return fail_alloc(r, res);
    memcpy((char *)a->data + a->count * a->elem, items, count * a->elem);
    a->count += count;
    return SK_OK;
}

/* ------------------------------------------------------------------ tokens */

typedef struct token {
    const char *s;
    size_t len;
} token;

static bool is_space(char c)
{
    return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

/* Splits [p, end) into tokens, storing at most `max`; returns how many there are. */
static int split(const char *p, const char *end, token *out, int max)
{
    int n = 0;
    while (p < end) {
        while (p < end && is_space(*p)) p++;
        if (p == end) break;
        const char *s = p;
        while (p < end && !is_space(*p)) p++;
        if (n < max) {
            out[n].s = s;
            out[n].len = (size_t)(p - s);
        }
        n++;
    }
    return n;
}

static bool token_is(token t, const char *word)
{
    size_t n = strlen(word);
    return t.len == n && memcmp(t.s, word, n) == 0;
}

static sk_result parse_float(obj_reader *r, token t, const char *what, float *out)
{
    double d;
    if (!sk__parse_double(t.s, t.len, &d))
        return fail_line(r, SK_ERROR_PARSE, "%s \"%.*s\" is not a number", what,
                         (int)fmin(t.len, 40), t.s);
    float f = (float)d;
    if (!isfinite(d) || !isfinite(f))
        return fail_line(r, SK_ERROR_PARSE, "%s \"%.*s\" is not a finite float", what,
                         (int)fmin(t.len, 40), t.s);
    *out = f;
    return SK_OK;
}

static sk_result parse_floats(obj_reader *r, const token *t, int count, const char *what,
                              float *out)
{
    for (int i = 0; i < count; i++) {
        sk_result res = parse_float(r, t[i], what, &out[i]);
        if (res != SK_OK) return res;
    }
    return SK_OK;
}

/* ------------------------------------------------------------------ statements */

static sk_result read_v(obj_reader *r, const token *t, int n)
{
    if (n != 3 && n != 4 && n != 6)
        return fail_line(r, SK_ERROR_PARSE,
                         "v needs 3 coordinates (x y z), optionally w or r g b; got %d values", n);
    float xyz[3], w, rgb[3] = {1.0f, 1.0f, 1.0f};
    sk_result res = parse_floats(r, t, 3, "coordinate", xyz);
    /* w only weighs rational curves; it is checked and dropped. */
    if (res == SK_OK && n == 4) res = parse_float(r, t[3], "w", &w);
    if (res == SK_OK && n == 6) res = parse_floats(r, t + 3, 3, "colour", rgb);
    if (res != SK_OK) return res;
    /* the colour extension holds sRGB values (what Blender and MeshLab write and read) */
    for (int c = 0; n == 6 && c < 3; c++) rgb[c] = (float)sk__srgb_decode(rgb[c]);
    if (n == 6 && r->colors.count == 0 && r->v.count > 0) {
        /* First coloured vertex: earlier vertices get white. */
        for (size_t i = 0; res == SK_OK && i < r->v.count; i++) {
            static const float white[3] = {1.0f, 1.0f, 1.0f};
            res = push(r, &r->colors, white, 1);
        }
    }
    if (res == SK_OK && (n == 6 || r->colors.count > 0)) res = push(r, &r->colors, rgb, 1);
    if (res == SK_OK) res = push(r, &r->v, xyz, 1);
    return res;
}

static sk_result read_vt(obj_reader *r, const token *t, int n)
{
    if (n < 1 || n > 3)
        return fail_line(r, SK_ERROR_PARSE, "vt needs 1-3 values (u [v [w]]); got %d", n);
    float uvw[3] = {0.0f, 0.0f, 0.0f};
    sk_result res = parse_floats(r, t, n, "texture coordinate", uvw);
    return res == SK_OK ? push(r, &r->vt, uvw, 1) : res; /* w dropped: elem is 2 floats */
}

static sk_result read_vn(obj_reader *r, const token *t, int n)
{
    if (n != 3) return fail_line(r, SK_ERROR_PARSE, "vn needs 3 values; got %d", n);
    float xyz[3];
    sk_result res = parse_floats(r, t, 3, "normal", xyz);
    return res == SK_OK ? push(r, &r->vn, xyz, 1) : res;
}

/* Resolves a 1-based or negative (relative to the end of the list so far) index. */
static sk_result resolve(obj_reader *r, const char *s, size_t len, size_t count, const char *list,
                         const char *plural, uint32_t *out)
{
    long long i;
    if (!sk__parse_int64(s, len, &i))
        return fail_line(r, SK_ERROR_PARSE, "%s index \"%.*s\" is not an integer", list,
                         (int)(len < 40 ? len : 40), s);
    if (i == 0)
        return fail_line(r, SK_ERROR_PARSE, "%s index 0 is not valid (OBJ indices start at 1)",
                         list);
    long long resolved = i > 0 ? i - 1 : (long long)count + i;
    if (resolved < 0 || (unsigned long long)resolved >= count)
        return fail_line(r, SK_ERROR_PARSE, "%s index %lld is out of range (%zu %s defined so far)",
                         list, i, count, plural);
    *out = (uint32_t)resolved;
    return SK_OK;
}

static uint64_t corner_hash(corner c) { return sk_hash(c.v, c.t, c.n, 0); }

static sk_result grow_slots(obj_reader *r)
{
    size_t count = r->slot_count ? r->slot_count * 2 : 1024;
    size_t bytes;
    if (!sk_size_mul(count, sizeof(uint32_t), &bytes) ||
        r->budget.used - r->slot_count * sizeof(uint32_t) + bytes > r->budget.max)
        return fail_alloc(r, SK_ERROR_LIMIT);
    uint32_t *slots = calloc(count, sizeof *slots);
    if (!slots) return fail_alloc(r, SK_ERROR_OUT_OF_MEMORY);
    const corner *cs = r->corners.data;
    for (size_t i = 0; i < r->corners.count; i++) {
        size_t h = (size_t)corner_hash(cs[i]) & (count - 1);
        while (slots[h]) h = (h + 1) & (count - 1);
        slots[h] = (uint32_t)(i + 1);
    }
    r->budget.used = r->budget.used - r->slot_count * sizeof(uint32_t) + bytes;
    free(r->slots);
    r->slots = slots;
    r->slot_count = count;
    return SK_OK;
}

/* The output vertex for a corner triple, made on first use. */
static sk_result unify(obj_reader *r, corner c, uint32_t *out)
{
    if ((r->corners.count + 1) * 2 > r->slot_count) {
        sk_result res = grow_slots(r);
        if (res != SK_OK) return res;
    }
    const corner *cs = r->corners.data;
    size_t mask = r->slot_count - 1;
    size_t h = (size_t)corner_hash(c) & mask;
    for (; r->slots[h]; h = (h + 1) & mask) {
        const corner *o = &cs[r->slots[h] - 1];
        if (o->v == c.v && o->t == c.t && o->n == c.n) {
            *out = r->slots[h] - 1;
            return SK_OK;
        }
    }
    if (r->corners.count >= UINT32_MAX - 1)
        return fail_line(r, SK_ERROR_LIMIT, "more than 2^32 - 2 distinct vertices");
    sk_result res = push(r, &r->corners, &c, 1);
    if (res != SK_OK) return res;
    *out = (uint32_t)(r->corners.count - 1);
    r->slots[h] = *out + 1;
    return SK_OK;
}

/* One corner "v", "v/vt", "v//vn" or "v/vt/vn". */
static sk_result read_corner(obj_reader *r, token t, corner *c)
{
    const char *parts[3];
    size_t lens[3];
    int count = 0;
    const char *p = t.s, *end = t.s + t.len;
    for (const char *q = p; q < end; q++)
        if (*q == '/' && ++count > 2)
            return fail_line(r, SK_ERROR_PARSE, "face corner \"%.*s\" has more than two '/'",
                             (int)(t.len < 40 ? t.len : 40), t.s);
    count = 0;
    for (;;) {
        const char *slash = memchr(p, '/', (size_t)(end - p));
        parts[count] = p;
        lens[count] = (size_t)((slash ? slash : end) - p);
        count++;
        if (!slash) break;
        p = slash + 1;
    }
    c->t = c->n = NO_INDEX;
    if (lens[0] == 0 || (count == 2 && lens[1] == 0) || (count == 3 && lens[2] == 0))
        return fail_line(r, SK_ERROR_PARSE,
                         "face corner \"%.*s\" is malformed (v, v/vt, v//vn or v/vt/vn)",
                         (int)(t.len < 40 ? t.len : 40), t.s);
    sk_result res = resolve(r, parts[0], lens[0], r->v.count, "vertex", "vertices", &c->v);
    if (res == SK_OK && count >= 2 && lens[1] > 0)
        res = resolve(r, parts[1], lens[1], r->vt.count, "texture coordinate",
                      "texture coordinates", &c->t);
    if (res == SK_OK && count == 3)
        res = resolve(r, parts[2], lens[2], r->vn.count, "normal", "normals", &c->n);
    return res;
}

static sk_result read_f(obj_reader *r, const char *p, const char *end)
{
    r->face.count = r->face_pos.count = 0;
    r->any_face = true;
    sk_result res = SK_OK;
    while (res == SK_OK) {
        token t[1];
        while (p < end && is_space(*p)) p++;
        if (p == end) break;
        t[0].s = p;
        while (p < end && !is_space(*p)) p++;
        t[0].len = (size_t)(p - t[0].s);
        corner c;
        uint32_t vertex;
        res = read_corner(r, t[0], &c);
        if (res == SK_OK) res = unify(r, c, &vertex);
        if (res == SK_OK) res = push(r, &r->face, &vertex, 1);
        if (res == SK_OK) res = push(r, &r->face_pos, &c.v, 1);
    }
    if (res != SK_OK) return res;
    size_t n = r->face.count;
    if (n < 3) return fail_line(r, SK_ERROR_PARSE, "a face needs at least 3 corners; got %zu", n);
    const uint32_t *face = r->face.data;
    r->face_tri.count = 0;
    res = sk__array_reserve(&r->face_tri, n - 2, &r->budget);
    if (res != SK_OK) return fail_alloc(r, res);
    if (sk__triangulate(&r->triangulator, r->v.data, r->face_pos.data, n, r->face_tri.data) !=
        SK_OK)
        return fail_alloc(r, SK_ERROR_OUT_OF_MEMORY);
    res = sk__array_reserve(&r->tris, n - 2, &r->budget);
    if (res != SK_OK) return fail_alloc(r, res);
    const uint32_t *local = r->face_tri.data;
    uint32_t *dst = (uint32_t *)r->tris.data + 3 * r->tris.count;
    for (size_t i = 0; i < 3 * (n - 2); i++) dst[i] = face[local[i]];
    r->tris.count += n - 2;
    return SK_OK;
}

/* Statements that carry nothing a triangle mesh holds (groups, materials, smoothing,
 * lines, points, free-form geometry and its attributes). */
static bool is_ignored(token t)
{
    static const char *const words[] = {
        "o",      "g",          "s",         "mg",       "usemtl",   "mtllib", "l",
        "p",      "vp",         "cstype",    "deg",      "bmat",     "step",   "curv",
        "curv2",  "surf",       "parm",      "trim",     "hole",     "scrv",   "sp",
        "end",    "con",        "bevel",     "c_interp", "d_interp", "lod",    "maplib",
        "usemap", "shadow_obj", "trace_obj", "ctech",    "stech"};
    for (size_t i = 0; i < sizeof words / sizeof words[0]; i++)
        if (token_is(t, words[i])) return true;
    return false;
}

static sk_result read_line(obj_reader *r, const char *p, const char *end)
{
    const char *hash = memchr(p, '#', (size_t)(end - p));
    if (hash) end = hash;
    token kw;
    if (split(p, end, &kw, 1) == 0) return SK_OK;
    const char *args = kw.s + kw.len;
    if (token_is(kw, "f")) return read_f(r, args, end);
    if (is_ignored(kw)) return SK_OK;
    token t[6];
    int n = split(args, end, t, 6);
    if (token_is(kw, "v")) return read_v(r, t, n);
    if (token_is(kw, "vt")) return read_vt(r, t, n);
    if (token_is(kw, "vn")) return read_vn(r, t, n);
    return fail_line(r, SK_ERROR_PARSE, "unknown statement \"%.*s\"",
                     (int)(kw.len < 40 ? kw.len : 40), kw.s);
}

/* ------------------------------------------------------------------ output */

static sk_result build_mesh(obj_reader *r, sk_mesh *mesh)
{
    const float *v = r->v.data, *colors = r->colors.data, *vt = r->vt.data, *vn = r->vn.data;
    bool has_colors = r->colors.count > 0;
    size_t cap = r->budget.max - r->budget.used;
    if (!r->any_face) {
        /* Only v lines: a point cloud. */
        sk_result res = sk__mesh_create_capped(mesh, r->v.count, 0, has_colors ? SK_MESH_COLORS : 0,
                                               cap, r->err);
        if (res != SK_OK) return sk_error_prefix(r->err, res, "%s", r->path);
        if (r->v.count) memcpy(mesh->positions, v, r->v.count * 3 * sizeof(float));
        if (has_colors) memcpy(mesh->colors, colors, r->v.count * 3 * sizeof(float));
        return SK_OK;
    }
    const corner *cs = r->corners.data;
    size_t count = r->corners.count;
    bool has_uv = false, has_normal = false;
    for (size_t i = 0; i < count; i++) {
        has_uv |= cs[i].t != NO_INDEX;
        has_normal |= cs[i].n != NO_INDEX;
    }
    int flags = (has_uv ? SK_MESH_UVS : 0) | (has_normal ? SK_MESH_NORMALS : 0) |
                (has_colors ? SK_MESH_COLORS : 0);
    sk_result res = sk__mesh_create_capped(mesh, count, r->tris.count, flags, cap, r->err);
    if (res != SK_OK) return sk_error_prefix(r->err, res, "%s", r->path);
    memcpy(mesh->indices, r->tris.data, r->tris.count * 3 * sizeof(uint32_t));
    bool missing_normal = false;
    for (size_t i = 0; i < count; i++) {
        corner c = cs[i];
        memcpy(mesh->positions + 3 * i, v + 3 * (size_t)c.v, 3 * sizeof(float));
        if (has_colors) memcpy(mesh->colors + 3 * i, colors + 3 * (size_t)c.v, 3 * sizeof(float));
        if (has_uv && c.t != NO_INDEX)
            memcpy(mesh->uvs + 2 * i, vt + 2 * (size_t)c.t, 2 * sizeof(float));
        if (!has_normal) continue;
        const float *nrm = c.n != NO_INDEX ? vn + 3 * (size_t)c.n : NULL;
        double len =
            nrm ? sqrt((double)nrm[0] * nrm[0] + (double)nrm[1] * nrm[1] + (double)nrm[2] * nrm[2])
                : 0.0;
        if (len > 0.0) {
            for (int k = 0; k < 3; k++) mesh->normals[3 * i + (size_t)k] = (float)(nrm[k] / len);
        } else {
            /* Marked for the computed normal below (no vn, or a zero vn). */
            mesh->normals[3 * i] = NAN;
            missing_normal = true;
        }
    }
    if (missing_normal) {
        float *computed = malloc(count * 3 * sizeof(float));
        if (!computed) return sk_fail(r->err, SK_ERROR_OUT_OF_MEMORY, "%s: out of memory", r->path);
        res = sk__mesh_normals_into(mesh, computed, r->err);
        for (size_t i = 0; res == SK_OK && i < count; i++)
            if (isnan(mesh->normals[3 * i]))
                memcpy(mesh->normals + 3 * i, computed + 3 * i, 3 * sizeof(float));
        free(computed);
    }
    return res;
}

sk_result sk_mesh_read_obj(sk_mesh *mesh, const char *path, const sk_mesh_read_desc *desc,
                           sk_error *err)
{
    if (!mesh || !path)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "mesh and path must not be NULL");
    memset(mesh, 0, sizeof *mesh);
    size_t cap = sk__mesh_read_cap(desc);
    char *text = NULL;
    size_t size = 0;
    sk_result res = sk_read_file(path, cap, &text, &size, err);
    if (res != SK_OK) return res;

    obj_reader r;
    memset(&r, 0, sizeof r);
    r.path = path;
    r.err = err;
    r.budget.max = cap;
    r.budget.used = size;
    r.v.elem = r.colors.elem = r.vn.elem = 3 * sizeof(float);
    r.vt.elem = 2 * sizeof(float);
    r.corners.elem = sizeof(corner);
    r.tris.elem = r.face_tri.elem = 3 * sizeof(uint32_t);
    r.face.elem = r.face_pos.elem = sizeof(uint32_t);

    sk__c_locale locale;
    sk__c_locale_push(&locale);
    const char *p = text, *end = text + size;
    if (size >= 3 && memcmp(p, "\xef\xbb\xbf", 3) == 0) p += 3; /* UTF-8 byte order mark */
    while (res == SK_OK && p < end) {
        r.line++;
        const char *nl = memchr(p, '\n', (size_t)(end - p));
        const char *line_end = nl ? nl : end;
        res = read_line(&r, p, line_end);
        p = nl ? nl + 1 : end;
    }
    sk__c_locale_pop(&locale);
    free(text);
    if (res == SK_OK) res = build_mesh(&r, mesh);
    sk__array_free(&r.v);
    sk__array_free(&r.colors);
    sk__array_free(&r.vt);
    sk__array_free(&r.vn);
    sk__array_free(&r.corners);
    sk__array_free(&r.tris);
    sk__array_free(&r.face);
    sk__array_free(&r.face_pos);
    sk__array_free(&r.face_tri);
    sk__triangulator_free(&r.triangulator);
    free(r.slots);
    if (res != SK_OK) sk_mesh_free(mesh);
    return res;
}
