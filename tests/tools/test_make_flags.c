/* test_make_flags.c: no command line takes the required flags away.
 *
 * docs/conventions.md: every build is C11 with warnings as errors and
 * -ffp-contract=off. The Makefile keeps those in REQUIRED_CFLAGS, which every
 * compile and link rule puts after the user's OPT and CFLAGS: with
 * `make CFLAGS=-O0`, `make OPT=-Og` or even `make CFLAGS=-Wno-error`, the
 * compiler still gets all of them, and they come last, so they win (the
 * compiler takes the last -std=, -ffp-contract=, -Werror or -Wno-error).
 *
 * Each test asks make what it would run (`make -n -B`, nothing is built) and
 * reads the command that compiles or links one file: the lessons', the
 * tools', the tests', and those of make sanitize, make bench and make fuzz. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "shell.h"

#define SHELL_TIMEOUT 120
#define MAX_WORDS 512

/* What docs/conventions.md asks of every compile and link. */
static const char *const REQUIRED[] = {
    "-std=c11",  "-Wall",       "-Wextra",      "-Werror",
    "-pedantic", "-Wshadow",    "-Wconversion", "-Wmissing-prototypes",
    "-ffp-contract=off",
};
#define REQUIRED_COUNT (sizeof REQUIRED / sizeof REQUIRED[0])

/* User flags that would undo them, were they last. */
#define UNDOING "-O0 -std=gnu99 -Wno-error -Wno-shadow -Wno-conversion -ffp-contract=fast"

typedef struct {
    char *text;             /* the command, split in place */
    char *word[MAX_WORDS];
    int n;
} Command;

/* The first line of `make -n -B ARGS` that holds every one of needles (a
 * NULL-terminated list), split into words; the test fails if there is none. */
static Command command_of(const char *args, const char *const *needles)
{
    ShellResult r = run_shell(NULL, SHELL_TIMEOUT, "make -n -B %s", args);
    if (r.status != 0)
        fail_msg("make -n -B %s: status %d\n%s", args, r.status, r.output);
    /* A recipe line continued with a backslash is one command. */
    char *to = r.output;
    for (const char *from = r.output; *from; from++) {
        if (from[0] == '\\' && from[1] == '\n')
            from++;
        else
            *to++ = *from;
    }
    *to = '\0';
    Command c = {0};
    for (char *line = strtok(r.output, "\n"); line; line = strtok(NULL, "\n")) {
        bool all = true;
        for (int i = 0; needles[i]; i++)
            all = all && strstr(line, needles[i]) != NULL;
        if (!all)
            continue;
        c.text = strdup(line);
        assert_non_null(c.text);
        break;
    }
    if (!c.text)
        fail_msg("make -n -B %s runs no command with \"%s\"", args, needles[0]);
    shell_result_free(&r);
    for (char *w = strtok(c.text, " \t"); w && c.n < MAX_WORDS; w = strtok(NULL, " \t"))
        c.word[c.n++] = w;
    return c;
}

/* Where word is last in the command; -1 if it is not there. */
static int last_index(const Command *c, const char *word)
{
    int at = -1;
    for (int i = 0; i < c->n; i++)
        if (strcmp(c->word[i], word) == 0)
            at = i;
    return at;
}

/* Every required flag is in c, after every word of the user's flags. */
static void expect_required_last(const Command *c, const char *what, const char *user)
{
    char copy[512];
    snprintf(copy, sizeof copy, "%s", user);
    int user_last = -1;
    for (char *w = strtok(copy, " "); w; w = strtok(NULL, " ")) {
        int at = last_index(c, w);
        if (at < 0)
            fail_msg("%s: the user's %s is not in the command", what, w);
        if (at > user_last)
            user_last = at;
    }
    for (size_t i = 0; i < REQUIRED_COUNT; i++) {
        int at = last_index(c, REQUIRED[i]);
        if (at < 0)
            fail_msg("%s: the command has no %s", what, REQUIRED[i]);
        if (at < user_last)
            fail_msg("%s: %s comes before the user's flags, which then win", what, REQUIRED[i]);
    }
}

static void expect_word(const Command *c, const char *what, const char *word)
{
    if (last_index(c, word) < 0)
        fail_msg("%s: the command has no %s", what, word);
}

static void command_free(Command *c)
{
    free(c->text);
}

static void compile_and_link_keep_them_with_cflags(void **state)
{
    (void)state;
    const char *compile[] = {" -c common/vecmath.c ", NULL};
    Command c = command_of("CFLAGS='" UNDOING "' build/obj/common/vecmath.o", compile);
    expect_required_last(&c, "make CFLAGS=... (compile)", UNDOING);
    expect_word(&c, "make CFLAGS=... (compile)", "-D_POSIX_C_SOURCE=200809L");
    command_free(&c);

    const char *link[] = {" -o build/bin/02_zbuffer", NULL};
    c = command_of("CFLAGS='" UNDOING "' build/bin/02_zbuffer", link);
    expect_required_last(&c, "make CFLAGS=... (link)", UNDOING);
    expect_word(&c, "make CFLAGS=... (link)", "-lm");
    command_free(&c);
}

static void plain_cflags_O0_keeps_werror(void **state)
{
    (void)state;
    const char *compile[] = {" -c tools/make_obj.c ", NULL};
    Command c = command_of("CFLAGS=-O0 build/obj/tools/make_obj.o", compile);
    expect_required_last(&c, "make CFLAGS=-O0", "-O0");
    command_free(&c);
}

static void opt_and_the_other_variables_keep_them(void **state)
{
    (void)state;
    /* OPT, and the required variables themselves on the command line. */
    const char *compile[] = {" -c build/lessons/02_zbuffer/main.c ", NULL};
    Command c = command_of("OPT='" UNDOING "' WARN= REQUIRED_CFLAGS= REQUIRED_CPPFLAGS= "
                           "build/obj/lessons/02_zbuffer/main.o",
                           compile);
    expect_required_last(&c, "make OPT=... WARN= REQUIRED_CFLAGS=", UNDOING);
    expect_word(&c, "make REQUIRED_CPPFLAGS=", "-Icommon");
    command_free(&c);

    /* A test's object keeps its include directories whatever CPPFLAGS says. */
    const char *test[] = {" -c tests/common/test_vecmath.c ", NULL};
    c = command_of("CPPFLAGS=-DNDEBUG CFLAGS=-O0 build/obj/tests/common/test_vecmath.o", test);
    expect_required_last(&c, "make CPPFLAGS=... (a test)", "-DNDEBUG -O0");
    expect_word(&c, "make CPPFLAGS=... (a test)", "-Itests/support");
    command_free(&c);

    const char *link[] = {" -o build/tests/common/test_vecmath", NULL};
    c = command_of("LDLIBS=-lc CFLAGS=-O0 build/tests/common/test_vecmath", link);
    expect_required_last(&c, "make LDLIBS=... (a test's link)", "-O0");
    expect_word(&c, "make LDLIBS=... (a test's link)", "-lm");
    command_free(&c);
}

static void sanitize_keeps_them_and_its_own(void **state)
{
    (void)state;
    const char *compile[] = {" -c common/vecmath.c ", "build/sanitize/", NULL};
    Command c = command_of("CFLAGS='" UNDOING "' sanitize", compile);
    expect_required_last(&c, "make sanitize CFLAGS=...", UNDOING);
    expect_word(&c, "make sanitize CFLAGS=...", "-fsanitize=address,undefined");
    expect_word(&c, "make sanitize CFLAGS=...", "-fsanitize=float-cast-overflow");
    command_free(&c);

    const char *link[] = {" -o build/sanitize/bin/02_zbuffer", NULL};
    c = command_of("OPT=-O0 sanitize", link);
    expect_required_last(&c, "make sanitize OPT=-O0 (link)", "-O0");
    expect_word(&c, "make sanitize OPT=-O0 (link)", "-fsanitize=address,undefined");
    command_free(&c);
}

static void bench_keeps_them_and_O2(void **state)
{
    (void)state;
    const char *compile[] = {" -c common/vecmath.c ", "build/bench/", NULL};
    Command c = command_of("CFLAGS='" UNDOING "' OPT=-O0 build/bench/obj/common/vecmath.o",
                           compile);
    expect_required_last(&c, "make bench CFLAGS=...", UNDOING);
    if (last_index(&c, "-O2") < last_index(&c, "-O0"))
        fail_msg("make bench CFLAGS=-O0: -O2 should come last, the benchmark times -O2");
    command_free(&c);
}

static void fuzz_keeps_them_and_its_own(void **state)
{
    (void)state;
    const char *compile[] = {" -c tests/fuzz/fuzz_obj.c ", NULL};
    Command c = command_of("CFLAGS='" UNDOING "' fuzz FUZZ=obj SECONDS=1", compile);
    expect_required_last(&c, "make fuzz CFLAGS=...", UNDOING);
    expect_word(&c, "make fuzz CFLAGS=...", "-fsanitize=fuzzer-no-link,address,undefined");
    command_free(&c);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(compile_and_link_keep_them_with_cflags),
        cmocka_unit_test(plain_cflags_O0_keeps_werror),
        cmocka_unit_test(opt_and_the_other_variables_keep_them),
        cmocka_unit_test(sanitize_keeps_them_and_its_own),
        cmocka_unit_test(bench_keeps_them_and_O2),
        cmocka_unit_test(fuzz_keeps_them_and_its_own),
    };
    return cmocka_run_group_tests_name("tools: required compiler flags", tests, NULL, NULL);
}
