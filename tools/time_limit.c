/* time_limit.c: run a program, but not for longer than a given time.
 *
 *   time_limit [--cpu CPU_SECONDS] [--cpu-out FILE] [--output FILE [--output-max BYTES]]
 *              SECONDS PROGRAM [ARG...]
 *
 * SECONDS is wall-clock time. --cpu also limits the CPU time of the program
 * and of each program it starts (each process, all its threads together, as
 * the kernel counts it: RLIMIT_CPU), so that a loaded machine, where the
 * program waits for a core, does not make it run out of time: make grade
 * limits CPU time this way and keeps SECONDS only to stop a program that
 * waits for ever. --cpu-out writes the CPU seconds that the program and the
 * programs it waited for used, user and system, to FILE ("%.3f\n").
 *
 * --output: the program's stdout and stderr go to FILE through a pipe that
 * time_limit reads, at most BYTES of them (1 MiB by default); the rest is
 * read and thrown away, so that a program printing gigabytes is neither
 * stopped nor slowed by a full pipe, and a note at the end says where the
 * output was cut. When the program ends, time_limit reads what is left in
 * the pipe and closes it: a process the program left behind that still
 * holds the pipe cannot keep time_limit waiting.
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
 *   152 (128 + SIGXCPU) when it ran out of CPU time,
 *   128 + N when signal N killed it (a crash: 139 is a segmentation fault),
 *   125 when time_limit itself was used wrongly, or could not write --output FILE
 *       (a full disk: the program's output would be lost without a word),
 *   127 when the program could not be started. */
#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/time.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#define STATUS_TIMED_OUT 124
#define STATUS_OWN_FAILURE 125
#define STATUS_CANNOT_RUN 127
#define STATUS_SIGNAL_BASE 128
#define MAX_SECONDS 86400.0
#define POLL_MS 5 /* look at the child every 5 ms */
#define NS_PER_SECOND 1e9
#define OUTPUT_MAX_DEFAULT (1L << 20)
#define CHUNK 65536
#define DRAIN_READS 64 /* after the end: what is in the pipe, not what comes later */

/* Set by a SIGINT or SIGTERM sent to time_limit: the child's group is in
 * another process group, so the terminal's Ctrl-C does not reach it. */
static volatile sig_atomic_t interrupted;

/* --output: the read end of the child's pipe, the file, what is kept. */
static int pipe_fd = -1, output_fd = -1;
static long output_max = OUTPUT_MAX_DEFAULT, output_kept, output_dropped;
static int output_errno; /* the first write into FILE that failed (0: none) */

static void on_interrupt(int sig)
{
    interrupted = sig;
}

static int usage_error(const char *what)
{
    fprintf(stderr, "time_limit: error: %s\n", what);
    fprintf(stderr, "usage: time_limit [--cpu CPU_SECONDS] [--cpu-out FILE] [--output FILE "
                    "[--output-max BYTES]] SECONDS PROGRAM [ARG...]\n");
    return STATUS_OWN_FAILURE;
}

/* A number of seconds above 0 and at most a day, or -1. */
static double seconds_of(const char *text)
{
    char *end;
    errno = 0;
    double v = strtod(text, &end);
    if (errno != 0 || end == text || *end != '\0' || !(v > 0.0) || v > MAX_SECONDS)
        return -1;
    return v;
}

/* The CPU time of the children waited for so far, user and system. */
static double children_cpu_seconds(void)
{
    struct rusage ru;
    if (getrusage(RUSAGE_CHILDREN, &ru) != 0)
        return 0;
    return (double)(ru.ru_utime.tv_sec + ru.ru_stime.tv_sec) +
           (double)(ru.ru_utime.tv_usec + ru.ru_stime.tv_usec) / 1e6;
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

/* What the pipe holds now, into the file up to the cap; false at its end
 * (or when nothing is there). */
static bool read_output(void)
{
    char buf[CHUNK];
    ssize_t n = read(pipe_fd, buf, sizeof buf);
    if (n <= 0)
        return false;
    long keep = output_max - output_kept;
    keep = keep < n ? keep : (long)n;
    if (keep > 0) {
        ssize_t written = write(output_fd, buf, (size_t)keep);
        if (written == (ssize_t)keep)
            output_kept += keep;
        else if (!output_errno) /* a full disk, /dev/full: the output is lost, and said so */
            output_errno = written < 0 ? errno : ENOSPC;
    }
    output_dropped += (long)n - (keep > 0 ? keep : 0);
    return true;
}

/* Waits for the program, a poll of its pipe (or a pause) at a time. */
static void wait_a_moment(void)
{
    if (pipe_fd >= 0) {
        struct pollfd p = {pipe_fd, POLLIN, 0};
        if (poll(&p, 1, POLL_MS) > 0 && (p.revents & (POLLIN | POLLHUP)))
            for (int k = 0; k < DRAIN_READS && read_output(); k++)
                continue;
        return;
    }
    struct timespec pause = {0, POLL_MS * 1000000L};
    nanosleep(&pause, NULL);
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
        wait_a_moment();
    }
}

/* After the end: what the pipe holds, then the note, then the pipe closed. */
static bool finish_output(void)
{
    for (int k = 0; k < DRAIN_READS && read_output(); k++)
        continue;
    close(pipe_fd);
    bool ok = true;
    if (output_dropped > 0) {
        char note[160];
        int n = snprintf(note, sizeof note,
                         "\n[... %ld more bytes of output: cut at %ld bytes]\n", output_dropped,
                         output_max);
        ok = n > 0 && write(output_fd, note, (size_t)n) == n;
    }
    return close(output_fd) == 0 && ok && !output_errno;
}

int main(int argc, char **argv)
{
    double cpu = 0;
    const char *cpu_out = NULL, *output = NULL;
    int a = 1;
    while (a < argc && strncmp(argv[a], "--", 2) == 0) {
        if (a + 1 >= argc)
            return usage_error("an option wants a value");
        if (strcmp(argv[a], "--cpu") == 0) {
            if ((cpu = seconds_of(argv[a + 1])) < 0)
                return usage_error("--cpu wants a number of seconds, above 0 and at most 86400");
        } else if (strcmp(argv[a], "--cpu-out") == 0) {
            cpu_out = argv[a + 1];
        } else if (strcmp(argv[a], "--output") == 0) {
            output = argv[a + 1];
        } else if (strcmp(argv[a], "--output-max") == 0) {
            char *end;
            errno = 0;
            output_max = strtol(argv[a + 1], &end, 10);
            if (errno != 0 || end == argv[a + 1] || *end != '\0' || output_max < 1)
                return usage_error("--output-max wants a number of bytes, at least 1");
        } else {
            return usage_error("unknown option");
        }
        a += 2;
    }
    if (argc - a < 2)
        return usage_error("wants a time in seconds and a program to run");
    double limit = seconds_of(argv[a]);
    if (limit < 0)
        return usage_error("the time limit must be a number of seconds, above 0 and at most 86400");
    char **program = argv + a + 1;

    /* --cpu-out is opened before the program runs: a FILE that cannot be
     * written is said at once, with its reason, rather than after the run,
     * when the program's own status would be lost to it. */
    FILE *cpu_file = NULL;
    if (cpu_out) {
        cpu_file = fopen(cpu_out, "w");
        if (!cpu_file) {
            fprintf(stderr, "time_limit: error: cannot write %s: %s\n", cpu_out, strerror(errno));
            return STATUS_OWN_FAILURE;
        }
        fcntl(fileno(cpu_file), F_SETFD, FD_CLOEXEC);
    }

    int pipe_ends[2] = {-1, -1};
    if (output) {
        output_fd = open(output, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
        if (output_fd < 0 || pipe(pipe_ends) != 0) {
            fprintf(stderr, "time_limit: error: cannot set up the output %s: %s\n", output,
                    strerror(errno));
            return STATUS_OWN_FAILURE;
        }
        pipe_fd = pipe_ends[0];
        fcntl(pipe_fd, F_SETFD, FD_CLOEXEC);
        fcntl(pipe_fd, F_SETFL, fcntl(pipe_fd, F_GETFL) | O_NONBLOCK);
    }

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
        if (output && (dup2(pipe_ends[1], STDOUT_FILENO) < 0 ||
                       dup2(pipe_ends[1], STDERR_FILENO) < 0)) {
            _exit(STATUS_OWN_FAILURE);
        }
        if (output)
            close(pipe_ends[1]);
        if (cpu > 0) {
            /* SIGXCPU at the limit, SIGKILL a second later if it is ignored. */
            rlim_t soft = (rlim_t)(cpu + 0.999);
            struct rlimit rl = {soft, soft + 1};
            if (setrlimit(RLIMIT_CPU, &rl) != 0) {
                fprintf(stderr, "time_limit: error: cannot limit CPU time: %s\n", strerror(errno));
                _exit(STATUS_OWN_FAILURE);
            }
        }
        execvp(program[0], program);
        fprintf(stderr, "time_limit: error: cannot run %s: %s\n", program[0], strerror(errno));
        _exit(STATUS_CANNOT_RUN);
    }
    if (output)
        close(pipe_ends[1]);
    setpgid(pid, pid); /* also here: whichever runs first, the group exists */
    int status = wait_for(pid, limit);
    if (output && !finish_output()) {
        fprintf(stderr, "time_limit: error: cannot write %s%s%s\n", output,
                output_errno ? ": " : "", output_errno ? strerror(output_errno) : "");
        return STATUS_OWN_FAILURE;
    }
    if (cpu_file) {
        errno = 0;
        bool written = fprintf(cpu_file, "%.3f\n", children_cpu_seconds()) >= 0;
        written = fclose(cpu_file) == 0 && written;
        if (!written) {
            fprintf(stderr, "time_limit: error: cannot write %s: %s\n", cpu_out,
                    strerror(errno ? errno : EIO));
            return STATUS_OWN_FAILURE;
        }
    }
    return status;
}
