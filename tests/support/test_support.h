/* Shared helpers for the cmocka tests: temporary paths, running the command-line tool,
 * reading files. Every test executable links this. */
#ifndef SK_TEST_SUPPORT_H
#define SK_TEST_SUPPORT_H

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdbool.h>

/* A fresh path under the test build's tmp folder: "<tmp>/<test>-<name>". Folders in
 * `name` are created. Returns a static buffer rotated over 8 slots. */
const char *sk_test_path(const char *name);

/* Runs the shitsukan command with a shell-quoted argument string (e.g. "skin --help"),
 * captures stdout and stderr (each truncated to the buffer size) and returns the exit
 * status (or -1 if it did not exit normally). $SK_TEST_CLI_WRAPPER, if set, is put before
 * the command (make test-valgrind runs it under valgrind this way). */
typedef struct sk_test_run {
    int status;
    char out[65536];
    char err[16384];
} sk_test_run;
int sk_test_cli(sk_test_run *run, const char *args_fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/* Number of lines in a NUL-terminated text (a final line without newline counts). */
int sk_test_count_lines(const char *text);
bool sk_test_file_exists(const char *path);
/* True if both files exist and hold the same bytes. */
bool sk_test_same_file(const char *a, const char *b);
/* Writes `size` bytes to path (for malformed-input tests). */
void sk_test_write_file(const char *path, const void *data, size_t size);
/* The whole text of a file, NUL-terminated (free()), or NULL if it cannot be read. */
char *sk_test_read_file(const char *path);
/* Lists names in folder containing `needle` (e.g. ".tmp"), returns the count. */
int sk_test_count_files_containing(const char *folder, const char *needle);
/* Sends `signal_number` to `child`, waits for it and asserts it ended by that signal. */
void sk_test_kill_and_reap(int child, int signal_number);

#endif
