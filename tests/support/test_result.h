/* Assertions on sk_result and sk_error for the cmocka tests. */
#ifndef SK_TEST_RESULT_H
#define SK_TEST_RESULT_H

#include "test_support.h"

#include "shitsukan/core.h"

/* Runs `call`, which may use the sk_error `e_` this macro declares, and fails the test
 * with the call, the result and the message unless it returns SK_OK. */
#define SK_ASSERT_OK(call)                                                                         \
    do {                                                                                           \
        sk_error e_ = {0};                                                                         \
        sk_result r_ = (call);                                                                     \
        if (r_ != SK_OK) fail_msg("%s -> %s: %s", #call, sk_result_string(r_), e_.message);        \
    } while (0)

/* Fails the test unless `got` is `want` and err's message contains `needle` (if not NULL).
 * With SK_TEST_VERBOSE set in the environment the message is printed, to review them. */
void sk_test_expect_failure(sk_result got, const sk_error *err, sk_result want, const char *needle);

#endif
