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
#include "file.h"

#include <errno.h>
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

/* "dir/name" -> "dir/.name.XXXXXX"; "name" -> ".name.XXXXXX". */
static char *temp_name_for(const char *path)
{
    const char *slash = strrchr(path, '/');
    size_t dir_len = slash ? (size_t)(slash - path) + 1 : 0;
    const char *base = path + dir_len;
    size_t n = dir_len + 1 + strlen(base) + sizeof TEMP_SUFFIX;
    char *tmp = malloc(n);
    if (tmp) {
        memcpy(tmp, path, dir_len);
        tmp[dir_len] = '.';
        strcpy(tmp + dir_len + 1, base);
        strcat(tmp, TEMP_SUFFIX);
    }
    return tmp;
}

static void release(AtomicFile *f)
{
    free(f->path);
    free(f->tmp_path);
    f->fp = NULL;
    f->path = NULL;
    f->tmp_path = NULL;
}

/* Devices and pipes cannot be replaced by a rename: write to them directly. */
static bool open_direct(AtomicFile *f, const char *path, Error *err)
{
    f->fp = fopen(path, "wb");
    if (!f->fp) {
        int e = errno;
        release(f);
        return error_set(err, "cannot write %s: %s", path, strerror(e));
    }
    return true;
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

    f->path = rename_target(path);
    f->tmp_path = f->path ? temp_name_for(f->path) : NULL;
    if (!f->tmp_path) {
        release(f);
        return error_set(err, "cannot write %s: out of memory", path);
    }
    int fd = mkstemp(f->tmp_path);
    if (fd < 0) {
        int e = errno;
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
        int e = errno;
        close(fd);
        unlink(f->tmp_path);
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
    errno = 0;
    int closed = fclose(f->fp);
    f->fp = NULL;
    if (closed != 0)
        note_failure(f, errno);
    if (!f->failed && f->tmp_path && rename(f->tmp_path, f->path) != 0)
        note_failure(f, errno);

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
    if (f->fp)
        fclose(f->fp);
    if (f->tmp_path)
        unlink(f->tmp_path);
    release(f);
}

/* Grows the buffer geometrically so that reading a file of n bytes costs O(n). */
#define READ_CHUNK 65536

bool read_file(const char *path, size_t max_bytes, char **data, size_t *len, Error *err)
{
    *data = NULL;
    *len = 0;
    FILE *fp = fopen(path, "rb");
    if (!fp)
        return error_set(err, "cannot read %s: %s", path, strerror(errno));
    struct stat st;
    if (fstat(fileno(fp), &st) == 0 && S_ISDIR(st.st_mode)) {
        fclose(fp);
        return error_set(err, "cannot read %s: %s", path, strerror(EISDIR));
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
                return error_set(err, "cannot read %s: out of memory", path);
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
        return error_set(err, "cannot read %s: %s", path, strerror(e));
    }
    fclose(fp);
    buf[size] = '\0';
    *data = buf;
    *len = size;
    return true;
}

bool same_file(const char *a, const char *b)
{
    struct stat sa, sb;
    return stat(a, &sa) == 0 && stat(b, &sb) == 0 &&
           sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
}

static bool is_directory(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 && S_ISDIR(st.st_mode);
}

/* Creates one directory; fine if it already exists as a directory. */
static bool make_one_dir(const char *path, Error *err)
{
    if (mkdir(path, NEW_DIR_MODE) == 0)
        return true;
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
