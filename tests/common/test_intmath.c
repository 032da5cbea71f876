/* test_intmath.c: floor_div and ceil_div against values worked out by hand:
 * the mathematical floor and ceiling of a / b, for either sign of a. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "intmath.h"

#define expect_div(actual, expected, what)                                              \
    do {                                                                                \
        int64_t a_ = (actual), e_ = (expected);                                         \
        if (a_ != e_)                                                                   \
            fail_msg("%s: got %lld, expected %lld", (what), (long long)a_,              \
                     (long long)e_);                                                    \
    } while (0)

static void negative_quotient_rounds_down_and_up(void **state)
{
    (void)state;
    expect_div(floor_div(-7, 2), -4, "floor(-3.5)");  /* C's -7 / 2 is -3 */
    expect_div(ceil_div(-7, 2), -3, "ceil(-3.5)");
    expect_div(floor_div(-1, 256), -1, "floor(-1/256)");
    expect_div(ceil_div(-1, 256), 0, "ceil(-1/256)");
}

static void positive_quotient_rounds_down_and_up(void **state)
{
    (void)state;
    expect_div(floor_div(7, 2), 3, "floor(3.5)");
    expect_div(ceil_div(7, 2), 4, "ceil(3.5)");
    expect_div(floor_div(1, 256), 0, "floor(1/256)");
    expect_div(ceil_div(1, 256), 1, "ceil(1/256)");
}

static void exact_multiples_are_not_rounded(void **state)
{
    (void)state;
    expect_div(floor_div(8, 2), 4, "floor(8/2)");
    expect_div(ceil_div(8, 2), 4, "ceil(8/2)");
    expect_div(floor_div(-8, 2), -4, "floor(-8/2)");
    expect_div(ceil_div(-8, 2), -4, "ceil(-8/2)");
    expect_div(floor_div(0, 5), 0, "floor(0/5)");
    expect_div(ceil_div(0, 5), 0, "ceil(0/5)");
    expect_div(floor_div(-5, 1), -5, "floor(-5/1)");
    expect_div(ceil_div(-5, 1), -5, "ceil(-5/1)");
}

static void int64_extremes_do_not_overflow(void **state)
{
    (void)state;
    expect_div(floor_div(INT64_MIN, 1), INT64_MIN, "floor(INT64_MIN/1)");
    expect_div(ceil_div(INT64_MIN, 1), INT64_MIN, "ceil(INT64_MIN/1)");
    expect_div(floor_div(INT64_MAX, 1), INT64_MAX, "floor(INT64_MAX/1)");
    expect_div(ceil_div(INT64_MAX, 1), INT64_MAX, "ceil(INT64_MAX/1)");
    /* INT64_MIN = -2^63 is even; INT64_MAX = 2^63 - 1 is odd */
    expect_div(floor_div(INT64_MIN, 2), INT64_MIN / 2, "floor(INT64_MIN/2)");
    expect_div(ceil_div(INT64_MIN, 2), INT64_MIN / 2, "ceil(INT64_MIN/2)");
    expect_div(floor_div(INT64_MAX, 2), INT64_MAX / 2, "floor(INT64_MAX/2)");
    expect_div(ceil_div(INT64_MAX, 2), INT64_MAX / 2 + 1, "ceil(INT64_MAX/2)");
    expect_div(floor_div(INT64_MIN + 1, 2), INT64_MIN / 2, "floor((INT64_MIN+1)/2)");
    expect_div(ceil_div(INT64_MIN + 1, 2), INT64_MIN / 2 + 1, "ceil((INT64_MIN+1)/2)");
    expect_div(floor_div(-1, INT64_MAX), -1, "floor(-1/INT64_MAX)");
    expect_div(ceil_div(1, INT64_MAX), 1, "ceil(1/INT64_MAX)");
}

static void floor_and_ceil_bracket_the_quotient(void **state)
{
    (void)state;
    for (int64_t a = -50; a <= 50; a++)
        for (int64_t b = 1; b <= 7; b++) {
            int64_t f = floor_div(a, b), c = ceil_div(a, b);
            if (!(f * b <= a && a < (f + 1) * b))
                fail_msg("floor_div(%lld, %lld) = %lld", (long long)a, (long long)b,
                         (long long)f);
            if (!((c - 1) * b < a && a <= c * b))
                fail_msg("ceil_div(%lld, %lld) = %lld", (long long)a, (long long)b,
                         (long long)c);
        }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(negative_quotient_rounds_down_and_up),
        cmocka_unit_test(positive_quotient_rounds_down_and_up),
        cmocka_unit_test(exact_multiples_are_not_rounded),
        cmocka_unit_test(int64_extremes_do_not_overflow),
        cmocka_unit_test(floor_and_ceil_bracket_the_quotient),
    };
    return cmocka_run_group_tests_name("intmath", tests, NULL, NULL);
}
