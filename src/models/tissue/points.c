/* The points of the model (Shigemori & Kawai sec. 4): grid points inside the skin are
 * "points"; those on the skin triangles are skin points, those outside the tissue fat
 * points, and those inside a muscle or bone next to a fat point muscle and bone points.
 * Also the rest skin's triangles over the skin points. */
#include <stdlib.h>
#include <string.h>

#include "models/tissue/tissue_internal.h"

static int compare_size(const void *a, const void *b)
{
    size_t x = *(const size_t *)a, y = *(const size_t *)b;
    return x < y ? -1 : x > y;
}

/* Whether grid point (x, y, z) is a corner of an inside cell. */
static bool in_volume(const sk__grid *g, const uint8_t *inside, int x, int y, int z)
{
    for (int b = 0; b < 8; b++) {
        int cx = x - (b & 1), cy = y - (b >> 1 & 1), cz = z - (b >> 2 & 1);
        if (cx < 0 || cy < 0 || cz < 0 || cx >= g->n[0] - 1 || cy >= g->n[1] - 1 ||
            cz >= g->n[2] - 1)
            continue;
        if (inside[sk__grid_index(g, cx, cy, cz)]) return true;
    }
    return false;
}

/* Classes during the build. */
enum { C_OUT = 0, C_SKIN, C_FAT, C_MUSCLE_CANDIDATE, C_BONE_CANDIDATE, C_MUSCLE, C_BONE };

/* The fat, muscle and bone point classes in point order (-1: not one of them). */
static int interior_class(uint8_t c)
{
    return c == C_FAT ? 0 : c == C_MUSCLE ? 1 : c == C_BONE ? 2 : -1;
}

/* What the classification holds while it runs. */
typedef struct classify {
    const sk__grid *g;
    const sk__skin_build *b;
    size_t *skin; /* distinct skin grid points, in grid order */
    size_t skin_count;
    uint8_t *cls; /* a class per grid point */
    uint8_t *touch, *on_tissue;
    size_t *counts; /* fat, muscle and bone points per slice, then their running sums */
    sk__cell_rows rows;
} classify;

static void classify_free(classify *c)
{
    sk__cell_rows_free(&c->rows);
    free(c->skin);
    free(c->cls);
    free(c->touch);
    free(c->on_tissue);
    free(c->counts);
}

static sk_result out_of_memory(sk_error *err)
{
    return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for the points");
}

/* Skin points: the distinct triangle corners, in grid order. */
static sk_result mark_skin(classify *c, sk_error *err)
{
    size_t nc = 3 * c->b->triangles;
    c->skin = malloc((nc ? nc : 1) * sizeof *c->skin);
    c->cls = calloc(c->g->count, 1);
    if (!c->skin || !c->cls) return out_of_memory(err);
    memcpy(c->skin, c->b->corners, nc * sizeof *c->skin);
    qsort(c->skin, nc, sizeof *c->skin, compare_size);
    size_t ns = 0;
    for (size_t i = 0; i < nc; i++)
        if (ns == 0 || c->skin[ns - 1] != c->skin[i]) c->skin[ns++] = c->skin[i];
    c->skin_count = ns;
    for (size_t i = 0; i < ns; i++) c->cls[c->skin[i]] = C_SKIN;
    /* the skin must lie outside the tissue */
    for (size_t i = 0; i < ns; i++)
        if (c->b->labels[c->skin[i]] != SK__LABEL_NONE) {
            sk_vec3d p = sk__grid_position(c->g, c->skin[i]);
            return sk_fail(
                err, SK_ERROR_INVALID_ARGUMENT,
                "the skin cuts into the tissue at (%.1f, %.1f, %.1f) mm: raise skin.dilations or "
                "skin.dilation_radius_mm, or lower skin.threshold",
                p.x, p.y, p.z);
        }
    return SK_OK;
}

/* Interior points by their tissue label: fat, or muscle and bone candidates. */
static void mark_interior(classify *c)
{
    const sk__grid *g = c->g;
    const sk__skin_build *b = c->b;
#pragma omp parallel for schedule(dynamic, 4)
    for (int z = 0; z < g->n[2]; z++)
        for (int y = 0; y < g->n[1]; y++) {
            int x0, x1;
            if (!sk__cell_rows_corners(g, &c->rows, y, z, &x0, &x1)) continue;
            for (int x = x0; x <= x1; x++) {
                size_t i = sk__grid_index(g, x, y, z);
                if (c->cls[i] == C_SKIN || !in_volume(g, b->inside, x, y, z)) continue;
                sk__label l = b->labels[i];
                c->cls[i] = l == SK__LABEL_NONE
                                ? C_FAT
                                : (l >= SK__LABEL_MUSCLE0 ? C_MUSCLE_CANDIDATE : C_BONE_CANDIDATE);
            }
        }
}

/* Muscle and bone points: tissue points next to a fat point (in the springs'
   neighbourhood), or next to a skin point that has no fat point among its 26 neighbours
   (where the skin lies on the tissue, the fat thinner than one spacing). */
static sk_result mark_touching(classify *c, int neighbourhood, sk_error *err)
{
    const sk__grid *g = c->g;
    int dirs[13][3], all[13][3];
    int nd = sk__lattice_directions(neighbourhood, dirs), na = sk__lattice_directions(26, all);
    bool near[13];
    for (int k = 0; k < na; k++)
        near[k] = neighbourhood == 26 || sk__lattice_direction_index(dirs, nd, all[k]) >= 0;
    c->touch = calloc(g->count, 1);
    c->on_tissue = calloc(g->count, 1);
    if (!c->touch || !c->on_tissue) return out_of_memory(err);
    const uint8_t *cls = c->cls;
#pragma omp parallel for schedule(dynamic, 64)
    for (size_t i = 0; i < c->skin_count; i++) {
        int q[3];
        sk__grid_coords(g, c->skin[i], q);
        bool fat = false;
        for (int k = 0; k < na && !fat; k++)
            for (int sgn = -1; sgn <= 1 && !fat; sgn += 2)
                fat = cls[sk__grid_index(g, q[0] + sgn * all[k][0], q[1] + sgn * all[k][1],
                                         q[2] + sgn * all[k][2])] == C_FAT;
        c->on_tissue[c->skin[i]] = !fat;
    }
#pragma omp parallel for schedule(dynamic, 4)
    for (int z = 1; z < g->n[2] - 1; z++)
        for (int y = 1; y < g->n[1] - 1; y++) {
            int x0, x1;
            if (!sk__cell_rows_corners(g, &c->rows, y, z, &x0, &x1)) continue;
            for (int x = x0 > 1 ? x0 : 1; x <= x1 && x < g->n[0] - 1; x++) {
                size_t i = sk__grid_index(g, x, y, z);
                if (cls[i] != C_MUSCLE_CANDIDATE && cls[i] != C_BONE_CANDIDATE) continue;
                bool touches = false;
                for (int k = 0; k < na && !touches; k++)
                    for (int sgn = -1; sgn <= 1 && !touches; sgn += 2) {
                        size_t q = sk__grid_index(g, x + sgn * all[k][0], y + sgn * all[k][1],
                                                  z + sgn * all[k][2]);
                        touches = (near[k] && cls[q] == C_FAT) || c->on_tissue[q];
                    }
                if (touches) c->touch[i] = 1;
            }
        }
    return SK_OK;
}

/* Candidates that touch become muscle and bone points; the counts per slice and class,
   summed so that slice z's points start where the slices before it end. */
static sk_result count_classes(classify *c, sk_error *err)
{
    const sk__grid *g = c->g;
    int nz = g->n[2];
    c->counts = calloc(3 * ((size_t)nz + 1), sizeof *c->counts);
    if (!c->counts) return out_of_memory(err);
#pragma omp parallel for schedule(dynamic, 4)
    for (int z = 0; z < nz; z++)
        for (int y = 0; y < g->n[1]; y++) {
            int x0, x1;
            if (!sk__cell_rows_corners(g, &c->rows, y, z, &x0, &x1)) continue;
            for (int x = x0; x <= x1; x++) {
                size_t i = sk__grid_index(g, x, y, z);
                if (c->touch[i]) c->cls[i] = c->cls[i] == C_MUSCLE_CANDIDATE ? C_MUSCLE : C_BONE;
                int k = interior_class(c->cls[i]);
                if (k >= 0) c->counts[3 * ((size_t)z + 1) + (size_t)k]++;
            }
        }
    for (int z = 0; z < nz; z++)
        for (int k = 0; k < 3; k++)
            c->counts[3 * ((size_t)z + 1) + (size_t)k] += c->counts[3 * (size_t)z + (size_t)k];
    return SK_OK;
}

/* The model's points (skin, then fat, muscle and bone, each in grid order) and triangles. */
static sk_result make_points(sk_tissue_model *m, const classify *c, sk_error *err)
{
    const sk__grid *g = c->g;
    int nz = g->n[2];
    size_t ns = c->skin_count;
    const size_t *total = c->counts + 3 * (size_t)nz;
    m->skin_count = ns;
    m->fat_count = total[0];
    m->muscle_count = total[1];
    m->bone_count = total[2];
    m->point_count = ns + total[0] + total[1] + total[2];
    m->grid_of = malloc(m->point_count * sizeof *m->grid_of);
    m->grid_point = malloc(g->count * sizeof *m->grid_point);
    m->triangles = malloc((c->b->triangles ? c->b->triangles : 1) * 3 * sizeof *m->triangles);
    if (!m->grid_of || !m->grid_point || !m->triangles)
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for %zu points", m->point_count);
    memcpy(m->grid_of, c->skin, ns * sizeof *c->skin);
    const size_t first[3] = {ns, ns + total[0], ns + total[0] + total[1]};
#pragma omp parallel for schedule(dynamic, 4)
    for (int z = 0; z < nz; z++) {
        size_t next[3];
        for (int k = 0; k < 3; k++) next[k] = first[k] + c->counts[3 * (size_t)z + (size_t)k];
        for (int y = 0; y < g->n[1]; y++) {
            int x0, x1;
            if (!sk__cell_rows_corners(g, &c->rows, y, z, &x0, &x1)) continue;
            for (int x = x0; x <= x1; x++) {
                size_t i = sk__grid_index(g, x, y, z);
                int k = interior_class(c->cls[i]);
                if (k >= 0) m->grid_of[next[k]++] = i;
            }
        }
    }
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < g->count; i++) m->grid_point[i] = -1;
    for (size_t p = 0; p < m->point_count; p++) m->grid_point[m->grid_of[p]] = (int32_t)p;
    m->triangle_count = c->b->triangles;
    for (size_t i = 0; i < 3 * c->b->triangles; i++)
        m->triangles[i] = (uint32_t)m->grid_point[c->b->corners[i]];
    return SK_OK;
}

sk_result sk__model_points(sk_tissue_model *m, const sk__skin_build *b, sk_error *err)
{
    classify c = {.g = b->grid, .b = b};
    sk_result r = mark_skin(&c, err);
    if (r == SK_OK) r = sk__cell_rows_make(c.g, b->inside, &c.rows, err);
    if (r == SK_OK) {
        mark_interior(&c);
        r = mark_touching(&c, m->neighbourhood, err);
    }
    if (r == SK_OK) r = count_classes(&c, err);
    if (r == SK_OK) r = make_points(m, &c, err);
    classify_free(&c);
    return r;
}
