/* test_handout.c: make handout and make grade on every lesson of the series.
 *
 * For each lesson in lessons/ (one cmocka test each):
 *   1. make handout ONLY=1 writes the student's tree into a temporary directory;
 *   2. the handout builds; no line that only the solution has is in it; the
 *      lesson's tests fail, and each failure has a hint that names a function
 *      with a TODO(student) in it; every test with points fails (one that
 *      passes without the student's work must be worth 0 in points.txt);
 *   3. the solution regions are put back: make test runs every test of
 *      points.txt, each passes, and every test that runs is in points.txt;
 *      for the first lesson, make grade too: full marks, as a student's
 *      own grade counts them. (make grade runs each test in a process of
 *      its own, twice the time of make test: every lesson's solution graded
 *      that way, judged, is make grade-check's, which CI runs; make grade
 *      itself, test_grade's, on a made-up lesson.)
 *   4. the mistakes of docs/teaching.md, made on purpose in the solution, fail
 *      exactly the tests that the page says catch them (make test), and the
 *      score the page gives is full marks less those tests' points.
 *
 * Quick by design: handouts leave the other lessons out, build with make -j2,
 * compile only what the series' build has not compiled from the same files
 * (seed_build), and run only the lesson's tests. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <ctype.h>
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "harness/file.h"
#include "json.h"
#include "shell.h"
#include "test_support.h"

#define SHELL_TIMEOUT 300 /* seconds for one build, test or grade */
#define PATH_MAX_LEN 4096
#define MAX_LESSONS 32
#define MAX_LINES 4096
#define MIN_CODE 8 /* shorter lines, like "break;", give nothing away */

/* The make options of every build and run here (see main). */
static char make_opts[64];
/* The first lesson of the series: its handout is graded by make grade too. */
static char first_lesson[256];

/* ---- a deliberate mistake, and the tests that must catch it ---- */

typedef struct {
    const char *lesson;   /* a lesson directory name */
    const char *mistake;  /* the name docs/teaching.md gives it */
    const char *file;     /* in the lesson directory */
    const char *from, *to; /* the edit: from must occur exactly once */
    bool every_run;           /* made in every run; the others with TEST_ALL_MISTAKES=1 */
    const char *page_says;    /* NULL, or what docs/teaching.md says of its score: a format
                                 with the score and the full marks, "... %g of %g" */
    const char *caught_by[48]; /* exactly the tests that fail, NULL-terminated */
} Mistake;

/* docs/teaching.md, "The usual mistakes": each made on purpose, with the
 * tests that must catch it and no other. A run of the tests costs seconds,
 * so a quick set runs every time: lesson 01's (its tests take a second),
 * lesson 02's inverted test, lesson 03's linear z, and lesson 04's two
 * one-character depth-test mistakes, whose lists hold no coverage test:
 * coverage is read from the fragments tested, so a wrong comparison costs
 * the depth tests only. TEST_ALL_MISTAKES=1 makes all of them, to check the
 * page after a change to a lesson or its tests. */
static const Mistake MISTAKES[] = {
    {"01_ybuffer", "the inverted test", "ybuffer.h",
     "return y > stored;",
     "return y < stored;",
     true, NULL,
     {"all_six_orders_agree_except_the_tie",
      "default_run_prints_the_summary_and_writes_three_pictures",
      "default_render_has_the_derived_runs",
      "depth_test_is_strict_larger_y_wins",
      "equal_segments_first_drawn_keeps_every_column",
      "no_arguments_writes_out_01_ybuffer_png",
      "order_312_changes_only_the_tie_column",
      "render_shows_the_runs_on_every_row",
      "scene_puts_world_y_up",
      "segment_at_the_coordinate_limit",
      "segment_wider_than_the_screen_is_clipped_to_it",
      "segments_file_with_the_default_scene_gives_the_default_picture",
      "steps_write_a_render_and_a_ybuffer_per_segment",
      "vertical_and_off_screen_segments_from_a_file",
      "vertical_segment_is_one_column_at_its_nearest_y",
      "ybuffer_after_each_step",
      "ybuffer_strip_is_brightest_where_nearest", NULL}},
    {"01_ybuffer", "the wrong initial value", "ybuffer.c",
     "yb->y[x] = YBUFFER_CLEARED;",
     "yb->y[x] = 0;",
     true, NULL,
     {"default_run_prints_the_summary_and_writes_three_pictures",
      "segment_outside_the_screen_wins_nothing",
      "vertical_segment_is_one_column_at_its_nearest_y",
      "ybuffer_after_each_step",
      "ybuffer_strip_is_brightest_where_nearest", NULL}},
    {"02_zbuffer", "the inverted test", "raster.c",
     "bool passed = d < stored;",
     "bool passed = d > stored;",
     true, NULL,
     {"clear_to_zero_draws_nothing",
      "clear_zero_picture_is_background_only",
      "default_render_matches_expected",
      "depth_is_interpolated_linearly_at_chosen_pixels",
      "depth_of_triangles3_is_linear_on_the_screen",
      "equal_depth_keeps_the_first_face",
      "every_scene_matches_expected",
      "fill_back_to_front_bench_draws_what_render_faces_draws",
      "fill_front_to_back_bench_draws_what_render_faces_draws",
      "huge_triangle_is_at_its_one_depth_everywhere",
      "id_out_round_trips_face_indices",
      "mesh_bench_draws_what_render_faces_draws",
      "obj_file_is_framed_and_coloured",
      "obj_sized_triangle_fills_the_view_or_nothing",
      "painter_gets_triangles3_wrong",
      "screen_covered_many_times_costs_the_screen",
      "separate_buffers_let_the_last_object_cover_the_first",
      "summary_agrees_with_the_written_files",
      "trace_winner_is_the_pictures_colour_on_random_pixels",
      "wrong_pictures_match_expected",
      "zbuffer_resolves_the_cycle_of_triangles3", NULL}},
    {"02_zbuffer", "the wrong initial value", "raster.c",
     "t->depth[i] = INFINITY;",
     "t->depth[i] = 0.0f;",
     false, NULL,
     {"default_render_matches_expected",
      "depth_is_interpolated_linearly_at_chosen_pixels",
      "depth_of_triangles3_is_linear_on_the_screen",
      "equal_depth_keeps_the_first_face",
      "every_scene_matches_expected",
      "fill_back_to_front_bench_draws_what_render_faces_draws",
      "fill_front_to_back_bench_draws_what_render_faces_draws",
      "huge_triangle_is_at_its_one_depth_everywhere",
      "id_out_round_trips_face_indices",
      "mesh_bench_draws_what_render_faces_draws",
      "obj_file_is_framed_and_coloured",
      "obj_sized_triangle_fills_the_view_or_nothing",
      "painter_gets_triangles3_wrong",
      "screen_covered_many_times_costs_the_screen",
      "separate_buffers_let_the_last_object_cover_the_first",
      "summary_agrees_with_the_written_files",
      "trace_winner_is_the_pictures_colour_on_random_pixels",
      "wrong_pictures_match_expected",
      "zbuffer_resolves_the_cycle_of_triangles3", NULL}},
    {"02_zbuffer", "one buffer per object", "raster.c",
     "bool passed = d < stored;",
     "bool passed = d < stored || t->face[i] != face; /* as if each face had its own buffer */",
     false, NULL,
     {"clear_to_zero_draws_nothing",
      "clear_zero_picture_is_background_only",
      "default_render_matches_expected",
      "depth_of_triangles3_is_linear_on_the_screen",
      "equal_depth_keeps_the_first_face",
      "every_scene_matches_expected",
      "fill_front_to_back_bench_draws_what_render_faces_draws",
      "order_does_not_change_the_picture",
      "scene_order_does_not_change_the_picture",
      "separate_buffers_let_the_last_object_cover_the_first",
      "summary_agrees_with_the_written_files",
      "zbuffer_resolves_the_cycle_of_triangles3", NULL}},
    {"02_zbuffer", "holes from float edges", "coverage.c",
     "return e > 0 || (e == 0 && top_left);",
     "(void)top_left;\n    return e > 0;",
     false, NULL,
     {"every_scene_matches_expected",
      "fan_of_thin_triangles_covers_once",
      "fill_back_to_front_bench_draws_what_render_faces_draws",
      "fill_front_to_back_bench_draws_what_render_faces_draws",
      "grid_lines_through_centres_draw_each_pixel_once",
      "grid_on_pixel_centres_follows_top_left",
      "jittered_grid_covers_rectangle_once",
      "jittered_grid_of_quads_covers_rectangle_once",
      "shared_edge_drawn_once_in_every_direction",
      "shared_vertex_drawn_once",
      "top_left_rule_in_every_orientation_and_winding",
      "top_left_rule_on_a_right_triangle", NULL}},
    {"03_perspective_z", "linear z under perspective", "raster.c",
     "return 1 / inv_d;",
     "(void)inv_d;\n    return w.w0 / inv_d0 + w.w1 / inv_d1 + w.w2 / inv_d2;",
     true, NULL,
     {"compare_naive_marks_the_pixels_the_naive_rule_gets_wrong",
      "default_render_matches_expected",
      "depth_out_is_where_the_ray_meets_the_plane",
      "every_scene_by_face_id_matches_expected",
      "huge_triangle_keeps_each_rules_depth_through_the_guard_band",
      "inverse_depth_is_linear_at_chosen_pixels",
      "negated_w_shows_the_farther_strip_everywhere",
      "perspective_rule_puts_the_seam_on_the_line",
      "triangles3_depth_is_where_the_ray_meets_the_plane",
      "worked_example_gives_2_5_and_naive_gives_2_7", NULL}},
    {"04_scanline_inverse_z", "the inverted test", "depth_buffer.c",
     "bool passed = inv_d > stored;",
     "bool passed = inv_d < stored;",
     true, "`inv_d < stored` scores %g of %g",
     {"an_obj_mesh_agrees_with_lesson_03",
      "ascii_and_trace_speak_of_inverse_depth",
      "clear_to_zero_loses_to_a_far_surface",
      "default_run_draws_the_walls_and_finds_the_front_object",
      "depth_out_writes_view_depth_not_its_inverse",
      "equal_depth_keeps_the_first_face",
      "equal_depth_keeps_the_first_fragment",
      "every_built_in_scene_agrees_with_lesson_03",
      "every_scene_matches_its_expected_pictures",
      "far_plane_discards_before_the_test",
      "fill_back_to_front_bench_draws_what_render_faces_draws",
      "fill_front_to_back_bench_draws_what_render_faces_draws",
      "huge_triangle_is_at_its_one_depth_everywhere",
      "inverse_depth_is_linear_across_the_span",
      "inverse_depth_is_linear_down_the_edges",
      "larger_inverse_depth_wins",
      "mesh_bench_draws_what_render_faces_draws",
      "obj_sized_triangle_fills_the_view_or_nothing",
      "screen_covered_many_times_costs_the_screen",
      "screen_polygon_at_depth_6_shows_only_around_the_triangle",
      "shade_depth_spreads_greys_over_the_drawn_depths",
      "stepping_along_a_long_span_stays_accurate",
      "trace_winner_is_the_pictures_colour_on_random_pixels",
      "triangle_at_depth_5_in_front_of_nothing",
      "two_buffers_do_not_depend_on_drawing_order", NULL}},
    {"04_scanline_inverse_z", "a tie to the later fragment", "depth_buffer.c",
     "bool passed = inv_d > stored;",
     "bool passed = inv_d >= stored;",
     true, "`>=` scores %g of %g",
     {"equal_depth_keeps_the_first_face",
      "equal_depth_keeps_the_first_fragment",
      "every_built_in_scene_agrees_with_lesson_03",
      "every_scene_matches_its_expected_pictures", NULL}},
    {"04_scanline_inverse_z", "the wrong initial value", "depth_buffer.h",
     "#define CLEARED_INV_DEPTH 0.0f",
     "#define CLEARED_INV_DEPTH INFINITY",
     false, NULL,
     {"an_obj_mesh_agrees_with_lesson_03",
      "ascii_and_trace_speak_of_inverse_depth",
      "clear_to_zero_loses_to_a_far_surface",
      "clear_to_zero_means_nothing_drawn",
      "default_run_draws_the_walls_and_finds_the_front_object",
      "depth_out_writes_view_depth_not_its_inverse",
      "equal_depth_keeps_the_first_face",
      "equal_depth_keeps_the_first_fragment",
      "every_built_in_scene_agrees_with_lesson_03",
      "every_scene_matches_its_expected_pictures",
      "far_plane_discards_before_the_test",
      "fill_back_to_front_bench_draws_what_render_faces_draws",
      "fill_front_to_back_bench_draws_what_render_faces_draws",
      "huge_triangle_is_at_its_one_depth_everywhere",
      "inverse_depth_is_linear_across_the_span",
      "inverse_depth_is_linear_down_the_edges",
      "larger_inverse_depth_wins",
      "mesh_bench_draws_what_render_faces_draws",
      "nothing_at_the_centre_is_reported",
      "obj_sized_triangle_fills_the_view_or_nothing",
      "screen_covered_many_times_costs_the_screen",
      "screen_polygon_at_depth_6_shows_only_around_the_triangle",
      "shade_depth_spreads_greys_over_the_drawn_depths",
      "stepping_along_a_long_span_stays_accurate",
      "trace_winner_is_the_pictures_colour_on_random_pixels",
      "triangle_at_depth_5_in_front_of_nothing",
      "two_buffers_do_not_depend_on_drawing_order", NULL}},
};

/* ---- files ---- */

static double cpu_seconds(const struct rusage *u) /* user and system */
{
    return (double)(u->ru_utime.tv_sec + u->ru_stime.tv_sec) +
           (double)(u->ru_utime.tv_usec + u->ru_stime.tv_usec) / 1e6;
}

/* run_shell; with TEST_TIMING=1 in the environment it prints how long each
 * command took and the CPU time it used (where the seconds of this test go). */
static ShellResult timed_shell(const char *dir, const char *command)
{
    struct timespec start;
    struct rusage before, after;
    clock_gettime(CLOCK_MONOTONIC, &start);
    getrusage(RUSAGE_CHILDREN, &before);
    ShellResult r = run_shell(dir, SHELL_TIMEOUT, "%s", command);
    double took = seconds_since(&start);
    getrusage(RUSAGE_CHILDREN, &after);
    const char *timing = getenv("TEST_TIMING");
    if (timing && strcmp(timing, "1") == 0)
        print_message("%6.2f s  %6.2f s CPU  %.100s\n",
                      took, cpu_seconds(&after) - cpu_seconds(&before), command);
    return r;
}

static ShellResult shell(const char *dir, const char *fmt, ...)
{
    char command[8192];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(command, sizeof command, fmt, ap);
    va_end(ap);
    return timed_shell(dir, command);
}

static void shell_ok(const char *dir, const char *fmt, ...)
{
    char command[8192];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(command, sizeof command, fmt, ap);
    va_end(ap);
    ShellResult r = timed_shell(dir, command);
    if (r.status != 0)
        fail_msg("`%s` in %s: status %d\n%s", command, dir ? dir : ".", r.status, r.output);
    shell_result_free(&r);
}

/* "$PWD/$TEST_OUTPUT/tmp/<name>", fresh: the commands run in other directories. */
static void abs_test_dir(const char *name, char *out, size_t size)
{
    char here[PATH_MAX_LEN];
    if (!getcwd(here, sizeof here))
        fail_msg("getcwd failed");
    const char *dir = test_dir(name);
    int n = dir[0] == '/' ? snprintf(out, size, "%s", dir) : snprintf(out, size, "%s/%s", here, dir);
    if (n < 0 || (size_t)n >= size)
        fail_msg("path too long: %s", dir);
}

/* ---- the lines only the solution has (an oracle of its own, in C) ---- */

typedef struct {
    char *code[MAX_LINES];
    char where[MAX_LINES][128];
    int n;
    char *outside[MAX_LINES * 4]; /* lines outside regions, or in stubs */
    int n_outside;
} SolutionLines;

/* A line's code: trimmed, without a trailing comment and a final ";" (a
 * header and its declaration are one line); in place. */
static char *code_of(char *s)
{
    while (isspace((unsigned char)*s))
        s++;
    char *c = strstr(s, "/*");
    if (c && c > s)
        *c = '\0';
    c = strstr(s, "//");
    if (c && c > s)
        *c = '\0';
    size_t n = strlen(s);
    while (n > 0 && isspace((unsigned char)s[n - 1]))
        s[--n] = '\0';
    if (n > 0 && s[n - 1] == ';')
        s[--n] = '\0';
    return s;
}

/* Worth looking for: MIN_CODE characters or more, not a comment, and a name
 * in it that is not a keyword of C ("} else {" is in every file). */
static bool significant(const char *c)
{
    static const char *const keywords[] = {
        "auto", "bool", "break", "case", "char", "const", "continue", "default", "do",
        "double", "else", "enum", "extern", "false", "float", "for", "goto", "if", "inline",
        "int", "long", "register", "restrict", "return", "short", "signed", "sizeof",
        "static", "struct", "switch", "true", "typedef", "union", "unsigned", "void",
        "volatile", "while", "NULL"};
    if (strlen(c) < MIN_CODE || c[0] == '*' || strncmp(c, "/*", 2) == 0 ||
        strncmp(c, "//", 2) == 0 || strncmp(c, "<!--", 4) == 0)
        return false;
    while (*c) {
        if (!(isalpha((unsigned char)*c) || *c == '_')) {
            c++;
            continue;
        }
        size_t n = 0;
        while (isalnum((unsigned char)c[n]) || c[n] == '_')
            n++;
        bool keyword = false;
        for (size_t k = 0; k < sizeof keywords / sizeof keywords[0]; k++)
            keyword |= strlen(keywords[k]) == n && strncmp(c, keywords[k], n) == 0;
        if (!keyword)
            return true;
        c += n;
    }
    return false;
}

static void collect_regions(SolutionLines *s, const char *path)
{
    char *text = read_text(path);
    bool md = strstr(path, ".md") != NULL;
    const char *close = md ? "-->" : "*/";
    enum { OUT, HINT, CODE, STUB } state = OUT;
    int line_no = 0;
    for (char *line = strtok(text, "\n"); line; line = strtok(NULL, "\n")) {
        line_no++;
        char *c = code_of(line);
        bool marker = strstr(line, "SOLUTION BEGIN:") || strstr(line, "SOLUTION END") ||
                      strstr(line, "SOLUTION STUB");
        if (state == HINT) {
            if (strstr(line, close))
                state = CODE;
            continue;
        }
        if (state == STUB) {
            if (strcmp(c, close) == 0)
                state = CODE;
            else if (s->n_outside < MAX_LINES * 4)
                s->outside[s->n_outside++] = strdup(c);
            continue;
        }
        if (marker && strstr(line, "SOLUTION BEGIN:")) {
            state = strstr(line, close) ? CODE : HINT;
            continue;
        }
        if (marker && strstr(line, "SOLUTION STUB")) {
            state = STUB;
            continue;
        }
        if (marker && strstr(line, "SOLUTION END")) {
            state = OUT;
            continue;
        }
        if (state == CODE) {
            /* The solution lines are those of the code: a page's region only
             * hides a quote of it. */
            if (!md && significant(c) && s->n < MAX_LINES) {
                s->code[s->n] = strdup(c);
                snprintf(s->where[s->n], sizeof s->where[0], "%.100s:%d", path, line_no);
                s->n++;
            }
        } else if (s->n_outside < MAX_LINES * 4) {
            s->outside[s->n_outside++] = strdup(c);
        }
    }
    free(text);
}

static bool is_outside(const SolutionLines *s, const char *code)
{
    for (int i = 0; i < s->n_outside; i++)
        if (strcmp(s->outside[i], code) == 0)
            return true;
    return false;
}

static void free_solution_lines(SolutionLines *s)
{
    for (int i = 0; i < s->n; i++)
        free(s->code[i]);
    for (int i = 0; i < s->n_outside; i++)
        free(s->outside[i]);
    free(s);
}

/* Fails the test if a file under dir (recursively) holds a solution line.
 * Other lessons (a handout keeps, as they are, those its tests run) are not
 * searched: in lessons/, only the lesson itself is. */
static void expect_no_solution_line(const SolutionLines *s, const char *dir, const char *lesson,
                                    int *files)
{
    size_t dir_len = strlen(dir);
    bool in_lessons = dir_len >= 8 && strcmp(dir + dir_len - 8, "/lessons") == 0;
    DIR *d = opendir(dir);
    if (!d)
        fail_msg("cannot read the directory %s", dir);
    struct dirent *e;
    while ((e = readdir(d)) != NULL) {
        if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0 ||
            strcmp(e->d_name, "build") == 0)
            continue;
        char path[PATH_MAX_LEN];
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        struct stat st;
        if (stat(path, &st) != 0)
            continue;
        if (S_ISDIR(st.st_mode)) {
            if (!in_lessons || strcmp(e->d_name, lesson) == 0)
                expect_no_solution_line(s, path, lesson, files);
            continue;
        }
        const char *dot = strrchr(e->d_name, '.');
        if (dot && (strcmp(dot, ".png") == 0 || strcmp(dot, ".pfm") == 0 || strcmp(dot, ".pgm") == 0))
            continue;
        (*files)++;
        char *text = read_text(path);
        int line_no = 0;
        for (char *line = strtok(text, "\n"); line; line = strtok(NULL, "\n")) {
            line_no++;
            char *c = code_of(line);
            for (int i = 0; i < s->n; i++)
                if (strcmp(c, s->code[i]) == 0 && !is_outside(s, c)) {
                    char msg[PATH_MAX_LEN + 256];
                    snprintf(msg, sizeof msg, "%s:%d holds %s, a line of the solution: %s", path,
                             line_no, s->where[i], c);
                    free(text);
                    closedir(d);
                    fail_msg("%s", msg);
                }
        }
        free(text);
    }
    closedir(d);
}

/* Files, not directories (a lesson's extras/ is one). */
static bool is_regular_file(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 && S_ISREG(st.st_mode);
}

/* The lesson's files with regions (and its page, if it has some). */
static SolutionLines *solution_lines(const char *lesson)
{
    SolutionLines *s = calloc(1, sizeof *s);
    assert_non_null(s);
    char dir[PATH_MAX_LEN];
    snprintf(dir, sizeof dir, "lessons/%s", lesson);
    DIR *d = opendir(dir);
    assert_non_null(d);
    struct dirent *e;
    while ((e = readdir(d)) != NULL)
        if (e->d_name[0] != '.' && is_regular_file(path_join(dir, e->d_name)))
            collect_regions(s, path_join(dir, e->d_name));
    closedir(d);
    char page[PATH_MAX_LEN];
    snprintf(page, sizeof page, "docs/%s.md", lesson);
    if (file_exists(page))
        collect_regions(s, page);
    /* The files it inherits come solved in the handout: every line of them
     * is outside (tools/lesson-tree.sh lists "<path> <where it lives>"). */
    char command[PATH_MAX_LEN + 64];
    snprintf(command, sizeof command, "sh tools/lesson-tree.sh list %s", lesson);
    FILE *list = popen(command, "r");
    assert_non_null(list);
    char row[2 * PATH_MAX_LEN], rel[PATH_MAX_LEN], where[PATH_MAX_LEN];
    while (fgets(row, sizeof row, list)) {
        if (sscanf(row, "%4095s %4095s", rel, where) != 2 || strncmp(where, dir, strlen(dir)) == 0)
            continue;
        char *text = read_text(where);
        for (char *line = strtok(text, "\n"); line; line = strtok(NULL, "\n"))
            if (s->n_outside < MAX_LINES * 4)
                s->outside[s->n_outside++] = strdup(code_of(line));
        free(text);
    }
    if (pclose(list) != 0)
        fail_msg("`%s` failed", command);
    return s;
}

/* ---- results.json ---- */

typedef struct {
    double score, max;
    JsonValue json;
} Grade;

static const JsonValue *field(const JsonValue *obj, const char *key, JsonType type)
{
    const JsonValue *f = json_get(obj, key);
    if (!f || f->type != type)
        fail_msg("results.json: \"%s\" is missing or not a %s", key, json_type_name(type));
    return f;
}

/* Reads build/grade/results.json (a real JSON parser, not a grep) and checks
 * it has the fields Gradescope reads: tests[] of {name, score, max_score,
 * output}, and the overall score, which is the sum of the tests' scores. */
static Grade read_grade(const char *build)
{
    char *text = read_text(path_join(build, "grade/results.json"));
    Grade g = {0, 0, {0}};
    char why[256];
    if (!json_parse(text, strlen(text), &g.json, why, sizeof why))
        fail_msg("results.json is not JSON: %s", why);
    free(text);
    const JsonValue *tests = field(&g.json, "tests", JSON_ARRAY);
    if (tests->count == 0)
        fail_msg("results.json: no tests");
    for (size_t i = 0; i < tests->count; i++) {
        field(&tests->items[i], "name", JSON_STRING);
        field(&tests->items[i], "output", JSON_STRING);
        g.score += field(&tests->items[i], "score", JSON_NUMBER)->number;
        g.max += field(&tests->items[i], "max_score", JSON_NUMBER)->number;
    }
    if (field(&g.json, "score", JSON_NUMBER)->number != g.score)
        fail_msg("results.json: the score %g is not the sum of the tests' scores, %g",
                 field(&g.json, "score", JSON_NUMBER)->number, g.score);
    return g;
}

/* ---- the steps ---- */

/* What the handout's lesson asks the student to write, as " name() name2()":
 * each function that holds a TODO(student) (the last function header before
 * it: a line at column 0 with a "(" and no ";" at its end), and for a TODO
 * outside functions, the variable or macro its stub defines ("const T NAME =
 * ...", "#define NAME ..."). */
static void todo_functions(const char *lesson_dir, char *out, size_t size)
{
    out[0] = '\0';
    DIR *d = opendir(lesson_dir);
    assert_non_null(d);
    struct dirent *e;
    while ((e = readdir(d)) != NULL) {
        char file[PATH_MAX_LEN];
        snprintf(file, sizeof file, "%s/%s", lesson_dir, e->d_name);
        if (e->d_name[0] == '.' || !is_regular_file(file))
            continue;
        char *text = read_text(file);
        char current[256] = "";
        bool top_level_todo = false;
        for (char *line = strtok(text, "\n"); line; line = strtok(NULL, "\n")) {
            size_t n = strlen(line);
            char *paren = strchr(line, '(');
            char *equals = strchr(line, '=');
            char *name = NULL;
            size_t name_len = 0;
            if (isalpha((unsigned char)line[0]) && paren && line[n - 1] != ';' &&
                (!equals || equals > paren)) {
                /* A function's header: its name is just before the "(". */
                name = paren;
                while (name > line && (isalnum((unsigned char)name[-1]) || name[-1] == '_'))
                    name--;
                name_len = (size_t)(paren - name);
                snprintf(current, sizeof current, "%.*s()", (int)name_len, name);
            } else if (top_level_todo && strncmp(line, "#define ", 8) == 0) {
                /* The stub of a region that is a macro: "#define NAME value". */
                snprintf(current, sizeof current, "%.*s", (int)strcspn(line + 8, " ("), line + 8);
                if (strlen(out) + strlen(current) + 2 < size) {
                    strcat(out, " ");
                    strcat(out, current);
                }
                top_level_todo = false;
                current[0] = '\0';
            } else if (top_level_todo && isalpha((unsigned char)line[0]) && equals) {
                /* The stub of a region outside functions: a variable, "T NAME = ...". */
                name = equals;
                while (name > line && name[-1] == ' ')
                    name--;
                char *end = name;
                while (name > line && (isalnum((unsigned char)name[-1]) || name[-1] == '_'))
                    name--;
                snprintf(current, sizeof current, "%.*s", (int)(end - name), name);
                if (strlen(out) + strlen(current) + 2 < size) {
                    strcat(out, " ");
                    strcat(out, current);
                }
                top_level_todo = false;
                current[0] = '\0';
            }
            if (strstr(line, "TODO(student):")) {
                if (line[0] == '/')
                    top_level_todo = true;
                else if (current[0] && strlen(out) + strlen(current) + 2 < size) {
                    strcat(out, " ");
                    strcat(out, current);
                }
            }
        }
        free(text);
    }
    closedir(d);
}

/* The tests of tests/<lesson>/points.txt, each with its points, and their sum. */
typedef struct {
    int n;
    char name[1024][256];
    double points[1024];
    double full;
} Points;

static void read_points(const char *lesson, Points *p)
{
    char path[PATH_MAX_LEN];
    snprintf(path, sizeof path, "tests/%s/points.txt", lesson);
    char *text = read_text(path);
    p->n = 0;
    p->full = 0;
    for (char *line = strtok(text, "\n"); line; line = strtok(NULL, "\n")) {
        char name[256];
        double points;
        if (line[0] == '#' || sscanf(line, "%255s %lf", name, &points) != 2)
            continue;
        if (p->n == 1024)
            fail_msg("%s: more than 1024 tests", path);
        snprintf(p->name[p->n], sizeof p->name[0], "%s", name);
        p->points[p->n++] = points;
        p->full += points;
    }
    free(text);
    if (p->n == 0 || p->full <= 0)
        fail_msg("%s gives no test any points", path);
}

static int points_index(const Points *p, const char *name)
{
    for (int i = 0; i < p->n; i++)
        if (strcmp(p->name[i], name) == 0)
            return i;
    return -1;
}

/* make test in the handout: it fails; every failed test gets a hint line
 * naming one of the functions to write; and every test with points fails
 * (a test that passes without the student's work is worth 0 points). */
static void expect_tests_fail_with_hints(const char *h, const char *lesson)
{
    ShellResult r = shell(h, "make %s test LESSON=%.2s", make_opts, lesson);
    if (r.status == 0)
        fail_msg("make test LESSON=%.2s passed on the handout, with the solution taken out", lesson);
    char todo[2048];
    todo_functions(path_join(h, path_join("lessons", lesson)), todo, sizeof todo);
    if (!todo[0])
        fail_msg("no function with a TODO(student) in the handout of %s", lesson);
    int failed = 0;
    for (char *p = strstr(r.output, "[  FAILED  ] "); p; p = strstr(p + 1, "[  FAILED  ] ")) {
        char name[256];
        if (sscanf(p + strlen("[  FAILED  ] "), "%255[A-Za-z0-9_]", name) != 1 ||
            !(isalpha((unsigned char)name[0]) || name[0] == '_'))
            continue; /* "[  FAILED  ] 3 test(s), listed below:" */
        char want[300];
        snprintf(want, sizeof want, "hint: %s checks ", name);
        char *hint = strstr(r.output, want);
        if (!hint)
            fail_msg("the failed test %s has no hint line (\"%s...\") in make test's output", name,
                     want);
        char line[1024];
        sscanf(hint, "%1023[^\n]", line);
        char functions[2048];
        snprintf(functions, sizeof functions, "%s", todo);
        bool names_one = false;
        for (char *f = strtok(functions, " "); f; f = strtok(NULL, " "))
            names_one |= strstr(line, f) != NULL;
        if (!names_one)
            fail_msg("%s\nnames none of the functions to write:%s", line, todo);
        failed++;
    }
    if (failed == 0)
        fail_msg("make test failed on the handout, but no test did:\n%s", r.output);
    static Points points;
    read_points(lesson, &points);
    int n = 0; /* the tests with points */
    for (int i = 0; i < points.n; i++) {
        if (points.points[i] <= 0)
            continue;
        n++;
        char want[300];
        snprintf(want, sizeof want, "[  FAILED  ] %.255s\n", points.name[i]);
        if (!strstr(r.output, want))
            fail_msg("%s passes on the untouched handout of %s, yet tests/%s/points.txt gives it "
                     "points: a student would get them for nothing", points.name[i], lesson,
                     lesson);
    }
    /* So every point comes from a test that fails with the stubs in place
     * (the issue asked for at least half): said, with the count of tests. */
    if (n == 0 || points.full <= 0)
        fail_msg("tests/%s/points.txt gives no test any points", lesson);
    print_message("%s: the %d tests with points (of %d in points.txt) all fail on the untouched "
                  "handout: all %g points come from them\n", lesson, n, points.n, points.full);
    /* The points table of docs/teaching.md says these numbers. */
    char row[256];
    snprintf(row, sizeof row, "| %.2s | %d | %d | %g |\n", lesson, points.n, n, points.full);
    char *guide = read_text("docs/teaching.md");
    bool said = strstr(guide, row) != NULL;
    free(guide);
    if (!said)
        fail_msg("docs/teaching.md's points table should have the row\n%s", row);
    shell_result_free(&r);
}

/* A title, then the lines of text (which begins with a newline), one print
 * each: cmocka cuts a message at 1024 characters. */
static void print_lines(const char *title, char *text)
{
    print_error("%s%s\n", title, text[0] ? "" : " none");
    for (char *line = strtok(text, "\n"); line; line = strtok(NULL, "\n"))
        print_error("%s\n", line);
}

/* Whether output holds the line "<tag> name". */
static bool has_line(const char *output, const char *tag, const char *name)
{
    char line[320];
    snprintf(line, sizeof line, "%s %s\n", tag, name);
    for (const char *at = output; (at = strstr(at, line)) != NULL; at += strlen(line))
        if (at == output || at[-1] == '\n')
            return true;
    return false;
}

/* Whether test `name` passed in the output of make test: "[       OK ] name"
 * (or skipped) from one of the programs that ran it (a test passes if a
 * program that has it passed it, as make grade counts). ran: one started it. */
static bool passed_in(const char *output, const char *name, bool *ran)
{
    *ran = has_line(output, "[ RUN      ]", name);
    return has_line(output, "[       OK ]", name) || has_line(output, "[  SKIPPED ]", name);
}

/* The mistake made in the solution, the lesson's tests run by make test (each
 * program once, not each test alone as make grade runs them: half the time):
 * the tests that fail must be exactly m's, and the score, full's less their
 * points, what docs/teaching.md says. That make grade takes a failed test's
 * points, and only its, test_grade checks. */
static void expect_mistake_caught(const char *h, const Mistake *m, const Points *full)
{
    char path[PATH_MAX_LEN * 2];
    snprintf(path, sizeof path, "%s/lessons/%s/%s", h, m->lesson, m->file);
    char *text = read_text(path);
    char *at = strstr(text, m->from);
    if (!at || strstr(at + 1, m->from))
        fail_msg("%s: \"%s\" should occur exactly once in lessons/%s/%s (update MISTAKES)",
                 m->mistake, m->from, m->lesson, m->file);
    size_t n = strlen(text) - strlen(m->from) + strlen(m->to) + 1;
    char *broken = malloc(n);
    assert_non_null(broken);
    snprintf(broken, n, "%.*s%s%s", (int)(at - text), text, m->to, at + strlen(m->from));
    write_text(path, broken);
    ShellResult r = shell(h, "make %s test LESSON=%.2s", make_opts, m->lesson);
    write_text(path, text);
    free(broken);
    free(text);
    if (!strstr(r.output, " passed, ") || !strstr(r.output, " failed"))
        fail_msg("make test with %s did not run the tests: status %d\n%s", m->mistake, r.status,
                 r.output);

    double lost = 0, score = 0;
    /* Every difference from the list, and the tests that fail now, in one
     * message: what to look at, or to copy into MISTAKES if the change was meant. */
    char unexpected[8192] = "", missed[8192] = "", failing[16384] = "";
    for (int i = 0; i < full->n; i++) { /* every test of the lesson: all are in points.txt */
        const char *name = full->name[i];
        bool ran, passed = passed_in(r.output, name, &ran);
        if (!ran)
            fail_msg("make test with %s: %s did not run\n%s", m->mistake, name, r.output);
        bool listed = false;
        for (int k = 0; m->caught_by[k]; k++)
            listed |= strcmp(m->caught_by[k], name) == 0;
        char *into = listed && passed ? missed : !listed && !passed ? unexpected : NULL;
        if (into && strlen(into) + strlen(name) + 4 < sizeof unexpected)
            strcat(strcat(into, "\n  "), name);
        if (!passed && strlen(failing) + strlen(name) + 8 < sizeof failing)
            strcat(strcat(strcat(failing, "\n      \""), name), "\",");
        double points = full->points[i];
        lost += listed ? points : 0;
        score += passed ? points : 0;
    }
    shell_result_free(&r);
    if (unexpected[0] || missed[0]) {
        print_error("%s (%s, %s): the tests that catch it changed.\n", m->mistake, m->lesson,
                    m->file);
        print_lines("failed, and not in its list:", unexpected);
        print_lines("in its list, and passed:", missed);
        print_lines("the tests that fail now:", failing);
        fail_msg("%s (%s): update MISTAKES with the tests that fail now (above), if the "
                 "change was meant", m->mistake, m->lesson);
    }
    for (int k = 0; m->caught_by[k]; k++)
        if (points_index(full, m->caught_by[k]) < 0)
            fail_msg("%s: no test %s in lesson %s", m->mistake, m->caught_by[k], m->lesson);
    if (lost <= 0)
        fail_msg("%s: its tests are worth no points", m->mistake);
    if (m->page_says) {
        char said[256];
        snprintf(said, sizeof said, m->page_says, score, full->full);
        char *guide = read_text("docs/teaching.md");
        bool found = strstr(guide, said) != NULL;
        free(guide);
        if (!found)
            fail_msg("%s: docs/teaching.md should say \"%s\"", m->mistake, said);
    }
}

/* What a handout compiles from the same files as the series' own build
 * (common/, tools/, the tests, the lessons it keeps as they are, what it
 * inherits solved): copied from that build before the handout's first make,
 * so that make finds it up to date (tests/tools/seed_build.sh; nothing that
 * reads a file of the handout's own that differs). From the first handout's
 * build instead when the series' is not build/ with the default flags (make
 * sanitize's is build/sanitize, with other flags). */
static char seed[PATH_MAX_LEN * 2];

static void seed_build(const char *h)
{
    if (!seed[0]) {
        const char *bin = getenv("BIN_DIR");
        bool plain = (!bin || strcmp(bin, "build/bin") == 0) && !getenv("ASAN_OPTIONS");
        if (plain && !getcwd(seed, sizeof seed))
            fail_msg("getcwd failed");
        if (!plain) {
            snprintf(seed, sizeof seed, "%s", h); /* the first handout: nothing to copy yet */
            return;
        }
    }
    shell_ok(NULL, "sh tests/tools/seed_build.sh %s %s", seed, h);
}

/* No page of handout h links to a file the handout does not hold (a later
 * lesson's page, a diff that shows the lesson's code, the teacher's guide):
 * make handout keeps such a link's words alone (tools/md-links.awk). */
static void expect_no_dangling_link(const char *h, const char *lesson)
{
    ShellResult r = shell(h, "find . -name '*.md' ! -path './build/*' | sort | while read -r f; do "
                             "awk -v dir=\"$(dirname \"$f\")\" -v mode=check -f tools/md-links.awk "
                             "\"$f\"; done");
    if (r.output[0])
        fail_msg("the handout of %s has links to what it does not hold:\n%s", lesson, r.output);
    shell_result_free(&r);
}

/* The handout's README is the student's: its section for teachers (and its
 * word of the teacher's guide) gives way to how to get one's score. */
static void expect_readme_for_the_student(const char *h, const char *lesson)
{
    char path[2 * PATH_MAX_LEN + 32], command[64];
    snprintf(path, sizeof path, "%s/README.md", h);
    char *text = read_text(path);
    snprintf(command, sizeof command, "make grade LESSON=%.2s ", lesson);
    if (strstr(text, "For teachers") || strstr(text, "teaching.md"))
        fail_msg("the README of the handout of %s still speaks to the teacher", lesson);
    if (!strstr(text, "## Your score") || !strstr(text, command))
        fail_msg("the README of the handout of %s does not say how to get a score (%s)", lesson,
                 command);
    free(text);
}

/* make handout LESSON=NN with no option: the graded handout. It is written
 * (so handout.sh found no answer to a region in it), holds this lesson and
 * the earlier ones, and nothing of a later lesson: no code, test, page,
 * picture or diff. */
static void default_handout(void **state)
{
    const char *lesson = *state;
    char base[PATH_MAX_LEN], h[PATH_MAX_LEN + 8];
    char name[300];
    snprintf(name, sizeof name, "default_handout_%.250s", lesson);
    abs_test_dir(name, base, sizeof base);
    snprintf(h, sizeof h, "%s/h", base);
    shell_ok(NULL, "make --no-print-directory handout LESSON=%.2s DEST=%s", lesson, h);
    DIR *d = opendir("lessons");
    assert_non_null(d);
    struct dirent *e;
    char names[2048] = ""; /* find's tests for the later lessons' files, one -o another */
    while ((e = readdir(d)) != NULL) {
        if (!isdigit((unsigned char)e->d_name[0]) || !isdigit((unsigned char)e->d_name[1]))
            continue;
        char path[2 * PATH_MAX_LEN];
        bool later = strncmp(e->d_name, lesson, 2) > 0;
        snprintf(path, sizeof path, "%s/lessons/%s", h, e->d_name);
        if (file_exists(path) == later)
            fail_msg("the default handout of %s %s lessons/%s", lesson,
                     later ? "holds the later" : "lacks the earlier", e->d_name);
        size_t used = strlen(names);
        if (later)
            snprintf(names + used, sizeof names - used, "%s-name '%.2s_*' -o -name '*_%.2s.*'",
                     used ? " -o " : "", e->d_name, e->d_name);
    }
    closedir(d);
    if (names[0]) {
        ShellResult r = shell(h, "find tests docs \\( %s \\) | head -3", names);
        if (r.output[0])
            fail_msg("the default handout of %s holds files of a later lesson:\n%s", lesson,
                     r.output);
        shell_result_free(&r);
    }
    expect_no_dangling_link(h, lesson);
    expect_readme_for_the_student(h, lesson);
}

static void handout_round_trip(void **state)
{
    const char *lesson = *state;
    char base[PATH_MAX_LEN], h[PATH_MAX_LEN + 8], build[PATH_MAX_LEN + 16];
    char name[300];
    snprintf(name, sizeof name, "handout_%.250s", lesson);
    abs_test_dir(name, base, sizeof base);
    snprintf(h, sizeof h, "%s/h", base);
    snprintf(build, sizeof build, "%s/build", h);

    /* 1. The handout, alone. */
    shell_ok(NULL, "sh tools/handout.sh --only --dest %s %s", h, lesson);

    /* 2. It builds; no solution line in it; its tests fail, with hints. */
    seed_build(h);
    shell_ok(h, "make %s", make_opts);
    SolutionLines *s = solution_lines(lesson);
    if (s->n == 0)
        fail_msg("lessons/%s has no solution line: no region?", lesson);
    int files = 0;
    expect_no_solution_line(s, h, lesson, &files);
    assert_true(files > 10);
    free_solution_lines(s);
    expect_no_dangling_link(h, lesson);
    expect_tests_fail_with_hints(h, lesson);

    /* 3. The solution put back: every test of points.txt runs and passes, and
     * every test that runs is in points.txt; for the first lesson make grade
     * too, full marks. Only the files that differ are copied (those with a
     * solution region): the others keep their times, and make compiles again
     * only what reads a file that changed, as it would for a student who
     * wrote the regions. */
    shell_ok(NULL,
             "cd lessons/%s && find . -type f | while read -r f; do "
             "cmp -s \"$f\" \"%s/lessons/%s/$f\" || "
             "{ mkdir -p \"$(dirname \"%s/lessons/%s/$f\")\" && cp \"$f\" \"%s/lessons/%s/$f\"; } "
             "|| exit 1; done",
             lesson, h, lesson, h, lesson, h, lesson);
    static Points full;
    read_points(lesson, &full);
    ShellResult r = shell(h, "make %s test LESSON=%.2s", make_opts, lesson);
    if (r.status != 0)
        fail_msg("make test with the solution of %s: status %d\n%s", lesson, r.status, r.output);
    for (int i = 0; i < full.n; i++) {
        bool ran, passed = passed_in(r.output, full.name[i], &ran);
        if (!ran || !passed)
            fail_msg("with the solution, %s of tests/%s/points.txt %s:\n%s", full.name[i], lesson,
                     ran ? "failed" : "did not run", r.output);
    }
    const char *run = "[ RUN      ] ";
    for (const char *at = strstr(r.output, run); at; at = strstr(at + 1, run)) {
        char test[256];
        if (sscanf(at + strlen(run), "%255[A-Za-z0-9_]", test) == 1 &&
            points_index(&full, test) < 0)
            fail_msg("%s is not in tests/%s/points.txt: every test should be", test, lesson);
    }
    shell_result_free(&r);
    if (strcmp(lesson, first_lesson) == 0) {
        shell_ok(h, "make %s grade LESSON=%.2s", make_opts, lesson);
        Grade g = read_grade(build);
        if (g.max != full.full || g.score != g.max)
            fail_msg("make grade with the solution of %s: %g of %g points (points.txt: %g)",
                     lesson, g.score, g.max, full.full);
        const JsonValue *tests = json_get(&g.json, "tests");
        for (size_t i = 0; i < tests->count; i++) {
            const JsonValue *t = &tests->items[i];
            if (strcmp(json_get(t, "status")->string, "passed") != 0)
                fail_msg("make grade with the solution: %s failed:\n%s",
                         json_get(t, "name")->string, json_get(t, "output")->string);
        }
        json_free(&g.json);
    }

    /* 4. Each mistake of docs/teaching.md costs exactly its tests' points. */
    const char *all = getenv("TEST_ALL_MISTAKES");
    bool every_mistake = all && strcmp(all, "1") == 0;
    for (size_t k = 0; k < sizeof MISTAKES / sizeof MISTAKES[0]; k++)
        if (strcmp(MISTAKES[k].lesson, lesson) == 0 && (MISTAKES[k].every_run || every_mistake))
            expect_mistake_caught(h, &MISTAKES[k], &full);
}

/* The exercises at the end of each lesson page: 3 to 5, from a warm-up to a
 * challenge, and at least one names a test with points in the lesson's
 * points file: a test the handout carries checks it. */
static void exercises_go_from_warm_up_to_challenge_and_a_test_checks_one(void **state)
{
    const char *lesson = *state;
    char page[PATH_MAX_LEN];
    snprintf(page, sizeof page, "docs/%.200s.md", lesson);
    char *text = read_text(page);
    char *section = strstr(text, "\n## Exercises\n");
    if (!section)
        fail_msg("%s has no \"## Exercises\" section", page);
    section += strlen("\n## Exercises\n");
    char *end = strstr(section, "\n## ");
    if (end)
        *end = '\0';
    static Points points;
    read_points(lesson, &points);
    int items = 0;
    bool first_is_warm_up = false, last_is_challenge = false, checked = false;
    for (char *line = strtok(section, "\n"); line; line = strtok(NULL, "\n")) {
        if (isdigit((unsigned char)line[0]) && strstr(line, ". ")) {
            items++;
            if (items == 1)
                first_is_warm_up = strstr(line, "Warm-up") != NULL;
            last_is_challenge = strstr(line, "Challenge") != NULL;
        }
        for (int i = 0; i < points.n; i++) {
            char quoted[300];
            snprintf(quoted, sizeof quoted, "`%.255s`", points.name[i]);
            checked |= points.points[i] > 0 && strstr(line, quoted) != NULL;
        }
    }
    free(text);
    if (items < 3 || items > 5)
        fail_msg("%s has %d exercises; want 3 to 5", page, items);
    if (!first_is_warm_up || !last_is_challenge)
        fail_msg("%s: the first exercise should say \"Warm-up\" and the last \"Challenge\"", page);
    if (!checked)
        fail_msg("%s: no exercise names a test of tests/%s/points.txt (with points) that "
                 "checks it", page, lesson);
}

int main(void)
{
    /* The Makefile's own flags (-O2 -g), as the series' build has them: its
     * objects can be copied in (seed_build). -O2 builds more slowly than -O0,
     * but the lessons' tests run several times faster: the sum is smaller. */
    snprintf(make_opts, sizeof make_opts, "-j2");

    static char names[3 * MAX_LESSONS][300];
    static char lessons[MAX_LESSONS][256];
    struct CMUnitTest tests[3 * MAX_LESSONS];
    int n = 0;
    DIR *d = opendir("lessons");
    if (!d) {
        fprintf(stderr, "test_handout: run it from the top of the series\n");
        return 1;
    }
    struct dirent *e;
    while ((e = readdir(d)) != NULL && n < MAX_LESSONS)
        if (isdigit((unsigned char)e->d_name[0]) && isdigit((unsigned char)e->d_name[1]))
            snprintf(lessons[n++], sizeof lessons[0], "%s", e->d_name);
    closedir(d);
    qsort(lessons, (size_t)n, sizeof lessons[0], compare_strings);
    if (n > 0)
        snprintf(first_lesson, sizeof first_lesson, "%s", lessons[0]);
    for (int i = 0; i < n; i++) {
        snprintf(names[i], sizeof names[0], "exercises_of_%.200s", lessons[i]);
        tests[i] = (struct CMUnitTest){names[i],
                                       exercises_go_from_warm_up_to_challenge_and_a_test_checks_one,
                                       NULL, NULL, lessons[i]};
        snprintf(names[n + i], sizeof names[0], "handout_round_trip_%.200s", lessons[i]);
        tests[n + i] = (struct CMUnitTest){names[n + i], handout_round_trip, NULL, NULL, lessons[i]};
        snprintf(names[2 * n + i], sizeof names[0], "default_handout_of_%.200s", lessons[i]);
        tests[2 * n + i] = (struct CMUnitTest){names[2 * n + i], default_handout, NULL, NULL, lessons[i]};
    }
    return _cmocka_run_group_tests("tools: make handout and make grade on every lesson", tests,
                                   (size_t)(3 * n), NULL, NULL);
}
