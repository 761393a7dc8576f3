/* `shitsukan studio`: serves the browser studio (the library compiled to WebAssembly,
 * the page drawn with three.js; built by `make studio`) on a local HTTP server and
 * prints its address. Finding the folder and the options only; the server is http.h. */
#define _POSIX_C_SOURCE 200809L
#include <arpa/inet.h>
#include <limits.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "cli.h"
#include "http.h"

static volatile sig_atomic_t g_stop = 0;

static void on_signal(int sig)
{
    (void)sig;
    g_stop = 1;
}

static bool has_page(const char *dir)
{
    char path[PATH_MAX];
    struct stat st;
    snprintf(path, sizeof path, "%s/index.html", dir);
    return stat(path, &st) == 0 && S_ISREG(st.st_mode);
}

/* The studio's folder: $SHITSUKAN_STUDIO_DIR, the installed share folder beside the
 * executable, then the source tree's build-wasm/www. */
static bool find_root(char *out, size_t size)
{
    const char *env = getenv("SHITSUKAN_STUDIO_DIR");
    if (env && env[0] && has_page(env)) {
        snprintf(out, size, "%s", env);
        return true;
    }
    char exe[PATH_MAX];
    if (cli_executable_dir(exe, sizeof exe)) {
        snprintf(out, size, "%s/../share/shitsukan/studio", exe);
        if (has_page(out)) return true;
    }
    snprintf(out, size, "%s", SK_SOURCE_STUDIO_DIR);
    return has_page(out);
}

typedef struct ready_note {
    const char *host, *root;
} ready_note;

static void on_ready(void *user, int port)
{
    const ready_note *note = user;
    printf("shitsukan studio: serving %s\nhttp://%s:%d/\n", note->root, note->host, port);
    fflush(stdout);
}

static const cli_option k_options[] = {
    {"port", 'p', "N", "TCP port, 0 = any free port; default 8765", false},
    {"host", 0, "ADDR", "IPv4 address to listen on; default 127.0.0.1 (this machine only)", false},
    {"root", 0, "DIR", "folder to serve; default the studio built by 'make studio'", false},
};

static int run_studio(const cli_command *command, const cli_args *args)
{
    long long port;
    int status = cli_get_int(command, args, "port", 8765, 0, 65535, &port);
    if (status) return status;
    const char *host = cli_get(command, args, "host");
    if (!host) host = "127.0.0.1";
    struct in_addr address;
    if (inet_pton(AF_INET, host, &address) != 1)
        return cli_fail(CLI_EXIT_USAGE, "--host '%s' must be an IPv4 address such as 127.0.0.1",
                        host);
    char root[PATH_MAX];
    const char *given = cli_get(command, args, "root");
    if (given) {
        snprintf(root, sizeof root, "%s", given);
        struct stat st;
        if (stat(root, &st) != 0 || !S_ISDIR(st.st_mode))
            return cli_fail(CLI_EXIT_USAGE, "--root '%s' must be a folder", given);
        if (!has_page(root))
            return cli_fail(CLI_EXIT_USAGE, "--root '%s': no index.html there", given);
    } else if (!find_root(root, sizeof root)) {
        return cli_fail(
            CLI_EXIT_USAGE,
            "the studio is not built: run 'make studio' (needs emscripten), or give --root DIR");
    }
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal;
    sigaction(SIGINT, &sa, NULL);
    sigaction(SIGTERM, &sa, NULL);
    ready_note note = {host, root};
    char error[512];
    if (http_serve(root, host, (int)port, &g_stop, on_ready, &note,
                   args->common.quiet ? NULL : stderr, error, sizeof error) != 0)
        return cli_fail(CLI_EXIT_RUNTIME, "%s", error);
    return CLI_EXIT_OK;
}

const cli_command cmd_studio = {
    .name = "studio",
    .summary = "the browser studio: the models live in a web page (serves it locally)",
    .usage = "shitsukan studio [--port N] [--host ADDR] [--root DIR]",
    .description =
        "Serves the studio, a web page where the library itself (compiled to WebAssembly)\n"
        "runs the models: the hand posed with a slider per joint and its natural coupling,\n"
        "keyframes, the computer keyboard playing a piano with the hand (Yasumuro 2000,\n"
        "sec. 4.2), and every skin and wood preset key as a control with live maps,\n"
        "exported as the files 'skin maps' and 'wood cut' write. Open the printed address\n"
        "in a browser; Ctrl-C stops. Only files under the folder are served (GET, HEAD),\n"
        "with the cross-origin isolation headers; any static server can serve it too.\n"
        "Build the page first with 'make studio'.",
    .examples = "  shitsukan studio\n"
                "  shitsukan studio --port 0 --quiet",
    .options = k_options,
    .option_count = (int)(sizeof k_options / sizeof k_options[0]),
    .common = CLI_COMMON_QUIET,
    .min_positional = 0,
    .max_positional = 0,
    .run = run_studio,
};
