/* The skin surface (Shigemori & Kawai sec. 4): "an isosurface at the threshold whose
 * triangle vertices always lie on grid points". Taken as the boundary of the union of
 * grid cells whose eight corners are all points (the cuberille family, not edge-
 * interpolated marching cubes). Cells not connected to the tissue are dropped, and where
 * the boundary would pinch (two cells meeting at an edge or a corner only, inside or
 * outside) cells are removed until every vertex's neighbourhood is a disc. Each boundary
 * face is a quad of four grid points, split into two triangles. */
#include <stdlib.h>
#include <string.h>

#include "models/tissue/tissue_internal.h"

static int components(int mask, int *label); /* face-connected components of a mask */

/* ok[mask] = 1: the 2x2x2 cells around a vertex (bit dx + 2 dy + 4 dz set when inside)
 * give a manifold boundary there: the inside cells and the outside cells are each face
 * connected (or empty). */
static void make_table(uint8_t ok[256])
{
    for (int m = 0; m < 256; m++) {
        int label[8];
        ok[m] = components(m, label) <= 1 && components(~m & 255, label) <= 1;
    }
}

static int components(int mask, int *label)
{
    int n = 0;
    for (int i = 0; i < 8; i++) label[i] = -1;
    for (int i = 0; i < 8; i++) {
        if (!(mask >> i & 1) || label[i] >= 0) continue;
        int stack[8], top = 0;
        stack[top++] = i;
        label[i] = n;
        while (top) {
            int c = stack[--top];
            for (int b = 0; b < 3; b++) {
                int nb = c ^ (1 << b);
                if ((mask >> nb & 1) && label[nb] < 0) {
                    label[nb] = n;
                    stack[top++] = nb;
                }
            }
        }
        n++;
    }
    return n;
}

static size_t cell_of(const sk__grid *g, int x, int y, int z) { return sk__grid_index(g, x, y, z); }

sk_result sk__cell_rows_make(const sk__grid *g, const uint8_t *inside, sk__cell_rows *rows,
                             sk_error *err)
{
    size_t n = (size_t)g->n[1] * (size_t)g->n[2];
    rows->lo = malloc(n * sizeof *rows->lo);
    rows->hi = malloc(n * sizeof *rows->hi);
    if (!rows->lo || !rows->hi) {
        sk__cell_rows_free(rows);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for the skin cells");
    }
#pragma omp parallel for schedule(static)
    for (size_t r = 0; r < n; r++) {
        const uint8_t *row = inside + r * (size_t)g->n[0];
        int lo = g->n[0], hi = -1;
        for (int x = 0; x < g->n[0]; x++)
            if (row[x]) {
                if (lo > x) lo = x;
                hi = x;
            }
        rows->lo[r] = lo;
        rows->hi[r] = hi;
    }
    return SK_OK;
}

void sk__cell_rows_free(sk__cell_rows *rows)
{
    free(rows->lo);
    free(rows->hi);
    rows->lo = rows->hi = NULL;
}

bool sk__cell_rows_corners(const sk__grid *g, const sk__cell_rows *rows, int y, int z, int *lo,
                           int *hi)
{
    *lo = g->n[0];
    *hi = -1;
    for (int cz = z - 1; cz <= z; cz++)
        for (int cy = y - 1; cy <= y; cy++) {
            if (cy < 0 || cz < 0 || cy >= g->n[1] || cz >= g->n[2]) continue;
            size_t r = (size_t)cz * (size_t)g->n[1] + (size_t)cy;
            if (rows->lo[r] > rows->hi[r]) continue;
            if (rows->lo[r] < *lo) *lo = rows->lo[r];
            if (rows->hi[r] + 1 > *hi) *hi = rows->hi[r] + 1;
        }
    return *lo <= *hi;
}

static int vertex_mask(const sk__grid *g, const uint8_t *inside, int x, int y, int z)
{
    int m = 0;
    for (int b = 0; b < 8; b++)
        if (inside[cell_of(g, x - 1 + (b & 1), y - 1 + (b >> 1 & 1), z - 1 + (b >> 2 & 1))])
            m |= 1 << b;
    return m;
}

/* Removes cells around vertex (x, y, z) so its neighbourhood becomes manifold: inside
 * cells outside the largest inside component, or (when the outside is split) the inside
 * cells touching the smallest outside component. Returns the number removed. */
static int fix_vertex(const sk__grid *g, const uint8_t *ok, uint8_t *inside, int x, int y, int z)
{
    int m = vertex_mask(g, inside, x, y, z);
    if (ok[m]) return 0;
    int label[8], size[8] = {0};
    int n = components(m, label);
    int remove = 0;
    if (n > 1) {
        for (int i = 0; i < 8; i++)
            if (label[i] >= 0) size[label[i]]++;
        int keep = 0;
        for (int c = 1; c < n; c++)
            if (size[c] > size[keep]) keep = c;
        for (int i = 0; i < 8; i++)
            if (label[i] >= 0 && label[i] != keep) remove |= 1 << i;
    } else {
        int out = ~m & 255;
        int no = components(out, label);
        for (int i = 0; i < 8; i++)
            if (label[i] >= 0) size[label[i]]++;
        int smallest = 0;
        for (int c = 1; c < no; c++)
            if (size[c] < size[smallest]) smallest = c;
        for (int i = 0; i < 8; i++)
            if (label[i] == smallest)
                for (int b = 0; b < 3; b++)
                    if (m >> (i ^ (1 << b)) & 1) remove |= 1 << (i ^ (1 << b));
    }
    for (int b = 0; b < 8; b++)
        if (remove >> b & 1)
            inside[cell_of(g, x - 1 + (b & 1), y - 1 + (b >> 1 & 1), z - 1 + (b >> 2 & 1))] = 0;
    return remove;
}

typedef struct worklist {
    size_t *v;
    size_t count, cap, head;
} worklist;

static bool push(worklist *w, size_t vertex)
{
    if (w->count == w->cap) {
        size_t cap = w->cap ? 2 * w->cap : 4096;
        size_t *v = realloc(w->v, cap * sizeof *v);
        if (!v) return false;
        w->v = v;
        w->cap = cap;
    }
    w->v[w->count++] = vertex;
    return true;
}

/* Removes cells until every vertex with all 8 cells in the grid is manifold: the vertices
 * found bad in one parallel scan are fixed in index order, and the corners of every
 * removed cell are checked again, so the result does not depend on the thread count. */
static sk_result make_manifold(const sk__grid *g, const uint8_t *ok, uint8_t *inside,
                               size_t *removed, sk_error *err)
{
    int nz = g->n[2];
    uint8_t *bad_slice = calloc((size_t)nz, 1);
    sk__cell_rows rows = {0};
    if (!bad_slice) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for the skin cells");
    sk_result r = sk__cell_rows_make(g, inside, &rows, err);
    if (r != SK_OK) {
        free(bad_slice);
        return r;
    }
#pragma omp parallel for schedule(dynamic, 4)
    for (int z = 1; z < nz - 1; z++)
        for (int y = 1; y < g->n[1] - 1 && !bad_slice[z]; y++) {
            int x0, x1;
            if (!sk__cell_rows_corners(g, &rows, y, z, &x0, &x1)) continue;
            for (int x = x0 > 1 ? x0 : 1; x <= x1 && x < g->n[0] - 1; x++)
                if (!ok[vertex_mask(g, inside, x, y, z)]) {
                    bad_slice[z] = 1;
                    break;
                }
        }
    worklist w = {0};
    bool fine = true;
    for (int z = 1; z < nz - 1 && fine; z++)
        for (int y = 1; bad_slice[z] && y < g->n[1] - 1 && fine; y++)
            for (int x = 1; x < g->n[0] - 1 && fine; x++)
                if (!ok[vertex_mask(g, inside, x, y, z)])
                    fine = push(&w, sk__grid_index(g, x, y, z));
    sk__cell_rows_free(&rows);
    *removed = 0;
    while (fine && w.head < w.count) {
        int c[3];
        sk__grid_coords(g, w.v[w.head++], c);
        int gone = fix_vertex(g, ok, inside, c[0], c[1], c[2]);
        for (int b = 0; b < 8 && fine; b++) {
            if (!(gone >> b & 1)) continue;
            (*removed)++;
            /* the removed cell's 8 corners are the vertices whose neighbourhood changed */
            int cx = c[0] - 1 + (b & 1), cy = c[1] - 1 + (b >> 1 & 1), cz = c[2] - 1 + (b >> 2 & 1);
            for (int k = 0; k < 8 && fine; k++) {
                int vx = cx + (k & 1), vy = cy + (k >> 1 & 1), vz = cz + (k >> 2 & 1);
                if (vx < 1 || vy < 1 || vz < 1 || vx > g->n[0] - 2 || vy > g->n[1] - 2 ||
                    vz > g->n[2] - 2)
                    continue;
                if (!ok[vertex_mask(g, inside, vx, vy, vz)])
                    fine = push(&w, sk__grid_index(g, vx, vy, vz));
            }
        }
    }
    free(w.v);
    free(bad_slice);
    if (!fine) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for the skin cells");
    return SK_OK;
}

/* Keeps the face-connected groups of inside cells that reach a tissue point. */
static sk_result keep_tissue_components(const sk__grid *g, const sk__label *labels, uint8_t *inside,
                                        sk_error *err)
{
    size_t *queue = malloc(g->count * sizeof *queue);
    uint8_t *seen = calloc(g->count, 1);
    if (!queue || !seen) {
        free(queue);
        free(seen);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for the skin cells");
    }
    size_t head = 0, tail = 0;
    const ptrdiff_t step[6] = {1,
                               -1,
                               g->n[0],
                               -(ptrdiff_t)g->n[0],
                               (ptrdiff_t)g->n[0] * g->n[1],
                               -(ptrdiff_t)g->n[0] * g->n[1]};
    for (size_t c = 0; c < g->count; c++) {
        if (!inside[c]) continue;
        bool tissue = false;
        for (int b = 0; b < 8 && !tissue; b++)
            tissue =
                labels[c + (size_t)(b & 1) + (size_t)(b >> 1 & 1) * (size_t)g->n[0] +
                       (size_t)(b >> 2 & 1) * (size_t)g->n[0] * (size_t)g->n[1]] != SK__LABEL_NONE;
        if (tissue) {
            seen[c] = 1;
            queue[tail++] = c;
        }
    }
    while (head < tail) {
        size_t c = queue[head++];
        for (int k = 0; k < 6; k++) {
            ptrdiff_t q = (ptrdiff_t)c + step[k];
            if (q < 0 || (size_t)q >= g->count || !inside[q] || seen[q]) continue;
            seen[q] = 1;
            queue[tail++] = (size_t)q;
        }
    }
    for (size_t c = 0; c < g->count; c++) inside[c] = inside[c] && seen[c];
    free(queue);
    free(seen);
    return SK_OK;
}

sk_result sk__skin_cells(const sk__grid *g, const uint8_t *is_point, const sk__label *labels,
                         uint8_t *inside, size_t *removed, sk_error *err)
{
    uint8_t ok[256];
    make_table(ok);
    const size_t sx = 1, sy = (size_t)g->n[0], sz = (size_t)g->n[0] * (size_t)g->n[1];
#pragma omp parallel for schedule(dynamic, 4)
    for (int z = 0; z < g->n[2]; z++)
        for (int y = 0; y < g->n[1]; y++)
            for (int x = 0; x < g->n[0]; x++) {
                size_t c = sk__grid_index(g, x, y, z);
                bool all = x < g->n[0] - 1 && y < g->n[1] - 1 && z < g->n[2] - 1;
                for (int b = 0; b < 8 && all; b++)
                    all = is_point[c + (b & 1) * sx + (b >> 1 & 1) * sy + (b >> 2 & 1) * sz];
                inside[c] = all;
            }
    /* cells at the grid's border stay out, so every vertex checked has its 8 cells */
    sk_result r = make_manifold(g, ok, inside, removed, err);
    if (r != SK_OK) return r;
    return keep_tissue_components(g, labels, inside, err);
}

/* Appends the two triangles of the face of cell c towards axis k (sign +1 or -1). */
static size_t emit_face(const sk__grid *g, int cx, int cy, int cz, int k, int sign, size_t *out)
{
    int c[3] = {cx, cy, cz}, u = (k + 1) % 3, v = (k + 2) % 3;
    int q[4][3];
    for (int i = 0; i < 4; i++) {
        q[i][k] = c[k] + (sign > 0);
        q[i][u] = c[u] + (i == 1 || i == 2);
        q[i][v] = c[v] + (i >= 2);
    }
    size_t id[4];
    for (int i = 0; i < 4; i++) id[i] = sk__grid_index(g, q[i][0], q[i][1], q[i][2]);
    if (sign < 0) { /* reverse the winding so the normal points out */
        size_t t = id[1];
        id[1] = id[3];
        id[3] = t;
    }
    if (((cx + cy + cz) & 1) == 0) {
        size_t t[6] = {id[0], id[1], id[2], id[0], id[2], id[3]};
        memcpy(out, t, sizeof t);
    } else {
        size_t t[6] = {id[0], id[1], id[3], id[1], id[2], id[3]};
        memcpy(out, t, sizeof t);
    }
    return 2;
}

static size_t cell_faces(const sk__grid *g, const uint8_t *inside, int x, int y, int z, size_t *out)
{
    size_t c = sk__grid_index(g, x, y, z);
    if (!inside[c]) return 0;
    const ptrdiff_t step[3] = {1, g->n[0], (ptrdiff_t)g->n[0] * g->n[1]};
    const int coord[3] = {x, y, z};
    size_t n = 0;
    for (int k = 0; k < 3; k++)
        for (int sign = -1; sign <= 1; sign += 2) {
            int nc = coord[k] + sign;
            bool out_of_grid = nc < 0 || nc >= g->n[k] - 1;
            if (!out_of_grid && inside[(ptrdiff_t)c + sign * step[k]]) continue;
            if (out) emit_face(g, x, y, z, k, sign, out + 3 * n);
            n += 2;
        }
    return n;
}

sk_result sk__skin_faces(const sk__grid *g, const uint8_t *inside, size_t **out_corners,
                         size_t *out_triangles, sk_error *err)
{
    int nz = g->n[2];
    size_t *start = calloc((size_t)nz + 1, sizeof *start);
    sk__cell_rows rows = {0};
    if (!start) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for the skin");
    sk_result r = sk__cell_rows_make(g, inside, &rows, err);
    if (r != SK_OK) {
        free(start);
        return r;
    }
#define ROW(y, z) ((size_t)(z) * (size_t)g->n[1] + (size_t)(y))
#pragma omp parallel for schedule(dynamic, 4)
    for (int z = 0; z < nz; z++) {
        size_t n = 0;
        for (int y = 0; y < g->n[1]; y++)
            for (int x = rows.lo[ROW(y, z)]; x <= rows.hi[ROW(y, z)]; x++)
                n += cell_faces(g, inside, x, y, z, NULL);
        start[z + 1] = n;
    }
    for (int z = 0; z < nz; z++) start[z + 1] += start[z];
    size_t total = start[nz];
    size_t *corners = malloc((total ? total : 1) * 3 * sizeof *corners);
    if (!corners) {
        sk__cell_rows_free(&rows);
        free(start);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for %zu skin triangles", total);
    }
#pragma omp parallel for schedule(dynamic, 4)
    for (int z = 0; z < nz; z++) {
        size_t n = start[z];
        for (int y = 0; y < g->n[1]; y++)
            for (int x = rows.lo[ROW(y, z)]; x <= rows.hi[ROW(y, z)]; x++)
                n += cell_faces(g, inside, x, y, z, corners + 3 * n);
    }
#undef ROW
    sk__cell_rows_free(&rows);
    free(start);
    *out_corners = corners;
    *out_triangles = total;
    return SK_OK;
}
