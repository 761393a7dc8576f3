/* Keyframe animation, thesis 4.2.2-4.2.3: partial inputs (pinned angles, torques) at
 * keys, interpolated frame by frame by cubic Bezier curves (or Catmull-Rom), the
 * equilibrium solved at every frame by the caller. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "models/hand/hand_internal.h"
#include "shitsukan/io.h"

double sk_hand_interpolate(sk_hand_interp interp, double p0, double p1, double p2, double p3,
                           double t)
{
    if (interp == SK_HAND_INTERP_CATMULL_ROM) {
        double t2 = t * t, t3 = t2 * t;
        return 0.5 * (2.0 * p1 + (p2 - p0) * t + (2.0 * p0 - 5.0 * p1 + 4.0 * p2 - p3) * t2 +
                      (3.0 * p1 - p0 - 3.0 * p2 + p3) * t3);
    }
    /* cubic Bezier with control values (p1, p1, p2, p2) over a linear time axis (time
       handles at 1/3 and 2/3): B(t) = p1 + (p2 - p1)(3t^2 - 2t^3), at rest at each key */
    return p1 + (p2 - p1) * t * t * (3.0 - 2.0 * t);
}

int sk_hand_animation_frame_count(const sk_hand_animation *a)
{
    return a->key_count < 2 ? a->key_count : (a->key_count - 1) * a->steps + 1;
}

/* Value of one channel (the keys where `has` is set) at key position u. */
static double channel_value(const sk_hand_animation *a, const bool *has, const double *val,
                            size_t stride, double u)
{
    int idx[SK_HAND_MAX_KEYS], n = 0;
    for (int k = 0; k < a->key_count; k++)
        if (*(const bool *)((const char *)has + k * stride)) idx[n++] = k;
#define VAL(k) (*(const double *)((const char *)val + (size_t)(k)*stride))
    if (u <= idx[0]) return VAL(idx[0]);
    if (u >= idx[n - 1]) return VAL(idx[n - 1]);
    int s = 0;
    while (s + 1 < n - 1 && idx[s + 1] <= u) s++;
    double t = (u - idx[s]) / (double)(idx[s + 1] - idx[s]);
    double p1 = VAL(idx[s]), p2 = VAL(idx[s + 1]);
    double p0 = s > 0 ? VAL(idx[s - 1]) : p1;
    double p3 = s + 2 < n ? VAL(idx[s + 2]) : p2;
#undef VAL
    return sk_hand_interpolate(a->interp, p0, p1, p2, p3, t);
}

void sk_hand_animation_input(const sk_hand_animation *a, int frame, sk_hand_input *out)
{
    memset(out, 0, sizeof *out);
    if (a->key_count == 0) return;
    double u = a->key_count < 2 ? 0.0 : (double)frame / a->steps;
    const size_t stride = sizeof(sk_hand_key);
    for (int d = 0; d < SK_HAND_DOF_COUNT; d++) {
        bool any_pin = false, any_torque = false;
        for (int k = 0; k < a->key_count; k++) {
            any_pin |= a->keys[k].has_pin[d];
            any_torque |= a->keys[k].has_torque[d];
        }
        if (any_pin) {
            out->pinned[d] = true;
            out->pin_value[d] =
                channel_value(a, &a->keys[0].has_pin[d], &a->keys[0].pin[d], stride, u);
        }
        if (any_torque)
            out->torque[d] =
                channel_value(a, &a->keys[0].has_torque[d], &a->keys[0].torque[d], stride, u);
    }
}

void sk_hand_animation_driven(const sk_hand_animation *a, bool driven[SK_HAND_DOF_COUNT])
{
    for (int d = 0; d < SK_HAND_DOF_COUNT; d++) {
        driven[d] = false;
        for (int k = 0; k < a->key_count; k++)
            driven[d] |=
                a->keys[k].has_pin[d] || (a->keys[k].has_torque[d] && a->keys[k].torque[d] != 0.0);
    }
}
