/* Building a character for simulation (Shigemori & Kawai secs. 3-4): skeleton, bones and
 * muscles; the grid over the tissue, its voxels, the fat regions, the dilations, the skin
 * isosurface with vertices on grid points, the classified points and their springs. Also
 * the model's outputs as meshes (rest skin, point classes, the tissue's ellipsoids). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "models/tissue/tissue_internal.h"

#define MAX_GRID_POINTS ((size_t)1 << 28)

static void rest_shapes(const sk_tissue_model *m, sk__tissue_shapes *t)
{
    sk_tissue_pose rest;
    sk_quatd local[SK_TISSUE_MAX_JOINTS];
    for (int j = 0; j < m->skeleton.count; j++) local[j] = sk_qd_identity();
    sk__skeleton_pose(&m->skeleton, local, m->skeleton.rest[m->skeleton.root], &rest);
    t->bone_count = m->desc.bone_count;
    t->muscle_count = m->desc.muscle_count;
    for (int b = 0; b < t->bone_count; b++)
        for (int k = 0; k < 3; k++)
            t->bone[b][k] = sk__ellipsoid_transform(&m->bones[b].part[k], sk_m3d_identity(),
                                                    m->skeleton.rest[m->bones[b].joint]);
    for (int i = 0; i < t->muscle_count; i++)
        sk__muscle_shape(&m->muscles[i], &rest, &t->muscle[i]);
}

static sk_result make_grid(const sk_tissue_model *m, const sk__tissue_shapes *t, sk__grid *g,
                           sk_error *err)
{
    const sk_tissue_skin_desc *s = &m->desc.skin;
    sk_vec3d lo = sk_v3d(HUGE_VAL, HUGE_VAL, HUGE_VAL),
             hi = sk_v3d(-HUGE_VAL, -HUGE_VAL, -HUGE_VAL);
    for (int i = 0; i < t->bone_count * 3 + t->muscle_count; i++) {
        const sk__ellipsoid *e =
            i < t->bone_count * 3 ? &t->bone[i / 3][i % 3] : &t->muscle[i - t->bone_count * 3];
        sk_vec3d a, b;
        sk__ellipsoid_bounds(e, &a, &b);
        lo = sk_v3d(fmin(lo.x, a.x), fmin(lo.y, a.y), fmin(lo.z, a.z));
        hi = sk_v3d(fmax(hi.x, b.x), fmax(hi.y, b.y), fmax(hi.z, b.z));
    }
    double fat = 0.0;
    for (int i = 0; i < m->desc.fat_count; i++) fat = fmax(fat, m->desc.fat[i].thickness_mm);
    double margin = fat + (s->dilations + 1) * s->dilation_radius_mm + 3.0 * s->spacing_mm;
    g->spacing = s->spacing_mm;
    double ext[3] = {hi.x - lo.x + 2 * margin, hi.y - lo.y + 2 * margin, hi.z - lo.z + 2 * margin};
    size_t count = 1;
    for (int k = 0; k < 3; k++) {
        double n = ceil(ext[k] / g->spacing) + 1;
        if (n > 1e6) n = 1e6;
        g->n[k] = (int)n;
        count = count * (size_t)g->n[k] > MAX_GRID_POINTS ? MAX_GRID_POINTS + 1
                                                          : count * (size_t)g->n[k];
    }
    if (count > MAX_GRID_POINTS)
        return sk_fail(
            err, SK_ERROR_LIMIT,
            "skin.spacing_mm = %g makes a grid of %d x %d x %d points, more than 2^28: raise it",
            s->spacing_mm, g->n[0], g->n[1], g->n[2]);
    g->count = count;
    /* centre the tissue in the grid */
    g->origin = sk_v3d(0.5 * (lo.x + hi.x) - 0.5 * g->spacing * (g->n[0] - 1),
                       0.5 * (lo.y + hi.y) - 0.5 * g->spacing * (g->n[1] - 1),
                       0.5 * (lo.z + hi.z) - 0.5 * g->spacing * (g->n[2] - 1));
    return SK_OK;
}

typedef struct scratch {
    sk__label *labels;
    float *value;
    uint8_t *seed, *inside;
    size_t *corners;
} scratch;

static void free_scratch(scratch *s)
{
    free(s->labels);
    free(s->value);
    free(s->seed);
    free(s->inside);
    free(s->corners);
}

/* Seconds since *t0, which becomes now. */
static double lap(double *t0)
{
    double t = sk_time_seconds(), dt = t - *t0;
    *t0 = t;
    return dt;
}

static sk_result build(sk_tissue_model *m, const sk_progress *progress, sk_error *err)
{
    const sk_tissue_character_desc *d = &m->desc;
    double t0 = sk_time_seconds();
    sk_result r = sk__skeleton_build(d, &m->skeleton, err);
    if (r == SK_OK) r = sk__bones_build(d, &m->skeleton, m->bones, err);
    if (r == SK_OK) r = sk__muscles_build(d, &m->skeleton, m->bones, m->muscles, err);
    if (r != SK_OK) return r;
    sk__tissue_shapes *shapes = malloc(sizeof *shapes);
    if (!shapes) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    rest_shapes(m, shapes);
    sk__grid *g = &m->grid;
    m->neighbourhood = d->skin.neighbourhood;
    scratch s = {0};
    r = make_grid(m, shapes, g, err);
    if (r == SK_OK) {
        s.labels = malloc(g->count * sizeof *s.labels);
        s.seed = calloc(g->count, 1);
        s.value = malloc(g->count * sizeof *s.value);
        if (!s.labels || !s.seed || !s.value)
            r = sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for a grid of %zu points",
                        g->count);
    }
    sk_progress_report(progress, 0.05);
    if (r == SK_OK) r = sk__voxelise(g, shapes, s.labels, err);
    m->stats.seconds_voxelise = lap(&t0);
    if (r == SK_OK)
        r = sk__fat_regions_mark(d, &m->skeleton, m->bones, m->muscles, g, s.labels, s.seed, err);
    m->stats.seconds_fat = lap(&t0);
    sk_progress_report(progress, 0.2);
    size_t tissue = 0;
    if (r == SK_OK) {
        for (size_t i = 0; i < g->count; i++) {
            tissue += s.labels[i] != SK__LABEL_NONE;
            s.seed[i] |= s.labels[i] != SK__LABEL_NONE;
        }
        r = sk__dilate(g, s.seed, d->skin.dilations, d->skin.dilation_radius_mm, s.value, err);
    }
    m->stats.seconds_dilate = lap(&t0);
    sk_progress_report(progress, 0.5);
    size_t triangles = 0;
    if (r == SK_OK) {
        /* points: above the threshold (reusing the seed array) */
        float level = d->skin.threshold;
        for (size_t i = 0; i < g->count; i++) s.seed[i] = s.value[i] > level;
        free(s.value);
        s.value = NULL;
        s.inside = malloc(g->count);
        r = s.inside ? sk__skin_cells(g, s.seed, s.labels, s.inside, &m->stats.removed_cells, err)
                     : sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for the skin cells");
    }
    if (r == SK_OK) r = sk__skin_faces(g, s.inside, &s.corners, &triangles, err);
    if (r == SK_OK && triangles == 0)
        r = sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                    "the character has no skin: every grid point is below skin.threshold");
    m->stats.seconds_extract = lap(&t0);
    sk_progress_report(progress, 0.7);
    if (r == SK_OK) {
        sk__skin_build b = {g, s.labels, s.inside, s.corners, triangles};
        r = sk__model_points(m, &b, err);
    }
    if (r == SK_OK) {
        m->rest = malloc(m->point_count * sizeof *m->rest);
        m->mass = malloc(m->point_count * sizeof *m->mass);
        m->owner = malloc(m->point_count * sizeof *m->owner);
        m->local = malloc(m->point_count * sizeof *m->local);
        m->carrier_muscle = malloc(m->point_count * sizeof *m->carrier_muscle);
        m->near_muscles = calloc(m->point_count, sizeof *m->near_muscles);
        if (!m->rest || !m->mass || !m->owner || !m->local || !m->carrier_muscle ||
            !m->near_muscles)
            r = sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    }
    if (r == SK_OK) {
        for (size_t p = 0; p < m->point_count; p++)
            m->rest[p] = sk__grid_position(g, m->grid_of[p]);
        r = sk__skin_smooth(m, shapes, d->skin.smooth_iterations, err);
    }
    m->stats.seconds_classify = lap(&t0);
    sk_progress_report(progress, 0.85);
    if (r == SK_OK) r = sk__model_springs(m, err);
    if (r == SK_OK) sk__model_attach(m, shapes);
    m->stats.seconds_springs = lap(&t0);
    if (r == SK_OK) {
        sk_tissue_model_stats *st = &m->stats;
        for (int k = 0; k < 3; k++) st->grid[k] = g->n[k];
        st->spacing_mm = g->spacing;
        st->tissue_voxels = tissue;
        st->points = m->point_count;
        st->skin_points = m->skin_count;
        st->fat_points = m->fat_count;
        st->muscle_points = m->muscle_count;
        st->bone_points = m->bone_count;
        st->springs = m->spring_count;
        st->skin_springs = m->class_count[SK__SPRING_SKIN];
        st->skin_fat_springs = m->class_count[SK__SPRING_SKIN_FAT];
        st->fat_springs = m->class_count[SK__SPRING_FAT];
        st->anchor_springs = m->class_count[SK__SPRING_ANCHOR];
        st->skin_triangles = m->triangle_count;
    }
    free(m->grid_point);
    m->grid_point = NULL;
    free_scratch(&s);
    free(shapes);
    sk_progress_report(progress, 1.0);
    return r;
}

sk_result sk_tissue_model_build(const sk_tissue_character_desc *desc,
                                const sk_tissue_build_options *options, sk_tissue_model **out,
                                sk_error *err)
{
    *out = NULL;
    if (!desc) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "character desc is NULL");
    sk_tissue_model *m = calloc(1, sizeof *m);
    if (!m) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    m->desc = *desc;
    sk_tissue_character_desc_resolve(&m->desc);
    sk_result r = sk_tissue_character_desc_validate(&m->desc, err);
    double start = sk_time_seconds();
    if (r == SK_OK) r = build(m, options ? &options->progress : NULL, err);
    if (r != SK_OK) {
        sk_tissue_model_destroy(m);
        return r;
    }
    m->stats.seconds_total = sk_time_seconds() - start;
    *out = m;
    return SK_OK;
}

sk_result sk_tissue_model_memory(const sk_tissue_character_desc *desc, double *bytes, int grid[3],
                                 sk_error *err)
{
    *bytes = 0;
    if (!desc) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "character desc is NULL");
    sk_tissue_model *m = calloc(1, sizeof *m);
    sk__tissue_shapes *shapes = malloc(sizeof *shapes);
    sk_result r = m && shapes ? SK_OK : sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    if (r == SK_OK) {
        m->desc = *desc;
        sk_tissue_character_desc_resolve(&m->desc);
        r = sk_tissue_character_desc_validate(&m->desc, err);
    }
    if (r == SK_OK) r = sk__skeleton_build(&m->desc, &m->skeleton, err);
    if (r == SK_OK) r = sk__bones_build(&m->desc, &m->skeleton, m->bones, err);
    if (r == SK_OK) r = sk__muscles_build(&m->desc, &m->skeleton, m->bones, m->muscles, err);
    if (r == SK_OK) {
        rest_shapes(m, shapes);
        r = make_grid(m, shapes, &m->grid, err);
    }
    if (r == SK_OK) {
        *bytes = SK_TISSUE_BYTES_PER_GRID_POINT * (double)m->grid.count;
        for (int k = 0; grid && k < 3; k++) grid[k] = m->grid.n[k];
    }
    free(shapes);
    sk_tissue_model_destroy(m);
    return r;
}

void sk_tissue_model_destroy(sk_tissue_model *m)
{
    if (!m) return;
    free(m->grid_of);
    free(m->grid_point);
    free(m->rest);
    free(m->mass);
    free(m->owner);
    free(m->local);
    free(m->carrier_muscle);
    free(m->near_muscles);
    free(m->spring_i);
    free(m->spring_j);
    free(m->spring_rest);
    free(m->spring_class);
    free(m->triangles);
    free(m);
}

const sk_tissue_character_desc *sk_tissue_model_desc(const sk_tissue_model *m) { return &m->desc; }
sk_tissue_model_stats sk_tissue_model_get_stats(const sk_tissue_model *m) { return m->stats; }

sk_result sk_tissue_model_rest_skin(const sk_tissue_model *m, sk_mesh *out, sk_error *err)
{
    memset(out, 0, sizeof *out);
    sk_result r = sk_mesh_create(out, m->skin_count, m->triangle_count, 0, err);
    if (r != SK_OK) return r;
    for (size_t p = 0; p < m->skin_count; p++) {
        out->positions[3 * p] = (float)m->rest[p].x;
        out->positions[3 * p + 1] = (float)m->rest[p].y;
        out->positions[3 * p + 2] = (float)m->rest[p].z;
    }
    memcpy(out->indices, m->triangles, m->triangle_count * 3 * sizeof *out->indices);
    r = sk_mesh_compute_normals(out, err);
    if (r != SK_OK) sk_mesh_free(out);
    return r;
}

sk_result sk_tissue_model_points(const sk_tissue_model *m, sk_tissue_point_class cls, sk_mesh *out,
                                 sk_error *err)
{
    memset(out, 0, sizeof *out);
    size_t first = 0, count = 0;
    switch (cls) {
    case SK_TISSUE_POINT_SKIN:
        first = 0, count = m->skin_count;
        break;
    case SK_TISSUE_POINT_FAT:
        first = m->skin_count, count = m->fat_count;
        break;
    case SK_TISSUE_POINT_MUSCLE:
        first = m->skin_count + m->fat_count, count = m->muscle_count;
        break;
    case SK_TISSUE_POINT_BONE:
        first = m->skin_count + m->fat_count + m->muscle_count, count = m->bone_count;
        break;
    default:
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "point class %d is not one of 0..3",
                       (int)cls);
    }
    if (count == 0)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "the model has no points of class %d",
                       (int)cls);
    sk_result r = sk_mesh_create(out, count, 0, 0, err);
    float *owner = NULL;
    if (r == SK_OK) r = sk_mesh_add_attribute(out, "owner", 1, &owner, err);
    if (r != SK_OK) {
        sk_mesh_free(out);
        return r;
    }
    bool anchored = cls == SK_TISSUE_POINT_MUSCLE || cls == SK_TISSUE_POINT_BONE;
    for (size_t i = 0; i < count; i++) {
        sk_vec3d p = m->rest[first + i];
        out->positions[3 * i] = (float)p.x;
        out->positions[3 * i + 1] = (float)p.y;
        out->positions[3 * i + 2] = (float)p.z;
        owner[i] = anchored ? (float)m->owner[first + i] : -1.0f;
    }
    return SK_OK;
}

/* A UV sphere of `segments` around and segments / 2 rings, mapped onto an ellipsoid. */
static void ellipsoid_mesh(const sk__ellipsoid *e, int segments, sk_mesh *out, size_t v0, size_t t0)
{
    int rings = segments / 2;
    size_t v = v0;
    for (int i = 0; i <= rings; i++) {
        double th = SK_PI * i / rings;
        for (int j = 0; j < segments; j++) {
            double ph = 2.0 * SK_PI * j / segments;
            sk_vec3d l = sk_v3d(e->radii.x * sin(th) * cos(ph), e->radii.y * sin(th) * sin(ph),
                                e->radii.z * cos(th));
            sk_vec3d p = sk_v3d_add(e->centre, sk_m3d_apply(e->axes, l));
            out->positions[3 * v] = (float)p.x;
            out->positions[3 * v + 1] = (float)p.y;
            out->positions[3 * v + 2] = (float)p.z;
            v++;
        }
    }
    size_t t = t0;
    for (int i = 0; i < rings; i++)
        for (int j = 0; j < segments; j++) {
            uint32_t a = (uint32_t)(v0 + (size_t)i * segments + j),
                     b = (uint32_t)(v0 + (size_t)i * segments + (j + 1) % segments);
            uint32_t c = a + (uint32_t)segments, d = b + (uint32_t)segments;
            uint32_t tri[6] = {a, c, b, b, c, d};
            memcpy(out->indices + 3 * t, tri, sizeof tri);
            t += 2;
        }
}

sk_result sk_tissue_model_ellipsoids(const sk_tissue_model *m, sk_tissue_point_class cls,
                                     int segments, sk_mesh *out, sk_error *err)
{
    memset(out, 0, sizeof *out);
    if (cls != SK_TISSUE_POINT_BONE && cls != SK_TISSUE_POINT_MUSCLE)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "ellipsoids are drawn for bones and muscles only");
    if (segments < 8 || segments > 256)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "segments = %d is out of range [8, 256]",
                       segments);
    segments &= ~1;
    sk__tissue_shapes *t = malloc(sizeof *t);
    if (!t) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    rest_shapes(m, t);
    int count = cls == SK_TISSUE_POINT_BONE ? 3 * t->bone_count : t->muscle_count;
    if (count == 0) {
        free(t);
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "the character has no muscles");
    }
    size_t per_v = (size_t)(segments / 2 + 1) * (size_t)segments,
           per_t = (size_t)(segments / 2) * (size_t)segments * 2;
    sk_result r = sk_mesh_create(out, per_v * (size_t)count, per_t * (size_t)count, 0, err);
    for (int i = 0; r == SK_OK && i < count; i++) {
        const sk__ellipsoid *e =
            cls == SK_TISSUE_POINT_BONE ? &t->bone[i / 3][i % 3] : &t->muscle[i];
        ellipsoid_mesh(e, segments, out, per_v * (size_t)i, per_t * (size_t)i);
    }
    free(t);
    if (r == SK_OK) r = sk_mesh_compute_normals(out, err);
    if (r != SK_OK) sk_mesh_free(out);
    return r;
}
