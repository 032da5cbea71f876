/* test_lesson_diffs.c: what a lesson changes in the one before stays short.
 *
 * `make diff FROM=02 TO=03` shows the source difference between two lessons,
 * which is what the later lesson teaches; each page from 03 on links it, kept
 * in docs/diffs/. Two checks per pair of consecutive lessons:
 *
 *   1. A line budget per file: lines added plus lines removed, as
 *      `scripts/lesson-diff.sh --stat` counts them. When a file passes its
 *      budget, the test names the file, its count and its budget. A file that
 *      appears in a diff without a budget has budget 0: a new file in a lesson
 *      is a decision, and its budget says so. The budgets sit a little above
 *      today's counts (about a tenth, at least 10 lines), so that a small fix
 *      passes and a lesson that grows by a feature does not.
 *
 *   2. docs/diffs/<FROM>_to_<TO>.diff, which the lesson page links, is the
 *      diff of today's code (regenerate it with the command the message gives).
 *
 * 01 -> 02 has no budget: lesson 01 is a one-row program of its own (segments,
 * a y-buffer of ints), and lesson 02 starts the 3-D series from scratch; their
 * diff is both programs whole, and nothing in it is a "change". */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "error.h"
#include "file.h"

#define DIFF_MAX_BYTES ((size_t)1 << 22)

typedef struct {
    const char *from, *to;
    const char *file;
    int budget; /* lines added + removed */
} Budget;

/* The budgets, per pair and file. Their sums are the pairs' budgets. */
static const Budget BUDGETS[] = {
    /* 02 -> 03: d is blended as 1/d (raster.c); --compare-naive comes
     * (main.c, drawn by common/compare_naive.c); lesson 02's painter and two
     * bugs go, lesson 03's negated-w bug comes (bugs.c). */
    {"02", "03", "bugs.c", 165},
    {"02", "03", "bugs.h", 45},
    {"02", "03", "main.c", 120},
    {"02", "03", "painter.c", 80},
    {"02", "03", "painter.h", 28},
    {"02", "03", "raster.c", 65},
    {"02", "03", "raster.h", 34},
    /* 03 -> 04: the triangle rasterizer gives way to a scanline polygon filler
     * storing 1/d, so raster.c/h go and scanline.c/h come whole; the negated-w
     * bug stays in lesson 03. */
    {"03", "04", "bugs.c", 40},
    {"03", "04", "bugs.h", 28},
    {"03", "04", "main.c", 127},
    {"03", "04", "raster.c", 270}, /* 246 since the edge functions are stepped (make bench) */
    {"03", "04", "raster.h", 75},
    {"03", "04", "scanline.c", 385},
    {"03", "04", "scanline.h", 125},
};
#define BUDGET_COUNT ((int)(sizeof BUDGETS / sizeof BUDGETS[0]))

static const char *const PAIRS[][2] = {{"02", "03"}, {"03", "04"}};
#define PAIR_COUNT ((int)(sizeof PAIRS / sizeof PAIRS[0]))

static int budget_of(const char *from, const char *to, const char *file)
{
    for (int i = 0; i < BUDGET_COUNT; i++)
        if (!strcmp(BUDGETS[i].from, from) && !strcmp(BUDGETS[i].to, to) &&
            !strcmp(BUDGETS[i].file, file))
            return BUDGETS[i].budget;
    return 0;
}

static int pair_budget(const char *from, const char *to)
{
    int sum = 0;
    for (int i = 0; i < BUDGET_COUNT; i++)
        if (!strcmp(BUDGETS[i].from, from) && !strcmp(BUDGETS[i].to, to))
            sum += BUDGETS[i].budget;
    return sum;
}

/* The whole output of a shell command; fails the test when it cannot run. */
static char *command_output(const char *command)
{
    FILE *p = popen(command, "r");
    if (!p)
        fail_msg("cannot run: %s", command);
    size_t cap = 4096, len = 0;
    char *text = malloc(cap);
    assert_non_null(text);
    for (size_t n; (n = fread(text + len, 1, cap - len - 1, p)) > 0;) {
        len += n;
        if (cap - len < 2) {
            cap *= 2;
            text = realloc(text, cap);
            assert_non_null(text);
        }
    }
    text[len] = '\0';
    int status = pclose(p);
    if (status != 0)
        fail_msg("%s exited with status %d", command, status);
    return text;
}

static void every_lesson_diff_stays_within_its_line_budget(void **state)
{
    (void)state;
    for (int k = 0; k < PAIR_COUNT; k++) {
        const char *from = PAIRS[k][0], *to = PAIRS[k][1];
        char command[128];
        snprintf(command, sizeof command, "sh scripts/lesson-diff.sh --stat %s %s", from, to);
        char *stat = command_output(command), *save = NULL;
        int total = 0;
        char over[2048] = "";
        for (char *line = strtok_r(stat, "\n", &save); line; line = strtok_r(NULL, "\n", &save)) {
            int added, removed;
            char file[256];
            if (sscanf(line, "%d %d %255s", &added, &removed, file) != 3)
                fail_msg("%s printed a line that is not \"<added> <removed> <file>\": %s",
                         command, line);
            int changed = added + removed, budget = budget_of(from, to, file);
            total += changed;
            if (changed > budget) {
                size_t used = strlen(over);
                snprintf(over + used, sizeof over - used,
                         "\n  %s grew: %d lines changed (+%d -%d), budget %d%s", file, changed,
                         added, removed, budget,
                         budget == 0 ? " (a file with no budget: give it one in this test)" : "");
            }
        }
        free(stat);
        if (over[0])
            fail_msg("make diff FROM=%s TO=%s is over budget (%d lines changed, budget %d in "
                     "all):%s\nIf the lesson should teach more, raise the budget in "
                     "tests/tools/test_lesson_diffs.c and say why; otherwise make the change "
                     "smaller.", from, to, total, pair_budget(from, to), over);
    }
}

static void linked_diffs_in_docs_are_the_diffs_of_the_code(void **state)
{
    (void)state;
    for (int k = 0; k < PAIR_COUNT; k++) {
        const char *from = PAIRS[k][0], *to = PAIRS[k][1];
        char command[128], path[64];
        snprintf(command, sizeof command, "sh scripts/lesson-diff.sh %s %s", from, to);
        snprintf(path, sizeof path, "docs/diffs/%s_to_%s.diff", from, to);
        char *now = command_output(command), *kept = NULL;
        size_t len;
        Error err;
        if (!read_file(path, DIFF_MAX_BYTES, &kept, &len, &err))
            fail_msg("%s\nwrite it with: make diff FROM=%s TO=%s > %s", err.msg, from, to, path);
        if (strcmp(now, kept) != 0)
            fail_msg("%s is not the diff of today's lessons %s and %s\nregenerate it with: "
                     "make diff FROM=%s TO=%s > %s", path, from, to, from, to, path);
        free(now);
        free(kept);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(every_lesson_diff_stays_within_its_line_budget),
        cmocka_unit_test(linked_diffs_in_docs_are_the_diffs_of_the_code),
    };
    return cmocka_run_group_tests_name("tools: lesson diffs", tests, NULL, NULL);
}
