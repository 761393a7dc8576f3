/* Private helpers shared by the files of the hand module (skeleton indexing, strict JSON
 * reading with key paths). */
#ifndef SK_HAND_PRIVATE_H
#define SK_HAND_PRIVATE_H

#include <cjson/cJSON.h>

#include "shitsukan/hand.h"
#include "shitsukan/preset.h"

/* Finger of a link (-1 for the carpus), first link of a finger, links per finger. */
int sk_hand__finger_of_link(int link);
int sk_hand__first_link(int finger);
int sk_hand__link_count_of_finger(int finger);
/* First DOF carried by a link and how many (1..3, 3 for the wrist rotations). */
int sk_hand__first_dof_of_link(int link, int *count);

/* Largest JSON / CSV / BVH file read (bytes). */
#define SK_HAND_MAX_FILE_BYTES ((size_t)64 << 20)

/* ----- strict JSON reading (cJSON): every error names the key path ----- */
/* Parses text; on failure names the line of the error (callers prefix the source). */
sk_result sk_hand__json_parse(const char *text, size_t length, const char *source_name, cJSON **out,
                              sk_error *err);
/* Fails if `object` has a key that is neither in `allowed` (NULL-terminated) nor a
 * documentation key. */
sk_result sk_hand__json_check_keys(const cJSON *object, const char *path,
                                   const char *const *allowed, sk_error *err);
/* Reads a finite number in [lo, hi] at object[key] into *out (absent: leaves *out,
 * returns SK_OK unless `required`). */
sk_result sk_hand__json_number(const cJSON *object, const char *path, const char *key, double lo,
                               double hi, bool required, double *out, sk_error *err);
/* Reads a string at object[key] (absent: *out = NULL). */
sk_result sk_hand__json_string(const cJSON *object, const char *path, const char *key,
                               const char **out, sk_error *err);
/* Requires `item` to be an object. */
sk_result sk_hand__json_expect_object(const cJSON *item, const char *path, sk_error *err);
/* A finger by its letter ("T", "I", "M", "R", "L"), or -1. */
int sk_hand__finger_by_letter(const char *name);

/* Looks up a DOF by name or fails: "<path>: unknown DOF \"name\"". */
sk_result sk_hand__dof_by_name(const char *name, const char *path, int *dof, sk_error *err);

/* Reads a whole data file (at most SK_HAND_MAX_FILE_BYTES) and hands it to a parser
 * `parse(text, length, path, ctx, err)`. */
typedef sk_result (*sk_hand__parse_fn)(const char *text, size_t length, const char *source_name,
                                       void *ctx, sk_error *err);
sk_result sk_hand__parse_file(const char *path, sk_hand__parse_fn parse, void *ctx, sk_error *err);

/* Writes text through an atomic file (temp + rename). */
sk_result sk_hand__write_text_file(const char *path, const char *text, sk_error *err);

/* Angle values in files: degrees for rotations, millimetres for translations. */
static inline double sk_hand__from_file_units(int dof, double v)
{
    return sk_hand_dof(dof)->translation ? v : v * SK_DEG_TO_RAD;
}
static inline double sk_hand__to_file_units(int dof, double v)
{
    return sk_hand_dof(dof)->translation ? v : v * SK_RAD_TO_DEG;
}

#endif /* SK_HAND_PRIVATE_H */
