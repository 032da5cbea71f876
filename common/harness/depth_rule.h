/* depth_rule.h: what a lesson's depth buffer holds, in the words of its page.
 *
 * The inspection tools (--trace, --ascii; trace.h, ascii.h) are written once
 * for every lesson. Each lesson plugs in its own rule:
 *
 *   lesson  buffer          stored value  index     nearer is
 *   01      "y-buffer"      "y"           segment   larger   (y > stored wins)
 *   02, 03  "depth buffer"  "d"           face      smaller  (smaller d wins) 
 *   04      "depth buffer"  "1/d"         face      larger   (1/d > stored wins)
 *
 * A tool never converts the stored value: it shows what the buffer holds, so
 * that lesson 04's trace and text picture speak of 1/d, as its page does. */
#ifndef DEPTH_RULE_H
#define DEPTH_RULE_H

#include <stdbool.h>

typedef enum { SMALLER_IS_NEARER, LARGER_IS_NEARER } NearerIs;

typedef struct {
    const char *buffer; /* "depth buffer", "y-buffer" */
    const char *value;  /* what one entry is: "d", "1/d", "y" */
    const char *index;  /* what draws into it: "face", "segment" */
    NearerIs nearer;
} DepthRule;

/* Room for a float printed by format_stored, with its NUL. */
#define STORED_TEXT_MAX 32

/* True when stored value a is strictly nearer than b by the rule. */
bool rule_is_nearer(const DepthRule *rule, double a, double b);

/* A stored value as text, with the fewest significant digits (6 to 9) that
 * read back as the same float: 4.25 is "4.25", 1/5 is "0.2", but two values
 * that differ only in their last bits print differently, as a tie and a
 * near-tie must. An integer below 2^24 (a unorm code) prints whole:
 * 16351140, not 1.635114e+07. Infinities print as "inf" and "-inf". */
const char *format_stored(float v, char buf[STORED_TEXT_MAX]);

#endif
