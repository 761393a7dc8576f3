/* Helpers shared by the files of the hand model (skeleton indexing, file units); its
 * JSON readers share src/formats/hand/hand_json_internal.h. */
#ifndef SK_HAND_INTERNAL_H
#define SK_HAND_INTERNAL_H

#include "shitsukan/hand_posture.h"
#include "shitsukan/preset.h"

/* Finger of a link (-1 for the carpus), first link of a finger, links per finger. */
int sk__hand_finger_of_link(int link);
int sk__hand_first_link(int finger);
int sk__hand_link_count_of_finger(int finger);
/* First DOF carried by a link and how many (1..3, 3 for the wrist rotations). */
int sk__hand_first_dof_of_link(int link, int *count);

/* Largest JSON / CSV / BVH file read (bytes). */
#define SK_HAND_MAX_FILE_BYTES ((size_t)64 << 20)

/* A finger by its letter ("T", "I", "M", "R", "L"), or -1. */
int sk__hand_finger_by_letter(const char *name);

/* Looks up a DOF by name or fails: "<path>: unknown DOF \"name\"". */
sk_result sk__hand_dof_by_name(const char *name, const char *path, int *dof, sk_error *err);

/* Adds a constraint row on `n` DOFs with coefficients `coeff`, intercept `b` and `weight`,
 * given on absolute angles (radians) or on displacements from the rest pose. */
sk_result sk__hand_constraints_add_row(sk_hand_constraints *c, const sk_hand_skeleton *s,
                                       const int *dof, const double *coeff, int n, double b,
                                       double weight, bool absolute, const char *label,
                                       const char *path, sk_error *err);

/* Angle values in files: degrees for rotations, millimetres for translations. */
static inline double sk__hand_from_file_units(int dof, double v)
{
    return sk_hand_dof(dof)->translation ? v : v * SK_DEG_TO_RAD;
}
static inline double sk__hand_to_file_units(int dof, double v)
{
    return sk_hand_dof(dof)->translation ? v : v * SK_RAD_TO_DEG;
}

#endif /* SK_HAND_INTERNAL_H */
