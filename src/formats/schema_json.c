/* The inverse of binding: a desc written back as JSON through its schema, and the schema
 * described as JSON (for interfaces that build a control per key). */
#include <stdlib.h>
#include <string.h>

#include <cjson/cJSON.h>

#include "shitsukan/preset.h"

static cJSON *object_to_json(const sk_schema *schema, const unsigned char *base);

static int stored_count(const sk_schema_field *f, const unsigned char *base)
{
    if (f->count_offset == SK_FIELD_FIXED) return f->count;
    int n;
    memcpy(&n, base + f->count_offset, sizeof n);
    return n < 0 ? 0 : (n > f->count ? f->count : n);
}

static cJSON *value_to_json(const sk_schema_field *f, const unsigned char *base)
{
    const unsigned char *ptr = base + f->offset;
    double scale = f->scale != 0.0 ? f->scale : 1.0;
    switch (f->type) {
    case SK_FIELD_FLOAT: {
        float v;
        memcpy(&v, ptr, sizeof v);
        return cJSON_CreateNumber((double)v / scale);
    }
    case SK_FIELD_DOUBLE: {
        double v;
        memcpy(&v, ptr, sizeof v);
        return cJSON_CreateNumber(v / scale);
    }
    case SK_FIELD_INT: {
        int v;
        memcpy(&v, ptr, sizeof v);
        return cJSON_CreateNumber(v);
    }
    case SK_FIELD_SEED: {
        uint64_t v;
        memcpy(&v, ptr, sizeof v);
        return cJSON_CreateNumber((double)v);
    }
    case SK_FIELD_BOOL: {
        bool v;
        memcpy(&v, ptr, sizeof v);
        return cJSON_CreateBool(v);
    }
    case SK_FIELD_ENUM: {
        int v;
        memcpy(&v, ptr, sizeof v);
        int n = 0;
        while (f->names && f->names[n]) n++;
        return cJSON_CreateString(v >= 0 && v < n ? f->names[v] : "");
    }
    case SK_FIELD_STRING:
        return cJSON_CreateString((const char *)ptr);
    case SK_FIELD_FLOATS: {
        cJSON *arr = cJSON_CreateArray();
        int n = stored_count(f, base);
        for (int i = 0; i < n; i++) {
            float v;
            memcpy(&v, ptr + (size_t)i * sizeof v, sizeof v);
            cJSON_AddItemToArray(arr, cJSON_CreateNumber((double)v / scale));
        }
        return arr;
    }
    case SK_FIELD_OBJECT:
        return object_to_json(f->schema, ptr);
    case SK_FIELD_ARRAY: {
        cJSON *arr = cJSON_CreateArray();
        int n = stored_count(f, base);
        const sk_schema *es = f->schema;
        bool bare = es->field_count == 1 && es->fields[0].key == NULL;
        for (int i = 0; i < n; i++) {
            const unsigned char *elem = ptr + (size_t)i * f->elem_size;
            cJSON_AddItemToArray(arr, bare ? value_to_json(&es->fields[0], elem)
                                           : object_to_json(es, elem));
        }
        return arr;
    }
    }
    return cJSON_CreateNull();
}

static cJSON *object_to_json(const sk_schema *schema, const unsigned char *base)
{
    cJSON *obj = cJSON_CreateObject();
    for (int i = 0; i < schema->field_count; i++) {
        const sk_schema_field *f = &schema->fields[i];
        if (f->key) cJSON_AddItemToObject(obj, f->key, value_to_json(f, base));
    }
    return obj;
}

char *sk_schema_to_json(const sk_schema *schema, const void *desc)
{
    cJSON *obj = object_to_json(schema, desc);
    char *text = cJSON_Print(obj);
    cJSON_Delete(obj);
    return text;
}

static const char *field_kind(const sk_schema_field *f)
{
    switch (f->type) {
    case SK_FIELD_FLOAT:
        return "float";
    case SK_FIELD_DOUBLE:
        return "double";
    case SK_FIELD_INT:
        return "int";
    case SK_FIELD_SEED:
        return "seed";
    case SK_FIELD_BOOL:
        return "bool";
    case SK_FIELD_ENUM:
        return "enum";
    case SK_FIELD_STRING:
        return "string";
    case SK_FIELD_FLOATS:
        return "floats";
    case SK_FIELD_OBJECT:
        return "object";
    case SK_FIELD_ARRAY:
        return "array";
    }
    return "?";
}

static cJSON *describe_fields(const sk_schema *schema)
{
    cJSON *list = cJSON_CreateArray();
    for (int i = 0; i < schema->field_count; i++) {
        const sk_schema_field *f = &schema->fields[i];
        cJSON *o = cJSON_CreateObject();
        if (f->key)
            cJSON_AddStringToObject(o, "key", f->key);
        else
            cJSON_AddNullToObject(o, "key");
        cJSON_AddStringToObject(o, "type", field_kind(f));
        double lo, hi;
        sk_schema_field_json_range(f, &lo, &hi);
        switch (f->type) {
        case SK_FIELD_FLOAT:
        case SK_FIELD_DOUBLE:
        case SK_FIELD_INT:
        case SK_FIELD_FLOATS:
            cJSON_AddNumberToObject(o, "min", lo);
            cJSON_AddNumberToObject(o, "max", hi);
            break;
        case SK_FIELD_SEED:
            cJSON_AddNumberToObject(o, "min", 0);
            cJSON_AddNumberToObject(o, "max", 9007199254740992.0);
            break;
        default:
            break;
        }
        if (f->type == SK_FIELD_FLOATS || f->type == SK_FIELD_ARRAY) {
            bool fixed = f->count_offset == SK_FIELD_FIXED;
            cJSON_AddNumberToObject(o, "min_count", fixed ? f->count : f->min_count);
            cJSON_AddNumberToObject(o, "max_count", f->count);
        }
        if (f->type == SK_FIELD_STRING) cJSON_AddNumberToObject(o, "max_length", f->count - 1);
        if (f->type == SK_FIELD_ENUM) {
            cJSON *names = cJSON_CreateArray();
            for (int k = 0; f->names && f->names[k]; k++)
                cJSON_AddItemToArray(names, cJSON_CreateString(f->names[k]));
            cJSON_AddItemToObject(o, "names", names);
        }
        if (f->doc) cJSON_AddStringToObject(o, "doc", f->doc);
        char deflt[160];
        sk_schema_field_default_text(f, deflt, sizeof deflt);
        if (deflt[0]) cJSON_AddStringToObject(o, "default", deflt);
        if (f->type == SK_FIELD_OBJECT || f->type == SK_FIELD_ARRAY)
            cJSON_AddItemToObject(o, "fields", describe_fields(f->schema));
        cJSON_AddItemToArray(list, o);
    }
    return list;
}

char *sk_schema_describe_json(const sk_schema *schema)
{
    cJSON *root = cJSON_CreateObject();
    cJSON_AddStringToObject(root, "name", schema->name ? schema->name : "");
    cJSON_AddItemToObject(root, "fields", describe_fields(schema));
    char *text = cJSON_PrintUnformatted(root);
    cJSON_Delete(root);
    return text;
}
