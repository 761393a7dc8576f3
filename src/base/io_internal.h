/* Private helpers shared by the file readers and writers: file extensions, numbers in the
 * "C" locale (not installed). */
#ifndef SK_IO_INTERNAL_H
#define SK_IO_INTERNAL_H

/* Needs _POSIX_C_SOURCE >= 200809L (locale_t) defined before any system header. */
#include <locale.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

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

/* ----- outputs (atomic_file.c, output_set.c, signal_cleanup.c) ----- */

/* What an output path names once symbolic links are followed. */
typedef enum sk__output_kind {
    SK__OUTPUT_FILE,  /* a regular file or nothing yet: written beside it, renamed onto it */
    SK__OUTPUT_STREAM /* a character device or FIFO (/dev/null, a pipe): written in place */
} sk__output_kind;

/* Resolves `path` for writing: a symbolic link is followed to its target (so the link is
 * kept and the target replaced); folders, block devices and sockets are refused
 * (SK_ERROR_INVALID_ARGUMENT). Writes the path to write (malloc'd) and its kind. */
sk_result sk__output_resolve(const char *path, char **resolved, sk__output_kind *kind,
                             sk_error *err);
/* SK_ERROR_IO "<path>: cannot create file (<reason>)" unless the folder of `path` exists. */
sk_result sk__output_folder_exists(const char *path, sk_error *err);

/* A hidden sibling name of `path` for staging: "<dir>/.<name>.<8 hex digits><suffix>",
 * the name shortened so that it fits NAME_MAX however long `path`'s last component is.
 * `salt` picks the hex digits. Returns a malloc'd string or NULL. */
char *sk__sibling_name(const char *path, const char *suffix, uint64_t salt);

/* Registers a path to remove if SIGINT, SIGTERM or SIGHUP stops the process (a folder:
 * its files and itself). The string must stay valid until unregistered. Returns the slot
 * (-1 when the table is full), for sk__cleanup_unregister. */
int sk__cleanup_register(const char *path, bool folder);
void sk__cleanup_unregister(int slot);
/* Removes every registered path now (what the signal handler does). */
void sk__cleanup_now(void);

#endif
