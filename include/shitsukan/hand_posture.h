/* shitsukan hand: the skeleton of Yasumuro's thesis (2000, ch. 3) posed from few inputs
 * by the equilibrium of joint springs and a potential of natural joint coupling, with
 * calibration from measured angle pairs, lookup-table potentials, keyframe animation,
 * BVH / joint-position export (the pictures and plots: hand_pictures.h).
 *
 * Conventions (docs/hand.md has the table of every DOF):
 * - Units: millimetres and radians in the API; files say degrees where a key says so.
 * - Right-hand frames: X radial (toward the thumb), Y distal (along each link), Z palmar.
 *   Every joint rotates by 3-2-1 Euler angles (eq. 3.4): R = Rz(z) Ry(y) Rx(x).
 *   Flexion is the X angle and positive; abduction is a Z angle, positive away from the
 *   middle finger (each DOF's sign says how its value maps onto the Euler angle).
 * - A left hand is the exact mirror image of the right hand with the same DOF values,
 *   mirrored in the world plane x = 0 (so wrist.tx mirrors too).
 * - DOF values here are absolute joint angles theta*; the equilibrium works on the
 *   displacement from the relaxed posture theta = theta* - theta_bar (eq. 3.7).
 *
 * Thread-safety: skeletons, constraint sets and lookup tables are immutable after
 * creation and may be shared between threads; a solver (it caches factorisations)
 * belongs to one thread at a time. */
#ifndef SHITSUKAN_HAND_POSTURE_H
#define SHITSUKAN_HAND_POSTURE_H

#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>

#include "shitsukan/bvh.h"
#include "shitsukan/core.h"
#include "shitsukan/schema.h"

#ifdef __cplusplus
extern "C" {
#endif

/* -------------------------------------------------------------- DOF table */
/* 6 wrist DOF (translation + rotation of the carpus) + 29 joint DOF: thumb CMC 2, MCP 2,
 * IP 1; index..little CMC 2, MCP 2, PIP 1, DIP 1 (spec decision on Table 3.1). */
#define SK_HAND_DOF_COUNT 35
#define SK_HAND_WRIST_DOF_COUNT 6
/* Joint centres + fingertips: wrist, thumb CMC MCP IP tip, then for I, M, R, L:
 * CMC MCP PIP DIP tip. */
#define SK_HAND_POINT_COUNT 25
/* Rigid links: carpus, thumb metacarpal/proximal/distal, 4 x (metacarpal, proximal,
 * middle, distal). Each starts at its base joint (sk_hand_link_point). */
#define SK_HAND_LINK_COUNT 20

typedef enum sk_hand_finger {
    SK_HAND_THUMB = 0,
    SK_HAND_INDEX,
    SK_HAND_MIDDLE,
    SK_HAND_RING,
    SK_HAND_LITTLE,
    SK_HAND_FINGER_COUNT
} sk_hand_finger;

typedef enum sk_hand_side {
    SK_HAND_SIDE_DEFAULT = 0, /* = right */
    SK_HAND_SIDE_RIGHT,
    SK_HAND_SIDE_LEFT
} sk_hand_side;

typedef struct sk_hand_dof_info {
    const char *name;    /* e.g. "L.MCP.flex", "wrist.tx" */
    int link;            /* link whose base joint carries the DOF (0 = carpus) */
    char axis;           /* 'X', 'Y' or 'Z' of the link frame (translations: world axes) */
    int sign;            /* right hand: Euler angle (or translation) = sign * value */
    bool translation;    /* wrist.tx/ty/tz: millimetres; everything else radians */
    const char *meaning; /* one line: what a positive value does */
} sk_hand_dof_info;

/* Information on DOF 0..SK_HAND_DOF_COUNT-1 (NULL outside). */
const sk_hand_dof_info *sk_hand_dof(int dof);
/* Index of a DOF by name (exact, case-sensitive), or -1. */
int sk_hand_dof_find(const char *name);
/* Name of point 0..SK_HAND_POINT_COUNT-1 ("wrist", "T.CMC", ..., "L.tip"), NULL outside. */
const char *sk_hand_point_name(int point);
/* Parent point of a point (the joint at the base of its link), -1 for the wrist. */
int sk_hand_point_parent(int point);
/* Name of link 0..SK_HAND_LINK_COUNT-1 as used in BVH ("Hand", "T_CMC", ..., "L_DIP"),
 * named after its base joint. */
const char *sk_hand_link_name(int link);
/* Point at the base of a link (0 for the carpus) and the point at its far end (the next
 * joint or the fingertip; -1 for the carpus, which ends at five CMC joints). */
int sk_hand_link_point(int link);
int sk_hand_link_end_point(int link);

/* ----------------------------------------------------- anatomy (data file) */
/* Per-DOF data: limits, relaxed posture (theta_bar, eq. 3.7) and spring stiffness
 * (eq. 3.8). Angles in radians (translations in mm). */
typedef struct sk_hand_dof_data {
    double min, max;  /* anatomical limits of the absolute value */
    double relaxed;   /* theta_bar */
    double stiffness; /* k_i > 0; torque units per radian (per mm for translations) */
} sk_hand_dof_data;

/* Geometry as fractions of hand length (HL) and breadth (HB), after Buchholz et al.
 * 1992; the mount is the fixed orientation of each finger's CMC frame on the carpus. */
typedef struct sk_hand_finger_data {
    double cmc_x_hb, cmc_y_hl, cmc_z_hb; /* CMC centre from the wrist centre */
    double mc_dx_hb;      /* metacarpal: radial offset of the MCP from the CMC (x HB);
                             0 for the thumb */
    double mc_dy_hl;      /* metacarpal: distal offset of the MCP from the CMC (x HL);
                             for the thumb, the metacarpal length */
    double phalanx_hl[3]; /* proximal, middle, distal lengths (x HL); thumb: proximal,
                             distal, unused */
    /* Rest orientation of the CMC frame: R = Rz(splay) Rx(tilt) Ry(roll), radians.
       For I..L the splay follows the metacarpal direction (computed, must be 0 here). */
    double mount_tilt, mount_roll, thumb_splay;
} sk_hand_finger_data;

typedef struct sk_hand_anatomy {
    double hand_length_mm;  /* HL: wrist crease to the middle fingertip */
    double hand_breadth_mm; /* HB: across the metacarpal heads */
    sk_hand_finger_data finger[SK_HAND_FINGER_COUNT];
    sk_hand_dof_data dof[SK_HAND_DOF_COUNT];
} sk_hand_anatomy;

/* The built-in anatomy (the values of presets/hand/anatomy.json, with their sources). */
void sk_hand_anatomy_default(sk_hand_anatomy *out);
/* Reads an anatomy JSON file (format of presets/hand/anatomy.json): every key optional,
 * starting from the built-in values. Errors name the key path. */
sk_result sk_hand_anatomy_load_file(const char *path, sk_hand_anatomy *out, sk_error *err);
sk_result sk_hand_anatomy_parse(const char *text, size_t length, const char *source_name,
                                sk_hand_anatomy *out, sk_error *err);

/* --------------------------------------------------------------- skeleton */
typedef struct sk_hand_skeleton_desc {
    double hand_length_mm;          /* 0 = the anatomy's (190 mm); range [60, 400] */
    double hand_breadth_mm;         /* 0 = the anatomy's (85 mm); range [30, 200] */
    sk_hand_side side;              /* 0 = right */
    const sk_hand_anatomy *anatomy; /* NULL = sk_hand_anatomy_default() */
} sk_hand_skeleton_desc;

/* The link tree (3.1.1) with its fixed geometry, in right-hand coordinates. */
typedef struct sk_hand_skeleton {
    sk_hand_side side; /* resolved: RIGHT or LEFT */
    double hand_length_mm, hand_breadth_mm;
    sk_hand_dof_data dof[SK_HAND_DOF_COUNT];
    int parent[SK_HAND_LINK_COUNT];      /* parent link, -1 for the carpus */
    sk_vec3d offset[SK_HAND_LINK_COUNT]; /* r: parent joint -> this joint, parent frame */
    sk_mat3d mount[SK_HAND_LINK_COUNT];  /* fixed rotation before the joint's DOFs */
    double length[SK_HAND_LINK_COUNT];   /* joint -> next joint (tip) along +Y, mm */
} sk_hand_skeleton;

sk_hand_skeleton_desc sk_hand_skeleton_desc_resolved(const sk_hand_skeleton_desc *desc);
sk_result sk_hand_skeleton_init(sk_hand_skeleton *skeleton, const sk_hand_skeleton_desc *desc,
                                sk_error *err);
/* The relaxed posture theta_bar as absolute DOF values. */
void sk_hand_relaxed(const sk_hand_skeleton *skeleton, double dofs[SK_HAND_DOF_COUNT]);
/* Clamps every DOF into its limits; returns how many were changed. */
int sk_hand_clamp_to_limits(const sk_hand_skeleton *skeleton, double dofs[SK_HAND_DOF_COUNT]);

/* ---------------------------------------------------- forward kinematics */
/* Link frames and joint positions in world coordinates (eqs. 3.5, 3.6). */
typedef struct sk_hand_frames {
    sk_mat3d rotation[SK_HAND_LINK_COUNT]; /* link frame axes as columns */
    sk_vec3d point[SK_HAND_POINT_COUNT];   /* mm */
} sk_hand_frames;

/* 3-2-1 Euler rotation of eq. (3.4): Rz(z) Ry(y) Rx(x). */
sk_mat3d sk_hand_euler321(double x, double y, double z);
/* Inverse: angles (x, y, z) with R = Rz(z) Ry(y) Rx(x), y in [-pi/2, pi/2]. */
void sk_hand_euler321_from_matrix(sk_mat3d r, double *x, double *y, double *z);
/* Forward kinematics of absolute DOF values (not clamped). */
void sk_hand_forward(const sk_hand_skeleton *skeleton, const double dofs[SK_HAND_DOF_COUNT],
                     sk_hand_frames *out);

/* ------------------------------------------------------ constraint sets */
/* One row of A theta + b = 0 (eq. 3.13) with its weight (diagonal of W, eq. 3.14), on
 * displacements theta from the relaxed posture, in radians. */
/* enough for a row over every joint DOF (calibrated potentials, sk_hand_potential) */
#define SK_HAND_ROW_MAX_TERMS 32
typedef struct sk_hand_row {
    int term_count;
    int dof[SK_HAND_ROW_MAX_TERMS];
    double coeff[SK_HAND_ROW_MAX_TERMS];
    double b;      /* radians */
    double weight; /* w_k > 0 */
    char label[64];
} sk_hand_row;

#define SK_HAND_MAX_ROWS 256
typedef struct sk_hand_constraints {
    int row_count;
    sk_hand_row rows[SK_HAND_MAX_ROWS];
    bool has_stiffness[SK_HAND_DOF_COUNT]; /* stiffness overrides from the file */
    double stiffness[SK_HAND_DOF_COUNT];
} sk_hand_constraints;

/* Parses a constraint file (format: docs/hand.md, presets/hand/natural.json). The
 * skeleton gives the relaxed posture for rows written on absolute angles. Errors
 * (unknown DOF names, non-positive weights or stiffness, malformed JSON) name the key
 * path, e.g. "rows[2].pair: unknown DOF \"L.MPC.flex\"". */
sk_result sk_hand_constraints_parse(const char *text, size_t length, const char *source_name,
                                    const sk_hand_skeleton *skeleton, sk_hand_constraints *out,
                                    sk_error *err);
sk_result sk_hand_constraints_load_file(const char *path, const sk_hand_skeleton *skeleton,
                                        sk_hand_constraints *out, sk_error *err);
/* Appends a row y = slope * x + intercept between two DOFs (absolute angles when
 * `absolute`, otherwise displacements; radians). */
sk_result sk_hand_constraints_add_pair(sk_hand_constraints *c, const sk_hand_skeleton *skeleton,
                                       int dof_x, int dof_y, double slope, double intercept,
                                       double weight, bool absolute, sk_error *err);

/* ------------------------------------------------- lookup-table potentials */
/* Nonlinear potential of one DOF pair (3.2.3): squared distance (rad^2) from (x, y)
 * (absolute angles) to the nearest measured sample, tabulated on a grid with its x and
 * y gradients, bilinearly interpolated. */
typedef enum sk_hand_lut_interp {
    SK_HAND_LUT_INTERP_DEFAULT = 0, /* = HERMITE */
    SK_HAND_LUT_INTERP_HERMITE,     /* bicubic Hermite from the value and gradient tables
                                       (zero twist): C1, its gradient is the exact
                                       derivative of the interpolated potential and it
                                       reproduces the squared distance exactly where a
                                       cell's corners share their nearest sample, so the
                                       iterative solve reaches its tolerance */
    SK_HAND_LUT_INTERP_BILINEAR     /* value and gradient tables each bilinearly
                                       interpolated (the thesis's tables as they are):
                                       the gradient differs from the potential's slope by
                                       O(grid step), so the solve stops at a residual of
                                       about weight x grid step */
} sk_hand_lut_interp;

typedef struct sk_hand_lut_desc {
    int resolution;            /* grid nodes per axis; 0 = 100; range [8, 1024] */
    double margin;             /* grid extends this fraction of the sample range beyond it on
                                  every side; 0 = 0.25; range [0, 4] */
    double weight;             /* multiplies the potential; 0 = 1; range [1e-6, 1e6] */
    sk_hand_lut_interp interp; /* 0 = Hermite */
} sk_hand_lut_desc;

typedef struct sk_hand_lut {
    int dof_x, dof_y;
    int n;                   /* resolution */
    double x0, y0, h_x, h_y; /* node (i, j) at (x0 + i h_x, y0 + j h_y) */
    double weight;
    sk_hand_lut_interp interp; /* resolved */
    double *value;             /* n*n, node (i, j) at value[j * n + i] */
    double *grad_x, *grad_y;   /* exact gradient of the squared distance at the nodes */
} sk_hand_lut;

/* Builds the tables from `count` samples (xs[i], ys[i]) in radians. */
sk_result sk_hand_lut_build(sk_hand_lut *lut, int dof_x, int dof_y, const double *xs,
                            const double *ys, int count, const sk_hand_lut_desc *desc,
                            sk_error *err);
void sk_hand_lut_free(sk_hand_lut *lut);
/* Interpolated potential (times the weight) and its gradient (times the weight) at
 * absolute angles (x, y). Outside the grid the potential continues from the nearest
 * border point c with its slope and the squared distance d to the border:
 * V(c) + V_x dx + V_y dy + V_xy dx dy + |d|^2, whose gradient is returned (continuous
 * and consistent with the value for Hermite). */
double sk_hand_lut_eval(const sk_hand_lut *lut, double x, double y, double *gx, double *gy);

/* ------------------------------------------------------------- solver */
/* Inputs of one solve: directed torques tau_hat (eq. 3.9) and pinned DOFs. */
typedef struct sk_hand_input {
    double torque[SK_HAND_DOF_COUNT]; /* tau_hat; torque units = stiffness x radians */
    bool pinned[SK_HAND_DOF_COUNT];
    double pin_value[SK_HAND_DOF_COUNT]; /* absolute values of pinned DOFs (clamped into
                                            the limits) */
} sk_hand_input;

typedef struct sk_hand_solve_info {
    int active_set_iterations; /* solves of the linear system */
    int clamped_count;         /* DOFs held at a limit in the result */
    int pins_clamped;          /* pin values that were outside the limits */
    int newton_iterations;     /* iterative solve with lookup tables (0 without) */
    double residual;           /* max |gradient of the energy| over free DOFs not at a
                                  limit: (3.17) residual for linear sets */
    double energy;             /* 1/2 th'K th - tau'th + J (+ lookup potentials) */
    bool converged;
} sk_hand_solve_info;

typedef struct sk_hand_solver_desc {
    int max_newton_iterations; /* iterative solve with lookup tables; 0 = 500; [1, 10000] */
    double tolerance;          /* iterative solve stops when the residual (max |gradient|
                                  over free DOFs) is below; 0 = 1e-6; [1e-15, 1]. The
                                  linear solve is direct (residual ~1e-15). */
    int cache_size;            /* factorisations kept (by free set); 0 = 8; [1, 64] */
} sk_hand_solver_desc;

typedef struct sk_hand_solver sk_hand_solver;

/* The solver copies what it needs from the skeleton and constraints (stiffness from the
 * skeleton, overridden by the constraint file's). `luts` (may be NULL when lut_count is
 * 0) are referenced, not copied: they must outlive the solver. */
sk_result sk_hand_solver_create(sk_hand_solver **out, const sk_hand_skeleton *skeleton,
                                const sk_hand_constraints *constraints, const sk_hand_lut *luts,
                                int lut_count, const sk_hand_solver_desc *desc, sk_error *err);
void sk_hand_solver_destroy(sk_hand_solver *solver);
/* Changes one stiffness k_i (> 0) or one row weight (> 0): drops cached factorisations. */
sk_result sk_hand_solver_set_stiffness(sk_hand_solver *solver, int dof, double k, sk_error *err);
sk_result sk_hand_solver_set_weight(sk_hand_solver *solver, int row, double w, sk_error *err);
/* Solves the equilibrium (3.17) for the free DOFs with the pinned ones held, keeping
 * every DOF within its limits (active set). With lookup tables the equilibrium is
 * solved iteratively (damped Newton on the energy, the linear part exact). Writes
 * absolute DOF values. Fails with SK_ERROR_NUMERIC if the system is not positive
 * definite. `info` may be NULL. Allocation-free. */
sk_result sk_hand_solve(sk_hand_solver *solver, const sk_hand_input *input,
                        double dofs[SK_HAND_DOF_COUNT], sk_hand_solve_info *info, sk_error *err);
/* Matrix H = K + A'WA and vector g = -A'Wb (column-major n x n, n = SK_HAND_DOF_COUNT)
 * of the solver, for checks. */
const double *sk_hand_solver_matrix(const sk_hand_solver *solver);
const double *sk_hand_solver_rhs_constant(const sk_hand_solver *solver);

/* ----------------------------------------------------------- calibration */
typedef enum sk_hand_weight_rule {
    SK_HAND_WEIGHT_DEFAULT = 0,     /* = THESIS */
    SK_HAND_WEIGHT_THESIS,          /* eq. (3.18): w_k = mean l^2 / max_k(mean l^2) */
    SK_HAND_WEIGHT_INVERSE_VARIANCE /* w_k = min_k(mean l^2) / mean l^2 */
} sk_hand_weight_rule;

typedef struct sk_hand_fit {
    int dof_x, dof_y;
    double slope, intercept; /* y = slope x + intercept (absolute radians), least squares */
    double mean_sq_distance; /* mean of l_i^2, l_i = distance from the line (rad^2) */
    double weight;           /* by the chosen rule */
    int count;
} sk_hand_fit;

/* Fits one line per pair (3.2.2) from sample columns (radians). `columns[d]` is the
 * column of DOF d (NULL if absent); fits[k] gets pair k. */
sk_result sk_hand_calibrate(const double *const columns[SK_HAND_DOF_COUNT], int sample_count,
                            const int (*pairs)[2], int pair_count, sk_hand_weight_rule rule,
                            sk_hand_fit *fits, sk_error *err);
/* Writes fits as a constraint file (absolute angles, degrees). */
sk_result sk_hand_fits_write_json(const sk_hand_fit *fits, int count, sk_hand_weight_rule rule,
                                  const char *source_note, const char *path, sk_error *err);

/* Joint-angle samples from CSV: a header of DOF names, one sample per line, degrees
 * (translations mm). Errors name the line and the column. */
#define SK_HAND_SAMPLES_MAX_GROUPS 4096
typedef struct sk_hand_samples {
    int count;
    bool present[SK_HAND_DOF_COUNT];
    double *column[SK_HAND_DOF_COUNT]; /* radians / mm; NULL if absent */
    /* With a group column (the trial or person of each sample): */
    int group_count;        /* distinct values, numbered in order of appearance;
                               0 without a group column */
    int *group;             /* count entries; NULL without a group column */
    char (*group_name)[64]; /* group_count names */
    /* Unit check: the largest |angle| in the rotational columns (radians after
       conversion) and whether it suggests the wrong --units: degrees that all lie
       within +-pi (radians read as degrees), or radians beyond 2 pi. */
    double max_abs_angle;
    bool units_suspect;
} sk_hand_samples;

typedef enum sk_hand_angle_unit {
    SK_HAND_UNIT_DEFAULT = 0, /* = degrees */
    SK_HAND_UNIT_DEG,
    SK_HAND_UNIT_RAD
} sk_hand_angle_unit;

/* How a samples CSV is read. All zero: degrees, no group column, only "frame" and
 * "time" ignored besides the DOF columns. */
typedef struct sk_hand_samples_desc {
    sk_hand_angle_unit units;   /* of the rotational columns (translations are mm) */
    const char *group_column;   /* NULL = none; else a header name whose values (any text
                                   up to 63 characters) name the trial or person */
    const char *ignore_columns; /* NULL or comma-separated header names to skip (their
                                   values are not read) */
} sk_hand_samples_desc;

sk_result sk_hand_samples_parse(const char *text, size_t length, const char *source_name,
                                sk_hand_samples *out, sk_error *err);
sk_result sk_hand_samples_load_file(const char *path, sk_hand_samples *out, sk_error *err);
/* The same with a desc (NULL = defaults). An unknown header name that is neither a DOF
 * nor listed is an error naming it; a named group or ignored column must exist. */
sk_result sk_hand_samples_parse_desc(const char *text, size_t length, const char *source_name,
                                     const sk_hand_samples_desc *desc, sk_hand_samples *out,
                                     sk_error *err);
sk_result sk_hand_samples_read(const char *path, const sk_hand_samples_desc *desc,
                               sk_hand_samples *out, sk_error *err);
void sk_hand_samples_free(sk_hand_samples *samples);
/* "A:B,C:D" -> pairs of DOF indices (at most max_pairs). */
sk_result sk_hand_parse_pairs(const char *text, int (*pairs)[2], int max_pairs, int *count,
                              sk_error *err);

/* ----------------------------------------------- calibrated potential */
/* The whole quadratic potential of eq. 3.17 calibrated from samples (thesis 3.2.2 in
 * full): the relaxed posture theta_bar (eq. 3.7, step 2 of 3.2.2) is the samples' mean,
 * and K + A'WA is their precision matrix (times `scale`), split into springs K (eq. 3.8)
 * and coupling rows A, W (eq. 3.14) with b = 0, so the energy is the samples' Gaussian
 * and pinning joints gives the conditional mean of the others (kept within the joint
 * limits). A mixture of such Gaussians (one per grasp type) goes beyond linear: each
 * component is a full thesis-form set, and a solve blends the components' equilibria by
 * the probability of the pinned values under each. DOFs outside the samples keep the
 * base set's springs and the base rows among themselves. */
#define SK_HAND_POTENTIAL_MAX_COMPONENTS 16
#define SK_HAND_EVAL_MAX_PIN_SETS 16
#define SK_HAND_EVAL_MAX_PINS 8

/* A set of DOFs pinned together (the inputs of a prediction). */
typedef struct sk_hand_pin_set {
    int count;
    int dof[SK_HAND_EVAL_MAX_PINS];
} sk_hand_pin_set;

typedef enum sk_hand_potential_method {
    SK_HAND_POTENTIAL_DEFAULT = 0, /* = MIXTURE */
    SK_HAND_POTENTIAL_GAUSSIAN,    /* one Gaussian */
    SK_HAND_POTENTIAL_MIXTURE,     /* 1..max_components Gaussians, the count chosen by
                                      held-out likelihood (1 where more do not help) */
    SK_HAND_POTENTIAL_PAIRS        /* the thesis's form with pair rows (3.2.2): the relaxed
                                      posture from the samples, the base set's springs, and
                                      the pair rows and weight scale chosen on held-out
                                      samples (starting from the base set's rows, which
                                      are kept unless dropping them helps) */
} sk_hand_potential_method;

typedef struct sk_hand_potential_desc {
    sk_hand_potential_method method; /* 0 = mixture */
    int max_components;              /* mixture: 0 = 12; range [1, 16]; counts tried: 1, 2, 3, 4, 6,
                                        8, 12, 16 up to it */
    int components;        /* mixture: 0 = chosen on held-out samples; else fixed [1, 16] */
    double prior_strength; /* pseudo-samples of the base set's Gaussian that the mean and
                              covariance shrink toward; 0 = chosen by held-out
                              likelihood from 1, 4, 16, 64, 256; range [-1, 1e7] (a
                              negative value means none) */
    uint64_t seed;         /* mixture initialisation */
    const sk_hand_constraints *base; /* shrinkage target and the set kept on DOFs outside
                                        the samples; NULL = springs only */
    /* The pin patterns the held-out choices (prior strength, component count) are made
       for: pin these DOFs, predict the others. NULL = every calibrated DOF alone. */
    const sk_hand_pin_set *pin_sets;
    int pin_set_count; /* range [0, 16] */
    /* PAIRS: the candidate pairs X:Y (row y = A x + b, fitted on the samples' moments
       shrunk toward the base set's Gaussian); NULL = every ordered pair of calibrated DOFs */
    const int (*pairs)[2];
    int pair_count;                  /* range [0, 256] */
    sk_hand_weight_rule weight_rule; /* of the fitted rows; 0 = INVERSE_VARIANCE read in
                                        stiffness units (a row whose spread about its line
                                        is a spring's, 20 degrees, weighs 1); THESIS = eq.
                                        3.18 over the chosen rows */
    double weight_scale;             /* multiplies the fitted rows' weights; 0 = chosen on held-out
                                        samples from 1/4, 1/2, 1, ..., 64; range [1e-6, 1e6] */
    int max_pairs;                   /* fitted rows at most; 0 = 16; range [1, 64] */
} sk_hand_potential_desc;

typedef struct sk_hand_potential_component {
    double weight;                     /* mixing weight, sums to 1 over the components */
    double relaxed[SK_HAND_DOF_COUNT]; /* theta_bar (absolute radians; the skeleton's on
                                          DOFs outside the samples) */
    sk_hand_constraints constraints;   /* stiffness of every DOF (has_stiffness all true)
                                          and rows on displacements from `relaxed`, b = 0 */
} sk_hand_potential_component;

typedef struct sk_hand_potential {
    int dof_count; /* calibrated DOFs (joint angles present in the samples) */
    int dof[SK_HAND_DOF_COUNT];
    double scale;          /* K + A'WA = scale x precision (1/rad^2) on them, so
                              that torques keep the base set's units */
    int sample_count;      /* samples fitted */
    double prior_strength; /* resolved (pseudo-samples) */
    double weight_scale;   /* PAIRS: resolved scale of the fitted rows; else 0 */
    int pair_count;        /* PAIRS: fitted rows (in component 0, after the base
                              rows kept) */
    int component_count;
    sk_hand_potential_component *component; /* allocated */
} sk_hand_potential;

/* Fits the potential to samples idx[0..n) (all when idx is NULL) of `samples`: the
 * calibrated DOFs are the joint angles present (wrist DOFs excluded). Deterministic for
 * a seed and any thread count. Free with sk_hand_potential_free. */
sk_result sk_hand_potential_fit(sk_hand_potential *out, const sk_hand_skeleton *skeleton,
                                const sk_hand_samples *samples, const int *idx, int n,
                                const sk_hand_potential_desc *desc, sk_error *err);
void sk_hand_potential_free(sk_hand_potential *potential);
/* Mean and covariance (radians, over the calibrated DOFs in their order; d x d column-
 * major) of component m, from its springs and rows. */
sk_result sk_hand_potential_gaussian(const sk_hand_potential *potential, int m, double *mean,
                                     double *covariance, sk_error *err);
/* The potential as JSON (format in docs/hand.md) and back. The reader is strict: the
 * whole text must be one JSON value, no duplicate or unknown keys, every number finite
 * and in range, and every component's K + A'WA positive definite. */
sk_result sk_hand_potential_write_json(const sk_hand_potential *potential, const char *source_note,
                                       const char *path, sk_error *err);
sk_result sk_hand_potential_parse(const char *text, size_t length, const char *source_name,
                                  const sk_hand_skeleton *skeleton, sk_hand_potential *out,
                                  sk_error *err);
sk_result sk_hand_potential_load_file(const char *path, const sk_hand_skeleton *skeleton,
                                      sk_hand_potential *out, sk_error *err);

/* A solver for a potential: one equilibrium solver per component (same inputs), their
 * results blended by each component's probability of the pinned values (with a single
 * component, exactly sk_hand_solve on its set). Belongs to one thread at a time. */
typedef struct sk_hand_potential_solver sk_hand_potential_solver;
sk_result sk_hand_potential_solver_create(sk_hand_potential_solver **out,
                                          const sk_hand_skeleton *skeleton,
                                          const sk_hand_potential *potential,
                                          const sk_hand_solver_desc *desc, sk_error *err);
void sk_hand_potential_solver_destroy(sk_hand_potential_solver *solver);
/* `responsibility` (may be NULL) receives component_count probabilities. `info` is the
 * most probable component's, with `converged` false if any component's solve was not. */
sk_result sk_hand_potential_solve(sk_hand_potential_solver *solver, const sk_hand_input *input,
                                  double dofs[SK_HAND_DOF_COUNT], sk_hand_solve_info *info,
                                  double *responsibility, sk_error *err);

/* ------------------------------------------------ fingertip inverse kinematics */
/* A fingertip brought to a point through the equilibrium (beyond the thesis, whose GUI,
 * sec. 4.2.1, gives one joint an input at a time; the studio's fingertip drag): the
 * finger's three reach DOFs are pinned at the values whose equilibrium pose (eq. 3.17,
 * with the coupling of the set in use) puts the tip nearest the target. The pins are found
 * by damped Gauss-Newton (Levenberg-Marquardt) steps (J'J + lambda diag(J'J + 1)) dx = J'e
 * on the solved poses, e the target less the tip and J the tip's Jacobian in the three
 * pins by forward differences of whole solves; lambda = 0.01 after a step that brought
 * the tip nearer, ten times more after each that did not (that step taken back), so the
 * distance never grows. A step changes a pin by at most 0.2 rad, and the pins stay within
 * their DOFs' limits. The steps stop nearer than the tolerance, after the iterations (one
 * solve of the error each, three more for the Jacobian of a step kept), or where they no
 * longer move the pins; a target out of reach ends where the steps stop, nearest it.
 * Deterministic; allocation-free. */
typedef struct sk_hand_reach_desc {
    sk_hand_finger finger;
    sk_vec3d target;                            /* world frame, mm; finite */
    sk_hand_solver *solver;                     /* the equilibrium of the constraint set in
                                                   use, or: */
    sk_hand_potential_solver *potential_solver; /* a calibrated potential's (used when not
                                                   NULL) */
    int max_iterations;                         /* Gauss-Newton steps; 0 = 12; [0, 1000] */
    double tolerance_mm;                        /* 0 = 0.05; [0, 100] */
} sk_hand_reach_desc;

/* The DOFs that move a fingertip: its finger's first flexion, abduction and second
 * flexion (thumb: CMC flexion and abduction, MCP flexion); -1 each for a bad finger. */
void sk_hand_reach_dofs(sk_hand_finger finger, int dofs[3]);
/* The point of a finger's tip ("T.tip", "I.tip", ...), -1 for a bad finger. */
int sk_hand_fingertip_point(sk_hand_finger finger);
/* Reaches for desc->target from the inputs in use: `input` in (pins and torques), out
 * with the finger's reach DOFs pinned at the values found (the steps start from their
 * pins, or from `dofs` where they are not pinned); `dofs` out: the equilibrium of the
 * new inputs. `info` (may be NULL) gets that last solve's, `distance_mm` (may be NULL)
 * the distance left from the tip to the target. Errors, with `input` and `dofs`
 * unchanged: a finger out of range, a non-finite target, no solver, iterations or
 * tolerance out of range (SK_ERROR_INVALID_ARGUMENT), a failed solve. */
sk_result sk_hand_reach(const sk_hand_skeleton *skeleton, const sk_hand_reach_desc *desc,
                        sk_hand_input *input, double dofs[SK_HAND_DOF_COUNT],
                        sk_hand_solve_info *info, double *distance_mm, sk_error *err);

/* ------------------------------------------------------------- evaluation */
/* Held-out prediction of joint angles from pinned ones: per fold, the model is calibrated
 * on the other samples; every held-out sample's pins are set to its measured values and
 * the unpinned calibrated DOFs are compared with the measurement. Baselines fitted on the
 * same folds: the training mean, linear regression of the unpinned on the pinned DOFs
 * (least squares with intercept), and a PCA prior with k components (probabilistic PCA:
 * the top k principal directions plus isotropic noise of the mean discarded variance;
 * its conditional mean given the pins). */
typedef enum sk_hand_eval_model {
    SK_HAND_EVAL_MODEL_DEFAULT = 0, /* = CALIBRATED */
    SK_HAND_EVAL_MODEL_CALIBRATED,  /* sk_hand_potential_fit on each training fold */
    SK_HAND_EVAL_MODEL_FIXED,       /* a given constraint set, not refitted (the
                                       built-in relaxed posture) */
    SK_HAND_EVAL_MODEL_PAIRS,       /* the thesis's pair lines (3.2.2) fitted on each
                                       training fold, weights by `weight_rule` times
                                       `weight_scale`, added to the base set's springs */
    SK_HAND_EVAL_MODEL_LUT          /* lookup-table potentials (3.2.3) of `pairs` built
                                       from each training fold (`lut`), added to the
                                       base set (`potential.base`: springs and rows)
                                       around the built-in relaxed posture */
} sk_hand_eval_model;

typedef struct sk_hand_evaluation_desc {
    int folds;          /* contiguous blocks of samples; 0 = 5; range [2, 1000]; with
                           groups, at most this many folds of whole groups (groups
                           dealt round-robin in order of appearance), 0 = one fold per
                           group */
    bool by_group;      /* hold out whole groups (samples->group) */
    int pca_components; /* k; 0 = 6; range [1, calibrated DOFs] (clamped) */
    sk_hand_eval_model model;
    sk_hand_potential_desc potential; /* CALIBRATED */
    const sk_hand_constraints *fixed; /* FIXED (NULL = springs only) */
    const int (*pairs)[2];            /* PAIRS, LUT: at most 64 */
    int pair_count;
    sk_hand_lut_desc lut;              /* LUT */
    sk_hand_weight_rule weight_rule;   /* PAIRS */
    double weight_scale;               /* PAIRS: 0 = 1; range [1e-6, 1e6] */
    const sk_hand_solver_desc *solver; /* NULL = defaults */
    sk_progress progress;
} sk_hand_evaluation_desc;

typedef struct sk_hand_pin_result {
    sk_hand_pin_set pins;
    int joint_count; /* unpinned calibrated DOFs */
    int joint[SK_HAND_DOF_COUNT];
    /* RMS errors in radians, per joint and over all joints and samples */
    double model[SK_HAND_DOF_COUNT], mean[SK_HAND_DOF_COUNT], linear[SK_HAND_DOF_COUNT],
        pca[SK_HAND_DOF_COUNT];
    double model_all, mean_all, linear_all, pca_all;
    int solves, unconverged; /* model solves and those that did not converge
                                (their result is kept: the last iterate) */
    double max_residual;
} sk_hand_pin_result;

typedef struct sk_hand_evaluation {
    int sample_count, fold_count, dof_count, pca_k;
    double mean_components; /* CALIBRATED: mean over the folds */
    int pin_set_count;
    sk_hand_pin_result result[SK_HAND_EVAL_MAX_PIN_SETS];
} sk_hand_evaluation;

/* Runs the cross-validation; results are deterministic and the same for any thread
 * count. Errors: a pin that is not a calibrated DOF, fewer samples than folds, folds or
 * groups out of range. */
sk_result sk_hand_evaluate(const sk_hand_skeleton *skeleton, const sk_hand_samples *samples,
                           const sk_hand_pin_set *pin_sets, int pin_set_count,
                           const sk_hand_evaluation_desc *desc, sk_hand_evaluation *out,
                           sk_error *err);
/* "A,B" -> a pin set. */
sk_result sk_hand_parse_pin_set(const char *text, sk_hand_pin_set *out, sk_error *err);
/* The report: a list, one entry per pin set: {"pins": [...], "model_rms_deg": x,
 * "per_joint": {name: x, ...}, "baselines": {"mean": x, "linear": x,
 * "pca": {"k": k, "rms_deg": x}}, "solves": {"count": n, "not_converged": n,
 * "largest_residual": x}} (degrees). */
sk_result sk_hand_evaluation_write_json(const sk_hand_evaluation *eval, const char *path,
                                        sk_error *err);
/* The table: per pin set, every joint's RMS for the model and the baselines (degrees). */
void sk_hand_evaluation_print(const sk_hand_evaluation *eval, const char *model_name, FILE *out);

/* -------------------------------------------------- synthetic recordings */
/* A synthetic data set of glove-like recordings of the 12 finger flexion DOFs (index to
 * little: MCP, PIP, DIP), made to stand in for real recordings where none can be shipped:
 * several people each grasp ten object types (power, precision, hook, pointing, flat,
 * fist, ...) in a few trials of reach, hold and release. Per grasp type an aperture varies
 * the PIPs of all fingers together and each MCP partly with its neighbour (neighbouring
 * PIPs strongly coupled, neighbouring MCPs moderately, MCP and PIP of one finger weakly);
 * on the way to an object the hand opens beyond the grasp (pre-shaping); the DIP follows
 * its PIP along a curve (no
 * DIP flexion below about 20 degrees of PIP), with a person's own gain; people differ in
 * their relaxed posture and range; glove noise of about 2 degrees per sample and a
 * calibration offset per trial; angles stay within the joint limits. CSV columns:
 * person, trial, frame, then the 12 DOFs in degrees; comment lines (#) say how it was
 * made. Deterministic for a seed. */
typedef struct sk_hand_synthetic_desc {
    int people;       /* 0 = 6; range [1, 100] */
    int trials;       /* trials per person and grasp type; 0 = 2; range [1, 100] */
    int frames;       /* frames per trial; 0 = 50; range [5, 1000] */
    double noise_deg; /* glove noise per sample; 0 = 2; [-1, 20], negative = none */
    uint64_t seed;
} sk_hand_synthetic_desc;

/* The CSV text (NUL-terminated, free with free()). */
sk_result sk_hand_synthetic_grasps_csv(const sk_hand_synthetic_desc *desc, char **text,
                                       size_t *length, sk_error *err);
/* The same written to a file (atomically). */
sk_result sk_hand_synthetic_grasps_write(const sk_hand_synthetic_desc *desc, const char *path,
                                         sk_error *err);

/* -------------------------------------------------------------- animation */
typedef enum sk_hand_interp {
    SK_HAND_INTERP_DEFAULT = 0, /* = BEZIER */
    SK_HAND_INTERP_BEZIER,      /* cubic Bezier per segment, handles flat at the keys */
    SK_HAND_INTERP_CATMULL_ROM  /* uniform Catmull-Rom through the keys */
} sk_hand_interp;

#define SK_HAND_MAX_KEYS 256
/* One key: partial inputs (pins and torques on some DOFs). */
typedef struct sk_hand_key {
    bool has_pin[SK_HAND_DOF_COUNT];
    double pin[SK_HAND_DOF_COUNT]; /* absolute, radians / mm */
    bool has_torque[SK_HAND_DOF_COUNT];
    double torque[SK_HAND_DOF_COUNT];
} sk_hand_key;

typedef struct sk_hand_animation {
    char constraints[256]; /* "natural", "yasumuro-table-3.2" or a file path */
    sk_hand_side side;
    double hand_length_mm, hand_breadth_mm; /* 0 = defaults */
    sk_hand_interp interp;
    int steps;  /* frames from one key to the next; default 30 */
    double fps; /* default 30 */
    int key_count;
    sk_hand_key keys[SK_HAND_MAX_KEYS];
} sk_hand_animation;

/* Parses an animation file (presets/hand/little-mcp.json is an example). */
sk_result sk_hand_animation_parse(const char *text, size_t length, const char *source_name,
                                  sk_hand_animation *out, sk_error *err);
sk_result sk_hand_animation_load_file(const char *path, sk_hand_animation *out, sk_error *err);
/* Frames: (key_count - 1) * steps + 1. */
int sk_hand_animation_frame_count(const sk_hand_animation *anim);
/* Interpolated inputs at frame f: each pin or torque channel is its own curve through
 * the keys that set it, held before its first and after its last key. */
void sk_hand_animation_input(const sk_hand_animation *anim, int frame, sk_hand_input *out);
/* Scalar interpolation used above, exposed for tests: value at parameter t in [0, 1]
 * of the segment (p1, p2) with neighbours p0, p3. */
double sk_hand_interpolate(sk_hand_interp interp, double p0, double p1, double p2, double p3,
                           double t);

/* ---------------------------------------------------------------- export */
/* BVH: hierarchy with OFFSETs in millimetres in the rest pose (all DOFs zero), the root
 * "Hand" with 6 channels (X/Y/Z position, then Zrotation Yrotation Xrotation), every
 * other joint 3 channels in the model's order Zrotation Yrotation Xrotation (degrees),
 * rotations relative to the rest pose. `dofs` holds frame_count x SK_HAND_DOF_COUNT. */
sk_result sk_hand_bvh_write(const sk_hand_skeleton *skeleton, const double *dofs, int frame_count,
                            double frame_time, const char *path, sk_error *err);
sk_result sk_hand_bvh_write_stream(const sk_hand_skeleton *skeleton, const double *dofs,
                                   int frame_count, double frame_time, FILE *out);

/* BVH files are read (and written) by the general functions of include/shitsukan/bvh.h. */
/* Name in a BVH written by sk_hand_bvh_write of each hand point ("Hand", "T_CMC", ...,
 * "L_DIP", "L_DIP_end" for the tip). */
const char *sk_hand_point_bvh_name(int point);

/* Joint positions of frames (frame_count x SK_HAND_DOF_COUNT dofs) as CSV
 * ("frame,point,x_mm,y_mm,z_mm") or JSON ({"points": [...names], "frames": [[[x,y,z],..]]}). */
typedef enum sk_hand_positions_format {
    SK_HAND_POSITIONS_DEFAULT = 0, /* = CSV */
    SK_HAND_POSITIONS_CSV,
    SK_HAND_POSITIONS_JSON
} sk_hand_positions_format;
sk_result sk_hand_positions_write(const sk_hand_skeleton *skeleton, const double *dofs,
                                  int frame_count, sk_hand_positions_format format,
                                  const char *path, sk_error *err);
/* Joint angles of frames as CSV: "frame,time_s,<DOF names...>", degrees (mm for the
 * wrist translations); the data of joint-angle plots. */
sk_result sk_hand_angles_write_csv(const double *dofs, int frame_count, double frame_time,
                                   const char *path, sk_error *err);
/* A pose as JSON: {"side": ..., "dofs_deg": {name: value...}, "points_mm": {...}}. */
sk_result sk_hand_pose_write_json(const sk_hand_skeleton *skeleton,
                                  const double dofs[SK_HAND_DOF_COUNT],
                                  const sk_hand_solve_info *info, const char *path, sk_error *err);

/* DOFs that an animation drives: pinned, or given a non-zero torque, in some key. */
void sk_hand_animation_driven(const sk_hand_animation *anim, bool driven[SK_HAND_DOF_COUNT]);

/* ------------------------------------------------------------- schemas */
/* Preset schemas of the descs above (keys, ranges and defaults, stated once; the checks
 * read them): sk_hand_skeleton_desc, sk_hand_lut_desc, sk_hand_solver_desc, the scalar keys
 * of sk_hand_potential_desc and sk_hand_evaluation_desc, sk_hand_synthetic_desc. */
extern const sk_schema sk_hand_skeleton_schema, sk_hand_lut_schema, sk_hand_solver_schema,
    sk_hand_potential_schema, sk_hand_evaluation_schema, sk_hand_synthetic_schema;

#ifdef __cplusplus
}
#endif

#endif /* SHITSUKAN_HAND_POSTURE_H */
