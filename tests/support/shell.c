/* shell.c: see shell.h. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "shell.h"

#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#define STATUS_TIMED_OUT 124 /* what timeout(1) reports */
#define STATUS_SIGNAL_BASE 128
#define POLL_MAX_NS 10000000L /* wait_child looks at the child at least every 10 ms */

static char *read_all(FILE *fp)
{
    size_t cap = 4096, len = 0, got;
    char *buf = malloc(cap);
    if (!buf)
        fail_msg("out of memory");
    rewind(fp);
    while ((got = fread(buf + len, 1, cap - len - 1, fp)) > 0) {
        len += got;
        if (len + 1 == cap) {
            cap *= 2;
            buf = realloc(buf, cap);
            if (!buf)
        fail_msg("out of memory");
        }
    }
    buf[len] = '\0';
    return buf;
}

static void run_child(const char *dir, const char *command, FILE *out)
{
    setpgid(0, 0); /* its own group, so that a timeout kills all it started */
    int null_fd = open("/dev/null", O_RDONLY);
    if (null_fd < 0 || dup2(null_fd, STDIN_FILENO) < 0 ||
        dup2(fileno(out), STDOUT_FILENO) < 0 || dup2(fileno(out), STDERR_FILENO) < 0)
        _exit(127);
    if (dir && chdir(dir) != 0) {
        fprintf(stderr, "run_shell: cannot enter %s: %s\n", dir, strerror(errno));
        _exit(127);
    }
    /* What an enclosing make passed down: its flags, and the variables of its
     * command line (make exports them), which would steer this make too. */
    const char *const inherited[] = {"MAKEFLAGS", "MAKELEVEL", "MFLAGS", "BUILD", "OPT",
                                     "LESSON", "DEST", "ONLY", "TEST", "TIME_LIMIT",
                                     "UPDATE_EXPECTED"};
    for (size_t i = 0; i < sizeof inherited / sizeof inherited[0]; i++)
        unsetenv(inherited[i]);
    /* A make test in the command keeps its scratch in its own tree, not in
     * /dev/shm (tools/run-tests.sh): that tree is this test's, removed with it. */
    setenv("TEST_SCRATCH", "", 1);
    execl("/bin/sh", "sh", "-c", command, (char *)NULL);
    _exit(127);
}

ShellResult run_shell(const char *dir, int timeout_seconds, const char *fmt, ...)
{
    char command[8192];
    va_list ap;
    va_start(ap, fmt);
    int n = vsnprintf(command, sizeof command, fmt, ap);
    va_end(ap);
    if (n < 0 || (size_t)n >= sizeof command)
        fail_msg("run_shell: command too long");

    FILE *out = tmpfile();
    if (!out)
        fail_msg("run_shell: no temporary file: %s", strerror(errno));
    fflush(stdout);
    fflush(stderr);
    pid_t pid = fork();
    if (pid < 0)
        fail_msg("run_shell: cannot fork: %s", strerror(errno));
    if (pid == 0)
        run_child(dir, command, out);
    setpgid(pid, pid);

    ShellResult r = {wait_child(pid, timeout_seconds, true), NULL};
    r.output = read_all(out);
    fclose(out);
    return r;
}

int wait_child(pid_t pid, int timeout_seconds, bool group)
{
    struct timespec start, now;
    clock_gettime(CLOCK_MONOTONIC, &start);
    long sleep_ns = 100000;
    for (;;) {
        int st;
        pid_t w = waitpid(pid, &st, WNOHANG);
        if (w == pid)
            return WIFEXITED(st) ? WEXITSTATUS(st) : STATUS_SIGNAL_BASE + WTERMSIG(st);
        if (w < 0 && errno != EINTR)
            fail_msg("waitpid: %s", strerror(errno));
        clock_gettime(CLOCK_MONOTONIC, &now);
        if (now.tv_sec - start.tv_sec >= timeout_seconds) {
            kill(group ? -pid : pid, SIGKILL);
            while (waitpid(pid, &st, 0) < 0 && errno == EINTR)
                continue;
            return STATUS_TIMED_OUT;
        }
        struct timespec pause = {0, sleep_ns};
        nanosleep(&pause, NULL);
        sleep_ns = sleep_ns * 2 > POLL_MAX_NS ? POLL_MAX_NS : sleep_ns * 2;
    }
}

void shell_result_free(ShellResult *r)
{
    free(r->output);
    r->output = NULL;
}
