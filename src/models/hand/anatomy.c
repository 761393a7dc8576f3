/* Anatomy of the skeleton: segment lengths as fractions of hand length and breadth
 * (Buchholz, Armstrong, Goldstein 1992), the relaxed posture theta_bar (thesis 3.1.4) and
 * joint limits and spring stiffness per DOF (3.2.1). The same numbers, each with its
 * source, are in presets/hand/anatomy.json (a test keeps the two equal). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "models/hand/hand_internal.h"
#include "shitsukan/io.h"

/* One DOF: limits, relaxed value (degrees, mm for translations), stiffness. */
typedef struct dof_row {
    double min, max, relaxed, stiffness;
} dof_row;

static const dof_row default_dofs[SK_HAND_DOF_COUNT] = {
    /* wrist: places the hand in the scene (the forearm is not modelled) */
    {-1000, 1000, 0, 1},
    {-1000, 1000, 0, 1},
    {-1000, 1000, 0, 1},
    {-180, 180, 0, 1},
    {-180, 180, 0, 1},
    {-180, 180, 0, 1},
    /* thumb: AAOS active ranges (CMC extension 20 / flexion 15, abduction 70; MCP 0-50;
       IP -20..80); relaxed so that the thumb rests slightly flexed and palmar-abducted
       beside the index finger, its pad radial and palmar of the index's proximal
       phalanx (the resting pattern of Taylor & Schwarz 1955) */
    {-20, 15, 10, 1},
    {0, 70, 25, 2},
    {0, 50, 10, 1},
    {-5, 5, 0, 4},
    {-20, 80, 10, 1},
    /* index: CMC nearly rigid; MCP -45..90, abduction +-20 (AAOS); PIP 0-100, DIP 0-90
       (AAOS); relaxed at the lower bounds of Bain et al. 2015's functional ranges (19,
       23, 10), each finger toward the little one 5, 5 and 3 degrees more flexed: the
       flexion cascade of the resting hand (Taylor & Schwarz 1955) */
    {-2, 2, 0, 50},
    {-2, 2, 0, 50},
    {-45, 90, 19, 1},
    {-20, 20, 0, 2},
    {0, 100, 23, 1},
    {0, 90, 10, 1},
    /* middle */
    {-2, 2, 0, 50},
    {-2, 2, 0, 50},
    {-45, 90, 24, 1},
    {-20, 20, 0, 2},
    {0, 100, 28, 1},
    {0, 90, 13, 1},
    /* ring: CMC flexion about 10 degrees (Batmanabane & Malathi 1985) */
    {0, 10, 0, 5},
    {-5, 5, 0, 10},
    {-45, 90, 29, 1},
    {-20, 20, 0, 2},
    {0, 100, 33, 1},
    {0, 90, 16, 1},
    /* little: CMC flexion about 20 degrees (same source) */
    {0, 20, 0, 3},
    {-5, 5, 0, 10},
    {-45, 90, 34, 1},
    {-20, 20, 0, 2},
    {0, 100, 38, 1},
    {0, 90, 19, 1},
};

/* Buchholz et al. 1992: CMC centres 0.073 HL distal of the wrist centre, lateral offsets
 * in hand breadths; metacarpal and phalanx lengths in hand lengths. The thumb's mount is
 * its metacarpal's direction at zero CMC angles (35 degrees radial in the palm plane, pad
 * turned toward the fingers, i.e. rolled 90 degrees against the fingers' frames). */
static const sk_hand_finger_data default_fingers[SK_HAND_FINGER_COUNT] = {
    {0.196, 0.073, 0.0, 0.0, 0.251, {0.196, 0.158, 0.0}, 0, 0, 0},
    {0.126, 0.073, 0.0, 0.126, 0.374, {0.265, 0.143, 0.097}, 0, 0, 0},
    {0.0, 0.073, 0.0, 0.0, 0.373, {0.277, 0.170, 0.108}, 0, 0, 0},
    {-0.129, 0.073, 0.0, -0.077, 0.336, {0.259, 0.165, 0.107}, 0, 0, 0},
    {-0.223, 0.073, 0.0, -0.170, 0.295, {0.206, 0.117, 0.093}, 0, 0, 0},
};

/* Thumb mount (degrees): splay toward the radial side in the palm plane, tilt toward the
 * palm, roll about its own axis. */
#define THUMB_SPLAY_DEG (-35.0)
#define THUMB_TILT_DEG 0.0
#define THUMB_ROLL_DEG (-90.0)

void sk_hand_anatomy_default(sk_hand_anatomy *out)
{
    memset(out, 0, sizeof *out);
    /* a round adult size between the men's and women's means of the 1988 US Army
       anthropometric survey (Gordon et al. 1989) */
    out->hand_length_mm = 190.0;
    out->hand_breadth_mm = 85.0;
    memcpy(out->finger, default_fingers, sizeof default_fingers);
    out->finger[SK_HAND_THUMB].thumb_splay = THUMB_SPLAY_DEG * SK_DEG_TO_RAD;
    out->finger[SK_HAND_THUMB].mount_tilt = THUMB_TILT_DEG * SK_DEG_TO_RAD;
    out->finger[SK_HAND_THUMB].mount_roll = THUMB_ROLL_DEG * SK_DEG_TO_RAD;
    for (int i = 0; i < SK_HAND_DOF_COUNT; i++) {
        out->dof[i].min = sk__hand_from_file_units(i, default_dofs[i].min);
        out->dof[i].max = sk__hand_from_file_units(i, default_dofs[i].max);
        out->dof[i].relaxed = sk__hand_from_file_units(i, default_dofs[i].relaxed);
        out->dof[i].stiffness = default_dofs[i].stiffness;
    }
}
