/* The shipped motions (the BVH files of presets/tissue), generated so they can be made again: an
 * arm curl for the arm character, a jump and a walk for the full body. Written as motion
 * capture tools write BVH: the root with 6 channels, every joint "Zrotation Yrotation
 * Xrotation" (the CMU library's order), lengths in centimetres, 60 frames per second.
 * Joint rotations are built from anatomical angles (flexion about the joint's axis) and
 * written as ZYX Euler angles. Each motion ends held still, so the jiggle settles. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "shitsukan/tissue.h"

const char *const sk_tissue_motion_kind_names[] = {"curl", "jump", "walk", NULL};

#define FPS 60

/* ---------------------------------------------------------------- helpers */
static double smooth(double t) /* 0..1 ease in and out */
{
    t = sk_clampd(t, 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}
/* 0 before a, 1 after b, eased between */
static double ramp(double t, double a, double b) { return smooth((t - a) / (b - a)); }

static sk_mat3d rx(double deg) { return sk_m3d_rot_x(deg * SK_DEG_TO_RAD); }
static sk_mat3d ry(double deg) { return sk_m3d_rot_y(deg * SK_DEG_TO_RAD); }
static sk_mat3d rz(double deg) { return sk_m3d_rot_z(deg * SK_DEG_TO_RAD); }
static sk_mat3d mul(sk_mat3d a, sk_mat3d b) { return sk_m3d_mul(a, b); }

/* ZYX Euler angles (degrees) of R = Rz(z) Ry(y) Rx(x), written in that channel order. */
static void put_zyx(double *m, sk_mat3d r)
{
    double y = asin(sk_clampd(-r.m[2][0], -1.0, 1.0));
    double z = atan2(r.m[1][0], r.m[0][0]), x = atan2(r.m[2][1], r.m[2][2]);
    m[0] = z * SK_RAD_TO_DEG;
    m[1] = y * SK_RAD_TO_DEG;
    m[2] = x * SK_RAD_TO_DEG;
}

typedef struct builder {
    sk_bvh *b;
    sk_result r;
    sk_error *err;
} builder;

static int add(builder *bd, const char *name, int parent, double x, double y, double z, bool end)
{
    int j = -1;
    if (bd->r == SK_OK)
        bd->r = sk_bvh_add_joint(bd->b, name, parent, sk_v3d(x, y, z),
                                 end ? NULL : (parent < 0 ? "xyzZYX" : "ZYX"), end, &j, bd->err);
    return j;
}

/* Sets joint j's rotation in frame f (root: also its position, cm). */
static void set(sk_bvh *b, int f, int j, sk_mat3d r)
{
    double *m = b->motion + (size_t)f * (size_t)b->channels_per_frame + b->channel_first[j];
    put_zyx(m + (b->channel_count[j] == 6 ? 3 : 0), r);
}
static void set_root(sk_bvh *b, int f, int j, double x, double y, double z, sk_mat3d r)
{
    double *m = b->motion + (size_t)f * (size_t)b->channels_per_frame + b->channel_first[j];
    m[0] = x;
    m[1] = y;
    m[2] = z;
    put_zyx(m + 3, r);
}

/* ---------------------------------------------------------------- arm curl */
/* Elbow flexion (degrees) over time: two slow repetitions, then a fast curl that stops
 * dead at the top and a fast lowering that stops dead at the bottom, each held. */
static double curl_angle(double t)
{
    const double top = 125.0;
    if (t < 2.4) {
        double rep = fmod(t, 1.2);
        return top * (rep < 0.6 ? smooth(rep / 0.6) : 1.0 - smooth((rep - 0.6) / 0.6));
    }
    if (t < 2.7) return top * (t - 2.4) / 0.3; /* fast, constant speed */
    if (t < 3.7) return top;                   /* sudden stop, held */
    if (t < 3.95) return top * (1.0 - (t - 3.7) / 0.25);
    return 0.0;
}

static sk_result make_curl(sk_bvh *b, sk_error *err)
{
    builder bd = {b, SK_OK, err};
    int arm = add(&bd, "RightArm", -1, 0, 0, 0, false);
    int fore = add(&bd, "RightForeArm", arm, 0, -30, 0, false);
    int hand = add(&bd, "RightHand", fore, 0, -26, 0, false);
    add(&bd, "RightHand_end", hand, 0, -17, 0, true);
    int frames = (int)(5.0 * FPS) + 1;
    if (bd.r == SK_OK) bd.r = sk_bvh_alloc_motion(b, frames, 1.0 / FPS, err);
    if (bd.r != SK_OK) return bd.r;
    for (int f = 0; f < frames; f++) {
        double t = (double)f / FPS, a = curl_angle(t);
        /* the shoulder steadies the arm a little forward while it curls */
        set_root(b, f, arm, 0, 0, 0, rx(-0.08 * a));
        set(b, f, fore, rx(-a));        /* flexion brings the forearm forward (+Z) */
        set(b, f, hand, rx(-0.15 * a)); /* the wrist follows a little */
    }
    return SK_OK;
}

/* ---------------------------------------------------------------- the body */
typedef struct body_joints {
    int hips, hip[2], up[2], leg[2], foot[2], toe[2];
    int lower_back, spine, spine1, neck, neck1, head;
    int shoulder[2], arm[2], fore[2], hand[2], finger[2], index[2], thumb[2];
} body_joints;

/* The skeleton of presets/tissue/body.json (CMU names), in cm. */
static sk_result make_body(sk_bvh *b, body_joints *j, sk_error *err)
{
    builder bd = {b, SK_OK, err};
    static const char *const side[2] = {"Left", "Right"}, *const ab[2] = {"L", "R"};
    char name[64];
    /* the root's position is in its channels (its OFFSET 0), as motion capture writes it */
    j->hips = add(&bd, "Hips", -1, 0, 0, 0, false);
    for (int s = 0; s < 2; s++) {
        double x = s == 0 ? 1 : -1;
        snprintf(name, sizeof name, "%sHipJoint", ab[s]);
        j->hip[s] = add(&bd, name, j->hips, 0, 0, 0, false);
        snprintf(name, sizeof name, "%sUpLeg", side[s]);
        j->up[s] = add(&bd, name, j->hip[s], 9 * x, -6, 0, false);
        snprintf(name, sizeof name, "%sLeg", side[s]);
        j->leg[s] = add(&bd, name, j->up[s], 0, -42, 0, false);
        snprintf(name, sizeof name, "%sFoot", side[s]);
        j->foot[s] = add(&bd, name, j->leg[s], 0, -40, 0, false);
        snprintf(name, sizeof name, "%sToeBase", side[s]);
        j->toe[s] = add(&bd, name, j->foot[s], 0, -5, 12, false);
        snprintf(name, sizeof name, "%sToeBase_end", side[s]);
        add(&bd, name, j->toe[s], 0, 0, 4.5, true);
    }
    j->lower_back = add(&bd, "LowerBack", j->hips, 0, 2, 0, false);
    j->spine = add(&bd, "Spine", j->lower_back, 0, 11, 0, false);
    j->spine1 = add(&bd, "Spine1", j->spine, 0, 15, 0, false);
    j->neck = add(&bd, "Neck", j->spine1, 0, 19, 0, false);
    j->neck1 = add(&bd, "Neck1", j->neck, 0, 5, 0, false);
    j->head = add(&bd, "Head", j->neck1, 0, 5, 1, false);
    add(&bd, "Head_end", j->head, 0, 21, 0, true);
    for (int s = 0; s < 2; s++) {
        double x = s == 0 ? 1 : -1;
        snprintf(name, sizeof name, "%sShoulder", side[s]);
        j->shoulder[s] = add(&bd, name, j->spine1, 2 * x, 16, 0, false);
        snprintf(name, sizeof name, "%sArm", side[s]);
        j->arm[s] = add(&bd, name, j->shoulder[s], 15 * x, 3, 0, false);
        snprintf(name, sizeof name, "%sForeArm", side[s]);
        j->fore[s] = add(&bd, name, j->arm[s], 29 * x, 0, 0, false);
        snprintf(name, sizeof name, "%sHand", side[s]);
        j->hand[s] = add(&bd, name, j->fore[s], 26 * x, 0, 0, false);
        snprintf(name, sizeof name, "%sFingerBase", side[s]);
        j->finger[s] = add(&bd, name, j->hand[s], 2 * x, 0, 0, false);
        snprintf(name, sizeof name, "%sHandIndex1", side[s]);
        j->index[s] = add(&bd, name, j->finger[s], 8 * x, 0, 0, false);
        snprintf(name, sizeof name, "%sHandIndex1_end", side[s]);
        add(&bd, name, j->index[s], 6 * x, 0, 0, true);
        snprintf(name, sizeof name, "%sThumb", ab[s]);
        j->thumb[s] = add(&bd, name, j->hand[s], 2 * x, 0, 3, false);
        snprintf(name, sizeof name, "%sThumb_end", ab[s]);
        add(&bd, name, j->thumb[s], 4 * x, 0, 2.5, true);
    }
    return bd.r;
}

/* A body pose in anatomical angles (degrees): flexion positive forward for hips,
 * shoulders (arm swing from hanging) and the trunk; knees and elbows bend positive. */
typedef struct body_pose {
    double root[3];     /* cm */
    double trunk, neck; /* lean forward */
    double hip[2], knee[2], ankle[2];
    double arm_down[2];        /* from the T-pose towards hanging (90 = hanging) */
    double swing[2], elbow[2]; /* arm swing forward, elbow flexion */
    double pelvis_turn;        /* about Y */
} body_pose;

static void set_body(sk_bvh *b, int f, const body_joints *j, const body_pose *p)
{
    set_root(b, f, j->hips, p->root[0], p->root[1], p->root[2], ry(p->pelvis_turn));
    for (int s = 0; s < 2; s++) {
        double x = s == 0 ? 1 : -1;
        set(b, f, j->hip[s], sk_m3d_identity());
        set(b, f, j->up[s], rx(-p->hip[s]));
        set(b, f, j->leg[s], rx(p->knee[s]));
        set(b, f, j->foot[s], rx(p->ankle[s]));
        set(b, f, j->toe[s], sk_m3d_identity());
        /* the arm hangs (about Z), then swings forward about the world X axis */
        sk_mat3d arm = mul(rx(-p->swing[s]), rz(-x * p->arm_down[s]));
        set(b, f, j->arm[s], arm);
        /* the elbow bends the forearm forward about the (hanging) arm's own axis across */
        set(b, f, j->fore[s], ry(-x * p->elbow[s]));
        set(b, f, j->shoulder[s], sk_m3d_identity());
        set(b, f, j->hand[s], sk_m3d_identity());
        set(b, f, j->finger[s], sk_m3d_identity());
        set(b, f, j->index[s], sk_m3d_identity());
        set(b, f, j->thumb[s], sk_m3d_identity());
    }
    set(b, f, j->lower_back, rx(0.3 * p->trunk));
    set(b, f, j->spine, rx(0.4 * p->trunk));
    set(b, f, j->spine1, rx(0.3 * p->trunk));
    set(b, f, j->neck, rx(p->neck));
    set(b, f, j->neck1, sk_m3d_identity());
    set(b, f, j->head, sk_m3d_identity());
}

static body_pose standing(void)
{
    body_pose p;
    memset(&p, 0, sizeof p);
    p.root[1] = 94;
    for (int s = 0; s < 2; s++) {
        p.arm_down[s] = 75;
        p.elbow[s] = 10;
    }
    return p;
}

/* Crouch depth 0..1 into a pose: hips drop, knees and hips bend, the trunk leans, the
 * feet stay flat (ankle = hip - knee). */
static void crouch(body_pose *p, double c, double arms_back)
{
    double knee = 75 * c, hip = 60 * c;
    for (int s = 0; s < 2; s++) {
        p->knee[s] = knee;
        p->hip[s] = hip;
        p->ankle[s] = hip - knee;
        p->swing[s] = -40 * arms_back;
    }
    p->trunk = 35 * c;
    p->neck = -20 * c;
    /* a thigh of 42 cm and a shank of 40 cm bent this way lower the hips */
    double thigh = 42, shank = 40;
    p->root[1] = 94 - (thigh + shank) + thigh * cos(hip * SK_DEG_TO_RAD) +
                 shank * cos((knee - hip) * SK_DEG_TO_RAD);
}

static sk_result make_jump(sk_bvh *b, sk_error *err)
{
    body_joints j;
    sk_result r = make_body(b, &j, err);
    int frames = (int)(3.2 * FPS) + 1;
    if (r == SK_OK) r = sk_bvh_alloc_motion(b, frames, 1.0 / FPS, err);
    if (r != SK_OK) return r;
    const double g = 981.0, takeoff = 1.05, flight = 0.5; /* cm/s^2, s */
    double v0 = 0.5 * g * flight;                         /* up at take-off, cm/s */
    for (int f = 0; f < frames; f++) {
        double t = (double)f / FPS;
        body_pose p = standing();
        if (t < takeoff) {
            /* crouch (0.3-0.8 s), then the push: legs straighten, arms swing up */
            double down = ramp(t, 0.3, 0.8), up = ramp(t, 0.8, takeoff);
            crouch(&p, down * (1.0 - up), down * (1.0 - up));
            for (int s = 0; s < 2; s++) {
                p.swing[s] += 150 * up;
                p.ankle[s] -= 25 * up; /* rising on the toes */
            }
            p.root[1] += 4.0 * up * up;
        } else if (t < takeoff + flight) {
            double tf = t - takeoff;
            for (int s = 0; s < 2; s++) {
                p.swing[s] = 150 - 120 * ramp(tf, 0.0, flight);
                p.ankle[s] = -25 * (1.0 - ramp(tf, 0.0, flight));
                p.knee[s] = 15 * sin(SK_PI * tf / flight);
                p.hip[s] = 10 * sin(SK_PI * tf / flight);
            }
            p.root[1] = 98 + v0 * tf - 0.5 * g * tf * tf;
        } else {
            /* landing: the legs take the fall in 0.12 s (a sudden stop), then stand up */
            double tl = t - takeoff - flight;
            double absorb = ramp(tl, 0.0, 0.12) * (1.0 - ramp(tl, 0.25, 0.8));
            crouch(&p, 0.55 * absorb, 0.0);
            for (int s = 0; s < 2; s++) p.swing[s] = 30 * (1.0 - ramp(tl, 0.0, 0.6));
            p.root[1] += 4.0 * (1.0 - ramp(tl, 0.0, 0.08)); /* down from the toes */
        }
        set_body(b, f, &j, &p);
    }
    return SK_OK;
}

static sk_result make_walk(sk_bvh *b, sk_error *err)
{
    body_joints j;
    sk_result r = make_body(b, &j, err);
    const double cycle = 1.1, speed = 125.0; /* s per stride, cm/s */
    int frames = (int)((3 * cycle + 1.0) * FPS) + 1;
    if (r == SK_OK) r = sk_bvh_alloc_motion(b, frames, 1.0 / FPS, err);
    if (r != SK_OK) return r;
    double walk_end = 3 * cycle;
    for (int f = 0; f < frames; f++) {
        double t = (double)f / FPS;
        body_pose p = standing();
        double tw = t < walk_end ? t : walk_end;
        double amp =
            ramp(t, 0.0, 0.4) * (1.0 - ramp(t, walk_end - 0.3, walk_end)); /* start and stop */
        double ph = 2.0 * SK_PI * tw / cycle;
        for (int s = 0; s < 2; s++) {
            double q = ph + (s == 0 ? 0.0 : SK_PI);
            p.hip[s] = amp * 25 * sin(q);
            /* the knee bends in swing (when the leg goes forward) and a little at loading */
            double swing = sin(q + 0.9);
            p.knee[s] = amp * (swing > 0 ? 60 * swing * swing : 8 * swing * swing);
            p.ankle[s] = amp * (10 * sin(q - 0.6));
            p.swing[s] = -amp * 22 * sin(q); /* arms swing against the legs */
            p.elbow[s] = 15 + amp * 10 * (1 - cos(q)) * 0.5;
        }
        p.trunk = 4 * amp;
        p.pelvis_turn = amp * 6 * sin(ph);
        /* distance walked: the speed eased in and out like the stride */
        double dist = 0.0;
        for (int k = 0; k < f; k++) {
            double tk = (double)k / FPS;
            dist += speed / FPS * ramp(tk, 0.0, 0.4) * (1.0 - ramp(tk, walk_end - 0.3, walk_end));
        }
        p.root[2] = dist;
        p.root[1] = 94 - amp * (1.0 + cos(2.0 * ph)) * 1.2; /* lowest twice a stride */
        set_body(b, f, &j, &p);
    }
    return SK_OK;
}

sk_result sk_tissue_make_motion(sk_tissue_motion_kind kind, sk_bvh *out, sk_error *err)
{
    sk_bvh_init(out);
    sk_result r;
    switch (kind) {
    case SK_TISSUE_MOTION_CURL:
        r = make_curl(out, err);
        break;
    case SK_TISSUE_MOTION_JUMP:
        r = make_jump(out, err);
        break;
    case SK_TISSUE_MOTION_WALK:
        r = make_walk(out, err);
        break;
    default:
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "motion kind %d is not curl, jump or walk",
                       (int)kind);
    }
    if (r != SK_OK) sk_bvh_free(out);
    return r;
}
