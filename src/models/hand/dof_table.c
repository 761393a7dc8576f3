/* The DOF table, points and links of the hand skeleton (thesis 3.1.1, 3.1.3; Table 3.1
 * as decided in the spec: wrist 6 + 29 joint DOF). Names, axes and signs. */
#include <string.h>

#include "models/hand/hand_internal.h"

/* Right-hand frames: X radial, Y distal, Z palmar. Rz(+a) turns a link toward -X
 * (ulnar), so abduction away from the middle finger is -Z for the index and middle
 * (radial), +Z for the ring and little (ulnar). The thumb's frame is rotated by its
 * mount: its X points palmar and its Z across the palm, so palmar abduction is -Z. */
static const sk_hand_dof_info dof_table[SK_HAND_DOF_COUNT] = {
    {"wrist.tx", 0, 'X', 1, true, "translation of the wrist centre along world X (mm)"},
    {"wrist.ty", 0, 'Y', 1, true, "translation of the wrist centre along world Y (mm)"},
    {"wrist.tz", 0, 'Z', 1, true, "translation of the wrist centre along world Z (mm)"},
    {"wrist.flex", 0, 'X', 1, false, "palmar flexion of the whole hand (- = extension)"},
    {"wrist.roll", 0, 'Y', 1, false, "roll about the hand's long axis, palm toward the thumb side"},
    {"wrist.dev", 0, 'Z', 1, false, "ulnar deviation (- = radial deviation)"},
    {"T.CMC.flex", 1, 'X', 1, false, "thumb CMC flexion across the palm (- = extension)"},
    {"T.CMC.abd", 1, 'Z', -1, false, "thumb CMC palmar abduction, away from the palm"},
    {"T.MCP.flex", 2, 'X', 1, false, "thumb MCP flexion"},
    {"T.MCP.abd", 2, 'Z', -1, false, "thumb MCP abduction (palmar)"},
    {"T.IP.flex", 3, 'X', 1, false, "thumb IP flexion (- = hyperextension)"},
    {"I.CMC.flex", 4, 'X', 1, false, "index CMC flexion (nearly rigid)"},
    {"I.CMC.abd", 4, 'Z', -1, false, "index CMC abduction, radial (nearly rigid)"},
    {"I.MCP.flex", 5, 'X', 1, false, "index MCP flexion (- = extension)"},
    {"I.MCP.abd", 5, 'Z', -1, false, "index MCP abduction, radial (away from the middle finger)"},
    {"I.PIP.flex", 6, 'X', 1, false, "index PIP flexion"},
    {"I.DIP.flex", 7, 'X', 1, false, "index DIP flexion"},
    {"M.CMC.flex", 8, 'X', 1, false, "middle CMC flexion (nearly rigid)"},
    {"M.CMC.abd", 8, 'Z', -1, false, "middle CMC deviation, radial (nearly rigid)"},
    {"M.MCP.flex", 9, 'X', 1, false, "middle MCP flexion (- = extension)"},
    {"M.MCP.abd", 9, 'Z', -1, false, "middle MCP abduction, radial (- = ulnar)"},
    {"M.PIP.flex", 10, 'X', 1, false, "middle PIP flexion"},
    {"M.DIP.flex", 11, 'X', 1, false, "middle DIP flexion"},
    {"R.CMC.flex", 12, 'X', 1, false, "ring CMC flexion (cupping of the palm)"},
    {"R.CMC.abd", 12, 'Z', 1, false, "ring CMC deviation, ulnar"},
    {"R.MCP.flex", 13, 'X', 1, false, "ring MCP flexion (- = extension)"},
    {"R.MCP.abd", 13, 'Z', 1, false, "ring MCP abduction, ulnar (away from the middle finger)"},
    {"R.PIP.flex", 14, 'X', 1, false, "ring PIP flexion"},
    {"R.DIP.flex", 15, 'X', 1, false, "ring DIP flexion"},
    {"L.CMC.flex", 16, 'X', 1, false, "little CMC flexion (cupping of the palm)"},
    {"L.CMC.abd", 16, 'Z', 1, false, "little CMC deviation, ulnar"},
    {"L.MCP.flex", 17, 'X', 1, false, "little MCP flexion (- = extension)"},
    {"L.MCP.abd", 17, 'Z', 1, false, "little MCP abduction, ulnar (away from the middle finger)"},
    {"L.PIP.flex", 18, 'X', 1, false, "little PIP flexion"},
    {"L.DIP.flex", 19, 'X', 1, false, "little DIP flexion"},
};

static const char *const point_names[SK_HAND_POINT_COUNT] = {
    "wrist", "T.CMC", "T.MCP", "T.IP",  "T.tip", "I.CMC", "I.MCP", "I.PIP", "I.DIP",
    "I.tip", "M.CMC", "M.MCP", "M.PIP", "M.DIP", "M.tip", "R.CMC", "R.MCP", "R.PIP",
    "R.DIP", "R.tip", "L.CMC", "L.MCP", "L.PIP", "L.DIP", "L.tip",
};

static const char *const point_bvh_names[SK_HAND_POINT_COUNT] = {
    "Hand",      "T_CMC", "T_MCP",     "T_IP",      "T_IP_end", "I_CMC",     "I_MCP",
    "I_PIP",     "I_DIP", "I_DIP_end", "M_CMC",     "M_MCP",    "M_PIP",     "M_DIP",
    "M_DIP_end", "R_CMC", "R_MCP",     "R_PIP",     "R_DIP",    "R_DIP_end", "L_CMC",
    "L_MCP",     "L_PIP", "L_DIP",     "L_DIP_end",
};

/* Base point of each link; the carpus starts at the wrist. */
static const int link_point[SK_HAND_LINK_COUNT] = {
    0, 1, 2, 3, 5, 6, 7, 8, 10, 11, 12, 13, 15, 16, 17, 18, 20, 21, 22, 23,
};

const sk_hand_dof_info *sk_hand_dof(int dof)
{
    return dof >= 0 && dof < SK_HAND_DOF_COUNT ? &dof_table[dof] : NULL;
}

int sk_hand_dof_find(const char *name)
{
    if (!name) return -1;
    for (int i = 0; i < SK_HAND_DOF_COUNT; i++)
        if (strcmp(dof_table[i].name, name) == 0) return i;
    return -1;
}

const char *sk_hand_point_name(int point)
{
    return point >= 0 && point < SK_HAND_POINT_COUNT ? point_names[point] : NULL;
}

const char *sk_hand_point_bvh_name(int point)
{
    return point >= 0 && point < SK_HAND_POINT_COUNT ? point_bvh_names[point] : NULL;
}

int sk_hand_point_parent(int point)
{
    if (point <= 0 || point >= SK_HAND_POINT_COUNT) return -1;
    /* CMC joints hang from the wrist; every other point from the previous one. */
    if (point == 1 || (point >= 5 && (point - 5) % 5 == 0)) return 0;
    return point - 1;
}

const char *sk_hand_link_name(int link)
{
    return link >= 0 && link < SK_HAND_LINK_COUNT ? point_bvh_names[link_point[link]] : NULL;
}

int sk_hand_link_point(int link)
{
    return link >= 0 && link < SK_HAND_LINK_COUNT ? link_point[link] : -1;
}

int sk_hand_link_end_point(int link)
{
    if (link <= 0 || link >= SK_HAND_LINK_COUNT) return -1;
    return link_point[link] + 1;
}

int sk__hand_finger_of_link(int link)
{
    if (link <= 0) return -1;
    if (link <= 3) return SK_HAND_THUMB;
    return 1 + (link - 4) / 4;
}

int sk__hand_first_link(int finger) { return finger == SK_HAND_THUMB ? 1 : 4 + 4 * (finger - 1); }

int sk__hand_link_count_of_finger(int finger) { return finger == SK_HAND_THUMB ? 3 : 4; }

/* First DOF and DOF count of each link (matches dof_table's link column; the test
 * checks it). */
static const int link_first_dof[SK_HAND_LINK_COUNT] = {
    0, 6, 8, 10, 11, 13, 15, 16, 17, 19, 21, 22, 23, 25, 27, 28, 29, 31, 33, 34,
};
static const int link_dof_count[SK_HAND_LINK_COUNT] = {
    6, 2, 2, 1, 2, 2, 1, 1, 2, 2, 1, 1, 2, 2, 1, 1, 2, 2, 1, 1,
};

int sk__hand_first_dof_of_link(int link, int *count)
{
    if (count) *count = link_dof_count[link];
    return link_first_dof[link];
}
