/* Private helpers of the calibrated potential (potential_*.c) and its evaluation. */
#ifndef SK_HAND_POTENTIAL_INTERNAL_H
#define SK_HAND_POTENTIAL_INTERNAL_H

#include "models/hand/hand_internal.h"

/* The DOFs a potential calibrates from samples with these columns: the joint angles
 * (wrist DOFs and translations excluded), in DOF order. Returns the count. */
int sk__hand_calibrated_dofs(const bool *present, int *dof);

/* -------------------------------------------- fitting (potential_fit.c) */

/* A spring of stiffness 1 alone spreads a DOF by this much when the base set is read as a
 * Gaussian (its temperature is the square). */
#define SK_HAND__PRIOR_SPREAD (20.0 * SK_DEG_TO_RAD)
#define SK_HAND__FIT_MAX_MASKS                                                                     \
    (SK_HAND_EVAL_MAX_PIN_SETS > SK_HAND_DOF_COUNT ? SK_HAND_EVAL_MAX_PIN_SETS : SK_HAND_DOF_COUNT)

/* What every calibration method starts from: the samples split into a training and a
 * validation part, the pin patterns of the held-out choices, the base set's Gaussian,
 * the prior strength and the shrunk moments. */
typedef struct sk__hand_fit_data {
    int d, dof[SK_HAND_DOF_COUNT];
    bool masks[SK_HAND__FIT_MAX_MASKS][SK_HAND_DOF_COUNT]; /* true: pinned in pattern p */
    int mask_count;
    double *x; /* n x d rows (radians): the training part first, validation after */
    int n, n_train, n_val;
    bool can_validate;
    double mu0[SK_HAND_DOF_COUNT], sigma0[SK_HAND_DOF_COUNT * SK_HAND_DOF_COUNT]; /* base set */
    double base_diag[SK_HAND_DOF_COUNT]; /* K + A'WA of the base set on the diagonal */
    double nu;                           /* prior strength, resolved */
    double mu[SK_HAND_DOF_COUNT], sigma[SK_HAND_DOF_COUNT * SK_HAND_DOF_COUNT]; /* shrunk, all */
    double mu_train[SK_HAND_DOF_COUNT], sigma_train[SK_HAND_DOF_COUNT * SK_HAND_DOF_COUNT];
} sk__hand_fit_data;

/* Checks the desc's common fields, splits the samples and chooses the prior strength.
 * Free with sk__hand_fit_data_free. */
sk_result sk__hand_fit_prepare(sk__hand_fit_data *fd, const sk_hand_skeleton *skeleton,
                               const sk_hand_samples *samples, const int *idx, int n,
                               const sk_hand_potential_desc *desc, sk_error *err);
void sk__hand_fit_data_free(sk__hand_fit_data *fd);

/* The PAIRS method (pair_select.c): fills `out` (one component). */
sk_result sk__hand_pairs_fit(sk_hand_potential *out, const sk_hand_skeleton *skeleton,
                             const sk__hand_fit_data *fd, const sk_hand_potential_desc *desc,
                             sk_error *err);

#endif
