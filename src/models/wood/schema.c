/* Preset schema of sk_wood_desc: every key, its type, range (as written in JSON, before
 * any degree-to-radian scale) and one line of documentation. Ranges here admit 0 where 0
 * means "default"; sk_wood_desc_validate checks the resolved values and the rules between
 * fields. */
#include <stddef.h>

#include "shitsukan/wood.h"

const char *const sk_wood_shading_model_names[] = {"default", "figure", "fibre", NULL};
const char *const sk_wood_plane_names[] = {"default", "end", "flat", "quarter", NULL};
const char *const sk_wood_shift_mode_names[] = {"default", "add", "multiply", NULL};

#define FLOAT_FIELD(T, member, k, lo, hi, text)                                                    \
    {                                                                                              \
        .key = k, .type = SK_FIELD_FLOAT, .offset = offsetof(T, member), .min = lo, .max = hi,     \
        .doc = text                                                                                \
    }
#define DEG_FIELD(T, member, k, lo, hi, text)                                                      \
    {                                                                                              \
        .key = k, .type = SK_FIELD_FLOAT, .offset = offsetof(T, member), .min = lo, .max = hi,     \
        .scale = SK_DEG_TO_RAD, .doc = text                                                        \
    }
#define FLOATS_FIELD(T, member, k, n, lo, hi, text)                                                \
    {                                                                                              \
        .key = k, .type = SK_FIELD_FLOATS, .offset = offsetof(T, member), .min = lo, .max = hi,    \
        .count = n, .count_offset = SK_FIELD_FIXED, .doc = text                                    \
    }
#define OBJECT_FIELD(T, member, k, sub, text)                                                      \
    {                                                                                              \
        .key = k, .type = SK_FIELD_OBJECT, .offset = offsetof(T, member), .schema = &sub,          \
        .doc = text                                                                                \
    }
#define COUNT(a) ((int)(sizeof(a) / sizeof((a)[0])))

static const sk_schema_field transform_fields[] = {
    FLOATS_FIELD(sk_wood_transform, translate_mm, "translate_mm", 3, -1e6, 1e6,
                 "scene position of the pith at tree y = 0 (mm); default [0, 0, 0]"),
    {.key = "rotate_deg",
     .type = SK_FIELD_FLOATS,
     .offset = offsetof(sk_wood_transform, rotate),
     .min = -360,
     .max = 360,
     .scale = SK_DEG_TO_RAD,
     .count = 3,
     .count_offset = SK_FIELD_FIXED,
     .doc = "Euler angles X, Y, Z placing the tree (degrees); default [0, 0, 0] (axis = +y)"},
};
static const sk_schema transform_schema = {"transform", transform_fields, COUNT(transform_fields)};

static const sk_schema_field log_fields[] = {
    FLOAT_FIELD(sk_wood_log_desc, radius_mm, "radius_mm", 0, 2000,
                "radius the ring tables cover (mm); 0 = 150; [1, 2000]"),
    FLOAT_FIELD(sk_wood_log_desc, length_mm, "length_mm", 0, 100000,
                "period of the grain fluctuation along the axis (mm); 0 = 1000; [10, 100000]"),
};
static const sk_schema log_schema = {"log", log_fields, COUNT(log_fields)};

static const sk_schema_field rings_fields[] = {
    FLOAT_FIELD(sk_wood_rings_desc, width_mm, "width_mm", 0, 50,
                "d, mean ring width = growth per year (mm); 0 = 3; [0.05, 50]"),
    FLOAT_FIELD(sk_wood_rings_desc, width_variation, "width_variation", 0, 1,
                "year-to-year variation of the width (sd of its log); default 0"),
    FLOAT_FIELD(sk_wood_rings_desc, fluctuation, "fluctuation", 0, 0.9,
                "relative amplitude of the width's fractal variation around a ring; default 0"),
    FLOAT_FIELD(sk_wood_rings_desc, fluctuation_lobes, "fluctuation_lobes", 0, 64,
                "about how many bulges a ring has; 0 = 4; [0.5, 64]"),
    FLOAT_FIELD(sk_wood_rings_desc, fluctuation_years, "fluctuation_years", 0, 1000,
                "years over which a bulge persists; 0 = 10; [0.25, 1000]"),
    FLOAT_FIELD(sk_wood_rings_desc, latewood_fraction, "latewood_fraction", 0, 0.99,
                "fraction of a ring that is latewood; 0 = 0.3; [0.01, 0.99]"),
    FLOAT_FIELD(sk_wood_rings_desc, transition, "transition", 0, 0.99,
                "fraction of a ring over which earlywood turns into latewood; default 0 (abrupt)"),
    FLOATS_FIELD(sk_wood_rings_desc, earlywood_srgb, "earlywood_srgb", 3, 0, 1,
                 "earlywood colour (sRGB 0-1); default [0.82, 0.64, 0.44]"),
    FLOATS_FIELD(sk_wood_rings_desc, latewood_srgb, "latewood_srgb", 3, 0, 1,
                 "latewood colour (sRGB 0-1); default [0.62, 0.42, 0.25]"),
};
static const sk_schema rings_schema = {"rings", rings_fields, COUNT(rings_fields)};

static const sk_schema_field grain_point_fields[] = {
    {.key = NULL,
     .type = SK_FIELD_FLOATS,
     .offset = 0,
     .min = -1e6,
     .max = 1e6,
     .count = 2,
     .count_offset = SK_FIELD_FIXED,
     .doc = "[y_mm, slope]: height (mm) and g there"},
};
static const sk_schema grain_point_schema = {"grain point", grain_point_fields,
                                             COUNT(grain_point_fields)};

static const sk_schema_field grain_fields[] = {
    FLOAT_FIELD(sk_wood_grain_desc, spiral_slope, "spiral_slope", -2, 2,
                "g1 of spiral grain, tan of the fibre angle; default 0"),
    FLOAT_FIELD(sk_wood_grain_desc, wavy_amplitude, "wavy_amplitude", -2, 2,
                "A of wavy grain g = A sin(y / lambda); default 0"),
    FLOAT_FIELD(sk_wood_grain_desc, wavy_wavelength_mm, "wavy_wavelength_mm", 0, 100000,
                "lambda of wavy grain (mm; period 2 pi lambda); required when A != 0"),
    FLOAT_FIELD(sk_wood_grain_desc, interlocked_slope, "interlocked_slope", -2, 2,
                "s of interlocked grain g = s sin(2 pi t / P); default 0"),
    FLOAT_FIELD(sk_wood_grain_desc, interlocked_period_years, "interlocked_period_years", 0, 1000,
                "P, years per reversal cycle; required when s != 0"),
    {.key = "table",
     .type = SK_FIELD_ARRAY,
     .offset = offsetof(sk_wood_grain_desc, table),
     .count = SK_WOOD_MAX_GRAIN_POINTS,
     .min_count = 0,
     .count_offset = offsetof(sk_wood_grain_desc, table_count),
     .elem_size = sizeof(sk_wood_grain_point),
     .schema = &grain_point_schema,
     .doc = "user g(y): [[y_mm, slope], ...], heights ascending, linear between; default none"},
    FLOAT_FIELD(sk_wood_grain_desc, fluctuation, "fluctuation", 0, 1,
                "largest |dg| of the fractal fluctuation; default 0"),
    FLOAT_FIELD(sk_wood_grain_desc, fluctuation_scale_mm, "fluctuation_scale_mm", 0, 10000,
                "correlation length of dg along the axis (mm); 0 = 50; [1, 10000]"),
    FLOAT_FIELD(sk_wood_grain_desc, fluctuation_years, "fluctuation_years", 0, 1000,
                "correlation of dg across growth years; 0 = 5; [0.25, 1000]"),
};
static const sk_schema grain_schema = {"grain", grain_fields, COUNT(grain_fields)};

static const sk_schema_field diffuse_fields[] = {
    FLOAT_FIELD(sk_wood_diffuse_vessels, density_per_mm2, "density_per_mm2", 0, 400,
                "rho, diffuse-porous vessels per mm^2 of end grain; default 0 (none)"),
    FLOAT_FIELD(sk_wood_diffuse_vessels, radius_mm, "radius_mm", 0, 2,
                "mean vessel radius (mm); 0 = 0.03; [0.002, 2]"),
    FLOAT_FIELD(sk_wood_diffuse_vessels, radius_sd_mm, "radius_sd_mm", 0, 1,
                "standard deviation of the radius (mm); default 0"),
};
static const sk_schema diffuse_schema = {"diffuse", diffuse_fields, COUNT(diffuse_fields)};

static const sk_schema_field ring_vessel_fields[] = {
    FLOAT_FIELD(sk_wood_ring_vessels, linear_density, "linear_density", 0, 100,
                "P: ring j holds round(P j d) vessels per row; default 0 (none)"),
    FLOAT_FIELD(sk_wood_ring_vessels, radius_mm, "radius_mm", 0, 2,
                "mean vessel radius (mm); 0 = 0.12; [0.002, 2]"),
    FLOAT_FIELD(sk_wood_ring_vessels, radius_sd_mm, "radius_sd_mm", 0, 1,
                "standard deviation of the radius (mm); default 0"),
    {.key = "rows",
     .type = SK_FIELD_INT,
     .offset = offsetof(sk_wood_ring_vessels, rows),
     .min = 0,
     .max = 8,
     .doc = "rows of vessels in the earlywood band; 0 = 1; [1, 8]"},
    FLOAT_FIELD(sk_wood_ring_vessels, jitter, "jitter", 0, 1,
                "random displacement as a fraction of the spacing; default 0"),
};
static const sk_schema ring_vessel_schema = {"ring", ring_vessel_fields, COUNT(ring_vessel_fields)};

static const sk_schema_field vessels_fields[] = {
    OBJECT_FIELD(sk_wood_vessels_desc, diffuse, "diffuse", diffuse_schema,
                 "diffuse-porous vessels (sec. 5.3)"),
    OBJECT_FIELD(sk_wood_vessels_desc, ring, "ring", ring_vessel_schema,
                 "ring-porous vessels (sec. 5.4)"),
    FLOATS_FIELD(sk_wood_vessels_desc, color_srgb, "color_srgb", 3, 0, 1,
                 "colour of an open pore (sRGB 0-1); default [0.20, 0.13, 0.08]"),
};
static const sk_schema vessels_schema = {"vessels", vessels_fields, COUNT(vessels_fields)};

static const sk_schema_field fibre_fields[] = {
    FLOAT_FIELD(sk_wood_fibre_desc, brightness_shift, "brightness_shift", 0, 1,
                "spread of the cells' brightness shifts (Fig. 7: 0.4 = 40 %); default 0"),
    {.key = "shift_mode",
     .type = SK_FIELD_ENUM,
     .offset = offsetof(sk_wood_fibre_desc, shift_mode),
     .names = sk_wood_shift_mode_names,
     .doc = "\"add\" (the paper: brightness + a shift in [-s/2, s/2]) or \"multiply\" "
            "(colour x (1 - s u), darker only); default add"},
    FLOAT_FIELD(sk_wood_fibre_desc, cell_mm, "cell_mm", 0, 10,
                "cell size of the end-grain array (mm); 0 = 0.08; [0.005, 10]"),
    FLOAT_FIELD(sk_wood_fibre_desc, length_mm, "length_mm", 0, 10000,
                "fibre length: the shift is redrawn along the fibre every length_mm; "
                "default 0 (endless, as in the paper)"),
};
static const sk_schema fibre_schema = {"fibre", fibre_fields, COUNT(fibre_fields)};

static const sk_schema_field rays_fields[] = {
    FLOAT_FIELD(sk_wood_rays_desc, spacing_mm, "spacing_mm", 0, 100,
                "distance between broad rays round a ring (mm); default 0 (none)"),
    FLOAT_FIELD(sk_wood_rays_desc, width_mm, "width_mm", 0, 5,
                "a ray's width round the tree (mm); 0 = 0.4"),
    FLOAT_FIELD(sk_wood_rays_desc, height_mm, "height_mm", 0, 1000,
                "a ray's height along the fibre (mm); 0 = 20"),
    FLOAT_FIELD(sk_wood_rays_desc, length_mm, "length_mm", 0, 5000,
                "a ray's length out from the pith (mm); 0 = 50"),
    FLOAT_FIELD(sk_wood_rays_desc, jitter, "jitter", 0, 1,
                "randomness of the rays' places and sizes; default 0"),
    FLOATS_FIELD(sk_wood_rays_desc, color_srgb, "color_srgb", 3, 0, 1,
                 "colour of the ray tissue (sRGB 0-1); default [0.86, 0.76, 0.60]"),
};
static const sk_schema rays_schema = {"rays", rays_fields, COUNT(rays_fields)};

static const sk_schema_field knots_fields[] = {
    FLOAT_FIELD(sk_wood_knots_desc, whorl_spacing_mm, "whorl_spacing_mm", 0, 100000,
                "distance between whorls of branches along the axis (mm); default 0 (no knots)"),
    {.key = "per_whorl",
     .type = SK_FIELD_INT,
     .offset = offsetof(sk_wood_knots_desc, per_whorl),
     .min = 0,
     .max = 12,
     .doc = "branches per whorl; 0 = 4; [1, 12]"},
    DEG_FIELD(sk_wood_knots_desc, rise, "rise_deg", -10, 80,
              "a branch's angle above the horizontal (degrees); default 0"),
    FLOAT_FIELD(sk_wood_knots_desc, growth, "growth", 0, 1,
                "a branch's ring width over the stem's (the knot cone's slope); 0 = 0.12"),
    FLOAT_FIELD(sk_wood_knots_desc, dead_after_years, "dead_after_years", 0, 1000,
                "years a branch lives (then a dead knot in bark); default 0 (alive)"),
    FLOAT_FIELD(sk_wood_knots_desc, stub_mm, "stub_mm", 0, 1000,
                "how far a dead branch reaches before it is overgrown (mm); 0 = 40"),
    FLOAT_FIELD(sk_wood_knots_desc, jitter, "jitter", 0, 1,
                "randomness of whorl heights, azimuths, angles and sizes; default 0"),
    FLOAT_FIELD(sk_wood_knots_desc, darkening, "darkening", 0, 1,
                "the knot's end grain darker by this fraction; 0 = 0.4"),
    FLOAT_FIELD(sk_wood_knots_desc, bark_mm, "bark_mm", 0, 20,
                "bark ring round a dead knot (mm); 0 = 0.8"),
    FLOATS_FIELD(sk_wood_knots_desc, bark_srgb, "bark_srgb", 3, 0, 1,
                 "its colour (sRGB 0-1); default [0.24, 0.15, 0.09]"),
    FLOAT_FIELD(sk_wood_knots_desc, collar, "collar", 0, 2,
                "how far the rings curve round a knot, a fraction of its age; 0 = 0.5"),
    FLOAT_FIELD(sk_wood_knots_desc, deflection_reach, "deflection_reach", 0, 20,
                "how far the grain bends round a knot (knot radii); 0 = 3; [1.1, 20]"),
};
static const sk_schema knots_schema = {"knots", knots_fields, COUNT(knots_fields)};

static const sk_schema_field shading_fields[] = {
    {.key = "model",
     .type = SK_FIELD_ENUM,
     .offset = offsetof(sk_wood_shading_desc, model),
     .names = sk_wood_shading_model_names,
     .doc = "\"figure\" (eq. 4) or \"fibre\" (3D fibre highlight); default figure"},
    FLOAT_FIELD(sk_wood_shading_desc, specular, "specular", 0, 1,
                "ks of eq. (4); default 0 (no sheen)"),
    FLOAT_FIELD(sk_wood_shading_desc, diffuse, "diffuse", 0, 1, "kd of eq. (4); 0 = 1 - specular"),
    FLOAT_FIELD(sk_wood_shading_desc, exponent, "exponent", 0, 100000,
                "n of eq. (4); 0 = 64; [1, 100000]"),
    FLOAT_FIELD(sk_wood_shading_desc, fibre_strength, "fibre_strength", 0, 100,
                "k_f of the fibre lobe; 0 = 0.5"),
    DEG_FIELD(sk_wood_shading_desc, fibre_width, "fibre_width_deg", 0, 60,
              "beta, width of the fibre lobe (degrees); 0 = 8; [0.5, 60]"),
    FLOATS_FIELD(sk_wood_shading_desc, fibre_srgb, "fibre_srgb", 3, 0, 1,
                 "colour of the fibre highlight (sRGB 0-1); default [0.95, 0.80, 0.60]"),
    FLOAT_FIELD(sk_wood_shading_desc, finish_ior, "finish_ior", 0, 3,
                "refractive index of the clear finish; 0 = 1.5; [1, 3]"),
    FLOAT_FIELD(sk_wood_shading_desc, finish_exponent, "finish_exponent", 0, 100000,
                "Blinn-Phong exponent of the finish's highlight; 0 = 400"),
};
static const sk_schema shading_schema = {"shading", shading_fields, COUNT(shading_fields)};

static const sk_schema_field view_fields[] = {
    {.key = "plane",
     .type = SK_FIELD_ENUM,
     .offset = offsetof(sk_wood_view_desc, plane),
     .names = sk_wood_plane_names,
     .doc = "\"end\", \"flat\" or \"quarter\"; default flat"},
    FLOAT_FIELD(sk_wood_view_desc, distance_mm, "distance_mm", 0, 10000,
                "distance of the cut (flat) or view centre (quarter, end) from the pith (mm); "
                "0 = half the log radius (flat, quarter)"),
    FLOAT_FIELD(sk_wood_view_desc, height_mm, "height_mm", -100000, 100000,
                "tree y of the view centre (mm); default 0"),
    FLOAT_FIELD(sk_wood_view_desc, width_mm, "width_mm", 0, 100000,
                "width of the view (mm); 0 = 100"),
    DEG_FIELD(sk_wood_view_desc, tilt, "tilt_deg", -90, 90,
              "plane turned about the image's horizontal axis (degrees); default 0"),
    DEG_FIELD(sk_wood_view_desc, light_incidence, "light_deg", -89, 89,
              "delta: light turned from the normal towards the image top (degrees); default 0"),
    DEG_FIELD(sk_wood_view_desc, light_azimuth, "light_azimuth_deg", -180, 180,
              "the light's plane turned about the normal (degrees); default 0"),
    DEG_FIELD(sk_wood_view_desc, view_incidence, "view_deg", -89, 89,
              "viewer turned from the normal towards the image top (degrees); default 0"),
};
static const sk_schema view_schema = {"view", view_fields, COUNT(view_fields)};

static const sk_schema_field wood_fields[] = {
    {.key = "seed",
     .type = SK_FIELD_SEED,
     .offset = offsetof(sk_wood_desc, seed),
     .min = 0,
     .max = 9007199254740992.0,
     .doc = "random seed; default 0"},
    OBJECT_FIELD(sk_wood_desc, transform, "transform", transform_schema,
                 "placement of the tree in the scene"),
    OBJECT_FIELD(sk_wood_desc, log, "log", log_schema, "extent of the precomputed tables"),
    OBJECT_FIELD(sk_wood_desc, rings, "rings", rings_schema, "annual rings R(t, theta) (sec. 4.4)"),
    OBJECT_FIELD(sk_wood_desc, grain, "grain", grain_schema, "grain G'(t, y) (eq. 1)"),
    OBJECT_FIELD(sk_wood_desc, vessels, "vessels", vessels_schema, "vessels (sec. 5)"),
    OBJECT_FIELD(sk_wood_desc, rays, "rays", rays_schema,
                 "broad (medullary) rays, the silver figure (beyond the paper)"),
    OBJECT_FIELD(sk_wood_desc, fibre, "fibre", fibre_schema, "shifting brightness (sec. 6)"),
    OBJECT_FIELD(sk_wood_desc, knots, "knots", knots_schema,
                 "knots: branches as cones from the pith (beyond the paper)"),
    OBJECT_FIELD(sk_wood_desc, shading, "shading", shading_schema, "reflection (sec. 7)"),
    OBJECT_FIELD(sk_wood_desc, view, "view", view_schema, "default planar cut and light"),
};

const sk_schema sk_wood_schema = {"wood", wood_fields, COUNT(wood_fields)};
