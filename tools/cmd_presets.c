/* `shitsukan presets`: lists the shipped presets with their one-line descriptions, and
 * prints one preset's JSON. */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <limits.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "shitsukan/io.h"

static int compare_names(const void *a, const void *b)
{
    return strcmp(*(const char *const *)a, *(const char *const *)b);
}

/* Sorted names of the entries of `folder` (files ending in `suffix`, or folders if NULL). */
static int list_entries(const char *folder, const char *suffix, char ***out)
{
    *out = NULL;
    DIR *dir = opendir(folder);
    if (!dir) return 0;
    int n = 0, cap = 0;
    char **names = NULL;
    struct dirent *e;
    while ((e = readdir(dir)) != NULL) {
        if (e->d_name[0] == '.') continue;
        size_t len = strlen(e->d_name);
        if (suffix) {
            size_t sl = strlen(suffix);
            if (len <= sl || strcmp(e->d_name + len - sl, suffix) != 0) continue;
        } else {
            char path[PATH_MAX];
            snprintf(path, sizeof path, "%s/%s", folder, e->d_name);
            DIR *sub = opendir(path);
            if (!sub) continue;
            closedir(sub);
        }
        if (n == cap) {
            cap = cap ? cap * 2 : 32;
            char **grown = realloc(names, (size_t)cap * sizeof *names);
            if (!grown) break;
            names = grown;
        }
        names[n] = strdup(e->d_name);
        if (names[n]) n++;
    }
    closedir(dir);
    qsort(names, (size_t)n, sizeof *names, compare_names);
    *out = names;
    return n;
}

static void free_entries(char **names, int n)
{
    for (int i = 0; i < n; i++) free(names[i]);
    free(names);
}

static int list_module(const char *root, const char *module)
{
    char folder[PATH_MAX];
    snprintf(folder, sizeof folder, "%s/%s", root, module);
    char **files;
    int n = list_entries(folder, ".json", &files);
    for (int i = 0; i < n; i++) {
        char path[PATH_MAX];
        snprintf(path, sizeof path, "%s/%s", folder, files[i]);
        sk_preset *preset = NULL;
        const char *description = NULL;
        if (sk_preset_load_file(&preset, path, NULL) == SK_OK)
            description = sk_preset_get_string(preset, "description");
        files[i][strlen(files[i]) - 5] = '\0'; /* drop ".json" */
        printf("%-10s %-28s %s\n", module, files[i], description ? description : "");
        sk_preset_free(preset);
    }
    free_entries(files, n);
    return n;
}

static int run_presets(const cli_command *command, const cli_args *args)
{
    const char *dirs[4];
    if (cli_preset_dirs(dirs, 4) == 0)
        return cli_fail(CLI_EXIT_RUNTIME, "no preset folder found (set SHITSUKAN_PRESET_DIR)");
    const char *root = dirs[0];
    if (args->positional_count == 2) {
        /* presets MODULE NAME: print the preset file */
        char path[PATH_MAX];
        if (!cli_find_preset(args->positional[0], args->positional[1], path, sizeof path))
            return cli_fail(CLI_EXIT_USAGE, "no preset '%s' in module '%s'", args->positional[1],
                            args->positional[0]);
        char *text;
        sk_error err = {0};
        if (sk_read_file(path, 0, &text, NULL, &err) != SK_OK) return cli_fail_error(&err);
        fputs(text, stdout);
        free(text);
        return CLI_EXIT_OK;
    }
    if (args->positional_count == 1) {
        char folder[PATH_MAX];
        snprintf(folder, sizeof folder, "%s/%s", root, args->positional[0]);
        DIR *d = opendir(folder);
        if (!d) {
            /* name the modules there are */
            char **modules;
            int n = list_entries(root, NULL, &modules);
            char names[512] = "";
            size_t used = 0;
            for (int i = 0; i < n && used < sizeof names; i++)
                used += (size_t)snprintf(names + used, sizeof names - used, "%s%s", i ? ", " : "",
                                         modules[i]);
            free_entries(modules, n);
            return cli_fail(CLI_EXIT_USAGE, "no preset module '%s' (modules: %s)",
                            args->positional[0], names);
        }
        closedir(d);
        list_module(root, args->positional[0]);
        return CLI_EXIT_OK;
    }
    char **modules;
    int n = list_entries(root, NULL, &modules);
    for (int i = 0; i < n; i++) list_module(root, modules[i]);
    free_entries(modules, n);
    (void)command;
    return CLI_EXIT_OK;
}

const cli_command cmd_presets = {
    .name = "presets",
    .summary = "list the shipped parameter presets, or print one",
    .usage = "shitsukan presets [MODULE [NAME]]",
    .description = "Without arguments lists every shipped preset as 'module name description'.\n"
                   "With MODULE lists that module's presets; with MODULE NAME prints the preset's\n"
                   "JSON. Presets are found in $SHITSUKAN_PRESET_DIR, the installed share folder,\n"
                   "or the source tree's presets/ folder.",
    .examples = "  shitsukan presets\n  shitsukan presets skin\n  shitsukan presets skin fig19a",
    .min_positional = 0,
    .max_positional = 2,
    .run = run_presets,
};
