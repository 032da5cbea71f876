/* file.c: see file.h.
 *
 * The atomic write, step by step:
 *   atomic_open    create ".<name>.XXXXXX" beside the target (same directory,
 *                  so same file system, so rename(2) can replace it atomically)
 *   atomic_write   append bytes, remembering the first failure
 *   atomic_commit  flush and close (both checked: a full disk often shows only
 *                  there), then rename the temporary file over the target
 * Any failure removes the temporary file; the target is touched only by the
 * final rename, so it keeps its old bytes until the new ones are complete. */
/* realpath(3) is an X/Open function. */
#define _XOPEN_SOURCE 700

#include "file.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

/* The "XXXXXX" that mkstemp replaces by a unique suffix. */
static const char TEMP_SUFFIX[] = ".XXXXXX";

/* A new file gets the permissions fopen(path, "w") would give it, rather than
 * mkstemp's owner-only 0600. */
#define NEW_FILE_MODE 0666
#define NEW_DIR_MODE 0777

static char *copy_string(const char *s)
{
    size_t n = strlen(s) + 1;
    char *c = malloc(n);
    if (c)
        memcpy(c, s, n);
    return c;
}

#ifndef NAME_MAX
#define NAME_MAX 255
#endif

/* "dir/name" -> "dir/.name.XXXXXX"; "name" -> ".name.XXXXXX". A name so long
 * that the temporary one would pass NAME_MAX is shortened in the temporary
 * name only: any legal name can be written. */
static char *temp_name_for(const char *path)
{
    const char *slash = strrchr(path, '/');
    size_t dir_len = slash ? (size_t)(slash - path) + 1 : 0;
    const char *base = path + dir_len;
    size_t base_len = strlen(base), room = NAME_MAX - 1 - (sizeof TEMP_SUFFIX - 1);
    if (base_len > room)
        base_len = room;
    size_t n = dir_len + 1 + base_len + sizeof TEMP_SUFFIX;
    char *tmp = malloc(n);
    if (tmp) {
        memcpy(tmp, path, dir_len);
        tmp[dir_len] = '.';
        memcpy(tmp + dir_len + 1, base, base_len);
        memcpy(tmp + dir_len + 1 + base_len, TEMP_SUFFIX, sizeof TEMP_SUFFIX);
    }
    return tmp;
}

/* ---- the temporary files that exist, for the signal handler ----
 *
 * Each slot holds a pointer to a path that is complete before the slot is
 * filled; slots change only while the signals are blocked, so the handler
 * sees either no path or a whole one. It calls only unlink, rmdir and _exit,
 * which are async-signal-safe. */
#define TEMP_SLOTS 8192 /* --steps: two files per face, up to 2000 faces, and the rest */
#define DIR_SLOTS 64
/* Every signal whose default action ends the program without a core dump, and
 * SIGQUIT and SIGABRT (an assertion) too: a run ended by any of them leaves
 * no temporary file. SIGXFSZ (a file size limit, ulimit -f) is ignored
 * instead, so that the write fails and the run says so with status 1. */
static const int CLEANUP_SIGNALS[] = {SIGINT,  SIGTERM,   SIGHUP,  SIGPIPE, SIGQUIT,
                                      SIGALRM, SIGUSR1,   SIGUSR2, SIGABRT, SIGVTALRM,
                                      SIGPROF, SIGXCPU};
#define CLEANUP_SIGNAL_COUNT ((int)(sizeof CLEANUP_SIGNALS / sizeof CLEANUP_SIGNALS[0]))
/* Their names, in the same order, for the line the handler prints. */
static const char *const CLEANUP_SIGNAL_NAMES[CLEANUP_SIGNAL_COUNT] = {
    "SIGINT",  "SIGTERM", "SIGHUP",  "SIGPIPE", "SIGQUIT",   "SIGALRM",
    "SIGUSR1", "SIGUSR2", "SIGABRT", "SIGVTALRM", "SIGPROF", "SIGXCPU"};

/* "<program>: error: stopped by ", set by signals_begin before any handler
 * can run; empty (a tool that did not call it): the handler prints nothing. */
static char stop_prefix[160];

static char *volatile temp_slot[TEMP_SLOTS];
static volatile int temp_slots_used; /* slots at and past this index are empty */
static char *volatile dir_slot[DIR_SLOTS]; /* directories made for the pending outputs */
static volatile int dir_slots_used;

/* text appended to line[0 .. *used), as far as size allows; no library
 * call, so that the signal handler may use it. */
static void append_text(char *line, size_t *used, size_t size, const char *text)
{
    while (*text && *used < size)
        line[(*used)++] = *text++;
}

/* One line on stderr, "<program>: error: stopped by SIGTERM", with write(2)
 * alone. */
static void say_stopped(int sig)
{
    if (stop_prefix[0] == '\0')
        return;
    const char *name = "a signal";
    for (int i = 0; i < CLEANUP_SIGNAL_COUNT; i++)
        if (CLEANUP_SIGNALS[i] == sig)
            name = CLEANUP_SIGNAL_NAMES[i];
    char line[sizeof stop_prefix + 16];
    size_t used = 0;
    append_text(line, &used, sizeof line - 1, stop_prefix);
    append_text(line, &used, sizeof line - 1, name);
    line[used++] = '\n';
    (void)!write(STDERR_FILENO, line, used);
}

static void remove_temporaries_and_exit(int sig)
{
    for (int i = 0; i < temp_slots_used; i++)
        if (temp_slot[i])
            unlink(temp_slot[i]);
    for (int i = dir_slots_used - 1; i >= 0; i--)
        if (dir_slot[i])
            rmdir(dir_slot[i]);
    say_stopped(sig);
    _exit(128 + sig);
}

/* Each time a temporary file is made: a signal left at its default action
 * gets the handler; one that is ignored (nohup, a shell's background job)
 * stays ignored, and one with a handler of the program's keeps it. */
static void install_handlers(void)
{
    struct sigaction fsize;
    if (sigaction(SIGXFSZ, NULL, &fsize) == 0 && fsize.sa_handler == SIG_DFL)
        signal(SIGXFSZ, SIG_IGN);
    for (int i = 0; i < CLEANUP_SIGNAL_COUNT; i++) {
        struct sigaction old, sa;
        if (sigaction(CLEANUP_SIGNALS[i], NULL, &old) != 0 || old.sa_handler != SIG_DFL)
            continue;
        memset(&sa, 0, sizeof sa);
        sa.sa_handler = remove_temporaries_and_exit;
        sigfillset(&sa.sa_mask);
        sigaction(CLEANUP_SIGNALS[i], &sa, NULL);
    }
}

static void block_signals(sigset_t *old)
{
    sigset_t set;
    sigemptyset(&set);
    for (int i = 0; i < CLEANUP_SIGNAL_COUNT; i++)
        sigaddset(&set, CLEANUP_SIGNALS[i]);
    sigprocmask(SIG_BLOCK, &set, old);
}

static void restore_signals(const sigset_t *old)
{
    sigprocmask(SIG_SETMASK, old, NULL);
}

void signals_begin(const char *program)
{
    struct sigaction broken_pipe;
    if (sigaction(SIGPIPE, NULL, &broken_pipe) == 0 && broken_pipe.sa_handler == SIG_DFL)
        signal(SIGPIPE, SIG_IGN);
    sigset_t old;
    block_signals(&old);
    size_t used = 0;
    append_text(stop_prefix, &used, sizeof stop_prefix - 1, program);
    append_text(stop_prefix, &used, sizeof stop_prefix - 1, ": error: stopped by ");
    stop_prefix[used] = '\0';
    restore_signals(&old);
    install_handlers();
}

/* Call with the signals blocked. False when every slot is taken. */
static bool list_temporary(char *path)
{
    for (int i = 0; i < TEMP_SLOTS; i++)
        if (!temp_slot[i]) {
            temp_slot[i] = path;
            if (i >= temp_slots_used)
                temp_slots_used = i + 1;
            return true;
        }
    return false;
}

/* Call with the signals blocked. */
static void unlist_temporary(const char *path)
{
    for (int i = 0; i < temp_slots_used; i++)
        if (temp_slot[i] == path) {
            temp_slot[i] = NULL;
            break;
        }
    while (temp_slots_used > 0 && !temp_slot[temp_slots_used - 1])
        temp_slots_used--;
}

/* ---- the pending outputs of a run (output_set_begin) ---- */

typedef struct {
    char *tmp_path, *path;
} Pending;

static bool staging;
static Pending *pending;
static int pending_count, pending_cap;

void output_set_begin(void)
{
    staging = true;
}

bool output_set_open(void)
{
    return staging;
}

static bool add_pending(char *tmp_path, char *path)
{
    if (pending_count == pending_cap) {
        int cap = pending_cap ? pending_cap * 2 : 16;
        Pending *grown = realloc(pending, (size_t)cap * sizeof *grown);
        if (!grown)
            return false;
        pending = grown;
        pending_cap = cap;
    }
    pending[pending_count].tmp_path = tmp_path;
    pending[pending_count].path = path;
    pending_count++;
    return true;
}

static void forget_dirs(void)
{
    sigset_t old;
    block_signals(&old);
    int n = dir_slots_used;
    dir_slots_used = 0;
    restore_signals(&old);
    for (int i = 0; i < n; i++) {
        free(dir_slot[i]);
        dir_slot[i] = NULL;
    }
}

static void end_set(void)
{
    free(pending);
    pending = NULL;
    pending_count = pending_cap = 0;
    forget_dirs();
    staging = false;
}

bool output_set_publish(Error *err)
{
    bool ok = true;
    for (int i = 0; i < pending_count; i++) {
        Pending *p = &pending[i];
        sigset_t old;
        block_signals(&old);
        if (ok && rename(p->tmp_path, p->path) != 0) {
            ok = error_set(err, "cannot write %s: %s", p->path, strerror(errno));
        }
        if (!ok)
            unlink(p->tmp_path);
        unlist_temporary(p->tmp_path);
        restore_signals(&old);
        free(p->tmp_path);
        free(p->path);
    }
    end_set();
    return ok;
}

void output_set_abort(void)
{
    for (int i = 0; i < pending_count; i++) {
        sigset_t old;
        block_signals(&old);
        unlink(pending[i].tmp_path);
        unlist_temporary(pending[i].tmp_path);
        restore_signals(&old);
        free(pending[i].tmp_path);
        free(pending[i].path);
    }
    /* The directories made for these outputs, deepest first: rmdir removes
     * only those that are still empty. */
    for (int i = dir_slots_used - 1; i >= 0; i--)
        rmdir(dir_slot[i]);
    end_set();
}

/* make_dirs made this directory for a pending output. */
static void note_made_dir(const char *path)
{
    if (!staging || dir_slots_used == DIR_SLOTS)
        return;
    char *copy = copy_string(path);
    if (!copy)
        return;
    sigset_t old;
    block_signals(&old);
    dir_slot[dir_slots_used] = copy;
    dir_slots_used = dir_slots_used + 1;
    restore_signals(&old);
}

static void release(AtomicFile *f)
{
    free(f->path);
    free(f->tmp_path);
    f->fp = NULL;
    f->path = NULL;
    f->tmp_path = NULL;
}

/* A pipe that output_check opened stays open until its output is written:
 * closed in between, its reader would see the end of its input and go. */
#define HELD_PIPES 8
typedef struct { dev_t dev; ino_t ino; int fd; } HeldPipe;
static HeldPipe held_pipe[HELD_PIPES];
static int held_pipes;

static void hold_pipe(const struct stat *st, int fd)
{
    if (held_pipes < HELD_PIPES)
        held_pipe[held_pipes++] = (HeldPipe){st->st_dev, st->st_ino, fd};
    else
        close(fd);
}

/* The descriptor output_check left open for the pipe at path, or -1. */
static int held_pipe_of(const char *path)
{
    struct stat st;
    if (stat(path, &st) != 0 || !S_ISFIFO(st.st_mode))
        return -1;
    for (int i = 0; i < held_pipes; i++)
        if (held_pipe[i].dev == st.st_dev && held_pipe[i].ino == st.st_ino) {
            int fd = held_pipe[i].fd;
            held_pipe[i] = held_pipe[--held_pipes];
            return fd;
        }
    return -1;
}

/* Devices and pipes cannot be replaced by a rename: write to them directly.
 * A pipe is opened without waiting: one that nobody reads is refused (ENXIO)
 * rather than waited on for ever. */
static bool open_direct(AtomicFile *f, const char *path, Error *err)
{
    int fd = held_pipe_of(path);
    if (fd < 0)
        fd = open(path, O_WRONLY | O_NONBLOCK);
    if (fd < 0) {
        int e = errno;
        release(f);
        if (e == ENXIO)
            return error_set(err, "cannot write %s: a pipe that nobody reads", path);
        return error_set(err, "cannot write %s: %s", path, strerror(e));
    }
    int flags = fcntl(fd, F_GETFL);
    if (flags >= 0)
        fcntl(fd, F_SETFL, flags & ~O_NONBLOCK);
    f->fp = fdopen(fd, "wb");
    if (!f->fp) {
        int e = errno;
        close(fd);
        release(f);
        return error_set(err, "cannot write %s: %s", path, strerror(e));
    }
    return true;
}

bool is_stdout_name(const char *path)
{
    return path && strcmp(path, "-") == 0;
}

/* A file no one may write: refused, as a shell's > refuses it, rather than
 * replaced (a rename needs only the directory's permission). Root may write
 * anything, so a file without any write bit counts as read-only too. */
static bool read_only(const char *path, const struct stat *st)
{
    return access(path, W_OK) != 0 || (st->st_mode & (S_IWUSR | S_IWGRP | S_IWOTH)) == 0;
}

#define LINK_HOPS_MAX 40 /* as Linux: a longer chain is surely a loop */

/* "dir/link" pointing to "name" -> "dir/name"; an absolute target as it is. */
static char *follow_link_once(const char *link_path)
{
    char target[PATH_TEXT_MAX];
    ssize_t n = readlink(link_path, target, sizeof target - 1);
    if (n < 0 || (size_t)n == sizeof target - 1)
        return NULL;
    target[n] = '\0';
    const char *slash = strrchr(link_path, '/');
    size_t dir_len = target[0] == '/' || !slash ? 0 : (size_t)(slash - link_path) + 1;
    char *next = malloc(dir_len + (size_t)n + 1);
    if (next) {
        memcpy(next, link_path, dir_len);
        memcpy(next + dir_len, target, (size_t)n + 1);
    }
    return next;
}

/* The name to rename over: a symbolic link to a file is written through (the
 * link stays a link), e.g. /dev/stdout when the shell sent it to a file. */
static char *rename_target(const char *path)
{
    char *name = copy_string(path);
    for (int hops = 0; name && hops < LINK_HOPS_MAX; hops++) {
        struct stat st;
        if (lstat(name, &st) != 0 || !S_ISLNK(st.st_mode))
            break;
        char *next = follow_link_once(name);
        if (!next)
            break;
        free(name);
        name = next;
    }
    return name;
}

bool atomic_open(AtomicFile *f, const char *path, Error *err)
{
    memset(f, 0, sizeof *f);
    if (is_stdout_name(path)) {
        f->path = copy_string(path);
        if (!f->path)
            return error_set(err, "cannot write standard output: out of memory");
        f->fp = stdout;
        f->to_stdout = true;
        return true;
    }
    const char *base = strrchr(path, '/');
    base = base ? base + 1 : path;
    if (*base == '\0')
        return error_set(err, "cannot write %s: no file name", path[0] ? path : "\"\"");

    struct stat st;
    bool exists = stat(path, &st) == 0;
    if (exists && S_ISDIR(st.st_mode))
        return error_set(err, "cannot write %s: %s", path, strerror(EISDIR));
    if (exists && !S_ISREG(st.st_mode)) {
        f->path = copy_string(path);
        if (!f->path)
            return error_set(err, "cannot write %s: out of memory", path);
        return open_direct(f, path, err);
    }
    if (exists && read_only(path, &st))
        return error_set(err, "cannot write %s: %s", path, strerror(EACCES));

    f->path = rename_target(path);
    f->tmp_path = f->path ? temp_name_for(f->path) : NULL;
    if (!f->tmp_path) {
        release(f);
        return error_set(err, "cannot write %s: out of memory", path);
    }
    install_handlers();
    sigset_t old;
    block_signals(&old);
    int fd = mkstemp(f->tmp_path);
    int e = errno;
    if (fd >= 0 && !list_temporary(f->tmp_path)) {
        close(fd);
        unlink(f->tmp_path);
        fd = -1;
        e = EMFILE;
    }
    restore_signals(&old);
    if (fd < 0) {
        release(f);
        return error_set(err, "cannot write %s: %s", path, strerror(e));
    }
    /* An existing file keeps its permissions; a new one gets 0666 less the
     * umask (umask can only be read by setting it). */
    mode_t mask = umask(0);
    umask(mask);
    fchmod(fd, exists ? st.st_mode & 07777 : NEW_FILE_MODE & ~mask);
    f->fp = fdopen(fd, "wb");
    if (!f->fp) {
        e = errno;
        close(fd);
        block_signals(&old);
        unlink(f->tmp_path);
        unlist_temporary(f->tmp_path);
        restore_signals(&old);
        release(f);
        return error_set(err, "cannot write %s: %s", path, strerror(e));
    }
    return true;
}

static void note_failure(AtomicFile *f, int e)
{
    if (!f->failed)
        f->error_number = e;
    f->failed = true;
}

void atomic_write(AtomicFile *f, const void *bytes, size_t n)
{
    if (!f->fp || f->failed || n == 0)
        return;
    errno = 0;
    if (fwrite(bytes, 1, n, f->fp) != n)
        note_failure(f, errno);
}

bool atomic_commit(AtomicFile *f, Error *err)
{
    if (!f->fp) {
        const char *path = f->path ? f->path : "(file not open)";
        error_set(err, "cannot write %s: the file was not opened", path);
        atomic_abort(f);
        return false;
    }
    /* No fsync: the point is "never a half-written file", not surviving a
     * power cut, and fsync would make every test run slower. */
    errno = 0;
    if (fflush(f->fp) != 0 || ferror(f->fp))
        note_failure(f, errno);
    if (f->to_stdout) {
        f->fp = NULL;
        if (f->failed) {
            int e = f->error_number;
            error_set(err, "cannot write standard output: %s", e ? strerror(e) : "write failed");
        }
        release(f);
        return !f->failed;
    }
    errno = 0;
    int closed = fclose(f->fp);
    f->fp = NULL;
    if (closed != 0)
        note_failure(f, errno);
    if (!f->failed && f->tmp_path && staging) {
        /* output_set_publish renames it, with the others. */
        if (add_pending(f->tmp_path, f->path)) {
            f->tmp_path = NULL;
            f->path = NULL;
            return true;
        }
        note_failure(f, ENOMEM);
    }
    if (!f->failed && f->tmp_path) {
        sigset_t old;
        block_signals(&old);
        if (rename(f->tmp_path, f->path) != 0)
            note_failure(f, errno);
        else
            unlist_temporary(f->tmp_path);
        restore_signals(&old);
    }

    if (f->failed) {
        int e = f->error_number;
        error_set(err, "cannot write %s: %s", f->path,
                  e ? strerror(e) : "write failed");
        atomic_abort(f);
        return false;
    }
    release(f);
    return true;
}

void atomic_abort(AtomicFile *f)
{
    if (f->fp && !f->to_stdout)
        fclose(f->fp);
    if (f->tmp_path) {
        sigset_t old;
        block_signals(&old);
        unlink(f->tmp_path);
        unlist_temporary(f->tmp_path);
        restore_signals(&old);
    }
    release(f);
}

/* Grows the buffer geometrically so that reading a file of n bytes costs O(n). */
#define READ_CHUNK 65536

/* What a file that is not a regular file is, for a message. */
static const char *file_kind(mode_t mode)
{
    if (S_ISDIR(mode))
        return strerror(EISDIR);
    if (S_ISFIFO(mode))
        return "not a regular file (a pipe)";
    if (S_ISSOCK(mode))
        return "not a regular file (a socket)";
    if (S_ISCHR(mode) || S_ISBLK(mode))
        return "not a regular file (a device)";
    return "not a regular file";
}

/* "cannot read PATH: reason" for errno e, and errno e again for the caller. */
static bool read_failed(Error *err, const char *path, int e)
{
    error_set(err, "cannot read %s: %s", path, strerror(e));
    errno = e;
    return false;
}

bool read_file(const char *path, size_t max_bytes, char **data, size_t *len, Error *err)
{
    *data = NULL;
    *len = 0;
    errno = 0; /* ENOMEM below: this call ran out of memory, not an earlier one */
    /* O_NONBLOCK: opening a pipe for reading would wait for a writer. */
    int fd = open(path, O_RDONLY | O_NONBLOCK);
    if (fd < 0)
        return read_failed(err, path, errno);
    struct stat st;
    if (fstat(fd, &st) != 0) {
        int e = errno;
        close(fd);
        return read_failed(err, path, e);
    }
    if (!S_ISREG(st.st_mode)) {
        close(fd);
        return error_set(err, "cannot read %s: %s", path, file_kind(st.st_mode));
    }
    int flags = fcntl(fd, F_GETFL);
    if (flags >= 0)
        fcntl(fd, F_SETFL, flags & ~O_NONBLOCK);
    FILE *fp = fdopen(fd, "rb");
    if (!fp) {
        int e = errno;
        close(fd);
        return read_failed(err, path, e);
    }

    char *buf = NULL;
    size_t size = 0, cap = 0;
    for (;;) {
        if (cap - size < READ_CHUNK) {
            size_t new_cap = cap ? cap * 2 : READ_CHUNK;
            char *grown = realloc(buf, new_cap + 1); /* + 1 for the NUL */
            if (!grown) {
                free(buf);
                fclose(fp);
                error_set(err, "cannot read %s: out of memory", path);
                errno = ENOMEM; /* the caller may tell this from a file it cannot read */
                return false;
            }
            buf = grown;
            cap = new_cap;
        }
        /* Never read more than one byte past the limit: enough to refuse. */
        size_t want = cap - size;
        size_t room = max_bytes - size; /* size <= max_bytes here */
        if (room < SIZE_MAX && want > room + 1)
            want = room + 1;
        size_t got = fread(buf + size, 1, want, fp);
        size += got;
        if (size > max_bytes) {
            free(buf);
            fclose(fp);
            return error_set(err, "cannot read %s: it is larger than %zu bytes",
                             path, max_bytes);
        }
        if (got == 0)
            break;
    }
    if (ferror(fp)) {
        int e = errno;
        free(buf);
        fclose(fp);
        return read_failed(err, path, e);
    }
    fclose(fp);
    buf[size] = '\0';
    *data = buf;
    *len = size;
    return true;
}

/* ---- identity ---- */

/* Appends the component [c, c + n) to the absolute path buf (length *len),
 * taking "." and ".." by name. False when it does not fit. */
static bool push_component(char *buf, size_t *len, const char *c, size_t n)
{
    if (n == 0 || (n == 1 && c[0] == '.'))
        return true;
    if (n == 2 && c[0] == '.' && c[1] == '.') {
        while (*len > 1 && buf[*len - 1] != '/')
            (*len)--;
        if (*len > 1)
            (*len)--; /* the slash, unless it is the root */
        buf[*len] = '\0';
        return true;
    }
    if (*len + 1 + n + 1 > PATH_TEXT_MAX)
        return false;
    if (*len > 1)
        buf[(*len)++] = '/';
    memcpy(buf + *len, c, n);
    *len += n;
    buf[*len] = '\0';
    return true;
}

/* The absolute name of dir with every part that exists resolved by realpath
 * and the rest (directories still to be made) taken apart by name. */
static bool resolve_dir(const char *dir, char out[PATH_TEXT_MAX])
{
    char *real = realpath(dir, NULL);
    if (real) {
        bool fits = strlen(real) < PATH_TEXT_MAX;
        if (fits)
            strcpy(out, real);
        free(real);
        return fits;
    }
    /* The longest prefix that exists: cut the last component, resolve the
     * rest (recursively), then add the components back by name. */
    const char *end = dir + strlen(dir);
    while (end > dir && end[-1] == '/')
        end--;
    const char *slash = end;
    while (slash > dir && slash[-1] != '/')
        slash--;
    if (slash == dir) { /* a single relative component */
        if (!getcwd(out, PATH_TEXT_MAX))
            return false;
    } else {
        size_t n = (size_t)(slash - dir);
        char *parent = malloc(n + 1);
        if (!parent)
            return false;
        memcpy(parent, dir, n);
        parent[n] = '\0';
        bool ok = resolve_dir(parent, out);
        free(parent);
        if (!ok)
            return false;
    }
    size_t len = strlen(out);
    return push_component(out, &len, slash, (size_t)(end - slash));
}

bool file_id(const char *path, FileId *id)
{
    memset(id, 0, sizeof *id);
    char *name = rename_target(path); /* through a symbolic link, dangling or not */
    if (!name)
        return false;
    const char *slash = strrchr(name, '/');
    const char *base = slash ? slash + 1 : name;
    char dir[PATH_TEXT_MAX];
    bool ok;
    if (!slash)
        ok = resolve_dir(".", dir);
    else if (slash == name)
        ok = resolve_dir("/", dir);
    else {
        size_t n = (size_t)(slash - name);
        char *d = malloc(n + 1);
        ok = d != NULL;
        if (ok) {
            memcpy(d, name, n);
            d[n] = '\0';
            ok = resolve_dir(d, dir);
            free(d);
        }
    }
    size_t len = ok ? strlen(dir) : 0;
    ok = ok && push_component(dir, &len, base, strlen(base));
    if (ok)
        id->resolved = copy_string(dir);
    struct stat st;
    if (stat(name, &st) == 0) {
        id->exists = true;
        id->dev = (unsigned long long)st.st_dev;
        id->ino = (unsigned long long)st.st_ino;
    }
    free(name);
    return id->resolved != NULL;
}

void file_id_free(FileId *id)
{
    free(id->resolved);
    id->resolved = NULL;
}

bool file_id_same(const FileId *a, const FileId *b)
{
    if (a->exists && b->exists && a->dev == b->dev && a->ino == b->ino)
        return true;
    return a->resolved && b->resolved && strcmp(a->resolved, b->resolved) == 0;
}

bool same_file(const char *a, const char *b)
{
    if (strcmp(a, b) == 0)
        return true;
    FileId ia = {0}, ib = {0};
    bool same = file_id(a, &ia) && file_id(b, &ib) && file_id_same(&ia, &ib);
    file_id_free(&ia);
    file_id_free(&ib);
    return same;
}

/* "step_" digits (four or more) then ".png" or "_depth.png". */
static bool step_picture_name(const char *base)
{
    if (strncmp(base, "step_", 5) != 0)
        return false;
    const char *p = base + 5;
    int digits = 0;
    while (*p >= '0' && *p <= '9')
        p++, digits++;
    return digits >= 4 && (strcmp(p, ".png") == 0 || strcmp(p, "_depth.png") == 0);
}

bool is_step_picture(const char *path, const char *dir)
{
    FileId file = {0}, d = {0};
    bool in = false;
    if (file_id(path, &file) && file_id(dir, &d)) {
        const char *slash = strrchr(file.resolved, '/');
        size_t n = (size_t)(slash - file.resolved);
        in = step_picture_name(slash + 1) &&
             (n == 0 ? strcmp(d.resolved, "/") == 0
                     : strlen(d.resolved) == n && strncmp(d.resolved, file.resolved, n) == 0);
    }
    file_id_free(&file);
    file_id_free(&d);
    return in;
}

/* ---- outputs checked before drawing ---- */

/* The nearest ancestor of path that exists must be a writable directory: then
 * make_dirs and mkstemp can do their work. dir_of_output names what path is
 * for the message: "cannot create directory" or "cannot write". */
static bool ancestor_writable(const char *path, const char *output, Error *err)
{
    char *p = copy_string(path);
    if (!p)
        return error_set(err, "cannot write %s: out of memory", output);
    bool ok = true;
    for (;;) {
        size_t n = strlen(p);
        while (n > 1 && p[n - 1] == '/')
            p[--n] = '\0';
        struct stat st;
        if (stat(p, &st) == 0) {
            if (!S_ISDIR(st.st_mode))
                ok = error_set(err, "cannot create directory %s: a file of that name exists", p);
            else if (access(p, W_OK | X_OK) != 0)
                ok = error_set(err, "cannot write %s: %s", output, strerror(errno));
            break;
        }
        if (errno != ENOENT && errno != ENOTDIR) {
            ok = error_set(err, "cannot write %s: %s", output, strerror(errno));
            break;
        }
        char *slash = strrchr(p, '/');
        if (!slash) {
            strcpy(p, ".");
        } else if (slash == p) {
            p[1] = '\0';
        } else {
            *slash = '\0';
        }
    }
    free(p);
    return ok;
}

/* The directory part of path ("." when there is none). */
static char *dir_part(const char *path)
{
    const char *slash = strrchr(path, '/');
    if (!slash)
        return copy_string(".");
    size_t n = slash == path ? 1 : (size_t)(slash - path);
    char *d = malloc(n + 1);
    if (d) {
        memcpy(d, path, n);
        d[n] = '\0';
    }
    return d;
}

bool output_check(const char *path, Error *err)
{
    if (is_stdout_name(path))
        return true;
    const char *base = strrchr(path, '/');
    base = base ? base + 1 : path;
    if (*base == '\0')
        return error_set(err, "cannot write %s: no file name (it ends in '/')",
                         path[0] ? path : "\"\"");
    struct stat st;
    if (stat(path, &st) == 0) {
        if (S_ISDIR(st.st_mode))
            return error_set(err, "cannot write %s: %s", path, strerror(EISDIR));
        if (S_ISREG(st.st_mode) && read_only(path, &st))
            return error_set(err, "cannot write %s: %s", path, strerror(EACCES));
        if (S_ISFIFO(st.st_mode)) {
            /* Nobody reads it now: the run would wait for ever. */
            int fd = open(path, O_WRONLY | O_NONBLOCK);
            if (fd < 0)
                return error_set(err, "cannot write %s: %s", path,
                                 errno == ENXIO ? "a pipe that nobody reads" : strerror(errno));
            hold_pipe(&st, fd); /* open until written: its reader waits for the picture */
            return true;
        }
        if (!S_ISREG(st.st_mode))
            return true; /* a device: written directly */
    } else if (errno == ENAMETOOLONG || errno == ELOOP || errno == EACCES) {
        return error_set(err, "cannot write %s: %s", path, strerror(errno));
    }
    char *name = rename_target(path);
    char *dir = name ? dir_part(name) : NULL;
    bool ok = dir ? ancestor_writable(dir, path, err)
                  : error_set(err, "cannot write %s: out of memory", path);
    free(dir);
    free(name);
    return ok;
}

bool output_dir_check(const char *dir, Error *err)
{
    struct stat st;
    if (stat(dir, &st) == 0 && !S_ISDIR(st.st_mode))
        return error_set(err, "cannot create directory %s: a file of that name exists", dir);
    return ancestor_writable(dir, dir, err);
}

int stdout_to_stderr_begin(void)
{
    fflush(stdout);
    int saved = dup(STDOUT_FILENO);
    if (saved >= 0 && dup2(STDERR_FILENO, STDOUT_FILENO) < 0) {
        close(saved);
        saved = -1;
    }
    return saved;
}

void stdout_to_stderr_end(int saved)
{
    fflush(stdout);
    if (saved < 0)
        return;
    dup2(saved, STDOUT_FILENO);
    close(saved);
}

bool stdout_flush(Error *err)
{
    errno = 0;
    if (fflush(stdout) != 0 || ferror(stdout)) {
        int e = errno;
        return error_set(err, "cannot write standard output: %s",
                         e ? strerror(e) : "write failed");
    }
    return true;
}

static bool is_directory(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 && S_ISDIR(st.st_mode);
}

/* Creates one directory; fine if it already exists as a directory. */
static bool make_one_dir(const char *path, Error *err)
{
    if (mkdir(path, NEW_DIR_MODE) == 0) {
        note_made_dir(path);
        return true;
    }
    int e = errno;
    if (e == EEXIST && is_directory(path))
        return true;
    if (e == EEXIST)
        return error_set(err, "cannot create directory %s: a file of that name exists", path);
    return error_set(err, "cannot create directory %s: %s", path, strerror(e));
}

bool make_dirs(const char *path, Error *err)
{
    if (path[0] == '\0')
        return error_set(err, "cannot create a directory with an empty name");
    char *p = copy_string(path);
    if (!p)
        return error_set(err, "cannot create directory %s: out of memory", path);
    /* Each '/' after a name ends a parent: create it, then put the '/' back. */
    bool ok = true;
    for (char *s = p + 1; ok && *s; s++) {
        if (*s == '/' && s[-1] != '/') {
            *s = '\0';
            ok = make_one_dir(p, err);
            *s = '/';
        }
    }
    if (ok)
        ok = make_one_dir(p, err);
    free(p);
    return ok;
}
