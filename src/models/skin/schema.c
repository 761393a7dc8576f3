/* Preset schema of the skin (keys of presets/skin/ *.json): the paper's six parameters per
 * level (Table 1 columns), tiling, pores and shading, with ranges and one-line docs. */
#include <stddef.h>

#include "models/skin/skin_internal.h"

#define F(key_, type_, field, lo, hi, doc_)                                                        \
    {                                                                                              \
        .key = key_, .type = type_, .offset = offsetof(STRUCT, field), .min = lo, .max = hi,       \
        .doc = doc_                                                                                \
    }

static const char *const layout_names[] = {"default", "triangular", "square", "random", NULL};
static const char *const jitter_names[] = {"default", "uniform", "normal", NULL};
static const char *const normal_model_names[] = {"default", "gradient", "profile", NULL};

#define STRUCT float
static const sk_schema_field point_fields[] = {
    {.key = NULL,
     .type = SK_FIELD_FLOATS,
     .offset = 0,
     .min = -1000,
     .max = 1000,
     .count = 2,
     .count_offset = SK_FIELD_FIXED,
     .doc = "control point [x, z]: x in [0, 10] from centre to boundary, z in tenths of the "
            "nominal cell radius"},
};
static const sk_schema point_schema = {"point", point_fields, 1};
#undef STRUCT

#define STRUCT sk_skin_segment
static const sk_schema_field segment_fields[] = {
    {.key = "points",
     .type = SK_FIELD_ARRAY,
     .offset = offsetof(sk_skin_segment, points),
     .count = 4,
     .min_count = 4,
     .count_offset = SK_FIELD_FIXED,
     .elem_size = sizeof(float[2]),
     .schema = &point_schema,
     .doc = "the 4 control points of one cubic Bezier segment"},
};
static const sk_schema segment_schema = {"segment", segment_fields, 1};
#undef STRUCT

#define STRUCT sk_skin_level
static const sk_schema_field level_fields[] = {
    {.key = "layout",
     .type = SK_FIELD_ENUM,
     .offset = offsetof(STRUCT, layout),
     .names = layout_names,
     .doc = "centre-point layout: triangular (default), square or random"},
    {.key = "jitter",
     .type = SK_FIELD_ENUM,
     .offset = offsetof(STRUCT, jitter),
     .names = jitter_names,
     .doc = "lattice jitter: uniform (default) or normal"},
    F("jitter_rate", SK_FIELD_FLOAT, jitter_rate, 0, 1,
      "maximum jitter as a fraction of the spacing; default 0"),
    F("spacing_mm", SK_FIELD_FLOAT, spacing_mm, 0, 1000,
      "lattice spacing in mm before stretch; 0 = 0.8 mm at level 1, 0.4 x the level above"),
    F("perturb_rate", SK_FIELD_FLOAT, perturb_rate, 0, 1,
      "edge perturbation A of V = A 2^(-n h) Rnd L; default 0"),
    F("perturb_decay", SK_FIELD_FLOAT, perturb_decay, 0, 4,
      "decay h of the displacement with division depth n; default 0"),
    F("perturb_depth", SK_FIELD_INT, perturb_depth, 0, 10,
      "midpoint division depths (2^depth segments per edge); 0 = 4"),
    {.key = "stretch",
     .type = SK_FIELD_FLOATS,
     .offset = offsetof(STRUCT, stretch),
     .min = 0,
     .max = 100,
     .count = 2,
     .count_offset = SK_FIELD_FIXED,
     .doc = "[Sx, Sy] stretch of this level's polygons; 0 = 1"},
    {.key = "stretch_angle_deg",
     .type = SK_FIELD_FLOAT,
     .offset = offsetof(STRUCT, stretch_angle),
     .min = -360,
     .max = 360,
     .scale = SK_DEG_TO_RAD,
     .doc = "direction of Sx, degrees counter-clockwise from +x; default 0"},
    {.key = "profile",
     .type = SK_FIELD_ARRAY,
     .offset = offsetof(STRUCT, segments),
     .count = SK_SKIN_MAX_SEGMENTS,
     .min_count = 1,
     .count_offset = offsetof(STRUCT, segment_count),
     .elem_size = sizeof(sk_skin_segment),
     .schema = &segment_schema,
     .doc = "section profile: chained cubic Bezier segments, x from 0 to 10; default "
            "(0,3)(5,3)(8,2.5)(10,0)"},
    F("roundness", SK_FIELD_FLOAT, roundness, 0, 1,
      "0: contours similar to the polygon, 1: nearly circular; default 0"),
};
static const sk_schema level_schema = {"level", level_fields,
                                       (int)(sizeof level_fields / sizeof level_fields[0])};
#undef STRUCT

#define STRUCT sk_skin_pore_kind
static const sk_schema_field pore_fields[] = {
    F("depth_mm", SK_FIELD_FLOAT, depth_mm, 0, 10, "pit depth in mm; default 0 = none"),
    F("radius_mm", SK_FIELD_FLOAT, radius_mm, 0, 10, "pit radius in mm; 0 = 0.03"),
    F("density", SK_FIELD_FLOAT, density, 0, 1,
      "fraction of the candidate places that get a pore; 0 = 0.5"),
};
static const sk_schema pore_schema = {"pore", pore_fields, 3};
#undef STRUCT

#define STRUCT sk_skin_pores
static const sk_schema_field pores_fields[] = {
    {.key = "hair",
     .type = SK_FIELD_OBJECT,
     .offset = offsetof(STRUCT, hair),
     .schema = &pore_schema,
     .doc = "hair pores at the junctions of level-1 furrows"},
    {.key = "sweat",
     .type = SK_FIELD_OBJECT,
     .offset = offsetof(STRUCT, sweat),
     .schema = &pore_schema,
     .doc = "sweat pores at ridge centres"},
    F("sweat_level", SK_FIELD_INT, sweat_level, 0, SK_SKIN_MAX_LEVELS,
      "level whose ridges get sweat pores; 0 = 1"),
};
static const sk_schema pores_schema = {"pores", pores_fields, 3};
#undef STRUCT

#define STRUCT sk_skin_shading
static const sk_schema_field shading_fields[] = {
    {.key = "light_azimuth_deg",
     .type = SK_FIELD_FLOAT,
     .offset = offsetof(STRUCT, light_azimuth),
     .min = -360,
     .max = 360,
     .scale = SK_DEG_TO_RAD,
     .doc = "where the light comes from: 0 = top of the image, counter-clockwise; default 0"},
    {.key = "light_elevation_deg",
     .type = SK_FIELD_FLOAT,
     .offset = offsetof(STRUCT, light_elevation),
     .min = 0,
     .max = 90,
     .scale = SK_DEG_TO_RAD,
     .doc = "light elevation above the surface in degrees; 0 = 45"},
    {.key = "albedo",
     .type = SK_FIELD_FLOATS,
     .offset = offsetof(STRUCT, albedo),
     .min = 0,
     .max = 1,
     .count = 3,
     .count_offset = SK_FIELD_FIXED,
     .doc = "linear RGB albedo; [0,0,0] = skin tone (0.80, 0.52, 0.42)"},
    F("sun_fraction", SK_FIELD_FLOAT, sun_fraction, 0, 1,
      "share of directional light (the rest is sky light); 0 = 0.85"),
    F("specular", SK_FIELD_FLOAT, specular, 0, 1, "soft highlight strength; 0 = 0.06"),
    F("shininess", SK_FIELD_FLOAT, shininess, 0, 1000, "Blinn-Phong exponent; 0 = 24"),
    {.key = "no_specular",
     .type = SK_FIELD_BOOL,
     .offset = offsetof(STRUCT, no_specular),
     .doc = "true: Lambert only; default false"},
};
static const sk_schema shading_schema = {"shading", shading_fields,
                                         (int)(sizeof shading_fields / sizeof shading_fields[0])};
#undef STRUCT

#define STRUCT sk_skin_desc
static const sk_schema_field skin_fields[] = {
    {.key = "seed",
     .type = SK_FIELD_SEED,
     .offset = offsetof(STRUCT, seed),
     .min = 0,
     .max = 9007199254740992.0,
     .doc = "random seed; default 0"},
    {.key = "size_mm",
     .type = SK_FIELD_FLOATS,
     .offset = offsetof(STRUCT, size_mm),
     .min = 0,
     .max = 1000,
     .count = 2,
     .count_offset = SK_FIELD_FIXED,
     .doc = "[width, height] of the tile in mm; 0 = 10"},
    {.key = "aperiodic",
     .type = SK_FIELD_BOOL,
     .offset = offsetof(STRUCT, aperiodic),
     .doc = "true: no seamless wrap; default false (tileable)"},
    {.key = "levels",
     .type = SK_FIELD_ARRAY,
     .offset = offsetof(STRUCT, levels),
     .count = SK_SKIN_MAX_LEVELS,
     .min_count = 1,
     .count_offset = offsetof(STRUCT, level_count),
     .elem_size = sizeof(sk_skin_level),
     .schema = &level_schema,
     .doc = "hierarchy levels, largest ridges first; absent = the default 3-level skin"},
    {.key = "normal_model",
     .type = SK_FIELD_ENUM,
     .offset = offsetof(STRUCT, normal_model),
     .names = normal_model_names,
     .doc = "gradient (default: the height's exact normal, for maps) or profile (the paper's "
            "Fig. 7: the profile's slope along the ray from the cell centre)"},
    {.key = "pores",
     .type = SK_FIELD_OBJECT,
     .offset = offsetof(STRUCT, pores),
     .schema = &pores_schema,
     .doc = "hair and sweat pores (off by default)"},
    {.key = "shading",
     .type = SK_FIELD_OBJECT,
     .offset = offsetof(STRUCT, shading),
     .schema = &shading_schema,
     .doc = "light and material of the shaded preview"},
};
#undef STRUCT

const sk_schema sk_skin_schema = {"skin", skin_fields,
                                  (int)(sizeof skin_fields / sizeof skin_fields[0])};
