/* time_limit.c: run a program, but not for longer than a given time.
 *
 *   time_limit SECONDS PROGRAM [ARG...]
 *
 * make grade runs every test of a student's work through it, so that a test
 * that hangs costs that test's points and not the whole grade. It does what
 * timeout(1) does, written here so that a C compiler and make are all the
 * series needs, also where timeout(1) is missing.
 *
 * The program runs in a process group of its own; when time is up the whole
 * group is killed (a test that started a lesson's executable takes it along).
 *
 * Exit status, the same as timeout(1) and the shell use:
 *   the program's own status when it exits in time,
 *   124 when it ran out of time,
 *   128 + N when signal N killed it (a crash: 139 is a segmentation fault),
 *   125 when time_limit itself was used wrongly,
 *   127 when the program could not be started. */
#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#define STATUS_TIMED_OUT 124
#define STATUS_OWN_FAILURE 125
#define STATUS_CANNOT_RUN 127
#define STATUS_SIGNAL_BASE 128
#define MAX_SECONDS 86400.0
#define POLL_NS 5000000L /* look at the child every 5 ms */
#define NS_PER_SECOND 1e9

/* Set by a SIGINT or SIGTERM sent to time_limit: the child's group is in
 * another process group, so the terminal's Ctrl-C does not reach it. */
static volatile sig_atomic_t interrupted;

static void on_interrupt(int sig)
{
    interrupted = sig;
}

static int usage_error(const char *what)
{
    fprintf(stderr, "time_limit: error: %s\n", what);
    fprintf(stderr, "usage: time_limit SECONDS PROGRAM [ARG...]\n");
    return STATUS_OWN_FAILURE;
}

static double seconds_since(const struct timespec *start)
{
    struct timespec now;
    clock_gettime(CLOCK_MONOTONIC, &now);
    return (double)(now.tv_sec - start->tv_sec) +
           (double)(now.tv_nsec - start->tv_nsec) / NS_PER_SECOND;
}

static void kill_group(pid_t pid)
{
    kill(-pid, SIGKILL);
    kill(pid, SIGKILL); /* in case setpgid had not happened yet */
}

/* Waits for the child; returns its exit status as the shell reports it. */
static int wait_for(pid_t pid, double limit)
{
    struct timespec start;
    clock_gettime(CLOCK_MONOTONIC, &start);
    for (;;) {
        int st;
        pid_t r = waitpid(pid, &st, WNOHANG);
        if (r == pid) {
            kill(-pid, SIGKILL); /* what the program left running dies with it */
            return WIFEXITED(st) ? WEXITSTATUS(st) : STATUS_SIGNAL_BASE + WTERMSIG(st);
        }
        if (r < 0 && errno != EINTR) {
            fprintf(stderr, "time_limit: error: waitpid: %s\n", strerror(errno));
            kill_group(pid);
            return STATUS_OWN_FAILURE;
        }
        if (interrupted || seconds_since(&start) >= limit) {
            kill_group(pid);
            while (waitpid(pid, &st, 0) < 0 && errno == EINTR)
                continue;
            return interrupted ? STATUS_SIGNAL_BASE + interrupted : STATUS_TIMED_OUT;
        }
        struct timespec pause = {0, POLL_NS};
        nanosleep(&pause, NULL);
    }
}

int main(int argc, char **argv)
{
    if (argc < 3)
        return usage_error("wants a time in seconds and a program to run");
    char *end;
    errno = 0;
    double limit = strtod(argv[1], &end);
    if (errno != 0 || end == argv[1] || *end != '\0' || !(limit > 0.0) || limit > MAX_SECONDS)
        return usage_error("the time limit must be a number of seconds, above 0 and at most 86400");

    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_interrupt;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, NULL);
    sigaction(SIGTERM, &sa, NULL);

    fflush(stdout);
    fflush(stderr);
    pid_t pid = fork();
    if (pid < 0) {
        fprintf(stderr, "time_limit: error: cannot fork: %s\n", strerror(errno));
        return STATUS_OWN_FAILURE;
    }
    if (pid == 0) {
        setpgid(0, 0);
        signal(SIGINT, SIG_DFL);
        signal(SIGTERM, SIG_DFL);
        execvp(argv[2], argv + 2);
        fprintf(stderr, "time_limit: error: cannot run %s: %s\n", argv[2], strerror(errno));
        _exit(STATUS_CANNOT_RUN);
    }
    setpgid(pid, pid); /* also here: whichever runs first, the group exists */
    return wait_for(pid, limit);
}
