/* test_page_shape.c: a lesson page a student can follow, short and pictured.
 *
 * Every lesson page docs/NN_*.md:
 *   - shows a picture on its first screen: an image (a line with "![") within
 *     its first FIRST_SCREEN_LINES lines, under the title and the paragraph
 *     that states the lesson's idea;
 *   - has at most MAX_MAIN_WORDS words of main text before "## Exercises",
 *     counted as `wc -w` counts them (runs of non-space characters):
 *         awk '/^## Exercises/{exit} {print}' docs/02_zbuffer.md | wc -w
 *   - keeps what first reading does not need in "## Going further", after the
 *     exercises, if it has such a section at all.
 * docs/conventions.md, "How a lesson is laid out", says the same for whoever
 * writes a page. On a failure the message names the page and what to move. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <ctype.h>
#include <glob.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_MAIN_WORDS 2000
#define FIRST_SCREEN_LINES 25
#define EXERCISES "## Exercises"
#define GOING_FURTHER "## Going further"

typedef struct {
    int words_before_exercises; /* every word if there is no "## Exercises" */
    int exercises_line;         /* 1-based; 0 if none */
    int going_further_line;     /* 1-based; 0 if none */
    int first_image_line;       /* 1-based; 0 if none */
} PageShape;

static bool starts_with(const char *s, const char *prefix)
{
    return strncmp(s, prefix, strlen(prefix)) == 0;
}

static int count_words(const char *s)
{
    int words = 0;
    bool in_word = false;
    for (; *s; s++) {
        bool space = isspace((unsigned char)*s) != 0;
        if (!space && !in_word)
            words++;
        in_word = !space;
    }
    return words;
}

static PageShape page_shape(const char *path)
{
    FILE *f = fopen(path, "r");
    if (!f)
        fail_msg("cannot read %s", path);
    PageShape p = {0, 0, 0, 0};
    char line[8192];
    int number = 0;
    bool in_fence = false;
    while (fgets(line, sizeof line, f)) {
        number++;
        if (starts_with(line, "```"))
            in_fence = !in_fence;
        bool heading = !in_fence && line[0] == '#';
        if (heading && p.exercises_line == 0 && starts_with(line, EXERCISES))
            p.exercises_line = number;
        if (heading && p.going_further_line == 0 && starts_with(line, GOING_FURTHER))
            p.going_further_line = number;
        if (p.first_image_line == 0 && strstr(line, "!["))
            p.first_image_line = number;
        if (p.exercises_line == 0)
            p.words_before_exercises += count_words(line);
    }
    fclose(f);
    return p;
}

static void every_lesson_page_is_short_and_pictured(void **state)
{
    (void)state;
    glob_t g;
    if (glob("docs/[0-9][0-9]_*.md", 0, NULL, &g) != 0 || g.gl_pathc == 0)
        fail_msg("no lesson page docs/NN_*.md (run the test from the top of the tree)");
    int failures = 0;
    for (size_t i = 0; i < g.gl_pathc; i++) {
        const char *page = g.gl_pathv[i];
        PageShape p = page_shape(page);
        print_message("%s: %d words before \"%s\", first image on line %d\n", page,
                      p.words_before_exercises, EXERCISES, p.first_image_line);
        if (p.words_before_exercises > MAX_MAIN_WORDS) {
            print_error("%s: %d words before \"%s\"; at most %d. Move what a first reading "
                        "does not need to \"%s\" at the end of the page, or to "
                        "docs/tools.md, robustness.md or performance.md\n",
                        page, p.words_before_exercises, EXERCISES, MAX_MAIN_WORDS, GOING_FURTHER);
            failures++;
        }
        if (p.first_image_line == 0 || p.first_image_line > FIRST_SCREEN_LINES) {
            print_error("%s: no picture in its first %d lines (first image: line %d); put the "
                        "lesson's key picture under the paragraph that states its idea\n",
                        page, FIRST_SCREEN_LINES, p.first_image_line);
            failures++;
        }
        if (p.going_further_line != 0 &&
            (p.exercises_line == 0 || p.going_further_line < p.exercises_line)) {
            print_error("%s: \"%s\" (line %d) comes before \"%s\" (line %d); it belongs after "
                        "the exercises, at the end of the page\n",
                        page, GOING_FURTHER, p.going_further_line, EXERCISES, p.exercises_line);
            failures++;
        }
    }
    globfree(&g);
    if (failures)
        fail_msg("%d problem(s) with the shape of the lesson pages (above)", failures);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(every_lesson_page_is_short_and_pictured),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
