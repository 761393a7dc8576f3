/* Tests of the general BVH reader and writer (include/shitsukan/bvh.h): the forms
 * motion-capture tools write (CRLF, tabs, per-joint channel orders, several ROOTs), the
 * documented error of every broken file in the fuzz corpus, allocation bounded by the
 * file's size, and write -> read round trips. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "shitsukan/bvh.h"
#include "shitsukan/io.h"
#include "test_result.h"
#include "test_support.h"

static const char *corpus(const char *name)
{
    static char path[1024];
    snprintf(path, sizeof path, "%s/../fuzz/corpus/bvh/%s", SK_TEST_PRESET_DIR, name);
    return path;
}

static sk_bvh *load(const char *name, sk_result want, sk_error *err)
{
    sk_bvh *b = malloc(sizeof *b);
    assert_non_null(b);
    sk_result r = sk_bvh_load_file(corpus(name), b, err);
    if (r != want)
        fail_msg("%s: got %s (%s), want %s", name, sk_result_string(r), err->message,
                 sk_result_string(want));
    return b;
}

static double max_matrix_difference(sk_mat3d a, sk_mat3d b)
{
    double worst = 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) worst = fmax(worst, fabs(a.m[i][j] - b.m[i][j]));
    return worst;
}

static void test_reads_what_tools_write(void **state)
{
    (void)state;
    sk_error err = {0};
    /* CMU-style: CRLF, tabs, ZYX channels, End Site names */
    sk_bvh *b = load("cmu-crlf-tabs.bvh", SK_OK, &err);
    assert_int_equal(b->joint_count, 6);
    assert_int_equal(b->frame_count, 3);
    assert_int_equal(b->channels_per_frame, 15);
    assert_true(fabs(b->frame_time - 0.008333) < 1e-12);
    assert_int_equal(sk_bvh_find(b, "LeftUpLeg"), 2);
    assert_int_equal(sk_bvh_find(b, "LeftUpLeg_end"), 3);
    assert_true(b->end_site[3]);
    assert_int_equal(b->parent[sk_bvh_find(b, "LowerBack")], 0);
    assert_true(fabs(b->motion[14 + 15 * 2] - 0.9) < 1e-12);
    /* the same text with LF only reads the same */
    char *text;
    size_t size;
    SK_ASSERT_OK(sk_read_file(corpus("cmu-crlf-tabs.bvh"), 0, &text, &size, &e_));
    size_t n = 0;
    for (size_t i = 0; i < size; i++)
        if (text[i] != '\r') text[n++] = text[i];
    sk_bvh *lf = malloc(sizeof *lf);
    SK_ASSERT_OK(sk_bvh_parse(text, n, "lf", lf, &e_));
    assert_int_equal(lf->joint_count, b->joint_count);
    assert_memory_equal(lf->motion, b->motion, sizeof(double) * 45);
    free(text);
    sk_bvh_free(lf);
    free(lf);

    /* the rotation channels compose in file order: "Zrotation Yrotation Xrotation" is
       Rz Ry Rx, and the root's positions add to its OFFSET */
    sk_mat3d r;
    sk_vec3d t;
    sk_bvh_local(b, 0, 0, &r, &t);
    sk_mat3d want = sk_m3d_mul(
        sk_m3d_mul(sk_m3d_rot_z(-2.6 * SK_DEG_TO_RAD), sk_m3d_rot_y(-5.9 * SK_DEG_TO_RAD)),
        sk_m3d_rot_x(3.3 * SK_DEG_TO_RAD));
    assert_true(max_matrix_difference(r, want) < 1e-15);
    assert_true(fabs(t.x - 9.3722) < 1e-12 && fabs(t.y - 17.8693) < 1e-12);
    sk_bvh_free(b);
    free(b);

    /* Mixamo-style names and another order per joint */
    b = load("mixamo-spaces.bvh", SK_OK, &err);
    assert_int_equal(sk_bvh_find(b, "mixamorig:Spine"), 1);
    sk_bvh_local(b, 1, 1, &r, &t);
    want = sk_m3d_mul(sk_m3d_mul(sk_m3d_rot_z(2 * SK_DEG_TO_RAD), sk_m3d_rot_x(3 * SK_DEG_TO_RAD)),
                      sk_m3d_rot_y(4 * SK_DEG_TO_RAD));
    assert_true(max_matrix_difference(r, want) < 1e-15);
    /* forward kinematics: the end site hangs off the rotated spine */
    sk_vec3d pos[SK_BVH_MAX_JOINTS];
    sk_mat3d rot[SK_BVH_MAX_JOINTS];
    sk_bvh_pose(b, 1, rot, pos);
    sk_vec3d spine = sk_v3d_add(pos[0], sk_m3d_apply(rot[0], sk_v3d(0, 9.9, -1.2)));
    sk_vec3d tip = sk_v3d_add(spine, sk_m3d_apply(rot[1], sk_v3d(0, 11.6, 0)));
    assert_true(sk_v3d_length(sk_v3d_sub(pos[1], spine)) < 1e-12);
    assert_true(sk_v3d_length(sk_v3d_sub(pos[2], tip)) < 1e-12);
    sk_bvh_free(b);
    free(b);

    /* two ROOTs, position and rotation channels interleaved */
    b = load("two-roots-mixed-order.bvh", SK_OK, &err);
    assert_int_equal(b->parent[2], -1);
    sk_bvh_local(b, 2, 0, &r, &t);
    assert_true(fabs(t.x - 5.0) < 1e-15 && fabs(t.y) < 1e-15 && fabs(t.z) < 1e-15);
    sk_bvh_free(b);
    free(b);
    b = load("no-frames.bvh", SK_OK, &err);
    assert_int_equal(b->frame_count, 0);
    sk_bvh_free(b);
    free(b);
}

static void test_broken_files_give_the_documented_error(void **state)
{
    (void)state;
    static const struct {
        const char *file;
        sk_result result;
        const char *message;
    } cases[] = {
        {"bad-truncated-frame.bvh", SK_ERROR_PARSE,
         "line 35: truncated: frame 3 of 3 ends after 2 of its 15 numbers"},
        {"bad-unknown-channel.bvh", SK_ERROR_PARSE, "line 9: unknown channel \"Qrotation\""},
        {"bad-missing-brace.bvh", SK_ERROR_PARSE, "joint \"mixamorig:Hips\" is not closed"},
        {"bad-nan.bvh", SK_ERROR_PARSE, "line 20: \"nan\" is not a finite number"},
        {"bad-frame-time.bvh", SK_ERROR_PARSE, "line 18: Frame Time: 0 must be positive"},
        {"bad-duplicate-channel.bvh", SK_ERROR_PARSE, "line 9: channel \"Zrotation\" twice"},
        {"bad-channels-7.bvh", SK_ERROR_PARSE, "line 9: CHANNELS 7 is not a count 0..6"},
        {"bad-extra-data.bvh", SK_ERROR_PARSE, "line 21: data after the last frame"},
        {"bad-end-site-child.bvh", SK_ERROR_PARSE, "line 13: End Site with children"},
        {"bad-too-deep.bvh", SK_ERROR_LIMIT, "hierarchy deeper than 64"},
        /* found by fuzz_bvh: a NUL in a name cut it, so the file written again did not read */
        {"bad-control-name.bvh", SK_ERROR_PARSE,
         "line 6: joint name with a control byte (0x00) at byte 1"},
        {"bad-huge-frames.bvh", SK_ERROR_PARSE,
         "line 22: truncated: 22369621 frames x 12 channels need 268435452 numbers"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        sk_error err = {0};
        sk_bvh *b = load(cases[i].file, cases[i].result, &err);
        assert_null(b->motion);
        if (!strstr(err.message, cases[i].message) || !strstr(err.message, cases[i].file))
            fail_msg("%s: message \"%s\" lacks \"%s\"", cases[i].file, err.message,
                     cases[i].message);
        free(b);
    }
}

/* A header asking for 2^28 numbers in a file of a few hundred bytes is reported as
 * truncated even when the process may not allocate 2 GB (the reader sizes the motion by
 * what the file can hold). Runs in a child with an address-space limit; sanitizers
 * reserve huge shadow memory, so the limit is left out under them. */
static void test_huge_header_under_a_memory_limit(void **state)
{
    (void)state;
    if (getenv("SK_TEST_SANITIZED")) {
        sk_error err = {0};
        sk_bvh *b = load("bad-huge-frames.bvh", SK_ERROR_PARSE, &err);
        assert_non_null(strstr(err.message, "truncated"));
        free(b);
        return;
    }
    pid_t pid = fork();
    assert_true(pid >= 0);
    if (pid == 0) {
        struct rlimit limit = {(rlim_t)512 << 20, (rlim_t)512 << 20};
        setrlimit(RLIMIT_AS, &limit);
        sk_bvh *b = malloc(sizeof *b);
        sk_error err = {0};
        sk_result r =
            b ? sk_bvh_load_file(corpus("bad-huge-frames.bvh"), b, &err) : SK_ERROR_OUT_OF_MEMORY;
        _exit(r == SK_ERROR_PARSE && strstr(err.message, "truncated") ? 0 : 1);
    }
    int status = 0;
    waitpid(pid, &status, 0);
    assert_true(WIFEXITED(status));
    assert_int_equal(WEXITSTATUS(status), 0);
}

static void test_write_read_round_trip(void **state)
{
    (void)state;
    sk_bvh *b = malloc(sizeof *b), *back = malloc(sizeof *b);
    sk_bvh_init(b);
    int root, arm, fore;
    SK_ASSERT_OK(sk_bvh_add_joint(b, "Root", -1, sk_v3d(0, 0, 0), "xyzZXY", false, &root, &e_));
    SK_ASSERT_OK(sk_bvh_add_joint(b, "Arm", root, sk_v3d(10, 0, 0), "YXZ", false, &arm, &e_));
    SK_ASSERT_OK(sk_bvh_add_joint(b, "ForeArm", arm, sk_v3d(0, -30, 0), "XYZ", false, &fore, &e_));
    SK_ASSERT_OK(
        sk_bvh_add_joint(b, "ForeArm_end", fore, sk_v3d(0, -25, 0), NULL, true, NULL, &e_));
    SK_ASSERT_OK(sk_bvh_add_joint(b, "Leg", root, sk_v3d(0, -5, 0), "ZYX", false, NULL, &e_));
    SK_ASSERT_OK(sk_bvh_alloc_motion(b, 4, 1.0 / 60.0, &e_));
    for (int i = 0; i < 4 * b->channels_per_frame; i++) b->motion[i] = 0.125 * i - 3.0;
    const char *path = sk_test_path("bvh/round.bvh");
    SK_ASSERT_OK(sk_bvh_write(b, path, &e_));
    SK_ASSERT_OK(sk_bvh_load_file(path, back, &e_));
    assert_int_equal(back->joint_count, 5);
    assert_int_equal(back->channels_per_frame, 15);
    assert_int_equal(back->parent[4], 0);
    assert_true(back->end_site[3]);
    assert_memory_equal(back->channel[0], "xyzZXY", 6);
    assert_memory_equal(back->motion, b->motion, sizeof(double) * 60); /* exact binary fractions */
    sk_vec3d p1[SK_BVH_MAX_JOINTS], p2[SK_BVH_MAX_JOINTS];
    sk_bvh_positions(b, 3, p1);
    sk_bvh_positions(back, 3, p2);
    for (int j = 0; j < 5; j++) assert_true(sk_v3d_length(sk_v3d_sub(p1[j], p2[j])) < 1e-9);

    /* bad building calls name what is wrong */
    sk_error err = {0};
    sk_bvh_free(back);
    sk_bvh_init(back);
    sk_test_expect_failure(
        sk_bvh_add_joint(back, "a b", -1, sk_v3d(0, 0, 0), "xyz", false, NULL, &err), &err,
        SK_ERROR_INVALID_ARGUMENT, "without white space");
    sk_test_expect_failure(
        sk_bvh_add_joint(back, "A", -1, sk_v3d(0, 0, 0), "xxZ", false, NULL, &err), &err,
        SK_ERROR_INVALID_ARGUMENT, "distinct codes");
    sk_test_expect_failure(sk_bvh_add_joint(back, "A", 3, sk_v3d(0, 0, 0), "Z", false, NULL, &err),
                           &err, SK_ERROR_INVALID_ARGUMENT, "parent 3");
    b->motion[7] = NAN;
    sk_test_expect_failure(sk_bvh_write(b, sk_test_path("bvh/nan.bvh"), &err), &err,
                           SK_ERROR_INVALID_ARGUMENT, "motion value 7 (frame 0) is not finite");
    assert_false(sk_test_file_exists(sk_test_path("bvh/nan.bvh")));
    sk_bvh_free(b);
    free(b);
    free(back);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_reads_what_tools_write),
        cmocka_unit_test(test_broken_files_give_the_documented_error),
        cmocka_unit_test(test_huge_header_under_a_memory_limit),
        cmocka_unit_test(test_write_read_round_trip),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
