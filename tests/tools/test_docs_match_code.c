/* test_docs_match_code.c: every C quote on a lesson page is today's code.
 *
 * A page docs/NN_name.md quotes its lesson in fenced ```c blocks. Each block
 * must appear in the code of that lesson (the .c and .h files of lessons/NN_name/
 * and those it inherits, as the build links them in build/lessons/NN_name/) or in
 * those of common/: its non-empty lines must be consecutive non-empty lines
 * of one source file. Lines are compared with leading and trailing white
 * space trimmed and every run of white space inside collapsed to one space, so
 * the alignment of end-of-line comments does not matter but every token does.
 *
 * The source's solution markers are skipped, because the handout tool removes
 * them and the page quotes the code without them: a line containing
 * "SOLUTION BEGIN" or "SOLUTION END" (with the rest of its comment when that
 * comment spans several lines), and a "SOLUTION STUB" comment (the stub the
 * handout puts in place of the solution) to its closing star-slash.
 *
 * A block that is only a sketch (a formula, a wrong example that is not in the
 * code on purpose) opts out with the line `<!-- illustrative -->` right before
 * its fence. The test counts and prints the opt-outs, so that they stay few.
 *
 * On a mismatch the message names the page, the block's first line and its line
 * number, and the first line of the block that no source file continues with. */
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

#define ILLUSTRATIVE_MARK "<!-- illustrative -->"
#define C_FENCE "```c"
#define FENCE "```"

/* A text split into lines. With `normalized`, lines are trimmed and their runs of
 * white space collapsed; `number` keeps each line's 1-based line number. */
typedef struct {
    char **line;
    int *number;
    size_t count, capacity;
} Lines;

typedef struct {
    char *path;
    Lines lines; /* normalized, non-empty, markers removed */
} Source;

typedef struct {
    Source *file;
    size_t count;
} Sources;

static char *read_whole_file(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (f == NULL)
        return NULL;
    size_t capacity = 4096, length = 0;
    char *text = malloc(capacity);
    assert_non_null(text);
    size_t got;
    while ((got = fread(text + length, 1, capacity - length - 1, f)) > 0) {
        length += got;
        if (capacity - length - 1 == 0) {
            capacity *= 2;
            text = realloc(text, capacity);
            assert_non_null(text);
        }
    }
    fclose(f);
    text[length] = '\0';
    return text;
}

/* Trim and collapse white space runs to one space; returns a new string. */
static char *normalize(const char *s, size_t n)
{
    char *out = malloc(n + 1);
    assert_non_null(out);
    size_t k = 0;
    bool pending_space = false;
    for (size_t i = 0; i < n; i++) {
        unsigned char c = (unsigned char)s[i];
        if (isspace(c)) {
            pending_space = k > 0;
            continue;
        }
        if (pending_space)
            out[k++] = ' ';
        pending_space = false;
        out[k++] = (char)c;
    }
    out[k] = '\0';
    return out;
}

static void lines_push(Lines *l, char *line, int number)
{
    if (l->count == l->capacity) {
        l->capacity = l->capacity ? 2 * l->capacity : 256;
        l->line = realloc(l->line, l->capacity * sizeof *l->line);
        l->number = realloc(l->number, l->capacity * sizeof *l->number);
        assert_non_null(l->line);
        assert_non_null(l->number);
    }
    l->line[l->count] = line;
    l->number[l->count] = number;
    l->count++;
}

static void lines_free(Lines *l)
{
    for (size_t i = 0; i < l->count; i++)
        free(l->line[i]);
    free(l->line);
    free(l->number);
    memset(l, 0, sizeof *l);
}

/* Every line of `text`, normalized, empty ones kept (the page parser needs
 * them). */
static Lines split_lines(const char *text)
{
    Lines l = {0};
    int number = 1;
    const char *p = text;
    while (*p != '\0') {
        const char *end = strchr(p, '\n');
        size_t n = end ? (size_t)(end - p) : strlen(p);
        lines_push(&l, normalize(p, n), number++);
        p += n;
        if (*p == '\n')
            p++;
    }
    return l;
}

/* The source lines the pages may quote: non-empty, without solution markers. */
static Lines source_lines(const char *text)
{
    Lines all = split_lines(text);
    Lines kept = {0};
    bool in_marker_comment = false;
    for (size_t i = 0; i < all.count; i++) {
        char *s = all.line[i];
        bool skip = false;
        if (in_marker_comment) {
            skip = true;
            if (strstr(s, "*/") != NULL)
                in_marker_comment = false;
        } else if (strstr(s, "SOLUTION BEGIN") || strstr(s, "SOLUTION END") ||
                   strstr(s, "SOLUTION STUB")) {
            skip = true;
            const char *open = strstr(s, "/*");
            if (open != NULL && strstr(open + 2, "*/") == NULL)
                in_marker_comment = true;
        }
        if (skip || s[0] == '\0') {
            free(s);
        } else {
            lines_push(&kept, s, all.number[i]);
        }
    }
    free(all.line);
    free(all.number);
    return kept;
}

static void add_sources(Sources *srcs, const char *pattern)
{
    glob_t g;
    if (glob(pattern, 0, NULL, &g) != 0)
        return;
    for (size_t i = 0; i < g.gl_pathc; i++) {
        char *text = read_whole_file(g.gl_pathv[i]);
        if (text == NULL)
            fail_msg("cannot read %s", g.gl_pathv[i]);
        srcs->file = realloc(srcs->file, (srcs->count + 1) * sizeof *srcs->file);
        assert_non_null(srcs->file);
        srcs->file[srcs->count].path = strdup(g.gl_pathv[i]);
        srcs->file[srcs->count].lines = source_lines(text);
        srcs->count++;
        free(text);
    }
    globfree(&g);
}

static void sources_free(Sources *srcs)
{
    for (size_t i = 0; i < srcs->count; i++) {
        free(srcs->file[i].path);
        lines_free(&srcs->file[i].lines);
    }
    free(srcs->file);
    memset(srcs, 0, sizeof *srcs);
}

/* How many of the block's lines (from the first) some source file holds as
 * consecutive lines: the longest such prefix over every file and start. */
static size_t longest_matched_prefix(const Sources *srcs, char *const *block, size_t n)
{
    size_t best = 0;
    for (size_t f = 0; f < srcs->count && best < n; f++) {
        const Lines *src = &srcs->file[f].lines;
        for (size_t s = 0; s < src->count && best < n; s++) {
            size_t k = 0;
            while (k < n && s + k < src->count && strcmp(src->line[s + k], block[k]) == 0)
                k++;
            if (k > best)
                best = k;
        }
    }
    return best;
}

typedef struct {
    int blocks, illustrative, mismatches;
} PageResult;

static PageResult check_page(const char *page)
{
    PageResult r = {0, 0, 0};
    /* docs/NN_name.md -> lessons/NN_name/ */
    const char *base = strrchr(page, '/');
    base = base ? base + 1 : page;
    char name[256];
    size_t len = strlen(base);
    assert_true(len > 3 && len < sizeof name);
    memcpy(name, base, len - 3);
    name[len - 3] = '\0';

    /* The lesson's files as the build links them: its own and those it
     * inherits (tools/lesson-tree.sh), in <build>/lessons/NN_name/. */
    Sources srcs = {0};
    char pattern[1024];
    const char *bin = getenv("BIN_DIR") ? getenv("BIN_DIR") : "build/bin";
    snprintf(pattern, sizeof pattern, "%s/../lessons/%s/*.[ch]", bin, name);
    add_sources(&srcs, pattern);
    if (srcs.count == 0)
        fail_msg("%s: no lesson sources %s for this page", page, pattern);
    add_sources(&srcs, "common/*.[ch]");
    add_sources(&srcs, "common/harness/*.[ch]");

    char *text = read_whole_file(page);
    if (text == NULL)
        fail_msg("cannot read %s", page);
    Lines md = split_lines(text);
    free(text);

    for (size_t i = 0; i < md.count; i++) {
        if (strcmp(md.line[i], C_FENCE) != 0)
            continue;
        bool illustrative = i > 0 && strcmp(md.line[i - 1], ILLUSTRATIVE_MARK) == 0;
        size_t first = i + 1, end = first;
        while (end < md.count && strncmp(md.line[end], FENCE, strlen(FENCE)) != 0)
            end++;
        if (end == md.count)
            fail_msg("%s:%d: ```c block never closed", page, md.number[i]);
        r.blocks++;

        /* The block's non-empty lines. */
        char **block = malloc((end - first + 1) * sizeof *block);
        int *block_number = malloc((end - first + 1) * sizeof *block_number);
        assert_non_null(block);
        assert_non_null(block_number);
        size_t n = 0;
        for (size_t j = first; j < end; j++) {
            if (md.line[j][0] != '\0') {
                block[n] = md.line[j];
                block_number[n] = md.number[j];
                n++;
            }
        }
        const char *first_line = n > 0 ? block[0] : "(empty)";
        if (illustrative) {
            r.illustrative++;
            print_message("%s:%d: illustrative block, not checked: %s\n", page,
                          md.number[i], first_line);
        } else if (n > 0) {
            size_t matched = longest_matched_prefix(&srcs, block, n);
            if (matched < n) {
                r.mismatches++;
                print_error("%s:%d: ```c block starting \"%s\" is not in lesson %s's files nor "
                            "common/: no source file continues with its line %d \"%s\"\n"
                            "  (quote the code exactly, or mark a sketch with %s)\n",
                            page, md.number[i], first_line, name, block_number[matched],
                            block[matched], ILLUSTRATIVE_MARK);
            }
        }
        free(block);
        free(block_number);
        i = end;
    }
    lines_free(&md);
    sources_free(&srcs);
    return r;
}

static void every_c_quote_on_a_lesson_page_is_in_the_code(void **state)
{
    (void)state;
    glob_t g;
    int rc = glob("docs/[0-9][0-9]_*.md", 0, NULL, &g);
    assert_int_equal(rc, 0); /* run from the repository root: docs/NN_*.md exist */
    int blocks = 0, illustrative = 0, mismatches = 0;
    for (size_t i = 0; i < g.gl_pathc; i++) {
        PageResult r = check_page(g.gl_pathv[i]);
        blocks += r.blocks;
        illustrative += r.illustrative;
        mismatches += r.mismatches;
    }
    print_message("%zu pages, %d ```c blocks, %d illustrative (not checked), %d not in the code\n",
                  g.gl_pathc, blocks, illustrative, mismatches);
    globfree(&g);
    assert_true(blocks > 0); /* the pages quote the code: a parser that finds none is broken */
    if (mismatches > 0)
        fail_msg("%d ```c block(s) on the lesson pages differ from the code (listed above)",
                 mismatches);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(every_c_quote_on_a_lesson_page_is_in_the_code),
    };
    return cmocka_run_group_tests_name("docs_match_code", tests, NULL, NULL);
}
