/* shitsukan showcase: the four models in one scene. A right hand plays a piano cut from
 * the wood solid texture (Kawai 2000): each note drives two DOFs of its finger, MCP and
 * PIP flexion, and the rest of the hand follows by the natural coupling potential, as in
 * the thesis's piano demonstration (Yasumuro 2000, sec. 4.2.3, Fig. 4.21); the hand's
 * skin carries the microrelief (Ishii 1991) through the hand surface's texture, and the
 * forearm's fat jiggles as the fingers strike and the wrist travels (Shigemori & Kawai).
 *
 * The parts, each usable on its own:
 * - melodies: a plain text format and Standard MIDI Files (read through libsmf after the
 *   file's framing is checked here, so a malformed file is an error naming its byte
 *   offset, never a crash), and a MIDI writer;
 * - fingering: a finger for every note the input leaves without one (a dynamic programme
 *   over the hand's span and the fingers' order, docs/showcase.md states the rule);
 * - the piano: key layout and key mechanics (keys turn about a pivot behind the key slip
 *   and go down only when a fingertip pushes them);
 * - synthesis: an additive piano tone with inharmonic partials and two-stage decay;
 * - the showcase: the performance (notes -> finger inputs and wrist travel), the contact
 *   of fingertips and keys, and the frames, WAV and MP4 of the whole scene.
 *
 * Units: millimetres, seconds, radians. Scene frame: x along the keyboard (toward the
 * treble), y up, z toward the player (the keys' fronts face +z).
 *
 * Thread-safety: melodies, pianos and the pure functions here are thread-safe on
 * distinct outputs. An sk_showcase belongs to one thread at a time (its posture solver
 * and simulation keep caches); it renders each frame in parallel itself, with the same
 * bytes for any thread count. */
#ifndef SHITSUKAN_SHOWCASE_H
#define SHITSUKAN_SHOWCASE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "shitsukan/core.h"
#include "shitsukan/hand.h"
#include "shitsukan/render.h"
#include "shitsukan/tissue.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ================================================================ melody */

#define SK_PIANO_KEY_FIRST 21 /* A0, the lowest key of an 88-key piano (MIDI number) */
#define SK_PIANO_KEY_LAST 108 /* C8 */
#define SK_PIANO_KEY_COUNT 88
#define SK_MELODY_MAX_NOTES 20000
#define SK_MELODY_MAX_SECONDS 3600.0
#define SK_MELODY_MAX_BYTES (16u << 20) /* files larger than this are refused */
#define SK_FINGER_AUTO 0                /* a note's finger left to sk_melody_choose_fingers */

typedef struct sk_note {
    int key;           /* MIDI note number, SK_PIANO_KEY_FIRST..SK_PIANO_KEY_LAST (60 = C4) */
    double start_s;    /* onset, seconds from the start of the melody, >= 0 */
    double duration_s; /* > 0 */
    int finger;        /* 1 thumb, 2 index, 3 middle, 4 ring, 5 little; 0 = automatic */
    int velocity;      /* 1..127 (MIDI); the text format's default is 80 */
    long source;       /* text: the line it was read from; MIDI: byte offset of its note-on
                          event; 0 for notes made in C (used in messages) */
} sk_note;

typedef enum sk_melody_format {
    SK_MELODY_FORMAT_TEXT = 0, /* messages say "<name>:<line>:" */
    SK_MELODY_FORMAT_MIDI      /* messages say "<name>: byte <offset>:" */
} sk_melody_format;

typedef struct sk_melody {
    int note_count;
    sk_note *notes;          /* sorted by start, then key; allocated (sk_melody_free) */
    sk_melody_format format; /* where the notes came from */
    char name[128];          /* source name for messages (a file name) */
} sk_melody;

/* The text format (docs/showcase.md): one note a line, "NOTE START DURATION [FINGER]
 * [VELOCITY]", NOTE a name (C4, F#3, Bb5; octave -1..9, C4 = 60) or a key number 21..108,
 * START and DURATION in seconds (or in beats after a "bpm N" line), FINGER 1..5 or "-"
 * (automatic); a '#' at the start of a field starts a comment (C#4 is a note). Strict: every error
 * is one line naming the line of the input, e.g. "twinkle.txt:7: duration \"0\" must be a number >
 * 0". A key pressed again while it still sounds is an error (a piano key cannot be struck twice at
 * once). */
sk_result sk_melody_parse_text(const char *text, size_t length, const char *source_name,
                               sk_melody *out, sk_error *err);
/* Standard MIDI Files (format 0 or 1; any channel; tempo changes honoured). The chunk and
 * event framing is checked first (errors name the byte offset); the events are then read
 * through libsmf. A note-on without its note-off ends at the track's end; a key struck
 * again while it sounds ends the earlier note there (as a piano does). MIDI carries no
 * fingering: every note's finger is automatic. */
sk_result sk_melody_parse_midi(const uint8_t *data, size_t length, const char *source_name,
                               sk_melody *out, sk_error *err);
/* Reads a file: MIDI if it starts with "MThd", otherwise text. */
sk_result sk_melody_load(const char *path, sk_melody *out, sk_error *err);
void sk_melody_free(sk_melody *melody);
/* A deep copy (free with sk_melody_free). */
sk_result sk_melody_copy(const sk_melody *melody, sk_melody *out, sk_error *err);
/* Checks notes made in C: keys, finite times in range, no key struck twice at once,
 * order (sorts them if needed). */
sk_result sk_melody_validate(sk_melody *melody, sk_error *err);
/* Keeps the first `seconds` of a melody: notes starting later are dropped, notes still
 * sounding then end there (a preview of a long piece). seconds > 0. */
sk_result sk_melody_cut(sk_melody *melody, double seconds, sk_error *err);
/* The time the last note ends (0 for an empty melody). */
double sk_melody_end(const sk_melody *melody);

/* Writes a format-0 Standard MIDI File (480 ticks per quarter note at 120 bpm, so times
 * land on ticks of 1/960 s; velocities kept; fingers are not part of MIDI). */
sk_result sk_melody_write_midi(const sk_melody *melody, const char *path, sk_error *err);
/* Writes the text format (seconds, with each note's finger). */
sk_result sk_melody_write_text(const sk_melody *melody, const char *path, sk_error *err);

/* Note names: "C4" <-> 60. sk_note_parse accepts A-G (either case), then '#' or 'b' (at
 * most two), then the octave -1..9, or a plain key number; false if it is neither. */
bool sk_note_parse(const char *text, int *key);
/* Writes e.g. "C#4" (sharps) into `out` (at least 6 bytes). */
void sk_note_name(int key, char *out, size_t size);
/* True for the black keys (C#, D#, F#, G#, A#). */
bool sk_note_is_black(int key);

/* ================================================================ piano */

/* The keyboard. Keys are boxes at their standard sizes (white keys notched around the
 * black ones); a key turns about an axis across the keyboard `pivot_mm` behind its front,
 * so its front goes down by at most `dip_mm`. */
typedef struct sk_piano_desc {
    double white_pitch_mm; /* white keys' centre spacing; 0 = 23.5 (an octave 164.5 mm);
                              [15, 30] */
    double dip_mm;         /* key dip at the front; 0 = 10; [2, 20] */
    double pivot_mm;       /* from a key's front to its pivot; 0 = 250; [100, 600] */
    double white_top_mm;   /* height of the white keys' tops at rest; 0 = 747; [0, 5000] */
    double front_mm;       /* z of the keys' fronts; 0 = 275; [-5000, 5000] */
} sk_piano_desc;

typedef struct sk_piano_key {
    int key; /* MIDI number */
    bool black;
    double x_mm;                   /* centre of the key's playing surface across the keyboard */
    double width_mm;               /* of the playing surface (a white key's front part) */
    double top_mm;                 /* top at rest */
    double front_mm, back_mm;      /* z of its front and of the back of its visible top */
    double notch_front_mm;         /* white keys: where the front part ends (the black keys'
                                      fronts); black keys: = back_mm */
    double back_x0_mm, back_x1_mm; /* white keys: x range of the part between the black
                                      keys; black keys: their x range */
    double thickness_mm;
} sk_piano_key;

typedef struct sk_piano {
    sk_piano_desc desc; /* resolved */
    double pivot_z_mm;  /* z of every key's pivot axis (at the height of its top) */
    double max_angle;   /* turn of a key at full dip (radians) */
    sk_piano_key keys[SK_PIANO_KEY_COUNT]; /* index = key - SK_PIANO_KEY_FIRST */
} sk_piano;

sk_result sk_piano_init(sk_piano *piano, const sk_piano_desc *desc, sk_error *err);
static inline const sk_piano_key *sk_piano_key_get(const sk_piano *piano, int key)
{
    return key < SK_PIANO_KEY_FIRST || key > SK_PIANO_KEY_LAST
               ? NULL
               : &piano->keys[key - SK_PIANO_KEY_FIRST];
}
/* Height of a key's top at scene depth z when the key is turned down by `angle`. */
double sk_piano_key_top_at(const sk_piano *piano, const sk_piano_key *key, double angle, double z);
/* The key whose top contains (x, z) seen from above (a black key over the white keys'
 * back parts), or 0 if none. */
int sk_piano_key_under(const sk_piano *piano, double x, double z);
/* Signed distance from a point to a key's solid turned down by `angle` (negative inside;
 * the key is the union of its boxes). */
double sk_piano_key_distance(const sk_piano *piano, const sk_piano_key *key, double angle,
                             sk_vec3d p);
/* Render objects of one key turned by `angle` (its front part and, for white keys, the
 * part between the black keys), named "key-<name>[-back]" with material `material`;
 * returns how many it wrote (1 or 2) into `out`. */
int sk_piano_key_objects(const sk_piano *piano, const sk_piano_key *key, double angle,
                         const char *material, sk_render_object_desc out[2]);

/* ================================================================ fingering */

/* Automatic fingering of a right hand (docs/showcase.md): a dynamic programme over the
 * notes in time order whose state is the finger of every note still sounding, so notes
 * held together always get distinct fingers in the order of their keys and a span the
 * hand reaches. Costs (in white keys' widths): moving the hand (how far the key step
 * differs from the step between the two fingers' places in the five-finger position,
 * dearer when there is little time), one finger on two different keys in a row, the
 * thumb or little finger on a black key, the weaker fourth finger; neighbouring fingers
 * busy at once never take keys closer than two fingertips (a half step). Fingers given in
 * the input are kept. */
typedef struct sk_fingering_desc {
    double finger_x_mm[5];              /* fingertips across the keyboard in the hand's playing
                                           position, thumb first; all 0 = one white key apart
                                           (0, 23.5, 47, 70.5, 94) */
    double reach_mm;                    /* notes held together: the largest difference between their
                                           keys' spacing and their fingers' that the fingers' spread
                                           can make up; 0 = 30; [0, 200] */
    double pitch_mm;                    /* a white key's width for the costs; 0 = 23.5 */
    double spacing_mm;                  /* neighbouring fingers (index to little) busy at once need
                                           keys at least this far apart: two fingertips' breadth;
                                           0 = 17; [0, 50] */
    double busy_before_s, busy_after_s; /* a finger is busy from this long before its
                               note to this long after (its approach and lift); 0 = 0.12,
                               0.14 */
    double move_gap_s; /* the least silence in which one finger moves to another key
                          while the hand is busy; 0 = 0.05 */
    bool apart[5][5];  /* pairs of fingers (thumb first) that cannot hold keys down
                          together (a hand whose fingers reach different depths);
                          all false = any pair can; the showcase fills it from its
                          hand */
} sk_fingering_desc;

/* Chooses the automatic fingers of `melody` in place; keys are placed by `piano` (NULL =
 * the default layout). `cost` (may be NULL) gets the total. Errors: more than five notes
 * at once, or held notes no fingering reaches, naming the note's line or byte. */
sk_result sk_melody_choose_fingers(sk_melody *melody, const sk_piano *piano,
                                   const sk_fingering_desc *desc, double *cost, sk_error *err);

/* ================================================================ synthesis */

/* An additive piano tone: partials f_n = n f0 sqrt(1 + B n^2) (string inharmonicity B,
 * Fletcher 1964), amplitudes shaped by the hammer's strike position and velocity, each
 * partial decaying in two stages (the prompt sound and the aftersound of coupled strings,
 * Weinreich 1977) until the damper ends it after the note's release. Deterministic. */
typedef struct sk_synth_desc {
    int sample_rate;      /* 0 = 44100; [8000, 192000] */
    double gain;          /* level of a note of velocity 127; 0 = 0.25; [1e-6, 1] */
    double inharmonicity; /* B at C4 (scaled by pitch); 0 = 0.0004; [-1, 0.01], negative = 0 */
    double decay_s;       /* aftersound time constant at C4; 0 = 3; [0.1, 60] */
    double release_s;     /* damper time constant; 0 = 0.1; [0.005, 5] */
    double tail_s;        /* sound kept after the last note ends; 0 = 1; [0, 30] */
} sk_synth_desc;

/* Number of samples a melody's sound takes (its end plus the tail). */
size_t sk_synth_length(const sk_melody *melody, const sk_synth_desc *desc);
/* Renders `count` mono samples into `out` (values in [-1, 1]); count may differ from
 * sk_synth_length (cut or padded with silence). Same samples for any thread count. */
sk_result sk_synth_render(const sk_melody *melody, const sk_synth_desc *desc, float *out,
                          size_t count, sk_error *err);

/* ================================================================ performance */

/* How the hand plays (beyond the thesis's input, which is the press itself). */
typedef struct sk_performance_desc {
    double approach_s;       /* a finger starts down toward its key this long before the
                                key reaches half its dip (= the note's start); 0 = 0.12;
                                [0.02, 1] */
    double descent_s;        /* key travel from top to bottom (and back); 0 = 0.04;
                                [0.005, 0.2] */
    double lift_s;           /* back up to the hover height after the key is up; 0 = 0.12;
                                [0.02, 1] */
    double hover_mm;         /* fingertips' height above the white keys in the playing
                                posture; 0 = 6; [2, 40] */
    double clearance_mm;     /* a finger that does not play stays at least this above any
                                key (it is lifted if the coupling pulls it lower); 0 = 1;
                                [0, 10] */
    double press_pip_ratio;  /* PIP torque per MCP torque of a press; 0 = 0.5 / 0.9 (the
                                thesis's piano demo, presets/hand/piano-key.json); [0, 4] */
    double travel_s;         /* how far in time the wrist looks to the notes before and
                                after (Gaussian width of the blend of their positions);
                                0 = 0.04; [0.01, 2] */
    double strike_drop_mm;   /* the wrist gives way this much at a strike and recovers;
                                0 = 1.5; [-1, 10], negative = none */
    double tip_radius_mm[5]; /* fingertip pads (spheres at the ends of the distal links);
                               all 0 = measured on the hand surface: the largest distance
                               of its flesh from the distal link's axis near the tip, so
                               the sphere holds the fingertip */
} sk_performance_desc;

/* ================================================================ the showcase */

typedef struct sk_showcase_desc {
    const sk_melody *melody;                /* required; copied, automatic fingers chosen */
    const sk_render_scene_desc *stage;      /* required: the cabinet, floor, lights, film
                                               and the materials named "ivory" and "ebony"
                                               (presets/showcase/stage.json); its camera if
                                               position or target is set, else a camera
                                               framing the keys the melody plays and the
                                               hand. Copied; wood trees built once. */
    const sk_hand_constraints *constraints; /* required: the coupling potential
                                               (presets/hand/natural.json) */
    const sk_hand_skeleton_desc *hand;      /* NULL = the default right hand (a left hand
                                               is refused: the piece is for the right) */
    const sk_hand_surface *surface;         /* the hand's skin surface, built on a skeleton
                                               of the same desc; NULL = built here (about
                                               1 s). Referenced: it must outlive the
                                               showcase */
    const sk_image *skin_albedo;            /* the surface's texture (sk_hand_texture_bake):
                                               linear albedo and normal map of its atlas;
                                               NULL = baked here from back_skin and palm_skin
                                               at texture_size. Referenced */
    const sk_image *skin_normal;
    const sk_skin *back_skin, *palm_skin;    /* microrelief of the baked texture (the skin
                                                module's back-of-hand and palm presets); NULL
                                                = none */
    int texture_size;                        /* 0 = 1024; [64, 8192] */
    int hand_triangles;                      /* of a surface built here; 0 = 8000 (the
                                                thesis's count); [500, 200000] */
    const sk_tissue_character_desc *forearm; /* the forearm's tissue character (presets/
                                               showcase/forearm.json): its root joint is
                                               the elbow, its joint named "wrist" rides on
                                               the hand's wrist, its rest +Y is the back of
                                               the forearm; NULL = no forearm. Copied */
    sk_piano_desc piano;
    sk_fingering_desc fingering; /* finger_x_mm all 0 = measured on the hand's
                                    playing posture */
    sk_performance_desc performance;
    sk_synth_desc synth;
    double fps;        /* 0 = 24; [1, 240] */
    int width, height; /* frames; 0 = 1280 x 720; [16, 8192] */
    int samples;       /* camera samples per pixel; 0 = 16; [1, 1024] */
} sk_showcase_desc;

typedef struct sk_showcase sk_showcase;

sk_result sk_showcase_create(const sk_showcase_desc *desc, sk_showcase **out, sk_error *err);
void sk_showcase_destroy(sk_showcase *showcase);

/* Frames: from time 0 to the end of the sound (the melody plus the synth's tail). */
int sk_showcase_frame_count(const sk_showcase *showcase);
double sk_showcase_fps(const sk_showcase *showcase);
/* The melody with its fingers chosen. */
const sk_melody *sk_showcase_melody(const sk_showcase *showcase);
const sk_piano *sk_showcase_piano(const sk_showcase *showcase);
const sk_hand_skeleton *sk_showcase_skeleton(const sk_showcase *showcase);
const sk_hand_surface *sk_showcase_surface(const sk_showcase *showcase);
/* Radius of the flesh around each link of the hand (the largest distance of the
 * surface's vertices bound to it from its axis; 0 for the carpus): capsules from the
 * link's joint to its end point (the fingertip pads for the distal links) that hold the
 * hand, for contact checks. */
double sk_showcase_link_radius(const sk_showcase *showcase, int link);

/* The hand and keys at one time: a function of the time alone (no history), so any
 * frame can be computed by itself. */
typedef struct sk_showcase_pose {
    double time_s;
    double dofs[SK_HAND_DOF_COUNT];       /* absolute, hand coordinates (sk_hand_forward) */
    sk_hand_frames frames;                /* posed, hand coordinates */
    double key_angle[SK_PIANO_KEY_COUNT]; /* turn of each key (0 = up, piano->max_angle =
                                             fully down) */
    int key_finger[SK_PIANO_KEY_COUNT];   /* the finger pushing each key (1..5), 0 none */
    int finger_note[5];                   /* note index (into the melody) each finger plays
                                             now, -1 none */
    sk_vec3d tip_centre[5];               /* scene position of each fingertip pad's centre */
    double tip_radius[5];
    int solves;              /* posture solves the contact took */
    double contact_error_mm; /* largest miss of a pressing fingertip's target */
} sk_showcase_pose;

sk_result sk_showcase_pose_at(sk_showcase *showcase, double time_s, sk_showcase_pose *out,
                              sk_error *err);
/* Scene position of a point in hand coordinates (the hand's placement over the keys). */
sk_vec3d sk_showcase_hand_to_scene(const sk_showcase *showcase, sk_vec3d p);

/* The forearm's skin points (0 without a forearm). */
size_t sk_showcase_forearm_points(const sk_showcase *showcase);
/* The forearm's skin at a frame (3 floats a point, scene mm, into `skin`) and where its
 * bones alone carry each point (`carried`, the flesh at rest relative to them); either may
 * be NULL. The simulation runs from time 0 (an earlier frame than the last one asked
 * restarts it), so the flesh at a frame is the same whatever was asked before. */
sk_result sk_showcase_forearm_at(sk_showcase *showcase, int frame, float *skin, float *carried,
                                 sk_error *err);

/* Where the time of the last frames went (seconds, summed over the frames). */
typedef struct sk_showcase_stats {
    int frames;
    double seconds_input;  /* melody -> finger intents and wrist travel */
    double seconds_solve;  /* posture solves of the contact */
    double seconds_skin;   /* hand mesh (skinning) and the forearm's normals */
    double seconds_tissue; /* forearm simulation */
    double seconds_scene;  /* building the render scene */
    double seconds_render; /* ray tracing */
    double seconds_write;  /* PNG files */
    double seconds_audio;  /* synthesis and WAV */
    double seconds_video;  /* the video encoder */
    bool video_written;
    char video_note[256]; /* why there is no MP4, if there is none */
} sk_showcase_stats;

/* Renders one frame (RGBA float, linear premultiplied, as sk_render_scene_render).
 * Any frame may be asked for in any order with the same result; with a forearm, frames
 * in increasing order are cheapest (its simulation runs forward from time 0 and an
 * earlier frame restarts it). `stats` (may be NULL) gets the time of this frame added. */
sk_result sk_showcase_render_frame(sk_showcase *showcase, int frame, sk_image *image,
                                   sk_showcase_stats *stats, sk_error *err);

/* Makes the video of a finished run: the frames (a printf pattern of PNG paths, one
 * %0Nd), their rate, the WAV, and the path of the video to write (atomically). It sets
 * *written, or leaves it false and says why in `note` (an encoder that is not there is
 * a note, not an error). The library runs no program itself: the shitsukan command's
 * encoder runs ffmpeg (tools/video_ffmpeg.c). */
typedef sk_result (*sk_showcase_video_fn)(void *user, const char *frames_pattern, double fps,
                                          const char *wav, const char *path, char *note,
                                          size_t note_size, bool *written, sk_error *err);

typedef struct sk_showcase_run_desc {
    const char *output_dir; /* required; created. Writes frames/frame_NNNN.png,
                               showcase.wav, fingering.txt and showcase.mp4 */
    int first_frame;        /* default 0 */
    int last_frame;         /* inclusive; -1 = the last frame */
    bool join_only;         /* render nothing: make the MP4 from the frames in the folder */
    bool no_video;          /* leave out the MP4 */
    const char *ffmpeg;     /* deprecated (kept for one release; docs/architecture.md): read
                               by the command's encoder only, the library ignores it */
    sk_showcase_video_fn encode_video; /* makes showcase.mp4 once every frame is there;
                                          NULL: no video (stats->video_note says so) */
    void *encode_video_user;
    sk_progress progress; /* fraction of the frames done */
} sk_showcase_run_desc;

/* Checks a run's outputs before any work: the output folder, if it exists, is a folder.
 * sk_showcase_run calls it. */
sk_result sk_showcase_check_output(const sk_showcase_run_desc *desc, sk_error *err);

/* Renders the frames first_frame..last_frame into the folder, writes the WAV and the
 * fingering, and once every frame of the piece is in the folder (from this run or earlier
 * ones, e.g. split with first/last_frame), has desc->encode_video make showcase.mp4
 * (unless no_video); stats->video_note says why there is none. A frame is the same
 * whichever runs render it. */
sk_result sk_showcase_run(sk_showcase *showcase, const sk_showcase_run_desc *desc,
                          sk_showcase_stats *stats, sk_error *err);

/* Writes the whole melody's sound as a WAV (44.1 kHz by default, 16-bit mono) of the
 * showcase's length. */
sk_result sk_showcase_write_wav(const sk_showcase *showcase, const char *path, sk_error *err);

/* Preset schema of the numbers of sk_showcase_desc (src/products/showcase/schema.c): the
 * frames, the hand's surface and texture, piano, fingering, performance and synth. */
extern const sk_schema sk_showcase_schema;

#ifdef __cplusplus
}
#endif

#endif /* SHITSUKAN_SHOWCASE_H */
