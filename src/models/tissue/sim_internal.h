/* Private structures of the tissue simulation (sim*.c, collision.c, state.c). */
#ifndef SK_TISSUE_SIM_INTERNAL_H
#define SK_TISSUE_SIM_INTERNAL_H

#include "models/tissue/solver.h"
#include "models/tissue/tissue_internal.h"

/* Something the flesh may not enter at one pose: a bone's three ellipsoids or a muscle's
 * one, in the world, with their bounds. */
typedef struct sk__obstacle_part {
    sk__ellipsoid e;
    double to_unit[3][3]; /* world offset from the centre -> ellipsoid coordinates / radii */
    sk_vec3d lo, hi;      /* bounds */
} sk__obstacle_part;
typedef struct sk__obstacle {
    int parts;
    sk__obstacle_part part[3];
    sk_vec3d lo, hi;
} sk__obstacle;
#define SK__MAX_OBSTACLES (SK_TISSUE_MAX_BONES + SK_TISSUE_MAX_MUSCLES)
#define SK__SIM_MAX_SECONDS                                                                        \
    1e7 /* the latest time a simulation advances to (and a state may hold) */

/* The bones (then the muscles, given their shapes) at a pose; returns how many. */
int sk__obstacles(const sk_tissue_model *m, const sk_tissue_pose *pose,
                  const sk__muscle_state *muscle, sk__obstacle *out);
/* Moves the first `count` points of x (3 doubles each) out of the obstacles: every bone,
 * and the muscles whose bit is set in the point's `near_muscles` mask (muscle i is
 * obstacle bone_count + i). Shares its work with an orphaned loop (call it from every
 * thread of a parallel region, or from one). `vectors`: the points that may be inside
 * found four at a time (AVX2; the same result, simd.h). */
void sk__collide(const sk__obstacle *obstacles, int count_obstacles, int bone_count,
                 const uint64_t *near_muscles, double *x, size_t count, bool vectors);
/* The same, each block's velocities then set from its moves: v = (x - base) inv_h (one
 * loop, one synchronisation). */
void sk__collide_finish(const sk__obstacle *obstacles, int obstacle_count, int bone_count,
                        const uint64_t *near_muscles, double *x, const double *base, double *v,
                        double inv_h, size_t count, bool vectors);

struct sk_tissue_sim {
    const sk_tissue_model *m;
    sk_tissue_motion motion;
    const sk__solver_ops *ops;
    sk__solver *solver;
    int step_hz;
    double h;     /* seconds per step */
    int64_t step; /* steps taken */
    size_t n, nfree;
    double *x;                    /* every point at the current step (3 each) */
    double *prev;                 /* every point at the step before */
    double *base;                 /* the step's start as the springs' damping sees it */
    double *v;                    /* free points' velocities, mm/s */
    double *target, *target_base; /* where the tissue carries the free points at the step's
                                     end and start (the tethers' other ends) */
    sk_tissue_pose pose, pose_prev;
    /* the step being taken: the pose at its end, and which bones jumped (and how they turned) */
    sk_tissue_pose next;
    bool carry[SK_TISSUE_MAX_BONES], any_carry;
    sk_quatd turn[SK_TISSUE_MAX_BONES];
    sk__muscle_state muscle[SK_TISSUE_MAX_MUSCLES];      /* at `pose` */
    sk__muscle_state muscle_prev[SK_TISSUE_MAX_MUSCLES]; /* at `pose_prev` */
    sk__muscle_state muscle_next[SK_TISSUE_MAX_MUSCLES]; /* at `next` */
    sk__obstacle obstacles[SK__MAX_OBSTACLES];
    int obstacle_count;
    uint64_t fingerprint;   /* of the model, for saved states */
    size_t parallel_points; /* below this many free points one thread runs the steps */
    double settle_move;     /* the largest move of the last settling step */
    int threads;            /* threads the steps run on (chosen by timing, see sim.c) */
    /* the choice of threads (sim.c), timed over as many calls as it takes */
    int64_t next_probe;       /* step at which the thread count is chosen again */
    int probe_phase;          /* 0 none; 1, 2: timing steps on one thread, then on all */
    int64_t probe_steps[2];   /* steps timed so far on one thread and on all */
    double probe_s[2];        /* and their seconds */
    double one_thread_step_s; /* seconds a step took on one thread at the last choice */
    double (*clock)(void);    /* the clock that times the choice (sk_time_seconds) */
    bool vectors;             /* the AVX2 paths (where the processor has them; simd.h) */
};

/* Whether the springs and the collisions take their AVX2 paths (on by default where the
 * processor has them; the tests turn them off to compare the bits). */
void sk__sim_use_vectors(sk_tissue_sim *s, bool on);
/* The pose of the motion at step k. */
void sk__sim_pose_at(const sk_tissue_sim *s, int64_t k, sk_tissue_pose *pose);
/* The muscles' shapes at a pose. */
void sk__sim_shape_muscles(const sk_tissue_sim *s, const sk_tissue_pose *pose,
                           sk__muscle_state *muscle);
/* Muscle and bone points where a pose puts them (into x), given the muscles' shapes at
 * that pose. An orphaned loop, like sk__collide. */
void sk__sim_place_anchors(const sk_tissue_sim *s, const sk_tissue_pose *pose,
                           const sk__muscle_state *muscle, double *x);
/* Where the tissue alone (the pose's bones, the muscles' shapes at it) carries free point
 * p's rest position (inline: the step calls it for every free point). */
static inline sk_vec3d sk__sim_carried(const sk_tissue_sim *s, const sk_tissue_pose *pose,
                                       const sk__muscle_state *muscle, size_t p)
{
    const sk_tissue_model *m = s->m;
    int mu = m->carrier_muscle[p];
    if (mu >= 0) {
        /* the muscle's deformation, extended beyond its surface */
        const sk__ellipsoid *e = &muscle[mu].body;
        sk_vec3d u = m->local[p];
        return sk_v3d_add(
            e->centre,
            sk_m3d_apply(e->axes, sk_v3d(u.x * e->radii.x, u.y * e->radii.y, u.z * e->radii.z)));
    }
    return sk__pose_apply(pose, m->bones[m->owner[p]].joint, m->local[p]);
}

#endif
