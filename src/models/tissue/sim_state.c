/* A simulation's state as bytes, so a run can stop and resume bit for bit: the step
 * count and the fat and skin points' positions (now and one step before) and velocities.
 * Muscle and bone points and the bones are not stored: they follow from the motion at
 * the step. A fingerprint of the model (points, masses, material, step rate) guards
 * against resuming with another character. Layout (host byte order, little-endian
 * machines): "SKTSTATE", u32 version 1, u32 step_hz, u64 fingerprint, i64 step,
 * u64 free points, then 3 x free doubles each of x, x one step before, v (mm, mm/s). */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "shitsukan/io.h"
#include "models/tissue/sim_internal.h"

#define MAGIC "SKTSTATE"
#define VERSION 1u
#define HEADER (8 + 4 + 4 + 8 + 8 + 8)

size_t sk_tissue_sim_state_size(const sk_tissue_sim *s)
{
    return HEADER + 9 * s->nfree * sizeof(double);
}

sk_result sk_tissue_sim_save_state(const sk_tissue_sim *s, void *buffer, size_t size, sk_error *err)
{
    if (!buffer || size < sk_tissue_sim_state_size(s))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "state buffer of %zu bytes is smaller than %zu", size,
                       sk_tissue_sim_state_size(s));
    uint8_t *b = buffer;
    uint32_t version = VERSION, hz = (uint32_t)s->step_hz;
    uint64_t n = s->nfree;
    memcpy(b, MAGIC, 8);
    memcpy(b + 8, &version, 4);
    memcpy(b + 12, &hz, 4);
    memcpy(b + 16, &s->fingerprint, 8);
    memcpy(b + 24, &s->step, 8);
    memcpy(b + 32, &n, 8);
    size_t block = 3 * s->nfree * sizeof(double);
    memcpy(b + HEADER, s->x, block);
    memcpy(b + HEADER + block, s->prev, block);
    memcpy(b + HEADER + 2 * block, s->v, block);
    return SK_OK;
}

sk_result sk_tissue_sim_load_state(sk_tissue_sim *s, const void *buffer, size_t size, sk_error *err)
{
    const uint8_t *b = buffer;
    if (!b || size < HEADER || memcmp(b, MAGIC, 8) != 0)
        return sk_fail(err, SK_ERROR_PARSE, "not a tissue simulation state (no \"%s\" header)",
                       MAGIC);
    uint32_t version, hz;
    uint64_t fp, n;
    int64_t step;
    memcpy(&version, b + 8, 4);
    memcpy(&hz, b + 12, 4);
    memcpy(&fp, b + 16, 8);
    memcpy(&step, b + 24, 8);
    memcpy(&n, b + 32, 8);
    if (version != VERSION)
        return sk_fail(err, SK_ERROR_UNSUPPORTED, "state version %u (this reader knows %u)",
                       version, VERSION);
    if (hz != (uint32_t)s->step_hz)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "the state was saved at %u steps/s, this simulation runs %d", hz,
                       s->step_hz);
    if (n != s->nfree || fp != s->fingerprint)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "the state belongs to another character or material (%llu free points, this "
                       "one has %zu)",
                       (unsigned long long)n, s->nfree);
    /* a state must be one the simulation can go on from (found by fuzz_tissue_state) */
    if (step < 0 || (double)step > SK__SIM_MAX_SECONDS * s->step_hz)
        return sk_fail(err, SK_ERROR_PARSE,
                       "state step %lld is not a step count in [0, %g] (%g s at %d steps/s)",
                       (long long)step, SK__SIM_MAX_SECONDS * s->step_hz, SK__SIM_MAX_SECONDS,
                       s->step_hz);
    if (size != sk_tissue_sim_state_size(s))
        return sk_fail(err, SK_ERROR_PARSE,
                       "state of %zu bytes, expected %zu (truncated or padded)", size,
                       sk_tissue_sim_state_size(s));
    size_t block = 3 * s->nfree * sizeof(double);
    for (size_t i = 0; i < 9 * s->nfree; i++) {
        double v;
        memcpy(&v, b + HEADER + i * sizeof(double), sizeof v);
        if (!isfinite(v) || fabs(v) > 1e12)
            return sk_fail(err, SK_ERROR_PARSE, "state value %zu is not finite", i);
    }
    s->step = step;
    memcpy(s->x, b + HEADER, block);
    memcpy(s->prev, b + HEADER + block, block);
    memcpy(s->v, b + HEADER + 2 * block, block);
    /* the driven points and the bones follow from the motion */
    sk__sim_pose_at(s, step, &s->pose);
    if (step > 0)
        sk__sim_pose_at(s, step - 1, &s->pose_prev);
    else
        s->pose_prev = s->pose;
    sk__sim_shape_muscles(s, &s->pose_prev, s->muscle_prev);
    sk__sim_place_anchors(s, &s->pose_prev, s->muscle_prev, s->prev);
    sk__sim_shape_muscles(s, &s->pose, s->muscle);
    sk__sim_place_anchors(s, &s->pose, s->muscle, s->x);
    s->obstacle_count = sk__obstacles(s->m, &s->pose, s->muscle, s->obstacles);
    for (size_t p = 0; p < s->nfree; p++) {
        sk_vec3d a = sk__sim_carried(s, &s->pose_prev, s->muscle_prev, p),
                 c = sk__sim_carried(s, &s->pose, s->muscle, p);
        double av[3] = {a.x, a.y, a.z}, cv[3] = {c.x, c.y, c.z};
        for (int k = 0; k < 3; k++) {
            s->target_base[3 * p + (size_t)k] = av[k];
            s->target[3 * p + (size_t)k] = cv[k];
        }
    }
    return SK_OK;
}
