/* Character file schema: every key of a tissue character JSON with its type, range and
 * doc (bound onto sk_tissue_character_desc by the preset binder, which names the key path
 * in every error). The model it describes: Shigemori & Kawai secs. 2-4. */
#include <stddef.h>

#include "shitsukan/tissue.h"

#define BIG 1e5 /* mm: any offset within reason */

#define FLOAT3(k, T, field, lo, hi, d)                                                             \
    {                                                                                              \
        .key = k, .type = SK_FIELD_FLOATS, .offset = offsetof(T, field), .min = lo, .max = hi,     \
        .count = 3, .count_offset = SK_FIELD_FIXED, .doc = d                                       \
    }
#define NAME(k, T, field, d)                                                                       \
    {                                                                                              \
        .key = k, .type = SK_FIELD_STRING, .offset = offsetof(T, field),                           \
        .count = SK_TISSUE_NAME_SIZE, .doc = d                                                     \
    }
#define FLOAT(k, T, field, lo, hi, d)                                                              \
    {                                                                                              \
        .key = k, .type = SK_FIELD_FLOAT, .offset = offsetof(T, field), .min = lo, .max = hi,      \
        .doc = d                                                                                   \
    }
#define COUNT_OF(a) ((int)(sizeof(a) / sizeof((a)[0])))

static const sk_schema_field joint_fields[] = {
    NAME("name", sk_tissue_joint_desc, name,
         "unique joint name (as in motion files, or bound by joint_map)"),
    NAME("parent", sk_tissue_joint_desc, parent, "parent joint; \"\" or absent for the root"),
    FLOAT3("offset_mm", sk_tissue_joint_desc, offset_mm, -BIG, BIG,
           "from the parent at rest, mm, world axes (+Y up); the root: its rest position"),
};
static const sk_schema joint_schema = {"joint", joint_fields, COUNT_OF(joint_fields)};

static const sk_schema_field bone_fields[] = {
    NAME("name", sk_tissue_bone_desc, name, "unique bone name"),
    NAME("joint", sk_tissue_bone_desc, joint, "the joint whose frame carries the bone"),
    NAME("end", sk_tissue_bone_desc, end, "the joint where the bone ends; absent = joint + to_mm"),
    FLOAT3("from_mm", sk_tissue_bone_desc, from_mm, -BIG, BIG,
           "start, offset from the joint at rest; default 0"),
    FLOAT3("to_mm", sk_tissue_bone_desc, to_mm, -BIG, BIG,
           "end, offset from the joint, when `end` is absent"),
    FLOAT("radius_mm", sk_tissue_bone_desc, radius_mm, 0, 1000,
          "radius of the rounded ends, mm; required"),
    FLOAT("shaft_ratio", sk_tissue_bone_desc, shaft_ratio, 0, 1, "shaft radius / radius; 0 = 0.6"),
    FLOAT("depth_ratio", sk_tissue_bone_desc, depth_ratio, 0, 4,
          "Y / X semi-axis of the ellipsoids; 0 = 1"),
    FLOAT("end_length_mm", sk_tissue_bone_desc, end_length_mm, 0, 1000,
          "ends' semi-axis along the bone; 0 = radius"),
    FLOAT3("x_axis", sk_tissue_bone_desc, x_axis, -1, 1,
           "rest direction of the ellipsoids' X axis (made perpendicular to the bone); all 0 = "
           "automatic"),
};
static const sk_schema bone_schema = {"bone", bone_fields, COUNT_OF(bone_fields)};

static const sk_schema_field attachment_fields[] = {
    NAME("bone", sk_tissue_attachment_desc, bone, "the bone the tendon is fixed to"),
    FLOAT("at", sk_tissue_attachment_desc, at, -1, 2,
          "position along the bone: 0 its start, 1 its end"),
    FLOAT3("offset_mm", sk_tissue_attachment_desc, offset_mm, -BIG, BIG,
           "from that point, rest (world) axes, mm"),
};
static const sk_schema attachment_schema = {"attachment", attachment_fields,
                                            COUNT_OF(attachment_fields)};

static const sk_schema_field muscle_fields[] = {
    NAME("name", sk_tissue_muscle_desc, name, "unique muscle name"),
    {.key = "origin",
     .type = SK_FIELD_OBJECT,
     .offset = offsetof(sk_tissue_muscle_desc, origin),
     .schema = &attachment_schema,
     .doc = "where the first tendon is fixed"},
    {.key = "insertion",
     .type = SK_FIELD_OBJECT,
     .offset = offsetof(sk_tissue_muscle_desc, insertion),
     .schema = &attachment_schema,
     .doc = "where the second tendon is fixed"},
    FLOAT("thickness_mm", sk_tissue_muscle_desc, thickness_mm, 0, 1000,
          "rest thickness of the belly (2 a0), mm; required"),
    FLOAT("width_ratio", sk_tissue_muscle_desc, width_ratio, 0, 8,
          "width / thickness (b0 / a0, kept constant); 0 = 1"),
    FLOAT("belly_fraction", sk_tissue_muscle_desc, belly_fraction, 0, 1.5,
          "belly length / attachment distance at rest (2 c0 / L0); 0 = 0.8"),
    FLOAT3("x_axis", sk_tissue_muscle_desc, x_axis, -1, 1,
           "rest direction of the thickness (made perpendicular to the muscle); all 0 = away from "
           "the origin bone"),
};
static const sk_schema muscle_schema = {"muscle", muscle_fields, COUNT_OF(muscle_fields)};

static const sk_schema_field fat_fields[] = {
    NAME("name", sk_tissue_fat_desc, name, "region name (for messages)"),
    NAME("around", sk_tissue_fat_desc, around, "the bone or muscle the fat lies beside"),
    FLOAT("from", sk_tissue_fat_desc, from, -1, 2,
          "start along it (0 = its start); from and to both 0 = 0..1"),
    FLOAT("to", sk_tissue_fat_desc, to, -1, 2, "end along it (1 = its end)"),
    FLOAT("thickness_mm", sk_tissue_fat_desc, thickness_mm, 0, 500,
          "fat beyond the tissue in the region, mm; required"),
    FLOAT3("direction", sk_tissue_fat_desc, direction, -1, 1,
           "side of the bone or muscle (rest axes); all 0 = all around"),
    FLOAT("spread_deg", sk_tissue_fat_desc, spread_deg, 0, 180,
          "half-angle of the side around direction; 0 = 90"),
};
static const sk_schema fat_schema = {"fat", fat_fields, COUNT_OF(fat_fields)};

static const sk_schema_field map_fields[] = {
    {.key = "motion",
     .type = SK_FIELD_STRING,
     .offset = offsetof(sk_tissue_joint_map_desc, motion),
     .count = SK_BVH_NAME_SIZE,
     .doc = "a joint name in motion files"},
    NAME("joint", sk_tissue_joint_map_desc, joint, "the character joint it drives"),
};
static const sk_schema map_schema = {"joint_map", map_fields, COUNT_OF(map_fields)};

static const sk_schema_field tracked_fields[] = {
    NAME("name", sk_tissue_tracked_desc, name, "name in stats and plots"),
    NAME("bone", sk_tissue_tracked_desc, bone, "the bone the ray starts on"),
    FLOAT("at", sk_tissue_tracked_desc, at, -1, 2, "along the bone"),
    FLOAT3("direction", sk_tissue_tracked_desc, direction, -1, 1,
           "rest direction of the ray towards the skin"),
};
static const sk_schema tracked_schema = {"tracked", tracked_fields, COUNT_OF(tracked_fields)};

static const sk_schema_field skin_fields[] = {
    FLOAT("spacing_mm", sk_tissue_skin_desc, spacing_mm, 0, 50,
          "grid spacing, mm; 0 = 4; from 0.5"),
    {.key = "dilations",
     .type = SK_FIELD_INT,
     .offset = offsetof(sk_tissue_skin_desc, dilations),
     .min = 0,
     .max = 32,
     .doc = "dilation passes (sec. 4); 0 = 3"},
    FLOAT("dilation_radius_mm", sk_tissue_skin_desc, dilation_radius_mm, 0, 500,
          "reach of one pass, mm, 1 to 10 spacings; 0 = 1.5 spacings"),
    FLOAT("threshold", sk_tissue_skin_desc, threshold, 0, 0.999,
          "isosurface level in (0, 1); 0 = 0.3"),
    {.key = "smooth_iterations",
     .type = SK_FIELD_INT,
     .offset = offsetof(sk_tissue_skin_desc, smooth_iterations),
     .min = 0,
     .max = 200,
     .doc =
         "smoothing of the rest skin, kept outside the tissue; 0 = none (vertices on grid points)"},
    {.key = "neighbourhood",
     .type = SK_FIELD_INT,
     .offset = offsetof(sk_tissue_skin_desc, neighbourhood),
     .min = 0,
     .max = 26,
     .doc = "springs between grid neighbours: 18 or 26; 0 = 18"},
};
static const sk_schema skin_schema = {"skin", skin_fields, COUNT_OF(skin_fields)};

static const sk_schema_field material_fields[] = {
    FLOAT("fat_stiffness", sk_tissue_material_desc, fat_stiffness, 0, 1e6,
          "N/m, fat-fat and fat-skin springs; 0 = 5 (about 1 kPa fat at 4 mm); from 1e-3"),
    FLOAT("anchor_stiffness", sk_tissue_material_desc, anchor_stiffness, 0, 1e6,
          "N/m, fat to muscle and bone points; 0 = fat_stiffness"),
    FLOAT("skin_stiffness", sk_tissue_material_desc, skin_stiffness, 0, 1e6,
          "N/m, along skin triangle edges; 0 = 5 x fat_stiffness"),
    FLOAT("tether_stiffness", sk_tissue_material_desc, tether_stiffness, 0, 1e6,
          "N/m, zero-length spring from each fat and skin point to where the tissue carries it; 0 "
          "= 0.4 x fat; from 1e-4"),
    FLOAT("fat_density", sk_tissue_material_desc, fat_density, 0, 20000,
          "kg/m^3; 0 = 900; from 100"),
    FLOAT("skin_density", sk_tissue_material_desc, skin_density, 0, 20000,
          "kg/m^3; 0 = 1100; from 100"),
    FLOAT("skin_thickness_mm", sk_tissue_material_desc, skin_thickness_mm, 0, 20,
          "mass of the skin sheet, mm; 0 = 1.5"),
    FLOAT("damping_ratio", sk_tissue_material_desc, damping_ratio, 0, 4,
          "of every spring; 0 = 0.1"),
};
static const sk_schema material_schema = {"material", material_fields, COUNT_OF(material_fields)};

static const sk_schema_field simulation_fields[] = {
    {.key = "step_hz",
     .type = SK_FIELD_INT,
     .offset = offsetof(sk_tissue_simulation_desc, step_hz),
     .min = 0,
     .max = 20000,
     .doc = "fixed internal steps per second, from 60; 0 = 240 (a multiple of 120 suits 24/30/60 "
            "fps)"},
    {.key = "iterations",
     .type = SK_FIELD_INT,
     .offset = offsetof(sk_tissue_simulation_desc, iterations),
     .min = 0,
     .max = 64,
     .doc = "solver sweeps per step (more: closer to implicit Euler's exact stiffness); 0 = 1"},
    FLOAT("teleport_speed_m_s", sk_tissue_simulation_desc, teleport_speed_m_s, 0, 1e6,
          "a bone end faster than this (m/s) carries its flesh along; 0 = 50; from 0.1"),
    {.key = "no_fat",
     .type = SK_FIELD_BOOL,
     .offset = offsetof(sk_tissue_simulation_desc, no_fat),
     .doc = "skin follows the bones rigidly (no fat layer), for comparison; default false"},
};
static const sk_schema simulation_schema = {"simulation", simulation_fields,
                                            COUNT_OF(simulation_fields)};

#define ARRAY(k, field, count_field, max, T, schema_, d)                                           \
    {                                                                                              \
        .key = k, .type = SK_FIELD_ARRAY, .offset = offsetof(sk_tissue_character_desc, field),     \
        .count = max, .min_count = 0,                                                              \
        .count_offset = offsetof(sk_tissue_character_desc, count_field), .elem_size = sizeof(T),   \
        .schema = &schema_, .doc = d                                                               \
    }

static const sk_schema_field character_fields[] = {
    NAME("name", sk_tissue_character_desc, name, "character name"),
    FLOAT("motion_unit_mm", sk_tissue_character_desc, motion_unit_mm, 0, 1e4,
          "mm per length unit of motion files; 0 = 10 (cm); from 1e-3"),
    ARRAY("joints", joints, joint_count, SK_TISSUE_MAX_JOINTS, sk_tissue_joint_desc, joint_schema,
          "the skeleton at rest (sec. 2)"),
    ARRAY("bones", bones, bone_count, SK_TISSUE_MAX_BONES, sk_tissue_bone_desc, bone_schema,
          "bones of three ellipsoids (sec. 3)"),
    ARRAY("muscles", muscles, muscle_count, SK_TISSUE_MAX_MUSCLES, sk_tissue_muscle_desc,
          muscle_schema, "volume-keeping muscles (sec. 3)"),
    ARRAY("fat", fat, fat_count, SK_TISSUE_MAX_FAT_REGIONS, sk_tissue_fat_desc, fat_schema,
          "where fat lies beyond the base layer"),
    ARRAY("joint_map", joint_map, joint_map_count, SK_TISSUE_MAX_JOINT_MAP,
          sk_tissue_joint_map_desc, map_schema, "motion joint names bound to character joints"),
    ARRAY("tracked", tracked, tracked_count, SK_TISSUE_MAX_TRACKED, sk_tissue_tracked_desc,
          tracked_schema, "skin points followed in stats and plots"),
    {.key = "skin",
     .type = SK_FIELD_OBJECT,
     .offset = offsetof(sk_tissue_character_desc, skin),
     .schema = &skin_schema,
     .doc = "skin generation (sec. 4)"},
    {.key = "material",
     .type = SK_FIELD_OBJECT,
     .offset = offsetof(sk_tissue_character_desc, material),
     .schema = &material_schema,
     .doc = "springs, masses, damping"},
    {.key = "simulation",
     .type = SK_FIELD_OBJECT,
     .offset = offsetof(sk_tissue_character_desc, simulation),
     .schema = &simulation_schema,
     .doc = "internal step and guards"},
};
const sk_schema sk_tissue_character_schema = {"tissue character", character_fields,
                                              COUNT_OF(character_fields)};
