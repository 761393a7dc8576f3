/* shitsukan skin: the skin microrelief model of Ishii, Yasuda, Yokoi and Toriwaki (1991):
 * hierarchical Voronoi ridges with perturbed furrows, stretched along a direction, with a
 * Bezier section profile, and bump-mapped shading; plus seamless tiling, physical units,
 * pores and the maps a renderer takes (height, normal, furrow distance, cell id).
 *
 * Coordinates are millimetres on a tile of size_mm[0] x size_mm[1] with x to the right and
 * y up (as texture UV: u = x / width, v = y / height). A map of W x H pixels covers the
 * tile; its top row is at y = height. Levels are numbered from 1 (the paper's first, the
 * largest ridges) to level_count; desc.levels[0] describes level 1.
 *
 * Thread-safety: sk_skin_create / sk_skin_reprofile / sk_skin_destroy need exclusive access
 * to their skin;
 * every other function only reads the skin and may be called from any number of threads
 * at once (sk_skin_eval is allocation-free). */
#ifndef SHITSUKAN_SKIN_H
#define SHITSUKAN_SKIN_H

#include <stdbool.h>
#include <stdint.h>

#include "shitsukan/core.h"
#include "shitsukan/preset.h"
#include "shitsukan/vecmath.h"

#ifdef __cplusplus
extern "C" {
#endif

#define SK_SKIN_MAX_LEVELS 6      /* hierarchy levels (the paper uses up to 3) */
#define SK_SKIN_MAX_SEGMENTS 8    /* Bezier segments of one section profile */
#define SK_SKIN_MAX_CELLS 8000000 /* cells of all levels together */

/* Paper parameter 1, base layout of the centre points. */
typedef enum sk_skin_layout {
    SK_SKIN_LAYOUT_DEFAULT = 0, /* = TRIANGULAR */
    SK_SKIN_LAYOUT_TRIANGULAR,  /* triangular lattice, rows along the stretch x axis */
    SK_SKIN_LAYOUT_SQUARE,      /* square lattice */
    SK_SKIN_LAYOUT_RANDOM       /* uniform random points, as many as the triangular lattice */
} sk_skin_layout;

/* Paper parameter 1, kind of lattice jitter (used by the lattice layouts). */
typedef enum sk_skin_jitter {
    SK_SKIN_JITTER_DEFAULT = 0, /* = UNIFORM */
    SK_SKIN_JITTER_UNIFORM,     /* uniform in the disc of radius jitter_rate * spacing */
    SK_SKIN_JITTER_NORMAL       /* normal, sigma = jitter_rate * spacing / 2 per axis,
                                   truncated to that disc */
} sk_skin_jitter;

/* One cubic Bezier segment of a section profile: 4 control points (x, z). x runs from 0
 * (cell centre) to 10 (cell boundary); z is in tenths of the level's nominal cell radius
 * (spacing_mm / 2), so z = 10 is as high as the cell is wide at its radius. */
typedef struct sk_skin_segment {
    float points[4][2];
} sk_skin_segment;

typedef struct sk_skin_level {
    /* Centre points (paper parameter 1). */
    sk_skin_layout layout; /* default triangular */
    sk_skin_jitter jitter; /* default uniform */
    float jitter_rate;     /* maximum jitter / spacing, [0, 1]; default 0 (exact lattice) */
    float spacing_mm;      /* lattice spacing before stretch, (0, 1000]; 0 = default: level 1
                              0.8 mm, each deeper level 0.4 x the level above */
    /* Edge perturbation by midpoint displacement (parameter 2): at division depth n the
       midpoint moves by V = A 2^(-n h) Rnd L. */
    float perturb_rate;  /* A, [0, 1]; default 0 (straight edges) */
    float perturb_decay; /* h, [0, 4]; default 0 (self-similar) */
    int perturb_depth;   /* division depths, [1, 10]; 0 = default 4 (16 segments) */
    /* Stretch (parameter 3): polygons scaled by Sx along the direction stretch_angle and
       Sy across it, after division and perturbation. */
    float stretch[2];    /* Sx, Sy in (0, 100]; 0 = default 1 */
    float stretch_angle; /* radians, counter-clockwise from +x; default 0 */
    /* Section profile (parameter 5) and roundness (parameter 6). */
    int segment_count; /* [1, SK_SKIN_MAX_SEGMENTS]; 0 = default one segment
                          (0,3)(5,3)(8,2.5)(10,0) (Fig. 13c) */
    sk_skin_segment segments[SK_SKIN_MAX_SEGMENTS]; /* chained: each starts where the
                                previous ends; x non-decreasing from 0 to 10 */
    float roundness; /* [0, 1]: 0 contours similar to the polygon, 1 nearly
                        circular; default 0 */
} sk_skin_level;

/* A kind of pore (not in the paper's figures; the paper describes them in sec. 3.1):
 * a smooth pit of the given radius and depth, (1 - r^2/R^2)^2 in shape. */
typedef struct sk_skin_pore_kind {
    float depth_mm;  /* [0, 10]; default 0 = no pores of this kind */
    float radius_mm; /* (0, 10]; 0 = default 0.03 mm */
    float density;   /* fraction of the candidate places that get a pore, (0, 1];
                        0 = default 0.5 */
} sk_skin_pore_kind;

typedef struct sk_skin_pores {
    sk_skin_pore_kind hair;  /* hair pores at the junctions of level-1 furrows */
    sk_skin_pore_kind sweat; /* sweat pores at the centres of the ridges of sweat_level */
    int sweat_level;         /* [1, level_count]; 0 = default 1 */
} sk_skin_pores;

/* The shaded preview: bump mapping under a directional light (Blinn 1978), Lambert plus a
 * soft Blinn-Phong specular, viewed from straight above. */
typedef struct sk_skin_shading {
    float light_azimuth;   /* radians: direction the light comes from, 0 = from the top of
                              the image (+y), counter-clockwise; default 0 */
    float light_elevation; /* radians above the surface, (0, pi/2]; 0 = default pi/4 */
    float albedo[3];       /* linear RGB in [0, 1]; all 0 = default skin tone
                              (0.80, 0.52, 0.42) */
    float sun_fraction;    /* share of the directional light in the lighting, the rest
                              is uniform sky light; (0, 1]; 0 = default 0.85 */
    float specular;        /* specular strength, [0, 1]; 0 = default 0.06 */
    float shininess;       /* Blinn-Phong exponent, (0, 1000]; 0 = default 24 */
    bool no_specular;      /* true: Lambert only */
} sk_skin_shading;

/* How a level's normal follows from its section profile. */
typedef enum sk_skin_normal_model {
    SK_SKIN_NORMAL_DEFAULT = 0, /* = GRADIENT */
    SK_SKIN_NORMAL_GRADIENT,    /* the exact gradient of the height field: normal maps agree
                                   with the height map (what other renderers need); cells
                                   show creases where the ray meets a polygon corner */
    SK_SKIN_NORMAL_PROFILE      /* the paper's (Fig. 7, sec. 3.2.1 (2)): N = (S_x d, S_z)
                                   with S the normal of the profile drawn along the ray d
                                   from the cell centre (its slope dz/dr): cells read as
                                   round mounds whatever their outline. Not the gradient of
                                   the height where the boundary's distance changes with
                                   the angle. A stretched level takes the ray before the
                                   stretch and stretches the slope with the ridge */
} sk_skin_normal_model;

typedef struct sk_skin_desc {
    uint64_t seed;    /* every random choice derives from it; default 0 */
    float size_mm[2]; /* tile width and height in mm, (0, 1000]; 0 = default 10 */
    bool aperiodic;   /* false (default): the tile wraps seamlessly (periodic
                         Voronoi on a torus); true: no wrap inside the tile */
    int level_count;  /* [1, SK_SKIN_MAX_LEVELS]; 0 = the default skin (3 levels,
                         jittered and perturbed; levels[] is then ignored) */
    sk_skin_level levels[SK_SKIN_MAX_LEVELS];
    sk_skin_normal_model normal_model; /* default gradient */
    sk_skin_pores pores;
    sk_skin_shading shading;
    sk_progress progress; /* progress of sk_skin_create (not part of presets) */
    double max_memory;    /* bytes the cells may take (estimated at SK_SKIN_BYTES_PER_CELL
                             before building); 0 = no cap but SK_SKIN_MAX_CELLS (not part
                             of presets) */
} sk_skin_desc;

/* Memory of one cell of any level, all its structures together (peak resident memory
 * over the cell count, measured on large skins; docs/robustness.md). */
#define SK_SKIN_BYTES_PER_CELL 1600.0

/* The desc with every zero field replaced by its default (the values the model uses). */
sk_skin_desc sk_skin_desc_resolved(const sk_skin_desc *desc);

/* Checks a desc (resolved or not): every range of sk_skin_schema, then the rules it
 * cannot state (a profile's x from 0 to 10, non-decreasing, its segments chained; pores
 * on an existing level). Errors name the key path as in presets, e.g.
 * "levels[1].profile[0].points[2][0] = 12 is out of range [0, 10]". */
sk_result sk_skin_desc_validate(const sk_skin_desc *desc, sk_error *err);

/* Preset schema of sk_skin_desc (keys as in presets/skin/ *.json). */
extern const sk_schema sk_skin_schema;

typedef struct sk_skin sk_skin;

/* Builds the cell hierarchy. Fails with SK_ERROR_INVALID_ARGUMENT for a bad desc,
 * SK_ERROR_LIMIT when it would have more than SK_SKIN_MAX_CELLS cells or, with
 * desc->max_memory, need more memory than that (both checked before building). */
sk_result sk_skin_create(sk_skin **out, const sk_skin_desc *desc, sk_error *err);
void sk_skin_destroy(sk_skin *skin);

/* Gives a built skin the section profiles, roundness, normal model, pores and shading of
 * `desc` without building its cells again (an edit of those keys costs a render, not a
 * build): afterwards the skin renders the same bytes as sk_skin_create gives for `desc`.
 * The keys that place the cells (seed, size_mm, aperiodic, the number of levels and each
 * level's layout, jitter, jitter_rate, spacing_mm, perturb_rate, perturb_decay,
 * perturb_depth, stretch, stretch_angle) must resolve to the skin's own; where one
 * differs it fails with SK_ERROR_UNSUPPORTED naming the key (build a new skin then); a
 * bad desc fails as in sk_skin_create. On failure the skin is unchanged. */
sk_result sk_skin_reprofile(sk_skin *skin, const sk_skin_desc *desc, sk_error *err);

/* What sets two descs apart, as the maps see it (the flags of sk_skin_desc_changes). */
typedef enum sk_skin_change {
    SK_SKIN_CHANGE_CELLS = 1,  /* a key that places the cells: every map may change (and
                                  sk_skin_reprofile refuses it) */
    SK_SKIN_CHANGE_RELIEF = 2, /* the profiles, roundness, normal model or pores: the
                                  height, normal and shaded maps; the cell ids and furrow
                                  distances stay the same bytes */
    SK_SKIN_CHANGE_SHADING = 4 /* the shading: the shaded preview only (the normals stay) */
} sk_skin_change;
/* The changes (sk_skin_change flags; 0 for descs that give the same maps) between two
 * valid descs, compared as resolved. A map a change does not name renders the same
 * bytes for both. */
unsigned sk_skin_desc_changes(const sk_skin_desc *a, const sk_skin_desc *b);

/* The resolved desc the skin was built from (or last re-profiled to). */
const sk_skin_desc *sk_skin_get_desc(const sk_skin *skin);

/* Height (mm above the furrow floor of the paper's profiles; the sum over levels, minus
 * pores) and unit surface normal at (x_mm, y_mm). Any coordinates are accepted: the tile
 * repeats (aperiodic tiles repeat with a larger period). The normal combines the levels'
 * slopes as the paper's Fig. 10 does (normalize(-gx, -gy, 1) with g the sum of the levels'
 * slope vectors); with SK_SKIN_NORMAL_GRADIENT it is the exact normal of the height field
 * (g = the gradient of h), with SK_SKIN_NORMAL_PROFILE each level's slope is its profile's
 * along the ray from its cell centre. Either output may be NULL. Non-finite
 * coordinates give height 0 and normal (0, 0, 1). Allocation-free (about 24 KB of stack) and
 * thread-safe. */
void sk_skin_eval(const sk_skin *skin, double x_mm, double y_mm, float *height_mm,
                  sk_vec3f *normal);

/* Everything known at one point. */
typedef struct sk_skin_sample {
    float height_mm;
    sk_vec3f normal;
    uint32_t cell[SK_SKIN_MAX_LEVELS];   /* cell id of each level (level k at [k-1]) */
    float furrow_mm[SK_SKIN_MAX_LEVELS]; /* distance to the boundary of that cell (only
                                            with SK_SKIN_QUERY_FURROW, else 0) */
} sk_skin_sample;

enum { SK_SKIN_QUERY_FURROW = 1 };

/* Like sk_skin_eval, with the cells of every level and (flag SK_SKIN_QUERY_FURROW) the
 * distance to each level's furrow. Level 1 distances are exact; deeper levels measure in
 * the frame where the levels above are unperturbed (within the perturbation rate). */
void sk_skin_query(const sk_skin *skin, double x_mm, double y_mm, unsigned flags,
                   sk_skin_sample *out);

/* Size of the tile in mm; the repeat period may be larger for aperiodic tiles. */
void sk_skin_tile_size(const sk_skin *skin, double *width_mm, double *height_mm);
/* Bounds of every height the skin can take (from the profiles' control points and the
 * pores, overlapping pits added up): the range used to scale 16-bit height maps. */
void sk_skin_height_range(const sk_skin *skin, float *min_mm, float *max_mm);

/* ------------------------------------------------------------- introspection */
/* Cells of level `level` (1..level_count); 0 for a bad level. */
uint32_t sk_skin_cell_count(const sk_skin *skin, int level);

typedef struct sk_skin_cell_info {
    uint32_t parent;      /* cell of level - 1 (UINT32_MAX at level 1) */
    uint32_t first_child; /* children are first_child .. first_child + child_count - 1 */
    uint32_t child_count; /* at level + 1 (0 at the last level) */
    sk_vec2d centre;      /* where the section profile has its first control point */
    sk_vec2d site;        /* the centre point the Voronoi division started from */
    uint32_t edge_count;  /* polygon edges (before perturbation) */
} sk_skin_cell_info;

sk_result sk_skin_cell_info_get(const sk_skin *skin, int level, uint32_t cell,
                                sk_skin_cell_info *out, sk_error *err);

/* The cell's boundary as the renderer sees it (perturbed, stretched, carried by the
 * perturbation of the levels above), counter-clockwise, in mm, in the tile period nearest
 * the cell's centre; `subdivide` (>= 1) extra points per perturbed segment follow the
 * curvature that the levels above add. Writes up to `max_points` points and returns the
 * total count (call again with a bigger buffer if it is larger). Each edge shared with a
 * neighbour is the same chain of points from both sides. */
size_t sk_skin_cell_outline(const sk_skin *skin, int level, uint32_t cell, int subdivide,
                            sk_vec2d *points, size_t max_points);

/* One edge of that outline (edge 0 .. edge_count - 1, counter-clockwise): its points from
 * its start up to, not including, the next edge's start; `neighbour` receives the cell of
 * the same level across it (UINT32_MAX on a parent's boundary). Same count rules. */
size_t sk_skin_cell_edge(const sk_skin *skin, int level, uint32_t cell, uint32_t edge,
                         int subdivide, uint32_t *neighbour, sk_vec2d *points, size_t max_points);

/* ----------------------------------------------------------------- rendering */
typedef struct sk_skin_render_desc {
    int width, height; /* pixels of the whole map (covering the tile), [1, 65536] */
    int region[4];     /* x, y, w, h in pixels (y from the top row); w = h = 0 (default):
                          the whole map. Pixels are identical to the whole map's. */
    /* Outputs, each NULL or w * h elements (rows top first, row stride w): */
    float *height_mm;  /* mm */
    float *normal;     /* 3 floats: unit tangent-space normal (x right, y up, z out) */
    float *furrow;     /* mm to the nearest furrow of furrow_level */
    uint32_t *cell_id; /* cell of id_level */
    float *preview;    /* 3 floats: shaded linear RGB in [0, 1] */
    float *edges;      /* 3 floats: the preview with every level's furrows drawn in
                          (level 1 red, 2 green, 3 blue, deeper yellow) */
    int furrow_level;  /* 1..level_count; 0 = default 1 */
    int id_level;      /* 1..level_count; 0 = default 1 */
    int samples;       /* preview and edges: samples per pixel side, [1, 8]; 0 = 1 */
    sk_progress progress;
} sk_skin_render_desc;

/* Renders the requested maps (parallel over rows; same bytes for any thread count). */
sk_result sk_skin_render(const sk_skin *skin, const sk_skin_render_desc *desc, sk_error *err);

/* The colour of a cell id in the cells map (linear RGB in [0, 1], a hash of the id). */
void sk_skin_cell_color(uint32_t id, float rgb[3]);

/* Shades one normal with the skin's shading (linear RGB), as the preview does. */
sk_vec3f sk_skin_shade(const sk_skin *skin, sk_vec3f normal);

#ifdef __cplusplus
}
#endif

#endif /* SHITSUKAN_SKIN_H */
