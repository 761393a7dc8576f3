/* Preset schemas of the hand posture model's descs (Yasumuro 2000, ch. 3): the skeleton's
 * size and side (3.1), the lookup-table potentials (3.2.3), the solver, the calibrated
 * potential (3.2.2) and its held-out evaluation, and the synthetic glove recordings. Each
 * key's range and default are stated here once; the model's checks read them. */
#include <stddef.h>

#include "models/hand/solver_internal.h"
#include "shitsukan/hand_posture.h"

static const char *const side_names[] = {"default", "right", "left", NULL};
static const char *const interp_names[] = {"default", "hermite", "bilinear", NULL};
static const char *const method_names[] = {"default", "gaussian", "mixture", "pairs", NULL};
static const char *const rule_names[] = {"default", "thesis", "inverse-variance", NULL};

/* 3.1: the link lengths scale with the hand's length and breadth. */
static const sk_schema_field skeleton_fields[] = {
    SK_SCHEMA_DOUBLE(sk_hand_skeleton_desc, hand_length_mm, "hand_length_mm", 60, 400,
                     .flags = SK_FIELD_ZERO, .def_text = "the anatomy's (190)",
                     .doc = "hand length, wrist crease to middle fingertip (mm)"),
    SK_SCHEMA_DOUBLE(sk_hand_skeleton_desc, hand_breadth_mm, "hand_breadth_mm", 30, 200,
                     .flags = SK_FIELD_ZERO, .def_text = "the anatomy's (85)",
                     .doc = "hand breadth across the knuckles (mm)"),
    SK_SCHEMA_ENUM(sk_hand_skeleton_desc, side, "side", side_names, .def = SK_HAND_SIDE_RIGHT,
                   .doc = "right or left (the mirror image)"),
};
const sk_schema sk_hand_skeleton_schema =
    SK_SCHEMA_OF("hand", sk_hand_skeleton_desc, skeleton_fields);

/* 3.2.3: lookup tables of the squared distance to the samples of a DOF pair. */
static const sk_schema_field lut_fields[] = {
    SK_SCHEMA_INT(sk_hand_lut_desc, resolution, "resolution", 8, 1024, .flags = SK_FIELD_ZERO,
                  .def = 100, .doc = "grid nodes per axis"),
    SK_SCHEMA_DOUBLE(sk_hand_lut_desc, margin, "margin", 0, 4, .def = 0.25,
                     .doc = "the grid extends this fraction of the samples' range beyond it"),
    SK_SCHEMA_DOUBLE(sk_hand_lut_desc, weight, "weight", 1e-6, 1e6, .flags = SK_FIELD_ZERO,
                     .def = 1, .doc = "multiplies each table's potential"),
    SK_SCHEMA_ENUM(sk_hand_lut_desc, interp, "interp", interp_names,
                   .def = SK_HAND_LUT_INTERP_HERMITE,
                   .doc = "hermite (converges to 1e-6) or bilinear (the tables as they are)"),
};
const sk_schema sk_hand_lut_schema = SK_SCHEMA_OF("lut", sk_hand_lut_desc, lut_fields);

static const sk_schema_field solver_fields[] = {
    SK_SCHEMA_INT(sk_hand_solver_desc, max_newton_iterations, "max_newton_iterations", 1, 10000,
                  .flags = SK_FIELD_ZERO, .def = 500,
                  .doc = "iterative solve with lookup tables: steps at most"),
    SK_SCHEMA_DOUBLE(sk_hand_solver_desc, tolerance, "tolerance", 1e-15, 1, .flags = SK_FIELD_ZERO,
                     .def = 1e-6,
                     .doc = "the iterative solve stops when the residual is below (the linear "
                            "solve is direct)"),
    SK_SCHEMA_INT(sk_hand_solver_desc, cache_size, "cache_size", 1, SK_HAND_MAX_CACHE,
                  .flags = SK_FIELD_ZERO, .def = 8, .doc = "factorisations kept (by free set)"),
};
const sk_schema sk_hand_solver_schema = SK_SCHEMA_OF("solver", sk_hand_solver_desc, solver_fields);

/* 3.2.2 in full: eq. 3.17's potential from the samples' moments. */
static const sk_schema_field potential_fields[] = {
    SK_SCHEMA_ENUM(sk_hand_potential_desc, method, "method", method_names,
                   .def = SK_HAND_POTENTIAL_MIXTURE,
                   .doc = "gaussian, mixture (components chosen on held-out samples) or pairs "
                          "(the thesis's form: pair rows and weight scale chosen on held-out "
                          "samples)"),
    SK_SCHEMA_INT(sk_hand_potential_desc, max_components, "max_components", 1,
                  SK_HAND_POTENTIAL_MAX_COMPONENTS, .flags = SK_FIELD_ZERO, .def = 12,
                  .doc = "mixture: component counts tried, 1, 2, 3, 4, 6, 8, 12, 16 up to it"),
    SK_SCHEMA_INT(sk_hand_potential_desc, components, "components", 0,
                  SK_HAND_POTENTIAL_MAX_COMPONENTS, .def_text = "chosen on held-out samples",
                  .doc = "mixture: a fixed component count"),
    SK_SCHEMA_DOUBLE(sk_hand_potential_desc, prior_strength, "prior_strength", -1, 1e7,
                     .def_text = "chosen by held-out likelihood from 1, 4, 16, 64, 256",
                     .doc = "pseudo-samples of the base set's Gaussian the moments shrink "
                            "toward (negative: none)"),
    SK_SCHEMA_SEED(sk_hand_potential_desc, seed, "seed", .doc = "mixture initialisation"),
    SK_SCHEMA_ENUM(sk_hand_potential_desc, weight_rule, "weight_rule", rule_names,
                   .def_text = "inverse-variance in stiffness units",
                   .doc = "pairs: weights of the fitted rows, thesis (eq. 3.18 over the chosen "
                          "rows) or inverse-variance"),
    SK_SCHEMA_DOUBLE(sk_hand_potential_desc, weight_scale, "weight_scale", 1e-6, 1e6,
                     .flags = SK_FIELD_ZERO,
                     .def_text = "chosen on held-out samples from 1/4, 1/2, 1, ..., 64",
                     .doc = "pairs: multiplies the fitted rows' weights"),
    SK_SCHEMA_INT(sk_hand_potential_desc, max_pairs, "max_pairs", 1, 64, .flags = SK_FIELD_ZERO,
                  .def = 16, .doc = "pairs: fitted rows at most"),
};
const sk_schema sk_hand_potential_schema =
    SK_SCHEMA_OF("potential", sk_hand_potential_desc, potential_fields);

/* Held-out prediction of joint angles (the model and its baselines on the same folds). */
static const sk_schema_field evaluation_fields[] = {
    SK_SCHEMA_INT(sk_hand_evaluation_desc, folds, "folds", 2, 1000, .flags = SK_FIELD_ZERO,
                  .def_text = "5 (with groups: one fold per group)",
                  .doc = "contiguous blocks of samples held out in turn; with groups, at most "
                         "this many folds of whole groups"),
    SK_SCHEMA_INT(sk_hand_evaluation_desc, pca_components, "pca_components", 1, SK_HAND_DOF_COUNT,
                  .flags = SK_FIELD_ZERO, .def = 6, .doc = "k of the PCA prior baseline"),
    SK_SCHEMA_ENUM(sk_hand_evaluation_desc, weight_rule, "weight_rule", rule_names,
                   .def = SK_HAND_WEIGHT_THESIS,
                   .doc = "pair model: thesis (eq. 3.18) or inverse-variance"),
    SK_SCHEMA_DOUBLE(sk_hand_evaluation_desc, weight_scale, "weight_scale", 1e-6, 1e6,
                     .flags = SK_FIELD_ZERO, .def = 1,
                     .doc = "pair model: multiplies every weight"),
};
const sk_schema sk_hand_evaluation_schema =
    SK_SCHEMA_OF("evaluation", sk_hand_evaluation_desc, evaluation_fields);

static const sk_schema_field synthetic_fields[] = {
    SK_SCHEMA_INT(sk_hand_synthetic_desc, people, "people", 1, 100, .flags = SK_FIELD_ZERO,
                  .def = 6, .doc = "people in the data set"),
    SK_SCHEMA_INT(sk_hand_synthetic_desc, trials, "trials", 1, 100, .flags = SK_FIELD_ZERO,
                  .def = 2, .doc = "trials per person and grasp type"),
    SK_SCHEMA_INT(sk_hand_synthetic_desc, frames, "frames", 5, 1000, .flags = SK_FIELD_ZERO,
                  .def = 50, .doc = "frames per trial: reach, hold, release"),
    SK_SCHEMA_DOUBLE(sk_hand_synthetic_desc, noise_deg, "noise_deg", -1, 20, .def = 2,
                     .doc = "glove noise per sample in degrees (negative: none)"),
    SK_SCHEMA_SEED(sk_hand_synthetic_desc, seed, "seed", .doc = "random seed"),
};
const sk_schema sk_hand_synthetic_schema =
    SK_SCHEMA_OF("synthetic", sk_hand_synthetic_desc, synthetic_fields);
