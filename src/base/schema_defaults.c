/* A desc's zeros replaced by the defaults its schema states (each default stated once, in
 * the field; defaults computed from other keys stay with the model). */
#include <string.h>

#include "shitsukan/schema.h"

static double stored_value(const sk_schema_field *f, double json)
{
    return f->scale != 0.0 ? json * f->scale : json;
}

static void default_floats(const sk_schema_field *f, unsigned char *ptr, int n)
{
    float *v = (float *)(void *)ptr;
    if (f->defs) {
        for (int i = 0; i < n; i++)
            if (v[i] != 0.0f) return;
        for (int i = 0; i < n; i++) v[i] = (float)stored_value(f, f->defs[i]);
        return;
    }
    if (f->def == 0.0) return;
    for (int i = 0; i < n; i++)
        if (v[i] == 0.0f) v[i] = (float)stored_value(f, f->def);
}

static void apply_field(const sk_schema_field *f, unsigned char *base)
{
    unsigned char *ptr = base + f->offset;
    if (f->def_text || (f->flags & SK_FIELD_OWN)) return;
    switch (f->type) {
    case SK_FIELD_FLOAT: {
        float v;
        memcpy(&v, ptr, sizeof v);
        if (v == 0.0f && f->def != 0.0) v = (float)stored_value(f, f->def);
        memcpy(ptr, &v, sizeof v);
        return;
    }
    case SK_FIELD_DOUBLE: {
        double v;
        memcpy(&v, ptr, sizeof v);
        if (v == 0.0 && f->def != 0.0) v = stored_value(f, f->def);
        memcpy(ptr, &v, sizeof v);
        return;
    }
    case SK_FIELD_INT:
    case SK_FIELD_ENUM: {
        int v;
        memcpy(&v, ptr, sizeof v);
        if (v == 0 && f->def != 0.0) v = (int)f->def;
        memcpy(ptr, &v, sizeof v);
        return;
    }
    case SK_FIELD_FLOATS:
        if (f->count_offset == SK_FIELD_FIXED) default_floats(f, ptr, f->count);
        return;
    case SK_FIELD_OBJECT:
        sk_schema_apply_defaults(f->schema, ptr);
        return;
    case SK_FIELD_ARRAY: {
        int n;
        memcpy(&n, base + f->count_offset, sizeof n);
        if (n > f->count) n = f->count;
        const sk_schema *es = f->schema;
        bool bare = es->field_count == 1 && es->fields[0].key == NULL;
        for (int i = 0; i < n; i++) {
            unsigned char *elem = ptr + (size_t)i * f->elem_size;
            if (bare)
                apply_field(&es->fields[0], elem);
            else
                sk_schema_apply_defaults(es, elem);
        }
        return;
    }
    case SK_FIELD_SEED:
    case SK_FIELD_BOOL:
    case SK_FIELD_STRING:
        return;
    }
}

void sk_schema_apply_defaults(const sk_schema *schema, void *desc)
{
    for (int i = 0; i < schema->field_count; i++)
        apply_field(&schema->fields[i], (unsigned char *)desc);
}
