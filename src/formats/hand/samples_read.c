/* Joint-angle samples from CSV (the measured angle pairs of thesis 3.2.2 and 3.2.3): a
 * header of DOF names, then one sample per line in degrees or radians (mm for
 * translations), with an optional column naming the trial or person of each sample. */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "models/hand/hand_internal.h"
#include "shitsukan/hand.h"
#include "shitsukan/io.h"

void sk_hand_samples_free(sk_hand_samples *s)
{
    if (!s) return;
    for (int i = 0; i < SK_HAND_DOF_COUNT; i++) free(s->column[i]);
    free(s->group);
    free(s->group_name);
    memset(s, 0, sizeof *s);
}

/* Next field of a line: trims blanks, stops at ',' or the end. Sets *too_long when the
 * field does not fit `cap`. */
static const char *next_field(const char *p, const char *end, char *buf, size_t cap, bool *more,
                              bool *too_long)
{
    while (p < end && (*p == ' ' || *p == '\t')) p++;
    const char *start = p;
    while (p < end && *p != ',') p++;
    const char *stop = p;
    while (stop > start && (stop[-1] == ' ' || stop[-1] == '\t' || stop[-1] == '\r')) stop--;
    size_t n = (size_t)(stop - start);
    *too_long = n >= cap;
    if (n >= cap) n = cap - 1;
    memcpy(buf, start, n);
    buf[n] = '\0';
    *more = p < end && *p == ',';
    return p < end ? p + 1 : p;
}

/* Next name of a comma-separated list (blanks around names ignored): sets *name and
 * *len and returns the rest, or NULL at the end. */
static const char *next_list_name(const char *p, const char **name, size_t *len)
{
    if (!p || !*p) return NULL;
    while (*p == ' ') p++;
    size_t n = strcspn(p, ",");
    size_t m = n;
    while (m > 0 && p[m - 1] == ' ') m--;
    *name = p;
    *len = m;
    p += n;
    return *p == ',' ? p + 1 : p;
}

/* Whether `name` is one of the comma-separated names in `list`. */
static bool in_list(const char *list, const char *name)
{
    size_t want = strlen(name), len;
    const char *item;
    for (const char *p = list; (p = next_list_name(p, &item, &len)) != NULL;)
        if (len == want && strncmp(item, name, len) == 0) return true;
    return false;
}

#define MAX_COLUMNS 64
#define COL_IGNORED (-1)
#define COL_GROUP (-2)

/* The group number of a value, adding it if new. */
static sk_result group_of(sk_hand_samples *out, const char *value, int *cap, int line_no, int *g,
                          sk_error *err)
{
    for (int i = out->group_count - 1; i >= 0; i--)
        if (strcmp(out->group_name[i], value) == 0) {
            *g = i;
            return SK_OK;
        }
    if (out->group_count >= SK_HAND_SAMPLES_MAX_GROUPS)
        return sk_fail(err, SK_ERROR_LIMIT, "line %d: more than %d distinct groups", line_no,
                       SK_HAND_SAMPLES_MAX_GROUPS);
    if (out->group_count == *cap) {
        int ncap = *cap ? *cap * 2 : 16;
        char(*grown)[64] = realloc(out->group_name, (size_t)ncap * sizeof *grown);
        if (!grown) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
        out->group_name = grown;
        *cap = ncap;
    }
    snprintf(out->group_name[out->group_count], sizeof out->group_name[0], "%s", value);
    *g = out->group_count++;
    return SK_OK;
}

/* Checks that every name in a comma-separated list appeared in the header. */
static sk_result check_listed_columns(const char *list, char (*header)[128], int ncol,
                                      const char *what, sk_error *err)
{
    const char *item;
    size_t m;
    for (const char *p = list; (p = next_list_name(p, &item, &m)) != NULL;) {
        bool found = m == 0;
        for (int c = 0; c < ncol && !found; c++)
            found = strlen(header[c]) == m && strncmp(header[c], item, m) == 0;
        if (!found)
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "%s \"%.*s\" is not a column of the header", what,
                           (int)(m < 64 ? m : 64), item);
    }
    return SK_OK;
}

/* Unit check over the rotational columns: degrees that never leave +-pi look like
 * radians; radians beyond 2 pi look like degrees. */
static void check_units(sk_hand_samples *out, sk_hand_angle_unit units)
{
    double max_abs = 0.0, max_range = 0.0;
    for (int d = 0; d < SK_HAND_DOF_COUNT; d++) {
        if (!out->present[d] || sk_hand_dof(d)->translation) continue;
        double lo = INFINITY, hi = -INFINITY;
        for (int i = 0; i < out->count; i++) {
            double v = out->column[d][i];
            lo = fmin(lo, v);
            hi = fmax(hi, v);
            max_abs = fmax(max_abs, fabs(v));
        }
        max_range = fmax(max_range, hi - lo);
    }
    out->max_abs_angle = max_abs;
    if (units == SK_HAND_UNIT_RAD) out->units_suspect = max_abs > 2.0 * SK_PI;
    /* read as degrees: every value within +-3.2 deg while something moves by more than a
       hundredth of that is a recording in radians */
    else
        out->units_suspect = max_abs <= 3.2 * SK_DEG_TO_RAD && max_range > 0.03 * SK_DEG_TO_RAD;
}

/* The desc with its default unit (degrees), checked. */
static sk_result samples_settings(const sk_hand_samples_desc *desc, sk_hand_samples_desc *d,
                                  sk_error *err)
{
    *d = (sk_hand_samples_desc){0};
    if (desc) *d = *desc;
    if (d->units == SK_HAND_UNIT_DEFAULT) d->units = SK_HAND_UNIT_DEG;
    if (d->units != SK_HAND_UNIT_DEG && d->units != SK_HAND_UNIT_RAD)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "units = %d is not deg or rad",
                       (int)d->units);
    if (d->group_column && (!d->group_column[0] || strlen(d->group_column) > 127))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "group column name must have 1 to 127 characters");
    return SK_OK;
}

/* The reader's state: the header's columns and the samples' capacity so far. */
typedef struct csv_reader {
    const sk_hand_samples_desc *d;
    sk_hand_samples *out;
    int col_dof[MAX_COLUMNS];
    char (*header)[128];
    int ncol, cap, group_cap;
    bool want_group;
} csv_reader;

/* One header name (column ncol + 1): its DOF, the group column or an ignored one, checked
 * against the names before it. */
static sk_result header_column(csv_reader *c, const char *field, int line_no, bool *group_found,
                               sk_error *err)
{
    sk_result r = SK_OK;
    for (int k = 0; k < c->ncol && r == SK_OK; k++)
        if (strcmp(c->header[k], field) == 0)
            r = sk_fail(err, SK_ERROR_PARSE, "line %d, column %d: \"%s\" appears twice", line_no,
                        c->ncol + 1, field);
    if (r != SK_OK) return r;
    snprintf(c->header[c->ncol], sizeof c->header[0], "%s", field);
    int dof = COL_IGNORED;
    if (c->want_group && strcmp(field, c->d->group_column) == 0) {
        dof = COL_GROUP;
        *group_found = true;
    } else if (strcmp(field, "frame") != 0 && strcmp(field, "time") != 0 &&
               !in_list(c->d->ignore_columns, field)) {
        dof = sk_hand_dof_find(field);
        if (dof < 0)
            return sk_fail(err, SK_ERROR_PARSE,
                           "line %d, column %d: unknown DOF \"%s\" (names like \"L.MCP.flex\"; "
                           "\"frame\" and \"time\" are ignored, others with --ignore-columns)",
                           line_no, c->ncol + 1, field);
        c->out->present[dof] = true;
    }
    c->col_dof[c->ncol++] = dof;
    return SK_OK;
}

/* The header line (from q to eol): its columns, then the group column, the ignored columns
 * and at least one DOF checked. */
static sk_result read_header(csv_reader *c, const char *q, const char *eol, int line_no,
                             sk_error *err)
{
    char field[128];
    bool more = true, too_long = false, group_found = false;
    sk_result r = SK_OK;
    while (more && r == SK_OK) {
        q = next_field(q, eol, field, sizeof field, &more, &too_long);
        if (c->ncol >= MAX_COLUMNS)
            return sk_fail(err, SK_ERROR_LIMIT, "line %d: more than %d columns", line_no,
                           MAX_COLUMNS);
        if (too_long)
            return sk_fail(err, SK_ERROR_PARSE,
                           "line %d, column %d: header name longer than %d characters", line_no,
                           c->ncol + 1, (int)sizeof field - 1);
        r = header_column(c, field, line_no, &group_found, err);
    }
    if (r == SK_OK && c->want_group && !group_found)
        r = sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "group column \"%s\" is not in the header",
                    c->d->group_column);
    if (r == SK_OK)
        r = check_listed_columns(c->d->ignore_columns, c->header, c->ncol, "ignored column", err);
    if (r == SK_OK) {
        bool any = false;
        for (int dof = 0; dof < SK_HAND_DOF_COUNT; dof++) any |= c->out->present[dof];
        if (!any)
            r = sk_fail(err, SK_ERROR_PARSE, "line %d: no DOF columns in the header", line_no);
    }
    return r;
}

/* Room for more samples: the columns (and groups) doubled, up to 10000000 samples. */
static sk_result grow_samples(csv_reader *c, int line_no, sk_error *err)
{
    sk_hand_samples *out = c->out;
    sk_result r = SK_OK;
    int ncap = c->cap ? c->cap * 2 : 256;
    if (ncap > 10000000)
        return sk_fail(err, SK_ERROR_LIMIT, "line %d: more than 10000000 samples", line_no);
    for (int dof = 0; dof < SK_HAND_DOF_COUNT && r == SK_OK; dof++) {
        if (!out->present[dof]) continue;
        double *grown = realloc(out->column[dof], (size_t)ncap * sizeof(double));
        if (!grown)
            r = sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
        else
            out->column[dof] = grown;
    }
    if (r == SK_OK && c->want_group) {
        int *grown = realloc(out->group, (size_t)ncap * sizeof(int));
        if (!grown)
            r = sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
        else
            out->group = grown;
    }
    c->cap = ncap;
    return r;
}

/* One field of a sample (column col + 1): its group, nothing for an ignored column, or its
 * value (radians for angles) into its DOF's column. */
static sk_result sample_field(csv_reader *c, int col, const char *field, bool too_long, int line_no,
                              sk_error *err)
{
    sk_hand_samples *out = c->out;
    if (c->col_dof[col] == COL_GROUP) {
        if (field[0] == '\0' || too_long || strlen(field) > 63)
            return sk_fail(err, SK_ERROR_PARSE,
                           "line %d, column %d (%s): a group value needs 1 to 63 characters",
                           line_no, col + 1, c->header[col]);
        return group_of(out, field, &c->group_cap, line_no, &out->group[out->count], err);
    }
    if (c->col_dof[col] == COL_IGNORED && in_list(c->d->ignore_columns, c->header[col]))
        return SK_OK;
    char *stop = NULL;
    errno = 0;
    double v = too_long ? NAN : strtod(field, &stop);
    if (too_long || field[0] == '\0' || *stop != '\0' || errno == ERANGE || !isfinite(v) ||
        fabs(v) > 1e6)
        return sk_fail(err, SK_ERROR_PARSE,
                       "line %d, column %d (%s): \"%.40s\" is not a number in [-1e6, 1e6]", line_no,
                       col + 1, c->header[col], field);
    int dof = c->col_dof[col];
    if (dof >= 0)
        out->column[dof][out->count] = sk_hand_dof(dof)->translation     ? v
                                       : c->d->units == SK_HAND_UNIT_RAD ? v
                                                                         : v * SK_DEG_TO_RAD;
    return SK_OK;
}

/* One sample line (from q to eol): every field, as many as the header's. */
static sk_result read_sample(csv_reader *c, const char *q, const char *eol, int line_no,
                             sk_error *err)
{
    char field[128];
    bool more = true, too_long = false;
    sk_result r = SK_OK;
    int col = 0;
    while (more && r == SK_OK) {
        q = next_field(q, eol, field, sizeof field, &more, &too_long);
        if (col >= c->ncol)
            return sk_fail(err, SK_ERROR_PARSE, "line %d: more than the header's %d fields",
                           line_no, c->ncol);
        r = sample_field(c, col, field, too_long, line_no, err);
        if (r != SK_OK) return r;
        col++;
    }
    if (col != c->ncol)
        r = sk_fail(err, SK_ERROR_PARSE, "line %d: %d fields, the header has %d", line_no, col,
                    c->ncol);
    if (r == SK_OK) c->out->count++;
    return r;
}

sk_result sk_hand_samples_parse_desc(const char *text, size_t length, const char *name,
                                     const sk_hand_samples_desc *desc, sk_hand_samples *out,
                                     sk_error *err)
{
    memset(out, 0, sizeof *out);
    sk_hand_samples_desc d;
    sk_result r = samples_settings(desc, &d, err);
    if (r != SK_OK) return r;
    csv_reader c = {.d = &d, .out = out, .want_group = d.group_column != NULL};
    c.header = calloc(MAX_COLUMNS, sizeof *c.header);
    if (!c.header) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    int line_no = 0;
    bool have_header = false;
    const char *p = text, *end = text + length;
    while (p < end && r == SK_OK) {
        const char *eol = memchr(p, '\n', (size_t)(end - p));
        if (!eol) eol = end;
        line_no++;
        const char *q = p;
        p = eol < end ? eol + 1 : end;
        while (q < eol && (*q == ' ' || *q == '\t' || *q == '\r')) q++;
        if (q == eol || *q == '#') continue; /* blank or comment */
        if (!have_header) {
            have_header = true;
            r = read_header(&c, q, eol, line_no, err);
            continue;
        }
        if (out->count >= c.cap) r = grow_samples(&c, line_no, err);
        if (r == SK_OK) r = read_sample(&c, q, eol, line_no, err);
    }
    free(c.header);
    if (r == SK_OK && !have_header) r = sk_fail(err, SK_ERROR_PARSE, "no header line of DOF names");
    if (r == SK_OK && out->count == 0)
        r = sk_fail(err, SK_ERROR_PARSE, "no samples after the header");
    if (r == SK_OK) check_units(out, d.units);
    if (r != SK_OK) {
        sk_hand_samples_free(out);
        sk_error_prefix(err, r, "%s", name);
    }
    return r;
}

sk_result sk_hand_samples_parse(const char *text, size_t length, const char *name,
                                sk_hand_samples *out, sk_error *err)
{
    return sk_hand_samples_parse_desc(text, length, name, NULL, out, err);
}

sk_result sk_hand_samples_read(const char *path, const sk_hand_samples_desc *desc,
                               sk_hand_samples *out, sk_error *err)
{
    char *text = NULL;
    size_t size = 0;
    memset(out, 0, sizeof *out);
    sk_result r = sk_read_file(path, SK_HAND_MAX_FILE_BYTES, &text, &size, err);
    if (r != SK_OK) return r;
    r = sk_hand_samples_parse_desc(text, size, path, desc, out, err);
    free(text);
    return r;
}

sk_result sk_hand_samples_load_file(const char *path, sk_hand_samples *out, sk_error *err)
{
    return sk_hand_samples_read(path, NULL, out, err);
}

sk_result sk_hand_parse_pairs(const char *text, int (*pairs)[2], int max_pairs, int *count,
                              sk_error *err)
{
    *count = 0;
    const char *p = text;
    while (*p) {
        const char *comma = strchr(p, ',');
        size_t n = comma ? (size_t)(comma - p) : strlen(p);
        char item[140];
        if (n >= sizeof item)
            return sk_fail(err, SK_ERROR_PARSE, "pair \"%.40s...\" is too long", p);
        memcpy(item, p, n);
        item[n] = '\0';
        char *colon = strchr(item, ':');
        if (!colon) return sk_fail(err, SK_ERROR_PARSE, "pair \"%s\": expected DOF:DOF", item);
        *colon = '\0';
        int x = sk_hand_dof_find(item), y = sk_hand_dof_find(colon + 1);
        if (x < 0)
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "pair \"%s:%s\": unknown DOF \"%s\"",
                           item, colon + 1, item);
        if (y < 0)
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "pair \"%s:%s\": unknown DOF \"%s\"",
                           item, colon + 1, colon + 1);
        if (x == y)
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "pair \"%s:%s\": same DOF twice", item,
                           colon + 1);
        if (*count >= max_pairs)
            return sk_fail(err, SK_ERROR_LIMIT, "more than %d pairs", max_pairs);
        pairs[*count][0] = x;
        pairs[*count][1] = y;
        (*count)++;
        if (!comma) break;
        p = comma + 1;
    }
    if (*count == 0) return sk_fail(err, SK_ERROR_PARSE, "no pairs given (expected A:B,C:D)");
    return SK_OK;
}
