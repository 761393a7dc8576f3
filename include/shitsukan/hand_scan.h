/* shitsukan hand scan: the scan-to-surface pipeline of Yasumuro's thesis (2000,
 * sec. 4.1.1-4.1.5) on the surface of hand_surface.h. */
#ifndef SHITSUKAN_HAND_SCAN_H
#define SHITSUKAN_HAND_SCAN_H

#include "shitsukan/hand_pictures.h"
#include "shitsukan/hand_surface.h"
#include "shitsukan/image.h"
#include "shitsukan/mesh.h"

#ifdef __cplusplus
extern "C" {
#endif

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
                                 range [1e-6, 50] */
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
                               fraction; 0 = 1e-3; range [-1, 0.5] (negative = never) */
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

/* Preset schemas (src/models/hand_scan/schema.c): sk_hand_scan_desc and its scanner. */
extern const sk_schema sk_hand_scan_schema, sk_hand_scanner_schema;

#ifdef __cplusplus
}
#endif

#endif /* SHITSUKAN_HAND_SCAN_H */
