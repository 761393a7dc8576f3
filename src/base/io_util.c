/* File extensions and locale-independent number parsing for the text formats (OBJ, PLY). */
#define _POSIX_C_SOURCE 200809L
#include "base/io_internal.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

sk_result sk__fail_at(sk_error *err, sk_result result, const char *path, size_t line,
                      const char *fmt, va_list args)
{
    char what[SK_ERROR_MESSAGE_SIZE];
    vsnprintf(what, sizeof what, fmt, args);
    if (line > 0) return sk_fail(err, result, "%s:%zu: %s", path, line, what);
    return sk_fail(err, result, "%s: %s", path, what);
}

const char *sk__path_extension(const char *path)
{
    const char *slash = strrchr(path, '/');
    const char *base = slash ? slash + 1 : path;
    const char *dot = strrchr(base, '.');
    return (dot && dot != base) ? dot : "";
}

void sk__c_locale_push(sk__c_locale *state)
{
    state->previous = (locale_t)0;
    state->c_locale = newlocale(LC_NUMERIC_MASK, "C", (locale_t)0);
    /* If the locale object cannot be made, the thread keeps its locale: a program that
       never calls setlocale is in the "C" locale anyway. */
    if (state->c_locale) state->previous = uselocale(state->c_locale);
}

void sk__c_locale_pop(sk__c_locale *state)
{
    if (!state->c_locale) return;
    uselocale(state->previous);
    freelocale(state->c_locale);
    state->c_locale = (locale_t)0;
}

/* Tokens longer than this are not numbers any file writer produces. */
#define SK__MAX_NUMBER_TOKEN 127

bool sk__parse_double(const char *token, size_t len, double *out)
{
    char buf[SK__MAX_NUMBER_TOKEN + 1];
    if (len == 0 || len > SK__MAX_NUMBER_TOKEN) return false;
    /* strtod skips leading white space; a token never has any. */
    if (token[0] == ' ' || token[0] == '\t') return false;
    memcpy(buf, token, len);
    buf[len] = '\0';
    char *end;
    double v = strtod(buf, &end);
    if (end != buf + len) return false;
    /* Overflow gives +-HUGE_VAL (infinity), which callers reject as non-finite; underflow
       gives a tiny or zero value, which is harmless. */
    *out = v;
    return true;
}

bool sk__parse_int64(const char *token, size_t len, long long *out)
{
    char buf[SK__MAX_NUMBER_TOKEN + 1];
    if (len == 0 || len > SK__MAX_NUMBER_TOKEN) return false;
    size_t i = (token[0] == '-' || token[0] == '+') ? 1 : 0;
    if (i == len) return false;
    for (size_t k = i; k < len; k++)
        if (token[k] < '0' || token[k] > '9') return false;
    memcpy(buf, token, len);
    buf[len] = '\0';
    errno = 0;
    long long v = strtoll(buf, NULL, 10);
    if (errno == ERANGE) return false;
    *out = v;
    return true;
}
