/* Joint-angle samples from CSV (the measured angle pairs of thesis 3.2.2 and 3.2.3): a
 * header of DOF names, then one sample per line in degrees (mm for translations). */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "hand/hand_private.h"
#include "shitsukan/io.h"

void sk_hand_samples_free(sk_hand_samples *s)
{
    if (!s) return;
    for (int i = 0; i < SK_HAND_DOF_COUNT; i++) free(s->column[i]);
    memset(s, 0, sizeof *s);
}

/* Next field of a line: trims blanks, stops at ',' or the end. */
static const char *next_field(const char *p, const char *end, char *buf, size_t cap, bool *more)
{
    while (p < end && (*p == ' ' || *p == '\t')) p++;
    const char *start = p;
    while (p < end && *p != ',') p++;
    const char *stop = p;
    while (stop > start && (stop[-1] == ' ' || stop[-1] == '\t' || stop[-1] == '\r')) stop--;
    size_t n = (size_t)(stop - start);
    if (n >= cap) n = cap - 1;
    memcpy(buf, start, n);
    buf[n] = '\0';
    *more = p < end && *p == ',';
    return p < end ? p + 1 : p;
}

#define MAX_COLUMNS 64

sk_result sk_hand_samples_parse(const char *text, size_t length, const char *name,
                                sk_hand_samples *out, sk_error *err)
{
    memset(out, 0, sizeof *out);
    int col_dof[MAX_COLUMNS];
    int ncol = 0, line_no = 0, cap = 0;
    bool header = false;
    sk_result r = SK_OK;
    const char *p = text, *end = text + length;
    while (p < end && r == SK_OK) {
        const char *eol = memchr(p, '\n', (size_t)(end - p));
        if (!eol) eol = end;
        line_no++;
        const char *q = p;
        p = eol < end ? eol + 1 : end;
        while (q < eol && (*q == ' ' || *q == '\t' || *q == '\r')) q++;
        if (q == eol || *q == '#') continue; /* blank or comment */
        char field[128];
        bool more = true;
        if (!header) {
            header = true;
            while (more && r == SK_OK) {
                q = next_field(q, eol, field, sizeof field, &more);
                if (ncol >= MAX_COLUMNS) {
                    r = sk_fail(err, SK_ERROR_LIMIT, "line %d: more than %d columns", line_no, MAX_COLUMNS);
                    break;
                }
                int d = -1;
                if (strcmp(field, "frame") != 0 && strcmp(field, "time") != 0) {
                    d = sk_hand_dof_find(field);
                    if (d < 0) {
                        r = sk_fail(err, SK_ERROR_PARSE,
                                    "line %d, column %d: unknown DOF \"%s\" (names like "
                                    "\"L.MCP.flex\"; \"frame\" and \"time\" are ignored)",
                                    line_no, ncol + 1, field);
                        break;
                    }
                    if (out->present[d]) {
                        r = sk_fail(err, SK_ERROR_PARSE, "line %d, column %d: \"%s\" appears twice",
                                    line_no, ncol + 1, field);
                        break;
                    }
                    out->present[d] = true;
                }
                col_dof[ncol++] = d;
            }
            continue;
        }
        if (out->count >= cap) {
            int ncap = cap ? cap * 2 : 256;
            if (ncap > 10000000) {
                r = sk_fail(err, SK_ERROR_LIMIT, "line %d: more than 10000000 samples", line_no);
                break;
            }
            for (int d = 0; d < SK_HAND_DOF_COUNT && r == SK_OK; d++) {
                if (!out->present[d]) continue;
                double *grown = realloc(out->column[d], (size_t)ncap * sizeof(double));
                if (!grown) r = sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
                else out->column[d] = grown;
            }
            cap = ncap;
            if (r != SK_OK) break;
        }
        int c = 0;
        while (more && r == SK_OK) {
            q = next_field(q, eol, field, sizeof field, &more);
            if (c >= ncol) {
                r = sk_fail(err, SK_ERROR_PARSE, "line %d: more than the header's %d fields", line_no, ncol);
                break;
            }
            char *stop = NULL;
            errno = 0;
            double v = strtod(field, &stop);
            if (field[0] == '\0' || *stop != '\0' || errno == ERANGE || !isfinite(v)) {
                r = sk_fail(err, SK_ERROR_PARSE, "line %d, column %d (%s): \"%s\" is not a finite number",
                            line_no, c + 1, col_dof[c] >= 0 ? sk_hand_dof(col_dof[c])->name : "ignored",
                            field);
                break;
            }
            /* angles in degrees, translations in mm: anything larger is not a measurement */
            if (col_dof[c] >= 0 && fabs(v) > SK_HAND_SAMPLE_MAX) {
                r = sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                            "line %d, column %d (%s): %g is out of range [%g, %g]", line_no, c + 1,
                            sk_hand_dof(col_dof[c])->name, v, -SK_HAND_SAMPLE_MAX, SK_HAND_SAMPLE_MAX);
                break;
            }
            if (col_dof[c] >= 0)
                out->column[col_dof[c]][out->count] = sk_hand__from_file_units(col_dof[c], v);
            c++;
        }
        if (r == SK_OK && c != ncol)
            r = sk_fail(err, SK_ERROR_PARSE, "line %d: %d fields, the header has %d", line_no, c, ncol);
        if (r == SK_OK) out->count++;
    }
    if (r == SK_OK && !header) r = sk_fail(err, SK_ERROR_PARSE, "no header line of DOF names");
    if (r == SK_OK && out->count == 0) r = sk_fail(err, SK_ERROR_PARSE, "no samples after the header");
    if (r != SK_OK) {
        sk_hand_samples_free(out);
        sk_error_prefix(err, r, "%s", name);
    }
    return r;
}

sk_result sk_hand_samples_load_file(const char *path, sk_hand_samples *out, sk_error *err)
{
    char *text = NULL;
    size_t size = 0;
    memset(out, 0, sizeof *out);
    sk_result r = sk_read_file(path, SK_HAND_MAX_FILE_BYTES, &text, &size, err);
    if (r != SK_OK) return r;
    r = sk_hand_samples_parse(text, size, path, out, err);
    free(text);
    return r;
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
        if (n >= sizeof item) return sk_fail(err, SK_ERROR_PARSE, "pair \"%.40s...\" is too long", p);
        memcpy(item, p, n);
        item[n] = '\0';
        char *colon = strchr(item, ':');
        if (!colon) return sk_fail(err, SK_ERROR_PARSE, "pair \"%s\": expected DOF:DOF", item);
        *colon = '\0';
        int x = sk_hand_dof_find(item), y = sk_hand_dof_find(colon + 1);
        if (x < 0) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "pair \"%s:%s\": unknown DOF \"%s\"", item, colon + 1, item);
        if (y < 0)
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "pair \"%s:%s\": unknown DOF \"%s\"", item,
                           colon + 1, colon + 1);
        if (x == y) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "pair \"%s:%s\": same DOF twice", item, colon + 1);
        if (*count >= max_pairs) return sk_fail(err, SK_ERROR_LIMIT, "more than %d pairs", max_pairs);
        pairs[*count][0] = x;
        pairs[*count][1] = y;
        (*count)++;
        if (!comma) break;
        p = comma + 1;
    }
    if (*count == 0) return sk_fail(err, SK_ERROR_PARSE, "no pairs given (expected A:B,C:D)");
    return SK_OK;
}
