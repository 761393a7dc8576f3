/* The tree object: the resolved desc and every table built from it (Kawai 2000). */
#ifndef SK_WOOD_INTERNAL_H
#define SK_WOOD_INTERNAL_H

#include "shitsukan/wood.h"
#include "wood/attributes.h"
#include "wood/frame.h"
#include "wood/grain.h"
#include "wood/rings.h"
#include "wood/shade.h"
#include "wood/vessels.h"

struct sk_wood {
    sk_wood_desc desc; /* resolved */
    sk__wood_frame frame;
    sk__rings rings;
    sk__grain grain;
    sk__vessels vessels;
    sk__attributes attr;
    sk__shading shading;
    sk_vec3f axis;     /* the tree's +y in the scene */
    sk_wood_stats stats;
};

/* Points evaluated together by sk__wood_eval_batch. */
#define SK__WOOD_BATCH 16

/* sk_wood_eval_filtered for `count` <= SK__WOOD_BATCH points with one normal. */
void sk__wood_eval_batch(const sk_wood *wood, int count, const sk_vec3f *points, sk_vec3f normal,
                         float footprint_mm, sk_wood_sample *out);

#endif
