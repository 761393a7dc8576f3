/* The wood desc: defaults for zero fields and validation with key paths (the parameters
 * of Kawai 2000 sec. 4-7, in mm and radians). */
#include <math.h>
#include <stdio.h>

#include "shitsukan/wood.h"

static void default_f(float *v, float def)
{
    if (*v == 0.0f) *v = def;
}

static void default_color(float c[3], float r, float g, float b)
{
    if (c[0] == 0.0f && c[1] == 0.0f && c[2] == 0.0f) {
        c[0] = r;
        c[1] = g;
        c[2] = b;
    }
}

sk_wood_desc sk_wood_desc_resolved(const sk_wood_desc *desc)
{
    sk_wood_desc d = {0};
    if (desc) d = *desc;
    default_f(&d.log.radius_mm, 150.0f);
    default_f(&d.log.length_mm, 1000.0f);

    sk_wood_rings_desc *rg = &d.rings;
    default_f(&rg->width_mm, 3.0f);
    default_f(&rg->fluctuation_lobes, 4.0f);
    default_f(&rg->fluctuation_years, 10.0f);
    default_f(&rg->latewood_fraction, 0.3f);
    default_color(rg->earlywood_srgb, 0.82f, 0.64f, 0.44f);
    default_color(rg->latewood_srgb, 0.62f, 0.42f, 0.25f);

    default_f(&d.grain.fluctuation_scale_mm, 50.0f);
    default_f(&d.grain.fluctuation_years, 5.0f);

    default_f(&d.vessels.diffuse.radius_mm, 0.03f);
    default_f(&d.vessels.ring.radius_mm, 0.12f);
    if (d.vessels.ring.rows == 0) d.vessels.ring.rows = 1;
    default_color(d.vessels.color_srgb, 0.20f, 0.13f, 0.08f);

    default_f(&d.fibre.cell_mm, 0.08f);
    if (d.fibre.shift_mode == SK_WOOD_SHIFT_DEFAULT) d.fibre.shift_mode = SK_WOOD_SHIFT_ADD;

    sk_wood_rays_desc *ry = &d.rays;
    default_f(&ry->width_mm, 0.4f);
    default_f(&ry->height_mm, 20.0f);
    default_f(&ry->length_mm, 50.0f);
    default_color(ry->color_srgb, 0.86f, 0.76f, 0.60f);

    sk_wood_knots_desc *k = &d.knots;
    if (k->per_whorl == 0) k->per_whorl = 4;
    default_f(&k->growth, 0.12f);
    default_f(&k->stub_mm, 40.0f);
    default_f(&k->darkening, 0.4f);
    default_f(&k->bark_mm, 0.8f);
    default_color(k->bark_srgb, 0.24f, 0.15f, 0.09f);
    default_f(&k->collar, 0.5f);
    default_f(&k->deflection_reach, 3.0f);

    sk_wood_shading_desc *sh = &d.shading;
    if (sh->model == SK_WOOD_SHADING_DEFAULT) sh->model = SK_WOOD_SHADING_FIGURE;
    default_f(&sh->diffuse, 1.0f - sh->specular);
    default_f(&sh->exponent, 64.0f);
    default_f(&sh->fibre_strength, 0.5f);
    default_f(&sh->fibre_width, (float)(8.0 * SK_DEG_TO_RAD));
    default_color(sh->fibre_srgb, 0.95f, 0.80f, 0.60f);
    default_f(&sh->finish_ior, 1.5f);
    default_f(&sh->finish_exponent, 400.0f);

    sk_wood_view_desc *v = &d.view;
    if (v->plane == SK_WOOD_PLANE_DEFAULT) v->plane = SK_WOOD_PLANE_FLAT;
    if (v->plane != SK_WOOD_PLANE_END) default_f(&v->distance_mm, 0.5f * d.log.radius_mm);
    default_f(&v->width_mm, 100.0f);
    return d;
}

/* Range checks that stop at the first failure. */
#define CHECK(call)                                                                                \
    do {                                                                                           \
        sk_result check_result_ = (call);                                                          \
        if (check_result_ != SK_OK) return check_result_;                                          \
    } while (0)

static sk_result check_color(sk_error *err, const char *key, const float c[3])
{
    char name[96];
    for (int i = 0; i < 3; i++) {
        snprintf(name, sizeof name, "%s[%d]", key, i);
        CHECK(sk_check_range_f(err, name, c[i], 0.0, 1.0));
    }
    return SK_OK;
}

/* An angle stored in radians, checked (and reported) in degrees. */
static sk_result check_deg(sk_error *err, const char *key, float radians, double lo, double hi)
{
    return sk_check_range_f(err, key, radians * SK_RAD_TO_DEG, lo, hi);
}

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

sk_result sk_wood_desc_validate(const sk_wood_desc *desc_in, sk_error *err)
{
    if (!desc_in) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "wood: desc is NULL");
    sk_wood_desc d = sk_wood_desc_resolved(desc_in);
    char name[96];

    for (int i = 0; i < 3; i++) {
        snprintf(name, sizeof name, "transform.translate_mm[%d]", i);
        CHECK(sk_check_range_f(err, name, d.transform.translate_mm[i], -1e6, 1e6));
        snprintf(name, sizeof name, "transform.rotate_deg[%d]", i);
        CHECK(check_deg(err, name, d.transform.rotate[i], -360.0, 360.0));
    }
    CHECK(sk_check_range_f(err, "log.radius_mm", d.log.radius_mm, 1.0, 2000.0));
    CHECK(sk_check_range_f(err, "log.length_mm", d.log.length_mm, 10.0, 100000.0));

    const sk_wood_rings_desc *rg = &d.rings;
    CHECK(sk_check_range_f(err, "rings.width_mm", rg->width_mm, 0.05, 50.0));
    CHECK(sk_check_range_f(err, "rings.width_variation", rg->width_variation, 0.0, 1.0));
    CHECK(sk_check_range_f(err, "rings.fluctuation", rg->fluctuation, 0.0, 0.9));
    CHECK(sk_check_range_f(err, "rings.fluctuation_lobes", rg->fluctuation_lobes, 0.5, 64.0));
    CHECK(sk_check_range_f(err, "rings.fluctuation_years", rg->fluctuation_years, 0.25, 1000.0));
    CHECK(sk_check_range_f(err, "rings.latewood_fraction", rg->latewood_fraction, 0.01, 0.99));
    CHECK(sk_check_range_f(err, "rings.transition", rg->transition, 0.0, 0.99));
    if (rg->transition + rg->latewood_fraction > 1.0f)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "rings.transition = %g plus rings.latewood_fraction = %g exceeds 1 (a whole "
                       "ring)",
                       rg->transition, rg->latewood_fraction);
    if (d.log.radius_mm / rg->width_mm > SK_WOOD_MAX_RINGS)
        return sk_fail(err, SK_ERROR_LIMIT,
                       "log.radius_mm = %g with rings.width_mm = %g needs more than %d rings",
                       d.log.radius_mm, rg->width_mm, SK_WOOD_MAX_RINGS);
    CHECK(check_color(err, "rings.earlywood_srgb", rg->earlywood_srgb));
    CHECK(check_color(err, "rings.latewood_srgb", rg->latewood_srgb));

    const sk_wood_grain_desc *g = &d.grain;
    CHECK(sk_check_range_f(err, "grain.spiral_slope", g->spiral_slope, -2.0, 2.0));
    CHECK(sk_check_range_f(err, "grain.wavy_amplitude", g->wavy_amplitude, -2.0, 2.0));
    CHECK(sk_check_range_f(err, "grain.wavy_wavelength_mm", g->wavy_wavelength_mm, 0.0, 100000.0));
    if (g->wavy_amplitude != 0.0f && g->wavy_wavelength_mm < 0.01f)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "grain.wavy_wavelength_mm = %g must be at least 0.01 when "
                       "grain.wavy_amplitude = %g",
                       g->wavy_wavelength_mm, g->wavy_amplitude);
    CHECK(sk_check_range_f(err, "grain.interlocked_slope", g->interlocked_slope, -2.0, 2.0));
    CHECK(sk_check_range_f(err, "grain.interlocked_period_years", g->interlocked_period_years, 0.0,
                           1000.0));
    if (g->interlocked_slope != 0.0f && g->interlocked_period_years < 0.01f)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "grain.interlocked_period_years = %g must be at least 0.01 when "
                       "grain.interlocked_slope = %g",
                       g->interlocked_period_years, g->interlocked_slope);
    CHECK(sk_check_range_i(err, "grain.table count", g->table_count, 0, SK_WOOD_MAX_GRAIN_POINTS));
    for (int k = 0; k < g->table_count; k++) {
        snprintf(name, sizeof name, "grain.table[%d][0]", k);
        CHECK(sk_check_range_f(err, name, g->table[k].y_mm, -1e6, 1e6));
        snprintf(name, sizeof name, "grain.table[%d][1]", k);
        CHECK(sk_check_range_f(err, name, g->table[k].slope, -2.0, 2.0));
        if (k > 0 && !(g->table[k].y_mm > g->table[k - 1].y_mm))
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "grain.table[%d][0] = %g must be greater than grain.table[%d][0] = %g "
                           "(heights ascending)",
                           k, g->table[k].y_mm, k - 1, g->table[k - 1].y_mm);
    }
    CHECK(sk_check_range_f(err, "grain.fluctuation", g->fluctuation, 0.0, 1.0));
    CHECK(
        sk_check_range_f(err, "grain.fluctuation_scale_mm", g->fluctuation_scale_mm, 1.0, 10000.0));
    CHECK(sk_check_range_f(err, "grain.fluctuation_years", g->fluctuation_years, 0.25, 1000.0));

    const sk_wood_vessels_desc *v = &d.vessels;
    CHECK(sk_check_range_f(err, "vessels.diffuse.density_per_mm2", v->diffuse.density_per_mm2, 0.0,
                           400.0));
    CHECK(sk_check_range_f(err, "vessels.diffuse.radius_mm", v->diffuse.radius_mm, 0.002, 2.0));
    CHECK(sk_check_range_f(err, "vessels.diffuse.radius_sd_mm", v->diffuse.radius_sd_mm, 0.0, 1.0));
    if (v->diffuse.density_per_mm2 > 0.0f)
        CHECK(check_vessel_fit(err, "vessels.diffuse", v->diffuse.radius_mm,
                               v->diffuse.radius_sd_mm, 1, rg->width_mm));
    CHECK(sk_check_range_f(err, "vessels.ring.linear_density", v->ring.linear_density, 0.0, 100.0));
    CHECK(sk_check_range_f(err, "vessels.ring.radius_mm", v->ring.radius_mm, 0.002, 2.0));
    CHECK(sk_check_range_f(err, "vessels.ring.radius_sd_mm", v->ring.radius_sd_mm, 0.0, 1.0));
    CHECK(sk_check_range_i(err, "vessels.ring.rows", v->ring.rows, 1, 8));
    CHECK(sk_check_range_f(err, "vessels.ring.jitter", v->ring.jitter, 0.0, 1.0));
    if (v->ring.linear_density > 0.0f)
        CHECK(check_vessel_fit(err, "vessels.ring", v->ring.radius_mm, v->ring.radius_sd_mm,
                               v->ring.rows, rg->width_mm));
    CHECK(check_color(err, "vessels.color_srgb", v->color_srgb));

    CHECK(sk_check_range_f(err, "fibre.brightness_shift", d.fibre.brightness_shift, 0.0, 1.0));
    CHECK(sk_check_range_f(err, "fibre.cell_mm", d.fibre.cell_mm, 0.005, 10.0));
    CHECK(sk_check_range_f(err, "fibre.length_mm", d.fibre.length_mm, 0.0, 10000.0));
    CHECK(
        sk_check_range_i(err, "fibre.shift_mode", d.fibre.shift_mode, 0, SK_WOOD_SHIFT_COUNT - 1));

    const sk_wood_rays_desc *ry = &d.rays;
    if (ry->spacing_mm != 0.0f)
        CHECK(sk_check_range_f(err, "rays.spacing_mm", ry->spacing_mm, 0.2, 100.0));
    CHECK(sk_check_range_f(err, "rays.width_mm", ry->width_mm, 0.01, 5.0));
    CHECK(sk_check_range_f(err, "rays.height_mm", ry->height_mm, 0.1, 1000.0));
    CHECK(sk_check_range_f(err, "rays.length_mm", ry->length_mm, 1.0, 5000.0));
    CHECK(sk_check_range_f(err, "rays.jitter", ry->jitter, 0.0, 1.0));
    CHECK(check_color(err, "rays.color_srgb", ry->color_srgb));
    if (ry->spacing_mm > 0.0f && ry->width_mm > 0.9f * 2.0f * ry->spacing_mm)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "rays.width_mm = %g is too wide for rays.spacing_mm = %g (at most 1.8 x "
                       "the spacing)",
                       ry->width_mm, ry->spacing_mm);

    const sk_wood_knots_desc *k = &d.knots;
    if (k->whorl_spacing_mm != 0.0f)
        CHECK(sk_check_range_f(err, "knots.whorl_spacing_mm", k->whorl_spacing_mm, 20.0, 100000.0));
    CHECK(sk_check_range_i(err, "knots.per_whorl", k->per_whorl, 1, 12));
    CHECK(check_deg(err, "knots.rise_deg", k->rise, -10.0, 80.0));
    CHECK(sk_check_range_f(err, "knots.growth", k->growth, 0.01, 1.0));
    CHECK(sk_check_range_f(err, "knots.dead_after_years", k->dead_after_years, 0.0, 1000.0));
    CHECK(sk_check_range_f(err, "knots.stub_mm", k->stub_mm, 0.1, 1000.0));
    CHECK(sk_check_range_f(err, "knots.jitter", k->jitter, 0.0, 1.0));
    CHECK(sk_check_range_f(err, "knots.darkening", k->darkening, 0.0, 1.0));
    CHECK(sk_check_range_f(err, "knots.bark_mm", k->bark_mm, 0.01, 20.0));
    CHECK(check_color(err, "knots.bark_srgb", k->bark_srgb));
    CHECK(sk_check_range_f(err, "knots.collar", k->collar, 0.01, 2.0));
    CHECK(sk_check_range_f(err, "knots.deflection_reach", k->deflection_reach, 1.1, 20.0));

    const sk_wood_shading_desc *sh = &d.shading;
    CHECK(sk_check_range_i(err, "shading.model", sh->model, 0, SK_WOOD_SHADING_COUNT - 1));
    CHECK(sk_check_range_f(err, "shading.specular", sh->specular, 0.0, 1.0));
    CHECK(sk_check_range_f(err, "shading.diffuse", sh->diffuse, 0.0, 1.0));
    CHECK(sk_check_range_f(err, "shading.exponent", sh->exponent, 1.0, 100000.0));
    CHECK(sk_check_range_f(err, "shading.fibre_strength", sh->fibre_strength, 0.0, 100.0));
    CHECK(check_deg(err, "shading.fibre_width_deg", sh->fibre_width, 0.5, 60.0));
    CHECK(check_color(err, "shading.fibre_srgb", sh->fibre_srgb));
    CHECK(sk_check_range_f(err, "shading.finish_ior", sh->finish_ior, 1.0, 3.0));
    CHECK(sk_check_range_f(err, "shading.finish_exponent", sh->finish_exponent, 1.0, 100000.0));

    const sk_wood_view_desc *vw = &d.view;
    CHECK(sk_check_range_i(err, "view.plane", vw->plane, 0, SK_WOOD_PLANE_COUNT - 1));
    CHECK(sk_check_range_f(err, "view.distance_mm", vw->distance_mm, 0.0, 10000.0));
    CHECK(sk_check_range_f(err, "view.height_mm", vw->height_mm, -100000.0, 100000.0));
    CHECK(sk_check_range_f(err, "view.width_mm", vw->width_mm, 0.01, 100000.0));
    CHECK(check_deg(err, "view.tilt_deg", vw->tilt, -90.0, 90.0));
    CHECK(check_deg(err, "view.light_deg", vw->light_incidence, -89.0, 89.0));
    CHECK(check_deg(err, "view.light_azimuth_deg", vw->light_azimuth, -180.0, 180.0));
    CHECK(check_deg(err, "view.view_deg", vw->view_incidence, -89.0, 89.0));
    return SK_OK;
}
