/* The grid over the tissue (Shigemori & Kawai sec. 4, first step): every grid point
 * inside a bone or muscle ellipsoid is labelled with it, bones before muscles and, among
 * ellipsoids of one kind, the one the point is deepest in (lowest level). */
#include <float.h>
#include <math.h>
#include <stdlib.h>

#include "models/tissue/tissue_internal.h"

static sk__label label_of_bone(int b) { return (sk__label)(1 + b); }
static sk__label label_of_muscle(int m) { return (sk__label)(SK__LABEL_MUSCLE0 + m); }

sk__label sk__tissue_label_at(const sk__tissue_shapes *t, sk_vec3d p)
{
    sk__label best = SK__LABEL_NONE;
    double level = DBL_MAX;
    for (int b = 0; b < t->bone_count; b++)
        for (int k = 0; k < 3; k++) {
            double q = sk__ellipsoid_level(&t->bone[b][k], p);
            if (q <= 1.0 && q < level) {
                level = q;
                best = label_of_bone(b);
            }
        }
    if (best != SK__LABEL_NONE) return best;
    for (int m = 0; m < t->muscle_count; m++) {
        double q = sk__ellipsoid_level(&t->muscle[m], p);
        if (q <= 1.0 && q < level) {
            level = q;
            best = label_of_muscle(m);
        }
    }
    return best;
}

/* Grid index range [lo, hi] of a coordinate interval along axis k (empty if lo > hi). */
static void index_range(const sk__grid *g, int k, double a, double b, int *lo, int *hi)
{
    double o = k == 0 ? g->origin.x : (k == 1 ? g->origin.y : g->origin.z);
    *lo = (int)ceil((a - o) / g->spacing);
    *hi = (int)floor((b - o) / g->spacing);
    if (*lo < 0) *lo = 0;
    if (*hi > g->n[k] - 1) *hi = g->n[k] - 1;
}

/* Labels the points of one slice inside one ellipsoid, keeping the lowest level per
 * kind; `level` holds the current best level of the slice's points. */
static void stamp(const sk__grid *g, int z, const sk__ellipsoid *e, sk__label label, bool bone,
                  sk__label *labels, float *level)
{
    sk_vec3d lo, hi;
    sk__ellipsoid_bounds(e, &lo, &hi);
    int x0, x1, y0, y1;
    index_range(g, 0, lo.x, hi.x, &x0, &x1);
    index_range(g, 1, lo.y, hi.y, &y0, &y1);
    double pz = g->origin.z + g->spacing * z;
    for (int y = y0; y <= y1; y++) {
        double py = g->origin.y + g->spacing * y;
        for (int x = x0; x <= x1; x++) {
            sk_vec3d p = sk_v3d(g->origin.x + g->spacing * x, py, pz);
            double q = sk__ellipsoid_level(e, p);
            if (q > 1.0) continue;
            size_t i = sk__grid_index(g, x, y, z), s = (size_t)y * (size_t)g->n[0] + (size_t)x;
            bool has_bone = labels[i] != SK__LABEL_NONE && labels[i] < SK__LABEL_MUSCLE0;
            if (!bone && has_bone) continue; /* bones win */
            bool replace = labels[i] == SK__LABEL_NONE || (bone && !has_bone) || q < level[s];
            if (replace) {
                labels[i] = label;
                level[s] = (float)q;
            }
        }
    }
}

sk_result sk__voxelise(const sk__grid *g, const sk__tissue_shapes *t, sk__label *labels,
                       sk_error *err)
{
    size_t slice = (size_t)g->n[0] * (size_t)g->n[1];
    int threads = sk_threads_max();
    float *levels = malloc(slice * (size_t)threads * sizeof *levels);
    if (!levels) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for the tissue voxels");
#pragma omp parallel num_threads(threads)
    {
        float *level = levels + slice * (size_t)sk_thread_index();
#pragma omp for schedule(dynamic, 4)
        for (int z = 0; z < g->n[2]; z++) {
            for (size_t s = 0; s < slice; s++) labels[(size_t)z * slice + s] = SK__LABEL_NONE;
            double pz = g->origin.z + g->spacing * z;
            for (int b = 0; b < t->bone_count; b++)
                for (int k = 0; k < 3; k++) {
                    sk_vec3d lo, hi;
                    sk__ellipsoid_bounds(&t->bone[b][k], &lo, &hi);
                    if (pz >= lo.z && pz <= hi.z)
                        stamp(g, z, &t->bone[b][k], label_of_bone(b), true, labels, level);
                }
            for (int m = 0; m < t->muscle_count; m++) {
                sk_vec3d lo, hi;
                sk__ellipsoid_bounds(&t->muscle[m], &lo, &hi);
                if (pz >= lo.z && pz <= hi.z)
                    stamp(g, z, &t->muscle[m], label_of_muscle(m), false, labels, level);
            }
        }
    }
    free(levels);
    return SK_OK;
}
