/* A small character and scripted motions for the tissue tests: two bones (120 and 100 mm)
 * on a hinge, a muscle across the hinge, a fat region on the first bone; the motions hold
 * still, translate and stop, bend, move at random, or jump. */
#ifndef SK_TEST_TISSUE_FIXTURE_H
#define SK_TEST_TISSUE_FIXTURE_H

#include "shitsukan/tissue.h"

/* The desc (resolved, valid) with grid spacing `spacing_mm`. Free with free(). */
sk_tissue_character_desc *sk_test_rod_desc(double spacing_mm);
/* The built model (fails the test on error). */
sk_tissue_model *sk_test_rod_model(double spacing_mm);

typedef enum sk_test_motion_kind {
    SK_TEST_MOTION_REST = 0, /* the rest pose for ever */
    SK_TEST_MOTION_STOP,     /* along +x, eased in to `speed` mm/s over 0.2 s, until `until` s, then
                                still */
    SK_TEST_MOTION_BEND,     /* the hinge bends to `angle` rad by `until` s, then holds */
    SK_TEST_MOTION_RANDOM,   /* smooth random translation and bending (seeded) */
    SK_TEST_MOTION_TELEPORT, /* still, then at `until` s the root jumps by `speed` mm */
    SK_TEST_MOTION_UNIFORM   /* along +x at `speed` mm/s for ever */
} sk_test_motion_kind;

typedef struct sk_test_motion {
    sk_test_motion_kind kind;
    double speed, until, angle;
    uint64_t seed;
} sk_test_motion;

/* The motion as the simulation samples it (`m` must outlive it). */
sk_tissue_motion sk_test_motion_get(const sk_test_motion *m, double duration);

#endif
