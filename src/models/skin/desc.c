/* Skin parameters: defaults and validation of the six parameters of Ishii et al. 1991
 * (sec. 4.2, Fig. 11) plus tiling, pores and shading. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "models/skin/skin_internal.h"

/* The defaults computed from other keys (the others are stated in schema.c). */
#define SK__DEFAULT_SPACING_MM 0.8f
#define SK__DEFAULT_SPACING_RATIO 0.4f

static void set_segment(sk_skin_segment *s, const float p[4][2])
{
    memcpy(s->points, p, sizeof s->points);
}

/* The default skin: Table 1, Fig. 19a (3 levels, jitter 0.5, perturbation 0.1, round 0.2). */
static void default_skin_levels(sk_skin_desc *d)
{
    static const float prof[3][4][2] = {
        {{0, 4.0f}, {5, 4.0f}, {9, 3.0f}, {10, 0}},
        {{0, 2.0f}, {5, 2.0f}, {9, 1.5f}, {10, 0}},
        {{0, 0.8f}, {5, 0.8f}, {9, 0.4f}, {10, 0}},
    };
    memset(d->levels, 0, sizeof d->levels);
    d->level_count = 3;
    for (int k = 0; k < 3; k++) {
        sk_skin_level *lv = &d->levels[k];
        lv->jitter_rate = 0.5f;
        lv->perturb_rate = 0.1f;
        lv->perturb_decay = 0.5f;
        lv->segment_count = 1;
        set_segment(&lv->segments[0], prof[k]);
        lv->roundness = 0.2f;
    }
}

sk_skin_desc sk_skin_desc_resolved(const sk_skin_desc *desc)
{
    sk_skin_desc d;
    if (desc)
        d = *desc;
    else
        memset(&d, 0, sizeof d);
    if (d.level_count == 0) default_skin_levels(&d);
    /* the stated defaults (sk_skin_schema), of every level, and those computed here */
    sk_schema_apply_defaults(&sk_skin_schema, &d);
    float spacing = SK__DEFAULT_SPACING_MM;
    for (int k = 0; k < SK_SKIN_MAX_LEVELS; k++) {
        sk_skin_level *lv = &d.levels[k];
        sk_schema_apply_defaults(&sk__skin_level_schema, lv);
        if (lv->spacing_mm == 0.0f) lv->spacing_mm = spacing;
        spacing = lv->spacing_mm * SK__DEFAULT_SPACING_RATIO;
        if (lv->segment_count == 0) {
            static const float fig13c[4][2] = {{0, 3.0f}, {5, 3.0f}, {8, 2.5f}, {10, 0}};
            lv->segment_count = 1;
            set_segment(&lv->segments[0], fig13c);
        }
    }
    return d;
}

/* A key path such as "levels[1].jitter_rate", for the range checks' messages. */
static const char *key(char buf[160], const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
static const char *key(char buf[160], const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(buf, 160, fmt, ap);
    va_end(ap);
    return buf;
}

#define TRY(expr)                                                                                  \
    do {                                                                                           \
        sk_result r_ = (expr);                                                                     \
        if (r_ != SK_OK) return r_;                                                                \
    } while (0)

/* Parameter 5: a chain of cubic Bezier segments whose x runs monotonically from 0 to 10
 * (centre to boundary), so Bx(t) = x' has one solution (sec. 3.2.1 (2)). */
static sk_result validate_profile(const sk_skin_level *lv, int k, sk_error *err)
{
    char name[160];
    for (int s = 0; s < lv->segment_count; s++)
        for (int i = 0; i < 4; i++)
            TRY(sk_check_range_f(err, key(name, "levels[%d].profile[%d].points[%d][0]", k, s, i),
                                 lv->segments[s].points[i][0], 0, 10));
    if (lv->segment_count == 0) return SK_OK;
    const sk_skin_segment *seg = lv->segments;
    if (seg[0].points[0][0] != 0.0f)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "levels[%d].profile[0].points[0][0] = %g: the profile must start at "
                       "x = 0 (the cell centre)",
                       k, seg[0].points[0][0]);
    const sk_skin_segment *last = &seg[lv->segment_count - 1];
    if (last->points[3][0] != 10.0f)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "levels[%d].profile[%d].points[3][0] = %g: the profile must end at "
                       "x = 10 (the cell boundary)",
                       k, lv->segment_count - 1, last->points[3][0]);
    for (int s = 0; s < lv->segment_count; s++) {
        for (int i = 1; i < 4; i++)
            if (seg[s].points[i][0] < seg[s].points[i - 1][0])
                return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                               "levels[%d].profile[%d].points[%d][0] = %g is less than the "
                               "previous point's x = %g: the profile's x must not decrease",
                               k, s, i, seg[s].points[i][0], seg[s].points[i - 1][0]);
        if (!(seg[s].points[3][0] > seg[s].points[0][0]))
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "levels[%d].profile[%d]: x must increase from its first to its "
                           "last point (both are %g)",
                           k, s, seg[s].points[0][0]);
        if (s > 0 && (fabsf(seg[s].points[0][0] - seg[s - 1].points[3][0]) > 1e-4f ||
                      fabsf(seg[s].points[0][1] - seg[s - 1].points[3][1]) > 1e-4f))
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "levels[%d].profile[%d].points[0] = (%g, %g) must equal the end "
                           "of profile[%d], (%g, %g)",
                           k, s, seg[s].points[0][0], seg[s].points[0][1], s - 1,
                           seg[s - 1].points[3][0], seg[s - 1].points[3][1]);
    }
    return SK_OK;
}

sk_result sk_skin_desc_validate(const sk_skin_desc *desc, sk_error *err)
{
    char name[160];
    if (!desc) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "skin desc is NULL");
    TRY(sk_check_range_i(err, key(name, "level_count"), desc->level_count, 0, SK_SKIN_MAX_LEVELS));
    for (int k = 0; k < desc->level_count; k++)
        TRY(sk_check_range_i(err, key(name, "levels[%d].profile", k), desc->levels[k].segment_count,
                             0, SK_SKIN_MAX_SEGMENTS));
    /* every range, as sk_skin_schema states it */
    TRY(sk_schema_check(&sk_skin_schema, desc, "", err));
    /* the rules between keys */
    for (int k = 0; k < desc->level_count; k++) TRY(validate_profile(&desc->levels[k], k, err));
    int levels = desc->level_count ? desc->level_count : 3;
    TRY(sk_check_range_i(err, key(name, "pores.sweat_level"), desc->pores.sweat_level, 0, levels));
    return SK_OK;
}
