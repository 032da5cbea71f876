/* file.h: writing a file all at once, or not at all.
 *
 * docs/conventions.md: a failed run never leaves a truncated file behind, and an
 * existing file at that path keeps its bytes. So every output goes through an
 * AtomicFile: a temporary file in the same directory (so that rename(2) is
 * atomic), renamed over the target only after every byte was written and
 * flushed. atomic_abort removes the temporary file.
 *
 * A target that exists and is neither a regular file nor a directory (a device
 * such as /dev/null or /dev/stdout, a pipe) is written directly: renaming over
 * it would replace the device itself. A directory is refused. */
#ifndef FILE_H
#define FILE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>

#include "error.h"

/* Room for a path and its NUL, for the few places that keep one in a fixed
 * buffer (a name built from --out, a symbolic link's target). Linux's PATH_MAX;
 * a longer path is refused or left unchecked where the buffer is used. */
#define PATH_TEXT_MAX 4096

typedef struct {
    FILE *fp;           /* write here */
    char *path;         /* the final name */
    char *tmp_path;     /* the temporary name */
    bool failed;        /* a write failed: commit will refuse */
    int error_number;   /* errno of the first failed write, for commit's message */
} AtomicFile;

bool atomic_open(AtomicFile *f, const char *path, Error *err);
/* Writes bytes, remembering a failure for commit. */
void atomic_write(AtomicFile *f, const void *bytes, size_t n);
/* Flushes, checks every write, renames into place. On failure removes the
 * temporary file, leaves any existing file at path untouched, returns false. */
bool atomic_commit(AtomicFile *f, Error *err);
void atomic_abort(AtomicFile *f);

/* Whole file into a NUL-terminated buffer (the file may itself contain NULs:
 * *len says how long it is). Refuses files over max_bytes. */
bool read_file(const char *path, size_t max_bytes, char **data, size_t *len, Error *err);

/* True when a and b name the same existing file (same device and inode). */
bool same_file(const char *a, const char *b);

/* Creates a directory and its parents, like mkdir -p. */
bool make_dirs(const char *path, Error *err);

#endif
