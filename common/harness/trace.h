/* trace.h: --trace, the history of one pixel, as RenderDoc's pixel history
 * shows it for a GPU.
 *
 * The lesson's depth test reports every fragment it tests (target_record,
 * target.h); the one pixel being traced keeps them in a TraceLog, in the order
 * they came. trace_print writes that log, one fragment per line, then the
 * pixel's winner and what the buffer holds at the end:
 *
 *     trace pixel (40,15): 3 fragments
 *       1. face 0   d=5            stored=inf          passed
 *       2. face 1   d=8            stored=5            failed
 *       3. face 2   d=4            stored=5            passed
 *     winner: face 2, stored d=4
 *
 * Values are the floats the buffer compares, printed by format_stored
 * (depth_rule.h): the fewest digits, 6 to 9, that give back the same float.
 * The words come from the lesson's DepthRule: lesson 04 prints 1/d, lesson 01
 * prints y and "segment", and traces a column ("trace column 37: ...").
 *
 * A pixel no fragment reached prints one line:
 *     no fragment reached pixel (0,0); stored: inf (cleared)
 * A pixel where every fragment failed (a buffer cleared wrongly) ends with
 *     winner: none (no fragment passed), stored d=0 */
#ifndef TRACE_H
#define TRACE_H

#include <stdio.h>

#include "depth_rule.h"
#include "target.h"

/* One fragment's line: number, index, value, stored value, result. */
#define TRACE_LINE_FORMAT "%3d. %s %-3d %s=%-12s stored=%-12s %s\n"

/* where: "pixel (4,2)" or "column 37". winner: the index that holds the pixel
 * at the end (NO_FACE when none); stored: the buffer's final value there. */
void trace_print(FILE *out, const TraceLog *log, const DepthRule *rule, const char *where,
                 int winner, float stored);

#endif
