/* test_make_targets.c: the scripts behind the make targets a student or a
 * teacher types (make diff, snapshot, handout, classroom, autograder), given
 * values that are not theirs to take.
 *
 *   - A lesson is its two digits or its name: a path (FROM=.., which made
 *     make diff read the whole tree above and write copies there; FROM=../..
 *     wrote over files outside it), a pattern, one digit (LESSON=1 was lesson
 *     10) or a prefix of several lessons (make classroom LESSON=0 took the
 *     last, 09) is refused in one line, status 2, and nothing is written.
 *   - A DEST that is not the target's own is left as it is: make classroom's
 *     file never goes into a directory or over a device or a pipe (it was
 *     renamed over them: DEST=/dev/full replaced the device), DEST=/ is
 *     refused as any directory that holds something else.
 *   - A DEST with a space in its path works.
 *   - make test LESSON= naming no tests, and make update-expected without
 *     LESSON=, are refused before anything is built (make -n shows it).
 *   - BUILD may not be the tree, hold it, or be one of its own directories:
 *     make clean BUILD=lessons removed every lesson. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "shell.h"
#include "test_support.h"

#define SHELL_TIMEOUT 300
#define PATH_LEN 4096

/* An absolute path for test_dir(name), in buf. */
static const char *abs_dir(const char *name, char *buf, size_t size)
{
    const char *dir = test_dir(name);
    char here[PATH_LEN];
    if (!getcwd(here, sizeof here))
        fail_msg("getcwd failed");
    int n = dir[0] == '/' ? snprintf(buf, size, "%s", dir) : snprintf(buf, size, "%s/%s", here, dir);
    if (n < 0 || (size_t)n >= size)
        fail_msg("path too long: %s", dir);
    return buf;
}

/* Runs command from the top of the tree: it must exit with status `want`,
 * and the first line it prints must hold `words`; with one_line, it is the
 * only line (a usage line may follow an error otherwise). */
static void expect_refusal(const char *command, int want, const char *words, bool one_line)
{
    ShellResult r = run_shell(NULL, SHELL_TIMEOUT, "%s", command);
    const char *nl = strchr(r.output, '\n');
    const char *found = strstr(r.output, words);
    if (r.status != want || !nl || !found || found > nl || (one_line && nl[1] != '\0'))
        fail_msg("`%s`: status %d (want %d), want %s with \"%s\":\n%s", command, r.status, want,
                 one_line ? "one line" : "a first line", words, r.output);
    shell_result_free(&r);
}
#define expect_one_line(command, want, words) expect_refusal(command, want, words, true)

/* The number of entries in dir, "." and ".." aside. */
static int entries(const char *dir)
{
    char command[PATH_LEN + 64];
    snprintf(command, sizeof command, "ls -A '%s' | wc -l", dir);
    ShellResult r = run_shell(NULL, SHELL_TIMEOUT, "%s", command);
    int n = atoi(r.output);
    shell_result_free(&r);
    return n;
}

static void values_that_are_not_one_lesson_are_refused(void **state)
{
    (void)state;
    char dir[PATH_LEN], command[3 * PATH_LEN];
    abs_dir("make_targets_lessons", dir, sizeof dir);
    static const struct {
        const char *command; /* %s: the scratch directory */
        const char *words;
    } cases[] = {
        {"sh tools/lesson-diff.sh .. 02", "FROM=.. is not a lesson"},
        {"sh tools/lesson-diff.sh 02 'lessons/../..'", "TO=lessons/../.. is not a lesson"},
        {"sh tools/lesson-diff.sh 0 1", "FROM=0 is not a lesson"},
        {"sh tools/lesson-diff.sh 03 03_perspective_z", "are the same lesson, 03_perspective_z"},
        {"sh tools/lesson-diff.sh 99 03", "no lesson FROM=99 in lessons/"},
        {"sh tools/lesson-tree.sh list nosuch", "LESSON=nosuch is not a lesson"},
        {"sh tools/lesson-tree.sh list 99", "no lesson LESSON=99 in lessons/"},
        {"sh tools/lesson-tree.sh copy 99 '%s/copy'", "no lesson LESSON=99"},
        {"sh tools/classroom.sh --dest '%s/t.json' 0", "LESSON=0 is not a lesson"},
        {"sh tools/classroom.sh --dest '%s/t.json' 1", "LESSON=1 is not a lesson"},
        {"sh tools/classroom.sh --dest '%s/t.json' '0*'", "LESSON=0* is not a lesson"},
        {"sh tools/snapshot.sh --dest '%s/s' 1", "LESSON=1 is not a lesson"},
        {"sh tools/snapshot.sh --dest '%s/s' ../lessons/03", "is not a lesson"},
        {"sh tools/handout.sh --dest '%s/h' 1", "LESSON=1 is not a lesson"},
        {"sh tools/autograder.sh --build '%s' 1", "LESSON=1 is not a lesson"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        snprintf(command, sizeof command, cases[i].command, dir);
        expect_one_line(command, 2, cases[i].words);
        if (entries(dir) != 0)
            fail_msg("`%s` wrote into %s", command, dir);
    }
}

static void a_dest_that_is_not_theirs_is_left_alone(void **state)
{
    (void)state;
    char dir[PATH_LEN], command[3 * PATH_LEN];
    abs_dir("make_targets_dest", dir, sizeof dir);
    /* make classroom: a directory, a pipe, a name ending in '/' */
    if (mkdir(path_join(dir, "d"), 0755) != 0)
        fail_msg("mkdir failed");
    write_text(path_join(dir, "d/keep.txt"), "keep me\n");
    if (mkfifo(path_join(dir, "pipe"), 0644) != 0)
        fail_msg("mkfifo failed");
    snprintf(command, sizeof command, "sh tools/classroom.sh --dest '%s/d' 03", dir);
    expect_one_line(command, 2, "is a directory: name the file to write");
    snprintf(command, sizeof command, "sh tools/classroom.sh --dest '%s/d/' 03", dir);
    expect_one_line(command, 2, "ends in '/'");
    snprintf(command, sizeof command, "sh tools/classroom.sh --dest '%s/pipe' 03", dir);
    expect_one_line(command, 2, "exists and is not a regular file");
    /* nor over the points file it reads, by any name */
    char *points = read_text("tests/03_perspective_z/points.txt");
    snprintf(command, sizeof command,
             "sh tools/classroom.sh --dest tests/03_perspective_z/../03_perspective_z/points.txt 03");
    expect_one_line(command, 2, "is tests/03_perspective_z/points.txt, which the tests are read from");
    char *after = read_text("tests/03_perspective_z/points.txt");
    if (strcmp(points, after) != 0) {
        write_text("tests/03_perspective_z/points.txt", points);
        fail_msg("make classroom replaced the points file it reads");
    }
    free(points);
    free(after);
    struct stat st;
    if (stat(path_join(dir, "pipe"), &st) != 0 || !S_ISFIFO(st.st_mode))
        fail_msg("make classroom DEST=pipe replaced the pipe");
    if (entries(path_join(dir, "d")) != 1 || entries(dir) != 2)
        fail_msg("make classroom left a file beside its DEST");
    /* make snapshot and make handout: DEST=/ is a directory that holds
     * something else (it was read as an empty name, and the run went on). */
    expect_refusal("sh tools/snapshot.sh --dest / 03", 2,
                   "snapshot: error: DEST=/ exists and is not an earlier snapshot", false);
    expect_refusal("sh tools/handout.sh --dest / 03", 2,
                   "handout: error: DEST=/ exists and is not an earlier handout", false);
    /* and a classroom file in a directory of its own is written */
    snprintf(command, sizeof command, "sh tools/classroom.sh --dest '%s/d/t.json' 03", dir);
    ShellResult r = run_shell(NULL, SHELL_TIMEOUT, "%s", command);
    if (r.status != 0 || !file_exists(path_join(dir, "d/t.json")) || entries(path_join(dir, "d")) != 2)
        fail_msg("`%s`: status %d\n%s", command, r.status, r.output);
    shell_result_free(&r);
}

static void a_dest_with_a_space_works(void **state)
{
    (void)state;
    char dir[PATH_LEN], command[5 * PATH_LEN + 256];
    abs_dir("make_targets_space", dir, sizeof dir);
    snprintf(command, sizeof command,
             "mkdir -p '%s/a b' && sh tools/handout.sh --only --dest '%s/a b/h' 03 && "
             "sh tools/snapshot.sh --dest '%s/a b/s' 03 && "
             "sh tools/classroom.sh --dest '%s/a b/t.json' 03",
             dir, dir, dir, dir);
    ShellResult r = run_shell(NULL, SHELL_TIMEOUT, "%s", command);
    if (r.status != 0)
        fail_msg("`%s`: status %d\n%s", command, r.status, r.output);
    /* the snapshot's hint runs as printed: the path quoted */
    char hint[PATH_LEN + 64];
    snprintf(hint, sizeof hint, "build it with: make -C '%s/a b/s'\n", dir);
    if (!strstr(r.output, hint))
        fail_msg("the snapshot's hint should quote its path (%s):\n%s", hint, r.output);
    shell_result_free(&r);
    char sub[PATH_LEN + 8];
    snprintf(sub, sizeof sub, "%s/a b", dir);
    /* h, s and t.json, nothing else beside them */
    if (entries(sub) != 3)
        fail_msg("%s should hold h, s and t.json only", sub);
    assert_true(file_exists(path_join(sub, "h/.handout")));
    assert_true(file_exists(path_join(sub, "s/.snapshot")));
}

static void make_test_of_no_lesson_is_refused(void **state)
{
    (void)state;
    expect_one_line("make --no-print-directory -n test LESSON=..", 2,
                    "LESSON=.. names no tests (tests/..*/test_*.c): give a lesson's number");
    expect_one_line("make --no-print-directory -n update-expected LESSON=nosuch", 2,
                    "LESSON=nosuch names no tests");
    expect_one_line("make --no-print-directory -n update-expected", 2,
                    "usage: make update-expected LESSON=NN");
}

static void a_build_directory_of_the_trees_own_is_refused(void **state)
{
    (void)state;
    const char *builds[] = {"lessons", "./lessons/x", "tests/zz_build", "out", ".", "Makefile"};
    char command[256], words[128];
    for (size_t i = 0; i < sizeof builds / sizeof builds[0]; i++) {
        snprintf(command, sizeof command, "make --no-print-directory -n clean BUILD=%s", builds[i]);
        snprintf(words, sizeof words, "BUILD=%s is the tree, holds it, or is one of its own", builds[i]);
        expect_one_line(command, 2, words);
    }
    expect_one_line("make --no-print-directory -n clean BUILD=", 2, "BUILD is empty");
    /* Nothing was made on the way (the lessons' links, as the Makefile is read). */
    assert_false(file_exists("lessons/x"));
    assert_false(file_exists("lessons/lessons"));
    assert_false(file_exists("tests/zz_build"));
}

/* The series in a directory whose path holds a space (a student's
 * "My Documents") reads its Makefile and would build: the check of BUILD
 * above once took the tree's path apart at the space and refused build. */
static void a_tree_in_a_path_with_a_space_reads_its_makefile(void **state)
{
    (void)state;
    char dir[PATH_LEN], command[3 * PATH_LEN + 256];
    abs_dir("make_targets_tree_space", dir, sizeof dir);
    snprintf(command, sizeof command,
             "mkdir -p '%s/a b/t' && cp -R Makefile common lessons tools '%s/a b/t/' && "
             "cd '%s/a b/t' && make --no-print-directory -n build/bin/02_zbuffer >/dev/null",
             dir, dir, dir);
    ShellResult r = run_shell(NULL, SHELL_TIMEOUT, "%s", command);
    if (r.status != 0)
        fail_msg("make -n in a tree under '%s/a b': status %d\n%s", dir, r.status, r.output);
    shell_result_free(&r);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(values_that_are_not_one_lesson_are_refused),
        cmocka_unit_test(a_dest_that_is_not_theirs_is_left_alone),
        cmocka_unit_test(a_dest_with_a_space_works),
        cmocka_unit_test(make_test_of_no_lesson_is_refused),
        cmocka_unit_test(a_build_directory_of_the_trees_own_is_refused),
        cmocka_unit_test(a_tree_in_a_path_with_a_space_reads_its_makefile),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
