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

static inline bool sk__worker_trace(const sk_render_scene *scene, sk__worker *w,
                                    struct RTCRayHit *rh)
{
    if (!w->timing) return sk__trace(scene, rh);
    double t0 = sk_time_seconds();
    bool hit = sk__trace(scene, rh);
    w->intersect_seconds += sk_time_seconds() - t0;
    return hit;
}

static inline bool sk__worker_occluded(const sk_render_scene *scene, sk__worker *w, sk_vec3f o,
                                       sk_vec3f d, float tfar)
{
    w->shadow_rays++;
    if (!w->timing) return sk__occluded(scene, o, d, tfar);
    double t0 = sk_time_seconds();
    bool blocked = sk__occluded(scene, o, d, tfar);
    w->intersect_seconds += sk_time_seconds() - t0;
    return blocked;
}

/* Bumped and interpolated normals are lit right up to the geometric terminator, where
 * the shadow ray is cut off by the surface itself: a hard edge of light (the "shadow
 * terminator" problem). The light is faded out over the last few degrees before the
 * terminator (geometric cosine 0.15 .. 0) so the edge is soft. Where the shading normal
 * is the geometric one nothing changes, so flat and exactly tilted surfaces keep their
 * exact radiance. */
static inline float sk__terminator_fade(float cos_geometric, sk_vec3f ns, sk_vec3f ng)
{
    if (ns.x == ng.x && ns.y == ng.y && ns.z == ng.z) return 1.0f;
    return sk_smoothstepf(0.0f, 0.15f, cos_geometric);
}

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

/* The path integrator (path.c): the radiance of camera sample `sample` of `pixel` through
 * image position (x, y), and its coverage as sk__camera_sample. */
float sk__path_sample(const sk_render_scene *scene, sk__worker *w, uint64_t pixel, uint32_t sample,
                      float x, float y, sk_vec3f *radiance);

#endif
