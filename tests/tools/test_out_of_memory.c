/* test_out_of_memory.c: a lesson whose own buffers cannot be allocated fails
 * with one error line and exit status 1, and writes nothing.
 *
 * Lessons 08 to 10 allocate buffers of their own after the target's (the
 * shader's colour and counts, the tile buffer, the bins). Each draws
 * triangles3 (three faces: the buffers are the cost) at 4096 x 4096 under
 * a few limits of address space (`ulimit -v`) between
 * what the target needs and what the whole run needs. Whatever the limit,
 * a run either draws its picture and exits 0, or exits 1 with exactly one
 * line "<lesson>: error: ..." and no picture; and for lessons 08 and 09 at
 * least one limit fails in the shader's buffers, so that the test reaches
 * the path it is about. A run drawn with AddressSanitizer reserves far more
 * address space than any such limit: under make sanitize the test is skipped. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "shell.h"
#include "test_support.h"


static const int LIMITS_MB[] = {250, 350, 450};

/* Runs lesson under each limit; returns how many runs failed with `reason`. */
static int runs_under_limits(const char *lesson, const char *reason)
{
    if (getenv("ASAN_OPTIONS"))
        skip();
    const char *bin = abs_bin_dir();
    char name[128]; /* not the lesson's bare name: test_alloc_failure's, in a test run beside */
    snprintf(name, sizeof name, "oom_%s", lesson);
    const char *dir = test_dir(name);
    int with_reason = 0;
    for (size_t i = 0; i < sizeof LIMITS_MB / sizeof LIMITS_MB[0]; i++) {
        ShellResult r = run_shell(dir, 120,
                                  "ulimit -v %d && exec %s/%s --scene triangles3 --width 4096 "
                                  "--height 4096 --out p.png --id-out id.png >/dev/null",
                                  LIMITS_MB[i] * 1024, bin, lesson);
        bool picture = access(path_join(dir, "p.png"), F_OK) == 0 ||
                       access(path_join(dir, "id.png"), F_OK) == 0;
        size_t lines = 0;
        for (const char *c = r.output; *c; c++)
            lines += *c == '\n';
        char prefix[128];
        snprintf(prefix, sizeof prefix, "%s: error: ", lesson);
        if (r.status == 0) {
            if (access(path_join(dir, "p.png"), F_OK) != 0 || r.output[0] != '\0')
                fail_msg("%s under %d MB: status 0 without its picture, or with:\n%s", lesson,
                         LIMITS_MB[i], r.output);
        } else if (r.status != 1 || lines != 1 || strncmp(r.output, prefix, strlen(prefix)) != 0 ||
                   picture) {
            fail_msg("%s under %d MB: status %d%s; wanted 1, one line \"%s...\" and no picture:\n%s",
                     lesson, LIMITS_MB[i], r.status, picture ? ", a picture written" : "", prefix,
                     r.output);
        } else if (strstr(r.output, reason)) {
            with_reason++;
        }
        remove(path_join(dir, "p.png"));
        remove(path_join(dir, "id.png"));
        shell_result_free(&r);
    }
    return with_reason;
}

static void lesson_08_fails_when_its_shader_buffers_cannot_be_allocated(void **state)
{
    (void)state;
    if (runs_under_limits("08_early_z", "the shader's buffers") == 0)
        fail_msg("no limit made lesson 08's shader buffers fail: the test misses its path");
}

static void lesson_09_fails_when_its_shader_buffers_cannot_be_allocated(void **state)
{
    (void)state;
    if (runs_under_limits("09_hierarchical_z", "the shader's buffers") == 0)
        fail_msg("no limit made lesson 09's shader buffers fail: the test misses its path");
}

static void lesson_10_fails_or_draws_under_every_limit(void **state)
{
    (void)state;
    runs_under_limits("10_fast_raster", "out of memory");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(lesson_08_fails_when_its_shader_buffers_cannot_be_allocated),
        cmocka_unit_test(lesson_09_fails_when_its_shader_buffers_cannot_be_allocated),
        cmocka_unit_test(lesson_10_fails_or_draws_under_every_limit),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
