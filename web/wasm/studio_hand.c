/* The hand panel's calls (thesis ch. 3 and sec. 4.2): a skeleton, the constraint set in
 * use (natural, Table 3.2, a user's constraint file or calibrated potential, or none =
 * coupling off), pins and torques, the equilibrium solve with forward kinematics, a
 * keyframe animation solved frame by frame, and a fingertip dragged to a point
 * (sk_hand_reach). */
#include <stdlib.h>
#include <string.h>

#include <cjson/cJSON.h>

#include "shitsukan/hand.h"
#include "studio.h"

struct studio_hand {
    sk_hand_skeleton skeleton;
    sk_hand_constraints constraints;
    sk_hand_solver *solver;
    sk_hand_potential potential;
    sk_hand_potential_solver *potential_solver; /* non-NULL when a potential is in use */
    sk_hand_input input;
    double dofs[SK_HAND_DOF_COUNT];
    sk_hand_frames frames;
    sk_hand_solve_info info;
    double *animation; /* frames x SK_HAND_DOF_COUNT of the last animation */
    int animation_frames;
};

const sk_hand_skeleton *studio_hand_skeleton(const studio_hand *h) { return &h->skeleton; }
const sk_hand_frames *studio_hand_frames(const studio_hand *h) { return &h->frames; }

static void drop_solvers(studio_hand *h)
{
    sk_hand_solver_destroy(h->solver);
    h->solver = NULL;
    sk_hand_potential_solver_destroy(h->potential_solver);
    h->potential_solver = NULL;
    sk_hand_potential_free(&h->potential);
    memset(&h->potential, 0, sizeof h->potential);
}

STUDIO_API void studio_hand_destroy(studio_hand *h)
{
    if (!h) return;
    drop_solvers(h);
    free(h->animation);
    free(h);
}

/* A right (side 1) or left (2) hand of the default anatomy, springs only. */
STUDIO_API studio_hand *studio_hand_create(int side, sk_error *err)
{
    studio_hand *h = calloc(1, sizeof *h);
    if (!h) {
        sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
        return NULL;
    }
    sk_hand_skeleton_desc d = {0};
    d.side = side == 2 ? SK_HAND_SIDE_LEFT : SK_HAND_SIDE_RIGHT;
    if (sk_hand_skeleton_init(&h->skeleton, &d, err) != SK_OK ||
        sk_hand_solver_create(&h->solver, &h->skeleton, &h->constraints, NULL, 0, NULL, err) !=
            SK_OK) {
        studio_hand_destroy(h);
        return NULL;
    }
    sk_hand_relaxed(&h->skeleton, h->dofs);
    sk_hand_forward(&h->skeleton, h->dofs, &h->frames);
    return h;
}

/* The set in use from its JSON text: a constraint file (natural.json, Table 3.2, `hand
 * calibrate` rows) or a calibrated potential (`hand calibrate --potential`); NULL or ""
 * = none (springs only: coupling off). On error the previous set stays. */
STUDIO_API int studio_hand_use_set(studio_hand *h, const char *json, const char *name,
                                   sk_error *err)
{
    sk_hand_constraints *c = calloc(1, sizeof *c);
    if (!c) return (int)sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    size_t n = json ? strlen(json) : 0;
    sk_result r = SK_OK;
    sk_hand_potential pot;
    memset(&pot, 0, sizeof pot);
    bool is_potential = false;
    if (n > 0) {
        cJSON *root = cJSON_ParseWithLength(json, n);
        is_potential = root && cJSON_GetObjectItemCaseSensitive(root, "components") != NULL;
        cJSON_Delete(root);
        r = is_potential ? sk_hand_potential_parse(json, n, name, &h->skeleton, &pot, err)
                         : sk_hand_constraints_parse(json, n, name, &h->skeleton, c, err);
    }
    sk_hand_solver *solver = NULL;
    sk_hand_potential_solver *ps = NULL;
    if (r == SK_OK && is_potential)
        r = sk_hand_potential_solver_create(&ps, &h->skeleton, &pot, NULL, err);
    if (r == SK_OK && !is_potential)
        r = sk_hand_solver_create(&solver, &h->skeleton, c, NULL, 0, NULL, err);
    if (r != SK_OK) {
        sk_hand_potential_free(&pot);
        free(c);
        return (int)r;
    }
    drop_solvers(h);
    h->constraints = *c;
    free(c);
    h->solver = solver;
    h->potential_solver = ps;
    h->potential = pot;
    return SK_OK;
}

/* Rows of the set in use (0 for none or a potential). */
STUDIO_API int studio_hand_row_count(const studio_hand *h) { return h->constraints.row_count; }

STUDIO_API void studio_hand_clear_inputs(studio_hand *h) { memset(&h->input, 0, sizeof h->input); }

/* Pins a DOF at an absolute value (radians; mm for translations), or frees it. */
STUDIO_API void studio_hand_pin(studio_hand *h, int dof, int pinned, double value)
{
    if (dof < 0 || dof >= SK_HAND_DOF_COUNT) return;
    h->input.pinned[dof] = pinned != 0;
    h->input.pin_value[dof] = value;
}

STUDIO_API void studio_hand_torque(studio_hand *h, int dof, double torque)
{
    if (dof < 0 || dof >= SK_HAND_DOF_COUNT) return;
    h->input.torque[dof] = torque;
}

static sk_result solve_input(studio_hand *h, const sk_hand_input *in, double *dofs, sk_error *err)
{
    if (h->potential_solver)
        return sk_hand_potential_solve(h->potential_solver, in, dofs, &h->info, NULL, err);
    return sk_hand_solve(h->solver, in, dofs, &h->info, err);
}

/* The equilibrium for the current inputs, then the joint positions and link frames. */
STUDIO_API int studio_hand_solve(studio_hand *h, sk_error *err)
{
    sk_result r = solve_input(h, &h->input, h->dofs, err);
    if (r == SK_OK) sk_hand_forward(&h->skeleton, h->dofs, &h->frames);
    return (int)r;
}

/* Poses the skeleton at given DOF values (no solve), e.g. an animation frame. */
STUDIO_API void studio_hand_set_dofs(studio_hand *h, const double *dofs)
{
    memcpy(h->dofs, dofs, sizeof h->dofs);
    sk_hand_forward(&h->skeleton, h->dofs, &h->frames);
}

STUDIO_API const double *studio_hand_dofs(const studio_hand *h) { return h->dofs; }

/* Joint positions (SK_HAND_POINT_COUNT x 3, mm) and link frames (SK_HAND_LINK_COUNT x 9,
 * row-major rotation matrices whose columns are the link axes) of the last pose. */
STUDIO_API void studio_hand_pose_geometry(const studio_hand *h, float *points, float *rotations)
{
    for (int i = 0; i < SK_HAND_POINT_COUNT; i++) {
        points[3 * i] = (float)h->frames.point[i].x;
        points[3 * i + 1] = (float)h->frames.point[i].y;
        points[3 * i + 2] = (float)h->frames.point[i].z;
    }
    for (int l = 0; l < SK_HAND_LINK_COUNT; l++)
        for (int k = 0; k < 9; k++)
            rotations[9 * l + k] = (float)h->frames.rotation[l].m[k / 3][k % 3];
}

/* [residual, converged, clamped DOFs, pins clamped] of the last solve. */
STUDIO_API void studio_hand_info(const studio_hand *h, double *out)
{
    out[0] = h->info.residual;
    out[1] = h->info.converged;
    out[2] = h->info.clamped_count;
    out[3] = h->info.pins_clamped;
}

/* Every DOF (name, meaning, limits, relaxed value, translation), point and link, and
 * the finger colours of the stick figures, as JSON. */
STUDIO_API char *studio_hand_describe(const studio_hand *h)
{
    cJSON *root = cJSON_CreateObject();
    cJSON *dofs = cJSON_AddArrayToObject(root, "dofs");
    for (int i = 0; i < SK_HAND_DOF_COUNT; i++) {
        const sk_hand_dof_info *info = sk_hand_dof(i);
        cJSON *o = cJSON_CreateObject();
        cJSON_AddStringToObject(o, "name", info->name);
        cJSON_AddStringToObject(o, "meaning", info->meaning);
        cJSON_AddBoolToObject(o, "translation", info->translation);
        cJSON_AddNumberToObject(o, "link", info->link);
        cJSON_AddNumberToObject(o, "min", h->skeleton.dof[i].min);
        cJSON_AddNumberToObject(o, "max", h->skeleton.dof[i].max);
        cJSON_AddNumberToObject(o, "relaxed", h->skeleton.dof[i].relaxed);
        cJSON_AddItemToArray(dofs, o);
    }
    cJSON *points = cJSON_AddArrayToObject(root, "points");
    for (int p = 0; p < SK_HAND_POINT_COUNT; p++) {
        cJSON *o = cJSON_CreateObject();
        cJSON_AddStringToObject(o, "name", sk_hand_point_name(p));
        cJSON_AddNumberToObject(o, "parent", sk_hand_point_parent(p));
        cJSON_AddItemToArray(points, o);
    }
    cJSON *links = cJSON_AddArrayToObject(root, "links");
    for (int l = 0; l < SK_HAND_LINK_COUNT; l++) {
        cJSON *o = cJSON_CreateObject();
        cJSON_AddStringToObject(o, "name", sk_hand_link_name(l));
        cJSON_AddNumberToObject(o, "base", sk_hand_link_point(l));
        cJSON_AddNumberToObject(o, "end", sk_hand_link_end_point(l));
        cJSON_AddNumberToObject(o, "length", h->skeleton.length[l]);
        cJSON_AddItemToArray(links, o);
    }
    cJSON *colors = cJSON_AddArrayToObject(root, "finger_colors");
    for (int f = 0; f < SK_HAND_FINGER_COUNT; f++) {
        sk_color c = sk_hand_finger_color((sk_hand_finger)f);
        cJSON *rgb = cJSON_CreateArray();
        cJSON_AddItemToArray(rgb, cJSON_CreateNumber(c.r));
        cJSON_AddItemToArray(rgb, cJSON_CreateNumber(c.g));
        cJSON_AddItemToArray(rgb, cJSON_CreateNumber(c.b));
        cJSON_AddItemToArray(colors, rgb);
    }
    cJSON_AddNumberToObject(root, "hand_length_mm", h->skeleton.hand_length_mm);
    char *text = cJSON_PrintUnformatted(root);
    cJSON_Delete(root);
    return text;
}

/* Solves every frame of an animation file (the format `shitsukan hand animate` reads:
 * keys of pins and torques) with the set in use; returns the frame count (0 on error).
 * The frames stay in the hand until the next call (studio_hand_animation_frames). */
STUDIO_API int studio_hand_animate(studio_hand *h, const char *json, double *fps, sk_error *err)
{
    sk_hand_animation *anim = malloc(sizeof *anim);
    if (!anim) {
        sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
        return 0;
    }
    int frames = 0;
    if (sk_hand_animation_parse(json, strlen(json), "keyframes", anim, err) == SK_OK) {
        frames = sk_hand_animation_frame_count(anim);
        double *q = malloc(sizeof(double) * SK_HAND_DOF_COUNT * (size_t)(frames > 0 ? frames : 1));
        if (!q) {
            sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
            frames = 0;
        }
        for (int f = 0; f < frames; f++) {
            sk_hand_input in;
            sk_hand_animation_input(anim, f, &in);
            if (solve_input(h, &in, q + (size_t)f * SK_HAND_DOF_COUNT, err) != SK_OK) {
                frames = 0;
                break;
            }
        }
        if (frames > 0) {
            free(h->animation);
            h->animation = q;
            h->animation_frames = frames;
            *fps = anim->fps;
        } else {
            free(q);
        }
    }
    free(anim);
    return frames;
}

STUDIO_API const double *studio_hand_animation_frames(const studio_hand *h) { return h->animation; }

/* Drags a fingertip toward `target` (mm): pins its finger's three reach DOFs at the
 * values whose equilibrium (with the coupling of the set in use) brings the tip nearest
 * the target (sk_hand_reach), then poses the hand there. Returns the distance left, or -1
 * with the error. */
STUDIO_API double studio_hand_reach(studio_hand *h, int finger, double tx, double ty, double tz,
                                    sk_error *err)
{
    sk_hand_reach_desc d = {.finger = (sk_hand_finger)finger,
                            .target = {tx, ty, tz},
                            .solver = h->solver,
                            .potential_solver = h->potential_solver};
    double distance;
    if (sk_hand_reach(&h->skeleton, &d, &h->input, h->dofs, &h->info, &distance, err) != SK_OK)
        return -1;
    sk_hand_forward(&h->skeleton, h->dofs, &h->frames);
    return distance;
}

/* The pinned DOFs: mask (1 per DOF) and values. */
STUDIO_API void studio_hand_pins(const studio_hand *h, int *pinned, double *values)
{
    for (int i = 0; i < SK_HAND_DOF_COUNT; i++) {
        pinned[i] = h->input.pinned[i];
        values[i] = h->input.pin_value[i];
    }
}
