/* Shared helpers for the cmocka tests (see test_support.h). */
#define _POSIX_C_SOURCE 200809L
#include "test_support.h"

#include <dirent.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "shitsukan/io.h"

const char *sk_test_path(const char *name)
{
    static char slots[8][1024];
    static int next;
    char *buf = slots[next++ & 7];
    snprintf(buf, sizeof slots[0], "%s/%s", SK_TEST_TMP_DIR, name);
    char *slash = strrchr(buf, '/');
    if (slash) {
        *slash = '\0';
        sk_make_dirs(buf, NULL);
        *slash = '/';
    }
    return buf;
}

static void read_all(const char *path, char *dst, size_t cap)
{
    dst[0] = '\0';
    FILE *fp = fopen(path, "rb");
    if (!fp) return;
    size_t n = fread(dst, 1, cap - 1, fp);
    dst[n] = '\0';
    fclose(fp);
}

int sk_test_cli(sk_test_run *run, const char *args_fmt, ...)
{
    char args[8192];
    va_list ap;
    va_start(ap, args_fmt);
    vsnprintf(args, sizeof args, args_fmt, ap);
    va_end(ap);
    char out_path[1024], err_path[1024];
    snprintf(out_path, sizeof out_path, "%s/cli-%d.out", SK_TEST_TMP_DIR, (int)getpid());
    snprintf(err_path, sizeof err_path, "%s/cli-%d.err", SK_TEST_TMP_DIR, (int)getpid());
    char cmd[12288];
    /* SK_TEST_CLI_WRAPPER (e.g. valgrind and its options) runs the command under a tool */
    const char *wrapper = getenv("SK_TEST_CLI_WRAPPER");
    snprintf(cmd, sizeof cmd, "%s '%s' %s >'%s' 2>'%s' </dev/null", wrapper ? wrapper : "",
             SK_TEST_CLI, args, out_path, err_path);
    int status = system(cmd);
    run->status = (status != -1 && WIFEXITED(status)) ? WEXITSTATUS(status) : -1;
    read_all(out_path, run->out, sizeof run->out);
    read_all(err_path, run->err, sizeof run->err);
    unlink(out_path);
    unlink(err_path);
    return run->status;
}

int sk_test_count_lines(const char *text)
{
    int n = 0;
    const char *p = text;
    while (*p) {
        n++;
        const char *nl = strchr(p, '\n');
        if (!nl) break;
        p = nl + 1;
    }
    return n;
}

bool sk_test_file_exists(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0;
}

void sk_test_write_file(const char *path, const void *data, size_t size)
{
    FILE *fp = fopen(path, "wb");
    assert_non_null(fp);
    assert_int_equal(fwrite(data, 1, size, fp), size);
    fclose(fp);
}

void sk_test_kill_and_reap(int child, int signal_number)
{
    assert_int_equal(kill(child, signal_number), 0);
    int status;
    assert_int_equal(waitpid(child, &status, 0), child);
    assert_true(WIFSIGNALED(status) && WTERMSIG(status) == signal_number);
}

int sk_test_count_files_containing(const char *folder, const char *needle)
{
    DIR *dir = opendir(folder);
    if (!dir) return 0;
    int n = 0;
    struct dirent *e;
    while ((e = readdir(dir)) != NULL)
        if (strstr(e->d_name, needle)) n++;
    closedir(dir);
    return n;
}

bool sk_test_same_file(const char *a, const char *b)
{
    char *da = NULL, *db = NULL;
    size_t na = 0, nb = 0;
    bool same = sk_read_file(a, 0, &da, &na, NULL) == SK_OK &&
                sk_read_file(b, 0, &db, &nb, NULL) == SK_OK && na == nb && memcmp(da, db, na) == 0;
    free(da);
    free(db);
    return same;
}

char *sk_test_read_file(const char *path)
{
    char *text = NULL;
    return sk_read_file(path, 0, &text, NULL, NULL) == SK_OK ? text : NULL;
}
