/* Options that are other names for preset keys: each value checked against its key's
 * range and names as the schema states them (nothing restated here), reported as the
 * option, and set in the preset tree before the --set edits (see cli.h). */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"

int cli_set_key(sk_preset *tree, const char *key, const char *json)
{
    char assignment[256];
    snprintf(assignment, sizeof assignment, "%s=%s", key, json);
    sk_error err = {0};
    return sk_preset_set(tree, assignment, &err) == SK_OK ? 0 : cli_fail_error(&err);
}

const sk_schema_field *cli_find_key(const cli_command *command, const char *key)
{
    const sk_schema_field *f =
        command->part_schema ? sk_schema_find(command->part_schema, key) : NULL;
    return f ? f : (command->schema ? sk_schema_find(command->schema, key) : NULL);
}

/* "a, b or c": the names of an enum without its "default". */
static void list_names(const char *const *names, char *out, size_t size)
{
    int first = names && names[0] && strcmp(names[0], "default") == 0 ? 1 : 0, n = 0;
    while (names && names[n]) n++;
    size_t used = 0;
    out[0] = '\0';
    for (int i = first; i < n && used < size; i++)
        used += (size_t)snprintf(out + used, size - used, "%s%s",
                                 i == first ? "" : (i == n - 1 ? " or " : ", "), names[i]);
}

static int number_json(const cli_key_option *o, const sk_schema_field *f, const char *text,
                       char *json, size_t size)
{
    bool open_min = (f->flags & SK_FIELD_OPEN_MIN) != 0;
    if (f->type == SK_FIELD_INT || o->integer) {
        errno = 0;
        char *end;
        long long x = strtoll(text, &end, 10);
        long long lo = (long long)f->min + (open_min ? 1 : 0), hi = (long long)f->max;
        if (!text[0] || *end || errno || x < lo || x > hi)
            return cli_fail(CLI_EXIT_USAGE, "--%s '%s' must be an integer in [%lld, %lld]",
                            o->option, text, lo, hi);
        snprintf(json, size, "%lld", x);
        return 0;
    }
    double x;
    if (!cli_parse_decimal(text, &x) || (open_min ? !(x > f->min) : x < f->min) || x > f->max)
        return cli_fail(CLI_EXIT_USAGE, "--%s '%s' must be a number in %c%g, %g]", o->option, text,
                        open_min ? '(' : '[', f->min, f->max);
    snprintf(json, size, "%.17g", x);
    return 0;
}

int cli_key_option_json(const cli_command *command, const cli_key_option *o, const char *text,
                        char *json, size_t size)
{
    const sk_schema_field *f = cli_find_key(command, o->key);
    if (!f) {
        /* a programming error in a command: the key must be one of its schema's */
        fprintf(stderr, "shitsukan: internal error: %s has no key %s\n", command->name, o->key);
        abort();
    }
    if (o->value) text = o->value;
    switch (f->type) {
    case SK_FIELD_INT:
    case SK_FIELD_FLOAT:
    case SK_FIELD_DOUBLE:
        return number_json(o, f, text, json, size);
    case SK_FIELD_ENUM: {
        int first = f->names && f->names[0] && strcmp(f->names[0], "default") == 0 ? 1 : 0;
        for (int i = first; f->names && f->names[i]; i++)
            if (strcmp(f->names[i], text) == 0) {
                snprintf(json, size, "\"%s\"", text);
                return 0;
            }
        char names[256];
        list_names(f->names, names, sizeof names);
        return cli_fail(CLI_EXIT_USAGE, "--%s '%s' must be %s", o->option, text, names);
    }
    case SK_FIELD_BOOL:
        snprintf(json, size, "%s", strcmp(text, "false") == 0 ? "false" : "true");
        return 0;
    default:
        fprintf(stderr, "shitsukan: internal error: key %s of %s is not a value an option sets\n",
                o->key, command->name);
        abort();
    }
}
