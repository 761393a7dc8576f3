/* Results, error details and range checks shared by every module (CONTRIBUTING.md,
 * "Errors and files"). */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "shitsukan/core.h"

const char *sk_result_string(sk_result result)
{
    switch (result) {
    case SK_OK:
        return "ok";
    case SK_ERROR_INVALID_ARGUMENT:
        return "invalid argument";
    case SK_ERROR_OUT_OF_MEMORY:
        return "out of memory";
    case SK_ERROR_LIMIT:
        return "limit exceeded";
    case SK_ERROR_IO:
        return "input/output error";
    case SK_ERROR_PARSE:
        return "malformed input";
    case SK_ERROR_UNSUPPORTED:
        return "unsupported";
    case SK_ERROR_NOT_FOUND:
        return "not found";
    case SK_ERROR_NUMERIC:
        return "numeric failure";
    case SK_RESULT_COUNT:
        break;
    }
    return "unknown result";
}

sk_result sk_failv(sk_error *err, sk_result result, const char *fmt, va_list args)
{
    if (err) {
        err->result = result;
        vsnprintf(err->message, sizeof err->message, fmt, args);
    }
    return result;
}

sk_result sk_fail(sk_error *err, sk_result result, const char *fmt, ...)
{
    va_list args;
    va_start(args, fmt);
    sk_failv(err, result, fmt, args);
    va_end(args);
    return result;
}

sk_result sk_error_prefix(sk_error *err, sk_result result, const char *fmt, ...)
{
    if (!err) return result;
    err->result = result;
    char prefix[SK_ERROR_MESSAGE_SIZE];
    va_list args;
    va_start(args, fmt);
    vsnprintf(prefix, sizeof prefix, fmt, args);
    va_end(args);
    /* joined = prefix [": " message], truncated to the buffer */
    char joined[SK_ERROR_MESSAGE_SIZE];
    size_t pos = 0;
    const char *parts[3] = {prefix, err->message[0] ? ": " : "", err->message};
    for (int i = 0; i < 3; i++)
        for (const char *c = parts[i]; *c && pos + 1 < sizeof joined; c++) joined[pos++] = *c;
    joined[pos] = '\0';
    memcpy(err->message, joined, sizeof joined);
    return result;
}

void sk_error_clear(sk_error *err)
{
    if (!err) return;
    err->result = SK_OK;
    err->message[0] = '\0';
}

sk_result sk_check_finite(sk_error *err, const char *name, double value)
{
    if (!isfinite(value))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "%s is not a finite number (got %g)", name,
                       value);
    return SK_OK;
}

/* a == b at float precision (only where both are within the float range) */
static bool same_as_float(double a, double b)
{
    return fabs(a) <= FLT_MAX && fabs(b) <= FLT_MAX && (float)a == (float)b;
}

bool sk_in_range_f(double value, double lo, double hi)
{
    if (!isfinite(value)) return false;
    if (value < lo && !same_as_float(value, lo)) return false;
    if (value > hi && !same_as_float(value, hi)) return false;
    return true;
}

sk_result sk_check_range_f(sk_error *err, const char *name, double value, double lo, double hi)
{
    if (!isfinite(value))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "%s is not a finite number (got %g; accepted: [%g, %g])", name, value, lo,
                       hi);
    if (!sk_in_range_f(value, lo, hi))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "%s = %g is out of range [%g, %g]", name,
                       value, lo, hi);
    return SK_OK;
}

sk_result sk_check_range_i(sk_error *err, const char *name, long long value, long long lo,
                           long long hi)
{
    if (value < lo || value > hi)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "%s = %lld is out of range [%lld, %lld]",
                       name, value, lo, hi);
    return SK_OK;
}

bool sk_size_mul(size_t a, size_t b, size_t *out)
{
    if (a != 0 && b > SIZE_MAX / a) return false;
    *out = a * b;
    return true;
}

bool sk_size_add(size_t a, size_t b, size_t *out)
{
    if (b > SIZE_MAX - a) return false;
    *out = a + b;
    return true;
}
