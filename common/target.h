/* target.h: what a lesson draws into, passed explicitly (no globals).
 *
 * depth[]    what the lesson's depth test keeps per pixel (d in lessons 02
 *            and 03, 1/d in 04); the lesson's clear_depth clears it and face[]
 * face[]     the face that won each pixel, NO_FACE where none did (shade.h)
 * overdraw[] fragments tested per pixel (--overdraw-out) */
#ifndef TARGET_H
#define TARGET_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "error.h"
#include "fragments.h"

#define NO_FACE (-1)

typedef struct {
    int width, height;
    float *depth;
    int32_t *face;
    bool counting; /* on from target_init; off: no overdraw, stats or trace kept */
    uint32_t *overdraw;
    FragmentStats stats;
    TraceLog trace;
} Target;

/* Buffers of width x height (1 .. IMAGE_MAX_SIDE each), counting on, counts at
 * zero, no pixel traced. The lesson's own clear_depth clears depth[]. */
bool target_init(Target *t, int width, int height, Error *err);
void target_free(Target *t);
void target_trace_pixel(Target *t, int x, int y); /* --trace it from now on; inside t */

/* Every fragment a lesson's depth test tests at pixel i: counted, and logged at
 * the traced pixel (--trace). Not static: target.c has its external definition. */
inline void target_record(Target *t, size_t i, int face, float value, float stored, bool passed)
{
    if (!t->counting)
        return;
    t->overdraw[i]++;
    t->stats.tested++;
    t->stats.passed += passed;
    t->stats.failed += !passed;
    if ((long)i == t->trace.pixel)
        trace_log_append(&t->trace, face, value, stored, passed);
}

#endif
