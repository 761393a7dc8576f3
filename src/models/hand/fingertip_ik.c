/* Fingertip inverse kinematics through the equilibrium: a fingertip brought to a target
 * by pinning its finger's three reach DOFs at the values whose equilibrium pose (thesis
 * eq. 3.17, with the coupling of the set in use) puts the tip nearest it. Beyond the
 * thesis, whose GUI (sec. 4.2.1) gives one joint an input at a time: damped Gauss-Newton
 * (Levenberg-Marquardt) steps on the solved poses, the Jacobian of the tip by forward
 * differences of whole solves; a step that brings the tip no nearer is taken back and
 * damped more, so the distance never grows. */
#include <math.h>
#include <string.h>

#include "models/hand/hand_internal.h"

#define REACH_DEFAULT_ITERATIONS 12
#define REACH_DEFAULT_TOLERANCE_MM 0.05
/* Damping lambda of (J'J + lambda diag(J'J + 1)) dx = J'e after a step that brought the
   tip nearer (ten times more after each that did not). */
#define REACH_DAMPING 1e-2
/* Forward-difference step of the Jacobian (radians). */
#define REACH_FD_STEP 1e-4
/* Largest change of a pin in one step (radians). */
#define REACH_MAX_STEP 0.2

void sk_hand_reach_dofs(sk_hand_finger finger, int dofs[3])
{
    static const char *const names[SK_HAND_FINGER_COUNT][3] = {
        {"T.CMC.flex", "T.CMC.abd", "T.MCP.flex"},
        {"I.MCP.flex", "I.MCP.abd", "I.PIP.flex"},
        {"M.MCP.flex", "M.MCP.abd", "M.PIP.flex"},
        {"R.MCP.flex", "R.MCP.abd", "R.PIP.flex"},
        {"L.MCP.flex", "L.MCP.abd", "L.PIP.flex"}};
    for (int k = 0; k < 3; k++)
        dofs[k] = (unsigned)finger < SK_HAND_FINGER_COUNT ? sk_hand_dof_find(names[finger][k]) : -1;
}

int sk_hand_fingertip_point(sk_hand_finger finger)
{
    /* wrist, then the thumb's CMC MCP IP tip, then CMC MCP PIP DIP tip of each finger */
    if ((unsigned)finger >= SK_HAND_FINGER_COUNT) return -1;
    return finger == SK_HAND_THUMB ? 4 : 4 + 5 * (int)finger;
}

/* One equilibrium solve with the solver the desc names. */
static sk_result solve(const sk_hand_reach_desc *d, const sk_hand_input *in, double *dofs,
                       sk_hand_solve_info *info, sk_error *err)
{
    if (d->potential_solver)
        return sk_hand_potential_solve(d->potential_solver, in, dofs, info, NULL, err);
    return sk_hand_solve(d->solver, in, dofs, info, err);
}

static double det3(double a[3][3])
{
    return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
           a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
           a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
}

/* The tip at the pins x (a solve) and the error e = target - tip. */
static sk_result tip_error(const sk_hand_skeleton *s, const sk_hand_reach_desc *d, const int dof[3],
                           const double x[3], sk_hand_input *in, sk_hand_solve_info *info,
                           sk_vec3d *tip, double e[3], sk_error *err)
{
    double q[SK_HAND_DOF_COUNT];
    sk_hand_frames fr;
    for (int k = 0; k < 3; k++) in->pin_value[dof[k]] = x[k];
    sk_result r = solve(d, in, q, info, err);
    if (r != SK_OK) return r;
    sk_hand_forward(s, q, &fr);
    *tip = fr.point[sk_hand_fingertip_point(d->finger)];
    e[0] = d->target.x - tip->x, e[1] = d->target.y - tip->y, e[2] = d->target.z - tip->z;
    return SK_OK;
}

/* The tip's Jacobian in the pins at x (the tip there p0) by forward differences: a solve
 * per column. */
static sk_result tip_jacobian(const sk_hand_skeleton *s, const sk_hand_reach_desc *d,
                              const int dof[3], const double x[3], sk_vec3d p0, sk_hand_input *in,
                              sk_hand_solve_info *info, double jac[3][3], sk_error *err)
{
    for (int c = 0; c < 3; c++) {
        double xc[3] = {x[0], x[1], x[2]}, e[3];
        xc[c] = x[c] + REACH_FD_STEP;
        sk_vec3d p;
        sk_result r = tip_error(s, d, dof, xc, in, info, &p, e, err);
        if (r != SK_OK) return r;
        jac[0][c] = (p.x - p0.x) / REACH_FD_STEP;
        jac[1][c] = (p.y - p0.y) / REACH_FD_STEP;
        jac[2][c] = (p.z - p0.z) / REACH_FD_STEP;
    }
    return SK_OK;
}

/* The damped step (J'J + lambda diag(J'J + 1)) dx = J'e by Cramer's rule on the 3 x 3
 * system, each component at most REACH_MAX_STEP; false when the system is singular. */
static bool damped_step(double jac[3][3], const double e[3], double lambda, double dx[3])
{
    double a[3][3], b[3];
    for (int i = 0; i < 3; i++) {
        b[i] = 0;
        for (int r = 0; r < 3; r++) b[i] += jac[r][i] * e[r];
        for (int j = 0; j < 3; j++) {
            a[i][j] = 0;
            for (int r = 0; r < 3; r++) a[i][j] += jac[r][i] * jac[r][j];
        }
        a[i][i] += lambda * (a[i][i] + 1.0);
    }
    double det = det3(a);
    if (!(fabs(det) > 1e-300)) return false;
    for (int k = 0; k < 3; k++) {
        double m[3][3];
        memcpy(m, a, sizeof m);
        for (int r = 0; r < 3; r++) m[r][k] = b[r];
        double step = det3(m) / det;
        dx[k] = step > REACH_MAX_STEP    ? REACH_MAX_STEP
                : step < -REACH_MAX_STEP ? -REACH_MAX_STEP
                                         : step;
    }
    return true;
}

/* from + dx within the DOFs' limits into x; false when that leaves the pins where they
 * were (at `from`). */
static bool take_step(const sk_hand_skeleton *s, const int dof[3], const double from[3],
                      const double dx[3], double x[3])
{
    bool moved = false;
    for (int k = 0; k < 3; k++) {
        const sk_hand_dof_data *dd = &s->dof[dof[k]];
        double v = from[k] + dx[k];
        x[k] = v < dd->min ? dd->min : v > dd->max ? dd->max : v;
        moved |= x[k] != from[k];
    }
    return moved;
}

/* After a step to x that brought the tip no nearer: the next from `best`, damped ten
 * times more until it goes elsewhere than x; false when none moves the pins. */
static bool retry_step(const sk_hand_skeleton *s, const int dof[3], double jac[3][3],
                       const double e[3], const double best[3], double *lambda, double x[3])
{
    double tried[3] = {x[0], x[1], x[2]}, dx[3];
    while (*lambda < 1e12) {
        *lambda *= 10.0;
        if (!damped_step(jac, e, *lambda, dx) || !take_step(s, dof, best, dx, x)) return false;
        if (x[0] != tried[0] || x[1] != tried[1] || x[2] != tried[2]) return true;
    }
    return false;
}

/* The pins' search: from x, each step evaluated (a solve) and kept when it brings the tip
 * nearer, else taken back and damped ten times more; x ends at the last step's pins,
 * best at the nearest evaluated ones (*best_distance, infinite when none). */
static sk_result search(const sk_hand_skeleton *s, const sk_hand_reach_desc *d, const int dof[3],
                        int iterations, double tolerance, sk_hand_input *in,
                        sk_hand_solve_info *info, double x[3], double best[3],
                        double *best_distance, sk_error *err)
{
    double best_e[3], best_jac[3][3], lambda = REACH_DAMPING, dx[3];
    *best_distance = INFINITY;
    for (int it = 0; it < iterations; it++) {
        double e[3];
        sk_vec3d p;
        sk_result r = tip_error(s, d, dof, x, in, info, &p, e, err);
        if (r != SK_OK) return r;
        double dist = sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
        if (!(dist < *best_distance)) {
            /* no nearer: back to the best pins with a shorter step */
            if (!retry_step(s, dof, best_jac, best_e, best, &lambda, x)) break;
            continue;
        }
        memcpy(best, x, 3 * sizeof *x);
        memcpy(best_e, e, sizeof e);
        *best_distance = dist;
        lambda = REACH_DAMPING;
        if (dist < tolerance) break;
        if ((r = tip_jacobian(s, d, dof, x, p, in, info, best_jac, err)) != SK_OK) return r;
        if (!damped_step(best_jac, e, lambda, dx) || !take_step(s, dof, best, dx, x)) break;
    }
    return SK_OK;
}

static sk_result check_desc(const sk_hand_skeleton *s, const sk_hand_reach_desc *d,
                            const sk_hand_input *input, const double *dofs, sk_error *err)
{
    if (!s || !d || !input || !dofs)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "skeleton, desc, input and dofs must not be NULL");
    if ((unsigned)d->finger >= SK_HAND_FINGER_COUNT)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "finger = %d is out of range [0, %d]",
                       (int)d->finger, SK_HAND_FINGER_COUNT - 1);
    if (!d->solver && !d->potential_solver)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "a solver or a potential solver is needed for the equilibrium");
    sk_result r;
    if ((r = sk_check_finite(err, "target.x", d->target.x)) != SK_OK ||
        (r = sk_check_finite(err, "target.y", d->target.y)) != SK_OK ||
        (r = sk_check_finite(err, "target.z", d->target.z)) != SK_OK)
        return r;
    if ((r = sk_check_range_i(err, "max_iterations", d->max_iterations, 0, 1000)) != SK_OK)
        return r;
    if (!(d->tolerance_mm >= 0.0 && d->tolerance_mm <= 100.0))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "tolerance_mm = %g is out of range [0, 100] (0 = %g)", d->tolerance_mm,
                       REACH_DEFAULT_TOLERANCE_MM);
    return SK_OK;
}

sk_result sk_hand_reach(const sk_hand_skeleton *skeleton, const sk_hand_reach_desc *desc,
                        sk_hand_input *input, double dofs[SK_HAND_DOF_COUNT],
                        sk_hand_solve_info *info, double *distance_mm, sk_error *err)
{
    sk_result r = check_desc(skeleton, desc, input, dofs, err);
    if (r != SK_OK) return r;
    int iterations = desc->max_iterations ? desc->max_iterations : REACH_DEFAULT_ITERATIONS;
    double tolerance = desc->tolerance_mm > 0 ? desc->tolerance_mm : REACH_DEFAULT_TOLERANCE_MM;
    int dof[3];
    sk_hand_reach_dofs(desc->finger, dof);
    /* from the pins the finger has, else from the pose */
    sk_hand_input in = *input;
    double x[3];
    for (int k = 0; k < 3; k++) {
        in.pinned[dof[k]] = true;
        x[k] = input->pinned[dof[k]] ? input->pin_value[dof[k]] : dofs[dof[k]];
    }
    sk_hand_solve_info last;
    double best[3], best_distance;
    r = search(skeleton, desc, dof, iterations, tolerance, &in, &last, x, best, &best_distance,
               err);
    if (r != SK_OK) return r;
    /* the inputs with the pins found, and their equilibrium: the last step's, or the
       nearest evaluated pins' when the last step ended farther */
    double q[SK_HAND_DOF_COUNT], distance = 0;
    for (int pass = 0; pass < 2; pass++) {
        for (int k = 0; k < 3; k++) in.pin_value[dof[k]] = x[k];
        if ((r = solve(desc, &in, q, &last, err)) != SK_OK) return r;
        sk_hand_frames fr;
        sk_hand_forward(skeleton, q, &fr);
        sk_vec3d p = fr.point[sk_hand_fingertip_point(desc->finger)];
        double tx = desc->target.x, ty = desc->target.y, tz = desc->target.z;
        distance =
            sqrt((p.x - tx) * (p.x - tx) + (p.y - ty) * (p.y - ty) + (p.z - tz) * (p.z - tz));
        if (!(distance > best_distance)) break;
        memcpy(x, best, sizeof best);
    }
    *input = in;
    memcpy(dofs, q, sizeof q);
    if (info) *info = last;
    if (distance_mm) *distance_mm = distance;
    return SK_OK;
}
