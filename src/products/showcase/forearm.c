/* The forearm: a character of the fat and skin model of Shigemori & Kawai built and
 * simulated by the tissue module (include/shitsukan/tissue.h), its bones driven by the
 * hand's wrist. The forearm's root joint is the elbow and its joint named "wrist" rides
 * on the middle of the hand's wrist stump (measured on the hand's surface); the elbow
 * follows the wrist's travel only part way (the upper arm swings), so the forearm turns
 * as the hand moves along the keys and drops a little with the wrist at every strike
 * (performance.c), and the fat lags and swings (sec. 5). The motion is a function of time alone,
 * sampled by the simulation at every internal step; the simulation runs forward from time 0, so a
 * frame's flesh is the same whichever frames were asked for before it (an earlier frame restarts it
 * from its state at time 0). The skin carries UVs in mm (around and along the forearm in its rest
 * frame) for the skin microrelief. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "products/showcase/showcase_internal.h"

#define ELBOW_FOLLOW 0.5 /* the elbow moves this fraction of the wrist's displacement */

/* Rest frame of the forearm: d from the elbow to the wrist, b across it (the rest X axis
   made orthogonal to d), t = b x d (the back of the forearm, rest +Y). As columns. */
static sk_mat3d forearm_basis(sk_vec3d d, sk_vec3d across)
{
    d = sk_v3d_normalize(d);
    sk_vec3d b = sk_v3d_normalize(sk_v3d_sub(across, sk_v3d_scale(d, sk_v3d_dot(across, d))));
    sk_vec3d t = sk_v3d_cross(b, d);
    sk_mat3d m;
    const sk_vec3d cols[3] = {b, t, d};
    for (int c = 0; c < 3; c++) m.m[0][c] = cols[c].x, m.m[1][c] = cols[c].y, m.m[2][c] = cols[c].z;
    return m;
}

/* Where the elbow is and how the forearm is turned when the wrist is at `wrist`. */
static void forearm_place(const sk__forearm *fa, sk_vec3d wrist, sk_vec3d *elbow,
                          sk_quatd *rotation)
{
    sk_vec3d moved = sk_v3d_sub(wrist, fa->home_wrist);
    sk_vec3d guess = sk_v3d_add(fa->home_elbow,
                                sk_v3d_scale(moved, ELBOW_FOLLOW)); /* before keeping the length */
    sk_vec3d d = sk_v3d_normalize(sk_v3d_sub(wrist, guess));
    *elbow = sk_v3d_sub(wrist, sk_v3d_scale(d, fa->length));
    sk_mat3d target = forearm_basis(d, fa->across);
    sk_mat3d r; /* target * rest^T */
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            double s = 0;
            for (int k = 0; k < 3; k++) s += target.m[i][k] * fa->rest.m[j][k];
            r.m[i][j] = s;
        }
    *rotation = sk_qd_normalize(sk_m3d_to_qd(r));
}

static void forearm_sample(void *user, double seconds, sk_quatd *local, sk_vec3d *root_mm)
{
    const sk_showcase *sc = user;
    sk__intent in;
    sk__performance_at(&sc->perf, seconds, &in);
    forearm_place(&sc->forearm, sk_v3d_add(in.wrist, sc->forearm.ride), root_mm,
                  &local[sc->forearm.root]);
}

/* UVs in mm: around the forearm (angle times the point's distance from the axis, the
   seam underneath) and along it, in the rest frame. */
static void forearm_uvs(const sk__forearm *fa, sk_mesh *mesh, sk_vec3d elbow_rest)
{
    for (size_t v = 0; v < mesh->vertex_count; v++) {
        const float *p = mesh->positions + 3 * v;
        sk_vec3d q = sk_v3d_sub((sk_vec3d){p[0], p[1], p[2]}, elbow_rest);
        double c[3]; /* rest frame coordinates: across, back, along */
        for (int k = 0; k < 3; k++)
            c[k] = q.x * fa->rest.m[0][k] + q.y * fa->rest.m[1][k] + q.z * fa->rest.m[2][k];
        double x = c[0], y = c[1], z = c[2];
        double radius = sqrt(x * x + y * y);
        mesh->uvs[2 * v] = (float)(atan2(x, y) * radius);
        mesh->uvs[2 * v + 1] = (float)z;
    }
}

/* The hand's wrist stump (its vertices behind the wrist crease in the relaxed hand):
   the mean of the hand's texture there, so the skin's colour runs on across the join
   (the whole texture's mean at the hand's vertices if the stump has none), and the middle
   of its extent across and through the carpus (carpus frame, from the wrist), where the
   forearm's axis must run for the stump to lie inside it. */
static sk_result measure_stump(const sk_showcase *sc, float albedo_out[3], sk_vec3d *centre,
                               sk_error *err)
{
    const sk_image *albedo = sc->skin_albedo;
    for (int c = 0; c < 3; c++) albedo_out[c] = 0.6f;
    *centre = (sk_vec3d){0, 0, 0};
    sk_mesh mesh = {0};
    sk_result r = sk_hand_surface_export_mesh(sc->surface, NULL, NULL, false, &mesh, err);
    if (r != SK_OK) return r;
    double dofs[SK_HAND_DOF_COUNT];
    sk_hand_frames frames;
    sk_hand_relaxed(&sc->skeleton, dofs);
    sk_hand_forward(&sc->skeleton, dofs, &frames);
    sk_mat3d to_carpus = sk_m3d_transpose(frames.rotation[0]);
    double sum[2][3] = {{0, 0, 0}, {0, 0, 0}}, lo[3] = {INFINITY, INFINITY, INFINITY},
           hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    size_t count[2] = {0, 0};
    bool textured = albedo && albedo->width > 0 && albedo->height > 0 && mesh.uvs;
    for (size_t v = 0; v < mesh.vertex_count; v++) {
        const float *p = mesh.positions + 3 * v;
        sk_vec3d q = sk_v3d_sub((sk_vec3d){p[0], p[1], p[2]}, frames.point[0]);
        sk_vec3d l = sk_m3d_apply(to_carpus, q);
        const double local[3] = {l.x, l.y, l.z}; /* across, along the fingers, palmar */
        int part = local[1] < 0 ? 0 : 1;         /* 0: the stump */
        for (int k = 0; part == 0 && k < 3; k++)
            lo[k] = fmin(lo[k], local[k]), hi[k] = fmax(hi[k], local[k]);
        if (!textured) continue;
        int x = (int)(mesh.uvs[2 * v] * albedo->width),
            y = (int)((1 - mesh.uvs[2 * v + 1]) * albedo->height);
        x = x < 0 ? 0 : x >= albedo->width ? albedo->width - 1 : x;
        y = y < 0 ? 0 : y >= albedo->height ? albedo->height - 1 : y;
        const float *t = sk_image_pixel(albedo, x, y);
        bool grey = albedo->channels < 3;
        double rgb[3] = {t[0], grey ? t[0] : t[1], grey ? t[0] : t[2]};
        for (int c = 0; c < 3; c++) sum[part][c] += rgb[c];
        count[part]++;
    }
    sk_mesh_free(&mesh);
    int part = count[0] ? 0 : 1;
    for (int c = 0; c < 3 && count[part]; c++) albedo_out[c] = (float)(sum[part][c] / count[part]);
    if (lo[0] <= hi[0]) *centre = (sk_vec3d){0.5 * (lo[0] + hi[0]), 0, 0.5 * (lo[2] + hi[2])};
    return SK_OK;
}

/* The forearm's end lies over the back of the hand, its skin nearly on the hand's (the
 * stump inside it), so the two surfaces would cross in patches shaped by the forearm's
 * grid. The end is drawn in toward the forearm's axis, by nothing TUCK_FROM_MM before
 * the wrist and by TUCK_MM at the skin's end (smoothly), so it dives under the hand's
 * skin and the two meet along one line. Only the rendered mesh is changed, never the
 * simulation. */
#define TUCK_MM 5.0
#define TUCK_FROM_MM 20.0
/* The forearm's microrelief (the back of the hand's, at full strength) is sharper than
   the hand's baked one: over the last RELIEF_FADE_MM before the tuck and the tuck itself
   it softens to RELIEF_END_WEIGHT of its strength, so the texture does not change at the
   join. */
#define RELIEF_FADE_MM 20.0
#define RELIEF_END_WEIGHT 0.4f

static sk_result tuck_weights(sk__forearm *fa, sk_error *err)
{
    size_t n = fa->mesh.vertex_count;
    fa->tuck = malloc((n ? n : 1) * sizeof *fa->tuck);
    if (!fa->tuck) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for the forearm");
    double end = 0, from = fa->length - TUCK_FROM_MM;
    for (size_t v = 0; v < n; v++)
        end = fmax(end, fa->mesh.uvs[2 * v + 1]); /* along, mm from the elbow */
    fa->relief.fade_from = (float)(from - RELIEF_FADE_MM);
    fa->relief.fade_to = (float)fmax(end, from);
    fa->relief.end_weight = RELIEF_END_WEIGHT;
    for (size_t v = 0; v < n; v++) {
        double u = end > from ? (fa->mesh.uvs[2 * v + 1] - from) / (end - from) : 0;
        u = u < 0 ? 0 : u > 1 ? 1 : u;
        fa->tuck[v] = (float)(u * u * (3 - 2 * u));
    }
    return SK_OK;
}

void sk__forearm_skin_texture(void *user, const sk_render_surface *s, sk_render_texel *texel)
{
    const sk__forearm_relief *relief = user;
    sk_vec3f n;
    sk_skin_eval(relief->skin, s->st.x, s->st.y, NULL, &n);
    float u = (s->st.y - relief->fade_from) / (relief->fade_to - relief->fade_from);
    u = u < 0 ? 0 : u > 1 ? 1 : u;
    float weight = 1 - (1 - relief->end_weight) * u * u * (3 - 2 * u);
    if (n.z > 1e-6f) { /* the height field's normal is normalize(-dh/ds, -dh/dt, 1) */
        texel->slope.x -= weight * n.x / n.z;
        texel->slope.y -= weight * n.y / n.z;
    }
}

sk_result sk__forearm_setup(sk_showcase *sc, sk_error *err)
{
    sk__forearm *fa = &sc->forearm;
    fa->relief.skin = sc->desc.back_skin;
    if (!sc->desc.forearm) return SK_OK;
    sk_tissue_character_desc *cd = malloc(sizeof *cd);
    if (!cd) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for the forearm");
    *cd = *sc->desc.forearm;
    sk_tissue_character_desc_resolve(cd);
    sk_result r = sk_tissue_character_desc_validate(cd, err);
    int wrist = -1;
    for (int j = 0; r == SK_OK && j < cd->joint_count; j++) {
        if (!cd->joints[j].parent[0]) fa->root = j;
        if (strcmp(cd->joints[j].name, "wrist") == 0) wrist = j;
    }
    if (r == SK_OK && wrist < 0)
        r = sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                    "forearm: no joint named \"wrist\" (it rides on the hand's wrist)");
    if (r == SK_OK) r = sk_tissue_model_build(cd, NULL, &fa->model, err);
    if (r != SK_OK) {
        free(cd);
        return sk_error_prefix(err, r, "forearm");
    }
    /* the rest frame: elbow (root) to wrist, rest X across, rest +Y the back */
    sk_quatd identity[SK_TISSUE_MAX_JOINTS];
    for (int j = 0; j < SK_TISSUE_MAX_JOINTS; j++) identity[j] = sk_qd_identity();
    sk_vec3d elbow_rest = {cd->joints[fa->root].offset_mm[0], cd->joints[fa->root].offset_mm[1],
                           cd->joints[fa->root].offset_mm[2]};
    sk_tissue_pose *rest = malloc(sizeof *rest);
    if (!rest) {
        free(cd);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for the forearm");
    }
    sk_tissue_model_pose(fa->model, identity, elbow_rest, rest);
    sk_vec3d along = sk_v3d_sub(rest->position[wrist], rest->position[fa->root]);
    free(rest);
    free(cd);
    fa->length = sk_v3d_length(along);
    if (!(fa->length > 1))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "forearm: the wrist is %g mm from the root joint (need > 1)", fa->length);
    fa->rest = forearm_basis(along, (sk_vec3d){1, 0, 0});
    /* the hand's carpus in the playing posture: the forearm lies along it (sloping down
       to the wrist as the carpus does), so the hand's wrist stump runs inside it */
    double dofs[SK_HAND_DOF_COUNT], torque[SK_HAND_DOF_COUNT] = {0};
    sk_hand_frames frames;
    sk_vec3d pads[5];
    r = sk__contact_posture(&sc->contact, (sk_vec3d){0, 0, 0}, torque, dofs, &frames, pads, err);
    if (r != SK_OK) return r;
    const sk_mat3d *carpus = &frames.rotation[0];
    sk_vec3d stump;
    r = measure_stump(sc, sc->forearm_albedo, &stump, err);
    if (r != SK_OK) return r;
    fa->ride = sk__hand_to_scene(sk_m3d_apply(*carpus, stump));
    sk_vec3d fingers =
        sk__hand_to_scene((sk_vec3d){carpus->m[0][1], carpus->m[1][1], carpus->m[2][1]});
    sk_vec3d across =
        sk__hand_to_scene((sk_vec3d){carpus->m[0][0], carpus->m[1][0], carpus->m[2][0]});
    fa->home_axis = sk_v3d_normalize(fingers);
    /* across must make the back of the forearm face up */
    if (sk_v3d_cross(across, fa->home_axis).y < 0) across = sk_v3d_scale(across, -1);
    fa->across = across;
    sk__intent in;
    sk__performance_at(&sc->perf, 0, &in);
    fa->home_wrist = sk_v3d_add(in.wrist, fa->ride);
    fa->home_elbow = sk_v3d_sub(fa->home_wrist, sk_v3d_scale(fa->home_axis, fa->length));
    /* the simulation and its state at time 0 (a restart) */
    sk_tissue_motion motion = {forearm_sample, sc, sc->duration_s};
    r = sk_tissue_sim_create(fa->model, &motion, &fa->sim, err);
    if (r != SK_OK) return sk_error_prefix(err, r, "forearm");
    fa->start_size = sk_tissue_sim_state_size(fa->sim);
    fa->start = malloc(fa->start_size);
    if (!fa->start)
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for the forearm's state");
    r = sk_tissue_sim_save_state(fa->sim, fa->start, fa->start_size, err);
    if (r == SK_OK) r = sk_tissue_model_rest_skin(fa->model, &fa->mesh, err);
    if (r != SK_OK) return r;
    fa->mesh.uvs = malloc(2 * fa->mesh.vertex_count * sizeof *fa->mesh.uvs);
    if (!fa->mesh.uvs) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for the forearm");
    forearm_uvs(fa, &fa->mesh, elbow_rest);
    return tuck_weights(fa, err);
}

void sk__forearm_free(sk_showcase *sc)
{
    sk__forearm *fa = &sc->forearm;
    sk_tissue_sim_destroy(fa->sim);
    sk_tissue_model_destroy(fa->model);
    sk_mesh_free(&fa->mesh);
    free(fa->start);
    free(fa->tuck);
}

sk_result sk__forearm_advance(sk_showcase *sc, double seconds, sk_error *err)
{
    sk__forearm *fa = &sc->forearm;
    if (!fa->sim) return SK_OK;
    sk_result r = SK_OK;
    if (seconds < sk_tissue_sim_time(fa->sim) - 1e-9)
        r = sk_tissue_sim_load_state(fa->sim, fa->start, fa->start_size, err);
    if (r == SK_OK) r = sk_tissue_sim_skin(fa->sim, seconds, fa->mesh.positions, err);
    return r == SK_OK ? r : sk_error_prefix(err, r, "forearm");
}

sk_result sk__forearm_render_mesh(sk_showcase *sc, double seconds, sk_error *err)
{
    sk__forearm *fa = &sc->forearm;
    if (!fa->sim) return SK_OK;
    /* the end tucked in toward the forearm's axis where the hand's skin covers it */
    sk__intent in;
    sk__performance_at(&sc->perf, seconds, &in);
    sk_vec3d wrist = sk_v3d_add(in.wrist, fa->ride), elbow;
    sk_quatd turn;
    forearm_place(fa, wrist, &elbow, &turn);
    sk_vec3d axis = sk_v3d_normalize(sk_v3d_sub(wrist, elbow));
    float *p = fa->mesh.positions;
    for (size_t v = 0; v < fa->mesh.vertex_count; v++, p += 3) {
        if (fa->tuck[v] <= 0) continue;
        sk_vec3d q = sk_v3d_sub((sk_vec3d){p[0], p[1], p[2]}, elbow);
        sk_vec3d radial = sk_v3d_sub(q, sk_v3d_scale(axis, sk_v3d_dot(q, axis)));
        double r = sk_v3d_length(radial);
        if (r < 2 * TUCK_MM) continue;
        sk_vec3d in_by = sk_v3d_scale(radial, -TUCK_MM * fa->tuck[v] / r);
        p[0] += (float)in_by.x, p[1] += (float)in_by.y, p[2] += (float)in_by.z;
    }
    return sk_mesh_compute_normals(&fa->mesh, err);
}

size_t sk_showcase_forearm_points(const sk_showcase *sc)
{
    return sc->forearm.sim ? sc->forearm.mesh.vertex_count : 0;
}

sk_result sk_showcase_forearm_at(sk_showcase *sc, int frame, float *skin, float *carried,
                                 sk_error *err)
{
    if (!sc->forearm.sim)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "the showcase has no forearm");
    if (frame < 0 || frame >= sc->frame_count)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "frame %d is out of range [0, %d]", frame,
                       sc->frame_count - 1);
    sk_result r = sk__forearm_advance(sc, frame / sc->desc.fps, err);
    if (r != SK_OK) return r;
    size_t n = 3 * sc->forearm.mesh.vertex_count;
    if (skin) memcpy(skin, sc->forearm.mesh.positions, n * sizeof *skin);
    if (carried) sk_tissue_sim_skin_reference(sc->forearm.sim, carried);
    return SK_OK;
}
