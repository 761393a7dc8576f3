/* The equilibrium solver's state (thesis 3.2, eq. 3.17): the assembled system, the cache
 * of Cholesky factorisations by free set, and scratch space (allocation-free solves). */
#ifndef SK_HAND_SOLVER_INTERNAL_H
#define SK_HAND_SOLVER_INTERNAL_H

#include "models/hand/hand_internal.h"

#define N_DOF SK_HAND_DOF_COUNT

/* A factorisation of the free-DOF block of H (or of H plus the lookup tables' curvature). */
typedef struct sk_hand_factor {
    uint64_t key; /* bit i: DOF i fixed; bit 63: with lookup-table curvature */
    bool valid;
    uint64_t last_use;
    int nf;
    int free_dof[N_DOF];
    double l[N_DOF * N_DOF]; /* column-major nf x nf lower Cholesky factor */
} sk_hand_factor;

#define SK_HAND_FACTOR_LUT_BIT ((uint64_t)1 << 63)
#define SK_HAND_MAX_CACHE 64

struct sk_hand_solver {
    sk_hand_solver_desc desc;    /* resolved */
    double lo[N_DOF], hi[N_DOF]; /* limits as displacements from the relaxed posture */
    double relaxed[N_DOF];
    double min_abs[N_DOF], max_abs[N_DOF]; /* limits of absolute values */
    double k[N_DOF];
    sk_hand_constraints rows;
    double h[N_DOF * N_DOF]; /* K + A'WA, column-major (symmetric) */
    double lut_curv[N_DOF];  /* 2 * lookup weights per DOF (Gauss-Newton curvature) */
    double g0[N_DOF];        /* -A'Wb */
    double c0;               /* 1/2 b'Wb */
    const sk_hand_lut *luts;
    int lut_count;
    sk_hand_factor cache[SK_HAND_MAX_CACHE];
    uint64_t clock;
    int8_t clamp_side[N_DOF]; /* last solve: -1 at the lower limit, +1 at the upper
                                 (warm start of the active set) */
};

/* Assembles h, g0, c0 and lut_curv from k, rows and luts; drops the cache. */
void sk__hand_assemble(sk_hand_solver *solver);
/* Factorisation for the DOFs not in `fixed_mask` (bit 63 adds the lookup curvature),
 * from the cache or computed. NULL with SK_ERROR_NUMERIC if not positive definite. */
const sk_hand_factor *sk__hand_factor(sk_hand_solver *solver, uint64_t key, sk_error *err);
/* Solves L L' x = rhs in place (rhs indexed like factor->free_dof). */
void sk__hand_factor_solve(const sk_hand_factor *f, double *rhs);
/* y = h x (full n). */
void sk__hand_matvec(const double *h, const double *x, double *y);
/* Energy 1/2 th'H th - rhs'th + c0 + lookup potentials, and its gradient if grad != NULL. */
double sk__hand_energy(const sk_hand_solver *solver, const double *theta, const double *rhs,
                       double *grad);

/* A lookup potential with its gradient g and Hessian (h[0] = xx, h[1] = yy, h[2] = xy) at
 * absolute angles: exact for the Hermite interpolant inside a cell (its second
 * derivatives jump between cells), zero curvature for bilinear tables. */
double sk__hand_lut_eval_hessian(const sk_hand_lut *lut, double x, double y, double g[2],
                                 double h[3]);

/* Linear solve by active set (limits), and the iterative solve with lookup tables. */
sk_result sk__hand_solve_linear(sk_hand_solver *solver, const bool *pinned, double *theta,
                                const double *rhs, sk_hand_solve_info *info, sk_error *err);
sk_result sk__hand_solve_lut(sk_hand_solver *solver, const bool *pinned, double *theta,
                             const double *rhs, sk_hand_solve_info *info, sk_error *err);

/* K (skeleton stiffness with the set's overrides; the set may be NULL) + A'WA, column-
 * major N_DOF x N_DOF. */
void sk__hand_equilibrium_matrix(const sk_hand_skeleton *skeleton,
                                 const sk_hand_constraints *constraints, double *h);
/* K (skeleton stiffness with the set's overrides) + A'WA positive definite, or an error
 * naming the DOF where the factorisation fails. */
sk_result sk__hand_check_positive_definite(const sk_hand_skeleton *skeleton,
                                           const sk_hand_constraints *constraints, sk_error *err);

#endif /* SK_HAND_SOLVER_INTERNAL_H */
