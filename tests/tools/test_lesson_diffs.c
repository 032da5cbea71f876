/* test_lesson_diffs.c: each lesson reads in one sitting, and `make diff`
 * between two lessons shows only the later one's idea.
 *
 * The measures are those of `make reading` (tools/reading.sh), checked here
 * against budgets:
 *
 *   reading path   main.c, the taught files at the top of the lesson
 *                  directory, and the headers they include directly: at most
 *                  READING_MAX lines in all (lesson 10, which teaches bins,
 *                  blocks, SIMD and threads: READING_MAX_FAST); main.c at
 *                  most MAIN_MAX.
 *   make diff      02 -> 03: at most 150 lines, the 1/d change.
 *                  A file the later lesson's REPLACES names is shown whole
 *                  (lesson 04's scanline.c replaces lesson 03's raster.c):
 *                  everything else of 03 -> 04 at most 80 lines, of any later
 *                  pair at most 220 (from lesson 06 on a lesson keeps its own
 *                  state, state.h, and a later lesson that adds to it shows
 *                  that too).
 *
 * The diff is counted here from the output of tools/lesson-diff.sh, file by
 * file, and must agree with what `make reading` prints. Each lesson page names
 * its reading path, in order, under "## Reading the code"; the diffs a page
 * links (docs/diffs/) are today's, and the page names each file they change.
 * docs/conventions.md's table of the layout quotes today's measures. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "error.h"
#include "harness/file.h"
#include "test_support.h"

#define READING_MAX 600
#define READING_MAX_FAST 900
#define MAIN_MAX 80
#define DIFF_MAX_BYTES ((size_t)1 << 22)
#define MAX_LESSONS 16
#define MAX_PATH_FILES 32

typedef struct {
    char name[64];
    int files, path_lines, main_lines, solution_lines;
    char next[64];
    int diff_lines, replacing_lines; /* -1 for the last lesson */
    char path[MAX_PATH_FILES][128];  /* the reading path, in order */
    int path_count;
} Reading;

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

/* Every lesson as `make reading` measures it: the --tsv lines, and the
 * reading paths from the table (its indented lines). */
static int read_readings_afresh(Reading *out)
{
    char *tsv = command_output("sh tools/reading.sh --tsv"), *save = NULL;
    int n = 0;
    for (char *line = strtok_r(tsv, "\n", &save); line && n < MAX_LESSONS;
         line = strtok_r(NULL, "\n", &save)) {
        Reading *r = &out[n];
        memset(r, 0, sizeof *r);
        char diff[32], replacing[32];
        if (sscanf(line, "%63s %d %d %d %d %63s %31s %31s", r->name, &r->files, &r->path_lines,
                   &r->main_lines, &r->solution_lines, r->next, diff, replacing) != 8)
            fail_msg("make reading --tsv printed a line it should not: %s", line);
        r->diff_lines = strcmp(diff, "-") == 0 ? -1 : atoi(diff);
        r->replacing_lines = strcmp(replacing, "-") == 0 ? -1 : atoi(replacing);
        n++;
    }
    free(tsv);
    char *table = command_output("sh tools/reading.sh");
    int k = -1;
    save = NULL;
    for (char *line = strtok_r(table, "\n", &save); line; line = strtok_r(NULL, "\n", &save)) {
        if (line[0] != ' ') {
            for (k = 0; k < n && strncmp(line, out[k].name, strlen(out[k].name)) != 0; k++)
                ;
            continue;
        }
        char file[128];
        int lines;
        if (k < 0 || k >= n || sscanf(line, " %127s %d", file, &lines) != 2)
            continue;
        Reading *r = &out[k];
        if (r->path_count < MAX_PATH_FILES)
            snprintf(r->path[r->path_count++], sizeof r->path[0], "%s", file);
    }
    free(table);
    if (n < 4)
        fail_msg("make reading listed %d lessons, expected at least 4", n);
    return n;
}

/* The same, read once: the three tests that need it share it (a second each). */
static int read_readings(Reading *out)
{
    static Reading once[MAX_LESSONS];
    static int n;
    if (n == 0)
        n = read_readings_afresh(once);
    memcpy(out, once, (size_t)n * sizeof *out);
    return n;
}

/* A description for the expect_ checks, printf-style (one at a time). */
static const char *what(const char *fmt, ...)
{
    static char text[256];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(text, sizeof text, fmt, ap);
    va_end(ap);
    return text;
}

static int lines_in_file(const char *path)
{
    char *text = read_text(path);
    int n = 0;
    for (const char *c = text; *c; c++)
        n += *c == '\n';
    free(text);
    return n;
}

static void every_reading_path_fits_in_one_sitting(void **state)
{
    (void)state;
    Reading r[MAX_LESSONS];
    int n = read_readings(r);
    for (int k = 0; k < n; k++) {
        /* The count is the files' own: add them up again. */
        int sum = 0;
        for (int i = 0; i < r[k].path_count; i++)
            sum += lines_in_file(r[k].path[i]);
        expect_count(r[k].path_count, r[k].files, what("files on the reading path of %s", r[k].name));
        expect_count(sum, r[k].path_lines, what("lines on the reading path of %s", r[k].name));
        int most = strncmp(r[k].name, "10_", 3) == 0 ? READING_MAX_FAST : READING_MAX;
        if (r[k].path_lines > most)
            fail_msg("%s: its reading path is %d lines, more than %d (make reading lists "
                     "the files): move what the lesson does not teach out of them",
                     r[k].name, r[k].path_lines, most);
        expect_at_most(MAIN_MAX, r[k].main_lines, what("lines in %s's main.c", r[k].name));
        expect_at_least(1, r[k].solution_lines, what("solution lines in %s", r[k].name));
    }
}

/* Lines of `make diff FROM TO`, apart from the sections of files shown whole
 * because they replace a file (the note lines at the top count with them). */
static void count_diff(const char *from, const char *to, int *other, int *replacing)
{
    char command[128];
    snprintf(command, sizeof command, "sh tools/lesson-diff.sh %s %s", from, to);
    char *text = command_output(command), *save = NULL;
    char replaced[8][64];
    int n_replaced = 0;
    bool in_replacing = false;
    *other = *replacing = 0;
    for (char *line = strtok_r(text, "\n", &save); line; line = strtok_r(NULL, "\n", &save)) {
        const char *shown = strstr(line, " replaces ");
        if (strncmp(line, "# ", 2) == 0 && shown && n_replaced < 8) {
            /* "# lessons/04_x/scanline.c replaces lessons/03_y/raster.c: shown whole below" */
            const char *slash = shown;
            while (slash > line && slash[-1] != '/')
                slash--;
            snprintf(replaced[n_replaced++], sizeof replaced[0], "%.*s", (int)(shown - slash),
                     slash);
            (*replacing)++;
            continue;
        }
        if (strncmp(line, "diff ", 5) == 0) {
            in_replacing = false;
            for (int i = 0; i < n_replaced; i++) {
                size_t len = strlen(line), m = strlen(replaced[i]);
                if (len > m && strcmp(line + len - m, replaced[i]) == 0 && line[len - m - 1] == '/')
                    in_replacing = true;
            }
        }
        if (in_replacing)
            (*replacing)++;
        else
            (*other)++;
    }
    free(text);
}

static void every_lesson_diff_is_its_idea(void **state)
{
    (void)state;
    Reading r[MAX_LESSONS];
    int n = read_readings(r);
    for (int k = 0; k + 1 < n; k++) {
        char from[3], to[3];
        snprintf(from, sizeof from, "%.2s", r[k].name);
        snprintf(to, sizeof to, "%.2s", r[k + 1].name);
        int other, replacing;
        count_diff(from, to, &other, &replacing);
        expect_count(other, r[k].diff_lines, what("make reading's diff lines from %s to %s", from,
                     to));
        if (strcmp(from, "01") == 0)
            continue; /* lesson 02 starts the 3-D series: no budget (its page says so) */
        int budget = strcmp(from, "02") == 0 ? 150 : strcmp(from, "03") == 0 ? 80 : 220;
        if (other > budget)
            fail_msg("make diff FROM=%s TO=%s is %d lines (besides %d in files shown whole), "
                     "more than its budget of %d: keep what the lesson shows but does not hand "
                     "on in its extras/, and out of the files the next lesson grows from",
                     from, to, other, replacing, budget);
        if (strcmp(from, "03") == 0)
            expect_at_least(100, replacing, "lines of lesson 04's scanline files, shown whole");
    }
}

/* The page of each lesson lists its reading path, in order, as the numbered
 * items of its "## Reading the code" section: "1. `lessons/02_zbuffer/main.c`". */
static void every_page_names_its_reading_path_in_order(void **state)
{
    (void)state;
    Reading r[MAX_LESSONS];
    int n = read_readings(r);
    for (int k = 0; k < n; k++) {
        char page[96];
        snprintf(page, sizeof page, "docs/%.64s.md", r[k].name);
        char *text = read_text(page);
        char *section = strstr(text, "\n## Reading the code\n");
        if (!section)
            fail_msg("%s has no \"## Reading the code\" section naming its reading path", page);
        char *end = strstr(section + 1, "\n## ");
        if (end)
            *end = '\0';
        int found = 0;
        char *save = NULL;
        for (char *line = strtok_r(section, "\n", &save); line; line = strtok_r(NULL, "\n", &save)) {
            int number;
            char file[128];
            if (sscanf(line, "%d. `%127[^`]`", &number, file) != 2)
                continue;
            if (found >= r[k].path_count)
                fail_msg("%s names %s, which is not on the reading path", page, file);
            if (strcmp(file, r[k].path[found]) != 0)
                fail_msg("%s: item %d of \"Reading the code\" is %s; make reading has %s there",
                         page, found + 1, file, r[k].path[found]);
            found++;
        }
        expect_count(r[k].path_count, found, what("files %s names under \"Reading the code\"", page));
        free(text);
    }
}

static void linked_diffs_in_docs_are_the_diffs_of_the_code(void **state)
{
    (void)state;
    static const char *const PAIRS[][2] = {{"02", "03"}, {"03", "04"}, {"04", "05"}, {"05", "06"},
                                               {"06", "07"}, {"07", "08"}, {"08", "09"}, {"09", "10"}};
    for (size_t k = 0; k < sizeof PAIRS / sizeof PAIRS[0]; k++) {
        const char *from = PAIRS[k][0], *to = PAIRS[k][1];
        char command[128], path[64];
        snprintf(command, sizeof command, "sh tools/lesson-diff.sh %s %s", from, to);
        snprintf(path, sizeof path, "docs/diffs/%s_to_%s.diff", from, to);
        char *now = command_output(command), *kept = NULL;
        size_t len;
        Error err;
        if (!read_file(path, DIFF_MAX_BYTES, &kept, &len, &err))
            fail_msg("%s\nwrite it with: make diff FROM=%s TO=%s > %s", err.msg, from, to, path);
        if (strcmp(now, kept) != 0)
            fail_msg("%s is not the diff of today's lessons %s and %s\nregenerate it (and the "
                     "others) with: make diffs", path, from, to);
        free(now);
        free(kept);
    }
}

/* Each page says what its `make diff` shows, in the paragraph that names the
 * command: every file the diff changes is named there, as `clip.c`, or with
 * its kind as `scanline.*`. A file left out is one a reader meets unwarned. */
static void every_page_names_each_file_its_diff_changes(void **state)
{
    (void)state;
    Reading r[MAX_LESSONS];
    int n = read_readings(r);
    for (int k = 0; k + 1 < n; k++) {
        char from[3], to[3], path[64], page[96], command[64];
        snprintf(from, sizeof from, "%.2s", r[k].name);
        snprintf(to, sizeof to, "%.2s", r[k + 1].name);
        if (strcmp(from, "01") == 0)
            continue; /* lesson 02 starts the 3-D series: no diff */
        snprintf(path, sizeof path, "docs/diffs/%s_to_%s.diff", from, to);
        snprintf(page, sizeof page, "docs/%.64s.md", r[k + 1].name);
        snprintf(command, sizeof command, "make diff FROM=%s TO=%s", from, to);
        char *diff = read_text(path), *text = read_text(page);
        char *said = strstr(text, command);
        if (!said)
            fail_msg("%s does not say what `%s` shows", page, command);
        char *end = strstr(said, "\n\n");
        if (end)
            *end = '\0';
        int files = 0;
        for (char *line = diff; line && *line; line = strchr(line, '\n') ? strchr(line, '\n') + 1 : NULL) {
            if (strncmp(line, "diff -ruN ", 10) != 0)
                continue;
            char *eol = strchr(line, '\n'), name[128], kind[132];
            size_t len = eol ? (size_t)(eol - line) : strlen(line);
            char *slash = line + len;
            while (slash > line && slash[-1] != '/')
                slash--;
            snprintf(name, sizeof name, "%.*s", (int)(line + len - slash), slash);
            char *dot = strrchr(name, '.');
            snprintf(kind, sizeof kind, "%.*s.*", (int)(dot ? dot - name : (long)strlen(name)), name);
            if (!strstr(said, name) && !strstr(said, kind))
                fail_msg("%s: the paragraph on `%s` does not name %s, which the diff changes "
                         "(%s)", page, command, name, path);
            files++;
        }
        expect_at_least(1, files, what("files %s changes", path));
        free(diff);
        free(text);
    }
}

/* n as the pages write it: 1,541 (a comma every three digits). */
static const char *with_commas(int n, char out[32])
{
    char digits[24];
    int len = snprintf(digits, sizeof digits, "%d", n), o = 0;
    for (int i = 0; i < len; i++) {
        if (i > 0 && (len - i) % 3 == 0)
            out[o++] = ',';
        out[o++] = digits[i];
    }
    out[o] = '\0';
    return out;
}

/* docs/conventions.md's table of "before this layout and now": its "now"
 * columns are what `make reading` prints today, for every lesson it lists. */
static void conventions_table_is_what_make_reading_prints(void **state)
{
    (void)state;
    Reading r[MAX_LESSONS];
    int n = read_readings(r);
    char *text = read_text("docs/conventions.md");
    char *table = strstr(text, "Measured with `make reading`");
    if (!table)
        fail_msg("docs/conventions.md has no table measured with `make reading`");
    int rows = 0;
    for (char *line = strstr(table, "\n| 0"); line; line = strstr(line + 1, "\n| 0")) {
        char row[512], *eol = strchr(line + 1, '\n');
        snprintf(row, sizeof row, "%.*s", (int)(eol ? eol - line - 1 : (long)strlen(line + 1)), line + 1);
        char *cell[12], *save = NULL;
        int cells = 0;
        for (char *c = strtok_r(row, "|", &save); c && cells < 12; c = strtok_r(NULL, "|", &save)) {
            while (*c == ' ')
                c++;
            for (char *e = c + strlen(c); e > c && e[-1] == ' ';)
                *--e = '\0';
            cell[cells++] = c;
        }
        if (cells < 8)
            fail_msg("docs/conventions.md: a row of the reading table has %d cells", cells);
        int k = 0;
        while (k < n && strncmp(r[k].name, cell[0], 2) != 0)
            k++;
        if (k == n)
            fail_msg("docs/conventions.md: the reading table has lesson %s, make reading has not", cell[0]);
        char want[96], a[32], b[32];
        snprintf(want, sizeof want, "%d files, %s lines", r[k].files, with_commas(r[k].path_lines, a));
        if (strcmp(cell[2], want) != 0)
            fail_msg("docs/conventions.md, lesson %s: the reading path is \"%s\", make reading "
                     "prints %s", cell[0], cell[2], want);
        expect_count(r[k].main_lines, atoi(cell[4]), what("main.c of lesson %s in conventions.md", cell[0]));
        expect_count(r[k].solution_lines, atoi(cell[6]),
                     what("solution lines of lesson %s in conventions.md", cell[0]));
        if (cells > 8 && cell[8][0] && r[k].diff_lines >= 0) { /* (an empty cell quotes nothing) */
            if (r[k].replacing_lines > 0)
                snprintf(want, sizeof want, "%s (+ %s shown whole)", with_commas(r[k].diff_lines, a),
                         with_commas(r[k].replacing_lines, b));
            else
                snprintf(want, sizeof want, "%s", with_commas(r[k].diff_lines, a));
            if (strcmp(cell[8], want) != 0)
                fail_msg("docs/conventions.md, lesson %s: the diff to the next is \"%s\", make "
                         "reading prints %s", cell[0], cell[8], want);
        }
        rows++;
    }
    expect_at_least(4, rows, "rows of the reading table in docs/conventions.md");
    free(text);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(every_reading_path_fits_in_one_sitting),
        cmocka_unit_test(every_lesson_diff_is_its_idea),
        cmocka_unit_test(every_page_names_its_reading_path_in_order),
        cmocka_unit_test(linked_diffs_in_docs_are_the_diffs_of_the_code),
        cmocka_unit_test(every_page_names_each_file_its_diff_changes),
        cmocka_unit_test(conventions_table_is_what_make_reading_prints),
    };
    return cmocka_run_group_tests_name("tools: reading paths and lesson diffs", tests, NULL,
                                       NULL);
}
