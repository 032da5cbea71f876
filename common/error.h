/* error.h: one error message, carried back to whoever prints it.
 *
 * Functions of common/ never print and never exit. They fill an Error and return
 * false; the lesson's main.c prints "<program>: error: <msg>" and picks the exit
 * status (docs/conventions.md: 2 for a usage error, 1 for a failure while running). */
#ifndef ERROR_H
#define ERROR_H

#include <stdbool.h>

/* Room for two paths of PATH_MAX and the words around them: a long path
 * never cuts off the reason that follows it. */
#define ERROR_MSG_MAX (2 * 4096 + 512)

typedef struct {
    char msg[ERROR_MSG_MAX];
} Error;

/* Exit statuses of every lesson. */
enum {
    EXIT_OK = 0,
    EXIT_RUN_FAILED = 1,   /* a file missing, a malformed OBJ line, an unwritable output */
    EXIT_USAGE = 2,        /* a bad command line */
    EXIT_IMAGES_DIFFER = 3 /* --compare found a difference */
};

/* printf-style; always returns false so that `return error_set(err, ...)` reads well. */
bool error_set(Error *err, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/* Prints "<program>: error: <msg>" on stderr, one line (a control character in
 * msg prints as '?'), and returns status. */
int error_report(const char *program, const Error *err, int status);

#endif
