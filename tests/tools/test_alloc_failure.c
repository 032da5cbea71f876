/* test_alloc_failure.c: every allocation of a run, made to fail in turn.
 *
 * tests/tools/fail_alloc.c, preloaded, counts a run's allocations (malloc,
 * calloc, realloc, aligned_alloc, posix_memalign), then fails the first of
 * them, then only the second, and so on to the last. Whichever fails, the
 * run either
 *   - exits 0 and writes every output, the picture byte for byte the one
 *     written without a failure (a fallback may take over; a blank or
 *     partial picture reported as success may not), or
 *   - exits 1 with exactly one line "<lesson>: error: ..." and writes no
 *     output at all, nor leaves a temporary file behind.
 * Never a crash, an abort (an assertion in a library) or any other status.
 * Each lesson runs small, with its lesson-specific outputs; lesson 07 reads
 * docs/examples/house.obj and its .mtl, lesson 10 runs two threads. A
 * preloaded allocator and AddressSanitizer's exclude each other: under
 * make sanitize the test is skipped. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <dirent.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "shell.h"
#include "test_support.h"

#define MAX_OUTPUTS 8

typedef struct {
    const char *lesson, *args;      /* args: besides the outputs; $TOP: the series' top */
    const char *outputs[MAX_OUTPUTS]; /* flag, file, flag, file, ...; the first is the picture */
} Case;

static const Case CASES[] = {
    {"01_ybuffer", "--width 48", {"--out", "p.png"}},
    {"02_zbuffer", "--width 48 --height 36", {"--out", "p.png", "--id-out", "i.png", "--depth-out", "d.pfm"}},
    {"03_perspective_z", "--width 48 --height 36", {"--out", "p.png", "--depth-out", "d.pfm"}},
    {"04_scanline_inverse_z", "--width 48 --height 36", {"--out", "p.png", "--id-out", "i.png"}},
    {"05_clipping", "--width 48 --height 36 --scene inside", {"--out", "p.png", "--depth-out", "d.pfm"}},
    {"06_depth_precision", "--width 48 --height 36 --depth-format float32", {"--out", "p.png", "--id-out", "i.png"}},
    {"07_depth_bias", "--width 48 --height 36 --obj $TOP/docs/examples/house.obj", {"--out", "p.png", "--id-out", "i.png"}},
    {"08_early_z", "--width 48 --height 36 --z-mode prepass", {"--out", "p.png", "--colour-out", "c.png", "--shade-count-out", "s.png"}},
    {"09_hierarchical_z", "--width 48 --height 36", {"--out", "p.png", "--hiz-out", "h.png", "--overdraw-out", "o.png"}},
    {"10_fast_raster", "--width 48 --height 36 --threads 2", {"--out", "p.png", "--id-out", "i.png", "--depth-out", "d.pfm"}},
};

/* Beside the lessons' directory: build/tests/fail_alloc.so, as a full path. */
static const char *fail_alloc_library(void)
{
    const char *path = strdup(path_join(abs_bin_dir(), "../tests/fail_alloc.so"));
    if (!file_exists(path))
        fail_msg("no %s: make test builds it", path);
    return path; /* path_join's own buffer is used again */
}

/* The outputs of c, as flags for its command line. */
static const char *output_flags(const Case *c)
{
    static char flags[512];
    flags[0] = '\0';
    for (int k = 0; k < MAX_OUTPUTS && c->outputs[k]; k++)
        strcat(flags, " "), strcat(flags, c->outputs[k]);
    return flags;
}

/* How many files directory dir holds (dot files too). */
static int files_in(const char *dir)
{
    DIR *d = opendir(dir);
    int n = 0;
    for (struct dirent *e; d && (e = readdir(d)) != NULL;)
        n += strcmp(e->d_name, ".") != 0 && strcmp(e->d_name, "..") != 0;
    if (d)
        closedir(d);
    return n;
}

static void every_allocation_that_fails_gives_one_error_line_or_the_same_picture(void **state)
{
    (void)state;
    if (getenv("ASAN_OPTIONS"))
        skip();
    const char *library = fail_alloc_library();
    char top[4096];
    if (!getcwd(top, sizeof top))
        fail_msg("cannot tell the current directory");
    const char *bin = abs_bin_dir();
    for (size_t c = 0; c < sizeof CASES / sizeof CASES[0]; c++) {
        const Case *k = &CASES[c];
        char name[128]; /* not the lesson's bare name: test_out_of_memory's, in a test run beside */
        snprintf(name, sizeof name, "alloc_%s", k->lesson);
        char *dir = strdup(test_dir(name)), *ref = strdup(test_dir("alloc_reference"));
        ShellResult r = run_shell(ref, 60, "TOP=%s && FAIL_ALLOC_COUNT=count LD_PRELOAD=%s exec %s/%s %s%s >/dev/null",
                                  top, library, bin, k->lesson, k->args, output_flags(k));
        if (r.status != 0)
            fail_msg("%s without a failure: status %d\n%s", k->lesson, r.status, r.output);
        shell_result_free(&r);
        char *count = read_text(path_join(ref, "count"));
        long calls = atol(count);
        free(count);
        if (calls < 5)
            fail_msg("%s: %ld allocations counted: is the library preloaded?", k->lesson, calls);
        char *want = strdup(path_join(ref, k->outputs[1]));
        for (long at = 0; at < calls; at++) {
            r = run_shell(dir, 60, "TOP=%s && FAIL_ALLOC_AT=%ld LD_PRELOAD=%s exec %s/%s %s%s >/dev/null",
                          top, at, library, bin, k->lesson, k->args, output_flags(k));
            char prefix[64];
            snprintf(prefix, sizeof prefix, "%s: error: ", k->lesson);
            const char *newline = strchr(r.output, '\n');
            if (r.status == 0) {
                for (int o = 1; o < MAX_OUTPUTS && k->outputs[o]; o += 2)
                    if (!file_exists(path_join(dir, k->outputs[o])))
                        fail_msg("%s, allocation %ld of %ld failing: status 0 without %s\n%s",
                                 k->lesson, at, calls, k->outputs[o], r.output);
                if (!files_same_bytes(path_join(dir, k->outputs[1]), want) || strstr(r.output, "error"))
                    fail_msg("%s, allocation %ld of %ld failing: status 0, but another picture "
                             "or an error:\n%s", k->lesson, at, calls, r.output);
            } else if (r.status != 1 || strncmp(r.output, prefix, strlen(prefix)) != 0 ||
                       !newline || newline[1] != '\0' || files_in(dir) != 0) {
                fail_msg("%s, allocation %ld of %ld failing: status %d, %d files left; wanted "
                         "status 1, one line \"%s...\" and no file:\n%s", k->lesson, at, calls,
                         r.status, files_in(dir), prefix, r.output);
            }
            shell_result_free(&r);
            for (int o = 1; o < MAX_OUTPUTS && k->outputs[o]; o += 2)
                remove(path_join(dir, k->outputs[o]));
        }
        free(want);
        free(dir);
        free(ref);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(every_allocation_that_fails_gives_one_error_line_or_the_same_picture),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
