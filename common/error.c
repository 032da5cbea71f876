/* error.c: see error.h. */
#include "error.h"

#include <ctype.h>
#include <stdarg.h>
#include <stdio.h>

bool error_set(Error *err, const char *fmt, ...)
{
    if (err) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(err->msg, sizeof err->msg, fmt, ap);
        va_end(ap);
    }
    return false;
}

int error_report(const char *program, const Error *err, int status)
{
    /* One line, whatever the message quotes: a control character that came in
     * with a file name or an argument (a newline, an escape) prints as '?'. */
    char line[ERROR_MSG_MAX];
    size_t n = 0;
    for (; err->msg[n] != '\0' && n < sizeof line - 1; n++)
        line[n] = iscntrl((unsigned char)err->msg[n]) ? '?' : err->msg[n];
    line[n] = '\0';
    fprintf(stderr, "%s: error: %s\n", program, line);
    return status;
}
