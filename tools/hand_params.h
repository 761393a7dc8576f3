/* The parameters of the `shitsukan hand ...` commands as preset keys: one struct holding
 * the model descs the commands use (the skeleton, lookup tables, surface and texture,
 * scan, potential, evaluation, synthetic recordings), each command's schema of the parts
 * it takes (the models' own schemas under "hand", "lut", "surface", ...), and its options
 * that are other names for those keys. Preset files, --set and --help-keys work on them
 * as for every other command. */
#ifndef SK_TOOLS_HAND_PARAMS_H
#define SK_TOOLS_HAND_PARAMS_H

#include "cli.h"
#include "shitsukan/hand.h"

typedef struct hand_params {
    sk_hand_skeleton_desc hand;         /* "hand": side, hand_length_mm, hand_breadth_mm */
    sk_hand_lut_desc lut;               /* "lut": lookup tables (3.2.3) */
    sk_hand_surface_desc surface;       /* "surface": triangles, cell_mm */
    sk_hand_texture_desc texture;       /* "texture": the baked atlas */
    sk_hand_skinning skinning;          /* "skinning": rigid, lbs or dqs */
    sk_hand_gltf_material material;     /* "material": a .glb's blend or pbr */
    sk_hand_scan_desc scan;             /* "scan": the scan pipeline (4.1) */
    sk_hand_potential_desc potential;   /* "potential": the calibrated potential (3.2.2) */
    sk_hand_evaluation_desc evaluation; /* "evaluation": folds, PCA baseline, pair model */
    sk_hand_synthetic_desc synthetic;   /* "synthetic": synthetic glove recordings */
} hand_params;

/* The schemas of the commands (key paths "hand.side", "lut.resolution", ...). */
extern const sk_schema hand_pose_schema, hand_animate_schema, hand_mesh_schema, hand_scan_schema,
    hand_calibrate_schema, hand_evaluate_schema, hand_synthesize_schema;

/* The options of the skeleton that set keys (--side, --hand-length, --hand-breadth). */
#define HAND_SKELETON_KEY_OPTIONS                                                                  \
    {"side", "hand.side", NULL, false}, {"hand-length", "hand.hand_length_mm", NULL, false},       \
    {                                                                                              \
        "hand-breadth", "hand.hand_breadth_mm", NULL, false                                        \
    }
/* ... of the lookup tables (--lut-resolution, --lut-weight, --lut-interp). */
#define HAND_LUT_KEY_OPTIONS                                                                       \
    {"lut-resolution", "lut.resolution", NULL, false}, {"lut-weight", "lut.weight", NULL, false},  \
    {                                                                                              \
        "lut-interp", "lut.interp", NULL, false                                                    \
    }
/* ... of the surface (--triangles, --texture-size, --skinning, --material). */
#define HAND_SURFACE_KEY_OPTIONS                                                                   \
    {"triangles", "surface.triangles", NULL, false},                                               \
        {"texture-size", "texture.size", NULL, false}, {"skinning", "skinning", NULL, false},      \
    {                                                                                              \
        "material", "material", NULL, false                                                        \
    }

/* The command's parameters: the preset, its key options, --set and --seed bound through
 * its schema onto `params` (zeroed first; the potential's and the recordings' seed is 1
 * unless given, as it was before). Prints the error and returns its status. */
int hand_load_params(const cli_command *cmd, const cli_args *args, hand_params *params);

#endif
