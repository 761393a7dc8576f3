/* A field's range and default in words (for --help-keys and the docs' key tables), made
 * from what the schema states: nothing is restated in a field's doc. */
#include <stdio.h>
#include <string.h>

#include "shitsukan/schema.h"

static void number_range(const sk_schema_field *f, char *buf, size_t size)
{
    if (f->flags & SK_FIELD_OPEN_MIN)
        snprintf(buf, size, "(%g, %g]", f->min, f->max);
    else if ((f->flags & SK_FIELD_ZERO) && f->min > 0)
        snprintf(buf, size, "0 or [%g, %g]", f->min, f->max);
    else
        snprintf(buf, size, "[%g, %g]", f->min, f->max);
}

void sk_schema_field_range_text(const sk_schema_field *f, char *buf, size_t size)
{
    char range[96];
    buf[0] = '\0';
    switch (f->type) {
    case SK_FIELD_FLOAT:
    case SK_FIELD_DOUBLE:
    case SK_FIELD_INT:
        number_range(f, buf, size);
        return;
    case SK_FIELD_SEED:
        snprintf(buf, size, "[0, 2^53]");
        return;
    case SK_FIELD_FLOATS:
        number_range(f, range, sizeof range);
        if (f->count_offset == SK_FIELD_FIXED)
            snprintf(buf, size, "%d x %s", f->count, range);
        else
            snprintf(buf, size, "%d..%d x %s", f->min_count, f->count, range);
        return;
    case SK_FIELD_ENUM: {
        size_t used = 0;
        for (int k = 0; f->names && f->names[k]; k++) {
            int n = snprintf(buf + used, size - used, "%s%s", k ? "|" : "", f->names[k]);
            if (n < 0 || (size_t)n >= size - used) break;
            used += (size_t)n;
        }
        return;
    }
    case SK_FIELD_ARRAY:
        snprintf(buf, size, "%d..%d elements", f->min_count, f->count);
        return;
    case SK_FIELD_BOOL:
    case SK_FIELD_STRING:
    case SK_FIELD_OBJECT:
        return;
    }
}

/* Whether a preset may write 0 for the field (0 then means its default). */
static bool accepts_zero(const sk_schema_field *f)
{
    return (f->flags & SK_FIELD_ZERO) || (f->min <= 0 && f->max >= 0);
}

void sk_schema_field_default_text(const sk_schema_field *f, char *buf, size_t size)
{
    buf[0] = '\0';
    if (f->def_text) {
        const char *zero = f->type == SK_FIELD_FLOATS  ? "all 0 = "
                           : f->type == SK_FIELD_ARRAY ? "empty = "
                           : accepts_zero(f)           ? "0 = "
                                                       : "default ";
        snprintf(buf, size, "%s%s", zero, f->def_text);
        return;
    }
    switch (f->type) {
    case SK_FIELD_FLOAT:
    case SK_FIELD_DOUBLE:
    case SK_FIELD_INT:
        if ((f->flags & SK_FIELD_OPEN_MIN) && !(f->flags & SK_FIELD_ZERO))
            snprintf(buf, size, "required");
        else if (f->def != 0)
            snprintf(buf, size, accepts_zero(f) ? "0 = %g" : "default %g", f->def);
        else
            snprintf(buf, size, "default 0");
        return;
    case SK_FIELD_SEED:
        snprintf(buf, size, "default 0");
        return;
    case SK_FIELD_BOOL:
        snprintf(buf, size, "default false");
        return;
    case SK_FIELD_ENUM: {
        int n = 0;
        while (f->names && f->names[n]) n++;
        int k = (int)f->def;
        if (k >= 0 && k < n) snprintf(buf, size, "default %s", f->names[k]);
        return;
    }
    case SK_FIELD_FLOATS: {
        if (!f->key) return; /* a value of an array element: the array's doc says it */
        if (f->defs && f->count_offset == SK_FIELD_FIXED) {
            size_t used = (size_t)snprintf(buf, size, "all 0 = [");
            for (int i = 0; i < f->count && used < size; i++)
                used +=
                    (size_t)snprintf(buf + used, size - used, "%s%g", i ? ", " : "", f->defs[i]);
            if (used < size) snprintf(buf + used, size - used, "]");
        } else if (f->def != 0) {
            snprintf(buf, size, "0 = %g", f->def);
        } else {
            snprintf(buf, size, "default 0");
        }
        return;
    }
    case SK_FIELD_STRING:
    case SK_FIELD_OBJECT:
    case SK_FIELD_ARRAY:
        return;
    }
}
