/* Tests of the `shitsukan` command's framework: help, version, exit codes and one-line
 * errors for bad usage. Module commands have their own tests in their modules' files. */
#include <string.h>

#include "test_support.h"

static sk_test_run g_run;

static void assert_one_line_error(const sk_test_run *run, int status)
{
    assert_int_equal(run->status, status);
    assert_int_equal(sk_test_count_lines(run->err), 1);
    assert_true(strncmp(run->err, "shitsukan: error: ", 18) == 0);
}

static void test_version_and_help(void **state)
{
    (void)state;
    assert_int_equal(sk_test_cli(&g_run, "--version"), 0);
    assert_true(strncmp(g_run.out, "shitsukan ", 10) == 0);
    assert_int_equal(sk_test_cli(&g_run, "--help"), 0);
    assert_non_null(strstr(g_run.out, "usage: shitsukan <command>"));
    assert_non_null(strstr(g_run.out, "presets"));
    assert_int_equal(sk_test_cli(&g_run, "presets --help"), 0);
    assert_non_null(strstr(g_run.out, "usage: shitsukan presets"));
    assert_string_equal(g_run.err, "");
}

static void test_bad_usage_exits_2_with_one_line(void **state)
{
    (void)state;
    sk_test_cli(&g_run, "%s", "");
    assert_int_equal(g_run.status, 2);
    sk_test_cli(&g_run, "no-such-command");
    assert_one_line_error(&g_run, 2);
    assert_non_null(strstr(g_run.err, "unknown command 'no-such-command'"));
    sk_test_cli(&g_run, "presets --no-such-option");
    assert_one_line_error(&g_run, 2);
    assert_non_null(strstr(g_run.err, "unknown option '--no-such-option'"));
    sk_test_cli(&g_run, "presets a b c");
    assert_one_line_error(&g_run, 2);
    sk_test_cli(&g_run, "presets no-such-module");
    assert_one_line_error(&g_run, 2);
    sk_test_cli(&g_run, "presets no-such-module no-such-preset");
    assert_one_line_error(&g_run, 2);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_version_and_help),
        cmocka_unit_test(test_bad_usage_exits_2_with_one_line),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
