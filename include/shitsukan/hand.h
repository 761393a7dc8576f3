/* shitsukan hand: the skeleton of Yasumuro's thesis (2000, ch. 3) posed from few inputs
 * by the equilibrium of joint springs and a potential of natural joint coupling, with
 * calibration from measured angle pairs, lookup-table potentials, keyframe animation,
 * BVH / joint-position export, and stick-figure pictures and joint-angle plots.
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
 * belongs to one thread at a time. The picture and plot functions keep no state and are
 * thread-safe. */
#ifndef SHITSUKAN_HAND_H
#define SHITSUKAN_HAND_H

#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>

#include "shitsukan/bvh.h"
#include "shitsukan/core.h"
#include "shitsukan/draw.h"
#include "shitsukan/gltf.h"
#include "shitsukan/image.h"
#include "shitsukan/mesh.h"
#include "shitsukan/skin.h"

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
    double weight;             /* multiplies the potential; 0 = 1; range (0, 1e6] */
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
                              likelihood from 1, 4, 16, 64, 256; range [0, 1e7] (a
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
                                        samples from 1/4, 1/2, 1, ..., 64; range [0, 1e6] */
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
    double weight_scale;               /* PAIRS: 0 = 1; range (0, 1e6] */
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
/* Bar chart of the same: one panel per pin set, bars per joint and overall. `plot` may
 * be NULL (width 0 = 900, panel height 0 = 300; title used if set). */
sk_result sk_hand_plot_evaluation(const sk_hand_evaluation *eval, const char *model_name,
                                  const sk_plot_desc *plot, sk_image *out, sk_error *err);

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
    double noise_deg; /* glove noise per sample; 0 = 2; range [0, 20] (negative = 0) */
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

/* ---------------------------------------------------------------- pictures */
/* Stick figures of posed skeletons: bones as anti-aliased lines, joints as discs, one
 * colour per finger, the palm as a translucent plate, the end of the (fixed) forearm
 * below the wrist, direction arrows and a scale bar. Orthographic views along the world
 * axes; with the wrist rotations at zero they are the anatomical views named below. */
typedef enum sk_hand_view {
    SK_HAND_VIEW_DEFAULT = 0, /* in a view list: dorsal for the first view, radial for
                                 the second, palmar, ulnar */
    SK_HAND_VIEW_DORSAL,      /* from the back of the hand (camera on world -Z), fingers
                                 up: a right hand's thumb is on the left */
    SK_HAND_VIEW_PALMAR,      /* from the palm side (camera on +Z), fingers up */
    SK_HAND_VIEW_RADIAL,      /* from the thumb side (camera on +X for a right hand, -X
                                 for a left one), fingers up: a right hand's palm faces
                                 left, so flexion curls the fingers to the left */
    SK_HAND_VIEW_ULNAR        /* from the little-finger side, fingers up */
} sk_hand_view;

#define SK_HAND_DRAW_MAX_VIEWS 4

typedef enum sk_hand_framing {
    SK_HAND_FRAMING_DEFAULT = 0, /* = REACH */
    SK_HAND_FRAMING_REACH,       /* the window holds every pose of the skeleton's reach
                                    (flat, relaxed, fist, full extension, spread) as well
                                    as the given poses: one scale and placement for all
                                    poses of a hand, so animation frames and separate
                                    pictures line up */
    SK_HAND_FRAMING_TIGHT        /* the window fits the given poses only */
} sk_hand_framing;

typedef struct sk_hand_draw_desc {
    int width, height;                          /* whole picture in pixels; 0 = 400 per view x 480;
                                                   range 0 or 64..8192 */
    int view_count;                             /* side-by-side panels; 0 = 2; range 0..4 */
    sk_hand_view views[SK_HAND_DRAW_MAX_VIEWS]; /* DEFAULT entries: see sk_hand_view */
    sk_hand_framing framing;                    /* 0 = REACH */
    int text_scale;         /* bitmap-font scale of titles and labels; 0 = 2 if the
                               picture is at least 400 pixels high, else 1; range 0..8 */
    const char *caption;    /* NULL or "" = none; a line under the panels (e.g. the
                               driven DOFs and their values), wrapped onto two lines at
                               ", " when too wide, shrunk or cut if still too wide */
    bool label_points;      /* write every joint's name beside it ("I.MCP", ...) */
    bool hide_panel_titles; /* false = each panel's view name above it */
    bool hide_cues;         /* false = forearm end, direction arrows and scale bar */
} sk_hand_draw_desc;

/* Where a panel shows the world: a world point p lands at pixel
 *   (origin_x + s * dot(p, right), origin_y - s * dot(p, up)), s = pixels_per_mm,
 * and dot(p, toward) is its nearness to the viewer: drawing goes far to near, and parts
 * farther than the wrist fade toward the background (a depth cue). */
typedef struct sk_hand_panel {
    sk_hand_view view;
    int x0, y0, width, height;  /* the panel's rectangle in the picture */
    sk_vec3d right, up, toward; /* world unit vectors of screen right, screen up and
                                   toward the viewer (right = up x toward) */
    double origin_x, origin_y;  /* pixel position of the world origin */
} sk_hand_panel;

typedef struct sk_hand_draw_layout {
    int width, height, text_scale;
    int view_count;
    sk_hand_panel panel[SK_HAND_DRAW_MAX_VIEWS];
    double pixels_per_mm; /* the same in every panel */
} sk_hand_draw_layout;

/* The desc with zero fields replaced by their defaults. */
sk_hand_draw_desc sk_hand_draw_desc_resolved(const sk_hand_draw_desc *desc);
/* Frames `pose_count` poses (pose_count x SK_HAND_DOF_COUNT absolute DOF values) in
 * every panel at one common scale. Fit once over all frames of an animation and draw
 * each frame with the result so the frames line up. Errors name the desc field and its
 * range. `desc` may be NULL. */
sk_result sk_hand_draw_layout_fit(const sk_hand_skeleton *skeleton, const double *poses,
                                  int pose_count, const sk_hand_draw_desc *desc,
                                  sk_hand_draw_layout *layout, sk_error *err);
/* Pixel position of a world point in panel `view_index` of a layout. */
sk_vec2d sk_hand_draw_project(const sk_hand_draw_layout *layout, int view_index, sk_vec3d p);
/* Draws one pose into a newly allocated RGB image of the layout's size (free with
 * sk_image_free). `layout` NULL = fitted to this pose alone (with `desc`'s framing); a
 * layout must come from sk_hand_draw_layout_fit with the same desc (a caption, titles and
 * cues change the bands it leaves). Errors: a non-finite DOF value, a bad desc. */
sk_result sk_hand_draw(const sk_hand_skeleton *skeleton, const double dofs[SK_HAND_DOF_COUNT],
                       const sk_hand_draw_desc *desc, const sk_hand_draw_layout *layout,
                       sk_image *out, sk_error *err);
/* The colour of each finger's bones and joints in these pictures (linear RGB). */
sk_color sk_hand_finger_color(sk_hand_finger finger);

/* Draws every frame (frame_count x SK_HAND_DOF_COUNT) with one layout fitted over all of
 * them and writes "<dir>/frame_0000.png", ... (at least 4 digits; `dir` is created).
 * `captions` (NULL, or one string per frame, each may be NULL) replace desc->caption.
 * Frames are drawn in parallel; each file is written atomically. */
sk_result sk_hand_frames_write_png(const sk_hand_skeleton *skeleton, const double *dofs,
                                   int frame_count, const sk_hand_draw_desc *desc,
                                   const char *const *captions, const char *dir,
                                   sk_progress progress, sk_error *err);

/* Joint-angle plot: the angle of each listed DOF over the frames (degrees; mm for
 * translations), one line per DOF with its name in the legend. DOFs marked in `driven`
 * (may be NULL) are drawn thicker and labelled "(driven)". `plot` may be NULL (800 x 500,
 * "frame" and "angle (deg)" axis labels); its size, labels, title and ranges are used if
 * set. With an automatic y range and legend, when every corner of the plot would put the
 * legend over a line, the y range grows upward to leave it room above the data. */
sk_result sk_hand_plot_angles(const double *dofs, int frame_count, const int *dof_list,
                              int dof_count, const bool driven[SK_HAND_DOF_COUNT],
                              const sk_plot_desc *plot, sk_image *out, sk_error *err);
/* The DOFs of an animation worth plotting: the driven ones first (in DOF order), then the
 * others whose range over the frames is at least `min_range` (radians), largest range
 * first, at most `max_count` in all. Returns the count written to `out`. */
int sk_hand_moving_dofs(const double *dofs, int frame_count, const bool driven[SK_HAND_DOF_COUNT],
                        double min_range, int *out, int max_count);
/* DOFs that an animation drives: pinned, or given a non-zero torque, in some key. */
void sk_hand_animation_driven(const sk_hand_animation *anim, bool driven[SK_HAND_DOF_COUNT]);

/* ============================================================== hand surface */
/* The skin surface of thesis 4.1 built from the skeleton (no scan ships with the
 * thesis): flesh around every link (finger segments, the palm over the metacarpals,
 * thenar and hypothenar pads, webs, the wrist stump, nail plates) with sizes from
 * published anthropometry (presets/hand/flesh.json), blended into one implicit surface
 * and meshed in the relaxed posture into a single closed, manifold triangle mesh; skin
 * weights (the thesis's nearest link, and smooth weights); deformation by rigid links
 * (4.1.5), linear blend or dual quaternion skinning; levels of detail; exports.
 *
 * Thread-safety: a created surface is immutable; every function taking a const surface
 * may run from several threads at once. */
#include "shitsukan/mesh.h"

/* Sizes of the flesh in millimetres at the reference hand breadth; widths and
 * thicknesses scale with the skeleton's hand breadth / reference_breadth_mm. */
typedef struct sk_hand_flesh_finger {
    /* Stations along the finger: MCP, PIP, DIP, tip for I..L; MCP, IP, tip (index 0..2)
       for the thumb. Breadth across the palm plane (link X), thickness dorsal-palmar
       (link Z). */
    double breadth_mm[4];
    double thickness_mm[4];
    /* The palm around this finger's metacarpal, at its CMC and MCP ends (thumb: the
       metacarpal inside the thenar). */
    double metacarpal_breadth_mm[2];
    double metacarpal_thickness_mm[2];
} sk_hand_flesh_finger;

/* An ellipsoidal pad in the carpus frame: centre as fractions of hand breadth (x) and
 * length (y) plus mm palmar (z), semi-axes in mm, long axis turned in the palm plane. */
typedef struct sk_hand_flesh_pad {
    double centre_x_hb, centre_y_hl, centre_z_mm;
    double radius_mm[3];
    double angle_deg;
} sk_hand_flesh_pad;

typedef struct sk_hand_flesh {
    double reference_breadth_mm; /* hand breadth of the sizes below (85) */
    sk_hand_flesh_finger finger[SK_HAND_FINGER_COUNT];
    double palm_palmar_shift_mm;                 /* palm flesh centre palmar of the metacarpals */
    double wrist_breadth_mm, wrist_thickness_mm; /* at the wrist crease */
    double stump_length_mm;                      /* forearm kept below the wrist */
    sk_hand_flesh_pad thenar, hypothenar;
    double web_reach; /* webs reach this fraction of the proximal phalanx */
    double web_thickness_mm;
    double thumb_web_thickness_mm;
    double nail_length, nail_breadth; /* fractions of the distal segment / its breadth */
    double nail_thickness_mm;
    double blend_joint_mm, blend_root_mm, blend_palm_mm; /* smooth-union radii */
} sk_hand_flesh;

/* The built-in flesh (the values of presets/hand/flesh.json). */
void sk_hand_flesh_default(sk_hand_flesh *out);
/* Reads a flesh JSON file (format of presets/hand/flesh.json): every key optional,
 * starting from the built-in values. Errors name the key path. */
sk_result sk_hand_flesh_parse(const char *text, size_t length, const char *source_name,
                              sk_hand_flesh *out, sk_error *err);
sk_result sk_hand_flesh_load_file(const char *path, sk_hand_flesh *out, sk_error *err);

typedef struct sk_hand_surface_desc {
    int triangles;              /* target triangle count; 0 = 8000 (the thesis's count);
                                   range [500, 200000] */
    double cell_mm;             /* grid step of the implicit surface's meshing; 0 = chosen
                                   from the hand size and the triangle count; [0.2, 4] */
    const sk_hand_flesh *flesh; /* NULL = sk_hand_flesh_default() */
} sk_hand_surface_desc;

typedef struct sk_hand_surface sk_hand_surface;

/* Builds the flesh around the skeleton in its relaxed posture and meshes it. A left
 * skeleton gives the exact mirror of the right hand's mesh, vertex for vertex (the same
 * vertex order, positions and normals with x negated, triangles wound the other way). */
sk_result sk_hand_surface_create(sk_hand_surface **out, const sk_hand_skeleton *skeleton,
                                 const sk_hand_surface_desc *desc, sk_error *err);
void sk_hand_surface_destroy(sk_hand_surface *surface);
/* The memory sk_hand_surface_create peaks at for the skeleton and desc (bytes; desc may be
 * NULL): the meshing grid's cells near the surface dominate, so it grows with the hand's
 * length x breadth over the grid step squared (measured: 29 MB for the default 8000
 * triangles, 500 MB for 200000). For callers that cap their memory. */
double sk_hand_surface_memory(const sk_hand_skeleton *skeleton, const sk_hand_surface_desc *desc);

/* The closed, manifold mesh in the relaxed posture (positions in mm, unit normals; no
 * UVs: the atlas splits vertices along its seam, see sk_hand_surface_export_mesh), with
 * the attribute "nail" (1 on the nail plates, 0 elsewhere). Owned by the surface. */
const sk_mesh *sk_hand_surface_mesh(const sk_hand_surface *surface);
/* The skeleton it was built on (its relaxed frames are the bind pose). */
const sk_hand_skeleton *sk_hand_surface_skeleton(const sk_hand_surface *surface);

/* The implicit surface in the relaxed posture: negative inside, positive outside, about
 * the signed distance in mm near the surface (exact for a single round segment). */
double sk_hand_surface_field(const sk_hand_surface *surface, sk_vec3d p);
/* Gradient of the field (finite differences of 1e-3 mm). */
sk_vec3d sk_hand_surface_field_gradient(const sk_hand_surface *surface, sk_vec3d p);
/* Signed distance to the implicit surface (negative inside): the point is projected
 * onto the zero set by Newton steps along the gradient; `closest` (may be NULL) gets the
 * surface point. Accurate to about 1e-4 mm within a few mm of the surface. */
double sk_hand_surface_distance(const sk_hand_surface *surface, sk_vec3d p, sk_vec3d *closest);

/* ----------------------------------------------------------- skin weights */
typedef enum sk_hand_weights {
    SK_HAND_WEIGHTS_DEFAULT = 0, /* = SMOOTH */
    SK_HAND_WEIGHTS_NEAREST,     /* the thesis (4.1.5): every vertex on its nearest link */
    SK_HAND_WEIGHTS_SMOOTH       /* falling off along and around the links near joints: at
                                    most 4 links per vertex, summing to 1 */
} sk_hand_weights;

/* 4 links and 4 weights per vertex (vertex_count x 4 each; unused slots have weight 0
 * and link 0; the weights of a vertex sum to 1, largest first). Owned by the surface. */
void sk_hand_surface_weights(const sk_hand_surface *surface, sk_hand_weights which,
                             const uint16_t **links, const float **weights);

/* ------------------------------------------------------------- deformation */
typedef enum sk_hand_skinning {
    SK_HAND_SKINNING_DEFAULT = 0, /* = DQS */
    SK_HAND_SKINNING_RIGID,       /* the thesis: each vertex moves rigidly with its
                                     nearest link */
    SK_HAND_SKINNING_LBS,         /* linear blend of the link transforms, smooth weights */
    SK_HAND_SKINNING_DQS          /* dual quaternion blend (Kavan et al. 2008), smooth
                                     weights: no candy-wrapper collapse under twist */
} sk_hand_skinning;

/* Moves the mesh with posed frames (from sk_hand_forward on the surface's skeleton):
 * writes vertex_count x 3 positions and unit normals (the rest normals turned by each
 * vertex's blended rotation). Allocation-free; one thread below 20000 vertices. */
void sk_hand_surface_deform(const sk_hand_surface *surface, const sk_hand_frames *frames,
                            sk_hand_skinning method, float *positions, float *normals);
/* A posed copy of the mesh (allocated into `out`, free with sk_mesh_free). */
sk_result sk_hand_surface_pose(const sk_hand_surface *surface, const double dofs[SK_HAND_DOF_COUNT],
                               sk_hand_skinning method, sk_mesh *out, sk_error *err);

/* The thesis's defect (4.1.5): on the flexion side the surface sinks into the finger. */
typedef struct sk_hand_defect {
    double rest_volume_mm3, posed_volume_mm3;
    double volume_lost_mm3;     /* rest - posed (signed: negative = volume gained) */
    double volume_lost_percent; /* of the rest volume of the moved links' flesh */
    int inside_count;           /* vertices of a moved link's flesh that end up more than
                                   0.5 mm inside the neighbouring segment's flesh */
    double max_depth_mm;        /* deepest of them */
    int vertex_count;           /* vertices of the moved links (the denominator) */
} sk_hand_defect;
/* Measures the defect of a pose against the relaxed mesh for the links of `finger`. */
sk_result sk_hand_surface_defect(const sk_hand_surface *surface,
                                 const double dofs[SK_HAND_DOF_COUNT], sk_hand_skinning method,
                                 sk_hand_finger finger, sk_hand_defect *out, sk_error *err);

/* ------------------------------------------------------------- levels of detail */
#define SK_HAND_LOD_COUNT 3
/* Triangle targets of the levels: 8000 (level 0, the surface itself), 2000, 500. */
extern const int sk_hand_lod_triangles[SK_HAND_LOD_COUNT];
/* A coarser surface simplified from `base` by meshoptimizer (edge collapses onto its own
 * vertices, so the skin weights carry over unchanged), keeping the field and skeleton. */
sk_result sk_hand_surface_simplify(sk_hand_surface **out, const sk_hand_surface *base,
                                   int target_triangles, sk_error *err);

/* ------------------------------------------------------------- atlas and export */
/* The mesh as renderers and exporters take it: UVs of a two-chart atlas (the back of
 * the hand by planar projection on the left half, seen from the back; the palm on the
 * right half, seen from the palm side, as the thesis maps its photos, 4.1.6), so the
 * vertices along the seam between the charts are split in two. `positions` / `normals`
 * (vertex_count x 3 of the surface mesh, e.g. from sk_hand_surface_deform) or NULL for
 * the relaxed mesh. Adds the attributes "nail" and, if `with_weights`, "joints" and
 * "weights" (4 components each, smooth weights). */
sk_result sk_hand_surface_export_mesh(const sk_hand_surface *surface, const float *positions,
                                      const float *normals, bool with_weights, sk_mesh *out,
                                      sk_error *err);
/* Vertex of the surface mesh behind each export vertex (export vertex count entries). */
const uint32_t *sk_hand_surface_export_map(const sk_hand_surface *surface, size_t *count);

/* ------------------------------------------------------------- glTF export */
/* The skinned hand as glTF 2.0 (include/shitsukan/gltf.h): the skeleton as 20 joint
 * nodes in the link tree, named as the BVH export names them ("Hand", "T_CMC", ...,
 * "L_DIP"), one skin whose inverse bind matrices are the relaxed (bind) pose, one skinned
 * mesh node per level of detail ("hand_LOD0", ...) with JOINTS_0 / WEIGHTS_0, the atlas
 * UVs and the skin material, and optionally the frames as an animation (every joint's
 * rotation and the root's translation, one key per frame at frame / fps seconds, LINEAR).
 *
 * Units and axes: glTF's metres; the hand's frame is kept (X radial, Y distal = glTF's
 * up, Z palmar = glTF's front), so a glTF coordinate is the hand's millimetres / 1000.
 * A joint node's translation is its joint centre in its parent link's frame, its rotation
 * the link frame in the parent's (R_parent^T R_link); the root's are the carpus frame and
 * the wrist centre in the world. */
typedef enum sk_hand_gltf_material {
    SK_HAND_GLTF_MATERIAL_DEFAULT = 0, /* = BLEND */
    SK_HAND_GLTF_MATERIAL_BLEND,       /* the thesis's blend (4.1.6): a white surface lit at
                                          1 - w (base colour, with the normal map) plus the
                                          unlit albedo at w (emissive) */
    SK_HAND_GLTF_MATERIAL_PBR          /* the albedo as base colour, lit (engines' usual
                                          material), with the normal map */
} sk_hand_gltf_material;

typedef struct sk_hand_gltf_desc {
    /* Levels of detail, finest first, all built on one skeleton (a surface and its
       sk_hand_surface_simplify results); each is a mesh node sharing the one skin. */
    const sk_hand_surface *const *lods;
    int lod_count;              /* [1, 8] */
    const double *dofs;         /* frame_count x SK_HAND_DOF_COUNT absolute DOF values */
    int frame_count;            /* [1, 1000000]; more than 1 needs `animation` */
    bool animation;             /* write the frames as an animation (the nodes then stand
                                   in the bind pose); false: the nodes stand in the one
                                   pose given */
    double fps;                 /* key rate of the animation; 0 = 30; (0, 1000] */
    sk_hand_weights weights;    /* 0 = smooth; NEAREST gives every vertex one joint (the
                                   thesis's rigid links) */
    const sk_image *albedo;     /* the atlas's albedo (sk_hand_texture_bake); NULL = a
                                   plain skin colour and no UVs */
    const sk_image *normal_map; /* its normal map; NULL = none (needs albedo) */
    sk_hand_gltf_material material;
    double texture_weight; /* w of the blend; 0 = 0.7 (the thesis's 0.3 : 0.7);
                              [0, 1] */
} sk_hand_gltf_desc;

/* Adds the hand to a document (nodes, skin, meshes, material, animation). Errors name the
 * desc field and its range; nothing is added on an error of the desc. */
sk_result sk_hand_gltf_add(sk_gltf *gltf, const sk_hand_gltf_desc *desc, sk_error *err);
/* The hand alone as one .glb file (atomically written). */
sk_result sk_hand_gltf_write(const sk_hand_gltf_desc *desc, const char *path, sk_error *err);

/* ------------------------------------------------------------- poses, landmarks */
/* Reads a pose file: {"dofs": {"L.MCP.flex": 60, ...}} in degrees (mm for wrist.tx/ty/tz),
 * the format sk_hand_pose_write_json writes (its other keys are accepted); DOFs not given
 * keep their relaxed values. Errors name the key path. */
sk_result sk_hand_pose_parse(const char *text, size_t length, const char *source_name,
                             const sk_hand_skeleton *skeleton, double dofs[SK_HAND_DOF_COUNT],
                             sk_error *err);
sk_result sk_hand_pose_load_file(const char *path, const sk_hand_skeleton *skeleton,
                                 double dofs[SK_HAND_DOF_COUNT], sk_error *err);

/* The 21 landmarks of the common hand-pose datasets (e.g. MediaPipe Hands, FreiHAND):
 * 0 wrist; 1-4 thumb CMC, MCP, IP, tip; 5-8 index MCP, PIP, DIP, tip; 9-12 middle;
 * 13-16 ring; 17-20 little (base to tip). Joint centres of the skeleton, fingertips at
 * the ends of the distal links (where the surface's tips are). */
#define SK_HAND_LANDMARK_COUNT 21
const char *sk_hand_landmark_name(int landmark); /* "wrist", "thumb_cmc", ..., NULL outside */
int sk_hand_landmark_point(int landmark);        /* the skeleton point (sk_hand_point_name) */
/* Per frame (frame_count x SK_HAND_DOF_COUNT dofs): CSV "frame,landmark,name,x_mm,y_mm,z_mm"
 * or JSON {"landmarks": [names], "frames": [[[x, y, z] x 21] per frame]}. */
sk_result sk_hand_landmarks_write(const sk_hand_skeleton *skeleton, const double *dofs,
                                  int frame_count, sk_hand_positions_format format,
                                  const char *path, sk_error *err);

/* ------------------------------------------------------------- appearance */
/* The skin texture of the atlas (sk_hand_surface_export_mesh's UVs), for the thesis's
 * blend of shading and texture (4.1.6, Fig. 4.15: about 0.3 : 0.7). Generated: skin
 * colour (the back a little darker than the palm, knuckles a little redder, nails
 * pink with a pale free edge) and a height field whose normal map carries the skin
 * module's microrelief (back_skin on the back, palm_skin on the palm, evaluated in mm of
 * the planar projection), the transverse creases over the finger joints' backs and the
 * flexion creases of the fingers and the palm. With photos (linear RGB, each covering the
 * rest hand's x-y bounds as seen from its side: the back from the back, the palm from the
 * palm side), their planar projection replaces the generated colour, the two blended
 * across the sides of the hand so the seam does not show. */
typedef struct sk_hand_texture_desc {
    int size;                   /* atlas width = height in pixels; 0 = 1024; [64, 8192] */
    const sk_image *back_photo; /* NULL = generated colour */
    const sk_image *palm_photo;
    const sk_skin *back_skin; /* NULL = no microrelief on the back */
    const sk_skin *palm_skin; /* NULL = none on the palm */
    double relief_scale;      /* multiplies the microrelief's height; 0 = 1; [0, 100] */
    double crease_depth_mm;   /* depth of the joint and palm creases; 0 = 0.25; [0, 5] */
    double seam_width;        /* palm and back blend where |normal.z| < this; 0 = 0.3;
                                 (0, 1] */
} sk_hand_texture_desc;

/* Bakes the albedo (RGB, linear) and the tangent-space normal map (RGB, components
 * 0.5 n + 0.5: write it with SK_PNG_ENCODING_LINEAR) of the atlas. */
sk_result sk_hand_texture_bake(const sk_hand_surface *surface, const sk_hand_texture_desc *desc,
                               sk_image *albedo, sk_image *normal_map, sk_error *err);
/* The memory the bake peaks at (bytes; desc may be NULL): the texels being baked and the
 * two maps, 88 bytes a texel of the atlas (measured: 1.1 GB peak at 4096 x 4096). */
double sk_hand_texture_memory(const sk_hand_texture_desc *desc);

/* ===================================================================== scan pipeline */
/* The thesis's scan-to-surface pipeline (sec. 4.1.1-4.1.5), reproduced on a surface whose
 * truth is known: simulated range scans of the hand as the laser range finder saw the
 * plaster cast (palm side and back side, 9 marker bumps), registration of the back scan
 * onto the palm scan by least squares on the markers, segmentation by slices across the
 * links, polygons resampled per slice and link (eqs. 4.1, 4.2), bicubic Bezier patches
 * (eq. 4.3) fitted by least squares (eqs. 4.4, 4.5) with parameter correction (eqs. 4.6,
 * 4.7), the fitting error of Table 4.1, and control points that move with their links.
 * docs/hand-scan.md has the decisions on what the thesis leaves open.
 *
 * Frames: everything downstream of the scans is in the hand's own frame (the skeleton's
 * world frame, mm: X radial, Y distal, Z palmar). A scanner frame has the table in its
 * z = 0 plane and scan lines x = const; the hand's Y runs along the scanner's x, so the
 * thesis's slices x = const are the planes y = const of the hand frame.
 *
 * Thread-safety: a scan target is immutable after creation and may be shared; every
 * other function works on the objects it is given. Results never depend on the thread
 * count (per-item work, reductions in a fixed order). */
/* A rigid transform x' = R x + t (mm). */
typedef struct sk_hand_rigid {
    sk_mat3d rotation;
    sk_vec3d translation;
} sk_hand_rigid;

sk_hand_rigid sk_hand_rigid_identity(void);
sk_vec3d sk_hand_rigid_apply(const sk_hand_rigid *t, sk_vec3d p);
sk_hand_rigid sk_hand_rigid_inverse(const sk_hand_rigid *t);
/* a after b: x -> a(b(x)). */
sk_hand_rigid sk_hand_rigid_compose(const sk_hand_rigid *a, const sk_hand_rigid *b);
/* Rotation angle of a's rotation relative to b's (degrees) and the distance between
 * their translations (mm): how far an estimate is from the truth. */
void sk_hand_rigid_difference(const sk_hand_rigid *a, const sk_hand_rigid *b, double *angle_deg,
                              double *translation_mm);

/* ---------------------------------------------------------- scan target */
/* Signed distance (mm, negative inside) of the true surface at p with its gradient (may
 * be NULL), in the hand frame. Called from several threads at once. */
typedef double (*sk_hand_sdf_fn)(void *user, sk_vec3d p, sk_vec3d *gradient);

/* What the simulated scanner sees: a closed triangle mesh (ray casting, occlusion) and,
 * optionally, the implicit surface it was meshed from: each ray's hit on the mesh is then
 * refined onto the implicit surface, so the scans sample the smooth truth and not its
 * facets, and distances to the truth use it. Without it the mesh is the truth. */
typedef struct sk_hand_scan_target_desc {
    const sk_mesh *mesh; /* required: triangles, hand frame, mm (copied) */
    sk_hand_sdf_fn sdf;  /* NULL = the mesh is the true surface */
    void *sdf_user;
} sk_hand_scan_target_desc;

typedef struct sk_hand_scan_target sk_hand_scan_target;

/* Builds the ray-casting structure (a bounding volume hierarchy of the triangles, built on
 * one thread: see docs/hand-scan.md for why not Embree). Errors: no triangles, a
 * non-finite vertex, more than 2^26 triangles. */
sk_result sk_hand_scan_target_create(sk_hand_scan_target **out,
                                     const sk_hand_scan_target_desc *desc, sk_error *err);
void sk_hand_scan_target_destroy(sk_hand_scan_target *target);
/* The hand surface as a scan target: its mesh, refined onto its implicit field. The
 * surface must outlive the target. */
sk_result sk_hand_scan_target_from_surface(sk_hand_scan_target **out,
                                           const sk_hand_surface *surface, sk_error *err);
/* The plaster cast of 4.1.1: the hand surface meshed around the skeleton in the pose
 * `dofs` (a copy of the skeleton whose relaxed posture is that pose, written to
 * `cast_skeleton`: the pose the patches are fitted in and move from), and its scan
 * target. Free with sk_hand_scan_target_destroy, then sk_hand_surface_destroy. */
sk_result sk_hand_scan_cast(const sk_hand_skeleton *skeleton, const double dofs[SK_HAND_DOF_COUNT],
                            const sk_hand_surface_desc *surface_desc,
                            sk_hand_skeleton *cast_skeleton, sk_hand_surface **surface,
                            sk_hand_scan_target **target, sk_error *err);
/* Distance (mm, >= 0) from p to the true surface: |sdf| refined by one Newton step along
 * the gradient when an implicit is given, else the distance to the nearest triangle. */
double sk_hand_scan_target_distance(const sk_hand_scan_target *target, sk_vec3d p);
/* First hit of the ray o + t d (d need not be unit; t in (t_min, t_max)) with the mesh:
 * returns false on a miss; the hit parameter and the unit geometric normal facing the
 * ray's origin. */
bool sk_hand_scan_target_raycast(const sk_hand_scan_target *target, sk_vec3d o, sk_vec3d d,
                                 double t_min, double t_max, double *t, sk_vec3d *normal);

/* --------------------------------------------------------------- markers */
/* The 9 marker bumps on the cast, placed where both scans see them (4.1.1): spheres
 * half-sunk into the sides of the hand (wrist, thumb, index and little finger sides). */
#define SK_HAND_MARKER_COUNT 9
typedef struct sk_hand_markers {
    int count;
    double radius_mm;
    sk_vec3d centre[SK_HAND_MARKER_COUNT]; /* hand frame */
    char name[SK_HAND_MARKER_COUNT][24];   /* e.g. "wrist radial" */
} sk_hand_markers;

/* Places the markers on the target's sides: from a point on each chosen link's axis a ray
 * goes out sideways in the palm plane; the bump's centre sits `radius_mm` x 0.3 beyond the
 * surface it leaves. Where the cast lies over the bump (seen along the palm's normal,
 * from either side), the place moves along the link until it is open. radius_mm 0 = 2.5;
 * range [0.5, 10]. Errors: a ray that leaves no surface within 80 mm (the skeleton is not
 * inside the mesh). */
sk_result sk_hand_markers_place(const sk_hand_scan_target *target, const sk_hand_frames *frames,
                                double radius_mm, sk_hand_markers *out, sk_error *err);

/* --------------------------------------------------------------- scanner */
typedef enum sk_hand_scan_side {
    SK_HAND_SCAN_PALM = 0, /* the cast on its back, palm up */
    SK_HAND_SCAN_BACK = 1, /* the cast turned over, back up */
    SK_HAND_SCAN_SIDE_COUNT
} sk_hand_scan_side;

/* The laser range finder of 4.1.1 (Kubota CUBIST) as a light-section scanner: the object
 * moves along x on the table, a laser sheet x = const comes straight down, a camera sees it
 * from `triangulation_deg` off the vertical in the x-z plane. A sample is measured where
 * the laser's first hit is also seen by the camera (ray casting both ways) and neither
 * meets the surface at more than `grazing_deg`. Depth noise: Gaussian, sigma =
 * noise_mm / max(cos(angle between normal and camera), 0.25) (a stripe seen obliquely is
 * wider and its centre less certain), then quantised to depth_step_mm. The table (z = 0)
 * is scanned too, and removed later by a depth threshold. */
typedef struct sk_hand_scanner_desc {
    int lines;                /* scan lines (x = const); 0 = 512; range [8, 4096] */
    int points;               /* points per line; 0 = 512; range [8, 4096] */
    double size_x_mm;         /* along the lines' spacing; 0 = 250; range [10, 2000] */
    double size_y_mm;         /* along a line; 0 = 200; range [10, 2000] */
    double size_z_mm;         /* depth range; 0 = 200; range [10, 2000] */
    double depth_step_mm;     /* depth quantisation; 0 = 0.2; range [1e-4, 10] */
    double noise_mm;          /* depth noise sigma at normal view; 0 = 0.05; range [0, 10] */
    bool no_noise;            /* true = no noise (noise_mm ignored) */
    double triangulation_deg; /* camera angle off the vertical; 0 = 30; range [1, 80] */
    double grazing_deg;       /* steepest measurable incidence; 0 = 80; range [10, 89.9] */
    double
        table_threshold_mm; /* samples at z below this are the table; 0 = 1.0; range [0.01, 100] */
} sk_hand_scanner_desc;

sk_hand_scanner_desc sk_hand_scanner_desc_resolved(const sk_hand_scanner_desc *desc);
sk_result sk_hand_scanner_desc_validate(const sk_hand_scanner_desc *resolved, sk_error *err);

/* What a sample of a range scan saw. */
typedef enum sk_hand_sample_kind {
    SK_HAND_SAMPLE_NONE = 0, /* nothing measured: occluded from the camera or grazing */
    SK_HAND_SAMPLE_TABLE,    /* the table (removed by the threshold) */
    SK_HAND_SAMPLE_SURFACE,  /* the hand */
    SK_HAND_SAMPLE_MARKER    /* a marker bump */
} sk_hand_sample_kind;

/* One range scan: a depth image of lines x points. Sample (i, j) lies at scanner
 * x = (i + 0.5) step_x, y = (j + 0.5) step_y. */
typedef struct sk_hand_range_scan {
    sk_hand_scan_side side;
    int lines, points;
    double step_x_mm, step_y_mm, table_threshold_mm;
    sk_hand_rigid placement; /* hand frame -> this scanner's frame (where the cast lay) */
    float *depth;            /* lines * points, [i * points + j]: measured z (mm), NAN if none */
    float *true_depth;       /* the exact z of the surface the sample saw (before noise) */
    uint8_t *kind;           /* sk_hand_sample_kind */
    int marker_points[SK_HAND_MARKER_COUNT]; /* samples on each marker */
} sk_hand_range_scan;

/* The two placements of the cast: palm up, resting on the table, centred in the volume;
 * and turned over about the scanner's x axis, then turned 3 deg about z, tilted 1.5 deg,
 * shifted (+6, -4) mm and resting on the table again: the displacement a real second scan
 * has, which registration must undo. Fails if the target does not fit the volume. */
sk_result sk_hand_scan_placements(const sk_hand_scan_target *target,
                                  const sk_hand_scanner_desc *desc,
                                  sk_hand_rigid placement[SK_HAND_SCAN_SIDE_COUNT], sk_error *err);
/* Scans the target (and the markers, may be NULL) lying at `placement`. `seed` keys the
 * noise (hash of seed, side, line, point). */
sk_result sk_hand_scan_simulate(const sk_hand_scan_target *target, const sk_hand_markers *markers,
                                sk_hand_scan_side side, const sk_hand_rigid *placement,
                                const sk_hand_scanner_desc *desc, uint64_t seed,
                                sk_hand_range_scan *out, sk_error *err);
void sk_hand_range_scan_free(sk_hand_range_scan *scan);
/* Scanner-frame position of sample (i, j) at depth z. */
sk_vec3d sk_hand_range_scan_point(const sk_hand_range_scan *scan, int i, int j, double z);

/* ----------------------------------------------------------- registration */
/* Least-squares rigid transform (Kabsch: SVD of the cross-covariance, LAPACKE dgesvd, with
 * the reflection guard) taking `from` onto `to`: minimises sum |R from_i + t - to_i|^2.
 * residual_mm (may be NULL) gets |R from_i + t - to_i| per point. Needs 3 or more points,
 * not all on one line. */
sk_result sk_hand_register_rigid(const sk_vec3d *from, const sk_vec3d *to, int count,
                                 sk_hand_rigid *out, double *residual_mm, sk_error *err);

/* Finds each marker in a scan: the samples near its nominal place (where the operator of
 * the thesis would click) are fitted by a sphere of the marker's radius (Gauss-Newton,
 * samples off the sphere by more than 0.3 mm dropped). Centres in the scanner frame; a
 * marker seen by fewer than 6 samples is an error naming it. */
sk_result sk_hand_markers_locate(const sk_hand_range_scan *scan, const sk_hand_markers *markers,
                                 sk_vec3d centre[SK_HAND_MARKER_COUNT],
                                 int used[SK_HAND_MARKER_COUNT], sk_error *err);

typedef struct sk_hand_registration {
    sk_hand_rigid back_to_palm; /* estimated: back scanner frame -> palm scanner frame */
    sk_hand_rigid truth;        /* the true one (identity rotation when unknown) */
    bool has_truth;
    sk_vec3d palm_centre[SK_HAND_MARKER_COUNT], back_centre[SK_HAND_MARKER_COUNT];
    int palm_used[SK_HAND_MARKER_COUNT], back_used[SK_HAND_MARKER_COUNT];
    double residual_mm[SK_HAND_MARKER_COUNT]; /* after the fit */
    double rms_mm;
    double rotation_error_deg, translation_error_mm; /* estimate against the truth */
} sk_hand_registration;

/* ------------------------------------------------------------ point cloud */
/* The merged, registered data in the hand frame. */
typedef struct sk_hand_cloud {
    size_t count;
    sk_vec3d *position;      /* mm */
    sk_vec3d *true_position; /* the true surface point each sample measured; NULL if unknown */
    uint8_t *side;           /* sk_hand_scan_side of the scan it came from */
} sk_hand_cloud;

sk_result sk_hand_cloud_alloc(sk_hand_cloud *cloud, size_t count, bool with_truth, sk_error *err);
void sk_hand_cloud_free(sk_hand_cloud *cloud);
/* The samples of a scan above its table threshold, off the marker bumps (farther than the
 * radius + 0.5 mm from every nominal centre), mapped into the hand frame by `to_hand`
 * (scanner frame -> hand frame; the truth by `truth_to_hand`, NULL = to_hand), appended
 * to `cloud`. */
sk_result sk_hand_cloud_append_scan(sk_hand_cloud *cloud, const sk_hand_range_scan *scan,
                                    const sk_hand_markers *markers, const sk_hand_rigid *to_hand,
                                    const sk_hand_rigid *truth_to_hand, sk_error *err);
/* A user's point cloud (mesh vertices, triangles ignored) in the hand frame. The side of
 * each point: from an attribute "side" (0 palm, 1 back) if there is one, else from its
 * normal if there are normals (palm where it points palmar, along the carpus frame's Z),
 * else from which side of its nearest link's axis it lies on. */
sk_result sk_hand_cloud_from_points(sk_hand_cloud *cloud, const sk_mesh *points,
                                    const sk_hand_frames *frames, sk_error *err);

/* ---------------------------------------------------------- segmentation */
/* The links as segments in the hand frame (4.1.2): each from its base joint to the next
 * joint or tip; the carpus from the wrist to the mean of the index..little CMC joints. */
typedef struct sk_hand_link_geometry {
    sk_vec3d a[SK_HAND_LINK_COUNT], b[SK_HAND_LINK_COUNT];
    sk_mat3d frame[SK_HAND_LINK_COUNT]; /* link frame axes as columns */
} sk_hand_link_geometry;

void sk_hand_link_geometry_from_frames(const sk_hand_frames *frames, sk_hand_link_geometry *out);
/* The link whose segment is nearest to p (step 4 of 4.1.2), and that distance. */
int sk_hand_nearest_link(const sk_hand_link_geometry *links, sk_vec3d p, double *distance);

typedef struct sk_hand_slices_desc {
    int count;                /* slice planes y = const across the hand; 0 = 75 (2.9 mm apart on
                                 the default cast: 10 points per segment then give the thesis's
                                 about 4000 vertices); range [2, 2000] */
    double half_thickness_mm; /* points this near a plane are projected onto it; 0 = 0.5;
                                 range (0, 50] */
} sk_hand_slices_desc;

/* One projected point of a slice: its link and its polar coordinates in the slice plane
 * about the point where the link's axis crosses it (clamped to the segment's ends). */
typedef struct sk_hand_slice_point {
    uint32_t point; /* index in the cloud */
    int16_t link;
    uint8_t side;
    float theta; /* atan2(z - cz, x - cx), radians */
    float r;     /* mm */
} sk_hand_slice_point;

typedef struct sk_hand_slices {
    int count;
    double *y;                   /* plane positions (mm) */
    size_t *first;               /* count + 1: points of slice s are [first[s], first[s+1]) */
    sk_hand_slice_point *points; /* grouped by slice, then by link, then by angle */
    sk_vec3d (*centre)[SK_HAND_LINK_COUNT]; /* per slice and link: the polar centre */
    double half_thickness_mm;
} sk_hand_slices;

sk_result sk_hand_slices_build(const sk_hand_cloud *cloud, const sk_hand_link_geometry *links,
                               const sk_hand_slices_desc *desc, sk_hand_slices *out, sk_error *err);
void sk_hand_slices_free(sk_hand_slices *slices);

/* -------------------------------------------------------------- polygons */
typedef enum sk_hand_resample_mode {
    SK_HAND_RESAMPLE_DEFAULT = 0, /* = NEIGHBOURS */
    SK_HAND_RESAMPLE_NEIGHBOURS,  /* the fix the thesis proposes: samples placed alike on
                                     neighbouring slices (a ring's angles fixed per link, an
                                     arc's ends averaged 1:2:1 with the slices before and
                                     after); radii by eq. 4.2 on each slice's own data */
    SK_HAND_RESAMPLE_THESIS       /* eqs. 4.1, 4.2 on each slice alone (shows the wrinkles) */
} sk_hand_resample_mode;

typedef struct sk_hand_resample_desc {
    sk_hand_resample_mode mode;
    int points_per_segment; /* 0 = 10 (the thesis); range [3, 256] */
    double arc_gap_deg;     /* the palm's links (metacarpals, carpus): a gap between angles
                               wider than this splits a slice's points into separate arcs;
                               0 = 45; range [5, 180] */
} sk_hand_resample_desc;

typedef struct sk_hand_resample_stats {
    size_t rings, arcs;   /* resampled segments: closed rings, open arcs */
    double fold_mean_deg; /* angle between the two triangles of each quad (slice to slice):
                             a quad twisted or wrinkled by the resampling folds */
    double fold_max_deg;
    double truth_mean_mm, truth_max_mm; /* vertices against the true surface (set by the
                                           pipeline when it knows the truth, else 0) */
} sk_hand_resample_stats;

/* Resamples every slice and link (4.1.3) and joins consecutive slices of the same link by
 * triangles: a ring of 2n triangles around a phalanx (closed tubes), a strip of 2(n-1)
 * between overlapping arcs elsewhere. A link's points form a ring when it is a phalanx
 * whose widest gap between angles is below 180 deg, or any link without a gap wider than
 * arc_gap_deg; otherwise they split into arcs at those gaps. The mesh has normals and a
 * 1-component attribute "link". Links are not joined to each other (as in the thesis).
 * `stats` may be NULL. */
sk_result sk_hand_resample(const sk_hand_slices *slices, const sk_hand_link_geometry *links,
                           const sk_hand_resample_desc *desc, sk_mesh *out,
                           sk_hand_resample_stats *stats, sk_error *err);

/* ------------------------------------------------------- Bezier patches */
/* A bicubic Bezier patch, eq. (4.3): Q(u, v) = u^T G P G^T v with the corrected basis
 * matrix G (rows [1 0 0 0], [-3 3 0 0], [3 -6 3 0], [-1 3 -3 1]: the cubic Bernstein
 * polynomials), u, v in [0, 1]; control point P_ij multiplies B_i(u) B_j(v). */
typedef struct sk_hand_patch {
    sk_vec3d p[4][4];
    int link; /* the link it belongs to and moves with */
    sk_hand_scan_side side;
    int along, around; /* its place in the link's layout (0-based) */
} sk_hand_patch;

/* Q(u, v) and its partial derivatives (du, dv may be NULL). */
sk_vec3d sk_hand_patch_eval(const sk_hand_patch *patch, double u, double v, sk_vec3d *du,
                            sk_vec3d *dv);
/* The four cubic Bernstein values at t (the row u^T G of eq. 4.3). */
void sk_hand_bernstein3(double t, double out[4]);

typedef struct sk_hand_patch_fit_desc {
    int max_iterations; /* parameter corrections; 0 = 30; range [1, 10000] */
    double
        tolerance; /* stop when no parameter moves more than this; 0 = 1e-3; range [1e-12, 0.1] */
    double min_improvement; /* ... or when a correction lowers the RMS error by less than this
                               fraction; 0 = 1e-3; range [0, 0.5] (negative = never) */
    bool no_correction;     /* true = the least-squares fit of the chord-length parameters only */
} sk_hand_patch_fit_desc;

typedef struct sk_hand_patch_fit_info {
    int iterations;        /* parameter corrections done */
    bool converged;        /* the last update was below the tolerance, or the error stalled */
    bool regularised;      /* A^T A was singular (too few or degenerate points) and a tiny
                              ridge made it solvable */
    double rms_initial_mm; /* RMS of |S - Q(u, v)| after the first fit (4.5) */
    double rms_final_mm;   /* ... after the last correction and refit */
    double last_update;    /* largest parameter update of the last correction */
} sk_hand_patch_fit_info;

/* Least-squares fit (eqs. 4.4, 4.5) of one patch to `count` points with parameters u, v
 * (in: the initial ones, e.g. chord length; out: the corrected ones), then parameter
 * correction (4.6, 4.7) and refitting until no parameter moves more than the tolerance.
 * Each correction drops a perpendicular from every point to the patch (Newton steps of
 * 4.6/4.7 along u and v, halved when they would move the point farther away), so the sum
 * of squared distances never increases. `rms_history` (may be NULL; max_iterations + 1
 * entries) gets the RMS after each fit. Needs 16 or more points. */
sk_result sk_hand_patch_fit(const sk_vec3d *points, size_t count, double *u, double *v,
                            const sk_hand_patch_fit_desc *desc, sk_hand_patch *out,
                            sk_hand_patch_fit_info *info, double *rms_history, sk_error *err);

/* Chord-length parameters along one ordered row of points (the first formula of 4.4's
 * parameterisation): u_0 = 0, u_i = u_{i-1} + |Q_i - Q_{i-1}| / total, u_{n-1} = 1. */
void sk_hand_chord_parameters(const sk_vec3d *row, size_t count, double *u);

/* The error measure of Table 4.1: the patch split into splits x splits facets in (u, v)
 * (each a pair of triangles), and the distance of each point to its nearest facet (exact:
 * a quadtree of the facet grid, searched from the facets around the hint parameters u, v,
 * which may be NULL). splits 0 = 100; range [1, 1024]. */
sk_result sk_hand_patch_facet_distances(const sk_hand_patch *patch, int splits,
                                        const sk_vec3d *points, size_t count, const double *u_hint,
                                        const double *v_hint, double *distance, sk_error *err);

/* -------------------------------------------------------- patch layout */
/* Regions of the palm side and of the back side, 48 each (4.1.4's hand-drawn layout
 * made automatic): per link, the points nearest it from that side's scan, split into
 * `along` pieces along the link and `around` pieces about it: carpus 2 x 2, thumb
 * metacarpal 2 x 2, thumb phalanges 2 x 1, index..little metacarpals 3 x 1, their
 * phalanges 2 x 1. */
typedef struct sk_hand_layout_entry {
    int link, along, around;
} sk_hand_layout_entry;
/* The per-side table (SK_HAND_LINK_COUNT entries); sum of along x around = 48. */
const sk_hand_layout_entry *sk_hand_patch_layout_table(void);
#define SK_HAND_PATCHES_PER_SIDE 48
#define SK_HAND_PATCH_COUNT (2 * SK_HAND_PATCHES_PER_SIDE)

/* The points of each patch and their initial parameters: rows across the link (0.5 mm
 * apart along it, like scan lines), points in a row in order around the link, u by chord
 * length along the row within the row's share of the region, v from the position along the
 * link. Points within 0.5 mm of a boundary between two regions belong to both. */
typedef struct sk_hand_patch_data {
    size_t count;
    uint32_t *point; /* cloud indices */
    double *u, *v;   /* initial, then corrected by the fit */
} sk_hand_patch_data;

typedef struct sk_hand_patch_set {
    int count; /* SK_HAND_PATCH_COUNT */
    sk_hand_patch patch[SK_HAND_PATCH_COUNT];
    sk_hand_patch_data data[SK_HAND_PATCH_COUNT];
    sk_hand_patch_fit_info fit[SK_HAND_PATCH_COUNT];
    bool fitted[SK_HAND_PATCH_COUNT];         /* false: fewer than 16 points */
    double *error_scan[SK_HAND_PATCH_COUNT];  /* per point: distance to the nearest facet */
    double *error_truth[SK_HAND_PATCH_COUNT]; /* the same for the true surface points (NULL
                                                 without truth) */
} sk_hand_patch_set;

sk_result sk_hand_patch_layout_build(const sk_hand_cloud *cloud, const sk_hand_link_geometry *links,
                                     sk_hand_patch_set *out, sk_error *err);
/* Fits every patch with 16 or more points (in parallel); the others stay unfitted. */
sk_result sk_hand_patch_set_fit(sk_hand_patch_set *set, const sk_hand_cloud *cloud,
                                const sk_hand_patch_fit_desc *desc, sk_error *err);
/* Table 4.1's error of every point of every fitted patch: against its splits x splits
 * facets (0 = 100; range [1, 1024]), for the scan points and, when the cloud has them, for
 * the true surface points. */
sk_result sk_hand_patch_set_measure(sk_hand_patch_set *set, const sk_hand_cloud *cloud, int splits,
                                    sk_error *err);
void sk_hand_patch_set_free(sk_hand_patch_set *set);

/* ------------------------------------------------------------- Table 4.1 */
typedef struct sk_hand_fit_error {
    double mean_mm, max_mm;
    size_t points;   /* (patch, point) pairs: a point shared by two patches counts twice */
    int worst_patch; /* index of the patch with the largest error, -1 if none */
} sk_hand_fit_error;

typedef struct sk_hand_table41 {
    sk_hand_fit_error scan[SK_HAND_SCAN_SIDE_COUNT];  /* fitted points: the scan's */
    sk_hand_fit_error truth[SK_HAND_SCAN_SIDE_COUNT]; /* the true surface points the scan sampled */
    sk_hand_fit_error scan_all, truth_all;
    bool has_truth;
    int patches_fitted[SK_HAND_SCAN_SIDE_COUNT];
} sk_hand_table41;

/* The thesis's own figures (Table 4.1, mm). */
#define SK_HAND_THESIS_PALM_MEAN_MM 3.0e-2
#define SK_HAND_THESIS_PALM_MAX_MM 3.6
#define SK_HAND_THESIS_BACK_MEAN_MM 2.7e-2
#define SK_HAND_THESIS_BACK_MAX_MM 4.3e-1
#define SK_HAND_THESIS_ALL_MEAN_MM 2.9e-2

void sk_hand_table41_compute(const sk_hand_patch_set *set, sk_hand_table41 *out);

/* -------------------------------------------------- patches with their links */
/* Control points that move with their links (4.1.5). RIGID: each patch's 16 points move
 * with its own link (the thesis). SMOOTH: each control point blends the motions of up to 4
 * links with weights (linear blend). */
#define SK_HAND_PATCH_MAX_INFLUENCES 4
typedef struct sk_hand_patch_weights {
    int16_t link[SK_HAND_PATCH_MAX_INFLUENCES]; /* -1 = unused */
    float weight[SK_HAND_PATCH_MAX_INFLUENCES]; /* sum to 1 */
} sk_hand_patch_weights;

/* Moves `count` patches from the frames they were fitted in (`rest`) to `pose`.
 * `weights` NULL = rigid with each patch's link; else count * 16 entries, [k * 16 + 4i + j]
 * for P_ij of patch k. `out` may be `patches`. */
sk_result sk_hand_patches_pose(const sk_hand_patch *patches, int count, const sk_hand_frames *rest,
                               const sk_hand_frames *pose, const sk_hand_patch_weights *weights,
                               sk_hand_patch *out, sk_error *err);
/* Smooth weights of every control point (count * 16, in the order above): those of the
 * surface vertex nearest to the patch point the control point shapes most, Q(i/3, j/3).
 * The surface's bind pose must be the pose the patches were fitted in (sk_hand_scan_cast). */
sk_result sk_hand_patch_weights_from_surface(const sk_hand_surface *surface,
                                             const sk_hand_patch *patches, int count,
                                             sk_hand_patch_weights *out, sk_error *err);

/* ---------------------------------------------------------------- pipeline */
typedef struct sk_hand_scan_desc {
    sk_hand_scanner_desc scanner;
    sk_hand_slices_desc slices;
    sk_hand_resample_desc resample; /* its mode is ignored: both meshes are made */
    sk_hand_patch_fit_desc fit;
    int facet_splits;        /* Table 4.1's facet grid; 0 = 100; range [1, 1024] */
    double marker_radius_mm; /* 0 = 2.5, or 3 sample spacings if the scan is
                                coarser than 0.83 mm; range [0.5, 10] */
    uint64_t seed;           /* scanner noise */
} sk_hand_scan_desc;

/* What the pipeline runs on: a surface to scan (the hand, or a user's mesh), or a user's
 * point cloud taken as the registered data; and the skeleton placed in it. */
typedef struct sk_hand_scan_input {
    const sk_hand_scan_target *target; /* scan this; or NULL and give `cloud` */
    const sk_mesh *cloud;              /* points in the hand frame (used when target is NULL) */
    const sk_hand_skeleton *skeleton;
    const double *dofs; /* SK_HAND_DOF_COUNT absolute values: the pose of the
                           skeleton in the surface or cloud */
} sk_hand_scan_input;

/* The pose of the plaster cast: an open hand ("手を開いた姿勢の複製", 4.1.1): the fingers
 * nearly straight (MCP 5, PIP 8, DIP 4 deg) and a little spread, the thumb spread beside
 * the palm (CMC flexion -10, abduction 10 deg), the wrist straight. */
void sk_hand_scan_cast_pose(const sk_hand_skeleton *skeleton, double dofs[SK_HAND_DOF_COUNT]);

/* Seconds spent per stage (wall clock). */
typedef struct sk_hand_scan_timings {
    double simulate, register_, segment, resample, fit, measure, total;
} sk_hand_scan_timings;

typedef struct sk_hand_scan_result {
    sk_hand_frames frames; /* the skeleton placed in the data */
    sk_hand_link_geometry links;
    bool scanned; /* false when the input was a point cloud */
    sk_hand_markers markers;
    sk_hand_range_scan scan[SK_HAND_SCAN_SIDE_COUNT];
    sk_hand_registration registration;
    sk_hand_cloud cloud;
    sk_hand_slices slices;
    sk_mesh polygons;        /* resampled with neighbouring slices */
    sk_mesh polygons_thesis; /* resampled slice by slice (eqs. 4.1, 4.2 alone) */
    sk_hand_resample_stats polygons_stats, polygons_thesis_stats;
    sk_hand_patch_set *patches;
    sk_hand_table41 table;
    sk_hand_scan_timings timings;
} sk_hand_scan_result;

/* Runs every stage. `progress` gets the fraction done. */
sk_result sk_hand_scan_run(const sk_hand_scan_input *input, const sk_hand_scan_desc *desc,
                           sk_hand_scan_result *out, sk_progress progress, sk_error *err);
void sk_hand_scan_result_free(sk_hand_scan_result *result);
/* The memory sk_hand_scan_run peaks at (bytes; desc may be NULL), beyond its input's: the
 * two simulated scans' points dominate, about 128 bytes a point of lines x points
 * (measured: 135 MB at 1024 x 1024), and the slices. */
double sk_hand_scan_memory(const sk_hand_scan_desc *desc);

/* ------------------------------------------------------------------ files */
/* Table 4.1 beside the thesis's figures: JSON (mm) and a text table. */
sk_result sk_hand_table41_write_json(const sk_hand_table41 *table, const char *path, sk_error *err);
sk_result sk_hand_table41_write_text(const sk_hand_table41 *table, const char *path, sk_error *err);
/* The registration: per-marker centres and residuals, the estimated and true transforms. */
sk_result sk_hand_registration_write_json(const sk_hand_registration *reg,
                                          const sk_hand_markers *markers, const char *path,
                                          sk_error *err);
/* The cloud as a binary PLY point cloud: x y z, a float "side" (0 palm, 1 back) and, when
 * the truth is known, the true surface point of each sample as "truth_0" .. "truth_2". */
sk_result sk_hand_cloud_write_ply(const sk_hand_cloud *cloud, const char *path, sk_error *err);
/* Control points (16 per patch, mm) with each patch's link, side, point count and errors. */
sk_result sk_hand_patches_write_json(const sk_hand_patch_set *set, const char *path, sk_error *err);
/* The patches as one mesh: each tessellated into n x n quads (n 0 = 16; range [1, 256]),
 * with normals, UVs (the patch's u, v) and a 1-component attribute "patch". No vertex is
 * shared between patches (none of their control points is). */
sk_result sk_hand_patches_tessellate(const sk_hand_patch *patches, int count, int n, sk_mesh *out,
                                     sk_error *err);

/* --------------------------------------------------------------- pictures */
/* A range scan as the scanner's depth image: hill-shaded, nearer brighter, the table
 * removed (white), unmeasured samples (occluded or grazing) in red, markers circled. One
 * pixel per sample (lines across, points down), scaled by `scale` (0 = 1; range 1..8). */
sk_result sk_hand_draw_range_scan(const sk_hand_range_scan *scan, int scale, sk_image *out,
                                  sk_error *err);

/* The registered cloud from the back and from the thumb side: palm-scan points blue,
 * back-scan points orange, markers ringed with their residuals. */
sk_result sk_hand_draw_registered(const sk_hand_scan_result *result, sk_image *out, sk_error *err);
/* The slices (4.1.2): the cloud in grey from the back with every slice's points in its
 * link's colour, and three cross-sections (a finger level, the knuckles, the palm) drawn
 * flat with their link centres. */
sk_result sk_hand_draw_slices(const sk_hand_scan_result *result, sk_image *out, sk_error *err);
/* A flat-shaded mesh (polygons, tessellated patches) in orthographic views side by side
 * (view_count 0 = from the back and from the palm; else 1..4 of `views`, DEFAULT entries
 * meaning dorsal); `color_attribute` (may be NULL): a per-vertex attribute whose integer
 * values pick the colours ("link": each link's finger colour; else one colour each, e.g.
 * "patch"). */
sk_result sk_hand_draw_mesh_views(const sk_mesh *mesh, const char *title,
                                  const char *color_attribute, const sk_hand_view *views,
                                  int view_count, sk_image *out, sk_error *err);
/* The fitted patches moved to a pose (4.1.5) and drawn from the thumb side and the back:
 * rigidly with their links (the thesis) and, if `weights` is given, with the smooth
 * weights, side by side. */
sk_result sk_hand_draw_patches_posed(const sk_hand_patch_set *set, const sk_hand_frames *rest,
                                     const sk_hand_frames *pose,
                                     const sk_hand_patch_weights *weights, sk_image *out,
                                     sk_error *err);

#ifdef __cplusplus
}
#endif

#endif /* SHITSUKAN_HAND_H */
