/* The points of the model (Shigemori & Kawai sec. 4): grid points inside the skin are
 * "points"; those on the skin triangles are skin points, those outside the tissue fat
 * points, and those inside a muscle or bone next to a fat point muscle and bone points.
 * Also the rest skin's triangles over the skin points. */
#include <stdlib.h>
#include <string.h>

#include "tissue/tissue_internal.h"

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
        if (cx < 0 || cy < 0 || cz < 0 || cx >= g->n[0] - 1 || cy >= g->n[1] - 1 || cz >= g->n[2] - 1) continue;
        if (inside[sk__grid_index(g, cx, cy, cz)]) return true;
    }
    return false;
}

/* Classes during the build. */
enum { C_OUT = 0, C_SKIN, C_FAT, C_MUSCLE_CANDIDATE, C_BONE_CANDIDATE, C_MUSCLE, C_BONE };

sk_result sk__model_points(sk_tissue_model *m, const sk__skin_build *b, sk_error *err)
{
    const sk__grid *g = b->grid;
    /* skin points: the distinct triangle corners, in grid order */
    size_t nc = 3 * b->triangles;
    size_t *skin = malloc((nc ? nc : 1) * sizeof *skin);
    uint8_t *cls = calloc(g->count, 1);
    if (!skin || !cls) {
        free(skin);
        free(cls);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for the points");
    }
    memcpy(skin, b->corners, nc * sizeof *skin);
    qsort(skin, nc, sizeof *skin, compare_size);
    size_t ns = 0;
    for (size_t i = 0; i < nc; i++)
        if (ns == 0 || skin[ns - 1] != skin[i]) skin[ns++] = skin[i];
    for (size_t i = 0; i < ns; i++) cls[skin[i]] = C_SKIN;

    /* interior points by their tissue label */
    sk__cell_rows rows = {0};
    sk_result rr = sk__cell_rows_make(g, b->inside, &rows, err);
    if (rr != SK_OK) {
        free(skin);
        free(cls);
        return rr;
    }
#pragma omp parallel for schedule(dynamic, 4)
    for (int z = 0; z < g->n[2]; z++)
        for (int y = 0; y < g->n[1]; y++) {
            int x0, x1;
            if (!sk__cell_rows_corners(g, &rows, y, z, &x0, &x1)) continue;
            for (int x = x0; x <= x1; x++) {
                size_t i = sk__grid_index(g, x, y, z);
                if (cls[i] == C_SKIN || !in_volume(g, b->inside, x, y, z)) continue;
                sk__label l = b->labels[i];
                cls[i] = l == SK__LABEL_NONE ? C_FAT : (l >= SK__LABEL_MUSCLE0 ? C_MUSCLE_CANDIDATE : C_BONE_CANDIDATE);
            }
        }
    /* the skin must lie outside the tissue */
    for (size_t i = 0; i < ns; i++)
        if (b->labels[skin[i]] != SK__LABEL_NONE) {
            sk_vec3d p = sk__grid_position(g, skin[i]);
            sk__cell_rows_free(&rows);
            free(skin);
            free(cls);
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "the skin cuts into the tissue at (%.1f, %.1f, %.1f) mm: raise skin.dilations or "
                           "skin.dilation_radius_mm, or lower skin.threshold",
                           p.x, p.y, p.z);
        }
    /* muscle and bone points: tissue points next to a fat point (in the springs'
       neighbourhood), or next to a skin point that has no fat point among its 26
       neighbours (where the skin lies on the tissue, the fat thinner than one spacing) */
    int dirs[13][3], all[13][3];
    int nd = sk__lattice_directions(m->neighbourhood, dirs), na = sk__lattice_directions(26, all);
    uint8_t *touch = calloc(g->count, 1), *on_tissue = calloc(g->count, 1);
    bool near[13];
    for (int k = 0; k < na; k++) near[k] = m->neighbourhood == 26 || sk__lattice_direction_index(dirs, nd, all[k]) >= 0;
    if (!touch || !on_tissue) {
        sk__cell_rows_free(&rows);
        free(touch);
        free(on_tissue);
        free(skin);
        free(cls);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for the points");
    }
#pragma omp parallel for schedule(dynamic, 64)
    for (size_t i = 0; i < ns; i++) {
        int c[3];
        sk__grid_coords(g, skin[i], c);
        bool fat = false;
        for (int k = 0; k < na && !fat; k++)
            for (int sgn = -1; sgn <= 1 && !fat; sgn += 2)
                fat = cls[sk__grid_index(g, c[0] + sgn * all[k][0], c[1] + sgn * all[k][1], c[2] + sgn * all[k][2])] == C_FAT;
        on_tissue[skin[i]] = !fat;
    }
#pragma omp parallel for schedule(dynamic, 4)
    for (int z = 1; z < g->n[2] - 1; z++)
        for (int y = 1; y < g->n[1] - 1; y++) {
            int x0, x1;
            if (!sk__cell_rows_corners(g, &rows, y, z, &x0, &x1)) continue;
            for (int x = x0 > 1 ? x0 : 1; x <= x1 && x < g->n[0] - 1; x++) {
                size_t i = sk__grid_index(g, x, y, z);
                if (cls[i] != C_MUSCLE_CANDIDATE && cls[i] != C_BONE_CANDIDATE) continue;
                bool touches = false;
                for (int k = 0; k < na && !touches; k++)
                    for (int sgn = -1; sgn <= 1 && !touches; sgn += 2) {
                        size_t q = sk__grid_index(g, x + sgn * all[k][0], y + sgn * all[k][1], z + sgn * all[k][2]);
                        touches = (near[k] && cls[q] == C_FAT) || on_tissue[q];
                    }
                if (touches) touch[i] = 1;
            }
        }
    /* candidates that touch become muscle and bone points; counts per slice and class */
    int nz = g->n[2];
    size_t *counts = calloc(3 * ((size_t)nz + 1), sizeof *counts);
    if (!counts) {
        sk__cell_rows_free(&rows);
        free(touch);
        free(on_tissue);
        free(skin);
        free(cls);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for the points");
    }
#pragma omp parallel for schedule(dynamic, 4)
    for (int z = 0; z < nz; z++)
        for (int y = 0; y < g->n[1]; y++) {
            int x0, x1;
            if (!sk__cell_rows_corners(g, &rows, y, z, &x0, &x1)) continue;
            for (int x = x0; x <= x1; x++) {
                size_t i = sk__grid_index(g, x, y, z);
                if (touch[i]) cls[i] = cls[i] == C_MUSCLE_CANDIDATE ? C_MUSCLE : C_BONE;
                int c = cls[i] == C_FAT ? 0 : cls[i] == C_MUSCLE ? 1 : cls[i] == C_BONE ? 2 : -1;
                if (c >= 0) counts[3 * ((size_t)z + 1) + (size_t)c]++;
            }
        }
    free(touch);
    free(on_tissue);
    for (int z = 0; z < nz; z++)
        for (int c = 0; c < 3; c++) counts[3 * ((size_t)z + 1) + (size_t)c] += counts[3 * (size_t)z + (size_t)c];
    size_t nf = counts[3 * (size_t)nz], nm = counts[3 * (size_t)nz + 1], nb = counts[3 * (size_t)nz + 2];
    m->skin_count = ns;
    m->fat_count = nf;
    m->muscle_count = nm;
    m->bone_count = nb;
    m->point_count = ns + nf + nm + nb;
    m->grid_of = malloc(m->point_count * sizeof *m->grid_of);
    m->grid_point = malloc(g->count * sizeof *m->grid_point);
    m->triangles = malloc((b->triangles ? b->triangles : 1) * 3 * sizeof *m->triangles);
    if (!m->grid_of || !m->grid_point || !m->triangles) {
        sk__cell_rows_free(&rows);
        free(counts);
        free(skin);
        free(cls);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for %zu points", m->point_count);
    }
    memcpy(m->grid_of, skin, ns * sizeof *skin);
    /* fat, muscle and bone points each in grid order: slice z starts where the counts of
       the slices before it end */
    const size_t first[3] = {ns, ns + nf, ns + nf + nm};
#pragma omp parallel for schedule(dynamic, 4)
    for (int z = 0; z < nz; z++) {
        size_t next[3];
        for (int c = 0; c < 3; c++) next[c] = first[c] + counts[3 * (size_t)z + (size_t)c];
        for (int y = 0; y < g->n[1]; y++) {
            int x0, x1;
            if (!sk__cell_rows_corners(g, &rows, y, z, &x0, &x1)) continue;
            for (int x = x0; x <= x1; x++) {
                size_t i = sk__grid_index(g, x, y, z);
                int c = cls[i] == C_FAT ? 0 : cls[i] == C_MUSCLE ? 1 : cls[i] == C_BONE ? 2 : -1;
                if (c >= 0) m->grid_of[next[c]++] = i;
            }
        }
    }
    free(counts);
    sk__cell_rows_free(&rows);
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < g->count; i++) m->grid_point[i] = -1;
    for (size_t p = 0; p < m->point_count; p++) m->grid_point[m->grid_of[p]] = (int32_t)p;
    m->triangle_count = b->triangles;
    for (size_t i = 0; i < nc; i++) m->triangles[i] = (uint32_t)m->grid_point[b->corners[i]];
    free(skin);
    free(cls);
    return SK_OK;
}
