/* Character file schema: every key of a tissue character JSON with its type, range, default
 * and doc, stated once (the preset binder names the key path in every error, and
 * sk_tissue_character_desc_validate checks the resolved desc against the same ranges).
 * The model it describes: Shigemori & Kawai secs. 2-4. */
#include <stddef.h>

#include "shitsukan/tissue.h"

#define BIG 1e5 /* mm: any offset within reason */

static const sk_schema_field joint_fields[] = {
    SK_SCHEMA_STRING(sk_tissue_joint_desc, name, "name",
                     .doc = "unique joint name (as in motion files, or bound by joint_map)"),
    SK_SCHEMA_STRING(sk_tissue_joint_desc, parent, "parent",
                     .doc = "parent joint; \"\" or absent for the root"),
    SK_SCHEMA_FLOATS(sk_tissue_joint_desc, offset_mm, "offset_mm", 3, -BIG, BIG,
                     .doc = "from the parent at rest, mm, world axes (+Y up); the root: its rest "
                            "position"),
};
static const sk_schema joint_schema = SK_SCHEMA_OF("joint", sk_tissue_joint_desc, joint_fields);

/* Sec. 3: a bone of three ellipsoids. */
static const sk_schema_field bone_fields[] = {
    SK_SCHEMA_STRING(sk_tissue_bone_desc, name, "name", .doc = "unique bone name"),
    SK_SCHEMA_STRING(sk_tissue_bone_desc, joint, "joint",
                     .doc = "the joint whose frame carries the bone"),
    SK_SCHEMA_STRING(sk_tissue_bone_desc, end, "end",
                     .doc = "the joint where the bone ends; absent = joint + to_mm"),
    SK_SCHEMA_FLOATS(sk_tissue_bone_desc, from_mm, "from_mm", 3, -BIG, BIG,
                     .doc = "start, offset from the joint at rest"),
    SK_SCHEMA_FLOATS(sk_tissue_bone_desc, to_mm, "to_mm", 3, -BIG, BIG,
                     .doc = "end, offset from the joint, when `end` is absent"),
    SK_SCHEMA_FLOAT(sk_tissue_bone_desc, radius_mm, "radius_mm", 0, 1000,
                    .flags = SK_FIELD_OPEN_MIN, .doc = "radius of the rounded ends, mm"),
    SK_SCHEMA_FLOAT(sk_tissue_bone_desc, shaft_ratio, "shaft_ratio", 0, 1,
                    .flags = SK_FIELD_ZERO | SK_FIELD_OPEN_MIN, .def = 0.6,
                    .doc = "shaft radius / radius"),
    SK_SCHEMA_FLOAT(sk_tissue_bone_desc, depth_ratio, "depth_ratio", 0, 4,
                    .flags = SK_FIELD_ZERO | SK_FIELD_OPEN_MIN, .def = 1,
                    .doc = "Y / X semi-axis of the ellipsoids"),
    SK_SCHEMA_FLOAT(sk_tissue_bone_desc, end_length_mm, "end_length_mm", 0, 1000,
                    .flags = SK_FIELD_ZERO | SK_FIELD_OPEN_MIN, .def_text = "radius_mm",
                    .doc = "ends' semi-axis along the bone, mm"),
    SK_SCHEMA_FLOATS(
        sk_tissue_bone_desc, x_axis, "x_axis", 3, -1, 1,
        .def_text = "the world axis most across the bone",
        .doc = "rest direction of the ellipsoids' X axis (made perpendicular to the bone)"),
};
static const sk_schema bone_schema = SK_SCHEMA_OF("bone", sk_tissue_bone_desc, bone_fields);

static const sk_schema_field attachment_fields[] = {
    SK_SCHEMA_STRING(sk_tissue_attachment_desc, bone, "bone",
                     .doc = "the bone the tendon is fixed to"),
    SK_SCHEMA_FLOAT(sk_tissue_attachment_desc, at, "at", -1, 2,
                    .doc = "position along the bone: 0 its start, 1 its end"),
    SK_SCHEMA_FLOATS(sk_tissue_attachment_desc, offset_mm, "offset_mm", 3, -BIG, BIG,
                     .doc = "from that point, rest (world) axes, mm"),
};
static const sk_schema attachment_schema =
    SK_SCHEMA_OF("attachment", sk_tissue_attachment_desc, attachment_fields);

/* Sec. 3: a volume-keeping muscle. */
static const sk_schema_field muscle_fields[] = {
    SK_SCHEMA_STRING(sk_tissue_muscle_desc, name, "name", .doc = "unique muscle name"),
    SK_SCHEMA_OBJECT(sk_tissue_muscle_desc, origin, "origin", attachment_schema,
                     .doc = "where the first tendon is fixed"),
    SK_SCHEMA_OBJECT(sk_tissue_muscle_desc, insertion, "insertion", attachment_schema,
                     .doc = "where the second tendon is fixed"),
    SK_SCHEMA_FLOAT(sk_tissue_muscle_desc, thickness_mm, "thickness_mm", 0, 1000,
                    .flags = SK_FIELD_OPEN_MIN, .doc = "rest thickness of the belly (2 a0), mm"),
    SK_SCHEMA_FLOAT(sk_tissue_muscle_desc, width_ratio, "width_ratio", 0, 8,
                    .flags = SK_FIELD_ZERO | SK_FIELD_OPEN_MIN, .def = 1,
                    .doc = "width / thickness (b0 / a0, kept constant)"),
    SK_SCHEMA_FLOAT(sk_tissue_muscle_desc, belly_fraction, "belly_fraction", 0, 1.5,
                    .flags = SK_FIELD_ZERO | SK_FIELD_OPEN_MIN, .def = 0.8,
                    .doc = "belly length / attachment distance at rest (2 c0 / L0)"),
    SK_SCHEMA_FLOATS(sk_tissue_muscle_desc, x_axis, "x_axis", 3, -1, 1,
                     .def_text = "away from the origin bone",
                     .doc = "rest direction of the thickness (made perpendicular to the muscle)"),
};
static const sk_schema muscle_schema = SK_SCHEMA_OF("muscle", sk_tissue_muscle_desc, muscle_fields);

static const sk_schema_field fat_fields[] = {
    SK_SCHEMA_STRING(sk_tissue_fat_desc, name, "name", .doc = "region name (for messages)"),
    SK_SCHEMA_STRING(sk_tissue_fat_desc, around, "around",
                     .doc = "the bone or muscle the fat lies beside"),
    SK_SCHEMA_FLOAT(sk_tissue_fat_desc, from, "from", -1, 2,
                    .doc = "start along it (0 = its start, 1 = its end); less than to"),
    SK_SCHEMA_FLOAT(sk_tissue_fat_desc, to, "to", -1, 2, .def_text = "1 when from is 0 too",
                    .doc = "end along it"),
    SK_SCHEMA_FLOAT(sk_tissue_fat_desc, thickness_mm, "thickness_mm", 0, 500,
                    .flags = SK_FIELD_OPEN_MIN, .doc = "fat beyond the tissue in the region, mm"),
    SK_SCHEMA_FLOATS(sk_tissue_fat_desc, direction, "direction", 3, -1, 1, .def_text = "all around",
                     .doc = "side of the bone or muscle (rest axes)"),
    SK_SCHEMA_FLOAT(sk_tissue_fat_desc, spread_deg, "spread_deg", 0, 180,
                    .flags = SK_FIELD_ZERO | SK_FIELD_OPEN_MIN, .def = 90,
                    .doc = "half-angle of the side around direction, degrees"),
};
static const sk_schema fat_schema = SK_SCHEMA_OF("fat", sk_tissue_fat_desc, fat_fields);

static const sk_schema_field map_fields[] = {
    SK_SCHEMA_STRING(sk_tissue_joint_map_desc, motion, "motion",
                     .doc = "a joint name in motion files"),
    SK_SCHEMA_STRING(sk_tissue_joint_map_desc, joint, "joint",
                     .doc = "the character joint it drives"),
};
static const sk_schema map_schema = SK_SCHEMA_OF("joint_map", sk_tissue_joint_map_desc, map_fields);

static const sk_schema_field tracked_fields[] = {
    SK_SCHEMA_STRING(sk_tissue_tracked_desc, name, "name", .doc = "name in stats and plots"),
    SK_SCHEMA_STRING(sk_tissue_tracked_desc, bone, "bone", .doc = "the bone the ray starts on"),
    SK_SCHEMA_FLOAT(sk_tissue_tracked_desc, at, "at", -1, 2, .doc = "along the bone"),
    SK_SCHEMA_FLOATS(sk_tissue_tracked_desc, direction, "direction", 3, -1, 1,
                     .doc = "rest direction of the ray towards the skin"),
};
static const sk_schema tracked_schema =
    SK_SCHEMA_OF("tracked", sk_tissue_tracked_desc, tracked_fields);

/* Sec. 4: the skin from the dilated tissue. */
static const sk_schema_field skin_fields[] = {
    SK_SCHEMA_FLOAT(sk_tissue_skin_desc, spacing_mm, "spacing_mm", 0.5, 50, .flags = SK_FIELD_ZERO,
                    .def = 4, .doc = "grid spacing, mm"),
    SK_SCHEMA_INT(sk_tissue_skin_desc, dilations, "dilations", 1, 32, .flags = SK_FIELD_ZERO,
                  .def = 3, .doc = "dilation passes (sec. 4)"),
    SK_SCHEMA_FLOAT(sk_tissue_skin_desc, dilation_radius_mm, "dilation_radius_mm", 0, 500,
                    .def_text = "1.5 spacings", .doc = "reach of one pass, mm, 1 to 10 spacings"),
    SK_SCHEMA_FLOAT(sk_tissue_skin_desc, threshold, "threshold", 0, 0.999, .def = 0.3,
                    .doc = "isosurface level"),
    SK_SCHEMA_INT(sk_tissue_skin_desc, smooth_iterations, "smooth_iterations", 0, 200,
                  .doc = "smoothing of the rest skin, kept outside the tissue (0: every vertex on "
                         "a grid point)"),
    SK_SCHEMA_INT(sk_tissue_skin_desc, neighbourhood, "neighbourhood", 0, 26, .def = 18,
                  .doc = "springs between grid neighbours: 18 or 26"),
};
static const sk_schema skin_schema = SK_SCHEMA_OF("skin", sk_tissue_skin_desc, skin_fields);

static const sk_schema_field material_fields[] = {
    SK_SCHEMA_FLOAT(sk_tissue_material_desc, fat_stiffness, "fat_stiffness", 1e-3, 1e6,
                    .flags = SK_FIELD_ZERO, .def = 5,
                    .doc = "N/m, fat-fat and fat-skin springs (5: about 1 kPa fat at 4 mm)"),
    SK_SCHEMA_FLOAT(sk_tissue_material_desc, anchor_stiffness, "anchor_stiffness", 1e-3, 1e6,
                    .flags = SK_FIELD_ZERO, .def_text = "fat_stiffness",
                    .doc = "N/m, fat to muscle and bone points"),
    SK_SCHEMA_FLOAT(sk_tissue_material_desc, skin_stiffness, "skin_stiffness", 1e-3, 1e6,
                    .flags = SK_FIELD_ZERO, .def_text = "5 x fat_stiffness",
                    .doc = "N/m, along skin triangle edges"),
    SK_SCHEMA_FLOAT(
        sk_tissue_material_desc, tether_stiffness, "tether_stiffness", 1e-4, 1e6,
        .flags = SK_FIELD_ZERO, .def_text = "0.4 x fat_stiffness",
        .doc =
            "N/m, zero-length spring from each fat and skin point to where the tissue carries it"),
    SK_SCHEMA_FLOAT(sk_tissue_material_desc, fat_density, "fat_density", 100, 20000,
                    .flags = SK_FIELD_ZERO, .def = 900, .doc = "fat density, kg/m^3"),
    SK_SCHEMA_FLOAT(sk_tissue_material_desc, skin_density, "skin_density", 100, 20000,
                    .flags = SK_FIELD_ZERO, .def = 1100, .doc = "skin density, kg/m^3"),
    SK_SCHEMA_FLOAT(sk_tissue_material_desc, skin_thickness_mm, "skin_thickness_mm", 0, 20,
                    .def = 1.5, .doc = "mass of the skin sheet, mm"),
    SK_SCHEMA_FLOAT(sk_tissue_material_desc, damping_ratio, "damping_ratio", 0, 4,
                    .flags = SK_FIELD_ZERO | SK_FIELD_OPEN_MIN, .def = 0.1,
                    .doc = "of every spring"),
};
static const sk_schema material_schema =
    SK_SCHEMA_OF("material", sk_tissue_material_desc, material_fields);

static const sk_schema_field simulation_fields[] = {
    SK_SCHEMA_INT(sk_tissue_simulation_desc, step_hz, "step_hz", 60, 20000, .flags = SK_FIELD_ZERO,
                  .def = 240,
                  .doc = "fixed internal steps per second (a multiple of 120 suits 24/30/60 fps)"),
    SK_SCHEMA_INT(sk_tissue_simulation_desc, iterations, "iterations", 1, 64,
                  .flags = SK_FIELD_ZERO, .def = 1,
                  .doc =
                      "solver sweeps per step (more: closer to implicit Euler's exact stiffness)"),
    SK_SCHEMA_FLOAT(sk_tissue_simulation_desc, teleport_speed_m_s, "teleport_speed_m_s", 0.1, 1e6,
                    .flags = SK_FIELD_ZERO, .def = 50,
                    .doc = "a bone end faster than this (m/s) carries its flesh along"),
    SK_SCHEMA_BOOL(sk_tissue_simulation_desc, no_fat, "no_fat",
                   .doc = "skin follows the bones rigidly (no fat layer), for comparison"),
};
static const sk_schema simulation_schema =
    SK_SCHEMA_OF("simulation", sk_tissue_simulation_desc, simulation_fields);

static const sk_schema_field character_fields[] = {
    SK_SCHEMA_STRING(sk_tissue_character_desc, name, "name", .doc = "character name"),
    SK_SCHEMA_FLOAT(sk_tissue_character_desc, motion_unit_mm, "motion_unit_mm", 1e-3, 1e4,
                    .flags = SK_FIELD_ZERO, .def = 10,
                    .doc = "mm per length unit of motion files (10: cm)"),
    SK_SCHEMA_ARRAY(sk_tissue_character_desc, joints, "joints", joint_count, 0, joint_schema,
                    .doc = "the skeleton at rest (sec. 2)"),
    SK_SCHEMA_ARRAY(sk_tissue_character_desc, bones, "bones", bone_count, 0, bone_schema,
                    .doc = "bones of three ellipsoids (sec. 3)"),
    SK_SCHEMA_ARRAY(sk_tissue_character_desc, muscles, "muscles", muscle_count, 0, muscle_schema,
                    .doc = "volume-keeping muscles (sec. 3)"),
    SK_SCHEMA_ARRAY(sk_tissue_character_desc, fat, "fat", fat_count, 0, fat_schema,
                    .doc = "where fat lies beyond the base layer"),
    SK_SCHEMA_ARRAY(sk_tissue_character_desc, joint_map, "joint_map", joint_map_count, 0,
                    map_schema, .doc = "motion joint names bound to character joints"),
    SK_SCHEMA_ARRAY(sk_tissue_character_desc, tracked, "tracked", tracked_count, 0, tracked_schema,
                    .doc = "skin points followed in stats and plots"),
    SK_SCHEMA_OBJECT(sk_tissue_character_desc, skin, "skin", skin_schema,
                     .doc = "skin generation (sec. 4)"),
    SK_SCHEMA_OBJECT(sk_tissue_character_desc, material, "material", material_schema,
                     .doc = "springs, masses, damping"),
    SK_SCHEMA_OBJECT(sk_tissue_character_desc, simulation, "simulation", simulation_schema,
                     .doc = "internal step and guards"),
};
const sk_schema sk_tissue_character_schema =
    SK_SCHEMA_OF("tissue character", sk_tissue_character_desc, character_fields);
