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
    bool to_stdout;     /* "-": fp is stdout, flushed but never closed */
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
 * *len says how long it is). Refuses files over max_bytes, and anything that
 * is not a regular file (a pipe, a device, a directory) without waiting.
 * On failure errno says why: ENOMEM when memory ran out, not the file. */
bool read_file(const char *path, size_t max_bytes, char **data, size_t *len, Error *err);

/* ---- which file a name means ----
 *
 * The identity of a path, whether or not the file exists yet: a symbolic link
 * at the last component is followed to its target (dangling or not, as
 * atomic_open writes through it), the directory part is resolved with
 * realpath(3) as far as it exists and the rest ("new/../x") is taken apart
 * by name. For a file that exists, its device and inode too (a hard link). */
typedef struct {
    char *resolved; /* absolute, no ".", "..", or symbolic link in it; NULL: no memory */
    bool exists;
    unsigned long long dev, ino;
} FileId;

bool file_id(const char *path, FileId *id);
void file_id_free(FileId *id);
bool file_id_same(const FileId *a, const FileId *b);

/* True when a and b are one file: the same resolved name (a.png, ./a.png,
 * sub/../a.png, a link to it, dangling or not) or the same device and inode. */
bool same_file(const char *a, const char *b);

/* True when --steps dir would write path: dir/step_NNNN.png or
 * dir/step_NNNN_depth.png (four digits or more), by identity. */
bool is_step_picture(const char *path, const char *dir);

/* "-" as an output: standard output. */
bool is_stdout_name(const char *path);

/* Checks, before anything is drawn, that an output could be written: its
 * directory exists or can be made (no file in the way, writable), it is not a
 * directory, a pipe nobody reads or a read-only file, and its name ends in a
 * file name. Creates nothing. "-" (standard output) is always fine. */
bool output_check(const char *path, Error *err);
/* The same for a directory of outputs (--steps). */
bool output_dir_check(const char *dir, Error *err);

/* ---- a run's outputs: written all, then published all ----
 *
 * Between output_set_begin and output_set_publish, atomic_commit writes,
 * flushes and closes each temporary file but does not rename it: publish
 * renames them all, abort removes them all (and the directories make_dirs
 * created for them). Without output_set_begin a commit renames at once. */
void output_set_begin(void);
bool output_set_publish(Error *err);
void output_set_abort(void);
/* Whether a set is open (between begin and publish or abort): a function
 * that writes several files opens its own set only when none is. */
bool output_set_open(void);

/* Every temporary file that exists is listed; SIGINT, SIGTERM, SIGHUP and
 * the other signals that end a program (file.c's list) remove them all (and
 * the directories made for them) and end the program with status 128 + the
 * signal's number. The handlers are set by signals_begin, or at the latest
 * when the first temporary file is made; a signal that was ignored stays
 * ignored. */

/* At the start of a lesson: the handlers are set at once, and each prints
 * one line on stderr before the program ends, "<program>: error: stopped by
 * SIGTERM" (write(2) alone). SIGPIPE is ignored (unless something else
 * handles it): a write to a pipe whose reader has gone fails with EPIPE and
 * is reported as any failed write, "cannot write ...: Broken pipe", status 1. */
void signals_begin(const char *program);

/* While --out - sends the picture to standard output, what a lesson prints
 * there (the summary, --trace, --ascii) goes to standard error instead:
 * begin points descriptor 1 at standard error and returns the descriptor to
 * give end, which puts it back (-1: nothing was changed). */
int stdout_to_stderr_begin(void);
void stdout_to_stderr_end(int saved);

/* Flushes standard output: false (err set) when anything written to it was
 * lost (a full disk, a closed descriptor). */
bool stdout_flush(Error *err);

/* Creates a directory and its parents, like mkdir -p. */
bool make_dirs(const char *path, Error *err);

#endif
