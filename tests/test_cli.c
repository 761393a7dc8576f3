/* Tests of the `shitsukan` command's framework: help, version, exit codes and one-line
 * errors for bad usage. Module commands have their own tests in their modules' files. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "test_support.h"

#include "shitsukan/hand.h"

static sk_test_run g_run;

/* A path under the test folder with nothing there yet. */
static const char *fresh_path(const char *name)
{
    const char *path = sk_test_path(name);
    char command[2048];
    snprintf(command, sizeof command, "rm -rf '%s'", path);
    assert_int_equal(system(command), 0);
    return path;
}

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

/* "shitsukan hand --help" and "shitsukan hand" said "unknown command 'hand'". */
static void test_groups_have_help(void **state)
{
    (void)state;
    static const char *const groups[] = {"hand", "wood"};
    for (size_t i = 0; i < sizeof groups / sizeof groups[0]; i++) {
        assert_int_equal(sk_test_cli(&g_run, "%s --help", groups[i]), 0);
        assert_non_null(strstr(g_run.out, "subcommands:"));
        assert_string_equal(g_run.err, "");
        sk_test_cli(&g_run, "%s", groups[i]);
        assert_one_line_error(&g_run, 2);
        assert_non_null(strstr(g_run.err, "needs a subcommand"));
        sk_test_cli(&g_run, "%s no-such-subcommand", groups[i]);
        assert_one_line_error(&g_run, 2);
        assert_non_null(strstr(g_run.err, "unknown subcommand"));
    }
    assert_int_equal(sk_test_cli(&g_run, "hand --help"), 0);
    assert_non_null(strstr(g_run.out, "  pose "));
    assert_non_null(strstr(g_run.out, "  calibrate "));
    /* a command that is also a group lists its subcommands under its own help */
    assert_int_equal(sk_test_cli(&g_run, "skin --help"), 0);
    assert_non_null(strstr(g_run.out, "usage: shitsukan skin [options]"));
    assert_non_null(strstr(g_run.out, "  maps "));
}

/* --region sums overflowed a signed integer (0,0,4,4 ran for huge x, w). */
static void test_region_cannot_overflow(void **state)
{
    (void)state;
    const char *out = fresh_path("region.png");
    static const char *const regions[] = {
        "4611686018427387904,0,6917529027641081860,4",
        "9223372036854775807,0,1,1",
        "0,0,9223372036854775807,1",
        "1,1,-9223372036854775807,1",
        "0,0,99999999999999999999,1",
        "0x1,0,1,1",
        " 1,0,1,1",
        "1,0,1,1,",
    };
    for (size_t i = 0; i < sizeof regions / sizeof regions[0]; i++) {
        sk_test_cli(&g_run, "noise --size 16 -q --region '%s' -o '%s'", regions[i], out);
        assert_one_line_error(&g_run, 2);
        assert_non_null(strstr(g_run.err, "--region"));
        assert_false(sk_test_file_exists(out));
    }
    assert_int_equal(sk_test_cli(&g_run, "noise --size 16 -q --region 12,0,4,16 -o '%s'", out), 0);
    assert_true(sk_test_file_exists(out));
}

/* --pin: hexadecimal accepted as a number, 1e30 refused without the limit, the 65th
 * silently dropped, a repeated DOF silently keeping the last, a pin and a torque on one DOF
 * both accepted. */
static void test_hand_inputs_are_checked(void **state)
{
    (void)state;
    sk_test_cli(&g_run, "hand pose --pin L.MCP.flex=0x3c");
    assert_one_line_error(&g_run, 2);
    assert_non_null(strstr(g_run.err, "[-1000000, 1000000]"));
    sk_test_cli(&g_run, "hand pose --pin L.MCP.flex=1e30");
    assert_one_line_error(&g_run, 2);
    assert_non_null(strstr(g_run.err, "[-1000000, 1000000]"));
    sk_test_cli(&g_run, "hand pose --pin L.MCP.flex=10 --pin L.MCP.flex=20");
    assert_one_line_error(&g_run, 2);
    assert_non_null(strstr(g_run.err, "L.MCP.flex already has --pin"));
    sk_test_cli(&g_run, "hand pose --pin L.MCP.flex=10 --torque L.MCP.flex=0.5");
    assert_one_line_error(&g_run, 2);
    assert_non_null(strstr(g_run.err, "L.MCP.flex already has --pin"));
    /* 65 distinct inputs: every one is honoured (the hand has 49 DOFs, so 65 must repeat
       one; the repeat is named, not dropped) */
    char many[8192];
    size_t used = 0;
    for (int i = 0; i < SK_HAND_DOF_COUNT; i++)
        used += (size_t)snprintf(many + used, sizeof many - used, " --torque %s=0.01",
                                 sk_hand_dof(i)->name);
    assert_int_equal(sk_test_cli(&g_run, "hand pose%s", many), 0);
    for (int i = 0; i < 65 - SK_HAND_DOF_COUNT; i++)
        used += (size_t)snprintf(many + used, sizeof many - used, " --pin %s=1",
                                 sk_hand_dof(i)->name);
    sk_test_cli(&g_run, "hand pose%s", many);
    assert_one_line_error(&g_run, 2);
    assert_non_null(strstr(g_run.err, "already has --pin"));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_version_and_help),
        cmocka_unit_test(test_bad_usage_exits_2_with_one_line),
        cmocka_unit_test(test_groups_have_help),
        cmocka_unit_test(test_region_cannot_overflow),
        cmocka_unit_test(test_hand_inputs_are_checked),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
