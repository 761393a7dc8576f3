/* Private: the radiance of one camera sample (integrator.c), called by the tile loop. */
#ifndef SK_RENDER_INTEGRATOR_H
#define SK_RENDER_INTEGRATOR_H

#include "render/render_internal.h"
#include "render/sampling.h"

/* Per-thread counters of the tile loop. */
typedef struct sk__worker {
    bool timing;              /* measure time inside Embree */
    long long shadow_rays;    /* light and occlusion rays traced */
    double intersect_seconds; /* inside rtcIntersect1 / rtcOccluded1 (when timing) */
} sk__worker;

/* The sample patterns of one pixel (made once per pixel) and the current sample's index:
 * all random numbers of a sample derive from these. */
typedef struct sk__sample_id {
    uint32_t sample;                          /* index of the camera sample in the pixel */
    sk__pattern ao;                           /* occlusion rays: ao_samples per sample */
    sk__pattern lights[SK_RENDER_MAX_LIGHTS]; /* area light points: samples per sample */
} sk__sample_id;

/* Sets up the patterns of pixel (y * width + x). */
void sk__sample_id_init(const sk_render_scene *scene, uint64_t pixel, sk__sample_id *id);

/* Traces the camera ray through image position (x, y) (pixels, continuous) and returns its
 * coverage (1 hit or opaque background, 0 transparent background) with the radiance. */
float sk__camera_sample(const sk_render_scene *scene, sk__worker *w, const sk__sample_id *id,
                        float x, float y, sk_vec3f *radiance);

#endif
