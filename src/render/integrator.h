/* Private: the radiance of one camera sample (integrator.c), called by the tile loop. */
#ifndef SK_RENDER_INTEGRATOR_H
#define SK_RENDER_INTEGRATOR_H

#include "render/render_internal.h"

/* Per-thread counters of the tile loop. */
typedef struct sk__worker {
    bool timing;              /* measure time inside Embree */
    long long shadow_rays;    /* light and occlusion rays traced */
    double intersect_seconds; /* inside rtcIntersect1 / rtcOccluded1 (when timing) */
} sk__worker;

/* Which sample this is: all its random numbers derive from these. */
typedef struct sk__sample_id {
    uint64_t seed;
    uint64_t pixel;   /* y * width + x */
    uint32_t sample;  /* index of the camera sample in the pixel */
    uint32_t samples; /* camera samples per pixel */
} sk__sample_id;

/* Traces the camera ray through image position (x, y) (pixels, continuous) and returns its
 * coverage (1 hit or opaque background, 0 transparent background) with the radiance. */
float sk__camera_sample(const sk_render_scene *scene, sk__worker *w, const sk__sample_id *id,
                        float x, float y, sk_vec3f *radiance);

#endif
