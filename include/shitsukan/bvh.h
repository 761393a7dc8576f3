/* shitsukan BVH: the motion-capture format (Biovision Hierarchy) as motion-capture tools
 * write it, read strictly and written back. BVH has no formal specification; this follows
 * the common form described by Meredith & Maddock 2001 ("Motion capture file formats
 * explained"):
 *
 *   HIERARCHY
 *   ROOT <name> { OFFSET x y z  CHANNELS n <channel>...  (JOINT <name> { ... } | End Site
 *   { OFFSET x y z })... }          (one or more ROOTs)
 *   MOTION
 *   Frames: <count>
 *   Frame Time: <seconds>
 *   <channels_per_frame numbers> x count
 *
 * Each joint's CHANNELS line states its own channels and their order (any of Xposition
 * Yposition Zposition Xrotation Yrotation Zrotation, each at most once, in any order; 3
 * or 6 are usual). Rotations are in degrees and compose in the order listed: "Zrotation
 * Xrotation Yrotation" means R = Rz Rx Ry acting on column vectors, so the last listed
 * turns first. A joint's local transform is translation(OFFSET + position channels)
 * followed by that rotation; rest frames are aligned with the world (all channels zero
 * is the rest pose). Lines may end in LF or CRLF; tokens are separated by spaces or tabs.
 * Lengths are in whatever unit the file uses (a reader of the skeleton states it).
 *
 * Thread-safety: functions are thread-safe on distinct sk_bvh values; a read sk_bvh is
 * not modified by the query functions and may be shared. */
#ifndef SHITSUKAN_BVH_H
#define SHITSUKAN_BVH_H

#include <stdbool.h>
#include <stdio.h>

#include "shitsukan/core.h"

#ifdef __cplusplus
extern "C" {
#endif

#define SK_BVH_MAX_JOINTS 256
#define SK_BVH_NAME_SIZE 64
#define SK_BVH_MAX_DEPTH 64
/* Largest file sk_bvh_load_file reads (bytes). */
#define SK_BVH_MAX_FILE_BYTES ((size_t)64 << 20)

/* A skeleton and its motion. Joints are stored depth first, every parent before its
 * children; end sites are joints too (no channels, end_site set), named
 * "<parent>_end". */
typedef struct sk_bvh {
    int joint_count; /* joints and end sites */
    char name[SK_BVH_MAX_JOINTS][SK_BVH_NAME_SIZE];
    int parent[SK_BVH_MAX_JOINTS]; /* -1 for a ROOT */
    bool end_site[SK_BVH_MAX_JOINTS];
    sk_vec3d offset[SK_BVH_MAX_JOINTS];   /* from the parent, in file units */
    int channel_count[SK_BVH_MAX_JOINTS]; /* 0..6 */
    int channel_first[SK_BVH_MAX_JOINTS]; /* index of the first channel in a frame */
    char channel[SK_BVH_MAX_JOINTS][6];   /* 'x','y','z' position, 'X','Y','Z' rotation */
    int frame_count;
    int channels_per_frame;
    double frame_time; /* seconds per frame, > 0 */
    double *motion;    /* frame_count x channels_per_frame */
} sk_bvh;

/* ------------------------------------------------------------------ reading */
/* Parses BVH text. Malformed input fails with SK_ERROR_PARSE and a message
 * "<source>: line N: <reason>" (e.g. "unknown channel \"Qrotation\"", "expected \"{\",
 * found \"OFFSET\"", "truncated: 120 frames x 57 channels need 6840 numbers, the file
 * ends after 3121"); a hierarchy beyond SK_BVH_MAX_JOINTS or SK_BVH_MAX_DEPTH fails with
 * SK_ERROR_LIMIT. The motion array is sized by what the rest of the text can hold (each
 * number takes at least two bytes), so a header claiming more frames than the file holds
 * is reported as truncated before anything large is allocated. `out` is large (about
 * 30 KB): allocate it on the heap. On failure nothing is left allocated in `out`. */
sk_result sk_bvh_parse(const char *text, size_t length, const char *source_name, sk_bvh *out,
                       sk_error *err);
/* Reads and parses a file of at most SK_BVH_MAX_FILE_BYTES. */
sk_result sk_bvh_load_file(const char *path, sk_bvh *out, sk_error *err);
void sk_bvh_free(sk_bvh *bvh);

/* Index of the joint called `name`, or -1. */
int sk_bvh_find(const sk_bvh *bvh, const char *name);

/* A joint's local transform at a frame: its rotation (the rotation channels composed in
 * file order) and its translation from the parent (OFFSET plus the position channels). */
void sk_bvh_local(const sk_bvh *bvh, int joint, int frame, sk_mat3d *rotation,
                  sk_vec3d *translation);
/* World rotation and position of every joint (and end site) at a frame; `rotations` may
 * be NULL. Arrays hold joint_count entries. */
void sk_bvh_pose(const sk_bvh *bvh, int frame, sk_mat3d *rotations, sk_vec3d *positions);
/* World positions of every joint (and end site) at a frame. */
void sk_bvh_positions(const sk_bvh *bvh, int frame, sk_vec3d *out);

/* ------------------------------------------------------------ building, writing */
/* Starts an empty skeleton (no joints, no motion). */
void sk_bvh_init(sk_bvh *bvh);
/* Appends a joint under `parent` (-1 for a ROOT; otherwise a joint added before, not an
 * end site) with its channels as codes in order, e.g. "xyzZYX" (6) or "ZXY" (3); NULL or
 * "" with end_site for an End Site. Joints must be added depth first (each joint's
 * subtree complete before its next sibling) for the file to read back in the same order.
 * Writes the new index to *out_index (may be NULL). */
sk_result sk_bvh_add_joint(sk_bvh *bvh, const char *name, int parent, sk_vec3d offset,
                           const char *channels, bool end_site, int *out_index, sk_error *err);
/* Allocates zeroed motion for frame_count frames of frame_time seconds (after the
 * joints are added). */
sk_result sk_bvh_alloc_motion(sk_bvh *bvh, int frame_count, double frame_time, sk_error *err);

/* Writes the skeleton and motion in the form above (tab indentation, LF line ends,
 * numbers with 9 decimals, "C" locale). The file is written atomically. */
sk_result sk_bvh_write(const sk_bvh *bvh, const char *path, sk_error *err);
/* The same text to a stream; SK_ERROR_IO if the stream reports an error. */
sk_result sk_bvh_write_stream(const sk_bvh *bvh, FILE *out);

#ifdef __cplusplus
}
#endif

#endif /* SHITSUKAN_BVH_H */
