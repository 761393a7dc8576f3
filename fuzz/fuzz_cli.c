/* Fuzz harness: the command line's own parsers (tools/cli.c, tools/cli_keys.c): option
 * parsing of an argv (the input split at NUL bytes), then sizes "WxH", regions "x,y,w,h",
 * vectors "X,Y,Z", decimal numbers, integers, memory sizes, output extensions and the
 * values of options that set preset keys (integer, number and name keys) on the values
 * given. */
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"

static const cli_option k_options[] = {
    {"size", 0, "WxH", "", false},    {"region", 0, "x,y,w,h", "", false},
    {"point", 0, "X,Y,Z", "", false}, {"count", 'n', "N", "", false},
    {"scale", 0, "X", "", false},     {"label", 0, "TEXT", "", true},
    {"flag", 'f', NULL, "", false},   {"level", 0, "N", "", false},
    {"ratio", 0, "R", "", false},     {"mode", 0, "NAME", "", false},
    {"whole", 0, "N", "", false},
};
typedef struct fz_params {
    int level;
    double ratio;
    int mode;
    double whole;
} fz_params;
static const char *const k_modes[] = {"default", "a", "bb", NULL};
static const sk_schema_field k_fields[] = {
    SK_SCHEMA_INT(fz_params, level, "level", 2, 9, .flags = SK_FIELD_ZERO, .doc = ""),
    SK_SCHEMA_DOUBLE(fz_params, ratio, "ratio", 0, 2, .flags = SK_FIELD_OPEN_MIN, .doc = ""),
    SK_SCHEMA_ENUM(fz_params, mode, "mode", k_modes, .doc = ""),
    SK_SCHEMA_DOUBLE(fz_params, whole, "whole", -3, 3, .doc = ""),
};
static const sk_schema k_schema = SK_SCHEMA_OF("fuzz", fz_params, k_fields);
static const cli_key_option k_keys[] = {
    {"level", "level", NULL, false},
    {"ratio", "ratio", NULL, false},
    {"mode", "mode", NULL, false},
    {"whole", "whole", NULL, true},
};
static int run_none(const cli_command *command, const cli_args *args)
{
    (void)command;
    (void)args;
    return 0;
}
static const cli_command k_command = {
    .name = "fuzz sub",
    .summary = "",
    .usage = "",
    .options = k_options,
    .option_count = (int)(sizeof k_options / sizeof k_options[0]),
    .common = CLI_COMMON_ALL,
    .min_positional = 0,
    .max_positional = 4,
    .schema = &k_schema,
    .run = run_none,
    .key_options = k_keys,
    .key_option_count = (int)(sizeof k_keys / sizeof k_keys[0]),
};

/* A key option's value: accepted only within its key's range, as JSON of that value. */
static void check_key_options(const cli_args *args)
{
    for (int i = 0; i < k_command.key_option_count; i++) {
        const cli_key_option *o = &k_keys[i];
        const char *text = cli_get(&k_command, args, o->option);
        char json[128];
        if (!text || cli_key_option_json(&k_command, o, text, json, sizeof json) != 0) continue;
        const sk_schema_field *f = sk_schema_find(&k_schema, o->key);
        if (f->type == SK_FIELD_ENUM) {
            bool known = false;
            for (int k = 1; f->names[k]; k++) {
                char quoted[32];
                snprintf(quoted, sizeof quoted, "\"%s\"", f->names[k]);
                known = known || strcmp(json, quoted) == 0;
            }
            if (!known) abort();
            continue;
        }
        char *end;
        double v = strtod(json, &end);
        bool open = (f->flags & SK_FIELD_OPEN_MIN) != 0;
        if (*end || !(open ? v > f->min : v >= f->min) || !(v <= f->max)) abort();
        if ((f->type == SK_FIELD_INT || o->integer) && v != (double)(long long)v) abort();
    }
}
const cli_command *const cli_commands[] = {&k_command, NULL};

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    /* the parsers print one-line errors to stderr (make fuzz closes it: -close_fd_mask=2) */
    if (size > 4096) return 0;
    char *text = malloc(size + 1);
    if (!text) abort();
    memcpy(text, data, size);
    text[size] = '\0';
    char *argv[33];
    int argc = 0;
    for (size_t i = 0; i <= size && argc < 32;) {
        argv[argc++] = text + i;
        i += strlen(text + i) + 1;
    }
    argv[argc] = NULL;
    cli_args *args = malloc(sizeof *args);
    if (!args) abort();
    if (cli_parse(&k_command, argc, argv, args) == 0) {
        int w, h, region[4];
        long long n;
        double x, v[3];
        uint64_t bytes;
        int format;
        if (cli_get_size(&k_command, args, "size", 1, 1, SK_IMAGE_MAX_DIMENSION, &w, &h) == 0 &&
            (w < 1 || h < 1 || w > SK_IMAGE_MAX_DIMENSION || h > SK_IMAGE_MAX_DIMENSION))
            abort();
        const char *r = cli_get(&k_command, args, "region");
        if (r && cli_parse_region(r, 4096, 100, region) == 0 &&
            (region[0] < 0 || region[1] < 0 || region[2] < 1 || region[3] < 1 ||
             region[0] + region[2] > 4096 || region[1] + region[3] > 100))
            abort();
        const char *p = cli_get(&k_command, args, "point");
        if (p) cli_parse_numbers("point", p, 3, v);
        if (cli_get_int(&k_command, args, "count", 0, -5, 5, &n) == 0 && (n < -5 || n > 5)) abort();
        if (cli_get_double(&k_command, args, "scale", 0, -1, 1, &x) == 0 && !(x >= -1 && x <= 1))
            abort();
        check_key_options(args);
        static const char *const formats[] = {".png", ".exr", NULL};
        for (int i = 0; i < args->positional_count; i++) {
            cli_parse_memory_size(args->positional[i], &bytes);
            cli_parse_decimal(args->positional[i], &x);
            cli_output_format("-o", args->positional[i], formats, &format);
        }
    }
    free(args);
    free(text);
    return 0;
}
