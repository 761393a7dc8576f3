/* Command-line framework: option parsing, --help text, one-line errors with exit codes,
 * preset resolution and --set overrides (see cli.h). */
#define _POSIX_C_SOURCE 200809L
#include "cli.h"

#include "shitsukan/io.h"

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <unistd.h>

/* ------------------------------------------------------------------ errors */

int cli_fail(int status, const char *fmt, ...)
{
    char msg[1024];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    /* one line, whatever the message holds */
    for (char *c = msg; *c; c++)
        if (*c == '\n' || *c == '\r') *c = ' ';
    fprintf(stderr, "shitsukan: error: %s\n", msg);
    return status;
}

int cli_exit_status(sk_result result)
{
    switch (result) {
    case SK_OK:
        return CLI_EXIT_OK;
    case SK_ERROR_INVALID_ARGUMENT:
    case SK_ERROR_PARSE:
    case SK_ERROR_LIMIT:
    case SK_ERROR_UNSUPPORTED:
    case SK_ERROR_NOT_FOUND:
        return CLI_EXIT_USAGE;
    default:
        return CLI_EXIT_RUNTIME;
    }
}

int cli_fail_error(const sk_error *err)
{
    return cli_fail(cli_exit_status(err->result), "%s",
                    err->message[0] ? err->message : sk_result_string(err->result));
}

/* ------------------------------------------------------------------ groups */

bool cli_is_group(const char *group)
{
    size_t n = strlen(group);
    for (int i = 0; cli_commands[i]; i++) {
        const char *name = cli_commands[i]->name;
        if (strncmp(name, group, n) == 0 && name[n] == ' ') return true;
    }
    return false;
}

/* The subcommands of `group` from the command table, one line each. */
static void print_subcommands(const char *group, FILE *out)
{
    size_t n = strlen(group);
    for (int i = 0; cli_commands[i]; i++) {
        const char *name = cli_commands[i]->name;
        if (strncmp(name, group, n) == 0 && name[n] == ' ')
            fprintf(out, "  %-16s %s\n", name, cli_commands[i]->summary);
    }
}

void cli_group_subcommands(const char *group, char *out, size_t size)
{
    size_t n = strlen(group), used = 0;
    out[0] = '\0';
    for (int i = 0; cli_commands[i] && used < size; i++) {
        const char *name = cli_commands[i]->name;
        if (strncmp(name, group, n) == 0 && name[n] == ' ')
            used +=
                (size_t)snprintf(out + used, size - used, "%s%s", used ? ", " : "", name + n + 1);
    }
}

void cli_print_group_help(const char *group, FILE *out)
{
    fprintf(out, "usage: shitsukan %s <subcommand> [options]\n\nsubcommands:\n", group);
    print_subcommands(group, out);
    fprintf(out, "\n'shitsukan %s <subcommand> --help' shows a subcommand's options.\n", group);
}

/* ---------------------------------------------------------- common options */

typedef struct common_option {
    unsigned bit;
    const char *name;
    char short_name;
    const char *arg_name;
    const char *help;
} common_option;

static const common_option k_common[] = {
    {CLI_COMMON_OUTPUT, "output", 'o', "PATH", "output file or folder"},
    {CLI_COMMON_PRESET, "preset", 0, "NAME|FILE",
     "parameter preset: a shipped name (see 'shitsukan presets') or a JSON file"},
    {CLI_COMMON_SET, "set", 0, "KEY=VALUE",
     "override a preset key, e.g. --set levels[0].jitter=0.3 (repeatable)"},
    {CLI_COMMON_SEED, "seed", 0, "N", "random seed, an integer in [0, 2^53]"},
    {CLI_COMMON_THREADS, "threads", 0, "N", "threads to use; 0 = all cores (default)"},
    {CLI_COMMON_QUIET, "quiet", 'q', NULL, "no progress output"},
    {CLI_COMMON_MEMORY, "max-memory", 0, "SIZE",
     "refuse work planned to need more memory, e.g. 16G; default 8G"},
};
#define COMMON_COUNT ((int)(sizeof k_common / sizeof k_common[0]))

/* The common options a command takes: its mask, and --max-memory always. */
static unsigned common_mask(const cli_command *command)
{
    return command->common | CLI_COMMON_MEMORY;
}

static void print_option_line(FILE *out, char short_name, const char *name, const char *arg,
                              const char *help)
{
    char left[64];
    if (short_name)
        snprintf(left, sizeof left, "-%c, --%s%s%s", short_name, name, arg ? " " : "",
                 arg ? arg : "");
    else
        snprintf(left, sizeof left, "    --%s%s%s", name, arg ? " " : "", arg ? arg : "");
    fprintf(out, "  %-28s %s\n", left, help);
}

void cli_print_help(const cli_command *command, FILE *out)
{
    fprintf(out, "usage: %s\n\n", command->usage);
    if (command->description) fprintf(out, "%s\n\n", command->description);
    if (command->option_count > 0) {
        fprintf(out, "options:\n");
        for (int i = 0; i < command->option_count; i++) {
            const cli_option *o = &command->options[i];
            char help[512];
            snprintf(help, sizeof help, "%s", o->help);
            for (int k = 0; k < command->key_option_count; k++) {
                const cli_key_option *ko = &command->key_options[k];
                if (strcmp(ko->option, o->name) != 0) continue;
                size_t used = strlen(help);
                snprintf(help + used, sizeof help - used, " (key %s%s%s)", ko->key,
                         ko->value ? "=" : "", ko->value ? ko->value : "");
            }
            print_option_line(out, o->short_name, o->name, o->arg_name, help);
        }
        fprintf(out, "\n");
    }
    fprintf(out, "common options:\n");
    for (int i = 0; i < COMMON_COUNT; i++)
        if (common_mask(command) & k_common[i].bit)
            print_option_line(out, k_common[i].short_name, k_common[i].name, k_common[i].arg_name,
                              k_common[i].help);
    print_option_line(out, 'h', "help", NULL, "show this help and exit");
    if (command->schema)
        print_option_line(out, 0, "help-keys[=markdown]", NULL,
                          "list every preset key with its range and default (as a table)");
    if (command->examples) fprintf(out, "\nexamples:\n%s\n", command->examples);
    /* a command that also names a group (e.g. "skin" and "skin maps") lists the group */
    if (!strchr(command->name, ' ') && cli_is_group(command->name)) {
        fprintf(out, "\nsubcommands (see 'shitsukan %s <subcommand> --help'):\n", command->name);
        print_subcommands(command->name, out);
    }
}

/* ------------------------------------------------------------------ parsing */

static int find_option(const cli_command *command, const char *name, size_t len, char short_name)
{
    for (int i = 0; i < command->option_count; i++) {
        const cli_option *o = &command->options[i];
        if (short_name ? o->short_name == short_name
                       : (strlen(o->name) == len && strncmp(o->name, name, len) == 0))
            return i;
    }
    return -1;
}

static int find_common(const cli_command *command, const char *name, size_t len, char short_name)
{
    for (int i = 0; i < COMMON_COUNT; i++) {
        if (!(common_mask(command) & k_common[i].bit)) continue;
        if (short_name
                ? k_common[i].short_name == short_name
                : (strlen(k_common[i].name) == len && strncmp(k_common[i].name, name, len) == 0))
            return i;
    }
    return -1;
}

static int parse_u64(const char *text, uint64_t max, uint64_t *out)
{
    if (!text[0] || text[0] == '-' || text[0] == '+') return -1;
    errno = 0;
    char *end;
    unsigned long long v = strtoull(text, &end, 10);
    if (errno || *end || v > max) return -1;
    *out = v;
    return 0;
}

static int apply_common(const cli_command *command, int which, const char *value, cli_args *args)
{
    cli_common *c = &args->common;
    switch (k_common[which].bit) {
    case CLI_COMMON_OUTPUT:
        c->output = value;
        break;
    case CLI_COMMON_PRESET:
        c->preset = value;
        break;
    case CLI_COMMON_SET:
        if (c->set_count == CLI_MAX_SETS)
            return cli_fail(CLI_EXIT_USAGE, "%s: more than %d --set options", command->name,
                            CLI_MAX_SETS);
        c->sets[c->set_count++] = value;
        break;
    case CLI_COMMON_SEED:
        if (parse_u64(value, 9007199254740992ull, &c->seed) != 0)
            return cli_fail(CLI_EXIT_USAGE, "--seed '%s' must be an integer in [0, 2^53]", value);
        c->has_seed = true;
        break;
    case CLI_COMMON_THREADS: {
        uint64_t t;
        if (parse_u64(value, 1024, &t) != 0)
            return cli_fail(CLI_EXIT_USAGE, "--threads '%s' must be an integer in [0, 1024]",
                            value);
        c->threads = (int)t;
        break;
    }
    case CLI_COMMON_QUIET:
        c->quiet = true;
        break;
    case CLI_COMMON_MEMORY:
        if (!cli_parse_memory_size(value, &c->max_memory))
            return cli_fail(CLI_EXIT_USAGE,
                            "--max-memory '%s' must be a size in [1M, 1P], e.g. 512M or 16G",
                            value);
        break;
    }
    return 0;
}

static int store_option(const cli_command *command, int i, const char *value, cli_args *args)
{
    const cli_option *o = &command->options[i];
    if (args->count[i] > 0 && !o->repeatable)
        return cli_fail(CLI_EXIT_USAGE, "--%s given more than once", o->name);
    args->count[i]++;
    args->value[i] = value;
    if (o->repeatable) {
        if (args->values_count == CLI_MAX_VALUES)
            return cli_fail(CLI_EXIT_USAGE, "too many option values (at most %d)", CLI_MAX_VALUES);
        args->values[args->values_count] = value;
        args->values_option[args->values_count] = i;
        args->values_count++;
    }
    return 0;
}

int cli_parse(const cli_command *command, int argc, char **argv, cli_args *args)
{
    memset(args, 0, sizeof *args);
    args->common.max_memory = CLI_DEFAULT_MAX_MEMORY;
    bool only_positional = false;
    for (int k = 0; k < argc; k++) {
        const char *a = argv[k];
        if (only_positional || a[0] != '-' || a[1] == '\0') {
            if (args->positional_count == CLI_MAX_POSITIONAL)
                return cli_fail(CLI_EXIT_USAGE, "%s: too many arguments", command->name);
            args->positional[args->positional_count++] = a;
            continue;
        }
        if (strcmp(a, "--") == 0) {
            only_positional = true;
            continue;
        }
        if (strcmp(a, "-h") == 0 || strcmp(a, "--help") == 0) {
            cli_print_help(command, stdout);
            return -1;
        }
        if (strcmp(a, "--help-keys") == 0 && command->schema) {
            printf("preset keys of '%s' (key, type, accepted range, meaning; default):\n",
                   command->name);
            if (command->part_schema) sk_schema_print(command->part_schema, stdout);
            sk_schema_print(command->schema, stdout);
            return -1;
        }
        if (strcmp(a, "--help-keys=markdown") == 0 && command->schema) {
            /* the command's own keys: a second schema's are in its own docs */
            sk_schema_print_markdown(command->part_schema ? command->part_schema : command->schema,
                                     stdout);
            return -1;
        }
        const char *name, *inline_value = NULL;
        size_t len;
        char short_name = 0;
        if (a[1] == '-') {
            name = a + 2;
            const char *eq = strchr(name, '=');
            len = eq ? (size_t)(eq - name) : strlen(name);
            if (eq) inline_value = eq + 1;
        } else {
            short_name = a[1];
            name = a + 1;
            len = 1;
            if (a[2]) inline_value = a + 2;
        }
        int opt = find_option(command, name, len, short_name);
        int common = opt < 0 ? find_common(command, name, len, short_name) : -1;
        if (opt < 0 && common < 0)
            return cli_fail(CLI_EXIT_USAGE, "%s: unknown option '%s' (see 'shitsukan %s --help')",
                            command->name, a, command->name);
        const char *arg_name =
            opt >= 0 ? command->options[opt].arg_name : k_common[common].arg_name;
        const char *value = "";
        if (arg_name) {
            if (inline_value) {
                value = inline_value;
            } else if (k + 1 < argc) {
                value = argv[++k];
            } else {
                return cli_fail(CLI_EXIT_USAGE, "%s: option '%s' needs a value (%s)", command->name,
                                a, arg_name);
            }
        } else if (inline_value) {
            return cli_fail(CLI_EXIT_USAGE, "%s: option '%s' takes no value", command->name, a);
        }
        int status = opt >= 0 ? store_option(command, opt, value, args)
                              : apply_common(command, common, value, args);
        if (status != 0) return status;
    }
    if (args->positional_count < command->min_positional ||
        args->positional_count > command->max_positional) {
        if (command->max_positional == 0)
            return cli_fail(CLI_EXIT_USAGE,
                            "%s: unexpected argument '%s' (see 'shitsukan %s --help')",
                            command->name, args->positional[0], command->name);
        return cli_fail(CLI_EXIT_USAGE,
                        "%s: expected %d to %d arguments, got %d (see 'shitsukan %s --help')",
                        command->name, command->min_positional, command->max_positional,
                        args->positional_count, command->name);
    }
    return 0;
}

/* ------------------------------------------------------------------ access */

static int option_index(const cli_command *command, const char *name)
{
    int i = find_option(command, name, strlen(name), 0);
    if (i < 0) {
        /* a programming error in a command: the name must be one of its options */
        fprintf(stderr, "shitsukan: internal error: %s has no option --%s\n", command->name, name);
        abort();
    }
    return i;
}

const char *cli_get(const cli_command *command, const cli_args *args, const char *name)
{
    int i = option_index(command, name);
    return args->count[i] ? args->value[i] : NULL;
}

bool cli_has(const cli_command *command, const cli_args *args, const char *name)
{
    return args->count[option_index(command, name)] > 0;
}

bool cli_takes(const cli_command *command, const char *name)
{
    return find_option(command, name, strlen(name), 0) >= 0;
}

int cli_get_all(const cli_command *command, const cli_args *args, const char *name,
                const char **out, int max)
{
    int i = option_index(command, name), n = 0;
    for (int k = 0; k < args->values_count && n < max; k++)
        if (args->values_option[k] == i) out[n++] = args->values[k];
    return n;
}

int cli_get_int(const cli_command *command, const cli_args *args, const char *name,
                long long fallback, long long lo, long long hi, long long *out)
{
    const char *v = cli_get(command, args, name);
    if (!v) {
        *out = fallback;
        return 0;
    }
    errno = 0;
    char *end;
    long long x = strtoll(v, &end, 10);
    if (!v[0] || *end || errno || x < lo || x > hi)
        return cli_fail(CLI_EXIT_USAGE, "--%s '%s' must be an integer in [%lld, %lld]", name, v, lo,
                        hi);
    *out = x;
    return 0;
}

bool cli_parse_decimal(const char *text, double *out)
{
    /* [+-]digits[.digits][(e|E)[+-]digits], at least one digit before the exponent */
    const char *p = text;
    if (*p == '+' || *p == '-') p++;
    int digits = 0;
    while (*p >= '0' && *p <= '9') p++, digits++;
    if (*p == '.') {
        p++;
        while (*p >= '0' && *p <= '9') p++, digits++;
    }
    if (digits == 0) return false;
    if (*p == 'e' || *p == 'E') {
        p++;
        if (*p == '+' || *p == '-') p++;
        if (!(*p >= '0' && *p <= '9')) return false;
        while (*p >= '0' && *p <= '9') p++;
    }
    if (*p != '\0') return false;
    double x = strtod(text, NULL);
    if (!isfinite(x)) return false;
    *out = x;
    return true;
}

int cli_get_double(const cli_command *command, const cli_args *args, const char *name,
                   double fallback, double lo, double hi, double *out)
{
    const char *v = cli_get(command, args, name);
    if (!v) {
        *out = fallback;
        return 0;
    }
    double x;
    if (!cli_parse_decimal(v, &x) || x < lo || x > hi)
        return cli_fail(CLI_EXIT_USAGE, "--%s '%s' must be a number in [%g, %g]", name, v, lo, hi);
    *out = x;
    return 0;
}

int cli_get_size(const cli_command *command, const cli_args *args, const char *name, int fallback_w,
                 int fallback_h, int max, int *w, int *h)
{
    const char *v = cli_get(command, args, name);
    if (!v) {
        *w = fallback_w;
        *h = fallback_h;
        return 0;
    }
    char *end;
    errno = 0;
    long a = strtol(v, &end, 10), b = a;
    bool ok = end != v && !errno;
    if (ok && *end == 'x') {
        const char *second = end + 1;
        b = strtol(second, &end, 10);
        ok = end != second && !errno;
    }
    if (!ok || *end || a < 1 || b < 1 || a > max || b > max)
        return cli_fail(CLI_EXIT_USAGE, "--%s '%s' must be N or WxH with each in [1, %d]", name, v,
                        max);
    *w = (int)a;
    *h = (int)b;
    return 0;
}

int cli_parse_region(const char *text, int width, int height, int region[4])
{
    long long v[4];
    const char *p = text;
    for (int i = 0; i < 4; i++) {
        char *end = NULL;
        errno = 0;
        bool digit = (*p >= '0' && *p <= '9') || (*p == '-' && p[1] >= '0' && p[1] <= '9');
        if (digit) v[i] = strtoll(p, &end, 10);
        if (!digit || errno || (i < 3 ? *end != ',' : *end != '\0'))
            return cli_fail(CLI_EXIT_USAGE, "--region '%s' must be x,y,w,h (integers)", text);
        p = end + 1;
    }
    /* each term is bounded before the sums, so no sum can overflow */
    if (v[0] < 0 || v[1] < 0 || v[2] < 1 || v[3] < 1 || v[0] > width || v[1] > height ||
        v[2] > width - v[0] || v[3] > height - v[1])
        return cli_fail(CLI_EXIT_USAGE,
                        "--region '%s' must lie inside the %dx%d image (x, y >= 0, w, h >= 1, "
                        "x + w <= %d, y + h <= %d)",
                        text, width, height, width, height);
    for (int i = 0; i < 4; i++) region[i] = (int)v[i];
    return 0;
}

int cli_parse_numbers(const char *option, const char *text, int count, double *out)
{
    const char *p = text;
    for (int i = 0; i < count; i++) {
        size_t n = strcspn(p, ",");
        char item[64];
        bool last = i == count - 1;
        bool ok = n < sizeof item && (last ? p[n] == '\0' : p[n] == ',');
        if (ok) {
            memcpy(item, p, n);
            item[n] = '\0';
            ok = cli_parse_decimal(item, &out[i]);
        }
        if (!ok)
            return cli_fail(CLI_EXIT_USAGE, "--%s '%s' must be %d comma-separated numbers", option,
                            text, count);
        p += n + 1;
    }
    return 0;
}

/* ------------------------------------------------------------ memory, formats */

bool cli_parse_memory_size(const char *text, uint64_t *bytes)
{
    char number[64];
    size_t n = strspn(text, "0123456789.eE+");
    if (n == 0 || n >= sizeof number) return false;
    memcpy(number, text, n);
    number[n] = '\0';
    double v;
    if (!cli_parse_decimal(number, &v)) return false;
    static const struct {
        const char *suffix;
        double scale;
    } units[] = {{"", 1},
                 {"B", 1},
                 {"K", 1024.0},
                 {"KB", 1024.0},
                 {"KiB", 1024.0},
                 {"M", 1048576.0},
                 {"MB", 1048576.0},
                 {"MiB", 1048576.0},
                 {"G", 1073741824.0},
                 {"GB", 1073741824.0},
                 {"GiB", 1073741824.0},
                 {"T", 1099511627776.0},
                 {"TB", 1099511627776.0},
                 {"TiB", 1099511627776.0},
                 {"P", 1125899906842624.0},
                 {"PB", 1125899906842624.0},
                 {"PiB", 1125899906842624.0}};
    for (size_t i = 0; i < sizeof units / sizeof units[0]; i++) {
        if (strcasecmp(text + n, units[i].suffix) != 0) continue;
        double b = v * units[i].scale;
        if (!(b >= 1048576.0 && b <= 1125899906842624.0)) return false;
        *bytes = (uint64_t)b;
        return true;
    }
    return false;
}

double cli_image_bytes(double width, double height, double bytes_per_pixel)
{
    return width * height * bytes_per_pixel;
}

int cli_check_memory(const cli_args *args, double bytes, const char *driver)
{
    double cap = (double)args->common.max_memory;
    if (bytes <= cap) return 0;
    /* GiB with a decimal, or MiB below 1 GiB */
    const double gib = 1073741824.0, mib = 1048576.0;
    bool small = cap < gib;
    return cli_fail(CLI_EXIT_USAGE,
                    "%s needs about %.*f %s of memory, more than the cap of %.*f %s (make it "
                    "smaller, or raise the cap with --max-memory)",
                    driver, small ? 0 : 1, bytes / (small ? mib : gib), small ? "MiB" : "GiB",
                    small ? 0 : 1, cap / (small ? mib : gib), small ? "MiB" : "GiB");
}

int cli_check_image(int width, int height, int channels, const char *driver)
{
    double bytes = cli_image_bytes(width, height, 4.0 * channels);
    if (bytes <= (double)SK_IMAGE_MAX_BYTES) return 0;
    return cli_fail(CLI_EXIT_USAGE,
                    "%s of %d float channel(s) needs %.1f GiB, more than the %.0f GiB an image may "
                    "hold (make it smaller, or render parts with --region)",
                    driver, channels, bytes / 1073741824.0,
                    (double)SK_IMAGE_MAX_BYTES / 1073741824.0);
}

int cli_output_format(const char *option, const char *path, const char *const *accepted,
                      int *format)
{
    const char *slash = strrchr(path, '/');
    const char *base = slash ? slash + 1 : path;
    const char *dot = strrchr(base, '.');
    /* a device or FIFO (-o /dev/stdout, a named pipe) without a known extension gets the
       first format */
    struct stat st;
    bool stream = stat(path, &st) == 0 && (S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode));
    char list[128] = "";
    size_t used = 0;
    for (int i = 0; accepted[i]; i++) {
        if (dot && dot != base && strcasecmp(dot, accepted[i]) == 0) {
            *format = i;
            return 0;
        }
        int k = snprintf(list + used, sizeof list - used, "%s%s", i ? ", " : "", accepted[i]);
        if (k > 0 && (size_t)k < sizeof list - used) used += (size_t)k;
    }
    if (stream) {
        *format = 0;
        return 0;
    }
    bool image = strcmp(accepted[0], ".png") == 0 || strcmp(accepted[0], ".exr") == 0;
    return cli_fail(CLI_EXIT_USAGE, "%s '%s': unknown %s type (the name must end in %s)", option,
                    path, image ? "image" : "file", list);
}

int cli_reserve_outputs(const cli_output *list, int count, sk_output_set **set)
{
    *set = NULL;
    int format;
    for (int i = 0; i < count; i++)
        if (*list[i].path && list[i].formats) {
            int status = cli_output_format(list[i].option, *list[i].path, list[i].formats, &format);
            if (status) return status;
        }
    sk_error err = {0};
    sk_result r = sk_output_set_create(set, &err);
    /* folders first: a file may go inside one of them */
    for (int pass = 0; pass < 2; pass++)
        for (int i = 0; i < count && r == SK_OK; i++) {
            if (!*list[i].path || list[i].folder != (pass == 0)) continue;
            r = list[i].folder ? sk_output_set_folder(*set, *list[i].path, list[i].path, &err)
                               : sk_output_set_file(*set, *list[i].path, list[i].path, &err);
            if (r != SK_OK) sk_error_prefix(&err, r, "%s", list[i].option);
        }
    if (r != SK_OK) {
        sk_output_set_abort(*set);
        *set = NULL;
        return cli_fail_error(&err);
    }
    return 0;
}

int cli_finish_outputs(sk_output_set *set, int status)
{
    if (status) {
        sk_output_set_abort(set);
        return status;
    }
    sk_error err = {0};
    return sk_output_set_commit(set, &err) == SK_OK ? 0 : cli_fail_error(&err);
}

/* ------------------------------------------------------------------ presets */

static bool is_dir(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 && S_ISDIR(st.st_mode);
}

static bool is_file(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 && S_ISREG(st.st_mode);
}

bool cli_executable_dir(char *out, size_t size)
{
    char exe[PATH_MAX];
    ssize_t len = readlink("/proc/self/exe", exe, sizeof exe - 1);
    if (len <= 0) return false;
    exe[len] = '\0';
    char *slash = strrchr(exe, '/');
    if (!slash) return false;
    *slash = '\0';
    return (size_t)snprintf(out, size, "%s", exe) < size;
}

int cli_preset_dirs(const char **out, int max)
{
    /* Filled once per call into static storage: the process is single-threaded here. */
    static char installed[PATH_MAX];
    int n = 0;
    const char *env = getenv("SHITSUKAN_PRESET_DIR");
    if (env && env[0] && is_dir(env) && n < max) out[n++] = env;
    char exe[PATH_MAX];
    if (cli_executable_dir(exe, sizeof exe)) {
        snprintf(installed, sizeof installed, "%s/../share/shitsukan/presets", exe);
        if (is_dir(installed) && n < max) out[n++] = installed;
    }
    if (is_dir(SK_SOURCE_PRESET_DIR) && n < max) out[n++] = SK_SOURCE_PRESET_DIR;
    if (is_dir(SK_INSTALL_PRESET_DIR) && n < max) out[n++] = SK_INSTALL_PRESET_DIR;
    return n;
}

bool cli_find_preset(const char *module, const char *name, char *path, size_t size)
{
    const char *dirs[4];
    int n = cli_preset_dirs(dirs, 4);
    for (int i = 0; i < n; i++) {
        snprintf(path, size, "%s/%s/%s.json", dirs[i], module, name);
        if (is_file(path)) return true;
    }
    return false;
}

int cli_load_preset(const cli_command *command, const cli_args *args, sk_preset **out)
{
    *out = NULL;
    sk_error err = {0};
    sk_preset *preset = NULL;
    const char *name = args->common.preset;
    if (name) {
        char path[PATH_MAX];
        bool looks_like_file = strchr(name, '/') || strstr(name, ".json");
        if (looks_like_file) {
            snprintf(path, sizeof path, "%s", name);
        } else if (!command->preset_module ||
                   !cli_find_preset(command->preset_module, name, path, sizeof path)) {
            return cli_fail(CLI_EXIT_USAGE,
                            "--preset '%s': no such preset for '%s' (see 'shitsukan presets %s')",
                            name, command->name,
                            command->preset_module ? command->preset_module : "");
        }
        if (sk_preset_load_file(&preset, path, &err) != SK_OK) return cli_fail_error(&err);
    } else if (sk_preset_create(&preset, &err) != SK_OK) {
        return cli_fail_error(&err);
    }
    for (int i = 0; i < command->key_option_count; i++) {
        const cli_key_option *o = &command->key_options[i];
        if (!cli_has(command, args, o->option)) continue;
        char json[128], assignment[256];
        int status =
            cli_key_option_json(command, o, cli_get(command, args, o->option), json, sizeof json);
        if (status) {
            sk_preset_free(preset);
            return status;
        }
        snprintf(assignment, sizeof assignment, "%s=%s", o->key, json);
        if (sk_preset_set(preset, assignment, &err) != SK_OK) {
            sk_preset_free(preset);
            return cli_fail_error(&err);
        }
    }
    int hooked = command->set_option_keys ? command->set_option_keys(command, args, preset) : 0;
    if (hooked) {
        sk_preset_free(preset);
        return hooked;
    }
    for (int i = 0; i < args->common.set_count; i++) {
        if (sk_preset_set(preset, args->common.sets[i], &err) != SK_OK) {
            sk_preset_free(preset);
            return cli_fail_error(&err);
        }
    }
    if (args->common.has_seed) {
        char assignment[160];
        snprintf(assignment, sizeof assignment, "%s=%llu",
                 command->seed_key ? command->seed_key : "seed",
                 (unsigned long long)args->common.seed);
        if (sk_preset_set(preset, assignment, &err) != SK_OK) {
            sk_preset_free(preset);
            return cli_fail_error(&err);
        }
    }
    *out = preset;
    return 0;
}

int cli_bind_params(const cli_command *command, const cli_args *args, void *params)
{
    sk_preset *tree = NULL;
    int status = cli_load_preset(command, args, &tree);
    if (status) return status;
    sk_error err = {0};
    sk_result r = sk_preset_bind(tree, command->schema, params, &err);
    sk_preset_free(tree);
    return r == SK_OK ? 0 : cli_fail_error(&err);
}

void cli_apply_threads(const cli_args *args) { sk_threads_set(args->common.threads); }
