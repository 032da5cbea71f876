/* fragments.h: the books a depth test keeps, for the summary and --trace:
 * how many fragments it tested, passed and failed, and the history of the
 * one pixel being traced (trace.h prints it). target.h and lesson 01's
 * y-buffer keep both. */
#ifndef FRAGMENTS_H
#define FRAGMENTS_H

#include <stdbool.h>
#include <stdint.h>

typedef struct {
    uint64_t tested, passed, failed;
} FragmentStats;

/* One line of a pixel's history. */
typedef struct {
    int face;
    float value;  /* what the fragment brought: d, 1/d or y */
    float stored; /* what the buffer held before the test */
    bool passed;
} TraceEntry;

typedef struct {
    long pixel;              /* y * width + x of the traced pixel, -1 for none */
    TraceEntry *entries;
    int count, cap;
    bool overflowed;         /* more entries than memory allowed: the log is cut */
} TraceLog;

void trace_log_append(TraceLog *log, int face, float value, float stored, bool passed);

#endif
