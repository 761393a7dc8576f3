/* Tests of the hand module's portable dense algebra (the WebAssembly build's path)
 * against LAPACK on the same matrices: Cholesky factors, solves, inverses and
 * eigenvalues agree to rounding; a failing factorisation reports the same column. */
#include <math.h>
#include <string.h>

#include "models/hand/dense_internal.h"
#include "shitsukan/core.h"
#include "test_support.h"

#define MAXN 35

/* A random symmetric positive definite matrix B B' + n I (column-major). */
static void random_spd(uint64_t seed, int n, double *a)
{
    double b[MAXN * MAXN];
    sk_rng rng = sk_rng_make(seed, (uint64_t)n, 7, 0);
    for (int i = 0; i < n * n; i++) b[i] = sk_rng_range(&rng, -1.0, 1.0);
    for (int j = 0; j < n; j++)
        for (int i = 0; i < n; i++) {
            double s = i == j ? 0.5 * n : 0.0;
            for (int k = 0; k < n; k++) s += b[k * n + i] * b[k * n + j];
            a[j * n + i] = s;
        }
}

static double max_abs(const double *x, int count)
{
    double m = 0.0;
    for (int i = 0; i < count; i++) m = fmax(m, fabs(x[i]));
    return m;
}

static void test_cholesky_and_solve_match_lapack(void **state)
{
    (void)state;
    for (int n = 1; n <= MAXN; n++) {
        double a[MAXN * MAXN], la[MAXN * MAXN], pa[MAXN * MAXN];
        random_spd(11, n, a);
        memcpy(la, a, sizeof a);
        memcpy(pa, a, sizeof a);
        assert_int_equal(sk__hand_cholesky_at(la, n), 0);
        assert_int_equal(sk__hand_portable_cholesky(pa, n), 0);
        double scale = max_abs(la, n * n);
        for (int j = 0; j < n; j++)
            for (int i = j; i < n; i++)
                assert_true(fabs(la[j * n + i] - pa[j * n + i]) <= 1e-13 * scale);
        double lb[3 * MAXN], pb[3 * MAXN];
        sk_rng rng = sk_rng_make(5, (uint64_t)n, 0, 0);
        for (int i = 0; i < 3 * n; i++) lb[i] = pb[i] = sk_rng_range(&rng, -2.0, 2.0);
        sk__hand_cholesky_solve(la, n, lb, 3);
        sk__hand_portable_cholesky_solve(pa, n, pb, 3);
        double xs = max_abs(lb, 3 * n);
        for (int i = 0; i < 3 * n; i++) assert_true(fabs(lb[i] - pb[i]) <= 1e-12 * xs);
        /* and it is the solution: A x = b */
        for (int i = 0; i < n; i++) {
            double s = 0.0;
            for (int k = 0; k < n; k++) s += a[k * n + i] * pb[k];
            double b0 = 0;
            sk_rng r2 = sk_rng_make(5, (uint64_t)n, 0, 0);
            for (int k = 0; k <= i; k++) b0 = sk_rng_range(&r2, -2.0, 2.0);
            assert_true(fabs(s - b0) <= 1e-10);
        }
    }
}

static void test_failure_column_matches_lapack(void **state)
{
    (void)state;
    for (int n = 2; n <= MAXN; n += 3) {
        double a[MAXN * MAXN];
        random_spd(3, n, a);
        int bad = n / 2; /* a negative pivot at column `bad` */
        a[bad * n + bad] = -1.0;
        double la[MAXN * MAXN], pa[MAXN * MAXN];
        memcpy(la, a, sizeof a);
        memcpy(pa, a, sizeof a);
        int li = sk__hand_cholesky_at(la, n), pi = sk__hand_portable_cholesky(pa, n);
        assert_true(li > 0);
        assert_int_equal(li, pi);
        assert_false(sk__hand_cholesky(la, n));
    }
}

static void test_inverse_matches_lapack(void **state)
{
    (void)state;
    for (int n = 1; n <= MAXN; n += 2) {
        double a[MAXN * MAXN], la[MAXN * MAXN], pa[MAXN * MAXN];
        random_spd(21, n, a);
        memcpy(la, a, sizeof a);
        memcpy(pa, a, sizeof a);
        assert_true(sk__hand_spd_inverse(la, n));
        assert_true(sk__hand_portable_spd_inverse(pa, n));
        double scale = max_abs(la, n * n);
        for (int i = 0; i < n * n; i++) assert_true(fabs(la[i] - pa[i]) <= 1e-12 * scale);
        /* A A^-1 = I */
        for (int j = 0; j < n; j++)
            for (int i = 0; i < n; i++) {
                double s = 0.0;
                for (int k = 0; k < n; k++) s += a[k * n + i] * pa[j * n + k];
                assert_true(fabs(s - (i == j ? 1.0 : 0.0)) <= 1e-11);
            }
    }
    double z[4] = {1, 0, 0, -1};
    assert_false(sk__hand_portable_spd_inverse(z, 2));
}

static void test_eigen_matches_lapack(void **state)
{
    (void)state;
    for (int n = 1; n <= MAXN; n += 2) {
        double a[MAXN * MAXN], la[MAXN * MAXN], pa[MAXN * MAXN], lv[MAXN], pv[MAXN];
        random_spd(31, n, a);
        /* indefinite too: shift the spectrum down */
        for (int i = 0; i < n; i++) a[i * n + i] -= 0.75 * n;
        memcpy(la, a, sizeof a);
        memcpy(pa, a, sizeof a);
        assert_true(sk__hand_sym_eigen(la, n, lv, true));
        assert_true(sk__hand_portable_sym_eigen(pa, n, pv, true));
        double scale = fmax(fabs(lv[0]), fabs(lv[n - 1]));
        for (int i = 0; i < n; i++) {
            assert_true(fabs(lv[i] - pv[i]) <= 1e-12 * scale);
            if (i > 0) assert_true(pv[i] >= pv[i - 1]);
        }
        /* eigenvectors: the same up to sign (the spectrum of a random matrix is simple),
           and A v = lambda v */
        for (int c = 0; c < n; c++) {
            double dot = 0.0;
            for (int k = 0; k < n; k++) dot += la[c * n + k] * pa[c * n + k];
            assert_true(fabs(fabs(dot) - 1.0) <= 1e-9);
            for (int i = 0; i < n; i++) {
                double s = 0.0;
                for (int k = 0; k < n; k++) s += a[k * n + i] * pa[c * n + k];
                assert_true(fabs(s - pv[c] * pa[c * n + i]) <= 1e-10 * scale);
            }
        }
        double values_only[MAXN];
        memcpy(pa, a, sizeof a);
        assert_true(sk__hand_portable_sym_eigen(pa, n, values_only, false));
        for (int i = 0; i < n; i++) assert_true(fabs(values_only[i] - pv[i]) <= 1e-12 * scale);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_cholesky_and_solve_match_lapack),
        cmocka_unit_test(test_failure_column_matches_lapack),
        cmocka_unit_test(test_inverse_matches_lapack),
        cmocka_unit_test(test_eigen_matches_lapack),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
