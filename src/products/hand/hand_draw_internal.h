/* Private pieces shared by the skeleton pictures' layout and drawing. */
#ifndef SK_HAND_DRAW_INTERNAL_H
#define SK_HAND_DRAW_INTERNAL_H

#include "shitsukan/hand.h"

/* Length of forearm shown below the wrist, in hand lengths. */
#define SK_HAND__FOREARM_SHOWN 0.12

typedef struct sk__hand_band_sizes {
    int margin;  /* around the drawing area */
    int title;   /* panel title above the drawing area (0 when hidden) */
    int cues;    /* direction arrows and scale bar below it (0 when hidden) */
    int caption; /* one line under all panels (0 without a caption) */
} sk__hand_band_sizes;

/* Names beside points without covering each other, the bones or the joints: each label
 * takes the first of a ring of candidate places (nearest first, starting on the side
 * `prefer_x` (+1 right, -1 left) points to) with the least overlap, and gets a thin
 * leader line when it had to move away from its point. `bones` holds bone_count pairs of
 * point indices; labels stay inside [x0, x1) x [y0, y1). */
typedef struct sk__hand_label_scene {
    const sk_vec2f *points; /* point_count positions */
    const float *radius;    /* disc radius of each point */
    int point_count;
    const int (*bones)[2];
    int bone_count;
    float bone_width;
    float x0, y0, x1, y1;
} sk__hand_label_scene;
void sk__hand_draw_labels(sk_image *img, const sk__hand_label_scene *scene,
                          const char *const *names, const sk_color *colors, const float *prefer_x,
                          int scale);

void sk__hand_bands(const sk_hand_draw_desc *resolved, sk__hand_band_sizes *bands);
const char *sk__hand_view_title(sk_hand_view view);

#endif /* SK_HAND_DRAW_INTERNAL_H */
