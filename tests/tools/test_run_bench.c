/* test_run_bench.c: tests/bench/run-bench.sh, what `make bench` runs, with
 * stand-in programs that print a CSV line of tests/bench/measure.h each time
 * they run, their median going down or up from one round to the next.
 *
 * Each program runs BENCH_ROUNDS times (3 unless set), and each row is its
 * round with the least median: here the second round's, not the first's or
 * the last's. Rounds that leave different depth buffers (another checksum)
 * fail the run, naming the row; a BENCH_ROUNDS out of 1 to 9 is refused.
 * With lesson 10's program and more than one core, its one-thread row is
 * timed alone and in one copy per core at once, by the wall clock, and the
 * ceiling that leaves for threads is printed: the highest of a round, its
 * copies taken together. BENCH_AS=avx2 or sse hands
 * each program the instructions of a lesser x86-64 (FAST_RASTER_SIMD for
 * lesson 10, GALLIUM_OVERRIDE_CPU_CAPS for llvmpipe), and says so.
 * BENCH_BUSY=1 runs a loop beside every program, and none is left after.
 * The machine line says how many threads each core runs (lscpu); each
 * round's round trip between two threads is printed, not a row. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "shell.h"
#include "test_support.h"

#define TIMEOUT 60

/* A stand-in program at dir/name: its nth run prints a line of lesson name,
 * workload small, median medians[n - 1] (then the last of them), and a depth
 * checksum that is "same" each time or, when changing, the run's number. */
static const char *stand_in(const char *dir, const char *name, const char *medians, bool changing)
{
    char text[1024];
    snprintf(text, sizeof text,
             "#!/bin/sh\n"
             "n=$(cat \"$0.n\" 2>/dev/null || echo 0); n=$((n + 1)); echo $n >\"$0.n\"\n"
             "set -- %s; shift $((n <= $# ? n - 1 : $# - 1)); m=$1\n"
             "echo \"%s,small,8,8,11,100,1000,$m,$m,$m,%s\"\n",
             medians, name, changing ? "sum$n" : "same");
    return write_program_in(dir, name, text);
}

/* N of the machine line's "machine: ..., N CPUs"; fails without. */
static int machine_cpus(const char *output)
{
    const char *at = strstr(output, " CPUs"), *digits = at;
    while (digits && digits > output && digits[-1] >= '0' && digits[-1] <= '9')
        digits--;
    int cpus = 0;
    if (!at || digits == at || sscanf(digits, "%d", &cpus) != 1)
        fail_msg("no CPU count on the machine line:\n%s", output);
    return cpus;
}

/* run-bench.sh OUT LIMIT LESSON, with BENCH_ROUNDS=rounds (NULL: unset). */
static ShellResult run_bench(const char *dir, const char *rounds, const char *limit,
                             const char *lesson)
{
    return run_shell(NULL, TIMEOUT, "%s%s sh tests/bench/run-bench.sh %s/out %s %s",
                     rounds ? "BENCH_ROUNDS=" : "", rounds ? rounds : "", dir, limit, lesson);
}

static void each_row_is_its_round_with_the_least_median(void **state)
{
    (void)state;
    const char *dir = test_dir("run_bench_rounds");
    const char *limit = stand_in(dir, "limit", "0.001", false);
    const char *lesson = stand_in(dir, "lesson", "0.030 0.010 0.020", false);
    ShellResult r = run_bench(dir, NULL, limit, lesson);
    if (r.status != 0)
        fail_msg("run-bench.sh: status %d\n%s", r.status, r.output);
    expect_line(r.output, "running lesson, round 3 of 3 ...");
    if (!strstr(r.output, "each row: the best of 3 rounds"))
        fail_msg("the table does not say it is the best of 3 rounds:\n%s", r.output);
    char *csv = read_text(path_join(dir, "out/results.csv"));
    if (!strstr(csv, "\nlesson,small,8,8,11,100,1000,0.010,0.010,0.010,"))
        fail_msg("results.csv has not the second round's median, 0.010:\n%s", csv);
    if (strstr(csv, "0.030") || strstr(csv, "0.020"))
        fail_msg("results.csv keeps another round than the best:\n%s", csv);
    char *runs = read_text(path_join(dir, "lesson.n"));
    assert_string_equal(runs, "3\n"); /* three rounds, each program once a round */
    free(runs);
    free(csv);
    shell_result_free(&r);
}

static void rounds_that_leave_other_depth_buffers_fail_the_run(void **state)
{
    (void)state;
    const char *dir = test_dir("run_bench_checksums");
    const char *limit = stand_in(dir, "limit", "0.001", false);
    const char *lesson = stand_in(dir, "lesson", "0.030 0.010 0.020", true);
    ShellResult r = run_bench(dir, "2", limit, lesson);
    assert_int_not_equal(r.status, 0);
    if (!strstr(r.output, "run-bench.sh: lesson,small: rounds left different depth buffers"))
        fail_msg("no message naming the row:\n%s", r.output);
    shell_result_free(&r);
}

/* Lesson 10's stand-in: its row of small (0.030 s) each round; asked for its
 * first configuration of fill_back_to_front by the wall clock, a row whose
 * median is 0.010 s the first time (round 1, alone), 0.040 s the time after
 * the first round's copies (round 2, alone), 0.020 s else (a slot taken by
 * mkdir, as the copies run at once). Round 2 is the round whose copies drew
 * the most, 2 times one's frames each; round 1's alone, the faster, with any
 * round's copies would make it 0.5. */
static const char *lesson_10_stand_in(const char *dir)
{
    return write_program_in(
        dir, "bench_10_fast_raster",
        "#!/bin/sh\n"
        "if [ \"${BENCH_CONFIG-}:${BENCH_WALL_CLOCK-}:$*\" != 0:1:fill_back_to_front ]; then\n"
        "    echo 10_fast_raster_1t,small,8,8,11,100,1000,0.030,0.030,0.030,same; exit 0\n"
        "fi\n"
        "i=0; while ! mkdir \"$0.slot$i\" 2>/dev/null; do i=$((i + 1)); done\n"
        "m=0.020; [ $i = 0 ] && m=0.010; [ $i = $(($(nproc) + 1)) ] && m=0.040\n"
        "echo \"10_fast_raster_1t,fill_back_to_front,8,8,11,2,1000,$m,$m,$m,same\"\n");
}

static void the_cores_side_by_side_give_the_ceiling_for_threads(void **state)
{
    (void)state;
    const char *dir = test_dir("run_bench_cores");
    const char *limit = stand_in(dir, "limit", "0.001", false);
    const char *lesson = lesson_10_stand_in(dir);
    ShellResult r = run_bench(dir, "2", limit, lesson);
    if (r.status != 0)
        fail_msg("run-bench.sh: status %d\n%s", r.status, r.output);
    int cpus = machine_cpus(r.output);
    char want[160];
    snprintf(want, sizeof want, "%d copies of 10_fast_raster_1t on fill_back_to_front at once\n"
             "    drew %.2f times the frames of one alone (20.00 ms a frame at the slowest, 40.00 alone)",
             cpus, cpus * 2.0);
    if (cpus > 1 && !strstr(r.output, want))
        fail_msg("not '%s' (round 2: alone 0.040 s, each copy 0.020 s):\n%s", want, r.output);
    if (cpus == 1 && strstr(r.output, "side by side"))
        fail_msg("one core, yet the cores side by side:\n%s", r.output);
    char *csv = read_text(path_join(dir, "out/results.csv"));
    if (strstr(csv, "cores_"))
        fail_msg("results.csv has the cores' rows:\n%s", csv);
    free(csv);
    shell_result_free(&r);
}

/* bench_round_trip's stand-in: 100 ns its first run, 400 its second, 95 after. */
static void each_round_gives_its_round_trip(void **state)
{
    (void)state;
    const char *dir = test_dir("run_bench_round_trip");
    const char *limit = stand_in(dir, "limit", "0.001", false);
    const char *trip = write_program_in(
        dir, "bench_round_trip",
        "#!/bin/sh\n"
        "n=$(cat \"$0.n\" 2>/dev/null || echo 0); n=$((n + 1)); echo $n >\"$0.n\"\n"
        "set -- 0.000000100 0.000000400 0.000000095; shift $((n <= 3 ? n - 1 : 2))\n"
        "echo \"round_trip,cores,0,0,11,0,0,$1,$1,$1,0\"\n");
    ShellResult r = run_bench(dir, NULL, limit, trip);
    if (r.status != 0)
        fail_msg("run-bench.sh: status %d\n%s", r.status, r.output);
    int cpus = machine_cpus(r.output);
    const char *want = "the round trip of a cache line from one thread to the other and back: "
                       "100, 400, 95 ns";
    if (cpus > 1 && !strstr(r.output, want))
        fail_msg("not '%s':\n%s", want, r.output);
    if (cpus == 1 && strstr(r.output, "round trip"))
        fail_msg("one core, yet a round trip:\n%s", r.output);
    if (strstr(r.output, "\nround_trip"))
        fail_msg("the round trip is a row of the table:\n%s", r.output);
    char *csv = read_text(path_join(dir, "out/results.csv"));
    if (strstr(csv, "round_trip"))
        fail_msg("results.csv has the round trip's rows:\n%s", csv);
    free(csv);
    shell_result_free(&r);
}

/* The machine line names the CPU and how many threads each core runs, as
 * lscpu says (here a stand-in first on PATH); without that line, nothing. */
static void the_machine_line_says_how_many_threads_a_core_runs(void **state)
{
    (void)state;
    const char *dir = test_dir("run_bench_machine");
    const char *limit = stand_in(dir, "limit", "0.001", false);
    const char *lesson = stand_in(dir, "lesson", "0.010", false);
    const char *says[] = {"Thread(s) per core:   2", "Thread(s) per core:   1", ""};
    const char *want[] = {" CPUs (2 threads per core); compiler", " CPUs (1 thread per core); compiler",
                          " CPUs; compiler"};
    for (size_t k = 0; k < sizeof says / sizeof says[0]; k++) {
        char text[256];
        snprintf(text, sizeof text, "#!/bin/sh\nprintf 'Model name:            Test CPU 9000\\n%s\\n'\n",
                 says[k]);
        write_program_in(dir, "lscpu", text);
        ShellResult r = run_shell(NULL, TIMEOUT, "PATH=%s:$PATH BENCH_ROUNDS=1 sh tests/bench/run-bench.sh "
                                  "%s/out %s %s", dir, dir, limit, lesson);
        if (r.status != 0)
            fail_msg("run-bench.sh: status %d\n%s", r.status, r.output);
        if (!strstr(r.output, "machine: Test CPU 9000, ") || !strstr(r.output, want[k]))
            fail_msg("lscpu says '%s', and the machine line has not 'Test CPU 9000' and '%s':\n%s",
                     says[k], want[k], r.output);
        shell_result_free(&r);
    }
}

static void rounds_out_of_range_are_refused(void **state)
{
    (void)state;
    const char *dir = test_dir("run_bench_refused");
    const char *limit = stand_in(dir, "limit", "0.001", false);
    const char *lesson = stand_in(dir, "lesson", "0.010", false);
    const char *bad[] = {"0", "10", "three"};
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        ShellResult r = run_bench(dir, bad[k], limit, lesson);
        assert_int_equal(r.status, 2);
        char want[96];
        snprintf(want, sizeof want, "run-bench.sh: BENCH_ROUNDS: '%s' is not 1 to 9", bad[k]);
        expect_line(r.output, want);
        shell_result_free(&r);
    }
    assert_false(file_exists(path_join(dir, "lesson.n"))); /* refused before any run */
}

/* A stand-in that writes the instructions it was handed into dir/name.env. */
static const char *env_stand_in(const char *dir, const char *name)
{
    char text[512];
    snprintf(text, sizeof text,
             "#!/bin/sh\n"
             "echo \"${FAST_RASTER_SIMD-unset} ${GALLIUM_OVERRIDE_CPU_CAPS-unset}\" >\"$0.env\"\n"
             "echo \"%s,small,8,8,11,100,1000,0.010,0.010,0.010,same\"\n",
             name);
    return write_program_in(dir, name, text);
}

static void bench_as_hands_both_the_instructions_of_a_lesser_x86_64(void **state)
{
    (void)state;
    const char *dir = test_dir("run_bench_as");
    const char *limit = stand_in(dir, "limit", "0.001", false);
    const char *lesson = env_stand_in(dir, "lesson");
    const struct { const char *as, *env, *said; } tiers[] = {
        {"sse", "sse2 sse4.1\n", "as an x86-64 without AVX (BENCH_AS=sse):"},
        {"avx2", "avx2 avx\n", "as an x86-64 with AVX2, without AVX-512 (BENCH_AS=avx2):"},
    };
    for (size_t k = 0; k < sizeof tiers / sizeof tiers[0]; k++) {
        ShellResult r = run_shell(NULL, TIMEOUT, "BENCH_AS=%s BENCH_ROUNDS=1 sh tests/bench/run-bench.sh "
                                  "%s/out %s %s", tiers[k].as, dir, limit, lesson);
        if (r.status != 0)
            fail_msg("BENCH_AS=%s: status %d\n%s", tiers[k].as, r.status, r.output);
        expect_line(r.output, tiers[k].said);
        char *env = read_text(path_join(dir, "lesson.env"));
        assert_string_equal(env, tiers[k].env);
        free(env);
        shell_result_free(&r);
    }
    ShellResult r = run_shell(NULL, TIMEOUT, "BENCH_ROUNDS=1 FAST_RASTER_SIMD= GALLIUM_OVERRIDE_CPU_CAPS= "
                              "sh tests/bench/run-bench.sh %s/out %s %s", dir, limit, lesson);
    assert_int_equal(r.status, 0);
    expect_line(r.output, "instructions: lesson 10's kernels the widest the CPU has; llvmpipe all the "
                          "CPU has");
    shell_result_free(&r);
    r = run_shell(NULL, TIMEOUT, "BENCH_AS=avx512 sh tests/bench/run-bench.sh %s/out %s %s", dir,
                  limit, lesson);
    assert_int_equal(r.status, 2);
    expect_line(r.output, "run-bench.sh: BENCH_AS: 'avx512' is not avx2 or sse");
    shell_result_free(&r);
}

/* How many of run-bench.sh's busy loops run (their $0 is run-bench-busy). */
#define COUNT_LOOPS "grep -l 'run-bench-bus[y]' /proc/[0-9]*/cmdline 2>/dev/null | wc -l"

static void bench_busy_runs_a_loop_beside_every_program(void **state)
{
    (void)state;
    const char *dir = test_dir("run_bench_busy");
    Path limit = in_dir(dir, "limit"), lesson = in_dir(dir, "lesson"), loops = in_dir(dir, "lesson.loops");
    stand_in(dir, "limit", "0.001", false);
    write_program_in(dir, "lesson",
                     "#!/bin/sh\n"
                     COUNT_LOOPS " >>\"$0.loops\"\n"
                     "echo \"lesson,small,8,8,11,100,1000,0.010,0.010,0.010,same\"\n");
    const struct { const char *busy, *each_run, *said; } runs[] = {
        {"BENCH_BUSY=1", "1\n1\n", "busy: a loop runs beside every program (BENCH_BUSY=1), as other work "
                                   "on a shared machine"},
        {"BENCH_BUSY=0", "0\n0\n", NULL},
        {"", "0\n0\n", NULL},
    };
    for (size_t k = 0; k < sizeof runs / sizeof runs[0]; k++) {
        remove(loops.path);
        ShellResult r = run_shell(NULL, TIMEOUT, "%s BENCH_ROUNDS=2 sh tests/bench/run-bench.sh %s/out %s %s",
                                  runs[k].busy, dir, limit.path, lesson.path);
        if (r.status != 0)
            fail_msg("%s: status %d\n%s", runs[k].busy, r.status, r.output);
        if (runs[k].said)
            expect_line(r.output, runs[k].said);
        else if (strstr(r.output, "busy:"))
            fail_msg("'%s': a loop said to run:\n%s", runs[k].busy, r.output);
        char *seen = read_text(loops.path);
        if (strcmp(seen, runs[k].each_run) != 0)
            fail_msg("'%s': loops seen by the lesson's two rounds: '%s', not '%s'", runs[k].busy,
                     seen, runs[k].each_run);
        free(seen);
        shell_result_free(&r);
        r = run_shell(NULL, TIMEOUT, COUNT_LOOPS);
        if (strcmp(r.output, "0\n") != 0)
            fail_msg("'%s': loops left after the run: %s", runs[k].busy, r.output);
        shell_result_free(&r);
    }
    ShellResult r = run_shell(NULL, TIMEOUT, "BENCH_BUSY=2 sh tests/bench/run-bench.sh %s/out %s %s", dir,
                              limit.path, lesson.path);
    assert_int_equal(r.status, 2);
    expect_line(r.output, "run-bench.sh: BENCH_BUSY: '2' is not 0 or 1");
    shell_result_free(&r);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(each_row_is_its_round_with_the_least_median),
        cmocka_unit_test(rounds_that_leave_other_depth_buffers_fail_the_run),
        cmocka_unit_test(rounds_out_of_range_are_refused),
        cmocka_unit_test(the_cores_side_by_side_give_the_ceiling_for_threads),
        cmocka_unit_test(the_machine_line_says_how_many_threads_a_core_runs),
        cmocka_unit_test(each_round_gives_its_round_trip),
        cmocka_unit_test(bench_as_hands_both_the_instructions_of_a_lesser_x86_64),
        cmocka_unit_test(bench_busy_runs_a_loop_beside_every_program),
    };
    return cmocka_run_group_tests_name("tools: make bench's rounds (run-bench.sh)", tests, NULL,
                                       NULL);
}
