/* test_run_tests.c: tools/run-tests.sh, the runner of make test, on made-up
 * test programs (shell scripts that print what cmocka prints).
 *
 *   - The counts: "N passed, M failed" over every program, the exit status
 *     0 only when all passed; a program that exits non-zero without a
 *     cmocka failure, or cannot be run, is a failure of its own.
 *   - The logs whole and in the order of the command line, whatever order
 *     the programs end in.
 *   - The scratch, $TEST_OUTPUT/tmp: a link into a directory of its own
 *     under TEST_SCRATCH while the tests run (the programs see it, and see
 *     TEST_SCRATCH empty: a make test they run keeps its scratch where it
 *     is); removed after a run whose tests all passed and after an
 *     interrupted one, kept after a failure until the next run, which
 *     removes it, or `run-tests.sh --remove-scratch` (make clean); a link
 *     someone else made is never followed. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "shell.h"
#include "test_support.h"

#define TIMEOUT_SECONDS 60

/* A test program: a script in dir that runs body. */
static const char *program(const char *dir, const char *name, const char *body)
{
    char text[8192];
    snprintf(text, sizeof text, "#!/bin/sh\n%s\n", body);
    return write_program_in(dir, name, text);
}

/* run-tests.sh on the programs (a space-separated list of paths), from the
 * top of the tree as make test runs it, with TEST_OUTPUT dir/out and
 * TEST_SCRATCH dir/scratch; env: more of the environment, or "". */
static ShellResult run_runner(const char *dir, const char *env, const char *programs)
{
    return run_shell(NULL, TIMEOUT_SECONDS,
                     "mkdir -p %s/scratch && %s TEST_OUTPUT=%s/out TEST_SCRATCH=$PWD/%s/scratch "
                     "TEST_JOBS=2 sh tools/run-tests.sh %s",
                     dir, env, dir, dir, programs);
}

/* How many directories scratch/ holds. */
static int scratches(const char *dir)
{
    DIR *d = opendir(path_join(dir, "scratch"));
    assert_non_null(d);
    int n = 0;
    for (struct dirent *e; (e = readdir(d)) != NULL;)
        n += strncmp(e->d_name, "hsr-tests.", 10) == 0;
    closedir(d);
    return n;
}

static bool is_link(const char *path)
{
    struct stat st;
    return lstat(path, &st) == 0 && S_ISLNK(st.st_mode);
}

static void counts_and_order(void **state)
{
    (void)state;
    const char *dir = test_dir("run_tests_counts");
    char list[4096];
    snprintf(list, sizeof list, "%s %s %s %s",
             program(dir, "slow", "sleep 0.3; echo 'slow log'; echo '[  PASSED  ] 2 test(s).'"),
             program(dir, "fails", "echo 'fails log'; echo '[  FAILED  ] 1 test(s), listed below:'; "
                                   "echo '[  PASSED  ] 3 test(s).'; exit 1"),
             program(dir, "crashes", "echo 'crashes log'; exit 3"), path_join(dir, "missing"));
    ShellResult r = run_runner(dir, "", list);
    expect_count(1, r.status, "run-tests.sh with a failure: exit status");
    const char *slow = strstr(r.output, "slow log"), *fails = strstr(r.output, "fails log"),
               *crashes = strstr(r.output, "crashes log");
    if (!slow || !fails || !crashes || !(slow < fails && fails < crashes))
        fail_msg("the logs are not whole and in the command line's order:\n%s", r.output);
    if (!strstr(r.output, "\n5 passed, 3 failed\n"))
        fail_msg("want \"5 passed, 3 failed\" (a failed test, a crash, a missing program):\n%s",
                 r.output);
    if (!strstr(r.output, "crashes(exit 3)") || !strstr(r.output, "missing(exit 127)"))
        fail_msg("the broken programs are not named with their status:\n%s", r.output);
    shell_result_free(&r);

    r = run_runner(dir, "", path_join(dir, "slow"));
    expect_count(0, r.status, "run-tests.sh with every test passed: exit status");
    if (!strstr(r.output, "\n2 passed, 0 failed\n"))
        fail_msg("want \"2 passed, 0 failed\":\n%s", r.output);
    shell_result_free(&r);
}

static void scratch_is_a_link_removed_after_a_pass_kept_after_a_failure(void **state)
{
    (void)state;
    const char *dir = test_dir("run_tests_scratch");
    /* Writes into the scratch and says what it sees. */
    const char *writes = program(
        dir, "writes",
        "mkdir -p \"$TEST_OUTPUT/tmp/mine\" && echo kept >\"$TEST_OUTPUT/tmp/mine/file\" || exit 1\n"
        "case $(readlink \"$TEST_OUTPUT/tmp\") in /*/scratch/hsr-tests.*) echo 'in the scratch' ;; esac\n"
        "echo \"TEST_SCRATCH=[$TEST_SCRATCH]\"\n"
        "if [ -n \"$FAIL\" ]; then echo '[  FAILED  ] 1 test(s), listed below:'; exit 1; fi\n"
        "echo '[  PASSED  ] 1 test(s).'");
    ShellResult r = run_runner(dir, "", writes);
    expect_count(0, r.status, "a passing run: exit status");
    bool linked = strstr(r.output, "in the scratch") != NULL;
    if (!linked) { /* a machine whose file systems are full: the scratch stays on disk */
        print_message("skipped: no room for the scratch (2 GB) here:\n%s", r.output);
        shell_result_free(&r);
        skip();
    }
    if (!strstr(r.output, "TEST_SCRATCH=[]"))
        fail_msg("a test program should see TEST_SCRATCH empty:\n%s", r.output);
    if (scratches(dir) != 0 || access(path_join(dir, "out/tmp"), F_OK) == 0 ||
        is_link(path_join(dir, "out/tmp")))
        fail_msg("after a passing run, the scratch and its link should be gone");
    shell_result_free(&r);

    r = run_runner(dir, "FAIL=1", writes);
    expect_count(1, r.status, "a failing run: exit status");
    if (!strstr(r.output, "scratch is kept in") || scratches(dir) != 1 ||
        !is_link(path_join(dir, "out/tmp")))
        fail_msg("after a failing run, the scratch should be kept, with its link, and said:\n%s",
                 r.output);
    char *kept = read_text(path_join(dir, "out/tmp/mine/file"));
    assert_string_equal("kept\n", kept);
    free(kept);
    shell_result_free(&r);

    r = run_runner(dir, "", writes);
    expect_count(0, r.status, "the run after: exit status");
    expect_count(0, scratches(dir), "scratches left after the run that follows a failure");
    shell_result_free(&r);

    /* Kept again, then removed by --remove-scratch, as make clean asks. */
    r = run_runner(dir, "FAIL=1", writes);
    expect_count(1, scratches(dir), "scratches kept after a failure");
    shell_result_free(&r);
    r = run_shell(NULL, TIMEOUT_SECONDS,
                  "TEST_OUTPUT=%s/out sh tools/run-tests.sh --remove-scratch", dir);
    expect_count(0, r.status, "run-tests.sh --remove-scratch: exit status");
    expect_count(0, scratches(dir), "scratches left after --remove-scratch");
    if (is_link(path_join(dir, "out/tmp")))
        fail_msg("--remove-scratch left the link out/tmp");
    shell_result_free(&r);

    /* Stopped (SIGTERM) while a test runs: the scratch goes too. */
    char started[4096];
    snprintf(started, sizeof started, "%s", path_join(dir, "started"));
    char body[4096 + 64];
    snprintf(body, sizeof body, "touch %s; sleep 2; echo '[  PASSED  ] 1 test(s).'", started);
    const char *waits = program(dir, "waits", body);
    r = run_shell(NULL, TIMEOUT_SECONDS,
                  "mkdir -p %s/scratch && { TEST_OUTPUT=%s/out TEST_SCRATCH=$PWD/%s/scratch "
                  "sh tools/run-tests.sh %s & } && runner=$! && "
                  "while [ ! -f %s ]; do sleep 0.05; done && kill -TERM $runner; wait $runner",
                  dir, dir, dir, waits, started);
    expect_count(143, r.status, "run-tests.sh stopped by SIGTERM: exit status");
    expect_count(0, scratches(dir), "scratches left after a run stopped by SIGTERM");
    shell_result_free(&r);
}

static void a_link_someone_else_made_is_not_followed(void **state)
{
    (void)state;
    const char *dir = test_dir("run_tests_foreign");
    const char *passes = program(dir, "passes", "echo '[  PASSED  ] 1 test(s).'");
    ShellResult r = run_shell(dir, TIMEOUT_SECONDS,
                              "mkdir -p theirs out && echo theirs >theirs/file && "
                              "ln -s \"$PWD/theirs\" out/tmp");
    expect_count(0, r.status, "mkdir, ln -s");
    shell_result_free(&r);
    r = run_runner(dir, "", passes);
    expect_count(0, r.status, "run-tests.sh: exit status");
    shell_result_free(&r);
    char *text = read_text(path_join(dir, "theirs/file"));
    assert_string_equal("theirs\n", text);
    free(text);
}

/* A run in which no test ran (TEST= naming none, no program at all) fails,
 * and says why: it said only "0 passed, 0 failed". */
static void a_run_of_no_test_says_so(void **state)
{
    (void)state;
    const char *dir = test_dir("run_tests_none");
    const char *none = program(dir, "none", "echo '[  PASSED  ] 0 test(s).'");
    ShellResult r = run_runner(dir, "TEST_FILTER=nosuch", none);
    expect_count(1, r.status, "run-tests.sh, no test named nosuch: exit status");
    if (!strstr(r.output, "run-tests: error: no test is named 'nosuch' (TEST= takes a test's name; "
                          "* and ? work)\n0 passed, 0 failed\n"))
        fail_msg("want the error line before \"0 passed, 0 failed\":\n%s", r.output);
    shell_result_free(&r);
    r = run_runner(dir, "", "");
    expect_count(1, r.status, "run-tests.sh, no program: exit status");
    if (!strstr(r.output, "run-tests: error: no test program to run\n"))
        fail_msg("want \"no test program to run\":\n%s", r.output);
    shell_result_free(&r);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(counts_and_order),
        cmocka_unit_test(a_run_of_no_test_says_so),
        cmocka_unit_test(scratch_is_a_link_removed_after_a_pass_kept_after_a_failure),
        cmocka_unit_test(a_link_someone_else_made_is_not_followed),
    };
    return cmocka_run_group_tests_name("tools: run-tests.sh, the runner of make test", tests,
                                       NULL, NULL);
}
