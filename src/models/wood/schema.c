/* Preset schema of sk_wood_desc (the parameters of Kawai 2000, secs. 4-7, and the knots and
 * rays beyond it): every key, its type, range (as written in JSON, before any degree-to-
 * radian scale), default and one line of documentation, stated once. A key whose 0 means
 * its default (SK_FIELD_ZERO) accepts 0 besides its range; sk_wood_desc_validate checks the
 * resolved values against the ranges here, then the rules between keys. */
#include <stddef.h>

#include "shitsukan/wood.h"

const char *const sk_wood_shading_model_names[] = {"default", "figure", "fibre", NULL};
const char *const sk_wood_plane_names[] = {"default", "end", "flat", "quarter", NULL};
const char *const sk_wood_shift_mode_names[] = {"default", "add", "multiply", NULL};

static const sk_schema_field transform_fields[] = {
    SK_SCHEMA_FLOATS(sk_wood_transform, translate_mm, "translate_mm", 3, -1e6, 1e6,
                     .doc = "scene position of the pith at tree y = 0 (mm)"),
    SK_SCHEMA_FLOATS(sk_wood_transform, rotate, "rotate_deg", 3, -360, 360, .scale = SK_DEG_TO_RAD,
                     .doc = "Euler angles X, Y, Z placing the tree (degrees; 0: axis = +y)"),
};
static const sk_schema transform_schema =
    SK_SCHEMA_OF("transform", sk_wood_transform, transform_fields);

static const sk_schema_field log_fields[] = {
    SK_SCHEMA_FLOAT(sk_wood_log_desc, radius_mm, "radius_mm", 1, 2000, .flags = SK_FIELD_ZERO,
                    .def = 150, .doc = "radius the ring tables cover (mm)"),
    SK_SCHEMA_FLOAT(sk_wood_log_desc, length_mm, "length_mm", 10, 100000, .flags = SK_FIELD_ZERO,
                    .def = 1000, .doc = "period of the grain fluctuation along the axis (mm)"),
};
static const sk_schema log_schema = SK_SCHEMA_OF("log", sk_wood_log_desc, log_fields);

static const double default_earlywood[3] = {0.82, 0.64, 0.44};
static const double default_latewood[3] = {0.62, 0.42, 0.25};

/* Sec. 4.4: R(t, theta); sec. 6.3: the earlywood/latewood profile. */
static const sk_schema_field rings_fields[] = {
    SK_SCHEMA_FLOAT(sk_wood_rings_desc, width_mm, "width_mm", 0.05, 50, .flags = SK_FIELD_ZERO,
                    .def = 3, .doc = "d, mean ring width = growth per year (mm)"),
    SK_SCHEMA_FLOAT(sk_wood_rings_desc, width_variation, "width_variation", 0, 1,
                    .doc = "year-to-year variation of the width (sd of its log)"),
    SK_SCHEMA_FLOAT(sk_wood_rings_desc, fluctuation, "fluctuation", 0, 0.9,
                    .doc = "relative amplitude of the width's fractal variation around a ring"),
    SK_SCHEMA_FLOAT(sk_wood_rings_desc, fluctuation_lobes, "fluctuation_lobes", 0.5, 64,
                    .flags = SK_FIELD_ZERO, .def = 4, .doc = "about how many bulges a ring has"),
    SK_SCHEMA_FLOAT(sk_wood_rings_desc, fluctuation_years, "fluctuation_years", 0.25, 1000,
                    .flags = SK_FIELD_ZERO, .def = 10, .doc = "years over which a bulge persists"),
    SK_SCHEMA_FLOAT(sk_wood_rings_desc, latewood_fraction, "latewood_fraction", 0.01, 0.99,
                    .flags = SK_FIELD_ZERO, .def = 0.3,
                    .doc = "fraction of a ring that is latewood"),
    SK_SCHEMA_FLOAT(sk_wood_rings_desc, transition, "transition", 0, 0.99,
                    .doc =
                        "fraction of a ring over which earlywood turns into latewood (0: abrupt)"),
    SK_SCHEMA_FLOATS(sk_wood_rings_desc, earlywood_srgb, "earlywood_srgb", 3, 0, 1,
                     .defs = default_earlywood, .doc = "earlywood colour (sRGB 0-1)"),
    SK_SCHEMA_FLOATS(sk_wood_rings_desc, latewood_srgb, "latewood_srgb", 3, 0, 1,
                     .defs = default_latewood, .doc = "latewood colour (sRGB 0-1)"),
};
static const sk_schema rings_schema = SK_SCHEMA_OF("rings", sk_wood_rings_desc, rings_fields);

static const sk_schema_field grain_point_fields[] = {
    SK_SCHEMA_ELEMENT_FLOATS(2, -1e6, 1e6, .doc = "[y_mm, slope]: height (mm) and g there"),
};
static const sk_schema grain_point_schema = {"grain point", grain_point_fields, 1, NULL};

/* Eq. (1): G'(t, y) = g'(y) + dg'(t, y). */
static const sk_schema_field grain_fields[] = {
    SK_SCHEMA_FLOAT(sk_wood_grain_desc, spiral_slope, "spiral_slope", -2, 2,
                    .doc = "g1 of spiral grain, tan of the fibre angle"),
    SK_SCHEMA_FLOAT(sk_wood_grain_desc, wavy_amplitude, "wavy_amplitude", -2, 2,
                    .doc = "A of wavy grain g = A sin(y / lambda)"),
    SK_SCHEMA_FLOAT(sk_wood_grain_desc, wavy_wavelength_mm, "wavy_wavelength_mm", 0, 100000,
                    .doc = "lambda of wavy grain (mm; period 2 pi lambda); required when A != 0"),
    SK_SCHEMA_FLOAT(sk_wood_grain_desc, interlocked_slope, "interlocked_slope", -2, 2,
                    .doc = "s of interlocked grain g = s sin(2 pi t / P)"),
    SK_SCHEMA_FLOAT(sk_wood_grain_desc, interlocked_period_years, "interlocked_period_years", 0,
                    1000, .doc = "P, years per reversal cycle; required when s != 0"),
    SK_SCHEMA_ARRAY(sk_wood_grain_desc, table, "table", table_count, 0, grain_point_schema,
                    .def_text = "none",
                    .doc = "user g(y): [[y_mm, slope], ...], heights ascending, linear between"),
    SK_SCHEMA_FLOAT(sk_wood_grain_desc, fluctuation, "fluctuation", 0, 1,
                    .doc = "largest |dg| of the fractal fluctuation"),
    SK_SCHEMA_FLOAT(sk_wood_grain_desc, fluctuation_scale_mm, "fluctuation_scale_mm", 1, 10000,
                    .flags = SK_FIELD_ZERO, .def = 50,
                    .doc = "correlation length of dg along the axis (mm)"),
    SK_SCHEMA_FLOAT(sk_wood_grain_desc, fluctuation_years, "fluctuation_years", 0.25, 1000,
                    .flags = SK_FIELD_ZERO, .def = 5,
                    .doc = "correlation of dg across growth years"),
};
static const sk_schema grain_schema = SK_SCHEMA_OF("grain", sk_wood_grain_desc, grain_fields);

/* Sec. 5.3. */
static const sk_schema_field diffuse_fields[] = {
    SK_SCHEMA_FLOAT(sk_wood_diffuse_vessels, density_per_mm2, "density_per_mm2", 0, 400,
                    .def_text = "none", .doc = "rho, diffuse-porous vessels per mm^2 of end grain"),
    SK_SCHEMA_FLOAT(sk_wood_diffuse_vessels, radius_mm, "radius_mm", 0.002, 2,
                    .flags = SK_FIELD_ZERO, .def = 0.03, .doc = "mean vessel radius (mm)"),
    SK_SCHEMA_FLOAT(sk_wood_diffuse_vessels, radius_sd_mm, "radius_sd_mm", 0, 1,
                    .doc = "standard deviation of the radius (mm)"),
};
static const sk_schema diffuse_schema =
    SK_SCHEMA_OF("diffuse", sk_wood_diffuse_vessels, diffuse_fields);

/* Sec. 5.4. */
static const sk_schema_field ring_vessel_fields[] = {
    SK_SCHEMA_FLOAT(sk_wood_ring_vessels, linear_density, "linear_density", 0, 100,
                    .def_text = "none", .doc = "P: ring j holds round(P j d) vessels per row"),
    SK_SCHEMA_FLOAT(sk_wood_ring_vessels, radius_mm, "radius_mm", 0.002, 2, .flags = SK_FIELD_ZERO,
                    .def = 0.12, .doc = "mean vessel radius (mm)"),
    SK_SCHEMA_FLOAT(sk_wood_ring_vessels, radius_sd_mm, "radius_sd_mm", 0, 1,
                    .doc = "standard deviation of the radius (mm)"),
    SK_SCHEMA_INT(sk_wood_ring_vessels, rows, "rows", 1, 8, .flags = SK_FIELD_ZERO, .def = 1,
                  .doc = "rows of vessels in the earlywood band"),
    SK_SCHEMA_FLOAT(sk_wood_ring_vessels, jitter, "jitter", 0, 1,
                    .doc = "random displacement as a fraction of the spacing"),
};
static const sk_schema ring_vessel_schema =
    SK_SCHEMA_OF("ring", sk_wood_ring_vessels, ring_vessel_fields);

static const double default_pore[3] = {0.20, 0.13, 0.08};

static const sk_schema_field vessels_fields[] = {
    SK_SCHEMA_OBJECT(sk_wood_vessels_desc, diffuse, "diffuse", diffuse_schema,
                     .doc = "diffuse-porous vessels (sec. 5.3)"),
    SK_SCHEMA_OBJECT(sk_wood_vessels_desc, ring, "ring", ring_vessel_schema,
                     .doc = "ring-porous vessels (sec. 5.4)"),
    SK_SCHEMA_FLOATS(sk_wood_vessels_desc, color_srgb, "color_srgb", 3, 0, 1, .defs = default_pore,
                     .doc = "colour of an open pore (sRGB 0-1)"),
};
static const sk_schema vessels_schema =
    SK_SCHEMA_OF("vessels", sk_wood_vessels_desc, vessels_fields);

/* Sec. 6: shifting brightness. */
static const sk_schema_field fibre_fields[] = {
    SK_SCHEMA_FLOAT(sk_wood_fibre_desc, brightness_shift, "brightness_shift", 0, 1,
                    .doc = "spread of the cells' brightness shifts (Fig. 7: 0.4 = 40 %)"),
    SK_SCHEMA_ENUM(sk_wood_fibre_desc, shift_mode, "shift_mode", sk_wood_shift_mode_names,
                   .def = SK_WOOD_SHIFT_ADD,
                   .doc = "\"add\" (the paper: brightness + a shift in [-s/2, s/2]) or "
                          "\"multiply\" (colour x (1 - s u), darker only)"),
    SK_SCHEMA_FLOAT(sk_wood_fibre_desc, cell_mm, "cell_mm", 0.005, 10, .flags = SK_FIELD_ZERO,
                    .def = 0.08, .doc = "cell size of the end-grain array (mm)"),
    SK_SCHEMA_FLOAT(sk_wood_fibre_desc, length_mm, "length_mm", 0, 10000,
                    .def_text = "endless, as in the paper",
                    .doc = "fibre length: the shift is redrawn along the fibre every length_mm"),
};
static const sk_schema fibre_schema = SK_SCHEMA_OF("fibre", sk_wood_fibre_desc, fibre_fields);

static const double default_ray[3] = {0.86, 0.76, 0.60};

static const sk_schema_field rays_fields[] = {
    SK_SCHEMA_FLOAT(sk_wood_rays_desc, spacing_mm, "spacing_mm", 0.2, 100, .flags = SK_FIELD_ZERO,
                    .def_text = "none", .doc = "distance between broad rays round a ring (mm)"),
    SK_SCHEMA_FLOAT(sk_wood_rays_desc, width_mm, "width_mm", 0.01, 5, .flags = SK_FIELD_ZERO,
                    .def = 0.4,
                    .doc = "a ray's width round the tree (mm), at most 1.8 x the spacing"),
    SK_SCHEMA_FLOAT(sk_wood_rays_desc, height_mm, "height_mm", 0.1, 1000, .flags = SK_FIELD_ZERO,
                    .def = 20, .doc = "a ray's height along the fibre (mm)"),
    SK_SCHEMA_FLOAT(sk_wood_rays_desc, length_mm, "length_mm", 1, 5000, .flags = SK_FIELD_ZERO,
                    .def = 50, .doc = "a ray's length out from the pith (mm)"),
    SK_SCHEMA_FLOAT(sk_wood_rays_desc, jitter, "jitter", 0, 1,
                    .doc = "randomness of the rays' places and sizes"),
    SK_SCHEMA_FLOATS(sk_wood_rays_desc, color_srgb, "color_srgb", 3, 0, 1, .defs = default_ray,
                     .doc = "colour of the ray tissue (sRGB 0-1)"),
};
static const sk_schema rays_schema = SK_SCHEMA_OF("rays", sk_wood_rays_desc, rays_fields);

static const double default_bark[3] = {0.24, 0.15, 0.09};

static const sk_schema_field knots_fields[] = {
    SK_SCHEMA_FLOAT(sk_wood_knots_desc, whorl_spacing_mm, "whorl_spacing_mm", 20, 100000,
                    .flags = SK_FIELD_ZERO, .def_text = "no knots",
                    .doc = "distance between whorls of branches along the axis (mm)"),
    SK_SCHEMA_INT(sk_wood_knots_desc, per_whorl, "per_whorl", 1, 12, .flags = SK_FIELD_ZERO,
                  .def = 4, .doc = "branches per whorl"),
    SK_SCHEMA_DEG(sk_wood_knots_desc, rise, "rise_deg", -10, 80,
                  .doc = "a branch's angle above the horizontal (degrees)"),
    SK_SCHEMA_FLOAT(sk_wood_knots_desc, growth, "growth", 0.01, 1, .flags = SK_FIELD_ZERO,
                    .def = 0.12,
                    .doc = "a branch's ring width over the stem's (the knot cone's slope)"),
    SK_SCHEMA_FLOAT(sk_wood_knots_desc, dead_after_years, "dead_after_years", 0, 1000,
                    .def_text = "alive throughout",
                    .doc = "years a branch lives (then a dead knot in bark)"),
    SK_SCHEMA_FLOAT(sk_wood_knots_desc, stub_mm, "stub_mm", 0.1, 1000, .flags = SK_FIELD_ZERO,
                    .def = 40, .doc = "how far a dead branch reaches before it is overgrown (mm)"),
    SK_SCHEMA_FLOAT(sk_wood_knots_desc, jitter, "jitter", 0, 1,
                    .doc = "randomness of whorl heights, azimuths, angles and sizes"),
    SK_SCHEMA_FLOAT(sk_wood_knots_desc, darkening, "darkening", 0, 1, .def = 0.4,
                    .doc = "the knot's end grain darker by this fraction"),
    SK_SCHEMA_FLOAT(sk_wood_knots_desc, bark_mm, "bark_mm", 0.01, 20, .flags = SK_FIELD_ZERO,
                    .def = 0.8, .doc = "bark ring round a dead knot (mm)"),
    SK_SCHEMA_FLOATS(sk_wood_knots_desc, bark_srgb, "bark_srgb", 3, 0, 1, .defs = default_bark,
                     .doc = "its colour (sRGB 0-1)"),
    SK_SCHEMA_FLOAT(sk_wood_knots_desc, collar, "collar", 0.01, 2, .flags = SK_FIELD_ZERO,
                    .def = 0.5,
                    .doc = "how far the rings curve round a knot, a fraction of its age"),
    SK_SCHEMA_FLOAT(sk_wood_knots_desc, deflection_reach, "deflection_reach", 1.1, 20,
                    .flags = SK_FIELD_ZERO, .def = 3,
                    .doc = "how far the grain bends round a knot (knot radii)"),
};
static const sk_schema knots_schema = SK_SCHEMA_OF("knots", sk_wood_knots_desc, knots_fields);

static const double default_fibre[3] = {0.95, 0.80, 0.60};

/* Sec. 7: eq. (4), and the fibre highlight beyond it. */
static const sk_schema_field shading_fields[] = {
    SK_SCHEMA_ENUM(sk_wood_shading_desc, model, "model", sk_wood_shading_model_names,
                   .def = SK_WOOD_SHADING_FIGURE,
                   .doc = "\"figure\" (eq. 4) or \"fibre\" (3D fibre highlight)"),
    SK_SCHEMA_FLOAT(sk_wood_shading_desc, specular, "specular", 0, 1,
                    .doc = "ks of eq. (4) (0: no sheen)"),
    SK_SCHEMA_FLOAT(sk_wood_shading_desc, diffuse, "diffuse", 0, 1, .def_text = "1 - specular",
                    .doc = "kd of eq. (4)"),
    SK_SCHEMA_FLOAT(sk_wood_shading_desc, exponent, "exponent", 1, 100000, .flags = SK_FIELD_ZERO,
                    .def = 64, .doc = "n of eq. (4)"),
    SK_SCHEMA_FLOAT(sk_wood_shading_desc, fibre_strength, "fibre_strength", 0, 100, .def = 0.5,
                    .doc = "k_f of the fibre lobe"),
    SK_SCHEMA_DEG(sk_wood_shading_desc, fibre_width, "fibre_width_deg", 0.5, 60,
                  .flags = SK_FIELD_ZERO, .def = 8,
                  .doc = "beta, width of the fibre lobe (degrees)"),
    SK_SCHEMA_FLOATS(sk_wood_shading_desc, fibre_srgb, "fibre_srgb", 3, 0, 1, .defs = default_fibre,
                     .doc = "colour of the fibre highlight (sRGB 0-1)"),
    SK_SCHEMA_FLOAT(sk_wood_shading_desc, finish_ior, "finish_ior", 1, 3, .flags = SK_FIELD_ZERO,
                    .def = 1.5, .doc = "refractive index of the clear finish"),
    SK_SCHEMA_FLOAT(sk_wood_shading_desc, finish_exponent, "finish_exponent", 1, 100000,
                    .flags = SK_FIELD_ZERO, .def = 400,
                    .doc = "Blinn-Phong exponent of the finish's highlight"),
};
static const sk_schema shading_schema =
    SK_SCHEMA_OF("shading", sk_wood_shading_desc, shading_fields);

static const sk_schema_field view_fields[] = {
    SK_SCHEMA_ENUM(sk_wood_view_desc, plane, "plane", sk_wood_plane_names,
                   .def = SK_WOOD_PLANE_FLAT, .doc = "the cut: \"end\", \"flat\" or \"quarter\""),
    SK_SCHEMA_FLOAT(
        sk_wood_view_desc, distance_mm, "distance_mm", 0, 10000,
        .def_text = "half the log radius (flat, quarter)",
        .doc = "distance of the cut (flat) or view centre (quarter, end) from the pith (mm)"),
    SK_SCHEMA_FLOAT(sk_wood_view_desc, height_mm, "height_mm", -100000, 100000,
                    .doc = "tree y of the view centre (mm)"),
    SK_SCHEMA_FLOAT(sk_wood_view_desc, width_mm, "width_mm", 0.01, 100000, .flags = SK_FIELD_ZERO,
                    .def = 100, .doc = "width of the view (mm)"),
    SK_SCHEMA_DEG(sk_wood_view_desc, tilt, "tilt_deg", -90, 90,
                  .doc = "plane turned about the image's horizontal axis (degrees)"),
    SK_SCHEMA_DEG(sk_wood_view_desc, light_incidence, "light_deg", -89, 89,
                  .doc = "delta: light turned from the normal towards the image top (degrees)"),
    SK_SCHEMA_DEG(sk_wood_view_desc, light_azimuth, "light_azimuth_deg", -180, 180,
                  .doc = "the light's plane turned about the normal (degrees)"),
    SK_SCHEMA_DEG(sk_wood_view_desc, view_incidence, "view_deg", -89, 89,
                  .doc = "viewer turned from the normal towards the image top (degrees)"),
};
static const sk_schema view_schema = SK_SCHEMA_OF("view", sk_wood_view_desc, view_fields);

static const sk_schema_field wood_fields[] = {
    SK_SCHEMA_SEED(sk_wood_desc, seed, "seed", .doc = "random seed"),
    SK_SCHEMA_OBJECT(sk_wood_desc, transform, "transform", transform_schema,
                     .doc = "placement of the tree in the scene"),
    SK_SCHEMA_OBJECT(sk_wood_desc, log, "log", log_schema,
                     .doc = "extent of the precomputed tables"),
    SK_SCHEMA_OBJECT(sk_wood_desc, rings, "rings", rings_schema,
                     .doc = "annual rings R(t, theta) (sec. 4.4)"),
    SK_SCHEMA_OBJECT(sk_wood_desc, grain, "grain", grain_schema, .doc = "grain G'(t, y) (eq. 1)"),
    SK_SCHEMA_OBJECT(sk_wood_desc, vessels, "vessels", vessels_schema, .doc = "vessels (sec. 5)"),
    SK_SCHEMA_OBJECT(sk_wood_desc, rays, "rays", rays_schema,
                     .doc = "broad (medullary) rays, the silver figure (beyond the paper)"),
    SK_SCHEMA_OBJECT(sk_wood_desc, fibre, "fibre", fibre_schema,
                     .doc = "shifting brightness (sec. 6)"),
    SK_SCHEMA_OBJECT(sk_wood_desc, knots, "knots", knots_schema,
                     .doc = "knots: branches as cones from the pith (beyond the paper)"),
    SK_SCHEMA_OBJECT(sk_wood_desc, shading, "shading", shading_schema,
                     .doc = "reflection (sec. 7)"),
    SK_SCHEMA_OBJECT(sk_wood_desc, view, "view", view_schema,
                     .doc = "default planar cut and light"),
};

const sk_schema sk_wood_schema = SK_SCHEMA_OF("wood", sk_wood_desc, wood_fields);
