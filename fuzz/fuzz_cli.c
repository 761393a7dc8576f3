/* Fuzz harness: the command line's own parsers (tools/cli.c): option parsing of an argv
 * (the input split at NUL bytes), then sizes "WxH", regions "x,y,w,h", vectors "X,Y,Z",
 * decimal numbers, integers, memory sizes and output extensions on the values given. */
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
    {"flag", 'f', NULL, "", false},
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
    .run = run_none,
};
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
