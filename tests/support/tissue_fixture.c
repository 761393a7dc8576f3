/* The tissue tests' small character and scripted motions (see tissue_fixture.h). */
#include "tissue_fixture.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "test_support.h"

static void name(char *dst, const char *src) { strncpy(dst, src, SK_TISSUE_NAME_SIZE - 1); }

sk_tissue_character_desc *sk_test_rod_desc(double spacing_mm)
{
    sk_tissue_character_desc *d = calloc(1, sizeof *d);
    assert_non_null(d);
    name(d->name, "rod");
    d->joint_count = 3;
    name(d->joints[0].name, "Root");
    name(d->joints[1].name, "Hinge");
    name(d->joints[1].parent, "Root");
    d->joints[1].offset_mm[1] = -120;
    name(d->joints[2].name, "End");
    name(d->joints[2].parent, "Hinge");
    d->joints[2].offset_mm[1] = -100;
    d->bone_count = 2;
    name(d->bones[0].name, "upper");
    name(d->bones[0].joint, "Root");
    name(d->bones[0].end, "Hinge");
    d->bones[0].radius_mm = 12;
    name(d->bones[1].name, "lower");
    name(d->bones[1].joint, "Hinge");
    name(d->bones[1].end, "End");
    d->bones[1].radius_mm = 11;
    d->muscle_count = 1;
    sk_tissue_muscle_desc *mu = &d->muscles[0];
    name(mu->name, "flexor");
    name(mu->origin.bone, "upper");
    mu->origin.at = 0.25f;
    mu->origin.offset_mm[2] = 12;
    name(mu->insertion.bone, "lower");
    mu->insertion.at = 0.3f;
    mu->insertion.offset_mm[2] = 9;
    mu->thickness_mm = 18;
    mu->width_ratio = 1.3f;
    d->fat_count = 1;
    name(d->fat[0].name, "back");
    name(d->fat[0].around, "upper");
    d->fat[0].from = 0.2f;
    d->fat[0].to = 0.8f;
    d->fat[0].thickness_mm = 8;
    d->fat[0].direction[2] = -1;
    d->tracked_count = 1;
    name(d->tracked[0].name, "back");
    name(d->tracked[0].bone, "upper");
    d->tracked[0].at = 0.5f;
    d->tracked[0].direction[2] = -1;
    d->skin.spacing_mm = (float)spacing_mm;
    d->skin.dilations = 2;
    d->skin.dilation_radius_mm = (float)(2.0 * spacing_mm);
    sk_tissue_character_desc_resolve(d);
    sk_error err = {0};
    if (sk_tissue_character_desc_validate(d, &err) != SK_OK) fail_msg("rod desc: %s", err.message);
    return d;
}

sk_tissue_model *sk_test_rod_model(double spacing_mm)
{
    sk_tissue_character_desc *d = sk_test_rod_desc(spacing_mm);
    sk_tissue_model *m = NULL;
    sk_error err = {0};
    sk_result r = sk_tissue_model_build(d, NULL, &m, &err);
    free(d);
    if (r != SK_OK) fail_msg("rod model: %s", err.message);
    return m;
}

/* A smooth random signal in [-1, 1]: a few sines with hashed frequencies and phases. */
static double wobble(uint64_t seed, int channel, double t)
{
    double v = 0.0;
    for (int k = 0; k < 3; k++) {
        double f = 0.5 + 3.5 * sk_rand_uniform(seed, (uint64_t)channel, (uint64_t)k, 1);
        double ph = 2.0 * SK_PI * sk_rand_uniform(seed, (uint64_t)channel, (uint64_t)k, 2);
        v += sin(2.0 * SK_PI * f * t + ph) / 3.0;
    }
    return v;
}

static void sample(void *user, double t, sk_quatd *local, sk_vec3d *root)
{
    const sk_test_motion *m = user;
    *root = sk_v3d(0, 0, 0);
    switch (m->kind) {
    case SK_TEST_MOTION_STOP: {
        /* eased in over 0.2 s (a smooth start), constant, then a dead stop */
        double ease = 0.2, u = fmin(t, m->until);
        root->x = m->speed * (u < ease ? u * u / (2 * ease) : u - 0.5 * ease);
        break;
    }
    case SK_TEST_MOTION_UNIFORM:
        root->x = m->speed * t;
        break;
    case SK_TEST_MOTION_BEND: {
        double a = m->angle * fmin(t / m->until, 1.0);
        local[1] = sk_qd_axis_angle(sk_v3d(1, 0, 0), -a);
        break;
    }
    case SK_TEST_MOTION_RANDOM:
        *root = sk_v3d(60 * wobble(m->seed, 0, t), 40 * wobble(m->seed, 1, t),
                       60 * wobble(m->seed, 2, t));
        local[0] = sk_qd_axis_angle(sk_v3d(0, 0, 1), 0.6 * wobble(m->seed, 3, t));
        local[1] = sk_qd_axis_angle(sk_v3d(1, 0, 0), -1.0 - wobble(m->seed, 4, t));
        break;
    case SK_TEST_MOTION_TELEPORT:
        if (t >= m->until) root->x = m->speed;
        break;
    default:
        break;
    }
}

sk_tissue_motion sk_test_motion_get(const sk_test_motion *m, double duration)
{
    sk_tissue_motion out = {sample, (void *)m, duration};
    return out;
}
