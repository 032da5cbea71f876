/* test_lesson_tree.c: a file lives in one lesson, and later lessons inherit it.
 *
 * A lesson names each file it takes unchanged from an earlier lesson in the
 * table "Inherited files" of its README.md (tools/lesson-tree.sh); make
 * links a lesson's own and inherited files together under build/lessons/ and
 * compiles them there; make snapshot writes them out as a directory that
 * builds alone. Checked here:
 *   - every table is sound, and the check finds a wrong row when there is one;
 *   - no two lessons hold the same file (solution markers aside): a copy is
 *     an inherited file waiting to drift;
 *   - the build compiled each lesson from exactly its own and inherited files;
 *   - a snapshot builds with make alone (at -O0) and draws the lesson's
 *     pictures bit for bit;
 *   - common/ is a small core that includes nothing of common/harness/. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "shell.h"
#include "test_support.h"

#define SHELL_TIMEOUT 120
#define PATH_LEN 4096

/* Runs a command from the top of the tree; fails the test, with the command
 * and its output, unless it exits with status `want`. Returns the output. */
static char *shell_expect(int want, const char *dir, const char *command)
{
    ShellResult r = run_shell(dir, SHELL_TIMEOUT, "%s", command);
    if (r.status != want)
        fail_msg("`%s`%s%s: status %d, not %d:\n%s", command, dir ? " in " : "", dir ? dir : "",
                 r.status, want, r.output);
    return r.output;
}

static void every_inherited_file_names_where_it_lives(void **state)
{
    (void)state;
    char *out = shell_expect(0, NULL, "sh tools/lesson-tree.sh check");
    if (out[0] != '\0')
        fail_msg("lesson-tree.sh check printed:\n%s", out);
    free(out);
}

/* The check can fail: a table with four wrong rows, in a tree of its own. */
static void a_wrong_inherited_row_is_reported(void **state)
{
    (void)state;
    const char *dir = test_dir("lesson_tree_wrong");
    char here[PATH_LEN], command[2 * PATH_LEN];
    if (!getcwd(here, sizeof here))
        fail_msg("getcwd failed");
    snprintf(command, sizeof command,
             "mkdir -p lessons/01_a lessons/02_b lessons/03_c && "
             "echo 'int a;' >lessons/01_a/x.c && echo 'int b;' >lessons/02_b/x.c && "
             "echo 'int c;' >lessons/01_a/z.c && echo 'int d;' >lessons/03_c/z.c && "
             "printf '%%s\\n' '| file | taught in |' '|---|---|' "
             "'| [x.c](../01_a/x.c) | 01 |' '| [y.c](../01_a/y.c) | 01 |' "
             "'| [w.c](../01_a/x.c) | 01 |' '| [z.c](../01_a/z.c) | 01 |' "
             ">lessons/03_c/README.md && sh %s/tools/lesson-tree.sh check",
             here);
    char *out = shell_expect(1, dir, command);
    const char *faults[] = {
        "[x.c](../01_a/x.c): 02_b has a later version of it",
        "[y.c](../01_a/y.c): no such file",
        "[w.c](../01_a/x.c): the link's text is not its path there",
        "[z.c](../01_a/z.c): the lesson holds its own z.c too",
    };
    for (size_t i = 0; i < sizeof faults / sizeof faults[0]; i++)
        if (!strstr(out, faults[i]))
            fail_msg("lesson-tree.sh check did not say \"%s\":\n%s", faults[i], out);
    free(out);
    /* The build stops at a row naming what is not there, with one line... */
    snprintf(command, sizeof command, "sh %s/tools/lesson-tree.sh list 03_c", here);
    out = shell_expect(1, dir, command);
    if (!strstr(out, "lesson-tree: error: lessons/03_c/README.md inherits y.c from "
                     "lessons/01_a/y.c, which is not there\n"))
        fail_msg("lesson-tree.sh list did not name the missing file:\n%s", out);
    free(out);
    /* ... and a file the lesson holds wins over the row that names it. */
    snprintf(command, sizeof command,
             "sed -i '/y.c/d' lessons/03_c/README.md && sh %s/tools/lesson-tree.sh list 03_c", here);
    out = shell_expect(0, dir, command);
    if (!strstr(out, "z.c lessons/03_c/z.c\n") || strstr(out, "lessons/01_a/z.c"))
        fail_msg("lessons/03_c's own z.c should be its z.c:\n%s", out);
    free(out);
}

static void no_two_lessons_hold_the_same_file(void **state)
{
    (void)state;
    /* "<path in the lesson> <checksum without markers> <file>", sorted: a
     * path and checksum twice in a row is a copy. */
    char *out = shell_expect(0, NULL,
        "for f in lessons/*/*.[ch] lessons/*/extras/*.[ch]; do "
        "  rel=${f#lessons/*/}; "
        "  sum=$(awk -v mode=clean -f tools/solution-regions.awk \"$f\" | cksum | tr ' ' _); "
        "  echo \"$rel $sum $f\"; "
        "done | sort | awk '$1 \" \" $2 == key { print last \" and \" $3 } { key = $1 \" \" $2; last = $3 }'");
    if (out[0] != '\0')
        fail_msg("these lessons hold the same file: keep it in the first, and name it in the "
                 "later one's README.md (\"Inherited files\"):\n%s", out);
    free(out);
}

static void each_lesson_builds_from_its_own_and_inherited_files(void **state)
{
    (void)state;
    const char *bin = getenv("BIN_DIR") ? getenv("BIN_DIR") : "build/bin";
    const char *dir = test_dir("lesson_tree_links");
    char command[4 * PATH_LEN];
    /* Each link under <build>/lessons/<lesson>/ and the file it reaches,
     * against the list of the lesson's files. */
    snprintf(command, sizeof command,
             "top=$(pwd); tree=$(dirname '%s')/lessons; n=0; "
             "for d in lessons/[0-9][0-9]_*/; do l=$(basename \"$d\"); n=$((n + 1)); "
             "  [ -d \"$tree/$l\" ] || { echo \"no $tree/$l\"; continue; }; "
             "  (cd \"$tree/$l\" && find . -type f -o -type l | grep -v '/\\.files$' | sed 's|^\\./||' | "
             "   while read -r f; do [ -L \"$f\" ] || echo \"$f is no link\"; "
             "     echo \"$f $(realpath --relative-to=\"$top\" \"$f\")\"; done | sort) >'%s/tree'; "
             "  sh tools/lesson-tree.sh list \"$l\" | diff '%s/tree' - | sed \"s|^|$l: |\"; "
             "done; [ $n -ge 10 ] || echo \"only $n lessons\"",
             bin, dir, dir);
    char *out = shell_expect(0, NULL, command);
    if (out[0] != '\0')
        fail_msg("the build's lesson trees are not the lessons' files "
                 "(< built from, > should be):\n%s", out);
    free(out);
}

/* Lesson 10 inherits the most: its snapshot, built at -O0, draws what the
 * series' build draws, picture, faces and depth. */
static void a_snapshot_builds_alone_and_draws_the_lessons_pictures(void **state)
{
    (void)state;
    const char *dir = test_dir("lesson_tree_snapshot");
    char here[PATH_LEN], snap[2 * PATH_LEN + 8], command[8 * PATH_LEN];
    if (!getcwd(here, sizeof here))
        fail_msg("getcwd failed");
    snprintf(snap, sizeof snap, "%s%s%s/s", dir[0] == '/' ? "" : here, dir[0] == '/' ? "" : "/", dir);
    snprintf(command, sizeof command, "sh tools/snapshot.sh --dest %s 10", snap);
    free(shell_expect(0, NULL, command));

    char *links = shell_expect(0, snap, "find . -type l; grep -c . FILES; "
                                        "grep -c '	lessons/10_fast_raster/' FILES");
    /* no link; 29 files of which 15 its own */
    if (strcmp(links, "29\n15\n") != 0)
        fail_msg("the snapshot should hold 29 plain files, 15 of lesson 10's own:\n%s", links);
    free(links);

    free(shell_expect(0, snap, "make CFLAGS=-O0"));
    const char *bin = abs_bin_dir();
    const char *runs[] = {"", "--scene cubes --depth-format float32", "--scene inside --threads 1"};
    for (size_t i = 0; i < sizeof runs / sizeof runs[0]; i++) {
        snprintf(command, sizeof command,
                 "o='--width 96 --height 72 %s'; "
                 "./10_fast_raster $o --out a.png --id-out a_id.png --depth-out a.pfm >/dev/null && "
                 "%s/10_fast_raster $o --out b.png --id-out b_id.png --depth-out b.pfm >/dev/null && "
                 "cmp a.png b.png && cmp a_id.png b_id.png && cmp a.pfm b.pfm",
                 runs[i], bin);
        free(shell_expect(0, snap, command));
    }
}

/* common/ is the small core that taught code includes: at most CORE_MAX lines,
 * and none of it includes the harness (common/harness/), which holds the
 * program around the lessons. */
#define CORE_MAX 1500
static void the_common_core_is_small_and_includes_no_harness(void **state)
{
    (void)state;
    char *out = shell_expect(0, NULL, "cat common/*.c common/*.h | wc -l");
    int lines = atoi(out);
    free(out);
    if (lines <= 0 || lines > CORE_MAX)
        fail_msg("common/*.[ch] is %d lines: at most %d (what taught code does not include "
                 "belongs in common/harness/)", lines, CORE_MAX);
    out = shell_expect(0, NULL,
                       "for f in common/*.c common/*.h; do "
                       "  sed -n 's/^#include \"\\(.*\\)\".*/\\1/p' \"$f\" | while read -r h; do "
                       "    [ -f \"common/$h\" ] || echo \"$f includes $h, not in common/\"; done; "
                       "done");
    if (out[0] != '\0')
        fail_msg("the core includes what is not in it:\n%s", out);
    free(out);
}

/* What a lesson teaches never reaches the harness: every file at the top of
 * a lesson's tree but main.c (the outline, which calls the harness), and
 * every header those include, directly or not, is outside common/harness/.
 * The compiler lists the headers (-MM); the tree is assembled afresh. */
static void no_taught_file_includes_the_harness(void **state)
{
    (void)state;
    const char *dir = test_dir("lesson_tree_harness");
    char command[4 * PATH_LEN];
    snprintf(command, sizeof command,
             "sh tools/lesson-tree.sh assemble '%s' && "
             "for d in '%s'/[0-9][0-9]_*; do "
             "  for f in \"$d\"/*.c \"$d\"/*.h; do "
             "    case $f in */main.c) continue;; esac; [ -f \"$f\" ] || continue; "
             "    cc -MM -D_POSIX_C_SOURCE=200809L -Icommon -I\"$d\" -x c \"$f\" >\"$d/.deps\" || "
             "      { echo \"cannot list what $f includes\"; continue; }; "
             "    tr ' \\\\' '\\n\\n' <\"$d/.deps\" | grep -q 'common/harness/' && "
             "      echo \"${f#%s/} reaches common/harness/\"; "
             "  done; "
             "done; true",
             dir, dir, dir);
    char *out = shell_expect(0, NULL, command);
    if (out[0] != '\0')
        fail_msg("taught files that include the harness (it belongs to main.c and extras/):\n%s",
                 out);
    free(out);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(every_inherited_file_names_where_it_lives),
        cmocka_unit_test(a_wrong_inherited_row_is_reported),
        cmocka_unit_test(no_two_lessons_hold_the_same_file),
        cmocka_unit_test(each_lesson_builds_from_its_own_and_inherited_files),
        cmocka_unit_test(a_snapshot_builds_alone_and_draws_the_lessons_pictures),
        cmocka_unit_test(the_common_core_is_small_and_includes_no_harness),
        cmocka_unit_test(no_taught_file_includes_the_harness),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
