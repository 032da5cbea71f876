/* target.c: see target.h. */
#include "target.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "image.h"

/* A traced pixel that is drawn over more often than this is not worth a longer
 * log: the log stops and says it was cut. */
#define TRACE_MAX_ENTRIES (1 << 20)
#define TRACE_FIRST_CAP 16

/* The one external definition of the inline target_record of target.h. */
extern inline void target_record(Target *t, size_t i, int face, float value, float stored,
                                 bool passed);

/* n zeroed values of size bytes, from the start of a 64-byte cache line:
 * where the width is a multiple of 16, so is each row of a tile (lesson 10
 * clears an empty tile's lines whole, past the caches). NULL: no memory. */
static void *zeroed_lines(size_t n, size_t size)
{
    void *p = NULL;
    return posix_memalign(&p, 64, n * size) == 0 ? memset(p, 0, n * size) : NULL;
}

bool target_init(Target *t, int width, int height, Error *err)
{
    Target empty = {0};
    *t = empty;
    t->counting = true;
    t->trace.pixel = -1;
    if (width < 1 || width > IMAGE_MAX_SIDE || height < 1 || height > IMAGE_MAX_SIDE)
        return error_set(err, "image size %dx%d is out of range (1 to %d on a side)", width,
                         height, IMAGE_MAX_SIDE);

    /* Both sides are at most IMAGE_MAX_SIDE, so the product fits; the byte
     * counts are checked against SIZE_MAX for the sake of small size_t. */
    size_t n = (size_t)width * (size_t)height;
    if (n > SIZE_MAX / sizeof(float) || n > SIZE_MAX / sizeof(int32_t) ||
        n > SIZE_MAX / sizeof(uint32_t))
        return error_set(err, "image size %dx%d is too large for this machine", width, height);

    t->depth = zeroed_lines(n, sizeof *t->depth);
    t->face = zeroed_lines(n, sizeof *t->face);
    t->overdraw = zeroed_lines(n, sizeof *t->overdraw);
    if (!t->depth || !t->face || !t->overdraw) {
        target_free(t);
        return error_set(err, "out of memory for a %dx%d image", width, height);
    }
    t->width = width;
    t->height = height;
    return true;
}

void target_free(Target *t)
{
    free(t->depth);
    free(t->face);
    free(t->overdraw);
    free(t->trace.entries);
    Target empty = {0};
    *t = empty;
    t->trace.pixel = -1;
}

void target_trace_pixel(Target *t, int x, int y)
{
    t->trace.pixel = (long)y * t->width + x;
}

/* Grows the log by doubling; false when it may not or cannot grow. */
static bool trace_log_grow(TraceLog *log)
{
    if (log->cap >= TRACE_MAX_ENTRIES)
        return false;
    int cap = log->cap ? log->cap * 2 : TRACE_FIRST_CAP;
    if (cap > TRACE_MAX_ENTRIES)
        cap = TRACE_MAX_ENTRIES;
    TraceEntry *grown = realloc(log->entries, (size_t)cap * sizeof *grown);
    if (!grown)
        return false;
    log->entries = grown;
    log->cap = cap;
    return true;
}

void trace_log_append(TraceLog *log, int face, float value, float stored, bool passed)
{
    if (log->overflowed)
        return;
    if (log->count == log->cap && !trace_log_grow(log)) {
        log->overflowed = true; /* keep what we have, say that it is cut */
        return;
    }
    TraceEntry e = {.face = face, .value = value, .stored = stored, .passed = passed};
    log->entries[log->count++] = e;
}
