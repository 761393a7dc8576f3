/* Origins of secondary rays, moved off the surface just far enough that the ray cannot hit
 * the surface it leaves (no shadow acne), in the manner of Waechter and Binder, "A Fast and
 * Robust Method for Avoiding Self-Intersection" (Ray Tracing Gems, 2019, ch. 6): the
 * offset grows with the coordinate's magnitude (a fixed number of float steps), with an
 * absolute floor near the origin where float steps vanish. */
#ifndef SK_RENDER_RAY_OFFSET_H
#define SK_RENDER_RAY_OFFSET_H

#include <math.h>
#include <stdint.h>
#include <string.h>

#include "shitsukan/vecmath.h"

/* Float steps of offset per unit of normal: covers the rounding of the hit point rebuilt
 * from barycentrics and moved through an instance transform. */
#define SK__OFFSET_INT_SCALE 256.0f
/* Below this magnitude, offset by an absolute amount instead (scene units). */
#define SK__OFFSET_ORIGIN 1.0f / 32.0f
#define SK__OFFSET_FLOAT_SCALE 1.0f / 65536.0f

static inline float sk__offset_coord(float p, float n)
{
    int32_t steps = (int32_t)(SK__OFFSET_INT_SCALE * n);
    int32_t bits;
    memcpy(&bits, &p, sizeof bits);
    bits += (p < 0.0f) ? -steps : steps;
    float moved;
    memcpy(&moved, &bits, sizeof moved);
    return fabsf(p) < SK__OFFSET_ORIGIN ? p + SK__OFFSET_FLOAT_SCALE * n : moved;
}

/* p moved along the unit geometric normal ng, to the side `dir` points to. */
static inline sk_vec3f sk__offset_origin(sk_vec3f p, sk_vec3f ng, sk_vec3f dir)
{
    if (sk_v3f_dot(ng, dir) < 0.0f) ng = sk_v3f_neg(ng);
    return sk_v3f(sk__offset_coord(p.x, ng.x), sk__offset_coord(p.y, ng.y),
                  sk__offset_coord(p.z, ng.z));
}

#endif
