/* Dense linear algebra and Gaussian statistics for the calibrated potential of natural
 * posture (thesis 3.2.2 read as a Gaussian, eq. 3.17): small symmetric matrices
 * (n <= SK_HAND_DOF_COUNT), column-major, through dense_internal.h. */
#ifndef SK_HAND_GAUSSIAN_INTERNAL_H
#define SK_HAND_GAUSSIAN_INTERNAL_H

#include <stdbool.h>

#include "models/hand/dense_internal.h"
#include "models/hand/hand_internal.h"

/* log det of L L'. */
double sk__hand_cholesky_logdet(const double *l, int n);
/* Mean and scatter sum_i (x_i - mean)(x_i - mean)' of the columns `dofs[0..d)` over the
 * samples idx[0..n) (all samples when idx is NULL). */
void sk__hand_moments(const sk_hand_samples *s, const int *dofs, int d, const int *idx, int n,
                      double *mean, double *scatter);

/* Gaussian conditional mean in precision form: with precision P (d x d) and the
 * coordinates split by `pinned`, x_u = mu_u + B (x_p - mu_p) with B = -P_uu^-1 P_up.
 * Writes B as nu x np (column-major, nu rows) into `b`; returns false if P_uu is not
 * positive definite. */
bool sk__hand_conditional(const double *p, int d, const bool *pinned, double *b);

/* log N(x; mu, Sigma) given the Cholesky factor of Sigma and its log det. */
double sk__hand_gauss_logpdf(const double *x, const double *mu, const double *chol, double logdet,
                             int d);

#endif
