/* test_hooks.c: what every test binary does before its main() starts, and
 * around cmocka's run of its tests.
 *
 * - TEST_FILTER=name in the environment runs only the tests of that name
 *   (cmocka's * and ? wildcards work). make grade runs each test alone this
 *   way, so that one broken test costs only its own points.
 * - stdout is unbuffered: cmocka prints a test's name and result on stdout and
 *   its failure messages on stderr. When both go to one log (make test, make
 *   grade), each message then lands under the test that printed it. Observed
 *   for a grade (observe.h), stdout and stderr are written in blocks instead:
 *   a student's debug print per fragment then costs little.
 * - UPDATE_EXPECTED: while grading it is ignored altogether, whatever the
 *   code under test sets (test_update_expected()).
 *
 * Grading without a reference (tools/grade.sh, docs/teaching.md "Who
 * decides that a test passed"): the student's own feedback. (With a
 * reference, GRADE_OBSERVE_FD=n records what each check saw, observe.h, and
 * a judge decides.) The grader does not read what a test prints to decide
 * whether it passed: the process runs the student's code, which can print anything. It
 * gives the test program two files instead, GRADE_NONCE_FILE (a random
 * number, fresh for each run) and GRADE_RESULT_FILE. Before main() this file
 * reads the number, deletes its file and takes both names out of the
 * environment, and opens the result file. cmocka's run of the tests is
 * wrapped (the link's --wrap=_cmocka_run_group_tests): only when cmocka has
 * returned, having run exactly the one test TEST_FILTER names, is
 * "<number> passed <name>" or "<number> failed <name>" written there. A test
 * that ends the process (exit, _exit, a crash, a hang) writes nothing; lines
 * printed to look like cmocka's are only text in the log.
 * - GRADE_LIST=1: the program prints the names of its tests, one a line
 *   after "GRADE_LIST ", and runs none of them (how the grader learns which
 *   program has which test). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <fcntl.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "test_support.h"

#define NONCE_MAX 128

static char nonce[NONCE_MAX];
static int result_fd = -1;
static bool update_expected_asked;
static bool grading;

bool test_update_expected(void)
{
    if (grading)
        return false;
    const char *update = getenv("UPDATE_EXPECTED"); /* (a test of expect_image sets it) */
    return update_expected_asked || (update && strcmp(update, "1") == 0);
}

bool test_grading(void)
{
    return grading;
}

/* The nonce from its file, which is then removed. */
static void read_nonce(const char *path)
{
    FILE *f = fopen(path, "r");
    if (!f)
        return;
    if (!fgets(nonce, sizeof nonce, f))
        nonce[0] = '\0';
    fclose(f);
    remove(path);
    nonce[strcspn(nonce, "\r\n")] = '\0';
}

/* A constructor rather than a call in every test's main(): the tests stay as
 * they are, and a new test binary gets the same behaviour for free. */
__attribute__((constructor)) static void before_main(void)
{
    const char *filter = getenv("TEST_FILTER");
    if (filter && *filter)
        cmocka_set_test_filter(filter);

    const char *update = getenv("UPDATE_EXPECTED");
    update_expected_asked = update && strcmp(update, "1") == 0;
    const char *nonce_file = getenv("GRADE_NONCE_FILE");
    const char *result_file = getenv("GRADE_RESULT_FILE");
    if (nonce_file && *nonce_file) {
        grading = true; /* never an update of the expected images while grading */
        read_nonce(nonce_file);
        if (result_file && *result_file)
            result_fd = open(result_file, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
    }
    unsetenv("GRADE_NONCE_FILE");
    unsetenv("GRADE_RESULT_FILE");
    /* GRADE_OBSERVE_FD=n: write what each check compares to n (observe.h). */
    const char *observe_fd = getenv("GRADE_OBSERVE_FD");
    if (observe_fd && *observe_fd) {
        char *end;
        long fd = strtol(observe_fd, &end, 10);
        if (*end == '\0' && fd > 2 && fd < 1024) {
            grading = true;
            observe_start((int)fd);
        }
    }
    unsetenv("GRADE_OBSERVE_FD");
    /* Unbuffered, so that each message lands under its test in a log of
     * stdout and stderr together; observed for a grade, in blocks, so that a
     * debug print per fragment costs little. */
    if (observing()) {
        setvbuf(stdout, NULL, _IOFBF, 1 << 16);
        setvbuf(stderr, NULL, _IOFBF, 1 << 16);
    } else {
        setvbuf(stdout, NULL, _IONBF, 0);
    }
    if (grading)
        unsetenv("UPDATE_EXPECTED");
}

int __real__cmocka_run_group_tests(const char *group_name, const struct CMUnitTest *const tests,
                                   const size_t num_tests, CMFixtureFunction group_setup,
                                   CMFixtureFunction group_teardown);
int __wrap__cmocka_run_group_tests(const char *group_name, const struct CMUnitTest *const tests,
                                   const size_t num_tests, CMFixtureFunction group_setup,
                                   CMFixtureFunction group_teardown);

int __wrap__cmocka_run_group_tests(const char *group_name, const struct CMUnitTest *const tests,
                                   const size_t num_tests, CMFixtureFunction group_setup,
                                   CMFixtureFunction group_teardown)
{
    const char *list = getenv("GRADE_LIST");
    if (list && strcmp(list, "1") == 0) {
        for (size_t i = 0; i < num_tests; i++)
            if (tests[i].name)
                printf("GRADE_LIST %s\n", tests[i].name);
        return 0;
    }
    /* Which test the filter names, before anything runs. */
    const char *filter = getenv("TEST_FILTER");
    char name[256] = "";
    size_t matching = 0;
    if (filter)
        for (size_t i = 0; i < num_tests; i++)
            if (tests[i].name && strcmp(tests[i].name, filter) == 0) {
                matching++;
                snprintf(name, sizeof name, "%s", tests[i].name);
            }
    int failed = __real__cmocka_run_group_tests(group_name, tests, num_tests, group_setup,
                                                group_teardown);
    if (matching == 1)
        observe_end(failed == 0);
    if (result_fd >= 0 && nonce[0] && matching == 1) {
        char line[NONCE_MAX + 300];
        int n = snprintf(line, sizeof line, "%s %s %s\n", nonce, failed == 0 ? "passed" : "failed",
                         name);
        if (n > 0 && write(result_fd, line, (size_t)n) != n)
            failed = 1;
        close(result_fd);
        result_fd = -1;
    }
    return failed;
}
