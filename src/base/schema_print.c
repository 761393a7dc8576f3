/* A schema printed as a table of key paths with their types, ranges, defaults and docs:
 * one line per key for --help-keys, or a Markdown table for the docs' key tables (which a
 * test compares with this output, so the docs state nothing the schema does not). */
#include <stdio.h>
#include <string.h>

#include "shitsukan/schema.h"

#define PATH_SIZE 256

static const char *type_name(const sk_schema_field *f)
{
    switch (f->type) {
    case SK_FIELD_FLOAT:
    case SK_FIELD_DOUBLE:
        return "number";
    case SK_FIELD_INT:
    case SK_FIELD_SEED:
        return "integer";
    case SK_FIELD_BOOL:
        return "boolean";
    case SK_FIELD_ENUM:
    case SK_FIELD_STRING:
        return "string";
    case SK_FIELD_FLOATS:
        return "numbers";
    case SK_FIELD_OBJECT:
        return "object";
    case SK_FIELD_ARRAY:
        return "array";
    }
    return "?";
}

/* A Markdown table cell: '|' escaped. */
static void print_cell(FILE *out, const char *text)
{
    fputc(' ', out);
    for (const char *c = text; *c; c++) {
        if (*c == '|') fputc('\\', out);
        fputc(*c, out);
    }
    fputs(" |", out);
}

static void print_field(const sk_schema_field *f, const char *path, bool markdown, FILE *out)
{
    char range[160], deflt[160];
    sk_schema_field_range_text(f, range, sizeof range);
    sk_schema_field_default_text(f, deflt, sizeof deflt);
    const char *doc = f->doc ? f->doc : "";
    if (!markdown) {
        fprintf(out, "  %-36s %-8s %-22s %s%s%s\n", path, type_name(f), range, doc,
                doc[0] && deflt[0] ? "; " : "", deflt);
        return;
    }
    char key[PATH_SIZE + 2];
    snprintf(key, sizeof key, "`%s`", path);
    fputc('|', out);
    print_cell(out, key);
    print_cell(out, type_name(f));
    print_cell(out, range);
    print_cell(out, deflt);
    print_cell(out, doc);
    fputc('\n', out);
}

static void print_fields(const sk_schema *schema, const char *prefix, bool markdown, FILE *out)
{
    for (int i = 0; i < schema->field_count; i++) {
        const sk_schema_field *f = &schema->fields[i];
        char path[PATH_SIZE];
        if (f->key)
            snprintf(path, sizeof path, "%s%s%s", prefix, prefix[0] ? "." : "", f->key);
        else
            snprintf(path, sizeof path, "%s", prefix);
        bool expand = !(markdown && (f->flags & SK_FIELD_OWN));
        if (f->type == SK_FIELD_OBJECT && expand) {
            print_fields(f->schema, path, markdown, out);
        } else if (f->type == SK_FIELD_ARRAY) {
            print_field(f, path, markdown, out);
            char elem[sizeof path + 4];
            snprintf(elem, sizeof elem, "%s[]", path);
            print_fields(f->schema, elem, markdown, out);
        } else {
            print_field(f, path, markdown, out);
        }
    }
}

void sk_schema_print(const sk_schema *schema, FILE *out) { print_fields(schema, "", false, out); }

void sk_schema_print_markdown(const sk_schema *schema, FILE *out)
{
    fprintf(out, "| key | type | range | default | meaning |\n|---|---|---|---|---|\n");
    print_fields(schema, "", true, out);
}
