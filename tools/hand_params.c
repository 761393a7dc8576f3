/* The hand commands' parameters as preset keys (hand_params.h): each command's schema is
 * the models' schemas of the parts it takes, under one key each. */
#include <stddef.h>
#include <string.h>

#include "hand_params.h"

#define PART(member, key, sub, text) SK_SCHEMA_OBJECT(hand_params, member, key, sub, .doc = text)
#define SKELETON PART(hand, "hand", sk_hand_skeleton_schema, "the skeleton (3.1)")
#define LUT PART(lut, "lut", sk_hand_lut_schema, "lookup-table potentials (3.2.3)")
#define SURFACE                                                                                    \
    PART(surface, "surface", sk_hand_surface_schema, "the skin surface (4.1)"),                    \
        PART(texture, "texture", sk_hand_texture_schema, "its baked texture (4.1.6)"),             \
        SK_SCHEMA_ENUM(hand_params, skinning, "skinning", sk_hand_skinning_names,                  \
                       .def = SK_HAND_SKINNING_DQS,                                                \
                       .doc = "rigid (the thesis: nearest link), lbs or dqs"),                     \
        SK_SCHEMA_ENUM(hand_params, material, "material", sk_hand_gltf_material_names,             \
                       .def = SK_HAND_GLTF_MATERIAL_BLEND,                                         \
                       .doc = "a .glb's material: blend (the thesis's 0.3 lit : 0.7 unlit "        \
                              "texture) or pbr")
#define POTENTIAL                                                                                  \
    PART(potential, "potential", sk_hand_potential_schema,                                         \
         "the potential calibrated from the samples (3.2.2)")

static const sk_schema_field pose_fields[] = {SKELETON, LUT};
const sk_schema hand_pose_schema = SK_SCHEMA_OF("hand pose", hand_params, pose_fields);

static const sk_schema_field animate_fields[] = {SKELETON, SURFACE};
const sk_schema hand_animate_schema = SK_SCHEMA_OF("hand animate", hand_params, animate_fields);

static const sk_schema_field mesh_fields[] = {SKELETON, SURFACE};
const sk_schema hand_mesh_schema = SK_SCHEMA_OF("hand mesh", hand_params, mesh_fields);

static const sk_schema_field scan_fields[] = {
    SKELETON, PART(scan, "scan", sk_hand_scan_schema, "the scan pipeline (4.1)")};
const sk_schema hand_scan_schema = SK_SCHEMA_OF("hand scan", hand_params, scan_fields);

static const sk_schema_field calibrate_fields[] = {POTENTIAL};
const sk_schema hand_calibrate_schema =
    SK_SCHEMA_OF("hand calibrate", hand_params, calibrate_fields);

static const sk_schema_field evaluate_fields[] = {
    PART(evaluation, "evaluation", sk_hand_evaluation_schema, "the held-out evaluation"), POTENTIAL,
    LUT};
const sk_schema hand_evaluate_schema = SK_SCHEMA_OF("hand evaluate", hand_params, evaluate_fields);

static const sk_schema_field synthesize_fields[] = {
    PART(synthetic, "synthetic", sk_hand_synthetic_schema, "the synthetic recordings")};
const sk_schema hand_synthesize_schema =
    SK_SCHEMA_OF("hand synthesize", hand_params, synthesize_fields);

int hand_load_params(const cli_command *cmd, const cli_args *args, hand_params *params)
{
    memset(params, 0, sizeof *params);
    /* the seeds the commands used when none was given */
    params->potential.seed = 1;
    params->synthetic.seed = 1;
    return cli_bind_params(cmd, args, params);
}
