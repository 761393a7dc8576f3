/* Skin parameters: defaults and validation of the six parameters of Ishii et al. 1991
 * (sec. 4.2, Fig. 11) plus tiling, pores and shading. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "models/skin/skin_internal.h"

#define SK__DEFAULT_SIZE_MM 10.0f
#define SK__DEFAULT_SPACING_MM 0.8f
#define SK__DEFAULT_SPACING_RATIO 0.4f
#define SK__DEFAULT_DEPTH 4

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
    for (int i = 0; i < 2; i++)
        if (d.size_mm[i] == 0.0f) d.size_mm[i] = SK__DEFAULT_SIZE_MM;
    if (d.level_count == 0) default_skin_levels(&d);
    float spacing = SK__DEFAULT_SPACING_MM;
    for (int k = 0; k < SK_SKIN_MAX_LEVELS; k++) {
        sk_skin_level *lv = &d.levels[k];
        if (lv->layout == SK_SKIN_LAYOUT_DEFAULT) lv->layout = SK_SKIN_LAYOUT_TRIANGULAR;
        if (lv->jitter == SK_SKIN_JITTER_DEFAULT) lv->jitter = SK_SKIN_JITTER_UNIFORM;
        if (lv->spacing_mm == 0.0f) lv->spacing_mm = spacing;
        spacing = lv->spacing_mm * SK__DEFAULT_SPACING_RATIO;
        if (lv->perturb_depth == 0) lv->perturb_depth = SK__DEFAULT_DEPTH;
        for (int i = 0; i < 2; i++)
            if (lv->stretch[i] == 0.0f) lv->stretch[i] = 1.0f;
        if (lv->segment_count == 0) {
            static const float fig13c[4][2] = {{0, 3.0f}, {5, 3.0f}, {8, 2.5f}, {10, 0}};
            lv->segment_count = 1;
            set_segment(&lv->segments[0], fig13c);
        }
    }
    if (d.normal_model == SK_SKIN_NORMAL_DEFAULT) d.normal_model = SK_SKIN_NORMAL_GRADIENT;
    sk_skin_pore_kind *kinds[2] = {&d.pores.hair, &d.pores.sweat};
    for (int i = 0; i < 2; i++) {
        if (kinds[i]->radius_mm == 0.0f) kinds[i]->radius_mm = 0.03f;
        if (kinds[i]->density == 0.0f) kinds[i]->density = 0.5f;
    }
    if (d.pores.sweat_level == 0) d.pores.sweat_level = 1;
    sk_skin_shading *sh = &d.shading;
    if (sh->light_elevation == 0.0f) sh->light_elevation = (float)(SK_PI / 4.0);
    if (sh->albedo[0] == 0.0f && sh->albedo[1] == 0.0f && sh->albedo[2] == 0.0f) {
        sh->albedo[0] = 0.80f;
        sh->albedo[1] = 0.52f;
        sh->albedo[2] = 0.42f;
    }
    if (sh->sun_fraction == 0.0f) sh->sun_fraction = 0.85f;
    if (sh->specular == 0.0f) sh->specular = 0.06f;
    if (sh->shininess == 0.0f) sh->shininess = 24.0f;
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

/* Parameter 5: a chain of cubic Bezier segments whose x runs monotonically from 0 to 10,
 * so Bx(t) = x' has one solution (sec. 3.2.1 (2)). */
static sk_result validate_profile(const sk_skin_level *lv, int k, sk_error *err)
{
    char name[160];
    TRY(sk_check_range_i(err, key(name, "levels[%d].profile", k), lv->segment_count, 0,
                         SK_SKIN_MAX_SEGMENTS));
    if (lv->segment_count == 0) return SK_OK;
    for (int s = 0; s < lv->segment_count; s++)
        for (int i = 0; i < 4; i++) {
            TRY(sk_check_range_f(err, key(name, "levels[%d].profile[%d].points[%d][0]", k, s, i),
                                 lv->segments[s].points[i][0], 0, 10));
            TRY(sk_check_range_f(err, key(name, "levels[%d].profile[%d].points[%d][1]", k, s, i),
                                 lv->segments[s].points[i][1], -1000, 1000));
        }
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

static sk_result validate_level(const sk_skin_level *lv, int k, sk_error *err)
{
    char name[160];
    TRY(sk_check_range_i(err, key(name, "levels[%d].layout", k), lv->layout, SK_SKIN_LAYOUT_DEFAULT,
                         SK_SKIN_LAYOUT_RANDOM));
    TRY(sk_check_range_i(err, key(name, "levels[%d].jitter", k), lv->jitter, SK_SKIN_JITTER_DEFAULT,
                         SK_SKIN_JITTER_NORMAL));
    TRY(sk_check_range_f(err, key(name, "levels[%d].jitter_rate", k), lv->jitter_rate, 0, 1));
    TRY(sk_check_range_f(err, key(name, "levels[%d].spacing_mm", k), lv->spacing_mm, 0, 1000));
    TRY(sk_check_range_f(err, key(name, "levels[%d].perturb_rate", k), lv->perturb_rate, 0, 1));
    TRY(sk_check_range_f(err, key(name, "levels[%d].perturb_decay", k), lv->perturb_decay, 0, 4));
    TRY(sk_check_range_i(err, key(name, "levels[%d].perturb_depth", k), lv->perturb_depth, 0, 10));
    for (int i = 0; i < 2; i++)
        TRY(sk_check_range_f(err, key(name, "levels[%d].stretch[%d]", k, i), lv->stretch[i], 0,
                             100));
    TRY(sk_check_range_f(err, key(name, "levels[%d].stretch_angle", k), lv->stretch_angle,
                         -2 * SK_PI, 2 * SK_PI));
    TRY(validate_profile(lv, k, err));
    TRY(sk_check_range_f(err, key(name, "levels[%d].roundness", k), lv->roundness, 0, 1));
    return SK_OK;
}

static sk_result validate_pore(const sk_skin_pore_kind *p, const char *kind, sk_error *err)
{
    char name[160];
    TRY(sk_check_range_f(err, key(name, "pores.%s.depth_mm", kind), p->depth_mm, 0, 10));
    TRY(sk_check_range_f(err, key(name, "pores.%s.radius_mm", kind), p->radius_mm, 0, 10));
    TRY(sk_check_range_f(err, key(name, "pores.%s.density", kind), p->density, 0, 1));
    return SK_OK;
}

sk_result sk_skin_desc_validate(const sk_skin_desc *desc, sk_error *err)
{
    char name[160];
    if (!desc) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "skin desc is NULL");
    for (int i = 0; i < 2; i++)
        TRY(sk_check_range_f(err, key(name, "size_mm[%d]", i), desc->size_mm[i], 0, 1000));
    TRY(sk_check_range_i(err, key(name, "level_count"), desc->level_count, 0, SK_SKIN_MAX_LEVELS));
    for (int k = 0; k < desc->level_count; k++) TRY(validate_level(&desc->levels[k], k, err));
    TRY(sk_check_range_i(err, key(name, "normal_model"), desc->normal_model, SK_SKIN_NORMAL_DEFAULT,
                         SK_SKIN_NORMAL_PROFILE));
    TRY(validate_pore(&desc->pores.hair, "hair", err));
    TRY(validate_pore(&desc->pores.sweat, "sweat", err));
    int levels = desc->level_count ? desc->level_count : 3;
    TRY(sk_check_range_i(err, key(name, "pores.sweat_level"), desc->pores.sweat_level, 0, levels));
    const sk_skin_shading *sh = &desc->shading;
    TRY(sk_check_range_f(err, key(name, "shading.light_azimuth"), sh->light_azimuth, -2 * SK_PI,
                         2 * SK_PI));
    TRY(sk_check_range_f(err, key(name, "shading.light_elevation"), sh->light_elevation, 0,
                         SK_PI / 2 + 1e-6));
    for (int i = 0; i < 3; i++)
        TRY(sk_check_range_f(err, key(name, "shading.albedo[%d]", i), sh->albedo[i], 0, 1));
    TRY(sk_check_range_f(err, key(name, "shading.sun_fraction"), sh->sun_fraction, 0, 1));
    TRY(sk_check_range_f(err, key(name, "shading.specular"), sh->specular, 0, 1));
    TRY(sk_check_range_f(err, key(name, "shading.shininess"), sh->shininess, 0, 1000));
    return SK_OK;
}
