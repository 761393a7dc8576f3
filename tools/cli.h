/* Command-line framework of the `shitsukan` tool: subcommand table, option parsing,
 * help text, one-line errors with exit codes, and preset loading with --set overrides.
 * The tool only parses arguments, loads presets and calls the library. */
#ifndef SK_TOOLS_CLI_H
#define SK_TOOLS_CLI_H

#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>

#include "shitsukan/core.h"
#include "shitsukan/image.h"
#include "shitsukan/io.h"
#include "shitsukan/preset.h"

/* Exit status: 0 success, 1 runtime failure (e.g. a write failed), 2 bad usage or input. */
enum { CLI_EXIT_OK = 0, CLI_EXIT_RUNTIME = 1, CLI_EXIT_USAGE = 2 };

#define CLI_MAX_OPTIONS 48
#define CLI_MAX_SETS 128
#define CLI_MAX_POSITIONAL 256

/* A subcommand-specific option. */
typedef struct cli_option {
    const char *name;     /* long name without dashes, e.g. "size" */
    char short_name;      /* e.g. 'o', or 0 */
    const char *arg_name; /* e.g. "N" or "WxH"; NULL for a flag without value */
    const char *help;     /* one line, including the default */
    bool repeatable;      /* may be given several times (values kept in order) */
} cli_option;

/* Common options; a command lists which it takes (bit mask). */
enum {
    CLI_COMMON_OUTPUT = 1 << 0,  /* -o, --output PATH */
    CLI_COMMON_PRESET = 1 << 1,  /* --preset NAME|FILE */
    CLI_COMMON_SET = 1 << 2,     /* --set key.path=value (repeatable) */
    CLI_COMMON_SEED = 1 << 3,    /* --seed N */
    CLI_COMMON_THREADS = 1 << 4, /* --threads N */
    CLI_COMMON_QUIET = 1 << 5,   /* -q, --quiet */
    CLI_COMMON_MEMORY = 1 << 6,  /* --max-memory SIZE: taken by every command */
    CLI_COMMON_ALL = 0x7f
};

/* The memory a command may plan to use unless --max-memory says otherwise. */
#define CLI_DEFAULT_MAX_MEMORY ((uint64_t)8 << 30)

typedef struct cli_common {
    const char *output;
    const char *preset;
    const char *sets[CLI_MAX_SETS];
    int set_count;
    uint64_t seed;
    bool has_seed;
    int threads; /* 0 = all cores */
    bool quiet;
    uint64_t max_memory; /* bytes; CLI_DEFAULT_MAX_MEMORY unless --max-memory is given */
} cli_common;

#define CLI_MAX_VALUES 256
typedef struct cli_args {
    cli_common common;
    /* For option i of the command: how often it was given and its values. */
    int count[CLI_MAX_OPTIONS];
    const char *value[CLI_MAX_OPTIONS]; /* last value (or "" for a flag) */
    const char *values[CLI_MAX_VALUES]; /* all values of repeatable options, in order */
    int values_option[CLI_MAX_VALUES];  /* which option each of `values` belongs to */
    int values_count;
    const char *positional[CLI_MAX_POSITIONAL];
    int positional_count;
} cli_args;

struct cli_command;
typedef int (*cli_run_fn)(const struct cli_command *command, const cli_args *args);

/* An option that is another name for a preset key (the options a command had before its
 * keys joined the schema): cli_load_preset checks its value against the key's range in the
 * command's schema, with the option's own message ("--lut-resolution '4' must be an
 * integer in [8, 1024]"), and sets the key after the preset and before every --set. A
 * flag (an option without argument) sets `value`. */
typedef struct cli_key_option {
    const char *option; /* long name, e.g. "lut-resolution" */
    const char *key;    /* key path, e.g. "lut.resolution" */
    const char *value;  /* a flag's value ("left"); NULL: the option's argument */
    bool integer;       /* a number key taken as a whole number (the option's old form) */
} cli_key_option;

typedef struct cli_command {
    const char *name;        /* "skin" or a two-word "skin maps" */
    const char *summary;     /* one line for the tool's --help */
    const char *usage;       /* e.g. "shitsukan skin [options]" */
    const char *description; /* paragraph(s) for the command's --help */
    const char *examples;    /* example lines for --help, or NULL */
    const cli_option *options;
    int option_count;
    unsigned common; /* CLI_COMMON_* mask */
    int min_positional, max_positional;
    const char *preset_module; /* folder under presets/ for --preset NAME, or NULL */
    const sk_schema *schema;   /* preset schema (for --help-keys), or NULL */
    cli_run_fn run;
    /* Optional: options that set keys, and the key --seed sets (NULL = "seed"). */
    const cli_key_option *key_options;
    int key_option_count;
    const char *seed_key;
    /* Optional: sets the keys of options that need more than a range check (one option
       for two keys, an option whose 0 means "none"), in the tree after the key options
       and before --set (cli_set_key helps); 0 or the exit status after printing. */
    int (*set_option_keys)(const struct cli_command *command, const cli_args *args,
                           sk_preset *tree);
    /* Optional: a second schema, of the keys under one top-level key of the same preset
       (the showcase's own keys beside its stage scene); --help-keys lists it first and key
       options may name its keys. */
    const sk_schema *part_schema;
} cli_command;

/* All commands, NULL-terminated (tools/commands.c). */
extern const cli_command *const cli_commands[];

/* Prints "shitsukan: error: <message>" (one line) and returns `status`. */
int cli_fail(int status, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
/* Exit status for a library result: 2 for bad input (invalid argument, parse, limit,
 * unsupported, not found), 1 for runtime failures (I/O, memory, numeric). */
int cli_exit_status(sk_result result);
/* Prints the error's message as one line and returns its exit status. */
int cli_fail_error(const sk_error *err);

/* Parses argv (after the command words) into args. On --help prints help and returns -1
 * (exit 0); on bad usage prints one line and returns 2; otherwise 0. */
int cli_parse(const cli_command *command, int argc, char **argv, cli_args *args);
void cli_print_help(const cli_command *command, FILE *out);
/* Groups: the first word of two-word commands ("hand" of "hand pose"). cli_is_group says
 * whether `word` is one; cli_print_group_help lists its subcommands from the table, so a
 * new group has its help without code of its own. */
bool cli_is_group(const char *word);
void cli_print_group_help(const char *group, FILE *out);
/* The group's subcommand names, comma-separated ("pose, animate, calibrate"). */
void cli_group_subcommands(const char *group, char *out, size_t size);

/* Option access by long name (the name must be one of the command's options). */
const char *cli_get(const cli_command *command, const cli_args *args, const char *name);
bool cli_has(const cli_command *command, const cli_args *args, const char *name);
/* Whether the command has option --name at all (for helpers shared by commands). */
bool cli_takes(const cli_command *command, const char *name);
/* Values of a repeatable option, in order; returns how many were written (<= max). */
int cli_get_all(const cli_command *command, const cli_args *args, const char *name,
                const char **out, int max);

/* Typed option values with range checks; absent options give `fallback`. On a bad value
 * they print the one-line error and return 2, else 0. */
int cli_get_int(const cli_command *command, const cli_args *args, const char *name,
                long long fallback, long long lo, long long hi, long long *out);
int cli_get_double(const cli_command *command, const cli_args *args, const char *name,
                   double fallback, double lo, double hi, double *out);
/* A whole decimal number ("12", "-0.5", "1e-3"; no hexadecimal, "inf" or "nan", no
 * leading or trailing text) that is finite: true and *out, else false. */
bool cli_parse_decimal(const char *text, double *out);
/* "N" (square) or "WxH", each in [1, max]. */
int cli_get_size(const cli_command *command, const cli_args *args, const char *name, int fallback_w,
                 int fallback_h, int max, int *w, int *h);
/* Parses `count` comma-separated decimal numbers ("X,Y,Z") of option --`option`. */
int cli_parse_numbers(const char *option, const char *text, int count, double *out);
/* Parses "x,y,w,h" (a sub-rectangle of a width x height image). */
int cli_parse_region(const char *text, int width, int height, int region[4]);

/* Resolves --preset (a file path, or NAME looked up as presets/<module>/NAME.json in
 * $SHITSUKAN_PRESET_DIR, the installed share folder, then the source tree), sets the
 * keys of the command's key options that were given, applies every --set and --seed, and
 * returns the tree (or an empty one without --preset). Errors print and return their
 * exit status. */
int cli_load_preset(const cli_command *command, const cli_args *args, sk_preset **out);
/* The same, bound onto `params` (its fields absent from the tree keep their values)
 * through command->schema. */
int cli_bind_params(const cli_command *command, const cli_args *args, void *params);
/* A key option's value as the JSON of its key (checked against the key's range); 0 or the
 * exit status after printing the error. (cli_keys.c) */
int cli_key_option_json(const cli_command *command, const cli_key_option *option, const char *text,
                        char *json, size_t size);
/* Sets "key=json" in the tree (for set_option_keys); 0 or the exit status. */
int cli_set_key(sk_preset *tree, const char *key, const char *json);
/* The schema field of a key path in the command's schemas (part_schema, then schema). */
const sk_schema_field *cli_find_key(const cli_command *command, const char *key);
/* Finds a shipped preset file: writes its path and returns true. */
bool cli_find_preset(const char *module, const char *name, char *path, size_t size);
/* The folder of the running executable (for the share folder of an installed tool). */
bool cli_executable_dir(char *out, size_t size);
/* The preset folders searched, in order; returns how many were written (<= max). */
int cli_preset_dirs(const char **out, int max);

/* Parses a memory size: bytes, or a number with K, M, G or T (binary multiples; "KiB",
 * "GB" and the like read the same), in [1 MiB, 1 PiB]. */
bool cli_parse_memory_size(const char *text, uint64_t *bytes);
/* The memory cap: refuses (exit 2, one line) a plan of `bytes` above --max-memory,
 * naming what drives it (`driver`, e.g. "--size 20000x20000" or "--tile-size 16384 for
 * 2 images"). Every command calls it with its estimate before allocating. */
int cli_check_memory(const cli_args *args, double bytes, const char *driver);
/* The library's cap on one image (SK_IMAGE_MAX_BYTES of float samples), checked up front
 * so the message names what drives it (`driver`, e.g. "a 65536 x 65536 map (--size)"). */
int cli_check_image(int width, int height, int channels, const char *driver);
/* Pixel buffers of `bytes_per_pixel` bytes for a w x h image (as a double: no overflow). */
double cli_image_bytes(double width, double height, double bytes_per_pixel);

/* The output's format by its extension (case-insensitive), one of `accepted` (e.g.
 * {".png", ".exr", NULL}): its index in *format, or the one-line error (exit 2) naming the
 * option and the accepted extensions. A character device or FIFO (-o /dev/stdout) takes
 * the first format whatever its name. Called before any work, so a wrong name costs
 * nothing. */
int cli_output_format(const char *option, const char *path, const char *const *accepted,
                      int *format);

/* All-or-nothing outputs (sk_output_set in shitsukan/io.h) for a command's table of
 * outputs: each entry names its option (for messages), points at its path (NULL when the
 * option was not given; replaced by the staged path to write once reserved), lists the
 * accepted extensions (NULL = any) and says whether it is a folder. cli_reserve_outputs
 * checks every name and reserves every output before any work (one-line error and its exit
 * status on failure, with nothing left behind); cli_finish_outputs commits them after a
 * successful run (`status` 0) or removes them, and returns the final status. */
typedef struct cli_output {
    const char *option;
    const char **path;
    const char *const *formats;
    bool folder;
} cli_output;
int cli_reserve_outputs(const cli_output *list, int count, sk_output_set **set);
int cli_finish_outputs(sk_output_set *set, int status);

/* Applies --threads (0 = all cores) to the library's parallel loops. */
void cli_apply_threads(const cli_args *args);

#endif /* SK_TOOLS_CLI_H */
