/* Tests of `shitsukan studio`'s HTTP server, end to end: the command serves a folder on
 * a free port and raw requests check the files, MIME types, the cross-origin isolation
 * headers, HEAD, and that no request reaches outside the folder (dot segments, encoded
 * dots, backslashes, hidden files, symbolic links out of it) or gets anything but GET/HEAD. */
#define _POSIX_C_SOURCE 200809L
#include <arpa/inet.h>
#include <netinet/in.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "test_support.h"

static pid_t g_server = -1;
static int g_port = 0;
static char g_root[512];

/* Sends `request` as is and returns the whole response (static buffer). */
static const char *exchange(const char *request, size_t *length)
{
    static char buf[1 << 16];
    int fd = socket(AF_INET, SOCK_STREAM, 0);
    assert_true(fd >= 0);
    struct sockaddr_in a = {.sin_family = AF_INET, .sin_port = htons((uint16_t)g_port)};
    inet_pton(AF_INET, "127.0.0.1", &a.sin_addr);
    assert_int_equal(connect(fd, (struct sockaddr *)&a, sizeof a), 0);
    size_t n = strlen(request);
    assert_int_equal(send(fd, request, n, 0), (ssize_t)n);
    size_t used = 0;
    ssize_t got;
    while ((got = recv(fd, buf + used, sizeof buf - 1 - used, 0)) > 0) used += (size_t)got;
    close(fd);
    buf[used] = '\0';
    if (length) *length = used;
    return buf;
}

static int status_of(const char *response)
{
    int status = 0;
    sscanf(response, "HTTP/1.1 %d", &status);
    return status;
}

static int get_status(const char *target)
{
    char req[2048];
    snprintf(req, sizeof req, "GET %s HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n", target);
    return status_of(exchange(req, NULL));
}

static int setup(void **state)
{
    (void)state;
    snprintf(g_root, sizeof g_root, "%s", sk_test_path("studio/www/index.html"));
    sk_test_write_file(g_root, "<!doctype html><title>t</title>\n", 32);
    *strrchr(g_root, '/') = '\0';
    char path[700];
    snprintf(path, sizeof path, "%s/js", g_root);
    mkdir(path, 0755);
    snprintf(path, sizeof path, "%s/js/main.js", g_root);
    sk_test_write_file(path, "export {};\n", 11);
    snprintf(path, sizeof path, "%s/m.wasm", g_root);
    sk_test_write_file(path, "\0asm\1\0\0\0", 8);
    snprintf(path, sizeof path, "%s/.secret", g_root);
    sk_test_write_file(path, "secret", 6);
    /* a file beside the root and a link to it from inside */
    snprintf(path, sizeof path, "%s/../outside.txt", g_root);
    sk_test_write_file(path, "outside", 7);
    snprintf(path, sizeof path, "%s/link.txt", g_root);
    unlink(path);
    assert_int_equal(symlink("../outside.txt", path), 0);

    int pipefd[2];
    assert_int_equal(pipe(pipefd), 0);
    g_server = fork();
    assert_true(g_server >= 0);
    if (g_server == 0) {
        dup2(pipefd[1], 1);
        close(pipefd[0]);
        execl(SK_TEST_CLI, SK_TEST_CLI, "studio", "--port", "0", "--quiet", "--root", g_root,
              (char *)NULL);
        _exit(127);
    }
    close(pipefd[1]);
    FILE *out = fdopen(pipefd[0], "r");
    char line[1024];
    while (fgets(line, sizeof line, out))
        if (sscanf(line, "http://127.0.0.1:%d/", &g_port) == 1) break;
    fclose(out);
    assert_true(g_port > 0);
    return 0;
}

static int teardown(void **state)
{
    (void)state;
    if (g_server > 0) {
        kill(g_server, SIGTERM);
        int st;
        waitpid(g_server, &st, 0);
        /* SIGTERM stops it cleanly */
        assert_true(WIFEXITED(st) && WEXITSTATUS(st) == 0);
    }
    return 0;
}

static void test_serves_files_with_types_and_isolation(void **state)
{
    (void)state;
    size_t n;
    const char *r = exchange("GET / HTTP/1.1\r\nHost: x\r\n\r\n", &n);
    assert_int_equal(status_of(r), 200);
    assert_non_null(strstr(r, "Content-Type: text/html; charset=utf-8\r\n"));
    assert_non_null(strstr(r, "Cross-Origin-Opener-Policy: same-origin\r\n"));
    assert_non_null(strstr(r, "Cross-Origin-Embedder-Policy: require-corp\r\n"));
    assert_non_null(strstr(r, "Content-Length: 32\r\n"));
    assert_non_null(strstr(r, "\r\n\r\n<!doctype html>"));
    r = exchange("GET /js/main.js?v=3 HTTP/1.1\r\n\r\n", NULL);
    assert_int_equal(status_of(r), 200);
    assert_non_null(strstr(r, "Content-Type: text/javascript; charset=utf-8\r\n"));
    r = exchange("GET /m.wasm HTTP/1.0\r\n\r\n", &n);
    assert_non_null(strstr(r, "Content-Type: application/wasm\r\n"));
    assert_int_equal(memcmp(r + n - 8, "\0asm\1\0\0\0", 8), 0);
    /* HEAD: the headers alone */
    r = exchange("HEAD /js/main.js HTTP/1.1\r\n\r\n", &n);
    assert_int_equal(status_of(r), 200);
    assert_non_null(strstr(r, "Content-Length: 11\r\n"));
    assert_int_equal(strlen(strstr(r, "\r\n\r\n")), 4);
    /* a percent-encoded name */
    assert_int_equal(get_status("/js/%6dain.js"), 200);
}

static void test_nothing_outside_the_root(void **state)
{
    (void)state;
    const char *bad[] = {"/../outside.txt",
                         "/js/../../outside.txt",
                         "/%2e%2e/outside.txt",
                         "/%2E%2E%2Foutside.txt",
                         "/.secret",
                         "/js/..%5c..%5coutside.txt",
                         "/link.txt",
                         "/js/./main.js",
                         "//etc/passwd",
                         "/js",
                         "/nope.html",
                         "/a%00b"};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        int s = get_status(bad[i]);
        if (s != 404 && s != 400) fprintf(stderr, "%s -> %d\n", bad[i], s);
        assert_true(s == 404 || s == 400);
    }
    assert_int_equal(get_status("/a%zz"), 400);
    assert_int_equal(get_status("http://evil/"), 400);
}

static void test_bad_requests(void **state)
{
    (void)state;
    const char *r = exchange("POST / HTTP/1.1\r\nContent-Length: 0\r\n\r\n", NULL);
    assert_int_equal(status_of(r), 405);
    assert_non_null(strstr(r, "Allow: GET, HEAD\r\n"));
    assert_int_equal(status_of(exchange("GET / HTTP/2.0\r\n\r\n", NULL)), 505);
    assert_int_equal(status_of(exchange("GARBAGE\r\n\r\n", NULL)), 400);
    assert_int_equal(status_of(exchange("GET / HTTP/1.1\r\n folded\r\n\r\n", NULL)), 400);
    static char big[12000];
    memset(big, 'a', sizeof big - 1);
    memcpy(big, "GET /", 5);
    assert_int_equal(status_of(exchange(big, NULL)), 431);
    char longpath[2100] = "GET /";
    memset(longpath + 5, 'b', 1500);
    strcpy(longpath + 1505, " HTTP/1.1\r\n\r\n");
    assert_int_equal(status_of(exchange(longpath, NULL)), 414);
    /* still serving after all that */
    assert_int_equal(get_status("/"), 200);
}

static void test_cli_errors(void **state)
{
    (void)state;
    sk_test_run run;
    assert_int_equal(sk_test_cli(&run, "studio --root /nonexistent-folder"), 2);
    assert_non_null(strstr(run.err, "must be a folder"));
    assert_int_equal(sk_test_cli(&run, "studio --port 70000"), 2);
    assert_int_equal(sk_test_cli(&run, "studio --help"), 0);
    assert_non_null(strstr(run.out, "--port"));
}

int main(void)
{
    signal(SIGPIPE, SIG_IGN);
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_serves_files_with_types_and_isolation),
        cmocka_unit_test(test_nothing_outside_the_root),
        cmocka_unit_test(test_bad_requests),
        cmocka_unit_test(test_cli_errors),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
