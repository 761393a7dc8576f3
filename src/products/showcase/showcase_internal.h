/* Private helpers shared by the showcase's files: melody messages, sorting, the hand's
 * placement over the keys and the per-time state of the performance. */
#ifndef SK_SHOWCASE_INTERNAL_H
#define SK_SHOWCASE_INTERNAL_H

#include "shitsukan/showcase.h"

/* "<name>:<line>: " or "<name>: byte <offset>: " for a note's source (empty when 0). */
void sk__melody_where(const sk_melody *melody, long source, char *out, size_t size);
/* Sorts notes by start, then key (stable on equal pairs by source). */
void sk__melody_sort(sk_note *notes, int count);
/* Allocates room for `count` notes in `out` (count 0 allowed). */
sk_result sk__melody_alloc(sk_melody *out, int count, const char *name, sk_melody_format format,
                           sk_error *err);

/* A Standard MIDI File checked event by event and rewritten plainly for libsmf: the
 * header, then each track with only its note-on/off events (explicit status bytes),
 * tempo changes and the end of track, deltas kept exact. libsmf asserts or misreads on
 * some malformed or merely unusual files (meta lengths over 127, running status after a
 * meta event, a track without its end), so it only ever sees this copy. */
typedef struct sk__midi_plain {
    uint8_t *bytes;
    size_t size;
    int track_count;
    int *event_count; /* per track, events in the plain copy (end of track included) */
    long **offset;    /* per track, per event (0-based), its byte offset in the source */
} sk__midi_plain;

sk_result sk__midi_plain_make(const uint8_t *data, size_t length, const char *name,
                              sk__midi_plain *out, sk_error *err);
void sk__midi_plain_free(sk__midi_plain *plain);

/* ------------------------------------------------------------ performance */

/* The hand as the performance plays it: the playing posture (constant torques that hold
 * the fingertips over five neighbouring white keys at the hover height), the press and
 * aim DOFs of each finger, and where each fingertip pad sits from the wrist. */
typedef struct sk__hand_rig {
    double base_torque[SK_HAND_DOF_COUNT];
    double wrist_angles[3]; /* wrist.flex, wrist.roll, wrist.dev pinned (radians) */
    int press_dof[5][2];    /* the thesis's two DOFs of a press (MCP, PIP flexion; the
                               thumb: CMC palmar abduction, MCP flexion) */
    double press_dir[5][2]; /* torque per unit of press amplitude */
    int aim_dof[5];         /* abduction that aims a finger at its key's centre */
    double tip_radius[5];
    sk_vec3d pad_offset[5];   /* pad centre from the wrist in the playing posture (scene
                                 axes) */
    sk_vec3d press_offset[5]; /* the same with the finger pressing a key to the bottom (a
                                 press draws a pad back toward the palm) */
    double hover_depth;       /* pads' lowest points below the wrist in that posture */
    double max_depth[5];      /* how far below the hover a press can take each pad (the
                                 lowest point of its flexion arc) */
    double home_z;            /* the wrist's depth the hand keeps when it can: the mean
                                 of the depths at which each finger can strike a white
                                 key */
} sk__hand_rig;

/* Distal link and fingertip point of finger f (0 thumb .. 4 little). */
static inline int sk__distal_link(int f) { return f == 0 ? 3 : 4 * f + 3; }
static inline int sk__tip_point(int f) { return 5 * f + 4; }

/* What the performance asks of one finger at a time. */
typedef enum sk__finger_phase {
    SK__FINGER_FREE = 0, /* not playing: held by the playing posture, kept off the keys */
    SK__FINGER_APPROACH, /* going down toward its key: target between hover and key top */
    SK__FINGER_PRESS,    /* on its key: the pad's bottom on the key top turned by `angle` */
    SK__FINGER_LIFT      /* leaving the key: target between key top and hover */
} sk__finger_phase;

typedef struct sk__finger_intent {
    sk__finger_phase phase;
    int note; /* melody index, -1 when free */
    int key;
    double angle; /* PRESS: the key's turn */
    double blend; /* APPROACH / LIFT: 0 at hover, 1 at the key's top */
} sk__finger_intent;

typedef struct sk__intent {
    sk_vec3d wrist; /* scene position of the wrist centre */
    sk__finger_intent finger[5];
} sk__intent;

typedef struct sk__performance {
    const sk_melody *melody;
    const sk_piano *piano;
    const sk__hand_rig *rig;
    sk_performance_desc desc; /* resolved */
    double hover_y;           /* wrist height that puts the pads at the hover height */
} sk__performance;

/* The parts of sk_showcase_schema (schema.c): the frame keys (its first fields), the
   piano, fingering, performance and synth. */
extern const sk_schema sk__showcase_frame_schema, sk__piano_schema, sk__fingering_schema,
    sk__performance_schema, sk__synth_schema;

sk_performance_desc sk__performance_desc_resolved(const sk_performance_desc *desc);
sk_result sk__performance_desc_validate(const sk_performance_desc *desc, sk_error *err);
/* Finger intents and the wrist's position at time t: a function of t alone. */
void sk__performance_at(const sk__performance *perf, double t, sk__intent *out);
/* The depths (z) at which a finger's pad may be when it has pressed a key down. */
void sk__performance_contact_range(const sk__hand_rig *rig, const sk_piano_key *key, int finger,
                                   double *lo, double *hi);
/* The wrist depths (z) from which note i's finger can strike its key. */
void sk__performance_note_depths(const sk__performance *perf, int i, double *lo, double *hi);
/* Where the wrist must be for note i (its finger over its key at its contact depth). */
sk_vec3d sk__performance_note_wrist(const sk__performance *perf, int i);

/* ------------------------------------------------------------ numerics */

#define SK__NEWTON_MAX 16
/* One damped Gauss-Newton step for n unknowns and n residuals (n <= SK__NEWTON_MAX):
 * solves (J'J + lambda I) dx = -J'r, J row-major (row i = residual i), lambda a tiny
 * multiple of trace(J'J) so a DOF held at a limit (a zero column) does not break it. */
void sk__gauss_newton_step(int n, const double *jac, const double *res, double *dx);

/* The misses `res` (n values) for unknowns x. */
typedef sk_result (*sk__residual_fn)(void *user, const double *x, double *res, sk_error *err);
typedef struct sk__newton_desc {
    int n; /* unknowns = residuals, <= SK__NEWTON_MAX */
    sk__residual_fn fn;
    void *user;
    double tolerance; /* stops when every |miss| is below */
    int max_iterations;
    double diff_step; /* forward-difference step of the Jacobian */
    double max_step;  /* largest change of one unknown in a step */
} sk__newton_desc;
/* Solves from x (in place); res gets the misses at the returned x. */
sk_result sk__newton_solve(const sk__newton_desc *d, double *x, double *res, sk_error *err);

/* ------------------------------------------------------------ contact */

/* Scene point of a hand-coordinate point: the hand lies palm down over the keys, its
 * fingers toward the fallboard (hand X -> scene -x, Y -> -z, Z -> -y). */
static inline sk_vec3d sk__hand_to_scene(sk_vec3d p) { return (sk_vec3d){-p.x, -p.z, -p.y}; }
static inline sk_vec3d sk__scene_to_hand(sk_vec3d p) { return (sk_vec3d){-p.x, -p.z, -p.y}; }

typedef struct sk__contact {
    sk_hand_solver *solver;
    const sk_hand_skeleton *skeleton;
    const sk_piano *piano;
    const sk__hand_rig *rig;
    const sk_performance_desc *desc; /* resolved */
} sk__contact;

/* Solves the posture for an intent: torques on each playing finger's press and aim DOFs
 * such that its pad meets its target, fingers that do not play lifted where the coupling
 * pulls them into a key, the keys turned by the pads that push them. */
sk_result sk__contact_solve(const sk__contact *c, const sk__intent *in, double t,
                            sk_showcase_pose *out, sk_error *err);
/* Posture for given torques on top of the playing posture (wrist pinned at `wrist`): the
 * pads' centres in the scene. */
sk_result sk__contact_posture(const sk__contact *c, sk_vec3d wrist, const double *extra_torque,
                              double dofs[SK_HAND_DOF_COUNT], sk_hand_frames *frames,
                              sk_vec3d pads[5], sk_error *err);
/* Lowest point of a pad over the keys (the surface it may not go below): the highest key
 * top under the sphere, seen from the sphere's centre; -INFINITY over no key. */
double sk__keys_surface(const sk_piano *piano, sk_vec3d centre, double radius);

/* ------------------------------------------------------------ the forearm */

/* The forearm's skin relief as rendered: the microrelief of `skin`, softened toward the
 * forearm's end (along, mm from the elbow: full up to `fade_from`, `end_weight` of it at
 * `fade_to`) to the hand's softer baked relief where the two skins meet. */
typedef struct sk__forearm_relief {
    const sk_skin *skin;
    float fade_from, fade_to, end_weight;
} sk__forearm_relief;

/* The forearm (forearm.c): a tissue character whose root joint is the elbow and whose
 * joint "wrist" rides on the middle of the hand's wrist stump. */
typedef struct sk__forearm {
    sk_tissue_model *model; /* NULL: no forearm */
    sk_tissue_sim *sim;
    void *start; /* the simulation's state at time 0 */
    size_t start_size;
    int root;                        /* the elbow joint */
    double length;                   /* elbow to wrist, mm */
    sk_mat3d rest;                   /* rest frame (columns: across, back, elbow to wrist) */
    sk_vec3d across;                 /* scene direction across the hand (the hand's breadth) */
    sk_vec3d ride;                   /* from the hand's wrist centre to the middle of its
                                        wrist stump (scene), where the forearm's wrist rides */
    sk_vec3d home_axis;              /* direction from the elbow to the wrist (the carpus's) */
    sk_vec3d home_wrist, home_elbow; /* at time 0 */
    sk_mesh mesh;                    /* the skin: rest triangles and UVs, this frame's positions */
    float *tuck;                     /* per skin point: how far its end is drawn in (0..1) */
    sk__forearm_relief relief;       /* the render texture's data */
} sk__forearm;

sk_result sk__forearm_setup(sk_showcase *sc, sk_error *err);
void sk__forearm_free(sk_showcase *sc);
/* The skin at `seconds` into the forearm's mesh positions (the tissue step). */
sk_result sk__forearm_advance(sk_showcase *sc, double seconds, sk_error *err);
/* The mesh as rendered at `seconds` (after sk__forearm_advance to that time, with the
 * skinning): its end tucked under the hand's skin, then its normals. */
sk_result sk__forearm_render_mesh(sk_showcase *sc, double seconds, sk_error *err);
/* Render texture of the forearm's skin: the relief of the sk__forearm_relief `user` as a bump
 * map at the skin's UVs (mm). */
void sk__forearm_skin_texture(void *user, const sk_render_surface *surface, sk_render_texel *texel);

/* ------------------------------------------------------------ the showcase */

struct sk_showcase {
    sk_showcase_desc desc; /* resolved; pointers below replace the caller's */
    sk_melody melody;      /* with its fingers */
    sk_piano piano;
    sk_hand_skeleton skeleton;
    sk_hand_solver *solver;
    sk__hand_rig rig;
    sk__performance perf;
    sk__contact contact;
    sk_render_scene_desc *stage; /* the caller's stage, its wood trees built once */
    sk_wood *trees[SK_RENDER_MAX_MATERIALS];
    sk_render_scene_desc *scene; /* the frame being built */
    int ivory, ebony;            /* stage material indices */
    int frame_count;
    double duration_s;              /* of the sound and the frames */
    const sk_hand_surface *surface; /* the desc's or own_surface */
    sk_hand_surface *own_surface;
    const sk_image *skin_albedo, *skin_normal;
    sk_image own_albedo, own_normal;
    float *positions, *normals; /* skinning buffers (surface vertices) */
    double link_radius[SK_HAND_LINK_COUNT];
    sk__forearm forearm;
    float forearm_albedo[3]; /* the hand's texture's mean on its wrist stump */
};

/* The hand surface, its texture and the flesh radii (hand_mesh.c). */
sk_result sk__hand_mesh_setup(sk_showcase *sc, sk_error *err);
void sk__hand_mesh_free(sk_showcase *sc);
/* The skinned mesh of posed frames with atlas UVs, in scene coordinates (into `out`,
 * free with sk_mesh_free). */
sk_result sk__hand_mesh_posed(sk_showcase *sc, const sk_hand_frames *frames, sk_mesh *out,
                              sk_error *err);

/* The playing posture and the rig of the hand (posture.c). */
sk_result sk__hand_rig_make(sk_showcase *sc, sk_error *err);
/* A frame's render scene: the stage, the keys turned as the pose says, the hand's posed
 * mesh (referred to: it must live until the render scene is created) and the forearm
 * (scene.c). */
sk_result sk__scene_build(sk_showcase *sc, const sk_showcase_pose *pose, const sk_mesh *hand,
                          sk_render_scene_desc *out, sk_error *err);
/* The camera framing the keys the melody plays and the hand over them. */
void sk__scene_frame_camera(const sk_showcase *sc, sk_render_camera_desc *camera);

#endif /* SK_SHOWCASE_INTERNAL_H */
