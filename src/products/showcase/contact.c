/* Fingertips meet the keys. Each playing finger gets torques on its press DOFs (the
 * thesis's two DOFs of a key press, Fig. 4.21, in a fixed ratio: one amplitude) and on
 * its aim DOF (its abduction, so the pad lands on the key's centre); the rest of the hand
 * follows by the coupling potential (sk_hand_solve). The amplitudes are found by Newton
 * steps on the pads' misses (Jacobian by differences), starting from zero each time, so
 * a pose depends on its time alone. A finger that does not play but is pulled into a key
 * by the coupling gets an extension torque that holds it `clearance_mm` above. A key then
 * turns exactly as far as the pads over it push it: it goes down only when its finger
 * reaches it, and no pad passes through a key's top. */
#include <math.h>
#include <string.h>

#include "products/showcase/showcase_internal.h"

#define MAX_UNKNOWNS 10 /* two for each finger */
#define MAX_ITERATIONS 16
#define TOLERANCE_MM 1e-3
#define DIFF_STEP 1e-4
#define MAX_STEP 2.0 /* torque units */
#define EDGE_RAMP_MM 4.0
#define FRONT_MARGIN_MM 2.0
#define FRONT_SLOPE 3.0
#define LIFT_MAX 4.0 /* torque units */
#define LIFT_ITERATIONS 12
#define LIFT_ROUNDS 2
#define EDGE_RAMP_SLOPE 4.0

sk_result sk__contact_posture(const sk__contact *c, sk_vec3d wrist, const double *extra_torque,
                              double dofs[SK_HAND_DOF_COUNT], sk_hand_frames *frames,
                              sk_vec3d pads[5], sk_error *err)
{
    sk_hand_input input;
    memset(&input, 0, sizeof input);
    sk_vec3d w = sk__scene_to_hand(wrist);
    const double pin[6] = {
        w.x, w.y, w.z, c->rig->wrist_angles[0], c->rig->wrist_angles[1], c->rig->wrist_angles[2]};
    for (int i = 0; i < 6; i++) input.pinned[i] = true, input.pin_value[i] = pin[i];
    for (int i = 0; i < SK_HAND_DOF_COUNT; i++)
        input.torque[i] = c->rig->base_torque[i] + (extra_torque ? extra_torque[i] : 0);
    sk_result r = sk_hand_solve(c->solver, &input, dofs, NULL, err);
    if (r != SK_OK) return r;
    sk_hand_forward(c->skeleton, dofs, frames);
    for (int f = 0; f < 5; f++) {
        const sk_mat3d *rot = &frames->rotation[sk__distal_link(f)];
        sk_vec3d axis = {rot->m[0][1], rot->m[1][1], rot->m[2][1]};
        sk_vec3d tip = frames->point[sk__tip_point(f)];
        double rad = c->rig->tip_radius[f];
        sk_vec3d centre = {tip.x - rad * axis.x, tip.y - rad * axis.y, tip.z - rad * axis.z};
        pads[f] = sk__hand_to_scene(centre);
    }
    return SK_OK;
}

/* Horizontal distance from (x, z) to a rectangle [x0, x1] x [z0, z1]. */
static double rect_distance(double x, double z, double x0, double x1, double z0, double z1)
{
    double dx = x < x0 ? x0 - x : (x > x1 ? x - x1 : 0),
           dz = z < z0 ? z0 - z : (z > z1 ? z - z1 : 0);
    return sqrt(dx * dx + dz * dz);
}

/* Horizontal distance from (x, z) to a key's top (its front part and the part between the
 * black keys). */
static double key_distance_xz(const sk_piano_key *k, double x, double z)
{
    double front = rect_distance(x, z, k->x_mm - 0.5 * k->width_mm, k->x_mm + 0.5 * k->width_mm,
                                 k->notch_front_mm, k->front_mm);
    if (k->black) return front;
    double back = rect_distance(x, z, k->back_x0_mm, k->back_x1_mm, k->back_mm, k->notch_front_mm);
    return fmin(front, back);
}

static double keys_surface_except(const sk_piano *piano, sk_vec3d centre, double radius,
                                  int except);

double sk__keys_surface(const sk_piano *piano, sk_vec3d centre, double radius)
{
    return keys_surface_except(piano, centre, radius, 0);
}

/* The same leaving out one key (the one a finger is going to). */
static double keys_surface_except(const sk_piano *piano, sk_vec3d centre, double radius, int except)
{
    double best = -INFINITY;
    double reach = 0.5 * piano->desc.white_pitch_mm + radius + EDGE_RAMP_MM;
    for (int i = 0; i < SK_PIANO_KEY_COUNT; i++) {
        const sk_piano_key *k = &piano->keys[i];
        if (k->key == except || fabs(k->x_mm - centre.x) > reach + k->width_mm) continue;
        double rho = key_distance_xz(k, centre.x, centre.z);
        if (rho >= radius + EDGE_RAMP_MM) continue;
        double top = sk_piano_key_top_at(piano, k, 0, centre.z);
        /* the sphere over the key's top; beyond its edge a steep ramp keeps the surface
           continuous (a pad passes a key's edge above it, never into its side) */
        double v = rho < radius ? top - (radius - sqrt(radius * radius - rho * rho))
                                : top - radius - EDGE_RAMP_SLOPE * (rho - radius);
        if (v > best) best = v;
    }
    return best;
}

/* How far a pad turns a key down: the smallest angle at which the key's top under the
 * pad's centre is no higher than the sphere there (0 if the pad is above it). */
static double pushed_angle(const sk_piano *piano, const sk_piano_key *k, sk_vec3d centre,
                           double radius)
{
    double rho = key_distance_xz(k, centre.x, centre.z);
    if (rho >= radius) return 0;
    double low = centre.y - sqrt(radius * radius - rho * rho);
    if (sk_piano_key_top_at(piano, k, 0, centre.z) <= low) return 0;
    double a = 0, b = piano->max_angle;
    if (sk_piano_key_top_at(piano, k, b, centre.z) > low) return b; /* at the bottom stop */
    for (int it = 0; it < 40; it++) {
        double m = 0.5 * (a + b);
        if (sk_piano_key_top_at(piano, k, m, centre.z) > low)
            a = m;
        else
            b = m;
    }
    return b;
}

typedef struct unknown {
    int finger;
    bool aim; /* the aim torque, else the press amplitude */
} unknown;

/* A posture solved for some torques. The lifts and the Newton steps often ask again for
 * torques just solved for (a finger's lift left at 0, a step's point taken as the next
 * start), so the last few are kept and given back as they were. */
#define RECENT 4
typedef struct posture {
    double torque[SK_HAND_DOF_COUNT];
    double dofs[SK_HAND_DOF_COUNT];
    sk_hand_frames frames;
    sk_vec3d pads[5];
} posture;

typedef struct problem {
    const sk__contact *c;
    const sk__intent *in;
    int count;
    unknown u[MAX_UNKNOWNS];
    double lift[5]; /* press amplitude (negative: extension) holding a free finger up */
    int solves;     /* hand solves done */
    posture recent[RECENT];
    int recent_count, recent_next;
} problem;

static void torques_of(const problem *p, const double *x, double *torque)
{
    const sk__hand_rig *rig = p->c->rig;
    memset(torque, 0, SK_HAND_DOF_COUNT * sizeof *torque);
    for (int f = 0; f < 5; f++) {
        torque[rig->press_dof[f][0]] += p->lift[f] * rig->press_dir[f][0];
        torque[rig->press_dof[f][1]] += p->lift[f] * rig->press_dir[f][1];
    }
    for (int k = 0; k < p->count; k++) {
        int f = p->u[k].finger;
        if (p->u[k].aim) {
            torque[rig->aim_dof[f]] += x[k];
        } else {
            torque[rig->press_dof[f][0]] += x[k] * rig->press_dir[f][0];
            torque[rig->press_dof[f][1]] += x[k] * rig->press_dir[f][1];
        }
    }
}

/* The misses (mm) of every unknown's target for torques x. */
static sk_result misses(problem *p, const double *x, double *res, double dofs[SK_HAND_DOF_COUNT],
                        sk_hand_frames *frames, sk_vec3d pads[5], sk_error *err)
{
    const sk__contact *c = p->c;
    double torque[SK_HAND_DOF_COUNT];
    torques_of(p, x, torque);
    const posture *known = NULL;
    for (int k = 0; k < p->recent_count && !known; k++)
        if (memcmp(p->recent[k].torque, torque, sizeof torque) == 0) known = &p->recent[k];
    if (!known) {
        posture *fresh = &p->recent[p->recent_next];
        sk_result r = sk__contact_posture(c, p->in->wrist, torque, fresh->dofs, &fresh->frames,
                                          fresh->pads, err);
        p->solves++;
        if (r != SK_OK) return r;
        memcpy(fresh->torque, torque, sizeof torque);
        p->recent_next = (p->recent_next + 1) % RECENT;
        if (p->recent_count < RECENT) p->recent_count++;
        known = fresh;
    }
    memcpy(dofs, known->dofs, sizeof known->dofs);
    *frames = known->frames;
    memcpy(pads, known->pads, sizeof known->pads);
    double hover = p->in->wrist.y - c->rig->hover_depth;
    for (int k = 0; k < p->count; k++) {
        int f = p->u[k].finger;
        double rad = c->rig->tip_radius[f];
        const sk__finger_intent *fi = &p->in->finger[f];
        if (p->u[k].aim) {
            res[k] = pads[f].x - sk_piano_key_get(c->piano, fi->key)->x_mm;
            continue;
        }
        double bottom = pads[f].y - rad, target;
        const sk_piano_key *key = sk_piano_key_get(c->piano, fi->key);
        if (fi->phase == SK__FINGER_PRESS)
            target = sk_piano_key_top_at(c->piano, key, fi->angle, pads[f].z);
        else
            target = hover + fi->blend * (sk_piano_key_top_at(c->piano, key, 0, pads[f].z) - hover);
        /* a pad drawn off the key's front is no press: such a solution is refused */
        double off = pads[f].z - (key->front_mm - FRONT_MARGIN_MM);
        if (off > 0) target += FRONT_SLOPE * off;
        /* never into the keys beside it */
        double others =
            keys_surface_except(c->piano, pads[f], rad, fi->key) + c->desc->clearance_mm;
        if (others > target) target = others;
        res[k] = bottom - target;
    }
    return SK_OK;
}

static sk_result contact_fn(void *user, const double *x, double *res, sk_error *err)
{
    problem *p = user;
    double dofs[SK_HAND_DOF_COUNT];
    sk_hand_frames frames;
    sk_vec3d pads[5];
    return misses(p, x, res, dofs, &frames, pads, err);
}

/* How far free finger f's pad is above what it may not go below (negative: into a key). */
static sk_result free_clearance(problem *p, int f, double *x, double *gap, sk_error *err)
{
    double res[MAX_UNKNOWNS], dofs[SK_HAND_DOF_COUNT];
    sk_hand_frames frames;
    sk_vec3d pads[5];
    sk_result r = misses(p, x, res, dofs, &frames, pads, err);
    double rad = p->c->rig->tip_radius[f];
    *gap =
        pads[f].y - rad - (sk__keys_surface(p->c->piano, pads[f], rad) + p->c->desc->clearance_mm);
    return r;
}

/* The smallest extension that holds free finger f clear of the keys (the others held):
 * regula falsi (Illinois) on the lift amplitude in [-LIFT_MAX, 0], from the bracket the
 * last round's lift gives (a later round starts where the one before ended). */
static sk_result lift_finger(problem *p, int f, double *x, sk_error *err)
{
    double last = p->lift[f], gap; /* the lift of the round before (0 in the first) */
    p->lift[f] = 0;
    sk_result r = free_clearance(p, f, x, &gap, err);
    if (r != SK_OK || gap >= -TOLERANCE_MM) return r;
    double a = -LIFT_MAX, b = 0, ga = 0, gb = gap;
    bool bracketed = false;
    if (last < 0) { /* the last round's lift, tried first: the other fingers moved little */
        double gl;
        p->lift[f] = last;
        if ((r = free_clearance(p, f, x, &gl, err)) != SK_OK) return r;
        if (gl >= 0 && gl < 0.05) return SK_OK; /* still just clear */
        if (gl >= 0)
            a = last, ga = gl, bracketed = true;
        else
            b = last, gb = gl;
    }
    if (!bracketed) {
        p->lift[f] = a;
        if ((r = free_clearance(p, f, x, &ga, err)) != SK_OK) return r;
        if (ga < 0) return SK_OK; /* as high as it goes */
    }
    int side = 0; /* Illinois: halve a stale end's value so the bracket shrinks from both ends */
    for (int it = 0; it < LIFT_ITERATIONS && b - a > 1e-4; it++) {
        double m = b - gb * (b - a) / (gb - ga);
        if (!(m > a && m < b)) m = 0.5 * (a + b);
        p->lift[f] = m;
        double gm;
        if ((r = free_clearance(p, f, x, &gm, err)) != SK_OK) return r;
        if (gm >= 0) {
            a = m, ga = gm;
            if (gm < 0.05) break;
            if (side == 1) gb *= 0.5;
            side = 1;
        } else {
            b = m, gb = gm;
            if (side == -1) ga *= 0.5;
            side = -1;
        }
    }
    p->lift[f] = a; /* on the clear side */
    return SK_OK;
}

sk_result sk__contact_solve(const sk__contact *c, const sk__intent *in, double t,
                            sk_showcase_pose *out, sk_error *err)
{
    problem p;
    memset(&p, 0, sizeof p);
    p.c = c, p.in = in;
    for (int f = 0; f < 5; f++)
        if (in->finger[f].phase != SK__FINGER_FREE) {
            p.u[p.count++] = (unknown){f, false};
            p.u[p.count++] = (unknown){f, true};
        }
    double x[MAX_UNKNOWNS] = {0}, res[MAX_UNKNOWNS] = {0};
    sk_vec3d pads[5];
    memset(out, 0, sizeof *out);
    out->time_s = t;
    sk__newton_desc nd = {p.count,        contact_fn, &p,      TOLERANCE_MM,
                          MAX_ITERATIONS, DIFF_STEP,  MAX_STEP};
    sk_result r = sk__newton_solve(&nd, x, res, err);
    /* fingers that do not play but sink into a key are lifted one by one, then the
       playing fingers solved again with those lifts held (a few Gauss-Seidel rounds) */
    for (int round = 0; round < LIFT_ROUNDS && r == SK_OK; round++) {
        bool any = false;
        for (int f = 0; f < 5 && r == SK_OK; f++) {
            if (in->finger[f].phase != SK__FINGER_FREE) continue;
            double before = p.lift[f];
            r = lift_finger(&p, f, x, err);
            any = any || p.lift[f] != before;
        }
        if (r != SK_OK || !any) break;
        r = sk__newton_solve(&nd, x, res, err);
    }
    if (r == SK_OK) r = misses(&p, x, res, out->dofs, &out->frames, pads, err);
    if (r != SK_OK) return r;
    out->solves = p.solves;
    for (int k = 0; k < p.count; k++)
        out->contact_error_mm = fmax(out->contact_error_mm, fabs(res[k]));
    for (int f = 0; f < 5; f++) {
        out->tip_centre[f] = pads[f];
        out->tip_radius[f] = c->rig->tip_radius[f];
        out->finger_note[f] = in->finger[f].phase == SK__FINGER_FREE ? -1 : in->finger[f].note;
    }
    /* the keys follow the pads */
    for (int i = 0; i < SK_PIANO_KEY_COUNT; i++) {
        const sk_piano_key *k = &c->piano->keys[i];
        for (int f = 0; f < 5; f++) {
            if (fabs(pads[f].x - k->x_mm) > c->piano->desc.white_pitch_mm + out->tip_radius[f])
                continue;
            double a = pushed_angle(c->piano, k, pads[f], out->tip_radius[f]);
            if (a > out->key_angle[i]) {
                out->key_angle[i] = a;
                out->key_finger[i] = f + 1;
            }
        }
    }
    return SK_OK;
}
