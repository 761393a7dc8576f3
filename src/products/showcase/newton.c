/* Damped Gauss-Newton for the small square systems of the showcase: the contact of the
 * fingertips (at most ten unknowns) and the playing posture (fourteen). The Jacobian is
 * taken by forward differences and kept while it serves (chord steps); a step is capped
 * in size and, with a fresh Jacobian, halved until it lowers the sum of squared misses,
 * so joint limits (which flatten the map) cannot throw it off. */
#include <math.h>
#include <string.h>

#include "products/showcase/showcase_internal.h"

void sk__gauss_newton_step(int n, const double *jac, const double *res, double *dx)
{
    double a[SK__NEWTON_MAX][SK__NEWTON_MAX + 1];
    double trace = 0;
    for (int i = 0; i < n; i++) {
        for (int j = 0; j < n; j++) {
            double s = 0;
            for (int k = 0; k < n; k++) s += jac[k * n + i] * jac[k * n + j];
            a[i][j] = s;
        }
        double g = 0;
        for (int k = 0; k < n; k++) g += jac[k * n + i] * res[k];
        a[i][n] = -g;
        trace += a[i][i];
    }
    double lambda = 1e-9 * (trace > 0 ? trace : 1) + 1e-12;
    for (int i = 0; i < n; i++) a[i][i] += lambda;
    for (int col = 0; col < n; col++) { /* Gaussian elimination with partial pivoting */
        int piv = col;
        for (int i = col + 1; i < n; i++)
            if (fabs(a[i][col]) > fabs(a[piv][col])) piv = i;
        if (piv != col)
            for (int j = 0; j <= n; j++) {
                double tmp = a[col][j];
                a[col][j] = a[piv][j], a[piv][j] = tmp;
            }
        for (int i = col + 1; i < n; i++) {
            double m = a[i][col] / a[col][col];
            for (int j = col; j <= n; j++) a[i][j] -= m * a[col][j];
        }
    }
    for (int i = n - 1; i >= 0; i--) {
        double s = a[i][n];
        for (int j = i + 1; j < n; j++) s -= a[i][j] * dx[j];
        dx[i] = s / a[i][i];
    }
}

static double sum_sq(const double *v, int n)
{
    double s = 0;
    for (int i = 0; i < n; i++) s += v[i] * v[i];
    return s;
}

static double max_abs(const double *v, int n)
{
    double m = 0;
    for (int i = 0; i < n; i++) m = fmax(m, fabs(v[i]));
    return m;
}

sk_result sk__newton_solve(const sk__newton_desc *d, double *x, double *res, sk_error *err)
{
    int n = d->n;
    double jac[SK__NEWTON_MAX * SK__NEWTON_MAX], xs[SK__NEWTON_MAX], rs[SK__NEWTON_MAX],
        dx[SK__NEWTON_MAX];
    bool fresh = false, have = false; /* Jacobian just taken at x / one at hand */
    sk_result r = d->fn(d->user, x, res, err);
    for (int it = 0;
         it < d->max_iterations && r == SK_OK && n > 0 && max_abs(res, n) > d->tolerance; it++) {
        if (!have) { /* forward differences at x */
            for (int j = 0; j < n && r == SK_OK; j++) {
                memcpy(xs, x, (size_t)n * sizeof *x);
                xs[j] += d->diff_step;
                r = d->fn(d->user, xs, rs, err);
                for (int i = 0; i < n; i++) jac[i * n + j] = (rs[i] - res[i]) / d->diff_step;
            }
            if (r != SK_OK) break;
            have = fresh = true;
        }
        sk__gauss_newton_step(n, jac, res, dx);
        double big = max_abs(dx, n);
        if (big > d->max_step)
            for (int i = 0; i < n; i++) dx[i] *= d->max_step / big;
        double before = sum_sq(res, n), after = INFINITY;
        /* the map is nearly linear: the same Jacobian serves several steps (a chord
           method); a step that does not shrink the misses well takes a fresh one, and a
           fresh one that does not help is halved */
        for (int half = 0; half < (fresh ? 8 : 1) && r == SK_OK; half++) {
            for (int i = 0; i < n; i++) xs[i] = x[i] + dx[i];
            r = d->fn(d->user, xs, rs, err);
            after = sum_sq(rs, n);
            if (after < before) break;
            for (int i = 0; i < n; i++) dx[i] *= 0.5;
        }
        if (r != SK_OK) break;
        if (after < before) {
            memcpy(x, xs, (size_t)n * sizeof *x);
            memcpy(res, rs, (size_t)n * sizeof *rs);
            if (after > 0.25 * before) have = false; /* slow: refresh the Jacobian */
            fresh = false;
        } else if (fresh) {
            break; /* no step lowers the misses: as close as it gets */
        } else {
            have = false;
        }
    }
    return r;
}
