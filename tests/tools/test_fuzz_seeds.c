/* test_fuzz_seeds.c: every fuzz target of tests/fuzz/ on its committed
 * seeds (tests/fuzz/corpus/<target>/), built without libFuzzer
 * (tests/fuzz/replay.c, make builds them in build/fuzz-replay/): each input
 * must run through, with every invariant the target checks holding. The
 * seeds hold what fuzzing once found (docs/robustness.md), so a fix stays
 * fixed; under make sanitize they run with ASan and UBSan too. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "test_support.h"

#define MAX_SEEDS 64

/* The names in directory dir (no dot files), sorted; how many. */
static int names_in(const char *dir, char **names, int most)
{
    DIR *d = opendir(dir);
    if (!d)
        fail_msg("cannot read %s", dir);
    int n = 0;
    for (struct dirent *e; (e = readdir(d)) != NULL;)
        if (e->d_name[0] != '.') {
            if (n == most)
                fail_msg("%s holds more than %d files", dir, most);
            names[n++] = strdup(e->d_name);
        }
    closedir(d);
    qsort(names, (size_t)n, sizeof *names, compare_strings);
    return n;
}

static void every_fuzz_target_passes_its_seeds(void **state)
{
    (void)state;
    char *source[MAX_SEEDS];
    int ntargets = names_in("tests/fuzz", source, MAX_SEEDS), checked = 0;
    for (int t = 0; t < ntargets; t++) {
        size_t len = strlen(source[t]);
        if (strncmp(source[t], "fuzz_", 5) != 0 || len < 3 || strcmp(source[t] + len - 2, ".c") != 0)
            continue;
        source[t][len - 2] = '\0';
        const char *name = source[t] + 5;
        char dir[256], program[256];
        snprintf(dir, sizeof dir, "tests/fuzz/corpus/%s", name);
        snprintf(program, sizeof program, "../fuzz-replay/%s", source[t]);
        char *seed[MAX_SEEDS];
        const char *args[MAX_SEEDS + 1];
        int n = names_in(dir, seed, MAX_SEEDS);
        if (n == 0)
            fail_msg("%s: no seeds in %s", source[t], dir);
        for (int k = 0; k < n; k++)
            args[k] = strdup(path_join(dir, seed[k]));
        args[n] = NULL;
        RunResult r = run_tool(program, args);
        if (r.status != 0)
            fail_msg("%s on its seeds in %s: exit status %d\n%s", source[t], dir, r.status, r.err);
        run_result_free(&r);
        for (int k = 0; k < n; k++)
            free(seed[k]), free((void *)args[k]);
        checked++;
    }
    for (int t = 0; t < ntargets; t++)
        free(source[t]);
    if (checked < 13)
        fail_msg("only %d fuzz targets found in tests/fuzz, expected at least 13", checked);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(every_fuzz_target_passes_its_seeds),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
