/* Optional smoothing of the rest skin, the paper's own future work ("a smoother initial
 * shape", sec. 6): Taubin's lambda/mu smoothing (Taubin 1995, "A signal processing approach
 * to fair surface design", lambda 0.5, mu -0.53, so the skin does not shrink) over the skin
 * triangles' edges, a vertex's move refused where it would enter the tissue, and every
 * vertex kept within one grid spacing of its grid point. */
#include <math.h>
#include <stdlib.h>

#include "models/tissue/tissue_internal.h"

#define LAMBDA 0.5
#define MU (-0.53)
#define MARGIN 0.02 /* stay 2 % (of each semi-axis) outside every tissue ellipsoid */
#define MAX_NEAR 16

typedef struct near_list {
    int count;
    const sk__ellipsoid *e[MAX_NEAR];
} near_list;

static double widest(const sk__ellipsoid *e)
{
    return fmax(e->radii.x, fmax(e->radii.y, e->radii.z));
}

static bool outside_tissue(const near_list *n, sk_vec3d p)
{
    for (int k = 0; k < n->count; k++)
        if (sk__ellipsoid_level(n->e[k], p) < (1.0 + MARGIN) * (1.0 + MARGIN)) return false;
    return true;
}

sk_result sk__skin_smooth(sk_tissue_model *m, const sk__tissue_shapes *t, int iterations,
                          sk_error *err)
{
    size_t n = m->skin_count;
    if (iterations <= 0 || n == 0) return SK_OK;
    sk_result r = SK_OK;
    /* neighbours along triangle edges (each edge seen from both triangles: counted twice,
       which weighs every neighbour alike) */
    size_t *start = calloc(n + 1, sizeof *start);
    uint32_t *adj = malloc(m->triangle_count * 6 * sizeof *adj);
    sk_vec3d *a = malloc(n * sizeof *a), *b = malloc(n * sizeof *b),
             *home = malloc(n * sizeof *home);
    near_list *near = malloc(n * sizeof *near);
    if (!start || !adj || !a || !b || !home || !near) {
        r = sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for the skin smoothing");
        goto done;
    }
    for (size_t i = 0; i < m->triangle_count; i++)
        for (int k = 0; k < 3; k++) start[m->triangles[3 * i + (size_t)k] + 1] += 2;
    for (size_t v = 0; v < n; v++) start[v + 1] += start[v];
    {
        size_t *fill = malloc(n * sizeof *fill);
        if (!fill) {
            r = sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for the skin smoothing");
            goto done;
        }
        for (size_t v = 0; v < n; v++) fill[v] = start[v];
        for (size_t i = 0; i < m->triangle_count; i++)
            for (int k = 0; k < 3; k++) {
                uint32_t v = m->triangles[3 * i + (size_t)k];
                adj[fill[v]++] = m->triangles[3 * i + (size_t)(k + 1) % 3];
                adj[fill[v]++] = m->triangles[3 * i + (size_t)(k + 2) % 3];
            }
        free(fill);
    }
    double reach = 2.0 * m->grid.spacing;
#pragma omp parallel for schedule(static)
    for (size_t v = 0; v < n; v++) {
        home[v] = a[v] = m->rest[v];
        near[v].count = 0;
        for (int bo = 0; bo < t->bone_count; bo++)
            for (int k = 0; k < 3; k++) {
                const sk__ellipsoid *e = &t->bone[bo][k];
                if (sk_v3d_length(sk_v3d_sub(a[v], e->centre)) < widest(e) + reach &&
                    near[v].count < MAX_NEAR)
                    near[v].e[near[v].count++] = e;
            }
        for (int mu = 0; mu < t->muscle_count; mu++) {
            const sk__ellipsoid *e = &t->muscle[mu];
            if (sk_v3d_length(sk_v3d_sub(a[v], e->centre)) < widest(e) + reach &&
                near[v].count < MAX_NEAR)
                near[v].e[near[v].count++] = e;
        }
    }
    for (int it = 0; it < 2 * iterations; it++) {
        double f = (it & 1) ? MU : LAMBDA;
#pragma omp parallel for schedule(static)
        for (size_t v = 0; v < n; v++) {
            sk_vec3d sum = sk_v3d(0, 0, 0);
            size_t k0 = start[v], k1 = start[v + 1];
            for (size_t k = k0; k < k1; k++) sum = sk_v3d_add(sum, a[adj[k]]);
            sk_vec3d p = a[v];
            if (k1 > k0) {
                sk_vec3d avg = sk_v3d_scale(sum, 1.0 / (double)(k1 - k0));
                p = sk_v3d_add(p, sk_v3d_scale(sk_v3d_sub(avg, p), f));
            }
            /* at most one spacing from the grid point, and never into the tissue */
            sk_vec3d off = sk_v3d_sub(p, home[v]);
            double len = sk_v3d_length(off);
            if (len > m->grid.spacing)
                p = sk_v3d_add(home[v], sk_v3d_scale(off, m->grid.spacing / len));
            b[v] = outside_tissue(&near[v], p) ? p : a[v];
        }
        sk_vec3d *s = a;
        a = b;
        b = s;
    }
    for (size_t v = 0; v < n; v++) m->rest[v] = a[v];
done:
    free(start);
    free(adj);
    free(a);
    free(b);
    free(home);
    free(near);
    return r;
}
