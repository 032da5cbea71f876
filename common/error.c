/* error.c: see error.h. */
#include "error.h"

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
    fprintf(stderr, "%s: error: %s\n", program, err->msg);
    return status;
}
