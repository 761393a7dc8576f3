/* Private helpers of the calibrated potential (potential_*.c) and its evaluation. */
#ifndef SK_HAND_POTENTIAL_PRIVATE_H
#define SK_HAND_POTENTIAL_PRIVATE_H

#include "hand/hand_private.h"

/* The DOFs a potential calibrates from samples with these columns: the joint angles
 * (wrist DOFs and translations excluded), in DOF order. Returns the count. */
int sk_hand__calibrated_dofs(const bool *present, int *dof);

/* A constraint set read from a JSON object (the format of sk_hand_constraints_parse)
 * that may also hold the keys in `extra` (NULL-terminated, may be NULL). Errors name the
 * key path below `path`. */
sk_result sk_hand__constraints_from_json(const cJSON *object, const char *path,
                                         const sk_hand_skeleton *skeleton,
                                         const char *const *extra, sk_hand_constraints *out,
                                         sk_error *err);

/* Parses text as exactly one JSON value: trailing text, duplicate keys and numbers that
 * overflow are errors ("line N: ..."). */
sk_result sk_hand__json_parse_strict(const char *text, size_t length, cJSON **out, sk_error *err);

#endif
