/* shell.h: run a shell command line from a test, as a user would type it.
 *
 * For the tests of the classroom tools (make handout, make grade), which run
 * make and scripts in other directories. run_program (test_support.h) runs
 * the series' own executables; this runs `sh -c COMMAND`.
 *
 * The command runs in directory dir (NULL: the current one), with stdin from
 * /dev/null and stdout and stderr together in one text, without what an
 * enclosing make passes down (MAKEFLAGS, MAKELEVEL, MFLAGS, and the series'
 * variables of its command line: BUILD, OPT, LESSON, ...): a make in the
 * command starts afresh; a make test in it keeps its scratch in its own tree
 * (TEST_SCRATCH=, tools/run-tests.sh). After timeout_seconds it is killed
 * with everything it started: status 124. */
#ifndef SHELL_H
#define SHELL_H

#include <stdbool.h>
#include <sys/types.h>

typedef struct {
    int status;   /* exit status, 128 + N if signal N killed it, 124 on timeout */
    char *output; /* stdout and stderr, in the order they were written */
} ShellResult;

ShellResult run_shell(const char *dir, int timeout_seconds, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;
void shell_result_free(ShellResult *r);

/* Waits for child pid (run_shell's, run_program's): its exit status, 128 + N
 * if signal N killed it. After timeout_seconds it is killed, with the process
 * group it leads when group: 124. It is looked at 0.1 ms after the start,
 * then twice as long after each look, at least every 10 ms: most are short. */
int wait_child(pid_t pid, int timeout_seconds, bool group);

#endif
