/* The showcase object: the melody with its fingering, the piano, the hand's skeleton and
 * coupling solver, the stage; poses at any time (performance -> contact). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "products/showcase/showcase_internal.h"

static int find_material(const sk_render_scene_desc *d, const char *name)
{
    for (int i = 0; i < d->material_count; i++)
        if (strcmp(d->materials[i].name, name) == 0) return i;
    return -1;
}

static sk_result resolve_desc(const sk_showcase_desc *in, sk_showcase_desc *d, sk_error *err)
{
    *d = *in;
    if (!d->melody) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "showcase: no melody");
    if (!d->stage) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "showcase: no stage scene");
    if (!d->constraints)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "showcase: no coupling constraints");
    /* the frame keys' defaults and ranges (sk_showcase_schema) */
    sk_schema_apply_defaults(&sk__showcase_frame_schema, d);
    d->performance = sk__performance_desc_resolved(&d->performance);
    sk_result r;
    if ((r = sk_schema_check(&sk__showcase_frame_schema, d, "", err)) != SK_OK ||
        (r = sk__performance_desc_validate(&d->performance, err)) != SK_OK)
        return r;
    /* the synth desc is checked by rendering nothing */
    float none = 0;
    sk_melody empty = {0};
    if ((r = sk_synth_render(&empty, &d->synth, &none, 0, err)) != SK_OK) return r;
    return SK_OK;
}

sk_result sk_showcase_create(const sk_showcase_desc *desc, sk_showcase **out, sk_error *err)
{
    *out = NULL;
    sk_showcase *sc = calloc(1, sizeof *sc);
    if (!sc) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for the showcase");
    sk_result r = resolve_desc(desc, &sc->desc, err);
    if (r == SK_OK) r = sk_piano_init(&sc->piano, &sc->desc.piano, err);
    if (r == SK_OK) r = sk_melody_copy(sc->desc.melody, &sc->melody, err);
    if (r == SK_OK) r = sk_melody_validate(&sc->melody, err);
    sc->desc.melody = &sc->melody;
    if (r == SK_OK) {
        sk_hand_skeleton_desc hd = sc->desc.hand ? *sc->desc.hand : (sk_hand_skeleton_desc){0};
        if (hd.side == SK_HAND_SIDE_LEFT)
            r = sk_fail(err, SK_ERROR_UNSUPPORTED,
                        "hand.side: the showcase plays with a right hand");
        else
            r = sk_hand_skeleton_init(&sc->skeleton, &hd, err);
    }
    if (r == SK_OK)
        r = sk_hand_solver_create(&sc->solver, &sc->skeleton, sc->desc.constraints, NULL, 0, NULL,
                                  err);
    if (r == SK_OK) r = sk__hand_mesh_setup(sc, err);
    if (r == SK_OK) {
        sc->contact =
            (sk__contact){sc->solver, &sc->skeleton, &sc->piano, &sc->rig, &sc->desc.performance};
        r = sk__hand_rig_make(sc, err);
    }
    if (r == SK_OK) {
        /* fingers whose pads cannot be on white keys' front parts at one wrist depth
           cannot hold keys down together */
        const sk_piano_key *c4 = sk_piano_key_get(&sc->piano, 60);
        for (int a = 0; a < 5; a++)
            for (int b = 0; b < 5; b++) {
                double alo, ahi, blo, bhi;
                sk__performance_contact_range(&sc->rig, c4, a, &alo, &ahi);
                sk__performance_contact_range(&sc->rig, c4, b, &blo, &bhi);
                alo -= sc->rig.press_offset[a].z, ahi -= sc->rig.press_offset[a].z;
                blo -= sc->rig.press_offset[b].z, bhi -= sc->rig.press_offset[b].z;
                if (fmax(alo, blo) > fmin(ahi, bhi)) sc->desc.fingering.apart[a][b] = true;
            }
        r = sk_melody_choose_fingers(&sc->melody, &sc->piano, &sc->desc.fingering, NULL, err);
    }
    if (r == SK_OK) {
        sc->perf = (sk__performance){&sc->melody, &sc->piano, &sc->rig, sc->desc.performance, 0};
        sc->perf.hover_y =
            sc->piano.desc.white_top_mm + sc->desc.performance.hover_mm + sc->rig.hover_depth;
        sk_synth_desc sd = sc->desc.synth;
        int rate = sd.sample_rate ? sd.sample_rate : 44100;
        sc->duration_s = (double)sk_synth_length(&sc->melody, &sd) / rate;
        sc->frame_count = (int)floor(sc->duration_s * sc->desc.fps) + 1;
    }
    if (r == SK_OK) r = sk__forearm_setup(sc, err);
    if (r == SK_OK) {
        sc->stage = malloc(sizeof *sc->stage);
        sc->scene = malloc(sizeof *sc->scene);
        if (!sc->stage || !sc->scene)
            r = sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for the scene");
    }
    if (r == SK_OK) {
        *sc->stage = *sc->desc.stage;
        sc->desc.stage = sc->stage;
        r = sk_render_scene_desc_validate(sc->stage, err);
        if (r != SK_OK) sk_error_prefix(err, r, "stage");
    }
    if (r == SK_OK) {
        sc->ivory = find_material(sc->stage, "ivory");
        sc->ebony = find_material(sc->stage, "ebony");
        if (sc->ivory < 0 || sc->ebony < 0)
            r = sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                        "stage: the keys need materials named \"ivory\" and \"ebony\" (the stage "
                        "has %d materials)",
                        sc->stage->material_count);
    }
    for (int i = 0; r == SK_OK && i < sc->stage->material_count; i++) {
        sk_render_material_desc *m = &sc->stage->materials[i];
        if (m->type != SK_RENDER_MATERIAL_WOOD || m->wood_tree) continue;
        if ((r = sk_wood_create(&m->wood, &sc->trees[i], err)) != SK_OK)
            sk_error_prefix(err, r, "stage: materials[%d].wood", i);
        else
            m->wood_tree = sc->trees[i];
    }
    if (r != SK_OK) {
        sk_showcase_destroy(sc);
        return r;
    }
    *out = sc;
    return SK_OK;
}

void sk_showcase_destroy(sk_showcase *sc)
{
    if (!sc) return;
    for (int i = 0; i < SK_RENDER_MAX_MATERIALS; i++)
        if (sc->trees[i]) sk_wood_destroy(sc->trees[i]);
    sk__hand_mesh_free(sc);
    sk__forearm_free(sc);
    free(sc->stage);
    free(sc->scene);
    sk_hand_solver_destroy(sc->solver);
    sk_melody_free(&sc->melody);
    free(sc);
}

int sk_showcase_frame_count(const sk_showcase *sc) { return sc->frame_count; }
double sk_showcase_fps(const sk_showcase *sc) { return sc->desc.fps; }
const sk_melody *sk_showcase_melody(const sk_showcase *sc) { return &sc->melody; }
const sk_piano *sk_showcase_piano(const sk_showcase *sc) { return &sc->piano; }
const sk_hand_skeleton *sk_showcase_skeleton(const sk_showcase *sc) { return &sc->skeleton; }
const sk_hand_surface *sk_showcase_surface(const sk_showcase *sc) { return sc->surface; }
double sk_showcase_link_radius(const sk_showcase *sc, int link)
{
    return link >= 0 && link < SK_HAND_LINK_COUNT ? sc->link_radius[link] : 0;
}

sk_vec3d sk_showcase_hand_to_scene(const sk_showcase *sc, sk_vec3d p)
{
    (void)sc;
    return sk__hand_to_scene(p);
}

sk_result sk_showcase_pose_at(sk_showcase *sc, double time_s, sk_showcase_pose *out, sk_error *err)
{
    if (!isfinite(time_s))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "time %g is not finite", time_s);
    sk__intent in;
    sk__performance_at(&sc->perf, time_s, &in);
    return sk__contact_solve(&sc->contact, &in, time_s, out, err);
}
