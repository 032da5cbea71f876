/* intmath.h: integer division that rounds down or up, whatever the sign.
 *
 * C's "/" rounds towards zero: -7 / 2 is -3. Fixed-point rasterizers need the
 * floor (the first pixel at or left of a position) and the ceiling (the first
 * pixel at or right of it), for negative positions too:
 *
 *   floor_div(-7, 2) = -4    ceil_div(-7, 2) = -3
 *   floor_div( 7, 2) =  3    ceil_div( 7, 2) =  4
 *
 * b must be positive; a may be any int64_t, INT64_MIN and INT64_MAX included
 * (neither function negates a, so neither overflows). */
#ifndef INTMATH_H
#define INTMATH_H

#include <stdint.h>

/* a / b rounded towards minus infinity, b > 0. */
static inline int64_t floor_div(int64_t a, int64_t b)
{
    int64_t q = a / b;                     /* rounded towards zero */
    return (a % b != 0 && a < 0) ? q - 1 : q;
}

/* a / b rounded towards plus infinity, b > 0. */
static inline int64_t ceil_div(int64_t a, int64_t b)
{
    int64_t q = a / b;                     /* rounded towards zero */
    return (a % b != 0 && a > 0) ? q + 1 : q;
}

#endif
