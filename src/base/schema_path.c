/* A schema's fields by key path, and the range a JSON value of a field may take. */
#include <string.h>

#include "shitsukan/schema.h"

void sk_schema_field_json_range(const sk_schema_field *f, double *lo, double *hi)
{
    *lo = f->min;
    *hi = f->max;
    if ((f->flags & SK_FIELD_ZERO) && *lo > 0.0) *lo = 0.0;
}

const sk_schema_field *sk_schema_find(const sk_schema *schema, const char *key_path)
{
    const char *p = key_path;
    while (schema && p && *p) {
        size_t n = strcspn(p, ".[");
        const sk_schema_field *found = NULL;
        for (int i = 0; i < schema->field_count && !found; i++) {
            const char *k = schema->fields[i].key;
            if (k && strlen(k) == n && strncmp(k, p, n) == 0) found = &schema->fields[i];
        }
        if (!found) return NULL;
        p += n;
        if (strncmp(p, "[]", 2) == 0) {
            p += 2;
            if (found->type == SK_FIELD_FLOATS && !*p) return found;
            if (found->type != SK_FIELD_ARRAY) return NULL;
            const sk_schema *es = found->schema;
            if (es->field_count == 1 && es->fields[0].key == NULL)
                return *p ? NULL : &es->fields[0];
        } else if (*p == '[') {
            return NULL;
        }
        if (!*p) return found;
        if (*p != '.' || (found->type != SK_FIELD_OBJECT && found->type != SK_FIELD_ARRAY))
            return NULL;
        p++;
        schema = found->schema;
    }
    return NULL;
}
