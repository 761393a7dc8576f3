/* Tests of the core: results and error details, deterministic random numbers, noise,
 * vector math, loop progress. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <omp.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/loop_progress.h"
#include "shitsukan/core.h"
#include "test_support.h"

/* ------------------------------------------------------------ results */

static void test_result_strings_distinct(void **state)
{
    (void)state;
    for (int a = 0; a < SK_RESULT_COUNT; a++) {
        assert_non_null(sk_result_string((sk_result)a));
        for (int b = a + 1; b < SK_RESULT_COUNT; b++)
            assert_string_not_equal(sk_result_string((sk_result)a), sk_result_string((sk_result)b));
    }
    assert_string_equal(sk_result_string(SK_OK), "ok");
}

static void test_fail_and_prefix(void **state)
{
    (void)state;
    sk_error err = {0};
    assert_int_equal(sk_fail(&err, SK_ERROR_PARSE, "line %d: bad", 7), SK_ERROR_PARSE);
    assert_int_equal(err.result, SK_ERROR_PARSE);
    assert_string_equal(err.message, "line 7: bad");
    assert_int_equal(sk_error_prefix(&err, SK_ERROR_PARSE, "file.obj"), SK_ERROR_PARSE);
    assert_string_equal(err.message, "file.obj: line 7: bad");
    /* NULL err is accepted everywhere, and the result still passes up */
    assert_int_equal(sk_fail(NULL, SK_ERROR_IO, "x"), SK_ERROR_IO);
    assert_int_equal(sk_error_prefix(NULL, SK_ERROR_LIMIT, "ctx"), SK_ERROR_LIMIT);
    /* a long message is truncated, never overflows */
    char big[2000];
    memset(big, 'a', sizeof big - 1);
    big[sizeof big - 1] = '\0';
    sk_fail(&err, SK_ERROR_IO, "%s", big);
    assert_int_equal(strlen(err.message), SK_ERROR_MESSAGE_SIZE - 1);
    sk_error_prefix(&err, SK_ERROR_IO, "p");
    assert_int_equal(strlen(err.message), SK_ERROR_MESSAGE_SIZE - 1);
    sk_error_clear(&err);
    assert_int_equal(err.result, SK_OK);
    assert_string_equal(err.message, "");
}

static void test_range_checks(void **state)
{
    (void)state;
    sk_error err = {0};
    assert_int_equal(sk_check_range_f(&err, "levels[1].jitter", 0.5, 0.0, 1.0), SK_OK);
    assert_int_equal(sk_check_range_f(&err, "levels[1].jitter", 1.5, 0.0, 1.0),
                     SK_ERROR_INVALID_ARGUMENT);
    assert_string_equal(err.message, "levels[1].jitter = 1.5 is out of range [0, 1]");
    assert_int_equal(sk_check_range_f(&err, "h", NAN, 0.0, 1.0), SK_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(err.message, "h is not a finite number"));
    assert_int_equal(sk_check_range_f(&err, "h", INFINITY, 0.0, INFINITY),
                     SK_ERROR_INVALID_ARGUMENT);
    assert_int_equal(sk_check_range_i(&err, "levels", 0, 1, 8), SK_ERROR_INVALID_ARGUMENT);
    assert_string_equal(err.message, "levels = 0 is out of range [1, 8]");
}

static void test_size_arithmetic(void **state)
{
    (void)state;
    size_t out = 7;
    assert_true(sk_size_mul(1000, 1000, &out));
    assert_int_equal(out, 1000000);
    assert_false(sk_size_mul(SIZE_MAX / 2 + 1, 2, &out));
    assert_int_equal(out, 1000000); /* untouched on overflow */
    assert_true(sk_size_mul(0, SIZE_MAX, &out));
    assert_int_equal(out, 0);
    assert_false(sk_size_add(SIZE_MAX, 1, &out));
    assert_true(sk_size_add(SIZE_MAX - 1, 1, &out));
}

/* ------------------------------------------------------------ random */

static void test_rng_deterministic_and_keyed(void **state)
{
    (void)state;
    assert_true(sk_hash(1, 2, 3, 4) == sk_hash(1, 2, 3, 4));
    assert_true(sk_hash(1, 2, 3, 4) != sk_hash(1, 2, 3, 5));
    assert_true(sk_hash(1, 2, 3, 4) != sk_hash(2, 2, 3, 4));
    assert_true(sk_hash(0, 1, 0, 0) != sk_hash(0, 0, 1, 0)); /* argument order matters */
    sk_rng a = sk_rng_make(42, 7, 0, 0), b = sk_rng_make(42, 7, 0, 0);
    for (int i = 0; i < 100; i++) assert_true(sk_rng_next_u64(&a) == sk_rng_next_u64(&b));
    sk_rng c = sk_rng_make(42, 8, 0, 0);
    sk_rng d = sk_rng_make(42, 7, 0, 0);
    int same = 0;
    for (int i = 0; i < 100; i++) same += sk_rng_next_u64(&c) == sk_rng_next_u64(&d);
    assert_int_equal(same, 0);
}

static void test_rng_uniform_distribution(void **state)
{
    (void)state;
    enum { N = 1000000, BINS = 16 };
    double sum = 0, sum2 = 0;
    long bins[BINS] = {0};
    for (int i = 0; i < N; i++) {
        double u = sk_rand_uniform(99, (uint64_t)i, 0, 0);
        assert_true(u >= 0.0 && u < 1.0);
        sum += u;
        sum2 += u * u;
        bins[(int)(u * BINS)]++;
    }
    double mean = sum / N, var = sum2 / N - mean * mean;
    /* standard error of the mean: sqrt(1/12 / N) = 2.9e-4; allow 5 sigma */
    assert_true(fabs(mean - 0.5) < 0.0015);
    assert_true(fabs(var - 1.0 / 12.0) < 0.001);
    /* chi-square with 15 degrees of freedom: 99.99th percentile is about 44 */
    double expected = (double)N / BINS, chi2 = 0;
    for (int b = 0; b < BINS; b++) chi2 += (bins[b] - expected) * (bins[b] - expected) / expected;
    assert_true(chi2 < 44.0);
    /* lag-1 correlation of a stream */
    sk_rng r = sk_rng_make(5, 0, 0, 0);
    double prev = sk_rng_uniform(&r), sxy = 0;
    for (int i = 0; i < 200000; i++) {
        double u = sk_rng_uniform(&r);
        sxy += (prev - 0.5) * (u - 0.5);
        prev = u;
    }
    assert_true(fabs(sxy / 200000 / (1.0 / 12.0)) < 0.02);
}

static void test_rng_normal_distribution(void **state)
{
    (void)state;
    enum { N = 400000 };
    double s1 = 0, s2 = 0, s4 = 0;
    long within1 = 0;
    sk_rng r = sk_rng_make(3, 1, 4, 1);
    for (int i = 0; i < N; i++) {
        double x = sk_rng_normal(&r);
        assert_true(isfinite(x));
        s1 += x;
        s2 += x * x;
        s4 += x * x * x * x;
        within1 += fabs(x) < 1.0;
    }
    double mean = s1 / N, var = s2 / N - mean * mean, kurt = s4 / N / (var * var);
    assert_true(fabs(mean) < 0.01);
    assert_true(fabs(var - 1.0) < 0.015);
    assert_true(fabs(kurt - 3.0) < 0.06);
    assert_true(fabs((double)within1 / N - 0.6827) < 0.004);
    /* one-shot helper equals the stream's first sample */
    sk_rng s = sk_rng_make(3, 1, 4, 1);
    assert_true(sk_rand_normal(3, 1, 4, 1) == sk_rng_normal(&s));
}

static void test_rng_below_range(void **state)
{
    (void)state;
    sk_rng r = sk_rng_make(11, 0, 0, 0);
    long counts[7] = {0};
    for (int i = 0; i < 70000; i++) {
        uint32_t v = sk_rng_below(&r, 7);
        assert_true(v < 7);
        counts[v]++;
    }
    for (int k = 0; k < 7; k++) assert_true(labs(counts[k] - 10000) < 500);
    for (int i = 0; i < 1000; i++) {
        double v = sk_rng_range(&r, -2.0, 3.0);
        assert_true(v >= -2.0 && v < 3.0);
    }
}

static void test_rng_thread_independent(void **state)
{
    (void)state;
    enum { N = 10000 };
    static double one[N], two[N];
    for (int t = 1; t <= 2; t++) {
        double *dst = t == 1 ? one : two;
#pragma omp parallel for num_threads(t) schedule(dynamic, 7)
        for (int i = 0; i < N; i++) {
            sk_rng r = sk_rng_make(77, (uint64_t)i, 0, 0);
            dst[i] = sk_rng_normal(&r) + sk_rng_uniform(&r);
        }
    }
    assert_memory_equal(one, two, sizeof one);
}

/* ------------------------------------------------------------ noise */

static void test_noise_range_and_lattice_zero(void **state)
{
    (void)state;
    double max2 = 0, max3 = 0, s2 = 0;
    sk_rng r = sk_rng_make(1, 0, 0, 0);
    enum { N = 300000 };
    for (int i = 0; i < N; i++) {
        float x = (float)sk_rng_range(&r, -100, 100), y = (float)sk_rng_range(&r, -100, 100);
        float z = (float)sk_rng_range(&r, -100, 100);
        float n2 = sk_noise2(9, x, y), n3 = sk_noise3(9, x, y, z);
        assert_true(n2 >= -1.0f && n2 <= 1.0f);
        assert_true(n3 >= -1.0f && n3 <= 1.0f);
        max2 = fmax(max2, fabs(n2));
        max3 = fmax(max3, fabs(n3));
        s2 += (double)n2 * n2;
    }
    /* the stated range is used: values reach well beyond half of it */
    assert_true(max2 > 0.6);
    assert_true(max3 > 0.6);
    double sd = sqrt(s2 / N);
    assert_true(sd > 0.15 && sd < 0.35);
    for (int i = -5; i < 5; i++)
        for (int j = -5; j < 5; j++) {
            assert_true(fabsf(sk_noise2(9, (float)i, (float)j)) < 1e-6f);
            assert_true(fabsf(sk_noise3(9, (float)i, (float)j, 2.0f)) < 1e-6f);
        }
}

static void test_noise_gradient_matches_finite_difference(void **state)
{
    (void)state;
    sk_rng r = sk_rng_make(2, 0, 0, 0);
    const float h = 1e-3f;
    for (int i = 0; i < 2000; i++) {
        float x = (float)sk_rng_range(&r, -20, 20), y = (float)sk_rng_range(&r, -20, 20),
              z = (float)sk_rng_range(&r, -20, 20);
        float g2[2], g3[3];
        float v2 = sk_noise2_grad(4, x, y, g2);
        float v3 = sk_noise3_grad(4, x, y, z, g3);
        assert_true(v2 == sk_noise2(4, x, y));
        assert_true(v3 == sk_noise3(4, x, y, z));
        float fx = (sk_noise2(4, x + h, y) - sk_noise2(4, x - h, y)) / (2 * h);
        float fy = (sk_noise2(4, x, y + h) - sk_noise2(4, x, y - h)) / (2 * h);
        assert_true(fabsf(fx - g2[0]) < 0.02f);
        assert_true(fabsf(fy - g2[1]) < 0.02f);
        float d[3] = {(sk_noise3(4, x + h, y, z) - sk_noise3(4, x - h, y, z)) / (2 * h),
                      (sk_noise3(4, x, y + h, z) - sk_noise3(4, x, y - h, z)) / (2 * h),
                      (sk_noise3(4, x, y, z + h) - sk_noise3(4, x, y, z - h)) / (2 * h)};
        for (int a = 0; a < 3; a++) assert_true(fabsf(d[a] - g3[a]) < 0.02f);
    }
}

static void test_noise_continuous(void **state)
{
    (void)state;
    /* crossing lattice lines: the change over a tiny step is tiny (gradient bound ~ 4) */
    for (int i = -3; i <= 3; i++) {
        float x = (float)i;
        for (float y = -2.0f; y < 2.0f; y += 0.173f) {
            float a = sk_noise2(5, x - 1e-4f, y), b = sk_noise2(5, x + 1e-4f, y);
            assert_true(fabsf(a - b) < 1e-3f);
            float c = sk_noise3(5, x - 1e-4f, y, 0.3f), d = sk_noise3(5, x + 1e-4f, y, 0.3f);
            assert_true(fabsf(c - d) < 1e-3f);
        }
    }
    /* different seeds give different fields */
    assert_true(sk_noise2(1, 0.5f, 0.5f) != sk_noise2(2, 0.5f, 0.5f));
}

static void test_noise_periodic_tiles(void **state)
{
    (void)state;
    sk_rng r = sk_rng_make(8, 0, 0, 0);
    for (int i = 0; i < 1000; i++) {
        float x = (float)sk_rng_range(&r, 0, 7), y = (float)sk_rng_range(&r, 0, 5);
        float a = sk_noise2_periodic(3, x, y, 7, 5);
        assert_true(fabsf(a - sk_noise2_periodic(3, x + 7, y, 7, 5)) < 1e-5f);
        assert_true(fabsf(a - sk_noise2_periodic(3, x, y - 5, 7, 5)) < 1e-5f);
        assert_true(a >= -1.0f && a <= 1.0f);
    }
    /* continuity across the wrap seam */
    for (float y = 0; y < 5; y += 0.31f) {
        float left = sk_noise2_periodic(3, 7.0f - 1e-4f, y, 7, 5);
        float right = sk_noise2_periodic(3, 0.0f + 1e-4f, y, 7, 5);
        assert_true(fabsf(left - right) < 1e-3f);
    }
}

static void test_fbm_range_and_tiling(void **state)
{
    (void)state;
    sk_fbm_desc d = sk_fbm_desc_resolved(NULL);
    assert_int_equal(d.octaves, 5);
    assert_true(d.lacunarity == 2.0f && d.gain == 0.5f);
    sk_error err = {0};
    assert_int_equal(sk_fbm_desc_validate(&d, "noise", &err), SK_OK);
    sk_fbm_desc bad = d;
    bad.gain = 1.5f;
    assert_int_equal(sk_fbm_desc_validate(&bad, "noise", &err), SK_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(err.message, "noise.gain"));
    sk_rng r = sk_rng_make(12, 0, 0, 0);
    double maxv = 0;
    for (int i = 0; i < 20000; i++) {
        float x = (float)sk_rng_range(&r, -50, 50), y = (float)sk_rng_range(&r, -50, 50),
              z = (float)sk_rng_range(&r, -50, 50);
        float a = sk_fbm2(6, x, y, &d), b = sk_fbm3(6, x, y, z, &d);
        assert_true(a >= -1.0f && a <= 1.0f && b >= -1.0f && b <= 1.0f);
        maxv = fmax(maxv, fabs(a));
        float p = sk_fbm2_periodic(6, x, y, 4, 3, &d);
        assert_true(fabsf(p - sk_fbm2_periodic(6, x + 4, y + 3, 4, 3, &d)) < 1e-4f);
    }
    assert_true(maxv > 0.3);
}

/* ------------------------------------------------------------ vector math */

static void test_rotations_and_quaternions(void **state)
{
    (void)state;
    sk_vec3d axis = sk_v3d_normalize(sk_v3d(1, 2, 3));
    double angle = 0.7;
    sk_quatd q = sk_qd_axis_angle(axis, angle);
    sk_mat3d m = sk_qd_to_m3d(q);
    sk_vec3d v = sk_v3d(0.3, -1.2, 2.0);
    sk_vec3d a = sk_qd_rotate(q, v), b = sk_m3d_apply(m, v);
    assert_true(sk_v3d_length(sk_v3d_sub(a, b)) < 1e-12);
    assert_true(fabs(sk_m3d_det(m) - 1.0) < 1e-12);
    /* rotation about z by 90 degrees maps x to y */
    sk_vec3d xr = sk_m3d_apply(sk_m3d_rot_z(SK_PI / 2), sk_v3d(1, 0, 0));
    assert_true(fabs(xr.x) < 1e-12 && fabs(xr.y - 1) < 1e-12);
    /* matrix -> quaternion -> matrix, including angles near pi */
    for (int k = 0; k < 50; k++) {
        double ang = -3.1 + 0.125 * k;
        sk_mat3d rm =
            sk_m3d_mul(sk_m3d_rot_x(ang), sk_m3d_mul(sk_m3d_rot_y(0.4 * ang), sk_m3d_rot_z(1.7)));
        sk_mat3d back = sk_qd_to_m3d(sk_m3d_to_qd(rm));
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) assert_true(fabs(back.m[i][j] - rm.m[i][j]) < 1e-9);
    }
    /* slerp halfway is the half-angle rotation */
    sk_quatd h = sk_qd_slerp(sk_qd_identity(), q, 0.5);
    sk_quatd expect = sk_qd_axis_angle(axis, angle / 2);
    assert_true(fabs(fabs(sk_qd_dot(h, expect)) - 1.0) < 1e-12);
}

static void test_affine_inverse_and_basis(void **state)
{
    (void)state;
    sk_mat4f m = sk_m4f_mul(sk_m4f_translation(sk_v3f(1, -2, 3)),
                            sk_m4f_from_rt(sk_m3d_to_f(sk_m3d_rot_y(0.3)), sk_v3f(0, 0, 0)));
    m = sk_m4f_mul(m, sk_m4f_scaling(sk_v3f(2, 3, 0.5f)));
    sk_mat4f inv = sk_m4f_identity();
    assert_true(sk_m4f_affine_inverse(m, &inv));
    sk_vec3f p = sk_v3f(0.25f, 7, -1);
    sk_vec3f back = sk_m4f_apply_point(inv, sk_m4f_apply_point(m, p));
    assert_true(sk_v3f_length(sk_v3f_sub(back, p)) < 1e-5f);
    assert_false(sk_m4f_affine_inverse(sk_m4f_scaling(sk_v3f(1, 0, 1)), &inv));
    sk_rng r = sk_rng_make(4, 0, 0, 0);
    for (int i = 0; i < 1000; i++) {
        sk_vec3f n = sk_v3f_normalize(
            sk_v3f((float)sk_rng_normal(&r), (float)sk_rng_normal(&r), (float)sk_rng_normal(&r)));
        sk_vec3f t, b;
        sk_v3f_basis(n, &t, &b);
        assert_true(fabsf(sk_v3f_dot(t, n)) < 1e-5f && fabsf(sk_v3f_dot(b, n)) < 1e-5f);
        assert_true(fabsf(sk_v3f_dot(t, b)) < 1e-5f);
        assert_true(fabsf(sk_v3f_length(t) - 1) < 1e-5f && fabsf(sk_v3f_length(b) - 1) < 1e-5f);
        assert_true(sk_v3f_dot(sk_v3f_cross(t, b), n) > 0.999f); /* right-handed */
    }
}

/* ------------------------------------------------------------ progress */

typedef struct recorder {
    int calls;
    double last;
    int decreasing;
} recorder;

static void record(void *user, double f)
{
    recorder *r = user;
    if (f < r->last) r->decreasing++;
    if (f < 0 || f > 1) r->decreasing++;
    r->last = f;
    r->calls++;
}

static void test_loop_progress_monotone_and_bounded(void **state)
{
    (void)state;
    recorder rec = {0, 0, 0};
    sk_progress sink = {record, &rec};
    sk__loop_progress lp;
    sk__loop_progress_init(&lp, &sink, 5000);
#pragma omp parallel for num_threads(2) schedule(dynamic, 1)
    for (int i = 0; i < 5000; i++) sk__loop_progress_tick(&lp);
    assert_int_equal(rec.decreasing, 0);
    /* any thread may report (a descheduled thread 0 must not silence progress) */
    assert_true(rec.calls >= 1 && rec.calls <= 101);
    assert_true(rec.last > 0.0);
    assert_int_equal((long)atomic_load(&lp.done), 5000);
    /* no sink: ticks are free and nothing is called */
    sk__loop_progress_init(&lp, NULL, 10);
    sk__loop_progress_tick(&lp);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_result_strings_distinct),
        cmocka_unit_test(test_fail_and_prefix),
        cmocka_unit_test(test_range_checks),
        cmocka_unit_test(test_size_arithmetic),
        cmocka_unit_test(test_rng_deterministic_and_keyed),
        cmocka_unit_test(test_rng_uniform_distribution),
        cmocka_unit_test(test_rng_normal_distribution),
        cmocka_unit_test(test_rng_below_range),
        cmocka_unit_test(test_rng_thread_independent),
        cmocka_unit_test(test_noise_range_and_lattice_zero),
        cmocka_unit_test(test_noise_gradient_matches_finite_difference),
        cmocka_unit_test(test_noise_continuous),
        cmocka_unit_test(test_noise_periodic_tiles),
        cmocka_unit_test(test_fbm_range_and_tiling),
        cmocka_unit_test(test_rotations_and_quaternions),
        cmocka_unit_test(test_affine_inverse_and_basis),
        cmocka_unit_test(test_loop_progress_monotone_and_bounded),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
