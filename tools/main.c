/* The `shitsukan` command: dispatches to a subcommand (one or two words) and maps
 * results to exit codes (0 ok, 1 runtime failure, 2 bad usage or input). */
#include <stdbool.h>
#include <stdio.h>
#include <string.h>

#include "cli.h"

static void print_tool_help(FILE *out)
{
    fprintf(out, "usage: shitsukan <command> [options]\n"
                 "       shitsukan --version | --help\n\n"
                 "Builds how living and natural things look and move from their structure.\n\n"
                 "commands:\n");
    for (int i = 0; cli_commands[i]; i++)
        fprintf(out, "  %-16s %s\n", cli_commands[i]->name, cli_commands[i]->summary);
    fprintf(out, "\n'shitsukan <command> --help' shows a command's options.\n"
                 "Exit status: 0 success, 1 runtime failure, 2 bad usage or input.\n");
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
    if (!command && cli_is_group(argv[1])) {
        /* a group word alone, with --help, or with an unknown subcommand */
        if (argc > 2 && (strcmp(argv[2], "--help") == 0 || strcmp(argv[2], "-h") == 0)) {
            cli_print_group_help(argv[1], stdout);
            return CLI_EXIT_OK;
        }
        if (argc > 2 && argv[2][0] != '-')
            return cli_fail(CLI_EXIT_USAGE, "unknown command '%s %s' (see 'shitsukan %s --help')",
                            argv[1], argv[2], argv[1]);
        char names[256];
        cli_group_subcommands(argv[1], names, sizeof names);
        return cli_fail(CLI_EXIT_USAGE, "'%s' needs a subcommand: %s (see 'shitsukan %s --help')",
                        argv[1], names, argv[1]);
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
