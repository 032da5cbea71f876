/* test_target.c: the buffers a lesson draws into, the fragment counts and the
 * per-pixel trace log. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "target.h"

/* target.c's cap on a traced pixel's history: 1 << 20 entries. */
#define TRACE_CAP (1 << 20)

/* target_init allocates; clearing the depth buffer is the lesson's own
 * clear_depth (each lesson's tests check it). The counts start at zero. */
static void init_allocates_with_counts_at_zero(void **state)
{
    (void)state;
    Target t;
    Error err;
    assert_true(target_init(&t, 3, 2, &err));
    assert_int_equal(t.width, 3);
    assert_int_equal(t.height, 2);
    assert_non_null(t.depth);
    assert_non_null(t.face);
    for (int i = 0; i < 3 * 2; i++)
        if (t.overdraw[i] != 0)
            fail_msg("pixel %d starts with overdraw %u, not 0", i, t.overdraw[i]);
    assert_int_equal(t.stats.tested, 0);
    assert_int_equal(t.trace.pixel, -1);
    assert_int_equal(t.trace.count, 0);
    assert_true(t.counting); /* a lesson's summary prints the counts */
    target_free(&t);
}

static void init_refuses_sizes_outside_one_to_16384(void **state)
{
    (void)state;
    static const int bad[][2] = {{0, 10}, {10, 0}, {-1, 5}, {16385, 1}, {1, 16385}};
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        Target t;
        Error err = {""};
        if (target_init(&t, bad[k][0], bad[k][1], &err))
            fail_msg("target_init accepted %dx%d", bad[k][0], bad[k][1]);
        char want[128];
        snprintf(want, sizeof want, "image size %dx%d is out of range (1 to 16384 on a side)",
                 bad[k][0], bad[k][1]);
        assert_string_equal(err.msg, want);
        assert_null(t.depth);
        target_free(&t); /* harmless after a failed init */
    }
}

static void record_counts_and_traces_only_the_traced_pixel(void **state)
{
    (void)state;
    Target t;
    Error err;
    assert_true(target_init(&t, 4, 3, &err));
    target_trace_pixel(&t, 2, 1); /* index y * width + x = 1 * 4 + 2 = 6 */
    assert_int_equal(t.trace.pixel, 6);

    target_record(&t, 6, 0, 5.0f, INFINITY, true);
    target_record(&t, 6, 1, 7.0f, 5.0f, false);
    target_record(&t, 5, 2, 1.0f, INFINITY, true); /* another pixel: counted, not traced */

    assert_int_equal(t.stats.tested, 3);
    assert_int_equal(t.stats.passed, 2);
    assert_int_equal(t.stats.failed, 1);
    assert_int_equal(t.overdraw[6], 2);
    assert_int_equal(t.overdraw[5], 1);
    assert_int_equal(t.trace.count, 2);
    assert_int_equal(t.trace.entries[0].face, 0);
    assert_true(t.trace.entries[0].passed);
    assert_int_equal(t.trace.entries[1].face, 1);
    assert_true(t.trace.entries[1].value == 7.0f && t.trace.entries[1].stored == 5.0f);
    assert_false(t.trace.entries[1].passed);
    target_free(&t);
}

/* Counting off (make bench's timed repetitions): target_record keeps no book,
 * not the totals, not overdraw[], not the traced pixel's log; switched back
 * on, it counts from where the books were left. */
static void record_with_counting_off_keeps_no_books(void **state)
{
    (void)state;
    Target t;
    Error err;
    assert_true(target_init(&t, 4, 3, &err));
    target_trace_pixel(&t, 2, 1); /* pixel 6 */
    t.counting = false;
    target_record(&t, 6, 0, 5.0f, INFINITY, true);
    target_record(&t, 6, 1, 7.0f, 5.0f, false);
    target_record(&t, 5, 2, 1.0f, INFINITY, true);
    assert_int_equal(t.stats.tested, 0);
    assert_int_equal(t.stats.passed, 0);
    assert_int_equal(t.stats.failed, 0);
    for (int i = 0; i < 4 * 3; i++)
        if (t.overdraw[i] != 0)
            fail_msg("pixel %d counted %u fragments with counting off", i, t.overdraw[i]);
    assert_int_equal(t.trace.count, 0);

    t.counting = true;
    target_record(&t, 6, 3, 2.0f, 5.0f, true);
    assert_int_equal(t.stats.tested, 1);
    assert_int_equal(t.stats.passed, 1);
    assert_int_equal(t.overdraw[6], 1);
    assert_int_equal(t.overdraw[5], 0);
    assert_int_equal(t.trace.count, 1);
    assert_int_equal(t.trace.entries[0].face, 3);
    target_free(&t);
}

static void trace_log_keeps_order_as_it_grows(void **state)
{
    (void)state;
    TraceLog log = {.pixel = 0};
    for (int i = 0; i < 1000; i++)
        trace_log_append(&log, i, (float)i, 0, i % 2 == 0);
    assert_int_equal(log.count, 1000);
    assert_false(log.overflowed);
    for (int i = 0; i < 1000; i++)
        if (log.entries[i].face != i || log.entries[i].passed != (i % 2 == 0))
            fail_msg("entry %d holds face %d", i, log.entries[i].face);
    free(log.entries);
}

static void trace_log_stops_at_its_cap_and_says_so(void **state)
{
    (void)state;
    TraceLog log = {.pixel = 0};
    for (int i = 0; i < TRACE_CAP + 5; i++)
        trace_log_append(&log, i, 0, 0, true);
    assert_int_equal(log.count, TRACE_CAP);
    assert_true(log.overflowed);
    assert_int_equal(log.entries[TRACE_CAP - 1].face, TRACE_CAP - 1);
    free(log.entries);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(init_allocates_with_counts_at_zero),
        cmocka_unit_test(init_refuses_sizes_outside_one_to_16384),
        cmocka_unit_test(record_counts_and_traces_only_the_traced_pixel),
        cmocka_unit_test(record_with_counting_off_keeps_no_books),
        cmocka_unit_test(trace_log_keeps_order_as_it_grows),
        cmocka_unit_test(trace_log_stops_at_its_cap_and_says_so),
    };
    return cmocka_run_group_tests_name("target", tests, NULL, NULL);
}
