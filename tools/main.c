/* The `shitsukan` command: dispatches to a subcommand (one or two words) and maps
 * results to exit codes (0 ok, 1 runtime failure, 2 bad usage or input). */
#include <stdbool.h>
#include <stdio.h>
#include <string.h>

#include "cli.h"

static void print_tool_help(FILE *out)
{
    fprintf(out,
            "usage: shitsukan <command> [options]\n"
            "       shitsukan --version | --help\n\n"
            "Builds how living and natural things look and move from their structure.\n\n"
            "commands:\n");
    for (int i = 0; cli_commands[i]; i++)
        fprintf(out, "  %-16s %s\n", cli_commands[i]->name, cli_commands[i]->summary);
    fprintf(out, "\n'shitsukan <command> --help' shows a command's options.\n"
                 "Exit status: 0 success, 1 runtime failure, 2 bad usage or input.\n");
}

/* Whether `word` is the first word of two-word commands (a group such as "hand"). */
static bool is_group(const char *word)
{
    size_t n = strlen(word);
    for (int i = 0; cli_commands[i]; i++) {
        const char *space = strchr(cli_commands[i]->name, ' ');
        if (space && (size_t)(space - cli_commands[i]->name) == n && strncmp(cli_commands[i]->name, word, n) == 0)
            return true;
    }
    return false;
}

static void print_group_help(FILE *out, const char *group)
{
    size_t n = strlen(group);
    fprintf(out, "usage: shitsukan %s <command> [options]\n\ncommands:\n", group);
    for (int i = 0; cli_commands[i]; i++) {
        const char *name = cli_commands[i]->name;
        if (strncmp(name, group, n) == 0 && (name[n] == ' ' || name[n] == '\0'))
            fprintf(out, "  %-16s %s\n", name, cli_commands[i]->summary);
    }
    fprintf(out, "\n'shitsukan %s <command> --help' shows a command's options.\n", group);
}

/* The command whose name matches argv[1] (and argv[2] for two-word names). */
static const cli_command *find_command(int argc, char **argv, int *words)
{
    const cli_command *one = NULL;
    for (int i = 0; cli_commands[i]; i++) {
        const char *name = cli_commands[i]->name;
        const char *space = strchr(name, ' ');
        if (space) {
            size_t first = (size_t)(space - name);
            if (argc > 2 && strlen(argv[1]) == first && strncmp(argv[1], name, first) == 0 &&
                strcmp(argv[2], space + 1) == 0) {
                *words = 2;
                return cli_commands[i];
            }
        } else if (strcmp(argv[1], name) == 0) {
            one = cli_commands[i];
        }
    }
    *words = 1;
    return one;
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        print_tool_help(stderr);
        return CLI_EXIT_USAGE;
    }
    if (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0 ||
        strcmp(argv[1], "help") == 0) {
        print_tool_help(stdout);
        return CLI_EXIT_OK;
    }
    if (strcmp(argv[1], "--version") == 0) {
        printf("shitsukan %s\n", SK_VERSION_STRING);
        return CLI_EXIT_OK;
    }
    int words;
    const cli_command *command = find_command(argc, argv, &words);
    /* a group's own help: "shitsukan tissue --help" (or the group alone, as usage) */
    if (!command && is_group(argv[1])) {
        bool asked = argc > 2 && (strcmp(argv[2], "--help") == 0 || strcmp(argv[2], "-h") == 0);
        if (asked || argc == 2) {
            print_group_help(asked ? stdout : stderr, argv[1]);
            return asked ? CLI_EXIT_OK : CLI_EXIT_USAGE;
        }
        return cli_fail(CLI_EXIT_USAGE, "unknown command '%s %s' (see 'shitsukan %s --help')", argv[1], argv[2], argv[1]);
    }
    if (!command)
        return cli_fail(CLI_EXIT_USAGE, "unknown command '%s' (see 'shitsukan --help')", argv[1]);
    cli_args args;
    int status = cli_parse(command, argc - 1 - words, argv + 1 + words, &args);
    if (status < 0) return CLI_EXIT_OK; /* --help */
    if (status > 0) return status;
    cli_apply_threads(&args);
    return command->run(command, &args);
}
