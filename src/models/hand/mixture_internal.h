/* Mixtures of Gaussians over the calibrated DOFs (src/models/hand/mixture.c), used by the
 * calibrated potential (potential_*.c): fitting by EM and the held-out error of the
 * prediction from pinned joints. */
#ifndef SK_HAND_MIXTURE_INTERNAL_H
#define SK_HAND_MIXTURE_INTERNAL_H

#include <stdbool.h>
#include <stdint.h>

#include "models/hand/hand_internal.h"

/* Smallest variance kept on any DOF (a joint that never moved in the samples), rad^2. */
#define SK_HAND__VARIANCE_FLOOR ((0.25 * SK_DEG_TO_RAD) * (0.25 * SK_DEG_TO_RAD))

typedef struct sk__hand_mixture {
    int m, d;
    double weight[SK_HAND_POTENTIAL_MAX_COMPONENTS];
    double mean[SK_HAND_POTENTIAL_MAX_COMPONENTS][SK_HAND_DOF_COUNT];
    double cov[SK_HAND_POTENTIAL_MAX_COMPONENTS][SK_HAND_DOF_COUNT * SK_HAND_DOF_COUNT];
    double chol[SK_HAND_POTENTIAL_MAX_COMPONENTS][SK_HAND_DOF_COUNT * SK_HAND_DOF_COUNT];
    double logdet[SK_HAND_POTENTIAL_MAX_COMPONENTS];
} sk__hand_mixture;

/* EM for m components on the rows x[0..n) (n x d, row-major), each covariance shrunk
 * toward `pooled` by `nu` pseudo-samples; `resp` has room for n x m. False if a
 * covariance is not positive definite or memory runs out. */
bool sk__hand_mixture_fit(sk__hand_mixture *g, const double *x, int n, int d, int m,
                          const double *pooled, double nu, uint64_t seed, double *resp);
/* One component: mean mu, covariance sigma. */
void sk__hand_mixture_single(sk__hand_mixture *g, int d, const double *mu, const double *sigma);
/* Sum of squared errors of the prediction of the unpinned coordinates from the pinned
 * ones (`masks[p][a]` true where pattern p pins coordinate a), over the patterns and the
 * rows x[0..n); limits left out (a closed form). INFINITY if a block is not positive
 * definite. */
double sk__hand_mixture_validation_error(const sk__hand_mixture *g, const double *x, int n,
                                         bool (*masks)[SK_HAND_DOF_COUNT], int mask_count);

#endif
