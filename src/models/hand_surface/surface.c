/* The hand surface object (thesis 4.1): the implicit flesh around the relaxed skeleton
 * meshed into one closed manifold mesh of about the thesis's 8000 triangles (4.1.3),
 * with its skin weights, normals and atlas; the left hand is the exact mirror image. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "models/hand_surface/surface_internal.h"

static sk_result check_flesh(const sk_hand_flesh *f, sk_error *err)
{
    sk_result r =
        sk_check_range_f(err, "flesh.reference_breadth_mm", f->reference_breadth_mm, 30, 200);
    for (int i = 0; i < SK_HAND_FINGER_COUNT && r == SK_OK; i++) {
        int n = i == SK_HAND_THUMB ? 3 : 4;
        for (int k = 0; k < n && r == SK_OK; k++) {
            r = sk_check_range_f(err, "flesh.fingers.breadth_mm", f->finger[i].breadth_mm[k], 2,
                                 80);
            if (r == SK_OK)
                r = sk_check_range_f(err, "flesh.fingers.thickness_mm",
                                     f->finger[i].thickness_mm[k], 2, 80);
        }
        for (int k = 0; k < 2 && r == SK_OK; k++) {
            r = sk_check_range_f(err, "flesh.fingers.metacarpal_breadth_mm",
                                 f->finger[i].metacarpal_breadth_mm[k], 2, 80);
            if (r == SK_OK)
                r = sk_check_range_f(err, "flesh.fingers.metacarpal_thickness_mm",
                                     f->finger[i].metacarpal_thickness_mm[k], 2, 80);
        }
    }
    if (r == SK_OK)
        r = sk_check_range_f(err, "flesh.wrist.breadth_mm", f->wrist_breadth_mm, 10, 200);
    if (r == SK_OK)
        r = sk_check_range_f(err, "flesh.wrist.thickness_mm", f->wrist_thickness_mm, 10, 200);
    if (r == SK_OK)
        r = sk_check_range_f(err, "flesh.wrist.stump_length_mm", f->stump_length_mm, 0, 200);
    const sk_hand_flesh_pad *pads[2] = {&f->thenar, &f->hypothenar};
    for (int i = 0; i < 2 && r == SK_OK; i++)
        for (int k = 0; k < 3 && r == SK_OK; k++)
            r = sk_check_range_f(err, "flesh pad radius_mm", pads[i]->radius_mm[k], 1, 100);
    if (r == SK_OK) r = sk_check_range_f(err, "flesh.webs.reach", f->web_reach, 0, 0.8);
    if (r == SK_OK)
        r = sk_check_range_f(err, "flesh.webs.thickness_mm", f->web_thickness_mm, 1, 40);
    if (r == SK_OK)
        r = sk_check_range_f(err, "flesh.webs.thumb_thickness_mm", f->thumb_web_thickness_mm, 1,
                             40);
    if (r == SK_OK) r = sk_check_range_f(err, "flesh.nails.length", f->nail_length, 0.1, 0.9);
    if (r == SK_OK) r = sk_check_range_f(err, "flesh.nails.breadth", f->nail_breadth, 0.1, 0.95);
    if (r == SK_OK)
        r = sk_check_range_f(err, "flesh.nails.thickness_mm", f->nail_thickness_mm, 0, 3);
    if (r == SK_OK) r = sk_check_range_f(err, "flesh.blend.joint_mm", f->blend_joint_mm, 0.1, 20);
    if (r == SK_OK) r = sk_check_range_f(err, "flesh.blend.root_mm", f->blend_root_mm, 0.1, 20);
    if (r == SK_OK) r = sk_check_range_f(err, "flesh.blend.palm_mm", f->blend_palm_mm, 0.1, 30);
    return r;
}

void sk_hand_surface_destroy(sk_hand_surface *s)
{
    if (!s) return;
    sk_mesh_free(&s->mesh);
    for (int i = 0; i < 2; i++) {
        free(s->links[i]);
        free(s->weights[i]);
    }
    free(s->influences);
    free(s->by_influence);
    free(s->export_map);
    free(s->export_uv);
    free(s->export_indices);
    free(s);
}

/* Unit normals of the field's gradient at the vertices (the true surface's normals). */
static void field_normals(const sk__hand_field *field, sk_mesh *m)
{
#pragma omp parallel for schedule(static) if (m->vertex_count > 2048)
    for (size_t v = 0; v < m->vertex_count; v++) {
        const float *p = m->positions + 3 * v;
        sk_vec3d g = sk_v3d_normalize(sk__hand_field_gradient(field, sk_v3d(p[0], p[1], p[2])));
        m->normals[3 * v] = (float)g.x, m->normals[3 * v + 1] = (float)g.y,
                       m->normals[3 * v + 2] = (float)g.z;
    }
}

sk_result sk__hand_surface_finish(sk_hand_surface *s, sk_error *err)
{
    sk_mesh *m = &s->mesh;
    size_t V = m->vertex_count;
    for (int i = 0; i < 2; i++) {
        s->links[i] = calloc(4 * V, sizeof *s->links[i]);
        s->weights[i] = calloc(4 * V, sizeof *s->weights[i]);
        if (!s->links[i] || !s->weights[i])
            return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for skin weights");
    }
    s->influences = malloc(V);
    s->by_influence = malloc(V * sizeof *s->by_influence);
    if (!s->influences || !s->by_influence)
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for skin weights");
    field_normals(&s->field, m);
    sk__hand_weights_compute(&s->field, &s->right, m->positions, V, s->links[0], s->weights[0],
                             s->links[1], s->weights[1]);
    for (size_t v = 0; v < V; v++) {
        int n = 0;
        while (n < 4 && s->weights[1][4 * v + n] > 0.0f) n++;
        s->influences[v] = (uint8_t)(n ? n : 1);
    }
    uint32_t fill[5] = {0};
    for (size_t v = 0; v < V; v++) fill[s->influences[v]]++;
    s->influence_first[0] = 0;
    for (int n = 1; n <= 4; n++) s->influence_first[n] = s->influence_first[n - 1] + fill[n];
    for (int n = 1; n <= 4; n++) fill[n] = s->influence_first[n - 1];
    for (size_t v = 0; v < V; v++) s->by_influence[fill[s->influences[v]]++] = (uint32_t)v;
    /* the nail plates: vertices on a nail primitive's surface */
    float *nail;
    sk_result r = sk_mesh_add_attribute(m, "nail", 1, &nail, err);
    if (r != SK_OK) return r;
    for (size_t v = 0; v < V; v++) {
        const float *p = m->positions + 3 * v;
        for (int i = 0; i < s->field.count; i++)
            if (s->field.prim[i].nail &&
                sk__hand_prim_eval(&s->field.prim[i], sk_v3d(p[0], p[1], p[2])) < 0.25)
                nail[v] = 1;
    }
    if ((r = sk__hand_atlas_build(s, err)) != SK_OK) return r;
    if (s->skeleton.side == SK_HAND_SIDE_LEFT) {
        for (size_t v = 0; v < V; v++) {
            m->positions[3 * v] = -m->positions[3 * v];
            m->normals[3 * v] = -m->normals[3 * v];
        }
        for (size_t t = 0; t < m->triangle_count; t++) {
            uint32_t *tv = m->indices + 3 * t, x = tv[1];
            tv[1] = tv[2], tv[2] = x;
            uint32_t *ev = s->export_indices + 3 * t, y = ev[1];
            ev[1] = ev[2], ev[2] = y;
        }
    }
    double q[SK_HAND_DOF_COUNT];
    sk_hand_relaxed(&s->skeleton, q);
    sk_hand_forward(&s->skeleton, q, &s->bind);
    return SK_OK;
}

/* The meshing grid step: 2 mm at the default hand size resolves the gaps between the
   fingers; finer for meshes denser than the default. */
static double grid_step(const sk_hand_skeleton *right, const sk_hand_surface_desc *d, int triangles)
{
    if (d->cell_mm != 0.0) return d->cell_mm;
    double cell = 2.0 * right->hand_breadth_mm / 85.0 * fmin(1.0, sqrt(8000.0 / triangles));
    return fmax(cell, 0.35);
}

/* Bytes per unit of hand length x breadth / cell^2 (mm^2 / mm^2), and the fixed part:
   fitted to the peak resident memory of 8000, 50000 and 200000 triangles (29, 132 and
   500 MB at 190 x 85 mm), rounded up. */
#define SURFACE_BYTES_PER_AREA_CELL 5200.0
#define SURFACE_BYTES_FIXED (16.0 * 1048576.0)

double sk_hand_surface_memory(const sk_hand_skeleton *skeleton, const sk_hand_surface_desc *desc)
{
    sk_hand_surface_desc d = {0};
    if (desc) d = *desc;
    int triangles = d.triangles > 0 ? d.triangles : 8000;
    sk_hand_skeleton fallback;
    if (!skeleton) {
        if (sk_hand_skeleton_init(&fallback, NULL, NULL) != SK_OK) return SURFACE_BYTES_FIXED;
        skeleton = &fallback;
    }
    double cell = grid_step(skeleton, &d, triangles);
    if (!(cell > 0)) cell = 0.2;
    return SURFACE_BYTES_FIXED + SURFACE_BYTES_PER_AREA_CELL * skeleton->hand_length_mm *
                                     skeleton->hand_breadth_mm / (cell * cell);
}

sk_result sk_hand_surface_create(sk_hand_surface **out, const sk_hand_skeleton *skeleton,
                                 const sk_hand_surface_desc *desc, sk_error *err)
{
    *out = NULL;
    sk_hand_surface_desc d = {0};
    if (desc) d = *desc;
    if (!skeleton) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "skeleton is NULL");
    sk_hand_surface_desc sized = d;
    sk_schema_apply_defaults(&sk_hand_surface_schema, &sized);
    int triangles = sized.triangles;
    sk_result r = sk_schema_check(&sk_hand_surface_schema, &sized, "", err);
    if (r != SK_OK) return r;
    sk_hand_surface *s = calloc(1, sizeof *s);
    if (!s) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for the hand surface");
    if (d.flesh)
        s->flesh = *d.flesh;
    else
        sk_hand_flesh_default(&s->flesh);
    if ((r = check_flesh(&s->flesh, err)) != SK_OK) {
        free(s);
        return r;
    }
    s->skeleton = *skeleton;
    s->right = *skeleton;
    s->right.side = SK_HAND_SIDE_RIGHT;
    sk__hand_field_build(&s->field, &s->right, &s->flesh);
    double cell = grid_step(&s->right, &d, triangles);
    sk__hand_trimesh tm;
    r = sk__hand_extract(&s->field, cell, &tm, err);
    if (r == SK_OK) r = sk__hand_simplify(&tm, (size_t)triangles, err);
    if (r == SK_OK) {
        sk__hand_relax(&tm, &s->field, 3);
        sk__hand_untangle(&tm, &s->field);
        r = sk_mesh_create(&s->mesh, tm.vertex_count, tm.tri_count, SK_MESH_NORMALS, err);
    }
    if (r == SK_OK) {
        for (size_t i = 0; i < 3 * tm.vertex_count; i++) s->mesh.positions[i] = (float)tm.pos[i];
        memcpy(s->mesh.indices, tm.tri, 3 * tm.tri_count * sizeof *tm.tri);
    }
    sk__hand_trimesh_free(&tm);
    if (r == SK_OK) r = sk__hand_surface_finish(s, err);
    if (r != SK_OK) {
        sk_hand_surface_destroy(s);
        return r;
    }
    *out = s;
    return SK_OK;
}

const sk_mesh *sk_hand_surface_mesh(const sk_hand_surface *s) { return &s->mesh; }
const sk_hand_skeleton *sk_hand_surface_skeleton(const sk_hand_surface *s) { return &s->skeleton; }

/* The field is built on the right hand: a left hand's point is mirrored into it. */
static sk_vec3d to_right(const sk_hand_surface *s, sk_vec3d p)
{
    if (s->skeleton.side == SK_HAND_SIDE_LEFT) p.x = -p.x;
    return p;
}

double sk_hand_surface_field(const sk_hand_surface *s, sk_vec3d p)
{
    return sk__hand_field_eval(&s->field, to_right(s, p));
}

sk_vec3d sk_hand_surface_field_gradient(const sk_hand_surface *s, sk_vec3d p)
{
    sk_vec3d g = sk__hand_field_gradient(&s->field, to_right(s, p));
    return to_right(s, g);
}

double sk_hand_surface_distance(const sk_hand_surface *s, sk_vec3d p, sk_vec3d *closest)
{
    sk_vec3d c;
    double d = sk__hand_field_project(&s->field, to_right(s, p), &c);
    if (closest) *closest = to_right(s, c);
    return d;
}

void sk_hand_surface_weights(const sk_hand_surface *s, sk_hand_weights which,
                             const uint16_t **links, const float **weights)
{
    int i = which == SK_HAND_WEIGHTS_NEAREST ? 0 : 1;
    if (links) *links = s->links[i];
    if (weights) *weights = s->weights[i];
}
