/* Private data of the skin model (Ishii et al. 1991): the cell hierarchy, shared edges
 * with their midpoint-displacement polylines, and the per-level query structures.
 *
 * Frames. Level k is built in the frame F(k-1) in which the levels above it are
 * unperturbed: its cells are straight convex polygons there (Voronoi cells of its centre
 * points, clipped to the straight parent). Its perturbation is a homeomorphism of F(k-1)
 * supported in small triangles around its edges ("supports"): it moves each straight
 * edge onto its perturbed polyline. Undoing it ("unwarp") gives F(k), where level k is
 * straight again and level k + 1 lives. F(0) is the world. A query walks down the levels:
 * locate the cell in F(k-1), unwarp into F(k), evaluate level k's section profile there.
 * Children therefore tile their perturbed parent exactly, with no clipping of curves.
 *
 * Each level is built in its own pre-stretch space z = M^-1 y (M = that level's stretch)
 * and stored in y coordinates; lines and perturbation vectors fold M in.
 * Level-1 cells are stored around their site in a canonical tile period; all their
 * descendants use the same frame (no wrapping below level 1). */
#ifndef SK_SKIN_INTERNAL_H
#define SK_SKIN_INTERNAL_H

#include <math.h>
#include <stdint.h>

#include "shitsukan/skin.h"

#define SK__SKIN_NONE UINT32_MAX

/* One side of an edge as seen by a cell (cells list their uses counter-clockwise). */
typedef struct sk__use {
    float vx, vy;       /* start vertex of the edge (y space, cell frame) */
    float nx, ny, d;    /* outward unit normal and offset: inside is n . y <= d */
    float shx, shy;     /* add to a point of this cell's frame to get the edge's frame */
    uint32_t edge;      /* edge record of this level, or SK__SKIN_NONE (a piece of the
                           parent's boundary, or an unpaired degenerate edge) */
    uint32_t neighbour; /* cell across the edge at this level, or SK__SKIN_NONE */
    float bulge;        /* how far the edge's perturbed polyline strays from this line (the
                           edge record's bulge; 0 for a straight side) */
} sk__use;

/* Per-pixel query records, one of each per use, laid out so that one record (one cache
 * line) answers one test (query_records.c).
 *
 * Fan triangle k of a cell: the site, vertex k and vertex k + 1. A point inside it by a
 * margin lies in the cell, and use k's line is the one the ray from the site meets: the
 * fan decides which edge's perturbation can reach the point (locate.c). */
typedef struct sk__fan {
    float sx, sy;     /* site */
    float ax, ay, an; /* vertex k minus the site; margin (|ax| + |ay|) * SK__SECTOR_MARGIN */
    float bx, by, bn; /* vertex k + 1 minus the site; margin */
    float gx, gy;     /* gauge from the site: n / (d - n . site) (<= 1 inside the cell) */
    float shx, shy;   /* add to a point of the cell's frame to get the edge's frame */
    uint32_t edge;    /* perturbed edge record, or SK__SKIN_NONE (nothing to unwarp) */
    uint32_t cell;    /* the cell */
    uint32_t parent;  /* its parent (SK__SKIN_NONE at level 1) */
    float gcut;       /* below this gauge a point is clear of the edge's perturbation
                         support (with a margin far above rounding) */
} sk__fan;

/* Sector k of a cell seen from its profile centre (centre, vertex k, vertex k + 1), where
 * x' is 10 times the gauge of edge k, and the pair of edge normals k, k + 1 that frames
 * the roundness (profile.c). */
typedef struct sk__sector {
    float cx, cy;     /* profile centre */
    float ax, ay, an; /* vertex k minus the centre; margin */
    float bx, by, bn; /* vertex k + 1 minus the centre; margin */
    float gx, gy;     /* gauge from the centre: n_k / h_k */
    float nx, ny, h;  /* normal of edge k, distance h_k from the centre to its line */
    float mx, my, hm; /* the same for edge k + 1 */
} sk__sector;

/* A shared edge, perturbed once (paper sec. 3.2.1 (1), midpoint displacement). Geometry
 * in y space in the frame of its left cell. With s the signed distance from the straight
 * edge (positive towards the left site) and t in [0, 1] along it:
 *   t = at . (y - a), s = as . (y - a); the polyline is s = f(t);
 * the perturbation lives in the support |s| < H(t) (a triangle over the edge on each side,
 * inside the two cells' fan triangles), H(t) = h_apex min(t / t_apex, (1-t) / (1-t_apex)). */
typedef struct sk__edge {
    float ax, ay;   /* start point a */
    float bx, by;   /* end point b */
    float atx, aty; /* gradient of t */
    float asx, asy; /* gradient of s: the unit normal towards the left site */
    float dx, dy;   /* displacement per unit of s (the same unit normal) */
    float t_apex, h_apex;
    float rise, fall; /* slopes of H: h_apex / t_apex and h_apex / (1 - t_apex) */
    float bulge;      /* max |f| times |d|: how far the polyline strays (y units) */
    float shx, shy;   /* right frame = left frame - shift */
    uint32_t left, right;
    uint32_t f_first; /* first of the level's f values for this edge (f_count of them) */
} sk__edge;

typedef struct sk__cell {
    float sx, sy; /* site (centre point of the Voronoi division), y space */
    float zx, zy; /* site in pre-stretch space (nearest-sibling search) */
    float cx, cy; /* centre of the section profile: centroid of the straight cell */
    uint32_t parent;
    uint32_t first_child, child_count;
    uint32_t first_use, use_count;
} sk__cell;

/* A cubic Bezier chain in (x, z) (paper sec. 3.2.1 (2), parameter 5). */
#define SK__PROFILE_TABLE 256
#define SK__GUESS_G 8   /* steps of g in the Newton guess table */
#define SK__GUESS_X 128 /* steps of x' in it */
typedef struct sk__profile {
    int segment_count;
    float x[SK_SKIN_MAX_SEGMENTS][4];
    float z[SK_SKIN_MAX_SEGMENTS][4];
    /* z(x) of each segment at SK__PROFILE_TABLE even steps of x (exact values and slopes
       from the Bezier), as the cubic Hermite curve of each step in power form:
       z = a0 + u (a1 + u (a2 + u a3)), u in [0, 1] across the step */
    float zpoly[SK_SKIN_MAX_SEGMENTS][SK__PROFILE_TABLE - 1][4];
    float last_start; /* x where the last segment starts */
    /* The last segment under roundness (its end stays at 10, so it is not a scaled copy):
       power-basis coefficients of Bx and Bz (xd3 = xc3 - 10, zd = the derivative's), and
       a first guess of t for Newton's method over (g, x'), g from 1 - roundness to 1,
       bilinear in each cell: t = b0 + b1 xf + gf (b2 + b3 xf). */
    float last_xc[4], last_xd3, last_zc[4], last_zd[3];
    float g_min, g_step_inv;
    float t_guess[SK__GUESS_G][SK__GUESS_X][4];
    float seg_x0[SK_SKIN_MAX_SEGMENTS], seg_inv_w[SK_SKIN_MAX_SEGMENTS]; /* table mapping */
    float z_min, z_max; /* bounds of the control points */
} sk__profile;
/* Fills the tables of a profile whose control points are set. */
void sk__profile_prepare(sk__profile *p);

/* Level-1 lookup grid over the tile: each square lists the (cell, tile shift) pairs whose
 * straight polygon meets it. */
typedef struct sk__grid {
    int nx, ny;
    double inv_w, inv_h; /* squares per mm */
    uint32_t *start;     /* nx * ny + 1 */
    uint32_t *cell;
    double *shift; /* 2 per entry: origin of the cell's frame in this tile period */
} sk__grid;

typedef struct sk__level {
    uint32_t cell_count, use_count, edge_count;
    sk__cell *cells;
    sk__use *uses;
    sk__edge *edges;
    sk__fan *fans;       /* per use */
    sk__sector *sectors; /* per use */
    double *vxy;         /* use start vertices in double (2 per use), for clipping */
    float *f;            /* perturbation offsets, f_count per edge */
    int depth;           /* division depths; f_count = 2^depth + 1 */
    double amp[11];      /* midpoint displacement amplitude A 2^(-n h) at depth n */
    int f_count;
    float f_step; /* 1 / (f_count - 1): t from one f value to the next */
    bool perturbed;
    double m[2][2], minv[2][2]; /* stretch and its inverse */
    float minvf[2][2];
    sk__profile profile;
    float roundness;
    float z_scale; /* mm per profile z unit: spacing / 20 */
    float spacing; /* nominal spacing (mm, before stretch) */
} sk__level;

typedef struct sk__pore {
    float x, y; /* world, inside the tile period */
    float radius, depth;
} sk__pore;

/* A pore as a bucket's point sees it: its centre moved by the period where it lies across
 * the wrap from the bucket. */
typedef struct sk__pore_near {
    double x, y;
    float radius, depth;
} sk__pore_near;

/* Pores bucketed on a grid over the tile period (bucket size >= the largest radius): each
 * bucket lists the pores of itself and its 8 neighbours, neighbour by neighbour (rows from
 * below, left to right), each neighbour's in its own order. */
typedef struct sk__pore_grid {
    int nx, ny;
    double inv_w, inv_h;
    uint32_t *start; /* nx * ny + 1 */
    sk__pore_near *near;
    uint32_t count; /* pores */
    float max_radius;
} sk__pore_grid;

struct sk_skin {
    sk_skin_desc desc; /* resolved */
    int level_count;
    double period[2]; /* repeat period in mm (the tile, or more when aperiodic) */
    double tile[2];   /* the tile (the map's extent) */
    sk__level levels[SK_SKIN_MAX_LEVELS];
    sk__grid grid;  /* level 1 */
    double *origin; /* level-1 cell frames: the site in the tile period (2 per cell);
                       cells of every level store coordinates relative to the site
                       of their level-1 ancestor */
    sk__pore_grid pores;
    float height_min, height_max;
    /* shading, resolved */
    float light[3], half[3], albedo[3], sun, sky, spec, shininess;
    int shininess_int; /* the exponent if it is a whole number up to 1000, else 0 */
};

/* The smaller of two numbers that are not NaN (fmin is a library call without fast-math). */
static inline double sk__min(double a, double b) { return b < a ? b : a; }
/* min(t / apex, (1 - t) / (1 - apex)) for apex in (0, 1): the tent over [0, 1] peaking at
 * 1 at the apex; the smaller quotient is the one on t's side of the apex (one division). */
static inline double sk__tent(double t, double apex)
{
    return t < apex ? t / apex : (1.0 - t) / (1.0 - apex);
}

/* Construction loops over fewer items (cells, edges, points of a level) run on one
 * thread: starting and joining threads and the spinning of idle ones cost more than the
 * work, and on a loaded machine each join can wait a whole time slice for a descheduled
 * thread. The two heavy steps, clipping the cells and perturbing the edges (several
 * microseconds an item, three quarters of a build), go parallel from SK__PARALLEL_HEAVY_ITEMS,
 * in small dynamic chunks so that a thread held up by the machine's other work leaves its
 * share to the other: the finest level of the paper's figures builds about 30 % faster on
 * 2 threads than on one, under load too (docs/skin.md). */
#define SK__PARALLEL_ITEMS 50000
#define SK__PARALLEL_HEAVY_ITEMS 4096
/* Renders of fewer pixel-levels (pixels x levels x samples) run on one thread. */
#define SK__PARALLEL_PIXELS 32768

/* Wraps a coordinate into [0, period). */
static inline double sk__wrap(double v, double period)
{
    if (v >= 0.0 && v < period) return v;
    double r = v - period * floor(v / period);
    return (r >= period || r < 0.0) ? 0.0 : r;
}

/* ---- construction pieces (one file each) */
/* Centre points of a level over the period torus (layout.c). Returns the points in y
 * space, wrapped into [0, period). */
sk_result sk__layout_points(const sk_skin *skin, int level, double **xy, uint32_t *count,
                            sk_error *err);
/* Stretch matrix M = R(angle) diag(sx, sy) R(-angle) and its inverse (stretch.c). */
void sk__stretch_matrices(const sk_skin_level *lv, double m[2][2], double minv[2][2]);

/* Convex polygon with a tag per edge (edge i runs from v[i] to v[i+1]) (clip.c). */
#define SK__POLY_MAX 256
typedef struct sk__poly {
    int n;
    double x[SK__POLY_MAX], y[SK__POLY_MAX];
    int64_t tag[SK__POLY_MAX];
} sk__poly;
/* Keeps the part with nx * x + ny * y <= d; new edge tagged `tag`. Returns false when
 * the polygon would overflow SK__POLY_MAX. */
bool sk__poly_clip(sk__poly *p, double nx, double ny, double d, int64_t tag);
/* Centroid of the polygon (x[i], y[i]), i < n. */
void sk__polygon_centroid(const double *x, const double *y, int n, double *cx, double *cy);

/* Level 1: periodic Voronoi cells (voronoi.c). */
sk_result sk__build_level1(sk_skin *skin, const double *xy, uint32_t count, sk_error *err);
/* Levels 2..: children of every parent, clipped to it (hierarchy.c). */
sk_result sk__build_children(sk_skin *skin, int level, const double *xy, uint32_t count,
                             sk_error *err);
/* Shared edge tables: pairs the two uses of every edge and fills the edge records and
 * their perturbation (edges.c). `keys` holds per use the integers identifying its edge:
 * k0 = (left cell << 32 | right cell) and k1, the same from both sides, and its side. */
enum { SK__SIDE_LEFT, SK__SIDE_RIGHT, SK__SIDE_NONE };
typedef struct sk__edge_key {
    uint64_t k0, k1; /* identity of the edge (same from both sides) */
    uint8_t side;    /* SK__SIDE_LEFT / RIGHT, or NONE for a use that is no shared edge */
} sk__edge_key;
sk_result sk__build_edges(sk_skin *skin, int level, const sk__edge_key *keys,
                          const double *site_left_y, sk_error *err);
/* Builds the fan and sector records of a finished level (query_records.c). */
sk_result sk__build_query_records(sk__level *lv, sk_error *err);
/* Midpoint displacement of one edge (perturb.c). */
void sk__perturb_edge(const sk_skin *skin, int level, uint64_t edge_key, double length,
                      double t_apex, double h_apex, float *f);
/* The perturbation support of an edge from its left site (perturb.c). */
void sk__support(double ax, double ay, double bx, double by, double px, double py, double *t_apex,
                 double *h_apex);

/* What a built skin can change without moving its cells (reprofile.c): level k's section
 * profile tables and roundness, the height range (after the pores), the shading. */
void sk__level_profile_setup(sk_skin *skin, int k);
void sk__height_range(sk_skin *skin);
void sk__shading_setup(sk_skin *skin);

/* Level-1 lookup grid (grid.c). */
sk_result sk__build_grid(sk_skin *skin, sk_error *err);
/* Pores (pores.c). */
sk_result sk__build_pores(sk_skin *skin, sk_error *err);
void sk__pores_eval(const sk_skin *skin, double x, double y, float *h, float grad[2]);
/* A bound of the deepest pit the pores make anywhere (overlapping pores add up). */
float sk__pores_deepest(const sk_skin *skin);

/* ---- queries */
/* Locates the level-1 cell of world point (x, y) (straight cells, no perturbation):
 * returns the cell and the point in its frame (locate.c). */
uint32_t sk__locate_level1(const sk_skin *skin, double x, double y, float *px, float *py,
                           uint32_t *use, double shift[2]);
/* Nearest sibling among the children of `parent` at level `level` (0-based). */
uint32_t sk__locate_child(const sk__level *lv, uint32_t first, uint32_t count, float px, float py);
/* Fan triangle of point p in cell c: the use whose line the ray from the site through p
 * meets first. */
uint32_t sk__fan_use(const sk__level *lv, uint32_t c, float px, float py);
/* Unwarps point p (frame of fan f's cell) across the perturbed edge of f, if p lies in
 * that edge's support: returns the owner cell (f's cell or its neighbour), moves p into the
 * owner's frame and straight cell, multiplies jac by the unwarp's Jacobian and writes the
 * point before the unwarp in the owner's frame to pre (left alone outside the support). */
uint32_t sk__unwarp(const sk__level *lv, const sk__fan *f, float *px, float *py, float jac[2][2],
                    float *pre_x, float *pre_y);
/* Relative margin of the sector tests (far above float rounding). */
#define SK__SECTOR_MARGIN 1e-4f

/* True if p is inside fan triangle f by a margin: then f's cell holds p and f is its fan,
 * exactly as the full gauge would find. */
static inline bool sk__in_fan(const sk__fan *f, float px, float py)
{
    float qx = px - f->sx, qy = py - f->sy;
    float q1 = fabsf(qx) + fabsf(qy);
    return f->ax * qy - f->ay * qx > q1 * f->an && qx * f->by - qy * f->bx > q1 * f->bn &&
           f->gx * qx + f->gy * qy < 1.0f - SK__SECTOR_MARGIN;
}
/* The straight cell of `level` (0-based) containing a point of the tile period, going down
 * the levels without perturbation (frame F(level)); writes the point in the cell's frame. */
uint32_t sk__locate_straight(const sk_skin *skin, int level, double x, double y, float *px,
                             float *py);
/* Moves a point of the straight cell c of level index k (frame F(k+1)) to the world:
 * the warps of level k and every level above; returns world coordinates (not wrapped). */
void sk__to_world(const sk_skin *skin, int k, uint32_t c, double px, double py, double *wx,
                  double *wy);

/* Section profiles of m points at each of levels 0 .. L-1: item i = k m + p is point p at
 * level k, at (px[i], py[i]) of cell cell[i] (straight frame of that level): height z[i]
 * in mm and gradient grad[i] (mm per mm, in that frame). sector[k] is the hinted sector of
 * level k (UINT32_MAX for none), updated to the sector found. The items run side by side,
 * step by step: their long dependency chains (square root, divisions, Newton step) overlap
 * in the processor (profile.c). */
void sk__profile_eval(const sk_skin *skin, int L, int m, const uint32_t *cell, const float *px,
                      const float *py, uint32_t *sector, float *z, float (*grad)[2]);
/* Bezier chain helpers (bezier.c). Where the roundness scale g < 1 moves x' into the last
 * segment: a Newton solve of Bx(t) = x' in two halves, the table's guess (with 1 / Bx'),
 * then the step, z and its slopes; elsewhere the scaled copy of the profile, z(x' / g). */
typedef struct sk__newton {
    float c[4];   /* power basis of Bx at this g */
    float t, inv; /* guess of t and 1 / Bx'(t) */
} sk__newton;
void sk__last_segment_guess(const sk__profile *p, float g, float xq, sk__newton *s);
float sk__last_segment_finish(const sk__profile *p, float xq, const sk__newton *s, float *dz_dx,
                              float *dz_dg);
float sk__profile_scaled(const sk__profile *p, float g, float xq, float *dz_dx, float *dz_dg);
/* Cells found by the previous query of a row of pixels: tried first, and kept only where
 * the point is inside them by a margin, so results never depend on the hint. */
typedef struct sk__hint {
    uint32_t fan[SK_SKIN_MAX_LEVELS];    /* fan record (use) of the site's fan triangle */
    uint32_t sector[SK_SKIN_MAX_LEVELS]; /* use (index in the cell) of the centre's sector */
    double shift[2];                     /* level-1 frame of fan[0] */
} sk__hint;
void sk__hint_reset(sk__hint *hint);
/* Internal query flag: furrow distance of level k only when bit (SK__FURROW_LEVEL_SHIFT + k)
 * is set (SK_SKIN_QUERY_FURROW asks for every level). */
#define SK__FURROW_LEVEL_SHIFT 8
/* Internal query flag: the query walks down only the first D levels, D in the bits from
 * SK__QUERY_DEPTH_SHIFT (0: every level), and evaluates no section profile or pore: the
 * cells and furrow distances of those levels are the same as a full query's, the heights
 * and normals are left flat, the deeper levels' cells SK__SKIN_NONE. For renders of only
 * cell ids and furrow distances. */
#define SK__QUERY_DEPTH_SHIFT 16
#define SK__QUERY_DEPTH(d) ((unsigned)(d) << SK__QUERY_DEPTH_SHIFT)
/* Points a query runs side by side (their long dependency chains overlap). */
#define SK__QUERY_BATCH 32
/* The query behind sk_skin_query for n <= SK__QUERY_BATCH points, with an optional hint
 * (eval.c). Each point's result is the same as on its own. */
void sk__query(const sk_skin *skin, int n, const double *x, const double *y, unsigned flags,
               sk_skin_sample *out, sk__hint *hint);

/* The perturbed polygon of a cell of `level` (1-based) in the frame where its level is
 * built, before the levels above carry it (outline.c): its own edges' polylines and the
 * straight pieces of its parent's boundary. Same count rules as sk_skin_cell_outline. */
size_t sk__cell_polygon(const sk_skin *skin, int level, uint32_t cell, sk_vec2d *points,
                        size_t max_points);

/* Distance from p (frame of cell c, F(k-1)) to the perturbed boundary of c (furrow.c). */
float sk__furrow_distance(const sk__level *lv, uint32_t c, float px, float py);

/* ---- schema */
/* The keys of one level (schema.c): the defaults of every level, also those beyond
 * level_count, come from it. */
extern const sk_schema sk__skin_level_schema;

#endif /* SK_SKIN_INTERNAL_H */
