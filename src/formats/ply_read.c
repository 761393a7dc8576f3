/* PLY 1.0 reader (ascii, binary little and big endian): header with any elements and
 * scalar or list properties of every PLY type; vertex positions, normals, UVs, colours (sRGB,
 * decoded) and other scalars as attributes; face lists triangulated; other elements skipped. Counts
 * are checked against the file size and the read cap before anything is allocated. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "base/image_internal.h"
#include "base/io_internal.h"
#include "base/mesh_internal.h"
#include "base/polygon_triangulate.h"
#include "shitsukan/mesh.h"
#include "shitsukan/io.h"

/* Header limits: far beyond any real file, small enough to keep the header in memory. */
#define MAX_ELEMENTS 32
#define MAX_PROPERTIES 256
#define MAX_NAME 64
#define MAX_HEADER_LINE 4096
#define MAX_HEADER_BYTES (1 << 20)

typedef enum ply_type {
    T_NONE = 0,
    T_INT8,
    T_UINT8,
    T_INT16,
    T_UINT16,
    T_INT32,
    T_UINT32,
    T_FLOAT32,
    T_FLOAT64
} ply_type;

static const struct {
    const char *name;
    ply_type type;
} type_names[] = {
    {"char", T_INT8},     {"int8", T_INT8},       {"uchar", T_UINT8},    {"uint8", T_UINT8},
    {"short", T_INT16},   {"int16", T_INT16},     {"ushort", T_UINT16},  {"uint16", T_UINT16},
    {"int", T_INT32},     {"int32", T_INT32},     {"uint", T_UINT32},    {"uint32", T_UINT32},
    {"float", T_FLOAT32}, {"float32", T_FLOAT32}, {"double", T_FLOAT64}, {"float64", T_FLOAT64}};
static const int type_size[] = {0, 1, 1, 2, 2, 4, 4, 4, 8};
/* Divisor that maps an integer colour to [0, 1]. */
static const double type_max[] = {1, 127, 255, 32767, 65535, 2147483647.0, 4294967295.0, 1, 1};

static bool is_integer_type(ply_type t) { return t >= T_INT8 && t <= T_UINT32; }

typedef enum role {
    R_SKIP,
    R_X,
    R_Y,
    R_Z,
    R_NX,
    R_NY,
    R_NZ,
    R_U,
    R_V,
    R_RED,
    R_GREEN,
    R_BLUE,
    R_ATTR,
    R_FACE
} role;

typedef struct ply_property {
    char name[MAX_NAME];
    ply_type type;       /* of the value, or of the items of a list */
    ply_type count_type; /* T_NONE for a scalar */
    role role;
    int attr, component; /* for R_ATTR */
} ply_property;

typedef struct ply_element {
    char name[MAX_NAME];
    uint64_t count;
    int prop_count;
    ply_property props[MAX_PROPERTIES];
} ply_element;

typedef enum ply_format { F_ASCII, F_LITTLE, F_BIG } ply_format;

typedef struct ply_reader {
    const char *path;
    sk_error *err;
    FILE *fp;
    unsigned char buf[1 << 16];
    size_t pos, len;
    uint64_t consumed; /* bytes of the file before buf[pos] */
    uint64_t file_size;
    bool eof;
    size_t line; /* header and ASCII body: current line number */
    bool in_header;
    bool body_started; /* ASCII: a body value has been read */
    ply_format format;
    int element_count;
    ply_element elements[MAX_ELEMENTS];
    int vertex_element, face_element;
    const char *what;      /* "vertex", "face", element name: for messages */
    uint64_t record;       /* index of the record being read */
    const char *done_what; /* the last record completely read, for "extra values" */
    uint64_t done_record;
    size_t token_line; /* ASCII: line of the last value read */
    sk__budget budget;
    /* Results */
    sk_mesh *mesh;
    bool normals, uvs, colors;
    int attribute_count;
    char attr_names[SK_MESH_MAX_ATTRIBUTES][SK_MESH_ATTRIBUTE_NAME_SIZE];
    int attr_components[SK_MESH_MAX_ATTRIBUTES];
    sk__array corners; /* uint32: vertex indices of all polygons */
    sk__array sizes;   /* uint32: corner count of each polygon */
    uint64_t triangle_total;
} ply_reader;

/* ------------------------------------------------------------------ errors */

static sk_result fail(ply_reader *r, sk_result result, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;
static sk_result fail(ply_reader *r, sk_result result, const char *fmt, ...)
{
    /* Binary bodies have no lines to point at; the element and record name the place. */
    size_t line = (r->in_header || r->format == F_ASCII) ? r->line : 0;
    va_list args;
    va_start(args, fmt);
    sk__fail_at(r->err, result, r->path, line, fmt, args);
    va_end(args);
    return result;
}

/* Failure inside a record: names the element and the record index. */
static sk_result fail_record(ply_reader *r, sk_result result, const char *what)
{
    return fail(r, result, "%s %llu: %s", r->what, (unsigned long long)r->record, what);
}

/* ------------------------------------------------------------------ buffered input */

/* Makes at least n (<= sizeof buf) bytes available; false at the end of the file. */
static bool need(ply_reader *r, size_t n)
{
    while (r->len - r->pos < n) {
        if (r->eof) return false;
        memmove(r->buf, r->buf + r->pos, r->len - r->pos);
        r->len -= r->pos;
        r->pos = 0;
        size_t got = fread(r->buf + r->len, 1, sizeof r->buf - r->len, r->fp);
        r->len += got;
        if (got == 0) r->eof = true;
    }
    return true;
}

static int next_byte(ply_reader *r)
{
    if (!need(r, 1)) return -1;
    r->consumed++;
    return r->buf[r->pos++];
}

static uint64_t bytes_left(const ply_reader *r) { return r->file_size - r->consumed; }

/* ------------------------------------------------------------------ header */

static sk_result read_header_line(ply_reader *r, char *line, size_t *header_bytes)
{
    size_t n = 0;
    for (;;) {
        int c = next_byte(r);
        if (c < 0) return fail(r, SK_ERROR_PARSE, "header ends without end_header");
        if (++*header_bytes > MAX_HEADER_BYTES)
            return fail(r, SK_ERROR_PARSE, "header is longer than %d bytes", MAX_HEADER_BYTES);
        if (c == '\n') break;
        if (c == '\0') return fail(r, SK_ERROR_PARSE, "header contains a NUL byte");
        if (n + 1 >= MAX_HEADER_LINE)
            return fail(r, SK_ERROR_PARSE, "header line longer than %d bytes", MAX_HEADER_LINE);
        line[n++] = (char)c;
    }
    if (n > 0 && line[n - 1] == '\r') n--;
    line[n] = '\0';
    r->line++;
    return SK_OK;
}

/* Splits a header line into at most `max` words in place; returns how many there are. */
static int words(char *line, char **out, int max)
{
    int n = 0;
    char *p = line;
    for (;;) {
        while (*p == ' ' || *p == '\t') p++;
        if (!*p) break;
        if (n < max) out[n] = p;
        n++;
        while (*p && *p != ' ' && *p != '\t') p++;
        if (*p) *p++ = '\0';
    }
    return n;
}

static ply_type parse_type(const char *name)
{
    for (size_t i = 0; i < sizeof type_names / sizeof type_names[0]; i++)
        if (strcmp(name, type_names[i].name) == 0) return type_names[i].type;
    return T_NONE;
}

static sk_result header_element(ply_reader *r, char **w, int n)
{
    if (n != 3) return fail(r, SK_ERROR_PARSE, "expected \"element <name> <count>\"");
    if (r->element_count == MAX_ELEMENTS)
        return fail(r, SK_ERROR_UNSUPPORTED, "more than %d elements", MAX_ELEMENTS);
    if (strlen(w[1]) >= MAX_NAME) return fail(r, SK_ERROR_PARSE, "element name is too long");
    long long count;
    if (!sk__parse_int64(w[2], strlen(w[2]), &count) || count < 0 || w[2][0] == '+')
        return fail(r, SK_ERROR_PARSE, "element count \"%.40s\" is not a count", w[2]);
    for (int i = 0; i < r->element_count; i++)
        if (strcmp(r->elements[i].name, w[1]) == 0)
            return fail(r, SK_ERROR_PARSE, "element \"%s\" is declared twice", w[1]);
    ply_element *e = &r->elements[r->element_count++];
    memset(e, 0, sizeof *e);
    strcpy(e->name, w[1]);
    e->count = (uint64_t)count;
    return SK_OK;
}

static sk_result header_property(ply_reader *r, char **w, int n)
{
    if (r->element_count == 0) return fail(r, SK_ERROR_PARSE, "property before any element");
    ply_element *e = &r->elements[r->element_count - 1];
    if (e->prop_count == MAX_PROPERTIES)
        return fail(r, SK_ERROR_UNSUPPORTED, "element \"%s\" has more than %d properties", e->name,
                    MAX_PROPERTIES);
    ply_property p;
    memset(&p, 0, sizeof p);
    const char *name;
    if (n >= 2 && strcmp(w[1], "list") == 0) {
        if (n != 5)
            return fail(r, SK_ERROR_PARSE, "expected \"property list <count type> <type> <name>\"");
        p.count_type = parse_type(w[2]);
        p.type = parse_type(w[3]);
        if (p.count_type == T_NONE || p.type == T_NONE)
            return fail(r, SK_ERROR_PARSE, "unknown type in \"property list %s %s\"", w[2], w[3]);
        if (!is_integer_type(p.count_type))
            return fail(r, SK_ERROR_PARSE, "list count type \"%s\" is not an integer type", w[2]);
        name = w[4];
    } else {
        if (n != 3) return fail(r, SK_ERROR_PARSE, "expected \"property <type> <name>\"");
        p.type = parse_type(w[1]);
        if (p.type == T_NONE)
            return fail(r, SK_ERROR_PARSE, "unknown property type \"%.40s\"", w[1]);
        name = w[2];
    }
    if (strlen(name) >= MAX_NAME) return fail(r, SK_ERROR_PARSE, "property name is too long");
    for (int i = 0; i < e->prop_count; i++)
        if (strcmp(e->props[i].name, name) == 0)
            return fail(r, SK_ERROR_PARSE, "property \"%s\" is declared twice in \"%s\"", name,
                        e->name);
    strcpy(p.name, name);
    e->props[e->prop_count++] = p;
    return SK_OK;
}

static sk_result read_header(ply_reader *r)
{
    r->in_header = true;
    char line[MAX_HEADER_LINE];
    char *w[6];
    size_t header_bytes = 0;
    sk_result res = read_header_line(r, line, &header_bytes);
    if (res != SK_OK || strcmp(line, "ply") != 0)
        return fail(r, SK_ERROR_PARSE, "not a PLY file (the first line is not \"ply\")");
    bool have_format = false;
    for (;;) {
        res = read_header_line(r, line, &header_bytes);
        if (res != SK_OK) return res;
        int n = words(line, w, 6);
        if (n == 0) continue;
        if (strcmp(w[0], "comment") == 0 || strcmp(w[0], "obj_info") == 0) continue;
        if (strcmp(w[0], "end_header") == 0) {
            if (n != 1) return fail(r, SK_ERROR_PARSE, "text after end_header");
            break;
        }
        if (strcmp(w[0], "format") == 0) {
            if (have_format) return fail(r, SK_ERROR_PARSE, "format is given twice");
            if (n != 3) return fail(r, SK_ERROR_PARSE, "expected \"format <type> 1.0\"");
            if (strcmp(w[1], "ascii") == 0)
                r->format = F_ASCII;
            else if (strcmp(w[1], "binary_little_endian") == 0)
                r->format = F_LITTLE;
            else if (strcmp(w[1], "binary_big_endian") == 0)
                r->format = F_BIG;
            else
                return fail(r, SK_ERROR_PARSE,
                            "unknown format \"%.40s\" (ascii, binary_little_endian or "
                            "binary_big_endian)",
                            w[1]);
            if (strcmp(w[2], "1.0") != 0)
                return fail(r, SK_ERROR_UNSUPPORTED, "PLY version \"%.20s\" (only 1.0)", w[2]);
            have_format = true;
            continue;
        }
        if (!have_format) return fail(r, SK_ERROR_PARSE, "\"%.40s\" before the format line", w[0]);
        if (strcmp(w[0], "element") == 0)
            res = header_element(r, w, n);
        else if (strcmp(w[0], "property") == 0)
            res = header_property(r, w, n);
        else
            return fail(r, SK_ERROR_PARSE, "unknown header keyword \"%.40s\"", w[0]);
        if (res != SK_OK) return res;
    }
    if (!have_format) return fail(r, SK_ERROR_PARSE, "no format line");
    r->in_header = false;
    r->line++; /* the body starts on the line after end_header */
    return SK_OK;
}

/* ------------------------------------------------------------------ roles */

static ply_property *find_prop(ply_element *e, const char *name)
{
    for (int i = 0; i < e->prop_count; i++)
        if (strcmp(e->props[i].name, name) == 0 && e->props[i].count_type == T_NONE)
            return &e->props[i];
    return NULL;
}

/* Gives roles to all three properties of a group if all are scalars; true if it did. */
static bool claim(ply_element *e, const char *const *names, const role *roles, int count)
{
    ply_property *p[3];
    for (int i = 0; i < count; i++)
        if (!(p[i] = find_prop(e, names[i])) || p[i]->role != R_SKIP) return false;
    for (int i = 0; i < count; i++) p[i]->role = roles[i];
    return true;
}

/* Length of the run "<base>_0", "<base>_1", ... starting at property i (1 if none). */
static int component_run(const ply_element *e, int i, size_t *base_len)
{
    const char *name = e->props[i].name;
    size_t len = strlen(name);
    if (len < 3 || strcmp(name + len - 2, "_0") != 0) return 1;
    *base_len = len - 2;
    int run = 1;
    while (i + run < e->prop_count && run < 5) {
        const ply_property *q = &e->props[i + run];
        if (q->role != R_SKIP || q->count_type != T_NONE || strlen(q->name) != len ||
            strncmp(q->name, name, *base_len) != 0 || q->name[len - 2] != '_' ||
            q->name[len - 1] != (char)('0' + run))
            break;
        run++;
    }
    return run >= 2 && run <= 4 ? run : 1;
}

static sk_result assign_roles(ply_reader *r)
{
    r->vertex_element = r->face_element = -1;
    for (int i = 0; i < r->element_count; i++) {
        if (strcmp(r->elements[i].name, "vertex") == 0) r->vertex_element = i;
        if (strcmp(r->elements[i].name, "face") == 0) r->face_element = i;
    }
    if (r->face_element >= 0) {
        ply_element *f = &r->elements[r->face_element];
        ply_property *list = NULL;
        for (int i = 0; i < f->prop_count && !list; i++)
            if (strcmp(f->props[i].name, "vertex_indices") == 0 ||
                strcmp(f->props[i].name, "vertex_index") == 0)
                list = &f->props[i];
        if (!list || list->count_type == T_NONE || !is_integer_type(list->type))
            return fail(r, SK_ERROR_PARSE,
                        "element \"face\" has no integer list property vertex_indices");
        list->role = R_FACE;
        if (r->vertex_element < 0 && f->count > 0)
            return fail(r, SK_ERROR_PARSE, "faces but no element \"vertex\"");
    }
    if (r->vertex_element < 0) return SK_OK;
    ply_element *v = &r->elements[r->vertex_element];
    static const char *const xyz[3] = {"x", "y", "z"}, *const nxyz[3] = {"nx", "ny", "nz"},
                             *const rgb[3] = {"red", "green", "blue"};
    static const char *const uv_names[4][2] = {
        {"u", "v"}, {"s", "t"}, {"texture_u", "texture_v"}, {"texture_s", "texture_t"}};
    static const role pos_roles[3] = {R_X, R_Y, R_Z}, nrm_roles[3] = {R_NX, R_NY, R_NZ},
                      col_roles[3] = {R_RED, R_GREEN, R_BLUE}, uv_roles[2] = {R_U, R_V};
    if (!claim(v, xyz, pos_roles, 3))
        return fail(r, SK_ERROR_PARSE, "element \"vertex\" lacks scalar properties x, y and z");
    r->normals = claim(v, nxyz, nrm_roles, 3);
    for (int k = 0; k < 4 && !r->uvs; k++) r->uvs = claim(v, uv_names[k], uv_roles, 2);
    r->colors = claim(v, rgb, col_roles, 3);
    /* Every other scalar becomes an attribute; "<name>_0".."<name>_k" runs of 2-4 are one
       attribute with k + 1 components (the writer's form for vector attributes). */
    for (int i = 0; i < v->prop_count && r->attribute_count < SK_MESH_MAX_ATTRIBUTES; i++) {
        ply_property *p = &v->props[i];
        if (p->role != R_SKIP || p->count_type != T_NONE) continue;
        size_t len = strlen(p->name);
        int run = component_run(v, i, &len);
        /* Names are cut to the attribute name size; a name that then repeats is skipped. */
        char *name = r->attr_names[r->attribute_count];
        if (len >= SK_MESH_ATTRIBUTE_NAME_SIZE) len = SK_MESH_ATTRIBUTE_NAME_SIZE - 1;
        memcpy(name, p->name, len);
        name[len] = '\0';
        bool repeated = false;
        for (int a = 0; a < r->attribute_count; a++)
            repeated |= strcmp(r->attr_names[a], name) == 0;
        if (!repeated) {
            for (int k = 0; k < run; k++) {
                v->props[i + k].role = R_ATTR;
                v->props[i + k].attr = r->attribute_count;
                v->props[i + k].component = k;
            }
            r->attr_components[r->attribute_count++] = run;
        }
        i += run - 1;
    }
    return SK_OK;
}

/* ------------------------------------------------------------------ sizes and caps */

/* Smallest number of bytes one record of `e` can take in the body. */
static uint64_t min_record_bytes(const ply_reader *r, const ply_element *e)
{
    uint64_t bytes = 0;
    for (int i = 0; i < e->prop_count; i++) {
        const ply_property *p = &e->props[i];
        /* A list counts as its count alone, so that a too-short face list is reported
           as such rather than as a size mismatch. */
        if (r->format == F_ASCII)
            bytes += 2; /* "0 " */
        else
            bytes += (uint64_t)type_size[p->count_type != T_NONE ? p->count_type : p->type];
    }
    return bytes;
}

static sk_result check_counts(ply_reader *r)
{
    uint64_t left = bytes_left(r) + (r->format == F_ASCII ? 1 : 0); /* last separator */
    uint64_t total = 0;
    for (int i = 0; i < r->element_count; i++) {
        ply_element *e = &r->elements[i];
        uint64_t each = min_record_bytes(r, e);
        if (e->count > 0 && each == 0)
            return fail(r, SK_ERROR_PARSE, "element \"%s\" has records but no properties", e->name);
        if (each && e->count > (left - total) / each)
            return fail(r, SK_ERROR_PARSE,
                        "element \"%s\" claims %llu records, but the %llu bytes after the header "
                        "hold at most %llu",
                        e->name, (unsigned long long)e->count, (unsigned long long)bytes_left(r),
                        (unsigned long long)((left - total) / each));
        total += e->count * each;
    }
    size_t vertex_count = r->vertex_element >= 0 ? (size_t)r->elements[r->vertex_element].count : 0;
    size_t face_count = r->face_element >= 0 ? (size_t)r->elements[r->face_element].count : 0;
    size_t attr_floats = 0;
    if (r->vertex_element >= 0) {
        const ply_element *v = &r->elements[r->vertex_element];
        for (int i = 0; i < v->prop_count; i++) attr_floats += v->props[i].role == R_ATTR;
    }
    int flags = (r->normals ? SK_MESH_NORMALS : 0) | (r->uvs ? SK_MESH_UVS : 0) |
                (r->colors ? SK_MESH_COLORS : 0);
    size_t bytes;
    if (vertex_count > UINT32_MAX ||
        !sk__mesh_bytes(vertex_count, face_count, flags, attr_floats, &bytes) ||
        bytes > r->budget.max)
        return fail(r, SK_ERROR_LIMIT,
                    "%zu vertices and %zu faces need more memory than the cap of %zu bytes",
                    vertex_count, face_count, r->budget.max);
    return SK_OK;
}

/* ------------------------------------------------------------------ values */

/* Reads an ASCII token into buf. Sets *line_break when a newline preceded it. */
static sk_result ascii_token(ply_reader *r, char *buf, size_t cap, size_t *len, bool *line_break)
{
    *line_break = false;
    int c;
    for (;;) {
        c = next_byte(r);
        if (c < 0) return fail_record(r, SK_ERROR_PARSE, "unexpected end of file");
        if (c == '\n') {
            r->line++;
            *line_break = true;
        } else if (c != ' ' && c != '\t' && c != '\r') {
            break;
        }
    }
    size_t n = 0;
    while (c >= 0 && c != ' ' && c != '\t' && c != '\r' && c != '\n') {
        if (n + 1 >= cap) return fail_record(r, SK_ERROR_PARSE, "value is too long");
        buf[n++] = (char)c;
        if (!need(r, 1)) break;
        c = r->buf[r->pos]; /* peek: white space stays for the next token's line count */
        if (c == ' ' || c == '\t' || c == '\r' || c == '\n') break;
        r->pos++;
        r->consumed++;
    }
    buf[n] = '\0';
    *len = n;
    return SK_OK;
}

/* Reads one value of type t. `first` marks a record's first value, which must start a
 * new line in ASCII (except the very first record of the body); others must not. */
static sk_result read_value(ply_reader *r, ply_type t, bool first, double *out)
{
    if (r->format == F_ASCII) {
        char tok[128];
        size_t len = 0;
        bool line_break;
        bool at_start = !r->body_started;
        sk_result res = ascii_token(r, tok, sizeof tok, &len, &line_break);
        if (res != SK_OK) return res;
        r->body_started = true;
        /* Both faults belong to the line of the previous value. */
        if (first && !line_break && !at_start)
            return fail(r, SK_ERROR_PARSE, "%s %llu: line has more values than properties",
                        r->done_what, (unsigned long long)r->done_record);
        if (!first && line_break) {
            r->line = r->token_line;
            return fail_record(r, SK_ERROR_PARSE, "line has fewer values than properties");
        }
        r->token_line = r->line;
        if (is_integer_type(t)) {
            long long v;
            if (!sk__parse_int64(tok, len, &v))
                return fail_record(r, SK_ERROR_PARSE, "integer value expected");
            static const long long lo[] = {0, -128, 0, -32768, 0, -2147483648LL, 0};
            static const long long hi[] = {0, 127, 255, 32767, 65535, 2147483647LL, 4294967295LL};
            if (v < lo[t] || v > hi[t])
                return fail_record(r, SK_ERROR_PARSE, "integer value out of range for its type");
            *out = (double)v;
        } else if (!sk__parse_double(tok, len, out)) {
            return fail_record(r, SK_ERROR_PARSE, "number expected");
        } else if (t == T_FLOAT32 && isfinite(*out) && fabs(*out) > FLT_MAX) {
            return fail_record(r, SK_ERROR_PARSE, "value out of float range");
        }
        return SK_OK;
    }
    int size = type_size[t];
    if (!need(r, (size_t)size)) return fail_record(r, SK_ERROR_PARSE, "file is truncated");
    const unsigned char *b = r->buf + r->pos;
    uint64_t bits = 0;
    for (int i = 0; i < size; i++) {
        int shift = r->format == F_LITTLE ? 8 * i : 8 * (size - 1 - i);
        bits |= (uint64_t)b[i] << shift;
    }
    r->pos += (size_t)size;
    r->consumed += (uint64_t)size;
    switch (t) {
    case T_INT8:
        *out = (int8_t)(uint8_t)bits;
        break;
    case T_UINT8:
        *out = (uint8_t)bits;
        break;
    case T_INT16:
        *out = (int16_t)(uint16_t)bits;
        break;
    case T_UINT16:
        *out = (uint16_t)bits;
        break;
    case T_INT32:
        *out = (int32_t)(uint32_t)bits;
        break;
    case T_UINT32:
        *out = (uint32_t)bits;
        break;
    case T_FLOAT32: {
        uint32_t u = (uint32_t)bits;
        float f;
        memcpy(&f, &u, sizeof f);
        *out = f;
        break;
    }
    case T_FLOAT64:
        memcpy(out, &bits, sizeof *out);
        break;
    case T_NONE:
        break;
    }
    return SK_OK;
}

/* ------------------------------------------------------------------ elements */

static sk_result store_vertex_value(ply_reader *r, const ply_property *p, size_t i, double v)
{
    sk_mesh *m = r->mesh;
    if (!isfinite(v)) {
        char what[96];
        snprintf(what, sizeof what, "%s is not a finite number", p->name);
        return fail_record(r, SK_ERROR_PARSE, what);
    }
    /* every value is stored as float: a double beyond its range would become inf */
    if (fabs(v) > FLT_MAX) {
        char what[96];
        snprintf(what, sizeof what, "%s is out of float range", p->name);
        return fail_record(r, SK_ERROR_PARSE, what);
    }
    switch (p->role) {
    case R_X:
    case R_Y:
    case R_Z:
        m->positions[3 * i + (size_t)(p->role - R_X)] = (float)v;
        break;
    case R_NX:
    case R_NY:
    case R_NZ:
        m->normals[3 * i + (size_t)(p->role - R_NX)] = (float)v;
        break;
    case R_U:
    case R_V:
        m->uvs[2 * i + (size_t)(p->role - R_U)] = (float)v;
        break;
    case R_RED:
    case R_GREEN:
    case R_BLUE:
        /* stored sRGB-encoded, as tools write them; linear in memory */
        m->colors[3 * i + (size_t)(p->role - R_RED)] =
            (float)sk__srgb_decode(v / type_max[p->type]);
        break;
    case R_ATTR: {
        sk_mesh_attribute *a = &m->attributes[p->attr];
        a->data[i * (size_t)a->components + (size_t)p->component] = (float)v;
        break;
    }
    default:
        break;
    }
    return SK_OK;
}

static sk_result read_list(ply_reader *r, const ply_property *p, bool first, size_t vertex_count)
{
    double count_d;
    sk_result res = read_value(r, p->count_type, first, &count_d);
    if (res != SK_OK) return res;
    if (count_d < 0) return fail_record(r, SK_ERROR_PARSE, "list has a negative count");
    uint64_t count = (uint64_t)count_d;
    uint64_t item_bytes = r->format == F_ASCII ? 2 : (uint64_t)type_size[p->type];
    if (count > (bytes_left(r) + 1) / item_bytes) {
        char what[128];
        snprintf(what, sizeof what,
                 "file is truncated (a list of %llu items does not fit in "
                 "the %llu bytes left)",
                 (unsigned long long)count, (unsigned long long)bytes_left(r));
        return fail_record(r, SK_ERROR_PARSE, what);
    }
    if (p->role != R_FACE) {
        for (uint64_t k = 0; k < count && res == SK_OK; k++)
            res = read_value(r, p->type, false, &count_d);
        return res;
    }
    if (count < 3) {
        char what[64];
        snprintf(what, sizeof what, "face has %llu vertices (at least 3 needed)",
                 (unsigned long long)count);
        return fail_record(r, SK_ERROR_PARSE, what);
    }
    if (count > UINT32_MAX) return fail_record(r, SK_ERROR_LIMIT, "face has too many vertices");
    res = sk__array_reserve(&r->corners, (size_t)count, &r->budget);
    if (res == SK_OK) res = sk__array_reserve(&r->sizes, 1, &r->budget);
    if (res != SK_OK)
        return fail_record(r, res,
                           res == SK_ERROR_LIMIT ? "faces exceed the memory cap" : "out of memory");
    uint32_t *dst = (uint32_t *)r->corners.data + r->corners.count;
    for (uint64_t k = 0; k < count; k++) {
        double idx;
        res = read_value(r, p->type, false, &idx);
        if (res != SK_OK) return res;
        if (idx < 0 || idx >= (double)vertex_count) {
            char what[128];
            snprintf(what, sizeof what, "vertex index %.0f is out of range (vertex count %zu)", idx,
                     vertex_count);
            return fail_record(r, SK_ERROR_PARSE, what);
        }
        dst[k] = (uint32_t)idx;
    }
    r->corners.count += (size_t)count;
    ((uint32_t *)r->sizes.data)[r->sizes.count++] = (uint32_t)count;
    r->triangle_total += count - 2;
    return SK_OK;
}

static sk_result read_element(ply_reader *r, int index)
{
    ply_element *e = &r->elements[index];
    bool is_vertex = index == r->vertex_element;
    r->what = is_vertex ? "vertex" : index == r->face_element ? "face" : e->name;
    size_t vertex_count = r->vertex_element >= 0 ? (size_t)r->elements[r->vertex_element].count : 0;
    sk_result res = SK_OK;
    for (uint64_t i = 0; i < e->count && res == SK_OK; i++) {
        r->record = i;
        for (int k = 0; k < e->prop_count && res == SK_OK; k++) {
            const ply_property *p = &e->props[k];
            if (p->count_type != T_NONE) {
                res = read_list(r, p, k == 0, vertex_count);
                continue;
            }
            double v;
            res = read_value(r, p->type, k == 0, &v);
            if (res == SK_OK && is_vertex && p->role != R_SKIP)
                res = store_vertex_value(r, p, (size_t)i, v);
        }
        r->done_what = r->what;
        r->done_record = i;
    }
    return res;
}

static sk_result check_trailing(ply_reader *r)
{
    if (r->format != F_ASCII) {
        if (bytes_left(r) != 0)
            return fail(r, SK_ERROR_PARSE, "%llu bytes of trailing data after the last element",
                        (unsigned long long)bytes_left(r));
        return SK_OK;
    }
    for (int c; (c = next_byte(r)) >= 0;) {
        if (c == '\n')
            r->line++;
        else if (c != ' ' && c != '\t' && c != '\r')
            return fail(r, SK_ERROR_PARSE, "trailing data after the last element");
    }
    return SK_OK;
}

/* ------------------------------------------------------------------ mesh */

static sk_result create_mesh(ply_reader *r)
{
    size_t vertex_count = r->vertex_element >= 0 ? (size_t)r->elements[r->vertex_element].count : 0;
    int flags = (r->normals ? SK_MESH_NORMALS : 0) | (r->uvs ? SK_MESH_UVS : 0) |
                (r->colors ? SK_MESH_COLORS : 0);
    sk_result res = sk__mesh_create_capped(r->mesh, vertex_count, 0, flags, r->budget.max, r->err);
    if (res != SK_OK) return sk_error_prefix(r->err, res, "%s", r->path);
    size_t bytes;
    sk__mesh_bytes(vertex_count, 0, flags, 0, &bytes);
    r->budget.used += bytes;
    for (int a = 0; a < r->attribute_count; a++) {
        res = sk_mesh_add_attribute(r->mesh, r->attr_names[a], r->attr_components[a], NULL, r->err);
        if (res != SK_OK) return sk_error_prefix(r->err, res, "%s", r->path);
        r->budget.used += vertex_count * (size_t)r->attr_components[a] * sizeof(float);
    }
    return SK_OK;
}

static sk_result triangulate_faces(ply_reader *r)
{
    sk_mesh *m = r->mesh;
    if (r->triangle_total == 0) return SK_OK;
    size_t bytes;
    if (r->triangle_total > SIZE_MAX / 12 ||
        !sk_size_mul((size_t)r->triangle_total, 3 * sizeof(uint32_t), &bytes) ||
        r->budget.used + bytes > r->budget.max)
        return fail(r, SK_ERROR_LIMIT, "%llu triangles exceed the memory cap of %zu bytes",
                    (unsigned long long)r->triangle_total, r->budget.max);
    m->indices = malloc(bytes);
    if (!m->indices) return fail(r, SK_ERROR_OUT_OF_MEMORY, "out of memory for triangles");
    m->triangle_count = (size_t)r->triangle_total;
    sk__triangulator tri = {0};
    uint32_t local_small[3 * 64];
    uint32_t *local = local_small;
    size_t local_cap = 64;
    const uint32_t *corners = r->corners.data, *sizes = r->sizes.data;
    uint32_t *out = m->indices;
    sk_result res = SK_OK;
    for (size_t f = 0; f < r->sizes.count && res == SK_OK; f++) {
        size_t n = sizes[f];
        if (n - 2 > local_cap) {
            uint32_t *grown = local == local_small ? malloc(3 * (n - 2) * sizeof *grown)
                                                   : realloc(local, 3 * (n - 2) * sizeof *grown);
            if (!grown) {
                res = fail(r, SK_ERROR_OUT_OF_MEMORY, "out of memory triangulating faces");
                break;
            }
            local = grown;
            local_cap = n - 2;
        }
        if (sk__triangulate(&tri, m->positions, corners, n, local) != SK_OK) {
            res = fail(r, SK_ERROR_OUT_OF_MEMORY, "out of memory triangulating faces");
            break;
        }
        for (size_t k = 0; k < 3 * (n - 2); k++) out[k] = corners[local[k]];
        out += 3 * (n - 2);
        corners += n;
    }
    if (local != local_small) free(local);
    sk__triangulator_free(&tri);
    return res;
}

static sk_result read_ply(ply_reader *r)
{
    sk_result res = read_header(r);
    if (res == SK_OK) res = assign_roles(r);
    if (res == SK_OK) res = check_counts(r);
    if (res == SK_OK) res = create_mesh(r);
    for (int i = 0; i < r->element_count && res == SK_OK; i++) res = read_element(r, i);
    if (res == SK_OK) res = check_trailing(r);
    if (res == SK_OK) res = triangulate_faces(r);
    if (res == SK_OK && r->mesh->normals) {
        /* Files carry normals of any length; the mesh promises unit ones. */
        float *n = r->mesh->normals;
        for (size_t i = 0; i < r->mesh->vertex_count; i++, n += 3) {
            double len = sqrt((double)n[0] * n[0] + (double)n[1] * n[1] + (double)n[2] * n[2]);
            if (len > 0.0)
                for (int k = 0; k < 3; k++) n[k] = (float)(n[k] / len);
        }
    }
    return res;
}

sk_result sk_mesh_read_ply(sk_mesh *mesh, const char *path, const sk_mesh_read_desc *desc,
                           sk_error *err)
{
    if (!mesh || !path)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "mesh and path must not be NULL");
    memset(mesh, 0, sizeof *mesh);
    FILE *fp;
    long long file_size;
    sk_result opened = sk_open_regular_file(path, &fp, &file_size, err);
    if (opened != SK_OK) return opened;
    ply_reader *r = calloc(1, sizeof *r);
    if (!r) {
        fclose(fp);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    }
    r->path = path;
    r->err = err;
    r->fp = fp;
    r->file_size = (uint64_t)file_size;
    r->mesh = mesh;
    r->budget.max = sk__mesh_read_cap(desc);
    r->corners.elem = r->sizes.elem = sizeof(uint32_t);
    sk__c_locale locale;
    sk__c_locale_push(&locale);
    sk_result res = read_ply(r);
    sk__c_locale_pop(&locale);
    if (res == SK_OK && ferror(fp)) res = sk_fail(err, SK_ERROR_IO, "%s: read failed", path);
    sk__array_free(&r->corners);
    sk__array_free(&r->sizes);
    free(r);
    fclose(fp);
    if (res != SK_OK) sk_mesh_free(mesh);
    return res;
}
