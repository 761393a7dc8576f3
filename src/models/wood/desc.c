/* The wood desc: defaults for zero fields and validation with key paths (the parameters
 * of Kawai 2000 sec. 4-7, in mm and radians). */
#include <math.h>
#include <stdio.h>

#include "shitsukan/wood.h"

static void default_f(float *v, float def)
{
    if (*v == 0.0f) *v = def;
}

sk_wood_desc sk_wood_desc_resolved(const sk_wood_desc *desc)
{
    sk_wood_desc d = {0};
    if (desc) d = *desc;
    /* the defaults sk_wood_schema states, then those computed from other keys */
    sk_schema_apply_defaults(&sk_wood_schema, &d);
    sk_wood_shading_desc *sh = &d.shading;
    default_f(&sh->diffuse, 1.0f - sh->specular);
    sk_wood_view_desc *v = &d.view;
    if (v->plane != SK_WOOD_PLANE_END) default_f(&v->distance_mm, 0.5f * d.log.radius_mm);
    return d;
}

/* Checks that stop at the first failure. */
#define CHECK(call)                                                                                \
    do {                                                                                           \
        sk_result check_result_ = (call);                                                          \
        if (check_result_ != SK_OK) return check_result_;                                          \
    } while (0)

static sk_result check_vessel_fit(sk_error *err, const char *key, double radius, double sd,
                                  int rows, double ring_width)
{
    double need = 2.0 * (radius + 3.0 * sd) * rows;
    if (need > ring_width)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "%s.radius_mm = %g is too large for rings.width_mm = %g: %d row(s) of "
                       "vessels of diameter 2 (radius_mm + 3 radius_sd_mm) = %g mm must fit "
                       "in a ring",
                       key, radius, ring_width, rows, need / rows);
    return SK_OK;
}

/* Rings and grain: the rules between keys (sec. 4.4, eq. 1). */
static sk_result check_rings_grain(const sk_wood_desc *d, sk_error *err)
{
    char name[96];
    const sk_wood_rings_desc *rg = &d->rings;
    if (rg->transition + rg->latewood_fraction > 1.0f)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "rings.transition = %g plus rings.latewood_fraction = %g exceeds 1 (a whole "
                       "ring)",
                       rg->transition, rg->latewood_fraction);
    if (d->log.radius_mm / rg->width_mm > SK_WOOD_MAX_RINGS)
        return sk_fail(err, SK_ERROR_LIMIT,
                       "log.radius_mm = %g with rings.width_mm = %g needs more than %d rings",
                       d->log.radius_mm, rg->width_mm, SK_WOOD_MAX_RINGS);
    const sk_wood_grain_desc *g = &d->grain;
    if (g->wavy_amplitude != 0.0f && g->wavy_wavelength_mm < 0.01f)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "grain.wavy_wavelength_mm = %g must be at least 0.01 when "
                       "grain.wavy_amplitude = %g",
                       g->wavy_wavelength_mm, g->wavy_amplitude);
    if (g->interlocked_slope != 0.0f && g->interlocked_period_years < 0.01f)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "grain.interlocked_period_years = %g must be at least 0.01 when "
                       "grain.interlocked_slope = %g",
                       g->interlocked_period_years, g->interlocked_slope);
    for (int k = 0; k < g->table_count; k++) {
        /* a point's slope is a grain slope, as spiral_slope */
        const sk_schema_field *slope = sk_schema_find(&sk_wood_schema, "grain.spiral_slope");
        snprintf(name, sizeof name, "grain.table[%d][1]", k);
        CHECK(sk_check_range_f(err, name, g->table[k].slope, slope->min, slope->max));
        if (k > 0 && !(g->table[k].y_mm > g->table[k - 1].y_mm))
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "grain.table[%d][0] = %g must be greater than grain.table[%d][0] = %g "
                           "(heights ascending)",
                           k, g->table[k].y_mm, k - 1, g->table[k - 1].y_mm);
    }
    return SK_OK;
}

sk_result sk_wood_desc_validate(const sk_wood_desc *desc_in, sk_error *err)
{
    if (!desc_in) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "wood: desc is NULL");
    sk_wood_desc d = sk_wood_desc_resolved(desc_in);
    CHECK(sk_check_range_i(err, "grain.table count", d.grain.table_count, 0,
                           SK_WOOD_MAX_GRAIN_POINTS));
    /* every range, as sk_wood_schema states it */
    CHECK(sk_schema_check(&sk_wood_schema, &d, "", err));
    /* the rules between keys */
    CHECK(check_rings_grain(&d, err));
    const sk_wood_vessels_desc *v = &d.vessels;
    if (v->diffuse.density_per_mm2 > 0.0f)
        CHECK(check_vessel_fit(err, "vessels.diffuse", v->diffuse.radius_mm,
                               v->diffuse.radius_sd_mm, 1, d.rings.width_mm));
    if (v->ring.linear_density > 0.0f)
        CHECK(check_vessel_fit(err, "vessels.ring", v->ring.radius_mm, v->ring.radius_sd_mm,
                               v->ring.rows, d.rings.width_mm));
    const sk_wood_rays_desc *ry = &d.rays;
    if (ry->spacing_mm > 0.0f && ry->width_mm > 0.9f * 2.0f * ry->spacing_mm)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "rays.width_mm = %g is too wide for rays.spacing_mm = %g (at most 1.8 x "
                       "the spacing)",
                       ry->width_mm, ry->spacing_mm);
    return SK_OK;
}
