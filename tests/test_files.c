/* Tests of the file helpers of io.h: atomic writing (temporary file beside the target,
 * renamed on commit, removed on abort), capped whole-file reading, folder creation. The
 * image and mesh formats have their own tests (test_images.c, test_formats_mesh.c). */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "shitsukan/io.h"
#include "test_support.h"

static void test_atomic_file_commit_and_abort(void **state)
{
    (void)state;
    const char *path = sk_test_path("io/atomic/out.txt");
    unlink(path);
    char folder[1024];
    snprintf(folder, sizeof folder, "%s", path);
    *strrchr(folder, '/') = '\0';
    sk_atomic_file f;
    sk_error err = {0};
    assert_int_equal(sk_atomic_file_open(&f, path, &err), SK_OK);
    fputs("hello", f.fp);
    /* nothing under the final name before commit */
    assert_false(sk_test_file_exists(path));
    assert_int_equal(sk_test_count_files_containing(folder, ".tmp"), 1);
    assert_int_equal(sk_atomic_file_commit(&f, &err), SK_OK);
    assert_true(sk_test_file_exists(path));
    assert_int_equal(sk_test_count_files_containing(folder, ".tmp"), 0);
    char *text;
    size_t size;
    assert_int_equal(sk_read_file(path, 0, &text, &size, &err), SK_OK);
    assert_string_equal(text, "hello");
    free(text);

    /* an aborted rewrite leaves the old file and no temporary */
    assert_int_equal(sk_atomic_file_open(&f, path, &err), SK_OK);
    fputs("partial", f.fp);
    sk_atomic_file_abort(&f);
    assert_int_equal(sk_read_file(path, 0, &text, &size, &err), SK_OK);
    assert_string_equal(text, "hello");
    free(text);
    assert_int_equal(sk_test_count_files_containing(folder, ".tmp"), 0);

    /* a folder that does not exist */
    assert_int_equal(sk_atomic_file_open(&f, sk_test_path("io/no-such-dir-x/"), &err),
                     SK_ERROR_INVALID_ARGUMENT);
    char missing[1100];
    snprintf(missing, sizeof missing, "%s/nowhere/deeper/out.txt", folder);
    assert_int_equal(sk_atomic_file_open(&f, missing, &err), SK_ERROR_IO);
    assert_non_null(strstr(err.message, "cannot create"));
}

static void test_read_file_cap_and_missing(void **state)
{
    (void)state;
    const char *path = sk_test_path("io/cap.bin");
    char data[1000];
    memset(data, 'x', sizeof data);
    sk_test_write_file(path, data, sizeof data);
    char *text;
    size_t size;
    sk_error err = {0};
    assert_int_equal(sk_read_file(path, 999, &text, &size, &err), SK_ERROR_LIMIT);
    assert_null(text);
    assert_int_equal(sk_read_file(path, 1000, &text, &size, &err), SK_OK);
    assert_int_equal(size, 1000);
    free(text);
    assert_int_equal(sk_read_file(sk_test_path("io/none.bin"), 0, &text, &size, &err),
                     SK_ERROR_NOT_FOUND);
    assert_int_equal(sk_make_dirs(sk_test_path("io/a/b/c"), &err), SK_OK);
    assert_int_equal(sk_make_dirs(path, &err), SK_ERROR_IO); /* a file, not a folder */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_atomic_file_commit_and_abort),
        cmocka_unit_test(test_read_file_cap_and_missing),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
