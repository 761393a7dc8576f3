/* The playing posture and the rig of the hand. A pianist's hand hovers with its
 * fingertips over five neighbouring white keys; here that posture is held by constant
 * torques (the thesis's directed input, eq. 3.9) on each finger's MCP and PIP flexion and
 * MCP abduction (the thumb's CMC flexion and palmar abduction), found by Newton steps so
 * that the pads' lowest points lie at one level (the short digits' in the relaxed hand),
 * one white key apart across the keyboard, at reaches halfway between each
 * finger's relaxed reach and the index and middle fingers' (a quarter of the way for the
 * little finger, which is short). Everything
 * else of the hand stays relaxed and coupled. */
#include <math.h>
#include <string.h>

#include "products/showcase/showcase_internal.h"

#define POSTURE_UNKNOWNS 14
#define PRESS_MARGIN_MM 2.0 /* a press stops short of the bottom of its arc */
#define WRIST_FLEX                                                                                 \
    0.12 /* the wrist slightly flexed: the forearm level, the hand sloping                         \
            down to the knuckles */

static const char *const press_names[5][2] = {{"T.CMC.abd", "T.MCP.flex"},
                                              {"I.MCP.flex", "I.PIP.flex"},
                                              {"M.MCP.flex", "M.PIP.flex"},
                                              {"R.MCP.flex", "R.PIP.flex"},
                                              {"L.MCP.flex", "L.PIP.flex"}};
static const char *const aim_names[5] = {"T.CMC.flex", "I.MCP.abd", "M.MCP.abd", "R.MCP.abd",
                                         "L.MCP.abd"};
#define THUMB_PRESS_MCP 0.3 /* MCP torque per CMC abduction torque of a thumb press */

typedef struct posture_targets {
    double x[5], z[5], bottom;
} posture_targets;

/* Misses of the pads from the targets for the 14 posture torques. */
static sk_result posture_misses(sk_showcase *sc, const posture_targets *tg, const double *u,
                                double *res, sk_vec3d pads[5], sk_error *err)
{
    sk__hand_rig *rig = &sc->rig;
    double torque[SK_HAND_DOF_COUNT] = {0};
    int k = 0;
    torque[rig->aim_dof[0]] = u[k++];
    torque[rig->press_dof[0][0]] = u[k++];
    for (int f = 1; f < 5; f++) {
        torque[rig->press_dof[f][0]] = u[k++];
        torque[rig->press_dof[f][1]] = u[k++];
        torque[rig->aim_dof[f]] = u[k++];
    }
    double dofs[SK_HAND_DOF_COUNT];
    sk_hand_frames frames;
    sk_result r =
        sk__contact_posture(&sc->contact, (sk_vec3d){0, 0, 0}, torque, dofs, &frames, pads, err);
    if (r != SK_OK) return r;
    k = 0;
    res[k++] = pads[0].x - tg->x[0];
    res[k++] = pads[0].y - rig->tip_radius[0] - tg->bottom;
    for (int f = 1; f < 5; f++) {
        res[k++] = pads[f].x - tg->x[f];
        res[k++] = pads[f].y - rig->tip_radius[f] - tg->bottom;
        res[k++] = pads[f].z - tg->z[f];
    }
    return SK_OK;
}

typedef struct posture_problem {
    sk_showcase *sc;
    const posture_targets *tg;
    sk_vec3d *pads;
} posture_problem;

static sk_result posture_fn(void *user, const double *u, double *res, sk_error *err)
{
    posture_problem *p = user;
    return posture_misses(p->sc, p->tg, u, res, p->pads, err);
}

/* One finger pressing down from the playing posture: its pad's miss of `depth` below. */
typedef struct press_problem {
    sk_showcase *sc;
    int finger;
    double target;
    sk_vec3d *pads;
} press_problem;

static sk_result press_fn(void *user, const double *a, double *res, sk_error *err)
{
    press_problem *p = user;
    const sk__hand_rig *rig = &p->sc->rig;
    double torque[SK_HAND_DOF_COUNT] = {0};
    torque[rig->press_dof[p->finger][0]] = a[0] * rig->press_dir[p->finger][0];
    torque[rig->press_dof[p->finger][1]] = a[0] * rig->press_dir[p->finger][1];
    double dofs[SK_HAND_DOF_COUNT];
    sk_hand_frames frames;
    sk_result r = sk__contact_posture(&p->sc->contact, (sk_vec3d){0, 0, 0}, torque, dofs, &frames,
                                      p->pads, err);
    res[0] = p->pads[p->finger].y - rig->tip_radius[p->finger] - p->target;
    return r;
}

sk_result sk__hand_rig_make(sk_showcase *sc, sk_error *err)
{
    sk__hand_rig *rig = &sc->rig;
    memset(rig, 0, sizeof *rig);
    rig->wrist_angles[0] = WRIST_FLEX;
    for (int f = 0; f < 5; f++) {
        rig->press_dof[f][0] = sk_hand_dof_find(press_names[f][0]);
        rig->press_dof[f][1] = sk_hand_dof_find(press_names[f][1]);
        rig->aim_dof[f] = sk_hand_dof_find(aim_names[f]);
        rig->press_dir[f][0] = 1;
        rig->press_dir[f][1] = f == 0 ? THUMB_PRESS_MCP : sc->desc.performance.press_pip_ratio;
        rig->tip_radius[f] = sc->desc.performance.tip_radius_mm[f];
    }
    /* the relaxed hand (no torque) gives the targets' scale */
    sk_vec3d pads[5];
    double dofs[SK_HAND_DOF_COUNT];
    sk_hand_frames frames;
    sk_result r =
        sk__contact_posture(&sc->contact, (sk_vec3d){0, 0, 0}, NULL, dofs, &frames, pads, err);
    if (r != SK_OK) return r;
    posture_targets tg;
    double pitch = sc->piano.desc.white_pitch_mm;
    /* the pads' level: that of the short digits (thumb, index, little) in the relaxed
       hand; the long middle and ring fingers uncurl to it */
    double bottom = 0;
    const int level_fingers[3] = {0, 1, 4};
    for (int k = 0; k < 3; k++)
        bottom += (pads[level_fingers[k]].y - rig->tip_radius[level_fingers[k]]) / 3;
    tg.bottom = bottom;
    /* reaches: halfway between each finger's relaxed reach and the index and middle
       fingers' (a quarter of the way for the short little finger); curled further, a
       press would draw a pad back instead of down */
    double reach = 0.5 * (pads[1].z + pads[2].z);
    for (int f = 0; f < 5; f++) {
        tg.x[f] = pads[2].x + (f - 2) * pitch;
        tg.z[f] = pads[f].z + (f == 4 ? 0.25 : 0.5) * (reach - pads[f].z);
    }
    posture_problem pp = {sc, &tg, pads};
    sk__newton_desc nd = {POSTURE_UNKNOWNS, posture_fn, &pp, 1e-4, 60, 1e-4, 0.3};
    double u[POSTURE_UNKNOWNS] = {0}, res[POSTURE_UNKNOWNS];
    if ((r = sk__newton_solve(&nd, u, res, err)) != SK_OK) return r;
    double worst = 0;
    for (int i = 0; i < POSTURE_UNKNOWNS; i++) worst = fmax(worst, fabs(res[i]));
    if (worst > 0.05)
        return sk_fail(err, SK_ERROR_NUMERIC,
                       "the hand cannot take the playing posture (fingertips one white key apart, "
                       "%.3g mm off): "
                       "its hand_breadth_mm is too small for the keys' white_pitch_mm",
                       worst);
    int k = 0;
    rig->base_torque[rig->aim_dof[0]] = u[k++];
    rig->base_torque[rig->press_dof[0][0]] = u[k++];
    for (int f = 1; f < 5; f++) {
        rig->base_torque[rig->press_dof[f][0]] = u[k++];
        rig->base_torque[rig->press_dof[f][1]] = u[k++];
        rig->base_torque[rig->aim_dof[f]] = u[k++];
    }
    if ((r = sk__contact_posture(&sc->contact, (sk_vec3d){0, 0, 0}, NULL, dofs, &frames, pads,
                                 err)) != SK_OK)
        return r;
    for (int f = 0; f < 5; f++) rig->pad_offset[f] = pads[f];
    rig->hover_depth = -tg.bottom;
    /* how deep each pad can go: the lowest point of its press's flexion arc (golden
       section on the press amplitude) */
    for (int f = 0; f < 5; f++) {
        sk_vec3d pressed[5];
        press_problem pp2 = {sc, f, 0, pressed};
        double a = 0, b = 4, miss;
        const double g = 0.5 * (sqrt(5.0) - 1);
        for (int it = 0; it < 40; it++) {
            double m1 = b - g * (b - a), m2 = a + g * (b - a), y1, y2;
            if ((r = press_fn(&pp2, &m1, &y1, err)) != SK_OK ||
                (r = press_fn(&pp2, &m2, &y2, err)) != SK_OK)
                return r;
            if (y1 < y2)
                b = m2;
            else
                a = m1;
        }
        double at = 0.5 * (a + b);
        if ((r = press_fn(&pp2, &at, &miss, err)) != SK_OK) return r;
        rig->max_depth[f] = tg.bottom - miss; /* target 0: miss = the bottom's height */
        /* and where the pad is when it presses a key to the bottom (or as deep as it goes) */
        double depth = fmin(sc->desc.performance.hover_mm + sc->piano.desc.dip_mm,
                            rig->max_depth[f] - PRESS_MARGIN_MM);
        pp2.target = tg.bottom - depth;
        sk__newton_desc nd2 = {1, press_fn, &pp2, 1e-3, 30, 1e-4, 0.5};
        double amp = 0;
        if ((r = sk__newton_solve(&nd2, &amp, &miss, err)) != SK_OK) return r;
        if ((r = press_fn(&pp2, &amp, &miss, err)) != SK_OK) return r;
        rig->press_offset[f] = pressed[f];
    }
    /* home depth: the mean of the middles of the wrist depths at which each finger can
       strike a white key */
    const sk_piano_key *c4 = sk_piano_key_get(&sc->piano, 60);
    rig->home_z = 0;
    for (int f = 0; f < 5; f++) {
        double a, b;
        sk__performance_contact_range(rig, c4, f, &a, &b);
        rig->home_z += (0.5 * (a + b) - rig->press_offset[f].z) / 5;
    }
    return SK_OK;
}
