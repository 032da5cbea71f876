/* test_time_limit.c: tools/time_limit, which make grade runs each test under,
 * reports a program's end as timeout(1) and the shell do. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <time.h>

#include "test_support.h"

static double seconds_since(const struct timespec *start)
{
    struct timespec now;
    clock_gettime(CLOCK_MONOTONIC, &now);
    return (double)(now.tv_sec - start->tv_sec) + (double)(now.tv_nsec - start->tv_nsec) / 1e9;
}

static void program_in_time_keeps_its_status_and_output(void **state)
{
    (void)state;
    const char *args[] = {"5", "sh", "-c", "echo out; echo err >&2; exit 7", NULL};
    RunResult r = run_tool("time_limit", args);
    assert_int_equal(r.status, 7);
    assert_string_equal(r.out, "out\n");
    assert_string_equal(r.err, "err\n");
    run_result_free(&r);
}

/* sleep 30 under a limit of 0.3 s: killed, 124, in well under the 30 s. */
static void program_out_of_time_is_killed_with_124(void **state)
{
    (void)state;
    struct timespec start;
    clock_gettime(CLOCK_MONOTONIC, &start);
    const char *args[] = {"0.3", "sleep", "30", NULL};
    RunResult r = run_tool("time_limit", args);
    double took = seconds_since(&start);
    assert_int_equal(r.status, 124);
    if (took > 5.0)
        fail_msg("time_limit 0.3 took %.1f s to stop sleep 30", took);
    run_result_free(&r);
}

/* A test that starts a lesson's executable: the whole process group goes.
 * The shell prints the process id of its background sleep; once time_limit
 * has returned, that process must be gone (allowing a moment for the system
 * to reap it). */
static void what_the_program_started_dies_with_it(void **state)
{
    (void)state;
    const char *args[] = {"0.3", "sh", "-c", "sleep 30 & echo $!; sleep 30", NULL};
    RunResult r = run_tool("time_limit", args);
    assert_int_equal(r.status, 124);
    long pid = strtol(r.out, NULL, 10);
    assert_true(pid > 1);
    struct timespec start;
    clock_gettime(CLOCK_MONOTONIC, &start);
    while (kill((pid_t)pid, 0) == 0) {
        if (seconds_since(&start) > 2.0)
            fail_msg("process %ld, started by the timed program, outlived time_limit", pid);
        struct timespec pause = {0, 10000000L};
        nanosleep(&pause, NULL);
    }
    run_result_free(&r);
}

/* kill -SEGV $$: the shell dies of signal 11, reported as 128 + 11. */
static void crash_is_128_plus_the_signal(void **state)
{
    (void)state;
    const char *args[] = {"5", "sh", "-c", "kill -SEGV $$", NULL};
    RunResult r = run_tool("time_limit", args);
    assert_int_equal(r.status, 128 + 11);
    run_result_free(&r);
}

static void missing_program_is_127(void **state)
{
    (void)state;
    const char *args[] = {"5", "no-such-program-here", NULL};
    RunResult r = run_tool("time_limit", args);
    assert_int_equal(r.status, 127);
    assert_non_null(strstr(r.err, "time_limit: error: cannot run no-such-program-here"));
    run_result_free(&r);
}

static void bad_limit_is_125_with_usage(void **state)
{
    (void)state;
    const char *const bad[] = {"0", "-1", "ten", "1e9", "nan", ""};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        const char *args[] = {bad[i], "true", NULL};
        RunResult r = run_tool("time_limit", args);
        if (r.status != 125 || !strstr(r.err, "time_limit: error: the time limit must be"))
            fail_msg("time_limit '%s' true: status %d, stderr %s", bad[i], r.status, r.err);
        run_result_free(&r);
    }
    const char *args[] = {"5", NULL};
    RunResult r = run_tool("time_limit", args);
    assert_int_equal(r.status, 125);
    assert_non_null(strstr(r.err, "usage: time_limit SECONDS PROGRAM"));
    run_result_free(&r);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(program_in_time_keeps_its_status_and_output),
        cmocka_unit_test(program_out_of_time_is_killed_with_124),
        cmocka_unit_test(what_the_program_started_dies_with_it),
        cmocka_unit_test(crash_is_128_plus_the_signal),
        cmocka_unit_test(missing_program_is_127),
        cmocka_unit_test(bad_limit_is_125_with_usage),
    };
    return cmocka_run_group_tests_name("tools: time_limit", tests, NULL, NULL);
}
