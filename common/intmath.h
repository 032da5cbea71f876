/* intmath.h: integer division rounding down or up, whatever the sign of a.
 * C's "/" rounds towards zero (-7 / 2 is -3); fixed point needs floor_div(-7,
 * 2) = -4 and ceil_div(-7, 2) = -3. b > 0; any int64_t a, INT64_MIN included. */
#ifndef INTMATH_H
#define INTMATH_H

#include <stdint.h>

static inline int64_t floor_div(int64_t a, int64_t b) /* a / b towards -infinity, b > 0 */
{
    int64_t q = a / b; /* rounded towards zero */
    return (a % b != 0 && a < 0) ? q - 1 : q;
}

static inline int64_t ceil_div(int64_t a, int64_t b) /* a / b towards +infinity, b > 0 */
{
    int64_t q = a / b;
    return (a % b != 0 && a > 0) ? q + 1 : q;
}

#endif
