/* depth_rule.c: see depth_rule.h. */
#include "depth_rule.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/* Six digits read well; nine always give back the same float (FLT_DECIMAL_DIG). */
#define FEWEST_DIGITS 6
#define ROUND_TRIP_DIGITS 9
/* A float holds every integer below 2^24 exactly: a unorm code, in full. */
#define EXACT_INTEGERS 16777216.0f

bool rule_is_nearer(const DepthRule *rule, double a, double b)
{
    return rule->nearer == SMALLER_IS_NEARER ? a < b : a > b;
}

const char *format_stored(float v, char buf[STORED_TEXT_MAX])
{
    if (isinf(v)) {
        snprintf(buf, STORED_TEXT_MAX, "%s", v > 0 ? "inf" : "-inf");
        return buf;
    }
    if (isnan(v)) {
        snprintf(buf, STORED_TEXT_MAX, "nan");
        return buf;
    }
    if (v == floorf(v) && fabsf(v) < EXACT_INTEGERS) { /* 16351140, not 1.635114e+07 */
        snprintf(buf, STORED_TEXT_MAX, "%.0f", (double)v);
        return buf;
    }
    for (int digits = FEWEST_DIGITS; digits <= ROUND_TRIP_DIGITS; digits++) {
        snprintf(buf, STORED_TEXT_MAX, "%.*g", digits, (double)v);
        if (strtof(buf, NULL) == v)
            break;
    }
    return buf;
}
