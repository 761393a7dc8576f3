/* The batch of points the wood module evaluates together (eval.c): its size and the
 * samples it gives, one array entry per point (the fields of sk_wood_sample). */
#ifndef SK_WOOD_BATCH_H
#define SK_WOOD_BATCH_H

#include "shitsukan/vecmath.h"

/* Points evaluated together by sk__wood_eval_batch. */
#define SK__WOOD_BATCH 32

/* Optional outputs of sk__wood_eval_batch (the others are always filled). */
#define SK__WOOD_EVAL_DIVE 1u /* the dive angle (0 without it) */

typedef struct sk__wood_batch {
    float albedo[3][SK__WOOD_BATCH]; /* linear R, G, B */
    float vessel[SK__WOOD_BATCH];
    float fibre[3][SK__WOOD_BATCH]; /* unit fibre direction, scene frame */
    float dive[SK__WOOD_BATCH];     /* 0 without SK__WOOD_EVAL_DIVE */
    float t[SK__WOOD_BATCH], latewood[SK__WOOD_BATCH], phase[SK__WOOD_BATCH];
    sk_vec3f up; /* the same for every point (one normal) */
} sk__wood_batch;

#endif
