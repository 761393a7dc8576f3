/* shitsukan wood: a 3D solid texture of wood built from the tree's structure (Kawai 2000,
 * "Modeling fiber stream of internal wood"): annual rings with fluctuation, grain (spiral,
 * wavy, interlocked, tabulated, fractal) as a coordinate transform, vessels (diffuse- and
 * ring-porous), the fibre brightness-shift texture, the figure sheen of eq. (4) and a 3D
 * fibre highlight in the manner of Marschner et al. 2005; beyond the paper, knots (as
 * Larsson et al. 2022 model them, the grain flowing round them) and broad rays; planar
 * cuts to images.
 *
 * Units: millimetres and radians (preset keys ending in _deg are degrees). Colours in the
 * desc are sRGB-encoded in [0, 1] (as artists type them); every output colour is linear.
 *
 * Thread-safety: an sk_wood is immutable after sk_wood_create; sk_wood_eval, sk_wood_shade
 * and sk_wood_cut may be called on one sk_wood from any number of threads at once.
 * sk_wood_eval and sk_wood_shade never allocate. */
#ifndef SHITSUKAN_WOOD_H
#define SHITSUKAN_WOOD_H

#include "shitsukan/core.h"
#include "shitsukan/preset.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ------------------------------------------------------------------ desc */

/* Placement of the tree (log) in the scene: scene = Rz Ry Rx tree + translate. The tree
 * frame has its axis (pith) along +y, y = 0 at the ground, the end grain in the xz plane. */
typedef struct sk_wood_transform {
    float translate_mm[3]; /* scene position of the pith at tree y = 0; default 0 */
    float rotate[3];       /* Euler angles X, Y, Z in radians (preset key "rotate_deg");
                              default 0: tree axis = scene +y */
} sk_wood_transform;

typedef struct sk_wood_log_desc {
    float radius_mm; /* radius the ring and phase tables cover (points beyond see rings
                        continued with the outermost width); 0 = 150; [1, 2000] */
    float length_mm; /* period along the axis of the grain fluctuation dg (the phase table
                        repeats after it); 0 = 1000; [10, 100000] */
} sk_wood_log_desc;

/* Annual rings R(t, theta) (sec. 4.4) and their earlywood/latewood profile (sec. 6.3). */
typedef struct sk_wood_rings_desc {
    float width_mm;          /* d: mean growth per year; 0 = 3; [0.05, 50] */
    float width_variation;   /* year-to-year variation of the width (sd of its log); default
                                0 (every year alike); [0, 1] */
    float fluctuation;       /* relative amplitude of the width's variation around the ring
                                (fractal noise): rings stop being round; default 0; [0, 0.9] */
    float fluctuation_lobes; /* about how many bulges a ring has; 0 = 4; [0.5, 64] */
    float fluctuation_years; /* years over which a bulge persists; 0 = 10; [0.25, 1000] */
    float latewood_fraction; /* fraction of each ring that is latewood; 0 = 0.3; [0.01, 0.99] */
    float transition;        /* fraction of the ring over which earlywood turns linearly into
                                latewood before the latewood band; default 0 (abrupt);
                                [0, 0.99] */
    float earlywood_srgb[3]; /* earlywood colour; all 0 = (0.82, 0.64, 0.44) */
    float latewood_srgb[3];  /* latewood colour; all 0 = (0.62, 0.42, 0.25) */
} sk_wood_rings_desc;

/* One point of a tabulated grain function g(y) (linear between points, constant beyond). */
typedef struct sk_wood_grain_point {
    float y_mm;
    float slope; /* g = r dtheta/dy at that height */
} sk_wood_grain_point;

#define SK_WOOD_MAX_GRAIN_POINTS 64

/* The grain G'(t, y) = g'(y) + dg'(t, y) of eq. (1) / sec. 4.4; the terms add up. A slope
 * is the tangent of the fibre's angle to the axis on its ring (G = r dtheta/dy). */
typedef struct sk_wood_grain_desc {
    float spiral_slope;             /* g1 of spiral grain; default 0; [-2, 2] */
    float wavy_amplitude;           /* A of wavy grain g = A sin(y / lambda); default 0; [-2, 2] */
    float wavy_wavelength_mm;       /* lambda (the paper's: the period is 2 pi lambda); must be
                                       > 0 when wavy_amplitude != 0; [0, 100000] */
    float interlocked_slope;        /* s of interlocked grain g = s sin(2 pi t / P), the slope
                                       alternating with the growth layer; default 0; [-2, 2] */
    float interlocked_period_years; /* P; must be > 0 when interlocked_slope != 0; [0, 1000] */
    int table_count;                /* number of points in `table`; default 0 (no table) */
    sk_wood_grain_point table[SK_WOOD_MAX_GRAIN_POINTS]; /* user g(y), y ascending */
    float fluctuation;          /* bound on |dg|, fractal in (t, y); default 0; [0, 1] */
    float fluctuation_scale_mm; /* correlation length of dg along y; 0 = 50; [1, 10000] */
    float fluctuation_years;    /* correlation of dg across growth years; 0 = 5; [0.25, 1000] */
} sk_wood_grain_desc;

/* Diffuse-porous vessels (sec. 5.3): n = rho x area centres uniform over the end grain,
 * one in each cell of a square grid of cell area 1 / rho (spread like real pores). */
typedef struct sk_wood_diffuse_vessels {
    float density_per_mm2; /* rho; default 0 = none; [0, 400] */
    float radius_mm;       /* mean radius; 0 = 0.03; [0.002, 2] */
    float radius_sd_mm;    /* standard deviation of the radius (Normal, cut at 3 sd);
                              default 0; [0, 1] */
} sk_wood_diffuse_vessels;

/* Ring-porous vessels (sec. 5.4): rows of large vessels at the start of every ring. */
typedef struct sk_wood_ring_vessels {
    float linear_density; /* P: ring j (radius j d) holds round(P j d) vessels per row, at
                             theta_k = 2 pi k / (P j d); default 0 = none; [0, 100] */
    float radius_mm;      /* mean radius; 0 = 0.12; [0.002, 2] */
    float radius_sd_mm;   /* default 0; [0, 1] */
    int rows;             /* rows of vessels in the earlywood band; 0 = 1; [1, 8] */
    float jitter;         /* random displacement as a fraction of the spacing; default 0;
                             [0, 1] */
} sk_wood_ring_vessels;

typedef struct sk_wood_vessels_desc {
    sk_wood_diffuse_vessels diffuse;
    sk_wood_ring_vessels ring;
    float color_srgb[3]; /* colour of an open vessel (pore); all 0 = (0.20, 0.13, 0.08) */
} sk_wood_vessels_desc;

/* Broad rays (medullary rays; beyond Kawai 2000, who names the radial tissues in sec. 3.2
 * and as future work in sec. 8): ribbons of ray tissue running out from the pith, thin
 * around the tree (`width_mm`), tall along it (`height_mm`), `length_mm` long radially,
 * one every `spacing_mm` round a ring, placed on the end grain and carried by the grain
 * transform like everything else. Their cells run radially, so a quarter-sawn face (a
 * ray's own plane) shows them as broad shiny flecks (the silver figure of oak) and a
 * flat-sawn face as short lines. */
typedef struct sk_wood_rays_desc {
    float spacing_mm;    /* distance between rays round a ring; default 0 = none; [0.2, 100] */
    float width_mm;      /* width round the tree at a ray's middle; 0 = 0.4; [0.01, 5] */
    float height_mm;     /* height along the fibre; 0 = 20; [0.1, 1000] */
    float length_mm;     /* length out from the pith; 0 = 50; [1, 5000] */
    float jitter;        /* randomness of places and sizes; default 0; [0, 1] */
    float color_srgb[3]; /* colour of the ray tissue; all 0 = (0.86, 0.76, 0.60) */
} sk_wood_rays_desc;

/* How the brightness shift of sec. 6 changes a cell. */
typedef enum sk_wood_shift_mode {
    SK_WOOD_SHIFT_DEFAULT = 0, /* = ADD */
    SK_WOOD_SHIFT_ADD,         /* the paper's (sec. 6.3): the cell's brightness (its sRGB-encoded
                                  value) plus an independent shift uniform in
                                  [-shift / 2, +shift / 2], clamped to [0, 1] */
    SK_WOOD_SHIFT_MULTIPLY,    /* the colour times (1 - shift u), u uniform in [0, 1): darkens
                                  only */
    SK_WOOD_SHIFT_COUNT
} sk_wood_shift_mode;

/* Shifting brightness (sec. 6): every cell of the end-grain array C'(t, theta) gets an
 * independent random brightness shift, then is seen through the grain transform as fibre
 * streaks. Cells follow the rings: rows of cell_mm in t (at the mean ring width), each row
 * cut into cells of about cell_mm around the tree, like the radial files of wood cells. */
typedef struct sk_wood_fibre_desc {
    float brightness_shift;        /* the spread of the cells' shifts: added, at most this much
                                      brighter or darker from cell to cell (Fig. 7: 0.4 = 40 %);
                                      default 0; [0, 1] */
    sk_wood_shift_mode shift_mode; /* preset key "shift_mode": "add" or "multiply" */
    float cell_mm;                 /* cell size of the end-grain array; 0 = 0.08; [0.005, 10] */
    float length_mm;               /* length of a fibre: along the fibre the cell's shift is drawn
                                      anew every length_mm (ends staggered); default 0 = endless,
                                      the paper's projection; [0, 10000] */
} sk_wood_fibre_desc;

/* Knots (beyond Kawai 2000, as Larsson et al. 2022 model them): branches in whorls along
 * the stem, each a cone from the pith whose own rings grow by `growth` times the stem's
 * ring width a year. Branch and stem are one growth layer a year (their formation times
 * merged by a smooth minimum): while the branch lives it is a sound knot with the rings
 * curving into it. After `dead_after_years` it stops growing: further out it is a dead
 * knot of constant size in a ring of bark, the stem's later rings wrapping round it, for
 * `stub_mm`, then overgrown. The stem's fibres flow round every knot (a smooth deflection
 * of the grain, like a stream round a post), and the knot's own end grain is darker. */
typedef struct sk_wood_knots_desc {
    float whorl_spacing_mm; /* distance between whorls along the axis; default 0 = no knots;
                               [20, 100000] */
    int per_whorl;          /* branches per whorl; 0 = 4; [1, 12] */
    float rise;             /* a branch's angle above the horizontal, radians (key
                               "rise_deg"); default 0; [-10, 80] degrees */
    float growth;           /* a branch's ring width over the stem's (the cone's slope);
                               0 = 0.12; [0.01, 1] */
    float dead_after_years; /* years the branch lives; default 0 = alive throughout;
                               [0, 1000] */
    float stub_mm;          /* how far the dead branch reaches out of the stem before it is
                               overgrown; 0 = 40; [0.1, 1000] */
    float jitter;           /* randomness of whorl heights, branch azimuths, angles and
                               sizes; default 0; [0, 1] */
    float darkening;        /* the knot's wood (end grain) darker by this fraction; 0 = 0.4;
                               [0, 1] */
    float bark_mm;          /* width of the bark ring round a dead knot; 0 = 0.8; [0.01, 20] */
    float bark_srgb[3];     /* its colour; all 0 = (0.24, 0.15, 0.09) */
    float collar;           /* width of the smooth union of branch and stem rings (how far
                               the rings curve round a knot), a fraction of the knot's age;
                               0 = 0.5; [0.01, 2] */
    float deflection_reach; /* how far the grain bends round a knot, in knot radii; 0 = 3;
                               [1.1, 20] */
} sk_wood_knots_desc;

typedef enum sk_wood_shading_model {
    SK_WOOD_SHADING_DEFAULT = 0, /* = FIGURE */
    SK_WOOD_SHADING_FIGURE,      /* eq. (4): kd cos(delta) + ks cos^n(delta - alpha) */
    SK_WOOD_SHADING_FIBRE,       /* 3D fibre highlight under a clear finish (Marschner et al.
                                    2005): diffuse + finish reflection + fibre cone lobe */
    SK_WOOD_SHADING_COUNT
} sk_wood_shading_model;

typedef struct sk_wood_shading_desc {
    sk_wood_shading_model model; /* preset key "model": "figure" or "fibre" */
    /* eq. (4) */
    float specular; /* ks; default 0 (no sheen); [0, 1] */
    float diffuse;  /* kd; 0 = 1 - specular; [0, 1] */
    float exponent; /* n; 0 = 64; [1, 100000] */
    /* 3D fibre highlight */
    float fibre_strength;  /* k_f, scale of the fibre lobe; 0 = 0.5; [0, 100] */
    float fibre_width;     /* beta, width of the Gaussian lobe in radians (key
                              "fibre_width_deg"); 0 = 8 degrees; [0.5, 60] degrees */
    float fibre_srgb[3];   /* colour of the fibre highlight; all 0 = (0.95, 0.80, 0.60) */
    float finish_ior;      /* refractive index of the clear finish; 0 = 1.5; [1, 3] */
    float finish_exponent; /* Blinn-Phong exponent of the finish's own highlight; 0 = 400;
                              [1, 100000] */
} sk_wood_shading_desc;

typedef enum sk_wood_plane {
    SK_WOOD_PLANE_DEFAULT = 0, /* = FLAT */
    SK_WOOD_PLANE_END,         /* cross-cut: normal along the tree axis, image x = tree x,
                                  image up = -tree z */
    SK_WOOD_PLANE_FLAT,        /* flat-sawn (tangential): plane z = distance, image up = tree top */
    SK_WOOD_PLANE_QUARTER,     /* quarter-sawn (radial): plane z = 0, centred at x = distance */
    SK_WOOD_PLANE_COUNT
} sk_wood_plane;

/* The default framing of a planar cut (used by the command line and sk_wood_view_cut). */
typedef struct sk_wood_view_desc {
    sk_wood_plane plane;   /* preset key "plane": "end", "flat" or "quarter" */
    float distance_mm;     /* flat: distance of the plane from the pith; quarter: distance of
                              the view centre from the pith; end: offset of the centre along
                              tree x; 0 = half the log radius (flat, quarter), 0 (end);
                              [0, 10000] */
    float height_mm;       /* tree y of the view centre; default 0; [-100000, 100000] */
    float width_mm;        /* width of the view; 0 = 100; [0.01, 100000] */
    float tilt;            /* rotation of the plane about the image's horizontal axis, radians
                              (key "tilt_deg"); default 0; [-90, 90] degrees */
    float light_incidence; /* delta of eq. (4): the light turned from the normal towards the
                              image top (for flat and quarter cuts the tree top), radians (key
                              "light_deg"); default 0; [-89, 89] degrees */
    float light_azimuth;   /* the light's plane turned about the normal, radians (key
                              "light_azimuth_deg"); default 0; [-180, 180] degrees */
    float view_incidence;  /* the viewer turned from the normal towards the image top, radians
                              (key "view_deg"); default 0; [-89, 89] degrees */
} sk_wood_view_desc;

typedef struct sk_wood_desc {
    uint64_t seed; /* every random value derives from (seed, stable ids); default 0 */
    sk_wood_transform transform;
    sk_wood_log_desc log;
    sk_wood_rings_desc rings;
    sk_wood_grain_desc grain;
    sk_wood_vessels_desc vessels;
    sk_wood_rays_desc rays;
    sk_wood_fibre_desc fibre;
    sk_wood_knots_desc knots;
    sk_wood_shading_desc shading;
    sk_wood_view_desc view;
} sk_wood_desc;

/* The desc with every zero default filled in (colours stay sRGB). */
sk_wood_desc sk_wood_desc_resolved(const sk_wood_desc *desc);

/* Checks a desc (resolved or not): ranges, NaN, and the rules the schema cannot state
 * (a wavelength / period where its amplitude is set, table points ascending, vessels that
 * fit in a ring: 2 (radius + 3 sd) rows <= rings.width_mm). Messages name the key path,
 * e.g. "grain.wavy_wavelength_mm = 0 must be > 0 when grain.wavy_amplitude = 0.2". */
sk_result sk_wood_desc_validate(const sk_wood_desc *desc, sk_error *err);

/* Preset schema of sk_wood_desc (key paths as in the field comments above). */
extern const sk_schema sk_wood_schema;

/* ------------------------------------------------------------------ tree */

typedef struct sk_wood sk_wood;

/* Sets up the tree: ring tables R and T (with their search index and per-ring bounds for
 * the ring-porous vessel index), the phase table Phi(t, y) and the shading tables.
 * Vessels are generated from hashes on demand, so their number costs no memory. Fails
 * with the validation message on a bad desc, SK_ERROR_LIMIT if the log needs more than
 * SK_WOOD_MAX_RINGS rings. */
#define SK_WOOD_MAX_RINGS 4096
sk_result sk_wood_create(const sk_wood_desc *desc, sk_wood **out, sk_error *err);
void sk_wood_destroy(sk_wood *wood);

/* The resolved desc the tree was built from. */
const sk_wood_desc *sk_wood_get_desc(const sk_wood *wood);

typedef struct sk_wood_stats {
    size_t memory_bytes;     /* everything the tree holds */
    double setup_seconds;    /* wall time of sk_wood_create */
    int ring_count;          /* rings covered by the tables */
    int ring_table_size[2];  /* R(t, theta): t samples x theta samples */
    int phase_table_size[2]; /* Phi(t, y): t samples x y samples (0 x 0 without dg) */
} sk_wood_stats;
void sk_wood_get_stats(const sk_wood *wood, sk_wood_stats *stats);

/* ------------------------------------------------------------------ evaluation */

typedef struct sk_wood_sample {
    sk_vec3f albedo; /* linear RGB: ring profile, brightness shift, vessels */
    float vessel;    /* vessel (pore) coverage in [0, 1] */
    sk_vec3f fibre;  /* unit fibre direction in the scene frame, oriented up the tree */
    float dive;      /* alpha: dive angle of the fibre under the surface, radians,
                        positive when the fibre goes into the wood towards the tree top */
    sk_vec3f up;     /* unit direction on the surface towards the tree top (delta > 0
                        side of eq. 4); any tangent if the surface is end grain */
    float t;         /* formation time T(r, theta) in years (ring index = floor) */
    float latewood;  /* latewood weight of the ring profile in [0, 1] */
    float phase;     /* phi of eq. (3), radians */
} sk_wood_sample;

/* Evaluates the solid texture at a scene point with the surface's unit normal there
 * (the normal only matters for the dive angle and `up`). */
void sk_wood_eval(const sk_wood *wood, sk_vec3f point, sk_vec3f normal, sk_wood_sample *sample);

/* As sk_wood_eval, with a filter footprint (the pixel's size on the surface, mm) that
 * softens ring edges and vessel outlines over that width (0 = point sampling). */
void sk_wood_eval_filtered(const sk_wood *wood, sk_vec3f point, sk_vec3f normal, float footprint_mm,
                           sk_wood_sample *sample);

/* Light reflected towards `view` for unit incident light from `light` (unit vectors from
 * the surface point; `normal` the unit surface normal), linear RGB, by the desc's shading
 * model:
 *  FIGURE: albedo kd cos(delta) + ks cos^n(delta - alpha) (1 - vessel), with
 *          delta = atan2(light . up, light . normal), alpha = asin(-fibre . normal) (the
 *          sample's dive when it was evaluated with this normal) and the diffuse cosine
 *          light . normal (0 when the light is below the surface); `view` is not used
 *          (eq. 4 was derived for a view along the normal);
 *  FIBRE:  pi cos(theta_i) times the sum of the finish's Fresnel-weighted Blinn-Phong
 *          highlight and, through the finish (Fresnel transmittances in and out), the
 *          diffuse albedo / pi and the fibre lobe k_f g(beta, psi_h) / cos^2(psi_d / 2) /
 *          eta^2 on the cone around the sample's fibre (Marschner et al. 2005).
 * Both give 1 for a white diffuse surface lit along its normal. Thread-safe. */
sk_vec3f sk_wood_shade(const sk_wood *wood, const sk_wood_sample *sample, sk_vec3f normal,
                       sk_vec3f light, sk_vec3f view);

/* ------------------------------------------------------------------ planar cuts */

/* A planar cut through the solid texture rendered into caller buffers. Pixel (x, y) of
 * the full width x height image samples the plane point
 *   point + ((x + 0.5) / width - 0.5) width_mm axis + (0.5 - (y + 0.5) / height) height_mm up
 * with up = normal x axis and height_mm = width_mm height / width, so any region holds
 * exactly the full image's pixels. */
typedef struct sk_wood_cut_desc {
    sk_vec3f point;        /* centre of the image on the plane, scene frame, mm */
    sk_vec3f normal;       /* plane normal, towards the viewer (need not be unit) */
    sk_vec3f axis;         /* image x direction (projected onto the plane and normalised) */
    float width_mm;        /* physical width of the full image */
    int width, height;     /* full image size in pixels [1, 65536] */
    int region[4];         /* x, y, w, h of the part to render; all 0 = the full image */
    int samples;           /* samples per pixel along each axis (stratified grid); 0 = 1; [1, 8] */
    float light_incidence; /* light turned from the normal towards the image top (radians) */
    float light_azimuth;   /* the light's plane turned about the normal (radians) */
    float view_incidence;  /* viewer turned from the normal towards the image top (radians) */
    /* Outputs (caller buffers of region w x h pixels, row-major, top row first; NULL =
       not wanted): */
    float *shaded; /* RGB linear: sk_wood_shade under the light above */
    float *albedo; /* RGB linear */
    float *fibre;  /* RGB: 0.5 + 0.5 f with f the unit fibre direction (up the tree) in the
                      cut's frame (x = image right, y = image up, z = towards the viewer) */
    float *vessel; /* 1 channel: pore coverage */
    float *dive;   /* 1 channel: dive angle alpha in radians */
    sk_progress progress;
} sk_wood_cut_desc;

sk_result sk_wood_cut(const sk_wood *wood, const sk_wood_cut_desc *desc, sk_error *err);

/* Fills the plane, width and light/view angles of `cut` from the tree's view desc
 * (end / flat / quarter, distance, height, tilt, width) in the scene frame. */
void sk_wood_view_cut(const sk_wood *wood, const sk_wood_view_desc *view, sk_wood_cut_desc *cut);

/* Names of the enums as used in presets ("figure", "fibre"; "end", "flat", "quarter";
 * "add", "multiply"). */
extern const char *const sk_wood_shading_model_names[];
extern const char *const sk_wood_plane_names[];
extern const char *const sk_wood_shift_mode_names[];

#ifdef __cplusplus
}
#endif

#endif /* SHITSUKAN_WOOD_H */
