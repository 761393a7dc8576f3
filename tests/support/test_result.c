/* Assertions on sk_result and sk_error for the cmocka tests (see test_result.h). */
#include "test_result.h"

#include <stdlib.h>
#include <string.h>

void sk_test_expect_failure(sk_result got, const sk_error *err, sk_result want, const char *needle)
{
    if (got != want)
        fail_msg("expected %s, got %s (%s)", sk_result_string(want), sk_result_string(got),
                 err->message);
    if (needle && !strstr(err->message, needle))
        fail_msg("message \"%s\" does not mention \"%s\"", err->message, needle);
    if (getenv("SK_TEST_VERBOSE")) print_message("%s\n", err->message);
}
