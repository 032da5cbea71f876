/* test_time_limit.c: tools/time_limit, which make grade runs each test under,
 * reports a program's end as timeout(1) and the shell do. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <time.h>

#include "test_support.h"

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

/* --cpu: a program that computes for ever is stopped by its CPU time (152,
 * 128 + SIGXCPU) long before the wall-clock limit; one that waits uses no
 * CPU and is stopped by the wall clock (124). --cpu-out says what it used. */
static void cpu_time_limit_stops_computing_not_waiting(void **state)
{
    (void)state;
    struct timespec start;
    clock_gettime(CLOCK_MONOTONIC, &start);
    const char *cpu_out = path_join(test_dir("time_limit_cpu"), "cpu.txt");
    const char *spin[] = {"--cpu", "1", "--cpu-out", cpu_out, "30", "sh", "-c",
                          "while :; do :; done", NULL};
    RunResult r = run_tool("time_limit", spin);
    assert_int_equal(r.status, 152);
    if (seconds_since(&start) > 20.0)
        fail_msg("a spinning program under --cpu 1 ran %.1f s", seconds_since(&start));
    run_result_free(&r);
    char *used = read_text(cpu_out);
    double seconds = strtod(used, NULL);
    free(used);
    /* About 1 s: not 0, not the 30 s of the wall clock. The kernel stops the
     * program by its own count of CPU time and getrusage reports another:
     * on a loaded virtual machine (make test with three jobs on two cores)
     * they were seen 12% apart, 0.885 s. */
    if (!(seconds >= 0.5 && seconds < 3.0))
        fail_msg("--cpu-out says %.3f s for a program stopped at 1 s of CPU time", seconds);

    const char *sleep_args[] = {"--cpu", "1", "0.5", "sleep", "30", NULL};
    r = run_tool("time_limit", sleep_args);
    assert_int_equal(r.status, 124);
    run_result_free(&r);
}

/* --output: stdout and stderr in a file, at most the bytes asked, with a note
 * of how much more came; and a process left behind holding the pipe does
 * not keep time_limit waiting. */
static void output_is_kept_to_its_cap(void **state)
{
    (void)state;
    const char *log = path_join(test_dir("time_limit_output"), "log.txt");
    const char *args[] = {"--output", log, "--output-max", "100", "10", "sh", "-c",
                          "echo first; echo second >&2; yes 0123456789 | head -c 1000000; exit 3",
                          NULL};
    RunResult r = run_tool("time_limit", args);
    assert_int_equal(r.status, 3);
    run_result_free(&r);
    char *text = read_text(log);
    if (strncmp(text, "first\nsecond\n", 13) != 0 ||
        !strstr(text, "\n[... 999913 more bytes of output: cut at 100 bytes]\n"))
        fail_msg("the capped output is:\n%s", text);
    free(text);

    struct timespec start;
    clock_gettime(CLOCK_MONOTONIC, &start);
    const char *escape[] = {"--output", log, "10", "sh", "-c",
                            "setsid sh -c 'sleep 5; echo late' & echo now", NULL};
    r = run_tool("time_limit", escape);
    assert_int_equal(r.status, 0);
    if (seconds_since(&start) > 3.0)
        fail_msg("time_limit waited %.1f s for a process that holds its pipe",
                 seconds_since(&start));
    run_result_free(&r);
    text = read_text(log);
    assert_string_equal(text, "now\n");
    free(text);
}

/* Output that cannot be written (/dev/full) is lost: time_limit says so in
 * one line, status 125, instead of passing the program's 0 on. */
static void output_that_cannot_be_written_is_125(void **state)
{
    (void)state;
    const char *args[] = {"--output", "/dev/full", "10", "sh", "-c", "echo hello", NULL};
    RunResult r = run_tool("time_limit", args);
    if (r.status != 125 ||
        strcmp(r.err, "time_limit: error: cannot write /dev/full: No space left on device\n"))
        fail_msg("status %d, wanted 125 and one line:\n%s", r.status, r.err);
    run_result_free(&r);
}

/* --cpu-out that cannot be written: said before the program runs, with the
 * reason (it was said after the run, without one, the program's own status
 * lost); one that can be written gets the seconds. */
static void cpu_out_that_cannot_be_written_is_refused_before_the_run(void **state)
{
    (void)state;
    const char *dir = test_dir("time_limit_cpu_out");
    char ran[512], script[600], expected[700];
    snprintf(ran, sizeof ran, "%s", path_join(dir, "ran"));
    snprintf(script, sizeof script, "touch '%s'", ran);
    const char *args[] = {"--cpu-out", dir, "10", "sh", "-c", script, NULL};
    RunResult r = run_tool("time_limit", args);
    snprintf(expected, sizeof expected, "time_limit: error: cannot write %s: Is a directory\n", dir);
    if (r.status != 125 || strcmp(r.err, expected) != 0)
        fail_msg("status %d, wanted 125 and \"%s\":\n%s", r.status, expected, r.err);
    run_result_free(&r);
    if (file_exists(ran))
        fail_msg("the program ran, though its --cpu-out could not be written");
    char cpu[512];
    snprintf(cpu, sizeof cpu, "%s", path_join(dir, "cpu.txt"));
    const char *good[] = {"--cpu-out", cpu, "10", "sh", "-c", "exit 3", NULL};
    r = run_tool("time_limit", good);
    assert_int_equal(r.status, 3);
    run_result_free(&r);
    char *text = read_text(cpu);
    double seconds = -1;
    if (sscanf(text, "%lf", &seconds) != 1 || seconds < 0)
        fail_msg("--cpu-out wrote \"%s\"", text);
    free(text);
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
    assert_non_null(strstr(r.err, "usage: time_limit [--cpu CPU_SECONDS]"));
    run_result_free(&r);
    const char *const bad_options[][3] = {{"--cpu", "0", "--cpu wants a number of seconds"},
                                         {"--output-max", "0", "--output-max wants a number"},
                                         {"--frobnicate", "1", "unknown option"}};
    for (size_t i = 0; i < sizeof bad_options / sizeof bad_options[0]; i++) {
        const char *opt_args[] = {bad_options[i][0], bad_options[i][1], "5", "true", NULL};
        r = run_tool("time_limit", opt_args);
        if (r.status != 125 || !strstr(r.err, bad_options[i][2]))
            fail_msg("time_limit %s %s: status %d, stderr %s", bad_options[i][0],
                     bad_options[i][1], r.status, r.err);
        run_result_free(&r);
    }
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
        cmocka_unit_test(cpu_time_limit_stops_computing_not_waiting),
        cmocka_unit_test(output_is_kept_to_its_cap),
        cmocka_unit_test(output_that_cannot_be_written_is_125),
        cmocka_unit_test(cpu_out_that_cannot_be_written_is_refused_before_the_run),
    };
    return cmocka_run_group_tests_name("tools: time_limit", tests, NULL, NULL);
}
