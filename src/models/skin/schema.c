/* Preset schema of the skin (keys of presets/skin/ *.json): the paper's six parameters per
 * level (Ishii et al. 1991, sec. 4.2, Table 1 columns), tiling, pores and shading, each key
 * with its range, default and one-line doc, stated once: sk_skin_desc_validate and
 * sk_skin_desc_resolved read them from here. */
#include <stddef.h>

#include "models/skin/skin_internal.h"

static const char *const layout_names[] = {"default", "triangular", "square", "random", NULL};
static const char *const jitter_names[] = {"default", "uniform", "normal", NULL};
static const char *const normal_model_names[] = {"default", "gradient", "profile", NULL};

static const sk_schema_field point_fields[] = {
    SK_SCHEMA_ELEMENT_FLOATS(2, -1000, 1000,
                             .doc = "control point [x, z]: x in [0, 10] from centre to boundary, z "
                                    "in tenths of the nominal cell radius"),
};
static const sk_schema point_schema = {"point", point_fields, 1, NULL};

static const sk_schema_field segment_fields[] = {
    SK_SCHEMA_FIXED_ARRAY(sk_skin_segment, points, "points", point_schema,
                          .doc = "the 4 control points of one cubic Bezier segment"),
};
static const sk_schema segment_schema = SK_SCHEMA_OF("segment", sk_skin_segment, segment_fields);

/* Sec. 3.2 / Fig. 11: (1) centre points, (2) perturbation, (3) stretch, (5) profile,
 * (6) roundness; (4), the levels, is the length of `levels`. */
static const sk_schema_field level_fields[] = {
    SK_SCHEMA_ENUM(sk_skin_level, layout, "layout", layout_names, .def = SK_SKIN_LAYOUT_TRIANGULAR,
                   .doc = "centre-point layout (sec. 3.2 (1))"),
    SK_SCHEMA_ENUM(sk_skin_level, jitter, "jitter", jitter_names, .def = SK_SKIN_JITTER_UNIFORM,
                   .doc = "lattice jitter distribution"),
    SK_SCHEMA_FLOAT(sk_skin_level, jitter_rate, "jitter_rate", 0, 1,
                    .doc = "maximum jitter as a fraction of the spacing"),
    SK_SCHEMA_FLOAT(sk_skin_level, spacing_mm, "spacing_mm", 0, 1000,
                    .def_text = "0.8 mm at level 1, 0.4 x the level above",
                    .doc = "lattice spacing in mm before stretch"),
    SK_SCHEMA_FLOAT(sk_skin_level, perturb_rate, "perturb_rate", 0, 1,
                    .doc = "edge perturbation A of V = A 2^(-n h) Rnd L"),
    SK_SCHEMA_FLOAT(sk_skin_level, perturb_decay, "perturb_decay", 0, 4,
                    .doc = "decay h of the displacement with division depth n"),
    SK_SCHEMA_INT(sk_skin_level, perturb_depth, "perturb_depth", 0, 10, .def = 4,
                  .doc = "midpoint division depths (2^depth segments per edge)"),
    SK_SCHEMA_FLOATS(sk_skin_level, stretch, "stretch", 2, 0, 100, .def = 1,
                     .doc = "[Sx, Sy] stretch of this level's polygons"),
    SK_SCHEMA_DEG(sk_skin_level, stretch_angle, "stretch_angle_deg", -360, 360,
                  .doc = "direction of Sx, degrees counter-clockwise from +x"),
    SK_SCHEMA_ARRAY(sk_skin_level, segments, "profile", segment_count, 1, segment_schema,
                    .def_text = "(0,3)(5,3)(8,2.5)(10,0), Fig. 13c",
                    .doc = "section profile: chained cubic Bezier segments, x from 0 to 10"),
    SK_SCHEMA_FLOAT(sk_skin_level, roundness, "roundness", 0, 1,
                    .doc = "0: contours similar to the polygon, 1: nearly circular"),
};
const sk_schema sk__skin_level_schema = SK_SCHEMA_OF("level", sk_skin_level, level_fields);

static const sk_schema_field pore_fields[] = {
    SK_SCHEMA_FLOAT(sk_skin_pore_kind, depth_mm, "depth_mm", 0, 10,
                    .def_text = "no pores of this kind", .doc = "pit depth in mm"),
    SK_SCHEMA_FLOAT(sk_skin_pore_kind, radius_mm, "radius_mm", 0, 10, .def = 0.03,
                    .doc = "pit radius in mm"),
    SK_SCHEMA_FLOAT(sk_skin_pore_kind, density, "density", 0, 1, .def = 0.5,
                    .doc = "fraction of the candidate places that get a pore"),
};
static const sk_schema pore_schema = SK_SCHEMA_OF("pore", sk_skin_pore_kind, pore_fields);

static const sk_schema_field pores_fields[] = {
    SK_SCHEMA_OBJECT(sk_skin_pores, hair, "hair", pore_schema,
                     .doc = "hair pores at the junctions of level-1 furrows"),
    SK_SCHEMA_OBJECT(sk_skin_pores, sweat, "sweat", pore_schema,
                     .doc = "sweat pores at ridge centres"),
    SK_SCHEMA_INT(sk_skin_pores, sweat_level, "sweat_level", 0, SK_SKIN_MAX_LEVELS, .def = 1,
                  .doc = "level whose ridges get sweat pores, at most the level count"),
};
static const sk_schema pores_schema = SK_SCHEMA_OF("pores", sk_skin_pores, pores_fields);

static const double default_albedo[3] = {0.80, 0.52, 0.42};

static const sk_schema_field shading_fields[] = {
    SK_SCHEMA_DEG(sk_skin_shading, light_azimuth, "light_azimuth_deg", -360, 360,
                  .doc = "where the light comes from: 0 = top of the image, counter-clockwise"),
    SK_SCHEMA_DEG(sk_skin_shading, light_elevation, "light_elevation_deg", 0, 90, .def = 45,
                  .doc = "light elevation above the surface in degrees"),
    SK_SCHEMA_FLOATS(sk_skin_shading, albedo, "albedo", 3, 0, 1, .defs = default_albedo,
                     .doc = "linear RGB albedo (the default: a skin tone)"),
    SK_SCHEMA_FLOAT(sk_skin_shading, sun_fraction, "sun_fraction", 0, 1, .def = 0.85,
                    .doc = "share of directional light (the rest is sky light)"),
    SK_SCHEMA_FLOAT(sk_skin_shading, specular, "specular", 0, 1, .def = 0.06,
                    .doc = "soft highlight strength"),
    SK_SCHEMA_FLOAT(sk_skin_shading, shininess, "shininess", 0, 1000, .def = 24,
                    .doc = "Blinn-Phong exponent"),
    SK_SCHEMA_BOOL(sk_skin_shading, no_specular, "no_specular", .doc = "true: Lambert only"),
};
static const sk_schema shading_schema = SK_SCHEMA_OF("shading", sk_skin_shading, shading_fields);

static const sk_schema_field skin_fields[] = {
    SK_SCHEMA_SEED(sk_skin_desc, seed, "seed", .doc = "random seed"),
    SK_SCHEMA_FLOATS(sk_skin_desc, size_mm, "size_mm", 2, 0, 1000, .def = 10,
                     .doc = "[width, height] of the tile in mm"),
    SK_SCHEMA_BOOL(sk_skin_desc, aperiodic, "aperiodic",
                   .doc = "true: no seamless wrap (false: the tile wraps)"),
    SK_SCHEMA_ARRAY(sk_skin_desc, levels, "levels", level_count, 1, sk__skin_level_schema,
                    .def_text = "the 3 levels of Fig. 19a",
                    .doc = "hierarchy levels, largest ridges first"),
    SK_SCHEMA_ENUM(sk_skin_desc, normal_model, "normal_model", normal_model_names,
                   .def = SK_SKIN_NORMAL_GRADIENT,
                   .doc = "gradient (the height's exact normal, for maps) or profile (the paper's "
                          "Fig. 7: the profile's slope along the ray from the cell centre)"),
    SK_SCHEMA_OBJECT(sk_skin_desc, pores, "pores", pores_schema,
                     .doc = "hair and sweat pores (off by default)"),
    SK_SCHEMA_OBJECT(sk_skin_desc, shading, "shading", shading_schema,
                     .doc = "light and material of the shaded preview"),
};

const sk_schema sk_skin_schema = SK_SCHEMA_OF("skin", sk_skin_desc, skin_fields);
