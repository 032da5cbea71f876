/* fuzz_depth.h: lesson 06's depth buffer from the bytes, for the fuzz
 * targets of lessons 06-10: any format and mapping (log only where log_ok:
 * lesson 06), the scene's near and far planes (a far plane at infinity only
 * where it is allowed: reversed). */
#ifndef FUZZ_DEPTH_H
#define FUZZ_DEPTH_H

#include "depth_format.h"
#include "fuzz_clip.h"

static inline DepthSetup fuzz_depth_setup(FuzzScene *s, FuzzBytes *b, bool log_ok)
{
    uint8_t pick = fuzz_u8(b);
    DepthFormat format = pick % 3 == 0 ? UNORM16 : pick % 3 == 1 ? UNORM24 : FLOAT32;
    DepthMapping mapping = pick & 4 ? REVERSED : log_ok && (pick & 8) ? LOGARITHMIC : STANDARD;
    if (mapping != REVERSED && isinf(s->ctx.far))
        s->ctx.far = s->ctx.near * 200.0;
    return depth_setup(format, mapping, s->ctx.near, s->ctx.far);
}

#ifdef DEPTH_BIAS_H
/* Lesson 07's bias from the bytes: a factor and units of either sign, up to
 * 1e6 and beyond, a clamp or none; on the scene's faces in `decal`. */
static inline DepthBias fuzz_bias(const FuzzScene *s, FuzzBytes *b)
{
    double factor = fuzz_double(b), units = fuzz_double(b), clamp = fuzz_double(b);
    return (DepthBias){isfinite(factor) ? factor : 0, isfinite(units) ? units : 0,
                       isfinite(clamp) ? clamp : 0, &s->mesh};
}
#endif

#endif
