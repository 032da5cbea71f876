/* test_grade.c: make grade and make handout, on a made-up lesson whose tests
 * do every bad thing student code can do: fail, crash in a way cmocka
 * catches, abort the whole test program, hang. Each must cost exactly the
 * points of its own test; results.json must be JSON (read back with a real
 * parser) in the Gradescope format; the handout tool must refuse to write a
 * tree that gives a solution line away.
 *
 * The made-up lesson lives in a copy of the series' build machinery under
 * $TEST_OUTPUT/tmp/grade_tree, built once (at -O0, it is small). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <sys/stat.h>
#include <unistd.h>

#include "harness/file.h"
#include "json.h"
#include "shell.h"
#include "test_support.h"

#define SHELL_TIMEOUT 120 /* seconds: a build and a grade, with room to spare */

static char tree[4096]; /* the made-up series, set up once: an absolute path */

static const char FAKE_H[] = "int fake_add(int a, int b);\n";

/* The lesson's one idea: adding. Its region has a stub that compiles. */
static const char FAKE_C[] =
    "#include \"fake.h\"\n"
    "\n"
    "/* The sum of a and b. */\n"
    "int fake_add(int a, int b)\n"
    "{\n"
    "    /* SOLUTION BEGIN: return the sum of a and b */\n"
    "    int sum = a + b;\n"
    "    return sum;\n"
    "    /* SOLUTION STUB\n"
    "    (void)a; (void)b;\n"
    "    return 0;\n"
    "    */\n"
    "    /* SOLUTION END */\n"
    "}\n";

static const char MAIN_C[] = "#include \"fake.h\"\nint main(void) { return fake_add(0, 0); }\n";

/* The tests, in the order cmocka runs them. The abort kills the whole test
 * program, so make grade must run the three tests after it on their own.
 * hangs spins as a student's endless loop does, in four threads at once:
 * the kernel counts their CPU time together, so that its 1 s of CPU time
 * comes well within the 3 s of wall-clock time on a machine as busy as
 * make sanitize keeps it (one thread at nice 19 can starve there and be
 * stopped by the wall clock first). */
static const char TEST_FAKE_C[] =
    "#include <setjmp.h>\n#include <stdarg.h>\n#include <stddef.h>\n#include <stdint.h>\n"
    "#include <cmocka.h>\n#include <pthread.h>\n#include <signal.h>\n#include <stdlib.h>\n"
    "#include \"fake.h\"\n"
    "static void adds_small_numbers(void **s) { (void)s; assert_int_equal(fake_add(2, 3), 5); }\n"
    "static void not_in_points_file(void **s) { (void)s; }\n"
    "static void message_with_quotes(void **s) { (void)s;\n"
    "    fail_msg(\"say \\\"hi\\\" \\\\ tab\\there esc\\033 end\"); }\n"
    "static void crash_caught_by_cmocka(void **s) { (void)s; raise(SIGSEGV); }\n"
    "static void aborts(void **s) { (void)s; abort(); }\n"
    "static void after_the_abort(void **s) { (void)s; assert_int_equal(fake_add(1, 1), 2); }\n"
    "static void *spin(void *a) { for (volatile unsigned i = 0;; i++) {} return a; }\n"
    "static void hangs(void **s) { (void)s; pthread_t t;\n"
    "    for (int k = 0; k < 3; k++) (void)!pthread_create(&t, NULL, spin, NULL);\n"
    "    spin(NULL); }\n"
    "static void after_the_hang(void **s) { (void)s; assert_int_equal(fake_add(0, 0), 0); }\n"
    "int main(void) {\n"
    "    const struct CMUnitTest t[] = {cmocka_unit_test(adds_small_numbers),\n"
    "        cmocka_unit_test(not_in_points_file), cmocka_unit_test(message_with_quotes),\n"
    "        cmocka_unit_test(crash_caught_by_cmocka), cmocka_unit_test(aborts),\n"
    "        cmocka_unit_test(after_the_abort), cmocka_unit_test(hangs),\n"
    "        cmocka_unit_test(after_the_hang)};\n"
    "    return cmocka_run_group_tests(t, NULL, NULL);\n}\n";

static const char TEST_OTHER_C[] =
    "#include <setjmp.h>\n#include <stdarg.h>\n#include <stddef.h>\n#include <stdint.h>\n"
    "#include <cmocka.h>\n#include \"fake.h\"\n"
    "static void other_binary_passes(void **s) { (void)s; assert_int_equal(fake_add(-1, 1), 0); }\n"
    "int main(void) {\n"
    "    const struct CMUnitTest t[] = {cmocka_unit_test(other_binary_passes)};\n"
    "    return cmocka_run_group_tests(t, NULL, NULL);\n}\n";

/* Points: 2 + 1 + 1 + 1 + 1 + 1 + 1 + 1 + 2 = 11 in all. With the solution,
 * what passes is adds_small_numbers (2), after_the_abort (1),
 * after_the_hang (1) and other_binary_passes (2): 6. */
static const char POINTS[] =
    "# test                 points  what it checks\n"
    "adds_small_numbers       2     fake_add(): 2 + 3\n"
    "message_with_quotes      1     a message with \"quotes\"\n"
    "crash_caught_by_cmocka   1     a segmentation fault that cmocka catches\n"
    "\n"
    "aborts                   1     an abort() that ends the test program\n"
    "after_the_abort          1     fake_add(): after the abort\n"
    "hangs                    1     an endless loop\n"
    "after_the_hang           1     fake_add(): after the hang\n"
    "listed_but_missing       1     a test no program has\n"
    "other_binary_passes      2     fake_add(): -1 + 1, in another test program\n";
#define EXPECTED_SCORE 6.0
#define EXPECTED_MAX 11.0

/* A second made-up lesson, whose tests all pass on its solution (as a real
 * lesson's do), for make grade-reference and make grade REFERENCE=. Its
 * tests include test_support.h, as the series' do: their checks are
 * observed (tests/support/observe.h). */
/* Its header is taught too, as lesson 03's raster.h is: a macro in a
 * solution region (which sum.c does not need), for the rules on headers. */
static const char SUM_H[] = "/* SOLUTION BEGIN: where sums start */\n"
                            "#define SUM_FIRST 1\n"
                            "/* SOLUTION STUB\n"
                            "#define SUM_FIRST 0\n"
                            "*/\n"
                            "/* SOLUTION END */\n"
                            "int sum_to(int n);\n";
static const char SUM_C[] =
    "#include \"sum.h\"\n"
    "/* 1 + 2 + ... + n. */\n"
    "int sum_to(int n)\n{\n"
    "    /* SOLUTION BEGIN: the sum of 1 to n */\n"
    "    return n * (n + 1) / 2;\n"
    "    /* SOLUTION STUB\n"
    "    (void)n;\n"
    "    return 0;\n"
    "    */\n"
    "    /* SOLUTION END */\n"
    "}\n";
static const char SUM_MAIN_C[] = "#include \"sum.h\"\nint main(void) { return sum_to(0); }\n";
static const char TEST_SUM_C[] =
    "#include <setjmp.h>\n#include <stdarg.h>\n#include <stddef.h>\n#include <stdint.h>\n"
    "#include <cmocka.h>\n#include \"sum.h\"\n#include \"test_support.h\"\n"
    "static void sums_to_ten(void **s) { (void)s; assert_int_equal(sum_to(10), 55); }\n"
    "static void sums_in_a_loop(void **s) { (void)s;\n"
    "    int want = 0;\n"
    "    for (int n = 0; n < 50; want += ++n) {\n"
    "        observe_value(\"sum\", sum_to(n));\n"
    "        if (sum_to(n) != want) fail_msg(\"n = %d: %d\", n, sum_to(n));\n"
    "    } }\n"
    "static void at_least_the_last(void **s) { (void)s; expect_at_least(7, sum_to(7), \"sum\"); }\n"
    "static void needs_no_work(void **s) { (void)s; assert_int_equal(1 + 1, 2); }\n"
    "int main(void) {\n"
    "    const struct CMUnitTest t[] = {cmocka_unit_test(sums_to_ten),\n"
    "        cmocka_unit_test(sums_in_a_loop), cmocka_unit_test(at_least_the_last),\n"
    "        cmocka_unit_test(needs_no_work)};\n"
    "    return cmocka_run_group_tests(t, NULL, NULL);\n}\n";
static const char SUM_POINTS[] = "sums_to_ten        2  sum_to(): 1 to 10\n"
                                 "sums_in_a_loop     2  sum_to(): 0 to 49\n"
                                 "at_least_the_last  1  sum_to(): at least 7 for 7\n"
                                 "needs_no_work      0  (passes without the student's work) 1 + 1\n";

/* Code that tries to pass without the work, each way a test program linked
 * with it could be turned: cmocka's checks replaced by ones that do nothing
 * (the dynamic linker takes the program's own over the library's), a
 * record written by hand to every descriptor, an exit before the test ends
 * with the words of a passed test printed, a verdict file written. */
static const char SUM_NEUTERS_CMOCKA_C[] =
    "#include \"sum.h\"\n#include <stdint.h>\n#include <stddef.h>\n"
    "void _assert_int_equal(uintmax_t a, uintmax_t b, const char *f, int l);\n"
    "void _assert_int_equal(uintmax_t a, uintmax_t b, const char *f, int l)"
    " { (void)a; (void)b; (void)f; (void)l; }\n"
    "void _assert_true(uintmax_t r, const char *e, const char *f, int l);\n"
    "void _assert_true(uintmax_t r, const char *e, const char *f, int l)"
    " { (void)r; (void)e; (void)f; (void)l; }\n"
    "void _fail(const char *f, int l);\n"
    "void _fail(const char *f, int l) { (void)f; (void)l; }\n"
    "int sum_to(int n) { (void)n; return 0; }\n";
static const char SUM_WRITES_RECORD_C[] =
    "#include \"sum.h\"\n#include <stdio.h>\n#include <string.h>\n#include <unistd.h>\n"
    "int sum_to(int n) { (void)n;\n"
    "    const char *forged = \"D 1 0123456789abcdef\\nB x.c:1 > 7 7 1\\nE passed\\n\";\n"
    "    for (int fd = 3; fd < 64; fd++) (void)!write(fd, forged, strlen(forged));\n"
    "    printf(\"[       OK ] sums_to_ten\\n[  PASSED  ] 1 test(s).\\n\");\n"
    "    fflush(stdout);\n"
    "    _exit(0); }\n";
static const char SUM_REDEFINES_OBSERVER_C[] =
    "#include \"sum.h\"\n#include <stdint.h>\n"
    "void observed_int_equal(uintmax_t a, uintmax_t b, const char *f, int l);\n"
    "void observed_int_equal(uintmax_t a, uintmax_t b, const char *f, int l)"
    " { (void)a; (void)b; (void)f; (void)l; }\n"
    "int sum_to(int n) { return n * (n + 1) / 2; }\n";
/* The C library's formatting replaced, so that the record's lines say what
 * the code never computed; a record written before main; a correct solution
 * with a helper of its own and a debug print, which loses nothing. */
static const char SUM_REPLACES_PRINTF_C[] =
    "#include \"sum.h\"\n#include <stdarg.h>\n#include <stddef.h>\n"
    "int vsnprintf(char *s, size_t n, const char *f, va_list ap);\n"
    "int vsnprintf(char *s, size_t n, const char *f, va_list ap)"
    " { (void)f; (void)ap; if (n) s[0] = 0; return 0; }\n"
    "int sum_to(int n) { (void)n; return 0; }\n";
static const char SUM_RECORDS_BEFORE_MAIN_C[] =
    "#include \"sum.h\"\n#include <unistd.h>\n"
    "__attribute__((constructor)) static void forge(void) { (void)!write(3, \"E passed\\n\", 9); }\n"
    "int sum_to(int n) { (void)n; return 0; }\n";
/* Code run before main without a constructor: the resolver of an indirect
 * function, which the dynamic loader calls while it relocates the program. */
static const char SUM_RESOLVES_BEFORE_MAIN_C[] =
    "#include \"sum.h\"\n#include <stdio.h>\n"
    "static int sum_plain(int n) { return n * (n + 1) / 2; }\n"
    "static int (*resolve(void))(int) { puts(\"before main\"); return sum_plain; }\n"
    "int sum_to(int n) __attribute__((ifunc(\"resolve\")));\n";
static const char SUM_WITH_A_HELPER_C[] =
    "#include \"sum.h\"\n#include <stdio.h>\n"
    "int advance(int n);\n"
    "int advance(int n) { printf(\"n = %d\\n\", n); return n * (n + 1) / 2; }\n"
    "int sum_to(int n) { return advance(n); }\n";
static const char SUM_BUGGY_C[] =
    "#include \"sum.h\"\nint sum_to(int n) { return n <= 10 ? n * (n + 1) / 2 : 0; }\n";

/* run_shell, and the command must succeed. */
static ShellResult shell_ok(const char *dir, const char *fmt, ...)
{
    char command[8192];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(command, sizeof command, fmt, ap);
    va_end(ap);
    ShellResult r = run_shell(dir, SHELL_TIMEOUT, "%s", command);
    if (r.status != 0)
        fail_msg("`%s` in %s: status %d\n%s", command, dir ? dir : ".", r.status, r.output);
    return r;
}

/* A fresh directory under $TEST_OUTPUT/tmp, as an absolute path: the commands
 * run in the made-up tree, not here. Own buffers: test_dir's rotate. */
static const char *abs_test_dir(const char *name)
{
    static char slots[4][4096];
    static int next;
    char *buf = slots[next];
    next = (next + 1) % 4;
    char here[4096];
    if (!getcwd(here, sizeof here))
        fail_msg("getcwd failed");
    const char *dir = test_dir(name);
    if (dir[0] == '/')
        snprintf(buf, sizeof slots[0], "%s", dir);
    else if (snprintf(buf, sizeof slots[0], "%s/%s", here, dir) >= (int)sizeof slots[0])
        fail_msg("path too long: %s/%s", here, dir);
    return buf;
}

/* The series' build machinery and the made-up lesson 09_fake, built. */
static int set_up_tree(void **state)
{
    (void)state;
    snprintf(tree, sizeof tree, "%s", abs_test_dir("grade_tree"));
    ShellResult r = shell_ok(tree, "mkdir -p tests tools lessons/09_fake tests/09_fake lessons/08_plain");
    shell_result_free(&r);
    /* tools/: the scripts the Makefile calls, and time_limit of its programs */
    r = shell_ok(NULL, "cp -R Makefile common %s/ && cp tools/*.sh tools/*.awk %s/tools/ && "
                       "cp -R tools/autograder %s/tools/ && cp -R tests/support %s/tests/ && "
                       "cp tools/time_limit.c tools/judge.c %s/tools/", tree, tree, tree, tree, tree);
    shell_result_free(&r);
    write_text(path_join(tree, "lessons/09_fake/fake.h"), FAKE_H);
    write_text(path_join(tree, "lessons/09_fake/fake.c"), FAKE_C);
    write_text(path_join(tree, "lessons/09_fake/main.c"), MAIN_C);
    write_text(path_join(tree, "lessons/08_plain/main.c"), "int main(void) { return 0; }\n");
    write_text(path_join(tree, "tests/09_fake/test_fake.c"), TEST_FAKE_C);
    write_text(path_join(tree, "tests/09_fake/test_other.c"), TEST_OTHER_C);
    write_text(path_join(tree, "tests/09_fake/points.txt"), POINTS);
    r = shell_ok(NULL, "mkdir -p %s/lessons/06_sum %s/tests/06_sum", tree, tree);
    shell_result_free(&r);
    write_text(path_join(tree, "lessons/06_sum/sum.h"), SUM_H);
    write_text(path_join(tree, "lessons/06_sum/sum.c"), SUM_C);
    write_text(path_join(tree, "lessons/06_sum/main.c"), SUM_MAIN_C);
    write_text(path_join(tree, "tests/06_sum/test_sum.c"), TEST_SUM_C);
    write_text(path_join(tree, "tests/06_sum/points.txt"), SUM_POINTS);
    r = shell_ok(tree, "make -j2 OPT=-O0 all build/tests/09_fake/test_fake build/tests/09_fake/test_other");
    shell_result_free(&r);
    return 0;
}

/* After each test: the made-up lesson as set up, whatever the test changed. */
static int restore_tree(void **state)
{
    (void)state;
    write_text(path_join(tree, "lessons/09_fake/fake.c"), FAKE_C);
    write_text(path_join(tree, "tests/09_fake/points.txt"), POINTS);
    write_text(path_join(tree, "lessons/06_sum/sum.c"), SUM_C);
    write_text(path_join(tree, "lessons/06_sum/sum.h"), SUM_H);
    remove(path_join(tree, "tests/09_fake/notes.txt"));
    return 0;
}

/* ---- make grade ---- */

static JsonValue read_results(void)
{
    char *text = read_text(path_join(tree, "build/grade/results.json"));
    JsonValue v;
    char why[256];
    if (!json_parse(text, strlen(text), &v, why, sizeof why))
        fail_msg("build/grade/results.json is not JSON: %s\n%s", why, text);
    free(text);
    if (v.type != JSON_OBJECT)
        fail_msg("results.json holds a %s, not an object", json_type_name(v.type));
    return v;
}

static const JsonValue *field(const JsonValue *obj, const char *key, JsonType type)
{
    const JsonValue *f = json_get(obj, key);
    if (!f)
        fail_msg("results.json: no \"%s\"", key);
    if (f->type != type)
        fail_msg("results.json: \"%s\" is a %s, want a %s", key, json_type_name(f->type),
                 json_type_name(type));
    return f;
}

/* The entry of tests[] named "09_fake: <name>". */
static const JsonValue *test_entry(const JsonValue *results, const char *name)
{
    const JsonValue *tests = field(results, "tests", JSON_ARRAY);
    char full[256];
    snprintf(full, sizeof full, "09_fake: %s", name);
    for (size_t i = 0; i < tests->count; i++) {
        const JsonValue *n = json_get(&tests->items[i], "name");
        if (n && n->type == JSON_STRING && strcmp(n->string, full) == 0)
            return &tests->items[i];
    }
    fail_msg("results.json has no test \"%s\"", full);
    return NULL;
}

static void expect_test(const JsonValue *results, const char *name, double score, double max,
                        const char *output_has)
{
    const JsonValue *t = test_entry(results, name);
    double got = field(t, "score", JSON_NUMBER)->number;
    double of = field(t, "max_score", JSON_NUMBER)->number;
    const char *out = field(t, "output", JSON_STRING)->string;
    const char *status = field(t, "status", JSON_STRING)->string;
    if (got != score || of != max)
        fail_msg("%s scored %g/%g, want %g/%g; its output:\n%s", name, got, of, score, max, out);
    if (max > 0 && strcmp(status, got == max ? "passed" : "failed") != 0)
        fail_msg("%s scored %g/%g, but its status is %s", name, got, of, status);
    if (output_has && !strstr(out, output_has))
        fail_msg("the output of %s should say \"%s\"; it is:\n%s", name, output_has, out);
}

/* Every file of the tree outside build/, with its checksum: what a grade
 * must leave as it was. */
#define TREE_SUMS "find . -path ./build -prune -o -type f -print | sort | xargs md5sum"

static void each_failure_costs_only_its_own_points(void **state)
{
    (void)state;
    ShellResult before = shell_ok(tree, TREE_SUMS);
    ShellResult r = shell_ok(tree, "make -j2 OPT=-O0 grade LESSON=09 TIME_LIMIT=1");
    ShellResult after = shell_ok(tree, TREE_SUMS);
    assert_string_equal(before.output, after.output); /* a grade changes nothing but build/ */
    shell_result_free(&before);
    shell_result_free(&after);
    if (!strstr(r.output, "09_fake: 6/11") || !strstr(r.output, "total 6/11"))
        fail_msg("the score table should end 09_fake: 6/11:\n%s", r.output);
    /* The table says what a failed test checks. */
    assert_non_null(strstr(r.output, "checks: an abort() that ends the test program"));
    shell_result_free(&r);

    JsonValue v = read_results();
    assert_true(field(&v, "score", JSON_NUMBER)->number == EXPECTED_SCORE);
    double max = 0;
    const JsonValue *tests = field(&v, "tests", JSON_ARRAY);
    for (size_t i = 0; i < tests->count; i++)
        max += field(&tests->items[i], "max_score", JSON_NUMBER)->number;
    assert_true(max == EXPECTED_MAX);
    /* The solution is there: fake_add() works. */
    expect_test(&v, "adds_small_numbers", 2, 2, NULL);
    expect_test(&v, "other_binary_passes", 2, 2, NULL);
    /* cmocka caught the crash: the test program went on. */
    expect_test(&v, "crash_caught_by_cmocka", 0, 1, "Segmentation fault");
    /* The abort and the hang cost their own test, not those after them. */
    expect_test(&v, "aborts", 0, 1, "crashed: killed by SIGABRT");
    expect_test(&v, "after_the_abort", 1, 1, NULL);
    expect_test(&v, "hangs", 0, 1, "used more than 1 s of CPU time");
    expect_test(&v, "after_the_hang", 1, 1, NULL);
    expect_test(&v, "listed_but_missing", 0, 1, "did not run");
    /* Run and shown, but worth nothing: it is not in points.txt. */
    expect_test(&v, "not_in_points_file", 0, 0, "not in tests/09_fake/points.txt");
    /* The message comes back character for character through JSON: quotes,
     * backslash, tab and the escape character (0x1b) included. */
    expect_test(&v, "message_with_quotes", 0, 1, "say \"hi\" \\ tab\there esc\x1b end");
    /* A failed test says what it checks. */
    expect_test(&v, "message_with_quotes", 0, 1, "This test checks: a message with \"quotes\"");
    json_free(&v);
}

/* Student code that does not compile: every test of the lesson scores 0,
 * and the grade is still written. */
static void code_that_does_not_compile_scores_zero(void **state)
{
    (void)state;
    const char *fake_c = path_join(tree, "lessons/09_fake/fake.c");
    write_text(fake_c, "int fake_add(int a, int b) { return a + ; }\n");
    ShellResult r = run_shell(tree, SHELL_TIMEOUT, "make -j2 OPT=-O0 grade LESSON=09 TIME_LIMIT=1");
    write_text(fake_c, FAKE_C);
    if (r.status != 0)
        fail_msg("make grade should grade a lesson that does not compile (status %d):\n%s",
                 r.status, r.output);
    if (!strstr(r.output, "grade: the build failed") || !strstr(r.output, "09_fake: 0/11"))
        fail_msg("want the build errors, then 09_fake: 0/11:\n%s", r.output);
    shell_result_free(&r);
    JsonValue v = read_results();
    assert_true(field(&v, "score", JSON_NUMBER)->number == 0.0);
    expect_test(&v, "adds_small_numbers", 0, 2, "did not run");
    json_free(&v);
}

/* TEST=name: one test, run alone; the exit status says whether it passed
 * (make turns the script's 1 into its own 2). */
static void one_test_alone_sets_the_exit_status(void **state)
{
    (void)state;
    ShellResult r = shell_ok(tree, "make OPT=-O0 grade LESSON=09 TEST=after_the_abort");
    assert_non_null(strstr(r.output, "09_fake: 1/1"));
    shell_result_free(&r);
    JsonValue v = read_results();
    assert_int_equal(field(&v, "tests", JSON_ARRAY)->count, 1);
    expect_test(&v, "after_the_abort", 1, 1, NULL);
    json_free(&v);

    r = run_shell(tree, SHELL_TIMEOUT, "make OPT=-O0 grade LESSON=09 TEST=aborts");
    if (r.status == 0 || !strstr(r.output, "09_fake: 0/1"))
        fail_msg("make grade TEST=aborts should fail, scoring 0/1 (status %d):\n%s", r.status,
                 r.output);
    shell_result_free(&r);

    r = run_shell(tree, SHELL_TIMEOUT, "make OPT=-O0 grade LESSON=09 TEST=no_such_test");
    if (r.status == 0 || !strstr(r.output, "grade: error: no test no_such_test in tests/09_fake/points.txt"))
        fail_msg("make grade TEST=no_such_test: status %d:\n%s", r.status, r.output);
    shell_result_free(&r);
}

static void malformed_points_file_is_refused_with_its_line(void **state)
{
    (void)state;
    const char *points = path_join(tree, "tests/09_fake/points.txt");
    const char *bad[][2] = {
        {"adds_small_numbers 2 ok\nadds_small_numbers 1 again\n", "points.txt:2: "},
        {"adds_small_numbers two words\n", "points: a number"},
        {"adds_small_numbers 2\n", "a few words on what the test checks"},
        {"adds-small 2 dash\n", "a test name, a C identifier"},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        write_text(points, bad[i][0]);
        ShellResult r = run_shell(tree, SHELL_TIMEOUT, "sh tools/grade.sh --build build 09_fake");
        int status = r.status;
        bool said = strstr(r.output, bad[i][1]) && strstr(r.output, "points.txt is malformed");
        char *out = r.output;
        r.output = NULL;
        if (status != 1 || !said) {
            write_text(points, POINTS);
            fail_msg("points file %s: want status 1 and \"%s\", got %d:\n%s", bad[i][0],
                     bad[i][1], status, out);
        }
        free(out);
    }
    write_text(points, POINTS);
}

/* make grade with a TIME_LIMIT=, REFERENCE= or TEST= it cannot take: said
 * at once, the lesson's program not removed and built again first (it was,
 * for minutes on the series, before the refusal). */
static void bad_grade_values_are_refused_before_the_build(void **state)
{
    (void)state;
    const char *bin = path_join(tree, "build/bin/06_sum");
    ShellResult r = shell_ok(tree, "make -j2 OPT=-O0 build/bin/06_sum");
    shell_result_free(&r);
    struct stat before;
    assert_int_equal(stat(bin, &before), 0);
    const char *bad[][2] = {
        {"TIME_LIMIT=abc", "grade: error: TIME_LIMIT=abc: want a whole number of seconds"},
        {"REFERENCE=build/no-records", "grade: error: no records of the teacher's solution in build/no-records"},
        {"TEST=no_such_test", "grade: error: no test no_such_test in tests/06_sum/points.txt"},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        r = run_shell(tree, SHELL_TIMEOUT, "make OPT=-O0 grade LESSON=06 %s", bad[i][0]);
        if (r.status == 0 || !strstr(r.output, bad[i][1]))
            fail_msg("make grade %s: want \"%s\" (status %d):\n%s", bad[i][0], bad[i][1], r.status,
                     r.output);
        shell_result_free(&r);
        struct stat after;
        if (stat(bin, &after) != 0 || after.st_mtim.tv_sec != before.st_mtim.tv_sec ||
            after.st_mtim.tv_nsec != before.st_mtim.tv_nsec)
            fail_msg("make grade %s removed or rebuilt build/bin/06_sum before refusing", bad[i][0]);
    }
}

/* make grade-reference REFERENCE=dir replaces dir/<lesson> by the records:
 * never a directory that holds anything else. REFERENCE=tests replaced
 * tests/06_sum, the lesson's tests and points, by its records. */
static void records_never_replace_other_files(void **state)
{
    (void)state;
    ShellResult r = run_shell(tree, SHELL_TIMEOUT,
                              "make -j2 OPT=-O0 grade-reference LESSON=06 REFERENCE=tests");
    bool kept = file_exists(path_join(tree, "tests/06_sum/test_sum.c")) &&
                file_exists(path_join(tree, "tests/06_sum/points.txt"));
    if (!kept) {
        /* put the made-up lesson's tests back for the tests after this one */
        write_text(path_join(tree, "tests/06_sum/test_sum.c"), TEST_SUM_C);
        write_text(path_join(tree, "tests/06_sum/points.txt"), SUM_POINTS);
    }
    if (r.status == 0 || !kept ||
        !strstr(r.output, "tests/06_sum exists and is not records of the teacher's solution"))
        fail_msg("make grade-reference REFERENCE=tests: status %d, tests/06_sum %s:\n%s", r.status,
                 kept ? "kept" : "replaced", r.output);
    shell_result_free(&r);
}

/* ---- make handout ---- */

static void handout_replaces_the_region_by_stub_and_hint(void **state)
{
    (void)state;
    const char *dest = abs_test_dir("grade_handout");
    /* A README whose table and links name a lesson the handout leaves out. */
    write_text(path_join(tree, "README.md"),
               "| | lesson |\n|---|---|\n"
               "| <img src=\"docs/images/08_x.png\" alt=\"x\"> | [08 plain](lessons/08_plain/) |\n"
               "| <img src=\"docs/images/09_y.png\" alt=\"y\"> | [09 fake](lessons/09_fake/) |\n"
               "[the guide](docs/teaching.md) and [the tests](tests/).\n");
    ShellResult r = shell_ok(tree, "sh tools/handout.sh --only --dest %s/h 09", dest);
    remove(path_join(tree, "README.md"));
    assert_non_null(strstr(r.output, "lessons/09_fake/fake.c:6:"));
    shell_result_free(&r);
    const char *h = path_join(dest, "h");
    char *readme = read_text(path_join(h, "README.md"));
    const char *want_readme = "| | lesson |\n|---|---|\n|  | [09 fake](lessons/09_fake/) |\n"
                              "the guide and [the tests](tests/).\n";
    if (strcmp(readme, want_readme) != 0)
        fail_msg("the handout's README should hold\n%s\nit is\n%s", want_readme, readme);
    free(readme);
    char *fake = read_text(path_join(h, "lessons/09_fake/fake.c"));
    const char *want =
        "int fake_add(int a, int b)\n{\n"
        "    /* TODO(student): return the sum of a and b */\n"
        "    (void)a; (void)b;\n    return 0;\n}\n";
    if (!strstr(fake, want))
        fail_msg("the handout's fake.c should hold\n%s\nit is\n%s", want, fake);
    assert_null(strstr(fake, "a + b"));
    assert_null(strstr(fake, "SOLUTION"));
    free(fake);
    assert_true(file_exists(path_join(h, ".handout")));
    assert_true(file_exists(path_join(h, "Makefile")));
    assert_true(file_exists(path_join(h, "tests/09_fake/points.txt")));
    assert_true(file_exists(path_join(h, "tools/time_limit.c")));
    assert_false(file_exists(path_join(h, "lessons/08_plain"))); /* --only */
    /* Again into the same place: an earlier handout is replaced. */
    r = shell_ok(tree, "sh tools/handout.sh --only --dest %s/h 09", dest);
    shell_result_free(&r);
}

/* EARLIER=stubbed: the earlier lessons' regions are taken out too; a later
 * lesson, left out as usual, is not written back (with it a handout of any
 * lesson but the last failed), and kept (LATER=solved) it is stubbed too. */
static void handout_stubs_the_other_lessons_when_asked(void **state)
{
    (void)state;
    const char *dest = abs_test_dir("grade_stubbed");
    ShellResult r = shell_ok(tree, "sh tools/handout.sh --earlier stubbed --dest %s/h 06", dest);
    shell_result_free(&r);
    const char *h = path_join(dest, "h");
    assert_false(file_exists(path_join(h, "lessons/09_fake"))); /* later: out */
    assert_false(file_exists(path_join(h, "tests/09_fake")));
    char *sum = read_text(path_join(h, "lessons/06_sum/sum.c"));
    assert_non_null(strstr(sum, "TODO(student)"));
    free(sum);

    r = shell_ok(tree, "sh tools/handout.sh --earlier stubbed --dest %s/h 09", dest);
    shell_result_free(&r);
    sum = read_text(path_join(h, "lessons/06_sum/sum.c")); /* earlier: stubbed */
    if (!strstr(sum, "TODO(student)") || strstr(sum, "n * (n + 1)"))
        fail_msg("the earlier lesson's region should be stubbed:\n%s", sum);
    free(sum);

    r = shell_ok(tree, "sh tools/handout.sh --earlier stubbed --later solved --dest %s/h 06", dest);
    shell_result_free(&r);
    char *fake = read_text(path_join(h, "lessons/09_fake/fake.c")); /* later, kept: stubbed */
    if (!strstr(fake, "TODO(student)") || strstr(fake, "a + b"))
        fail_msg("the later lesson, kept, should be stubbed too:\n%s", fake);
    free(fake);
}

/* What must stop the handout, and the message that says why. Nothing is
 * written: neither DEST nor a temporary tree beside it. */
static void expect_refused_handout(const char *lesson, int status, const char *message)
{
    const char *dest = abs_test_dir("grade_refused");
    ShellResult r = run_shell(tree, SHELL_TIMEOUT, "sh tools/handout.sh --dest %s/h %s", dest,
                              lesson);
    if (r.status != status || !strstr(r.output, message))
        fail_msg("handout %s: want status %d and \"%s\", got %d:\n%s", lesson, status, message,
                 r.status, r.output);
    shell_result_free(&r);
    r = run_shell(NULL, 10, "ls -A %s", dest);
    if (r.status != 0 || r.output[0] != '\0')
        fail_msg("a refused handout left files in %s:\n%s", dest, r.output);
    shell_result_free(&r);
}

static void handout_refuses_a_tree_that_gives_a_solution_line_away(void **state)
{
    (void)state;
    const char *notes = path_join(tree, "tests/09_fake/notes.txt");
    write_text(notes, "the answer:\n  int sum = a + b;   /* see? */\n");
    expect_refused_handout("09", 1, "tests/09_fake/notes.txt:2 has lessons/09_fake/fake.c:7");
    /* In prose, spread over lines and dressed up: still the solution's line. */
    write_text(notes, "Hint: write\n`int sum =\n (a) + (b)` and you are done.\n");
    expect_refused_handout("09", 1, "tests/09_fake/notes.txt:2 has lessons/09_fake/fake.c:7");
    /* Words that only talk about it are fine. */
    write_text(notes, "Hint: the sum of a and b, as an int.\n");
    const char *dest = abs_test_dir("grade_prose_ok");
    ShellResult r = shell_ok(tree, "sh tools/handout.sh --only --dest %s/h 09", dest);
    shell_result_free(&r);
    remove(notes);
}

static void handout_refuses_malformed_markers(void **state)
{
    (void)state;
    const char *fake_c = path_join(tree, "lessons/09_fake/fake.c");
    const char *broken[][2] = {
        {"/* SOLUTION BEGIN: x */\nint f;\n", "fake.c:1: the SOLUTION region begun here has no SOLUTION END"},
        {"int f;\n/* SOLUTION END */\n", "fake.c:2: SOLUTION END without a SOLUTION BEGIN"},
        {"/* SOLUTION BEGIN: x */\n/* SOLUTION BEGIN: y */\n/* SOLUTION END */\n", "fake.c:2: SOLUTION BEGIN inside another region"},
        {"/* SOLUTION BEGIN x */\n", "fake.c:1: malformed SOLUTION marker"},
        {"/* SOLUTION BEGIN: */\nint f;\n/* SOLUTION END */\n", "fake.c:1: a SOLUTION BEGIN marker without a hint"},
        {"/* SOLUTION BEGIN: x */\n/* SOLUTION STUB\nint f;\n/* SOLUTION END */\n", "fake.c:4: a SOLUTION marker inside a stub"},
    };
    for (size_t i = 0; i < sizeof broken / sizeof broken[0]; i++) {
        write_text(fake_c, broken[i][0]);
        expect_refused_handout("09", 1, broken[i][1]);
    }
    write_text(fake_c, FAKE_C);
}

static void handout_refuses_bad_requests(void **state)
{
    (void)state;
    expect_refused_handout("08", 1, "lessons/08_plain has no SOLUTION BEGIN marker");
    expect_refused_handout("07", 2, "no lesson LESSON=07 in lessons/");
    expect_refused_handout("", 2, "which lesson?");
    /* A DEST that holds something else is left alone. */
    const char *dest = abs_test_dir("grade_foreign");
    write_text(path_join(dest, "precious.txt"), "keep me\n");
    ShellResult r = run_shell(tree, SHELL_TIMEOUT, "sh tools/handout.sh --dest %s 09", dest);
    if (r.status != 2 || !strstr(r.output, "is not an earlier handout"))
        fail_msg("handout into a foreign directory: status %d\n%s", r.status, r.output);
    shell_result_free(&r);
    assert_true(file_exists(path_join(dest, "precious.txt")));
    assert_false(file_exists(path_join(dest, "Makefile")));
}

/* make grade LESSON=06 REFERENCE=...: its score line, "06_sum: x/5". */
static void expect_judged_score(const char *sum_c, const char *score)
{
    write_text(path_join(tree, "lessons/06_sum/sum.c"), sum_c);
    ShellResult r = run_shell(tree, SHELL_TIMEOUT,
                              "make -j2 OPT=-O0 grade LESSON=06 TIME_LIMIT=5 REFERENCE=build/ref");
    write_text(path_join(tree, "lessons/06_sum/sum.c"), SUM_C);
    char want[64];
    snprintf(want, sizeof want, "06_sum: %s", score);
    if (r.status != 0 || !strstr(r.output, want))
        fail_msg("want %s (status %d):\n%s", want, r.status, r.output);
    shell_result_free(&r);
}

/* The same, for a submission not judged: its score 0/5 and why. */
static void expect_not_judged(const char *sum_c, const char *why)
{
    write_text(path_join(tree, "lessons/06_sum/sum.c"), sum_c);
    ShellResult r = run_shell(tree, SHELL_TIMEOUT,
                              "make -j2 OPT=-O0 grade LESSON=06 TIME_LIMIT=5 REFERENCE=build/ref");
    write_text(path_join(tree, "lessons/06_sum/sum.c"), SUM_C);
    if (r.status != 0 || !strstr(r.output, "06_sum: 0/5") || !strstr(r.output, "is not judged") ||
        !strstr(r.output, why))
        fail_msg("want 0/5, not judged: %s (status %d):\n%s", why, r.status, r.output);
    shell_result_free(&r);
}

/* make grade LESSON=06 against records that cannot judge (the teacher's
 * solution as the submission): the grading fails, saying why, rather than
 * scoring the tests it cannot judge 0 and ending with status 0. */
static void expect_grading_fails(const char *spoil, const char *why)
{
    ShellResult r = shell_ok(tree, "rm -rf build/ref-bad && cp -R build/ref build/ref-bad && %s", spoil);
    shell_result_free(&r);
    r = run_shell(tree, SHELL_TIMEOUT,
                  "make -j2 OPT=-O0 grade LESSON=06 TIME_LIMIT=5 REFERENCE=build/ref-bad");
    if (r.status == 0 || !strstr(r.output, why))
        fail_msg("records spoiled by `%s`: want a failed grading, \"%s\" (status %d):\n%s", spoil,
                 why, r.status, r.output);
    shell_result_free(&r);
}

/* The same, for a header of the submission (with the teacher's sum.c):
 * want_score its score line, or NULL and why it is not judged. */
static void expect_header(const char *sum_h, const char *want_score, const char *why)
{
    write_text(path_join(tree, "lessons/06_sum/sum.h"), sum_h);
    ShellResult r = run_shell(tree, SHELL_TIMEOUT,
                              "make -j2 OPT=-O0 grade LESSON=06 TIME_LIMIT=5 REFERENCE=build/ref");
    write_text(path_join(tree, "lessons/06_sum/sum.h"), SUM_H);
    bool ok = r.status == 0 && (want_score ? strstr(r.output, want_score) != NULL
                                           : strstr(r.output, "06_sum: 0/5") &&
                                                 strstr(r.output, "is not judged") &&
                                                 strstr(r.output, why));
    if (!ok)
        fail_msg("header:\n%swant %s (status %d):\n%s", sum_h, want_score ? want_score : why,
                 r.status, r.output);
    shell_result_free(&r);
}

/* A header is compiled into the tests: it may give the teacher's macro any
 * value and include a standard header, and nothing more. */
static const char SUM_H_WRITTEN_OTHERWISE[] =
    "#include <math.h>\n#include <stdio.h>\n"
    "#define SUM_FIRST (1) /* the first term */\n"
    "int sum_to(int n); // 1 + ... + n\n";
static const char SUM_H_REDEFINES_A_CHECK[] =
    "#define SUM_FIRST 1\n#define assert_int_equal(a, b) ((void)(a), (void)(b))\n"
    "int sum_to(int n);\n";
static const char SUM_H_INCLUDES_A_FILE[] =
    "#define SUM_FIRST 1\n#include \"../../tests/support/observe.h\"\n"
    "int sum_to(int n);\n";
static const char SUM_H_WITH_A_CONSTRUCTOR[] =
    "#define SUM_FIRST 1\nint sum_to(int n);\n"
    "__attribute__((constructor)) static void early(void) {}\n";
static const char SUM_H_WITH_CODE[] =
    "#define SUM_FIRST 1\nint sum_to(int n);\n"
    "static inline int quiet(void) { return 0; }\n"
    "#define main(...) main(__VA_ARGS__) { return quiet(); } int unused(void)\n";

/* The teacher's record made once, then each submission judged against it:
 * the solution scores all, the stub what needs no work, a bug what it gets
 * right, and no forgery more than the stub. */
static void a_judged_lesson_cannot_be_forged(void **state)
{
    (void)state;
    ShellResult r = shell_ok(tree, "make -j2 OPT=-O0 grade-reference LESSON=06 REFERENCE=build/ref");
    if (!strstr(r.output, "06_sum: 5/5"))
        fail_msg("the teacher's solution should score 5/5 while recorded:\n%s", r.output);
    shell_result_free(&r);
    expect_judged_score(SUM_C, "5/5");
    static const char STUB_C[] = "#include \"sum.h\"\nint sum_to(int n) { (void)n; return 0; }\n";
    expect_judged_score(STUB_C, "0/5");
    expect_judged_score(SUM_BUGGY_C, "3/5");
    expect_judged_score(SUM_NEUTERS_CMOCKA_C, "0/5");
    expect_judged_score(SUM_WRITES_RECORD_C, "0/5");
    expect_judged_score(SUM_REDEFINES_OBSERVER_C, "0/5");
    expect_not_judged(SUM_REPLACES_PRINTF_C, "defines vsnprintf, a name the tests or the C library use");
    expect_not_judged(SUM_RECORDS_BEFORE_MAIN_C, "runs code before main");
    expect_not_judged(SUM_RECORDS_BEFORE_MAIN_C, "calls write");
    expect_not_judged(SUM_RESOLVES_BEFORE_MAIN_C, "an indirect function, whose resolver the loader runs");
    expect_not_judged(SUM_REDEFINES_OBSERVER_C, "defines observed_int_equal");
    expect_not_judged(SUM_NEUTERS_CMOCKA_C, "begins with an underscore");
    expect_judged_score(SUM_WITH_A_HELPER_C, "5/5");
    expect_header(SUM_H_WRITTEN_OTHERWISE, "06_sum: 5/5", NULL);
    expect_header(SUM_H_REDEFINES_A_CHECK, NULL, "has the line '#define assert_int_equal'");
    expect_header(SUM_H_INCLUDES_A_FILE, NULL, "has the line '#include \"../../tests/support/observe.h\"'");
    expect_header(SUM_H_WITH_A_CONSTRUCTOR, NULL, "uses __attribute__");
    expect_header(SUM_H_WITH_CODE, NULL, "has the line '#define main");

    /* The judge's words reach the student. */
    write_text(path_join(tree, "lessons/06_sum/sum.c"), SUM_BUGGY_C);
    r = shell_ok(tree, "make -j2 OPT=-O0 grade LESSON=06 TIME_LIMIT=5 REFERENCE=build/ref");
    write_text(path_join(tree, "lessons/06_sum/sum.c"), SUM_C);
    shell_result_free(&r);
    JsonValue v = read_results();
    const JsonValue *tests = field(&v, "tests", JSON_ARRAY);
    bool said = false;
    for (size_t i = 0; i < tests->count; i++) {
        const JsonValue *out = json_get(&tests->items[i], "output");
        said = said || (out && out->type == JSON_STRING &&
                        strstr(out->string, "judge: failed: checks after the start found other "
                                            "values than the teacher's solution's"));
    }
    json_free(&v);
    if (!said)
        fail_msg("no test's output has the judge's words on what differs");

    /* A reference that is not the solution's is refused, and nothing recorded. */
    write_text(path_join(tree, "lessons/06_sum/sum.c"), SUM_BUGGY_C);
    r = run_shell(tree, SHELL_TIMEOUT, "make -j2 OPT=-O0 grade-reference LESSON=06 REFERENCE=build/ref2");
    write_text(path_join(tree, "lessons/06_sum/sum.c"), SUM_C);
    if (r.status == 0 || !strstr(r.output, "does not pass every test"))
        fail_msg("recording a wrong solution should fail (status %d):\n%s", r.status, r.output);
    shell_result_free(&r);
    assert_false(file_exists(path_join(tree, "build/ref2/06_sum")));

    /* Records that cannot judge: a malformed one, a missing one, no record
     * of what the solution calls. Each is the grader's failure. */
    expect_grading_fails("for f in build/ref-bad/06_sum/*.sums_to_ten.obs; do echo x >\"$f\"; done",
                         "could not judge: sums_to_ten");
    expect_grading_fails("rm build/ref-bad/06_sum/*.sums_in_a_loop.obs",
                         "have no record of: sums_in_a_loop");
    expect_grading_fails("rm -r build/ref-bad/06_sum/check",
                         "06_sum not graded: the teacher's records of 06_sum");
}

/* ---- make autograder: Gradescope's layout, simulated ---- */

/* The image of the made-up lesson 06_sum, built once as Gradescope would
 * (setup.sh, as root, in a directory of its layout), and graded in for each
 * submission (run_autograder). The student users are the test's own. */
#define TEST_USERS "grader-test0 grader-test1"
static char image[4096];

static void build_image(void)
{
    ShellResult r = shell_ok(tree, "make autograder LESSON=06");
    shell_result_free(&r);
    /* In /tmp, readable on the way down: the student users must reach the
     * tree they are graded in, as they reach /autograder on Gradescope, and
     * TEST_OUTPUT may lie below a directory only its owner enters. */
    snprintf(image, sizeof image, "/tmp/autograder-test.XXXXXX");
    if (!mkdtemp(image) || chmod(image, 0755) != 0)
        fail_msg("cannot make a directory for the autograder's image in /tmp");
    r = run_shell(image, SHELL_TIMEOUT,
                  "mkdir -p source && cd source && unzip -q %s/build/autograder/06_sum.zip && cd .. && "
                  "OPT=-O0 AUTOGRADER_ROOT=%s AUTOGRADER_SKIP_APT=1 AUTOGRADER_USERS='" TEST_USERS "' "
                  "sh source/setup.sh", tree, image);
    if (r.status != 0)
        fail_msg("setup.sh: status %d\n%s", r.status, r.output);
    shell_result_free(&r);
}

typedef struct {
    double score;
    char *output; /* results.json's output, and the tests' outputs after it */
    char *log;    /* run_autograder's own output, as the teacher sees it: the build's and the grade's logs */
    double seconds;
    char dir[4096]; /* where it was graded: submission/ and results/ */
} Graded;

/* Grades SUBMISSION (files to write under it: path, text, ...) in the image. */
static Graded autograde(const char *name, const char *const *files)
{
    char dir_name[64];
    snprintf(dir_name, sizeof dir_name, "autograder_%s", name);
    const char *dir = abs_test_dir(dir_name);
    ShellResult r = shell_ok(dir, "mkdir -p submission results");
    shell_result_free(&r);
    for (int i = 0; files[i]; i += 2) {
        const char *path = path_join(path_join(dir, "submission"), files[i]);
        r = shell_ok(NULL, "mkdir -p $(dirname %s)", path);
        shell_result_free(&r);
        write_text(path, files[i + 1]);
    }
    struct timespec t0;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    r = run_shell(dir, SHELL_TIMEOUT,
                  "AUTOGRADER_ROOT=%s AUTOGRADER_SUBMISSION=%s/submission "
                  "AUTOGRADER_RESULTS=%s/results/results.json AUTOGRADER_USERS='" TEST_USERS "' "
                  "AUTOGRADER_TIME_LIMIT=1 AUTOGRADER_TOTAL_LIMIT=60 sh %s/source/run_autograder",
                  image, dir, dir, image);
    Graded g;
    snprintf(g.dir, sizeof g.dir, "%s", dir);
    g.seconds = seconds_since(&t0);
    if (r.status != 0)
        fail_msg("run_autograder (%s): status %d\n%s", name, r.status, r.output);
    g.log = strdup(r.output);
    assert_non_null(g.log);
    shell_result_free(&r);
    char *text = read_text(path_join(dir, "results/results.json"));
    JsonValue v;
    char why[256];
    if (!json_parse(text, strlen(text), &v, why, sizeof why))
        fail_msg("%s: results.json is not JSON: %s\n%s", name, why, text);
    g.output = text; /* the whole of it: what a student could be shown */
    g.score = field(&v, "score", JSON_NUMBER)->number;
    const JsonValue *format = json_get(&v, "output_format");
    if (!format || format->type != JSON_STRING || strcmp(format->string, "text") != 0)
        fail_msg("%s: results.json should say \"output_format\": \"text\"", name);
    json_free(&v);
    return g;
}

/* No process of the student users is left (a zombie is dead: it has only
 * to be reaped by whoever inherited it). */
static void expect_no_student_process(const char *after)
{
    ShellResult r = run_shell(NULL, 30, "for u in " TEST_USERS "; do "
                                        "ps -o pid=,stat=,args= -u $u | awk '$2 !~ /^Z/'; done");
    if (r.output[0])
        fail_msg("after %s, processes of the student users are left:\n%s", after, r.output);
    shell_result_free(&r);
}

static const char SUM_STUB_C[] = "#include \"sum.h\"\nint sum_to(int n) { (void)n; return 0; }\n";
/* The teacher's solution, included from where the zip was unpacked. */
static const char INCLUDES_SOLUTION_C[] = "#include \"%s/source/lessons/06_sum/sum.c\"\n";
/* At run time: the solution printed, the results and the expected
 * pictures written over, a process left behind to write the results later
 * and to hold the output open. */
static const char ATTACKS_C[] =
    "#include \"sum.h\"\n#include <stdio.h>\n#include <stdlib.h>\n#include <unistd.h>\n"
    "static void over(const char *path) { FILE *f = fopen(path, \"w\");\n"
    "    if (f) { fputs(\"{\\\"score\\\": 100, \\\"tests\\\": []}\\n\", f); fclose(f); } }\n"
    "int sum_to(int n) {\n"
    "    FILE *s = fopen(\"%s/source/lessons/06_sum/sum.c\", \"r\");\n"
    "    for (int c; s && (c = getc(s)) != EOF;) putchar(c);\n"
    "    over(\"%s/results/results.json\");\n"
    "    over(\"%s/grading/results.json\");\n"
    "    over(\"tests/expected/06_sum/forged.png\");\n"
    "    if (fork() == 0) { setsid(); sleep(4); over(\"%s/results/results.json\"); _exit(0); }\n"
    "    (void)n; return 0; }\n";
static const char DEBUG_PRINT_C[] =
    "#include \"sum.h\"\n#include <stdio.h>\n"
    "int sum_to(int n) { int s = 0; for (int k = 1; k <= n; k++) { s += k;\n"
    "    printf(\"k %d s %d\\n\", k, s); fprintf(stderr, \"k %d\\n\", k); } return s; }\n";
static const char SUM_CRASH_C[] = "#include \"sum.h\"\n#include <signal.h>\n"
                                  "int sum_to(int n) { raise(SIGSEGV); return n; }\n";
/* Never returns, blocked rather than spinning: the wall clock ends it. */
static const char SUM_HANG_C[] = "#include \"sum.h\"\n#include <unistd.h>\n"
                                 "int sum_to(int n) { for (;;) pause(); return n; }\n";

/* After the autograder's test: its image gone from /tmp, and the tree as set up. */
static int remove_image(void **state)
{
    if (image[0]) {
        ShellResult r = run_shell(NULL, 60, "rm -rf %s", image);
        shell_result_free(&r);
        image[0] = '\0';
    }
    return restore_tree(state);
}

/* The autograder on the made-up lesson, each submission as a student would
 * send it or an attacker would: each scores what it should, in its time, and
 * leaves the image, the results and the machine as they were. */
static void autograder_cannot_be_forged_and_takes_any_shape(void **state)
{
    (void)state;
    if (geteuid() != 0) {
        print_message("skipped: Gradescope runs the autograder as root, and it grades as "
                      "users of its own; this test needs root to do the same\n");
        skip();
    }
    build_image();
    char includes[8192], attacks[32768];
    snprintf(includes, sizeof includes, INCLUDES_SOLUTION_C, image);
    snprintf(attacks, sizeof attacks, ATTACKS_C, image, image, image, image);
    const char *correct[] = {"sum.c", SUM_C, NULL};
    /* A repository: its own points file and tests count for nothing. */
    const char *repository[] = {"repo/lessons/06_sum/sum.c", SUM_C,
                                "repo/tests/06_sum/points.txt", "sums_to_ten 100 everything\n",
                                NULL};
    /* A zip of the handout folder, with a stubbed copy deeper in it. */
    const char *handout[] = {"h/lessons/06_sum/sum.c", SUM_C,
                             "h/build/handout/06_sum/lessons/06_sum/sum.c", SUM_STUB_C, NULL};
    const char *stub[] = {"sum.c", SUM_STUB_C, NULL};
    const char *buggy[] = {"sum.c", SUM_BUGGY_C, NULL};
    const char *neuters[] = {"sum.c", SUM_NEUTERS_CMOCKA_C, NULL};
    const char *writes_record[] = {"sum.c", SUM_WRITES_RECORD_C, NULL};
    const char *redefines[] = {"sum.c", SUM_REDEFINES_OBSERVER_C, NULL};
    const char *includes_solution[] = {"sum.c", includes, NULL};
    const char *attacking[] = {"sum.c", attacks, NULL};
    const char *debug[] = {"sum.c", DEBUG_PRINT_C, NULL};
    const char *crashing[] = {"sum.c", SUM_CRASH_C, NULL};
    const char *hanging[] = {"sum.c", SUM_HANG_C, NULL};
    const char *nothing[] = {"notes.txt", "I did not do it\n", NULL};
    struct { const char *name; const char *const *files; double score; } cases[] = {
        {"correct", correct, 5},        {"repository", repository, 5}, {"handout", handout, 5},
        {"stub", stub, 0},              {"buggy", buggy, 3},          {"neuters", neuters, 0},
        {"writes_record", writes_record, 0}, {"redefines", redefines, 0},
        {"includes_solution", includes_solution, 0}, {"attacking", attacking, 0},
        {"debug_print", debug, 5},      {"crashing", crashing, 0},    {"hanging", hanging, 0},
        {"nothing", nothing, 0},
    };
    ShellResult before = shell_ok(image, "cd template && find tests/expected -type f | sort | xargs md5sum");
    char attacked[4096] = "";
    struct timespec attacked_at = {0, 0};
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        Graded g = autograde(cases[i].name, cases[i].files);
        if (cases[i].files == attacking) {
            clock_gettime(CLOCK_MONOTONIC, &attacked_at);
            snprintf(attacked, sizeof attacked, "%s", g.dir);
            /* The tree it was graded in keeps the teacher's expected pictures. */
            ShellResult graded = shell_ok(image, "cd work && find tests/expected -type f | sort | xargs md5sum");
            assert_string_equal(before.output, graded.output);
            shell_result_free(&graded);
        }
        if (g.score != cases[i].score) { /* (whole: fail_msg cuts a message short) */
            fprintf(stderr, "results.json:\n%s\nrun_autograder said:\n%s\n", g.output, g.log);
            fail_msg("the %s submission scored %g, want %g (results.json and run_autograder's "
                     "own output above)", cases[i].name, g.score, cases[i].score);
        }
        if (g.seconds > 50)
            fail_msg("the %s submission took %.0f s: over its total limit", cases[i].name, g.seconds);
        /* The first line says which files were graded. */
        if (strcmp(cases[i].name, "nothing") != 0 &&
            !strstr(g.output, "\"output\": \"graded lessons/06_sum/sum.c: the submission's "))
            fail_msg("the %s submission's output should begin with the file graded:\n%s",
                     cases[i].name, g.output);
        /* Nothing of the solution reaches the student. */
        if (strstr(g.output, "(n + 1)"))
            fail_msg("the %s submission's results show the solution:\n%s", cases[i].name, g.output);
        free(g.output);
        free(g.log);
        expect_no_student_process(cases[i].name);
    }
    ShellResult after = shell_ok(image, "cd template && find tests/expected -type f | sort | xargs md5sum");
    assert_string_equal(before.output, after.output);
    shell_result_free(&before);
    shell_result_free(&after);
    /* The attacker's process, had it lived, would have written by now: 5 s
     * after its grading ended (the submissions after it took some of them). */
    double left = 5.0 - seconds_since(&attacked_at);
    if (left > 0) {
        struct timespec pause = {(time_t)left, (long)((left - (double)(time_t)left) * 1e9)};
        nanosleep(&pause, NULL);
    }
    char *text = read_text(path_join(attacked, "results/results.json"));
    if (strstr(text, "\"score\": 100"))
        fail_msg("the attacker's results file stands:\n%s", text);
    free(text);
}

/* make classroom: Classroom 50's declarative tests, read back as JSON: a
 * setup, then one "run" test per line of points.txt with points; and their
 * commands run as Classroom 50 runs them, in the tree: the setup builds, a
 * test that passes exits 0, one that fails does not. */
static void classroom_tests_run_as_classroom_50_runs_them(void **state)
{
    (void)state;
    ShellResult r = shell_ok(tree, "make classroom LESSON=06");
    shell_result_free(&r);
    char *text = read_text(path_join(tree, "classroom50/tests.json"));
    JsonValue v;
    char why[256];
    if (!json_parse(text, strlen(text), &v, why, sizeof why))
        fail_msg("tests.json is not JSON: %s\n%s", why, text);
    free(text);
    if (v.type != JSON_ARRAY)
        fail_msg("tests.json holds a %s, not the bare array Classroom 50 reads", json_type_name(v.type));
    assert_int_equal(v.count, 4); /* the setup, and the three tests with points */
    double points = 0;
    for (size_t i = 0; i < v.count; i++) {
        const JsonValue *t = &v.items[i];
        const char *name = field(t, "name", JSON_STRING)->string;
        assert_string_equal(field(t, "type", JSON_STRING)->string, "run");
        double timeout = field(t, "timeout", JSON_NUMBER)->number;
        assert_true(timeout >= 1 && timeout <= 600);
        points += field(t, "points", JSON_NUMBER)->number;
        if (i == 0)
            assert_string_equal(name, "setup");
        /* The command, as the runner would run it: in the checkout, by sh. */
        const char *run = field(t, "run", JSON_STRING)->string;
        r = run_shell(tree, SHELL_TIMEOUT, "%s", run);
        if (r.status != 0)
            fail_msg("%s: `%s` exits %d on the solution:\n%s", name, run, r.status, r.output);
        shell_result_free(&r);
    }
    assert_true(points == 5.0);
    /* A wrong sum_to: its test's command fails. */
    write_text(path_join(tree, "lessons/06_sum/sum.c"), SUM_BUGGY_C);
    r = run_shell(tree, SHELL_TIMEOUT, "%s", field(&v.items[0], "run", JSON_STRING)->string);
    shell_result_free(&r);
    r = run_shell(tree, SHELL_TIMEOUT, "%s", field(&v.items[2], "run", JSON_STRING)->string);
    write_text(path_join(tree, "lessons/06_sum/sum.c"), SUM_C);
    if (r.status == 0)
        fail_msg("`%s` passed with a bug in sum_to", field(&v.items[2], "run", JSON_STRING)->string);
    shell_result_free(&r);
    json_free(&v);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_teardown(each_failure_costs_only_its_own_points, restore_tree),
        cmocka_unit_test_teardown(code_that_does_not_compile_scores_zero, restore_tree),
        cmocka_unit_test_teardown(one_test_alone_sets_the_exit_status, restore_tree),
        cmocka_unit_test_teardown(malformed_points_file_is_refused_with_its_line, restore_tree),
        cmocka_unit_test_teardown(bad_grade_values_are_refused_before_the_build, restore_tree),
        cmocka_unit_test_teardown(records_never_replace_other_files, restore_tree),
        cmocka_unit_test_teardown(handout_replaces_the_region_by_stub_and_hint, restore_tree),
        cmocka_unit_test_teardown(handout_stubs_the_other_lessons_when_asked, restore_tree),
        cmocka_unit_test_teardown(handout_refuses_a_tree_that_gives_a_solution_line_away, restore_tree),
        cmocka_unit_test_teardown(handout_refuses_malformed_markers, restore_tree),
        cmocka_unit_test_teardown(handout_refuses_bad_requests, restore_tree),
        cmocka_unit_test_teardown(autograder_cannot_be_forged_and_takes_any_shape,
                                  remove_image),
        cmocka_unit_test_teardown(classroom_tests_run_as_classroom_50_runs_them, restore_tree),
        cmocka_unit_test_teardown(a_judged_lesson_cannot_be_forged, restore_tree),
    };
    return cmocka_run_group_tests_name("tools: make grade and make handout on a made-up lesson",
                                       tests, set_up_tree, NULL);
}
