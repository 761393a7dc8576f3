/* shitsukan tissue: the fat and skin model of Shigemori & Kawai ("A Fat and Skin Model for
 * CG Animation"), which puts a layer of fat between the underlying tissue of Wilhelms'
 * "Animals with Anatomy" (bones and muscles) and the skin, so that the skin jiggles as
 * the character moves.
 *
 * The character (sec. 2): a hierarchy of joints; bones of three ellipsoids each (sec. 3:
 * two rounded ends and a thinner shaft, fixed in the bone's frame); muscles as ellipsoids
 * on two tendons attached to points on bones, deforming with constant volume and X:Y
 * ratio (sec. 3); fat; skin. The skin is generated from the tissue (sec. 4): a grid over
 * the tissue's bounding box, a constant scalar on grid points inside tissue, dilations
 * that add values inversely proportional to distance, and an isosurface at a threshold
 * whose triangle vertices lie on grid points. Grid points above the threshold are
 * "points": fat points (between tissue and skin), muscle and bone points (in tissue,
 * next to a fat point; stored in their muscle's or bone's local frame), skin points (the
 * triangles' vertices), joined by springs. Motion (sec. 5): bones follow the skeleton's
 * motion, bone points move rigidly with them, muscle points with their muscle's
 * deformation, and fat and skin points under the spring forces.
 *
 * Decisions where the paper is silent (docs/tissue.md gives the reasons and figures):
 * - Units: millimetres for lengths, seconds, spring stiffness in N/m, densities in kg/m^3.
 *   World frame: +Y up; all rotations zero is the rest pose (BVH convention: rest frames
 *   aligned with the world).
 * - Dilation: each pass adds to every grid point within `dilation_radius_mm` of a point
 *   with a positive value w(d) = 1/max(d, spacing) normalised so a point surrounded by
 *   positive points gains 1 per pass; tissue starts at 1; threshold in (0, 1).
 * - Isosurface "with vertices on grid points": the boundary of the union of grid cells
 *   whose 8 corners are all points (the cuberille family), cells removed where that
 *   boundary would not be manifold, quads split into two triangles.
 * - Springs join grid neighbours (18- or 26-neighbourhood) of the classes the paper
 *   names; skin springs run along the triangle edges.
 * - Every fat and skin point is also tied by a weak zero-length spring (the tether) to
 *   where the bones and muscles alone carry it, so a violent motion cannot leave the
 *   flesh tangled and it returns exactly to rest when the bones stop (the principle of
 *   Complementary Dynamics, Zhang et al. 2020: secondary motion adds to the rig).
 * - Integration: XPBD (Macklin, Mueller, Chentanez 2016) with one iteration per substep
 *   at a fixed internal step ("Small steps", Macklin et al. 2019), springs in coloured
 *   Gauss-Seidel order, compliance 1/k, per-spring damping of a stated damping ratio.
 *   The result never depends on the output frame rate or on the thread count.
 *
 * Thread-safety: a model is immutable after sk_tissue_model_build and may be shared; a
 * simulation belongs to one thread at a time (it runs OpenMP loops itself). */
#ifndef SHITSUKAN_TISSUE_H
#define SHITSUKAN_TISSUE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "shitsukan/bvh.h"
#include "shitsukan/core.h"
#include "shitsukan/mesh.h"
#include "shitsukan/preset.h"

#ifdef __cplusplus
extern "C" {
#endif

#define SK_TISSUE_NAME_SIZE 48
#define SK_TISSUE_MAX_JOINTS 64
#define SK_TISSUE_MAX_BONES 64
#define SK_TISSUE_MAX_MUSCLES 64
#define SK_TISSUE_MAX_FAT_REGIONS 32
#define SK_TISSUE_MAX_JOINT_MAP 128
#define SK_TISSUE_MAX_TRACKED 8

/* ============================================================ character */

/* A joint of the skeleton at rest. Joints may be listed in any order; each names its
 * parent (exactly one joint, the root, has none). */
typedef struct sk_tissue_joint_desc {
    char name[SK_TISSUE_NAME_SIZE];
    char parent[SK_TISSUE_NAME_SIZE]; /* "" = the root */
    float offset_mm[3];               /* from the parent at rest (the root: its position) */
} sk_tissue_joint_desc;

/* A bone (sec. 3): rigid in the frame of `joint`, running from its start to its end, made
 * of three ellipsoids: one around each end (semi-axes radius, radius * depth_ratio,
 * end_length) and the shaft between them (semi-axes radius * shaft_ratio, the same times
 * depth_ratio, half the length). */
typedef struct sk_tissue_bone_desc {
    char name[SK_TISSUE_NAME_SIZE];  /* unique; muscles and fat regions refer to it */
    char joint[SK_TISSUE_NAME_SIZE]; /* the joint whose frame carries the bone */
    char end[SK_TISSUE_NAME_SIZE];   /* the joint where it ends; "" = joint + to_mm */
    float from_mm[3];                /* start, offset from the joint at rest; default 0 */
    float to_mm[3];                  /* end, offset from the joint, when `end` is "" */
    float radius_mm;                 /* of the rounded ends; (0, 1000] */
    float shaft_ratio;               /* shaft radius / radius; 0 = 0.6; (0, 1] */
    float depth_ratio;               /* Y / X semi-axis of every ellipsoid; 0 = 1; (0, 4] */
    float end_length_mm;             /* ends' semi-axis along the bone; 0 = radius */
    float x_axis[3];                 /* rest direction of the ellipsoids' X axis (projected
                                        across the bone); all 0 = the world axis most
                                        across the bone (X, then Y, then Z) */
} sk_tissue_bone_desc;

/* A point fixed on a bone: `at` along the bone (0 its start, 1 its end) plus an offset
 * in the rest (world) axes. */
typedef struct sk_tissue_attachment_desc {
    char bone[SK_TISSUE_NAME_SIZE];
    float at; /* [-1, 2] */
    float offset_mm[3];
} sk_tissue_attachment_desc;

/* A muscle (sec. 3): a belly ellipsoid between two tendons, centred between the origin
 * and the insertion with its Z axis along them. With L the attachment distance and L0 its
 * rest value the semi-axes are c = c0 L / L0, a = a0 sqrt(c0 / c), b = b0 sqrt(c0 / c):
 * volume and the X:Y ratio stay constant (spec/tissue.md). */
typedef struct sk_tissue_muscle_desc {
    char name[SK_TISSUE_NAME_SIZE];
    sk_tissue_attachment_desc origin;
    sk_tissue_attachment_desc insertion;
    float thickness_mm;   /* rest thickness 2 a0 along X; (0, 1000] */
    float width_ratio;    /* b0 / a0 (Y across); 0 = 1; (0, 8] */
    float belly_fraction; /* 2 c0 / L0 (the rest is tendon); 0 = 0.8; (0, 1.5] */
    float x_axis[3];      /* rest direction of X (the thickness), across Z;
                             all 0 = away from the origin bone's axis */
} sk_tissue_muscle_desc;

/* Where fat lies (per region): grid points within `thickness_mm` of the tissue, beside
 * the named bone or muscle between `from` and `to` along it, on the side `direction`
 * within `spread_deg`, become fat before the dilations (so the skin passes outside them). */
typedef struct sk_tissue_fat_desc {
    char name[SK_TISSUE_NAME_SIZE];
    char around[SK_TISSUE_NAME_SIZE]; /* a bone or muscle name */
    float from, to;                   /* along it; both 0 = [0, 1]; [-1, 2] */
    float thickness_mm;               /* (0, 500] */
    float direction[3];               /* rest direction of the side; all 0 = all around */
    float spread_deg;                 /* half-angle around `direction`; 0 = 90; (0, 180] */
} sk_tissue_fat_desc;

/* Binds a motion's joint name to a character joint (several names may bind one joint,
 * so one file can serve several naming schemes). */
typedef struct sk_tissue_joint_map_desc {
    char motion[SK_BVH_NAME_SIZE];
    char joint[SK_TISSUE_NAME_SIZE];
} sk_tissue_joint_map_desc;

/* A named skin point followed in stats and plots: the skin point nearest the ray from
 * the point `at` along `bone` in `direction`. */
typedef struct sk_tissue_tracked_desc {
    char name[SK_TISSUE_NAME_SIZE];
    char bone[SK_TISSUE_NAME_SIZE];
    float at;           /* [-1, 2] */
    float direction[3]; /* rest direction; must not be zero */
} sk_tissue_tracked_desc;

/* Skin generation (sec. 4). */
typedef struct sk_tissue_skin_desc {
    float spacing_mm;         /* grid spacing; 0 = 4; [0.5, 50] */
    int dilations;            /* the paper's dilation passes; 0 = 3; [1, 32] */
    float dilation_radius_mm; /* reach of one pass; 0 = 1.5 spacings; [spacing, 10 spacings] */
    float threshold;          /* isosurface level; 0 = 0.3; (0, 0.999] */
    int smooth_iterations;    /* optional smoothing of the rest skin (the paper's
                                 future work), kept outside the tissue; 0 = none:
                                 every vertex on a grid point; [0, 200] */
    int neighbourhood;        /* springs between grid neighbours: 18 (faces and
                                 face diagonals) or 26 (and body diagonals); 0 = 18 */
} sk_tissue_skin_desc;

/* Material of the springs and points (the paper leaves them open). */
typedef struct sk_tissue_material_desc {
    float fat_stiffness;     /* N/m, fat-fat and fat-skin springs; 0 = 5 (fat's
                                Young's modulus of about 1 kPa times a 4 mm
                                spacing); [1e-3, 1e6] */
    float anchor_stiffness;  /* N/m, fat to muscle and bone points; 0 = fat */
    float skin_stiffness;    /* N/m, along skin triangle edges; 0 = 5 x fat */
    float tether_stiffness;  /* N/m, a zero-length spring from every fat and skin
                                point to where the tissue alone carries it (beyond
                                the paper: the flesh cannot stay tangled, and it
                                returns exactly to rest); 0 = 0.4 x fat; [1e-4, 1e6] */
    float fat_density;       /* kg/m^3; 0 = 900; [100, 20000] */
    float skin_density;      /* kg/m^3; 0 = 1100; [100, 20000] */
    float skin_thickness_mm; /* mass of the skin sheet; 0 = 1.5; [0, 20] */
    float damping_ratio;     /* of every spring, c = 2 zeta sqrt(k m); 0 = 0.1;
                                (0, 4] */
} sk_tissue_material_desc;

/* The simulation's clock and its guards. */
typedef struct sk_tissue_simulation_desc {
    int step_hz;              /* fixed internal steps per second; 0 = 240;
                                 [60, 20000]; a multiple of 120 makes 24, 30 and
                                 60 fps frames fall on steps exactly; 480 brings
                                 the jiggle's period closer to the converged one
                                 (docs/tissue.md) at twice the cost */
    int iterations;           /* solver sweeps per step (XPBD converges to implicit
                                 Euler as they grow); 0 = 1; [1, 64] */
    float teleport_speed_m_s; /* a bone end moving faster than this in one step
                                 carries its flesh along instead of stretching
                                 it; 0 = 50; [0.1, 1e6] */
    bool no_fat;              /* skin follows the bones rigidly (no fat layer), for
                                 comparison; default false */
} sk_tissue_simulation_desc;

typedef struct sk_tissue_character_desc {
    char name[SK_TISSUE_NAME_SIZE];
    float motion_unit_mm; /* millimetres per length unit of motion files
                             (root translation); 0 = 10 (cm); [1e-3, 1e4] */
    int joint_count;
    sk_tissue_joint_desc joints[SK_TISSUE_MAX_JOINTS];
    int bone_count;
    sk_tissue_bone_desc bones[SK_TISSUE_MAX_BONES];
    int muscle_count;
    sk_tissue_muscle_desc muscles[SK_TISSUE_MAX_MUSCLES];
    int fat_count;
    sk_tissue_fat_desc fat[SK_TISSUE_MAX_FAT_REGIONS];
    int joint_map_count;
    sk_tissue_joint_map_desc joint_map[SK_TISSUE_MAX_JOINT_MAP];
    int tracked_count;
    sk_tissue_tracked_desc tracked[SK_TISSUE_MAX_TRACKED];
    sk_tissue_skin_desc skin;
    sk_tissue_material_desc material;
    sk_tissue_simulation_desc simulation;
} sk_tissue_character_desc;

/* Preset schema of a character file (presets/tissue/arm.json is an example). */
extern const sk_schema sk_tissue_character_schema;

/* Fills zero fields with their defaults (in place). */
void sk_tissue_character_desc_resolve(sk_tissue_character_desc *desc);
/* Checks a resolved desc: ranges, unique names, references (parents, bones, muscles, map
 * targets), one root, no cycles. Messages name the key path, e.g. "muscles[2].origin.bone
 * = \"radius\" is not a bone (bones: humerus, forearm, hand)". */
sk_result sk_tissue_character_desc_validate(const sk_tissue_character_desc *desc, sk_error *err);
/* Binds a parsed JSON tree (after --set edits), resolves and validates. `desc` is large
 * (allocate it on the heap). */
sk_result sk_tissue_character_bind(const sk_preset *preset, sk_tissue_character_desc *desc,
                                   sk_error *err);
/* Reads, binds, resolves and validates a character file. */
sk_result sk_tissue_character_load(const char *path, sk_tissue_character_desc *desc, sk_error *err);

/* ============================================================ muscle law */
/* Semi-axes of a muscle at attachment distance `length` (sec. 3): rest semi-axes a0, b0
 * (across) and c0 (along) at rest distance rest_length. */
void sk_tissue_muscle_axes(double a0, double b0, double c0, double rest_length, double length,
                           double *a, double *b, double *c);

/* ============================================================ model */
/* The character built for simulation: skeleton, bones, muscles, the generated skin and
 * the classified points and springs. */
typedef struct sk_tissue_model sk_tissue_model;

typedef struct sk_tissue_build_options {
    sk_progress progress; /* fraction of the skin generation done */
} sk_tissue_build_options;

/* Where the time of a build went (seconds) and what it made. */
typedef struct sk_tissue_model_stats {
    int grid[3]; /* grid points along x, y, z */
    double spacing_mm;
    size_t tissue_voxels; /* grid points inside bones or muscles */
    size_t points;        /* grid points above the threshold inside the skin */
    size_t fat_points, skin_points, muscle_points, bone_points;
    size_t springs, skin_springs, skin_fat_springs, fat_springs, anchor_springs;
    size_t skin_triangles;
    size_t removed_cells; /* cells removed to keep the skin manifold */
    double free_mass_kg;  /* fat and skin points */
    double seconds_voxelise, seconds_fat, seconds_dilate, seconds_extract, seconds_classify,
        seconds_springs, seconds_total;
} sk_tissue_model_stats;

sk_result sk_tissue_model_build(const sk_tissue_character_desc *desc,
                                const sk_tissue_build_options *options, sk_tissue_model **out,
                                sk_error *err);
void sk_tissue_model_destroy(sk_tissue_model *model);
/* The memory sk_tissue_model_build peaks at for `desc` (bytes), from its grid (grid[3]
 * points along x, y, z; may be NULL) at SK_TISSUE_BYTES_PER_GRID_POINT, for callers that
 * cap their memory: places the bones and muscles and sizes the grid only. Errors as the
 * build's (a desc out of range, a grid beyond 2^28 points). */
sk_result sk_tissue_model_memory(const sk_tissue_character_desc *desc, double *bytes, int grid[3],
                                 sk_error *err);
/* Peak resident memory of a build over its grid points, rounded up: measured 55, 50 and
 * 45 bytes for the arm at skin.spacing_mm 4, 2 and 1.5 mm and 19 for the body at 3 mm
 * (the springs of the points inside the skin dominate; a character that fills its box
 * more densely needs more). */
#define SK_TISSUE_BYTES_PER_GRID_POINT 64.0

const sk_tissue_character_desc *sk_tissue_model_desc(const sk_tissue_model *model);
sk_tissue_model_stats sk_tissue_model_get_stats(const sk_tissue_model *model);

/* The rest skin as a mesh (positions in mm, area-weighted normals), into a zeroed mesh. */
sk_result sk_tissue_model_rest_skin(const sk_tissue_model *model, sk_mesh *out, sk_error *err);

/* Point classes. */
typedef enum sk_tissue_point_class {
    SK_TISSUE_POINT_SKIN = 0,
    SK_TISSUE_POINT_FAT,
    SK_TISSUE_POINT_MUSCLE,
    SK_TISSUE_POINT_BONE,
    SK_TISSUE_POINT_CLASS_COUNT
} sk_tissue_point_class;

/* The rest positions of one class of points as a point cloud (positions only), with an
 * attribute "owner" (bone or muscle index for bone and muscle points, else -1). */
sk_result sk_tissue_model_points(const sk_tissue_model *model, sk_tissue_point_class cls,
                                 sk_mesh *out, sk_error *err);
/* The rest ellipsoids of the bones (cls BONE) or muscles (cls MUSCLE) as one triangle
 * mesh, `segments` around each (8..256). */
sk_result sk_tissue_model_ellipsoids(const sk_tissue_model *model, sk_tissue_point_class cls,
                                     int segments, sk_mesh *out, sk_error *err);

/* ============================================================ motion */
/* The skeleton's pose at a time: world rotation and position of every character joint. */
typedef struct sk_tissue_pose {
    sk_quatd rotation[SK_TISSUE_MAX_JOINTS];
    sk_vec3d position[SK_TISSUE_MAX_JOINTS]; /* mm */
} sk_tissue_pose;

/* A motion as the simulation samples it: any function of time giving each joint's local
 * rotation (relative to rest) and the root's position. Called at every internal step, in
 * increasing time. */
typedef struct sk_tissue_motion {
    /* local[j]: joint j's rotation relative to its rest frame; root_mm: the root's world
       position. Unset joints keep identity and the rest position. */
    void (*sample)(void *user, double seconds, sk_quatd *local, sk_vec3d *root_mm);
    void *user;
    double duration; /* seconds (for the default frame range) */
} sk_tissue_motion;

/* A BVH bound to a model's skeleton: each character joint takes the rotation of the
 * motion joint of the same name (or bound by the character's joint map, or the same
 * name after a "namespace:" prefix); the root takes the motion root's position times
 * motion_unit_mm (unit_mm > 0 overrides the character's). Frames are interpolated
 * (quaternion slerp, linear position); before the first frame and after the last the end
 * frames hold. Fails with SK_ERROR_NOT_FOUND if no joint binds. */
typedef struct sk_tissue_bvh_motion sk_tissue_bvh_motion;
sk_result sk_tissue_bvh_motion_create(const sk_tissue_model *model, const sk_bvh *bvh,
                                      double unit_mm, sk_tissue_bvh_motion **out, sk_error *err);
void sk_tissue_bvh_motion_destroy(sk_tissue_bvh_motion *motion);
sk_tissue_motion sk_tissue_bvh_motion_get(const sk_tissue_bvh_motion *motion);
/* How many character joints the motion drives; names of those it does not. */
int sk_tissue_bvh_motion_bound_joints(const sk_tissue_bvh_motion *motion);

/* World pose of the model's skeleton from local rotations and the root position. */
void sk_tissue_model_pose(const sk_tissue_model *model, const sk_quatd *local, sk_vec3d root_mm,
                          sk_tissue_pose *out);

/* The shipped motions, generated: an arm curl for presets/tissue/arm.json, a jump and a
 * walk for presets/tissue/body.json (joint names as the character's; cm; 60 fps). */
typedef enum sk_tissue_motion_kind {
    SK_TISSUE_MOTION_CURL = 0,
    SK_TISSUE_MOTION_JUMP,
    SK_TISSUE_MOTION_WALK,
    SK_TISSUE_MOTION_KIND_COUNT
} sk_tissue_motion_kind;
extern const char *const sk_tissue_motion_kind_names[]; /* "curl", "jump", "walk", NULL */
/* Builds the motion's BVH (sk_bvh_init'ed here; free with sk_bvh_free). */
sk_result sk_tissue_make_motion(sk_tissue_motion_kind kind, sk_bvh *out, sk_error *err);

/* ============================================================ simulation */
typedef struct sk_tissue_sim sk_tissue_sim;

/* Starts at time 0 with every point at rest and the bones at the motion's pose at 0 (the
 * flesh carried there rigidly). */
sk_result sk_tissue_sim_create(const sk_tissue_model *model, const sk_tissue_motion *motion,
                               sk_tissue_sim **out, sk_error *err);
void sk_tissue_sim_destroy(sk_tissue_sim *sim);

/* Advances by whole internal steps until the simulated time reaches `seconds` (no-op if
 * it already has). The states depend only on the motion and the model, never on how the
 * calls split the time. */
sk_result sk_tissue_sim_advance(sk_tissue_sim *sim, double seconds, sk_error *err);
/* Steps taken and the simulated time (steps / step_hz). */
int64_t sk_tissue_sim_steps(const sk_tissue_sim *sim);
double sk_tissue_sim_time(const sk_tissue_sim *sim);

/* Skin point positions (3 floats each, mm, in rest-skin vertex order) at `seconds`,
 * advancing as needed; a time between two steps interpolates their states linearly. A
 * time before the last step but one is an error (the simulation keeps two states). */
sk_result sk_tissue_sim_skin(sk_tissue_sim *sim, double seconds, float *xyz, sk_error *err);
/* Where the bones carry each skin point's rest position at the current step (the skin
 * without secondary motion), 3 floats each. */
void sk_tissue_sim_skin_reference(const sk_tissue_sim *sim, float *xyz);

/* Energy of the free points at the current step: spring potential (J) and kinetic energy
 * relative to the bones that carry them (J). */
void sk_tissue_sim_energy(const sk_tissue_sim *sim, double *potential_j, double *kinetic_j);

/* The state (step count, positions and velocities of the fat and skin points, the
 * previous step) as bytes, so a run can be resumed bit for bit. */
size_t sk_tissue_sim_state_size(const sk_tissue_sim *sim);
sk_result sk_tissue_sim_save_state(const sk_tissue_sim *sim, void *buffer, size_t size,
                                   sk_error *err);
sk_result sk_tissue_sim_load_state(sk_tissue_sim *sim, const void *buffer, size_t size,
                                   sk_error *err);
sk_result sk_tissue_sim_save_state_file(const sk_tissue_sim *sim, const char *path, sk_error *err);
sk_result sk_tissue_sim_load_state_file(sk_tissue_sim *sim, const char *path, sk_error *err);

/* ============================================================ a whole run */
/* What `shitsukan tissue run` writes into a folder: rest.obj (the rest skin), skin.pc2 (a
 * point cache of the skin, one sample per output frame, for Blender's Mesh Cache modifier
 * on rest.obj), skin.glb (glTF 2.0, the skin's frames as morph targets), stats.json, and
 * on request frames/NNNN.obj, render/NNNN.png (the skin through the renderer), a plot of
 * the tracked skin points and the final state. skin.glb holds every frame (a morph target
 * each, their weights animated), so it is left out beyond 4096 frames or 400 MB of them
 * (stats.json says whether it was written). Frames are numbered at `fps` from the
 * motion's start; the simulation always runs from time 0 (or a resumed state), whatever
 * frames are written. */
typedef struct sk_tissue_run_desc {
    const char *output_dir;   /* required; created */
    int fps;                  /* output frames per second; 0 = 30; [1, 1000] */
    int first_frame;          /* first frame written; default 0 */
    int last_frame;           /* last frame written; 0 = the motion's end */
    bool obj_frames;          /* frames/NNNN.obj */
    bool render;              /* render/NNNN.png */
    int render_width;         /* pixels; 0 = 480; [64, 4096] */
    bool no_pc2, no_glb;      /* leave those out */
    const char *plot;         /* PNG of the tracked points' displacement, or NULL */
    const char *save_state;   /* the state after the last frame, or NULL */
    const char *resume_state; /* start from this state (at or before first_frame) */
    sk_progress progress;     /* fraction of the frames done */
} sk_tissue_run_desc;

typedef struct sk_tissue_run_stats {
    int frames, first_frame, fps;
    int64_t steps;                                          /* internal steps taken */
    double simulated_seconds;                               /* motion time covered */
    double seconds_simulate, seconds_write, seconds_render; /* wall time */
    double frames_per_second;   /* output frames simulated per wall second */
    double max_displacement_mm; /* largest distance of a skin point from where the
                                   bones carry its rest position */
    double tracked_max_mm[SK_TISSUE_MAX_TRACKED];
    bool glb; /* skin.glb written (not asked for, or too large:
                 more than 4096 frames or 400 MB of frames) */
} sk_tissue_run_stats;

/* Runs the motion on the model and writes the folder (see above). `stats` may be NULL. */
sk_result sk_tissue_run(const sk_tissue_model *model, const sk_tissue_motion *motion,
                        const sk_tissue_run_desc *desc, sk_tissue_run_stats *stats, sk_error *err);

/* ============================================================ outputs */
/* The model's counts and build timings as JSON. */
sk_result sk_tissue_write_model_stats(const sk_tissue_model *model, const char *path,
                                      sk_error *err);
/* The layers into a folder (created): skin.ply, fat.ply, muscle.ply, bone.ply (rest point
 * clouds with an "owner" attribute), bones.obj and muscles.obj (the rest ellipsoids),
 * rest.obj, and layers.png: the layers cut open, rendered. */
sk_result sk_tissue_write_layers(const sk_tissue_model *model, const char *dir, sk_error *err);

#ifdef __cplusplus
}
#endif

#endif /* SHITSUKAN_TISSUE_H */
