/* target.h: what a lesson draws into, passed explicitly (no globals).
 *
 * depth[]    the value the lesson's depth test keeps per pixel: view depth d in
 *            lessons 02 and 03, 1/d in lesson 04. The lesson clears it.
 * face[]     the face that won each pixel, NO_FACE where nothing was drawn.
 *            Colours are resolved from it after drawing (shade.h), so the
 *            rasterizer writes one integer per pixel and no colour.
 * overdraw[] fragments tested per pixel (--overdraw-out).
 *
 * Every fragment that reaches a depth test is reported with target_record(),
 * which counts it and, when its pixel is the traced one, logs it (--trace). */
#ifndef TARGET_H
#define TARGET_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "error.h"

#define NO_FACE (-1)

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

typedef struct {
    int width, height;
    float *depth;
    int32_t *face;
    uint32_t *overdraw;
    FragmentStats stats;
    TraceLog trace;
} Target;

/* Buffers of width x height (1 .. IMAGE_MAX_SIDE each); depth is set to
 * clear_value, face to NO_FACE, counts to zero, no pixel traced. */
bool target_init(Target *t, int width, int height, float clear_value, Error *err);
void target_free(Target *t);
/* Trace pixel (x, y) from now on (x, y inside the target). */
void target_trace_pixel(Target *t, int x, int y);

void trace_log_append(TraceLog *log, int face, float value, float stored, bool passed);

/* Called by a lesson's depth test for every fragment it tests at pixel i.
 * Inline with external linkage (target.c holds its one external definition),
 * not static, so that a lesson's own inline depth_test may call it: clang
 * refuses a static function inside an inline function with external linkage. */
inline void target_record(Target *t, size_t i, int face, float value, float stored,
                                 bool passed)
{
    t->overdraw[i]++;
    t->stats.tested++;
    if (passed)
        t->stats.passed++;
    else
        t->stats.failed++;
    if ((long)i == t->trace.pixel)
        trace_log_append(&t->trace, face, value, stored, passed);
}

#endif
