/* What each point carries (Shigemori & Kawai sec. 4-5): masses of the fat and skin points
 * (from the fat density and a skin sheet), the local coordinates of muscle and bone
 * points (sec. 4: "their positions in the local frame are stored"), and for every fat and
 * skin point the tissue nearest it at rest (a bone, or a muscle whose deformation it then
 * follows), which carries it where the paper's model leaves the choice open: the start of
 * a run, a teleport, and the skin without the fat layer (Wilhelms' skin on the tissue). */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "models/tissue/tissue_internal.h"

/* Distance from p to an ellipsoid's surface along the ray from its centre (0 inside). */
static double surface_distance(const sk__ellipsoid *e, sk_vec3d p)
{
    double q = sk__ellipsoid_level(e, p);
    if (q <= 1.0) return 0.0;
    return sk_v3d_length(sk_v3d_sub(p, e->centre)) * (1.0 - 1.0 / sqrt(q));
}

/* p in the muscle's rest shape, in units of its semi-axes (what the muscle's deformation
 * scales, sec. 5). */
static sk_vec3d muscle_coordinates(const sk__ellipsoid *e, sk_vec3d x)
{
    sk_vec3d d = sk_v3d_sub(x, e->centre);
    const sk_mat3d ax = e->axes;
    return sk_v3d((ax.m[0][0] * d.x + ax.m[1][0] * d.y + ax.m[2][0] * d.z) / e->radii.x,
                  (ax.m[0][1] * d.x + ax.m[1][1] * d.y + ax.m[2][1] * d.z) / e->radii.y,
                  (ax.m[0][2] * d.x + ax.m[1][2] * d.y + ax.m[2][2] * d.z) / e->radii.z);
}

/* Whether the ellipsoid may lie closer to p than `best` (its centre's distance less its
 * longest semi-axis bounds the distance from below). */
static bool may_be_closer(const sk__ellipsoid *e, sk_vec3d p, double best)
{
    double r = fmax(e->radii.x, fmax(e->radii.y, e->radii.z));
    return sk_v3d_length(sk_v3d_sub(p, e->centre)) - r < best;
}

/* The tissue nearest a free point at rest: a bone (returns -1) or a muscle (its index);
 * *bone gets the bone, or the muscle's origin bone; *near the muscles within two grid
 * spacings of that nearest distance (the muscles the point lies against, which it is kept
 * out of; muscles of other limbs it may meet in a pose are not obstacles to it). */
static int nearest_tissue(const sk_tissue_model *m, const sk__tissue_shapes *t, sk_vec3d x,
                          int *bone, uint64_t *near)
{
    double best = HUGE_VAL;
    int muscle = -1;
    *bone = 0;
    for (int b = 0; b < t->bone_count; b++)
        for (int k = 0; k < 3; k++) {
            if (!may_be_closer(&t->bone[b][k], x, best)) continue;
            double d = surface_distance(&t->bone[b][k], x);
            if (d < best) {
                best = d;
                *bone = b;
            }
        }
    for (int i = 0; i < t->muscle_count; i++) {
        if (!may_be_closer(&t->muscle[i], x, best)) continue;
        double d = surface_distance(&t->muscle[i], x);
        if (d < best) {
            best = d;
            muscle = i;
        }
    }
    if (muscle >= 0) *bone = m->muscles[muscle].origin_bone;
    *near = 0;
    double reach = best + 2.0 * m->grid.spacing;
    for (int i = 0; i < t->muscle_count; i++)
        if (may_be_closer(&t->muscle[i], x, reach) && surface_distance(&t->muscle[i], x) <= reach)
            *near |= (uint64_t)1 << i;
    return muscle;
}

static void rest_pose(const sk_tissue_model *m, sk_tissue_pose *pose)
{
    sk_quatd local[SK_TISSUE_MAX_JOINTS];
    for (int j = 0; j < m->skeleton.count; j++) local[j] = sk_qd_identity();
    sk__skeleton_pose(&m->skeleton, local, m->skeleton.rest[m->skeleton.root], pose);
}

static void track(sk_tissue_model *m)
{
    const sk_tissue_character_desc *d = &m->desc;
    for (int k = 0; k < d->tracked_count; k++) {
        const sk_tissue_tracked_desc *t = &d->tracked[k];
        const sk__bone *b = &m->bones[sk__bone_find(d, t->bone)];
        sk_vec3d o =
            sk_v3d_add(m->skeleton.rest[b->joint], sk__bone_point(b, t->at, sk_v3d(0, 0, 0)));
        sk_vec3d dir = sk_v3d_normalize(sk_v3d(t->direction[0], t->direction[1], t->direction[2]));
        double near = 1.5 * m->grid.spacing, best_t = DBL_MAX, best_perp = DBL_MAX;
        int first = -1, closest = -1;
        for (size_t p = 0; p < m->skin_count; p++) {
            sk_vec3d v = sk_v3d_sub(m->rest[p], o);
            double along = sk_v3d_dot(v, dir);
            if (along <= 0) continue;
            double perp = sk_v3d_length(sk_v3d_sub(v, sk_v3d_scale(dir, along)));
            if (perp <= near && along < best_t) {
                best_t = along;
                first = (int)p;
            }
            if (perp < best_perp) {
                best_perp = perp;
                closest = (int)p;
            }
        }
        m->tracked_point[k] = first >= 0 ? first : closest;
    }
}

void sk__model_attach(sk_tissue_model *m, const sk__tissue_shapes *t)
{
    const sk_tissue_material_desc *mat = &m->desc.material;
    double a = m->grid.spacing * 1e-3; /* m */
    double cell = a * a * a;
    size_t nfree = m->skin_count + m->fat_count;
    /* skin sheet: a third of each incident triangle's area */
    double *area = calloc(m->skin_count ? m->skin_count : 1, sizeof *area);
    for (size_t i = 0; area && i < m->triangle_count; i++) {
        const uint32_t *v = m->triangles + 3 * i;
        sk_vec3d e1 = sk_v3d_sub(m->rest[v[1]], m->rest[v[0]]),
                 e2 = sk_v3d_sub(m->rest[v[2]], m->rest[v[0]]);
        double third = 0.5 * sk_v3d_length(sk_v3d_cross(e1, e2)) * 1e-6 / 3.0;
        for (int k = 0; k < 3; k++) area[v[k]] += third;
    }
    double skin_sheet = mat->skin_density * mat->skin_thickness_mm * 1e-3;
#pragma omp parallel for schedule(static)
    for (size_t p = 0; p < m->point_count; p++) {
        if (p < m->skin_count)
            m->mass[p] = 0.5 * mat->fat_density * cell + skin_sheet * (area ? area[p] : 0.0);
        else if (p < nfree)
            m->mass[p] = mat->fat_density * cell;
        else
            m->mass[p] = 0.0;
    }
    free(area);
    sk_tissue_pose rest;
    rest_pose(m, &rest);
#pragma omp parallel for schedule(dynamic, 256)
    for (size_t p = 0; p < m->point_count; p++) {
        sk_vec3d x = m->rest[p];
        if (p < nfree) {
            int bone, muscle = nearest_tissue(m, t, x, &bone, &m->near_muscles[p]);
            m->owner[p] = bone;
            m->carrier_muscle[p] = muscle;
            if (muscle >= 0) {
                sk__ellipsoid e;
                sk__muscle_shape(&m->muscles[muscle], &rest, &e);
                m->local[p] = muscle_coordinates(&e, x);
            } else {
                m->local[p] = sk_v3d_sub(x, m->skeleton.rest[m->bones[bone].joint]);
            }
        } else if (p < nfree + m->muscle_count) {
            sk__label l = sk__tissue_label_at(t, x);
            int mi = l >= SK__LABEL_MUSCLE0 ? l - SK__LABEL_MUSCLE0 : 0;
            sk__ellipsoid e;
            sk__muscle_shape(&m->muscles[mi], &rest, &e);
            m->owner[p] = mi;
            m->carrier_muscle[p] = -1;
            m->local[p] = muscle_coordinates(&e, x);
        } else {
            sk__label l = sk__tissue_label_at(t, x);
            int bi = l != SK__LABEL_NONE && l < SK__LABEL_MUSCLE0 ? l - 1 : 0;
            m->owner[p] = bi;
            m->carrier_muscle[p] = -1;
            m->local[p] = sk_v3d_sub(x, m->skeleton.rest[m->bones[bi].joint]);
        }
    }
    double total = 0.0;
    for (size_t p = 0; p < nfree; p++) total += m->mass[p];
    m->stats.free_mass_kg = total;
    track(m);
}
