/* Private helpers shared by the file readers and writers: file extensions, numbers in the
 * "C" locale (not installed). */
#ifndef SK_IO_INTERNAL_H
#define SK_IO_INTERNAL_H

/* Needs _POSIX_C_SOURCE >= 200809L (locale_t) defined before any system header. */
#include <locale.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stddef.h>

#include "shitsukan/core.h"

/* Records "<path>:<line>: <what>" (or "<path>: <what>" when line is 0) in `err` and
 * returns `result`: the form every text-format reader uses for its messages. */
sk_result sk__fail_at(sk_error *err, sk_result result, const char *path, size_t line,
                      const char *fmt, va_list args);

/* The extension of the last path component including its dot (".png"), or "" if none. */
const char *sk__path_extension(const char *path);

/* Text formats always use '.' as the decimal separator, whatever locale the program set:
 * the calling thread switches to the "C" numeric locale for the duration of a read or
 * write (uselocale is per thread, so other threads are not affected). */
typedef struct sk__c_locale {
    locale_t c_locale;
    locale_t previous;
} sk__c_locale;
void sk__c_locale_push(sk__c_locale *state);
void sk__c_locale_pop(sk__c_locale *state);

/* Parses a whole token of `len` bytes as a decimal (or hexadecimal) number. Returns false
 * for an empty token or trailing characters. The value is non-finite for "nan", "inf" or
 * a number beyond the double range; callers check finiteness. */
bool sk__parse_double(const char *token, size_t len, double *out);
/* Parses a whole token as a signed decimal integer in [INT64_MIN, INT64_MAX]. */
bool sk__parse_int64(const char *token, size_t len, long long *out);

#endif
