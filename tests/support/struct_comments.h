/* The members of a struct of the public headers with their comments, and the range and
 * default a comment states, for the test that header comments agree with the schemas. */
#ifndef SK_TEST_STRUCT_COMMENTS_H
#define SK_TEST_STRUCT_COMMENTS_H

#include <stdbool.h>

#define SK_TEST_MAX_MEMBERS 96

typedef struct sk_test_member {
    char name[64];
    char comment[1024];
    bool shared; /* declared with others ("int width, height;"): one comment for all */
} sk_test_member;

/* Finds "typedef struct `c_type` {" in include/shitsukan/ *.h of the source tree and lists
 * its members; returns how many (-1 when the struct is in no header). */
int sk_test_struct_members(const char *c_type, sk_test_member *out, int max);

/* A range a comment states: the last "[a, b]", "(a, b]", "[a, b)" or "(a, b)" of two
 * numbers. */
typedef struct sk_test_range {
    double lo, hi;
    bool lo_open, hi_open;
} sk_test_range;
bool sk_test_comment_range(const char *comment, sk_test_range *out);
/* The number after "0 = ", "0 = default " or "default " (first match), e.g. 150 of
 * "0 = 150; [1, 2000]"; false when the default is in words. */
bool sk_test_comment_default(const char *comment, double *out);
/* The n numbers after "all 0 = ", e.g. "(0.82, 0.64, 0.44)". */
bool sk_test_comment_defaults(const char *comment, double *out, int n);
/* Whether the comment says what 0 means ("0 = ...", "default 0"). */
bool sk_test_comment_zero_means(const char *comment);
/* The preset key a comment names for its member: `key "..."` (e.g. (key "rise_deg")). */
bool sk_test_comment_key(const char *comment, char *key, int size);

#endif
