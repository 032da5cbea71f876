/* depth_buffer.c: lesson 06's depth buffer of window depth z_w, in a format
 * and a mapping, step by step (depth_format.h, docs/06_depth_precision.md). */
#include "depth_format.h"

#include <math.h>

#include "clip.h"
#include "scanline.h"

#define UNORM16_MAX 65535.0    /* 2^16 - 1: the code of z_w = 1 */
#define UNORM24_MAX 16777215.0 /* 2^24 - 1 */

/* Both mappings as z_w = a + b/d, from the formulas of depth_format.h. */
DepthSetup depth_setup(DepthFormat format, DepthMapping mapping, double near, double far)
{
    DepthSetup s = {.format = format, .mapping = mapping, .near = near, .far = far};
    if (mapping == STANDARD) {
        s.a = far / (far - near); /* f/(f-n) (1 - n/d) */
        s.b = -near * s.a;
    } else if (isinf(far)) {
        s.b = near; /* n/d */
    } else {
        s.a = -near / (far - near); /* n/(f-n) (f/d - 1) */
        s.b = -far * s.a;
    }
    return s;
}

double window_depth(const DepthSetup *s, double d)
{
    return s->a + s->b / d;
}

double view_depth(const DepthSetup *s, double z_w)
{
    return s->b / (z_w - s->a);
}

static double unorm_max(DepthFormat format)
{
    return format == UNORM16 ? UNORM16_MAX : UNORM24_MAX;
}

/* What the buffer stores for z_w: for a unorm format the integer code, z_w
 * clamped to [0, 1] (as a GPU clamps) times 2^bits - 1, rounded to nearest
 * (exact in a float: every code is below 2^24); for float32, z_w itself. */
float encode_depth(DepthFormat format, float z_w)
{
    if (format == FLOAT32)
        return z_w;
    double z = z_w < 0 ? 0.0 : z_w > 1 ? 1.0 : (double)z_w;
    return (float)floor(z * unorm_max(format) + 0.5);
}

double decode_depth(DepthFormat format, float stored)
{
    return format == FLOAT32 ? stored : stored / unorm_max(format);
}

/* The spacing of the values the format can hold, in z_w, at z_w: one code
 * for unorm, one float32 step (2^-23 of the power of two at or below z_w). */
double depth_quantum(DepthFormat format, double z_w)
{
    if (format != FLOAT32)
        return 1.0 / unorm_max(format);
    int e;
    frexp(z_w, &e); /* z_w = m 2^e, 1/2 <= m < 1 */
    return ldexp(1.0, e - 24 < -149 ? -149 : e - 24);
}

/* The depth step at d: how far apart two surfaces must be, in world units,
 * to store different values: one quantum over |dz_w/dd| = |b| / d^2. */
double depth_step(const DepthSetup *s, double d)
{
    return depth_quantum(s->format, window_depth(s, d)) * d * d / fabs(s->b);
}

/* The far plane everywhere, nothing drawn: 1 (standard) or 0 (reversed). */
static float cleared(const DepthSetup *s)
{
    return encode_depth(s->format, s->mapping == REVERSED ? 0.0f : 1.0f);
}

/* The target's buffer in the format and mapping of t->depth_setup. */
void clear_depth(Target *t)
{
    size_t n = (size_t)t->width * (size_t)t->height;
    float value = cleared(t->depth_setup);
    for (size_t i = 0; i < n; i++) {
        t->depth[i] = value;
        t->face[i] = NO_FACE;
    }
}

/* The depth test of one fragment at pixel i. The scanline hands it the
 * fragment's 1/d (stepped in double, rounded to float); z_w = a + b/d is
 * computed in double and rounded to float32, as a GPU's interpolator hands
 * the depth test a float; then it is stored in the buffer's format. Lesson 07:
 * the face's bias o is added first, before the format rounds z_w, as in OpenGL. */
inline bool depth_test(Target *t, size_t i, int face, float inv_d)
{
    const DepthSetup *s = t->depth_setup;
    float z_w = (float)(s->a + s->b * inv_d + s->offset);
    float value = encode_depth(s->format, z_w), stored = t->depth[i];
    bool passed = s->mapping == REVERSED ? value > stored : value < stored;
    target_record(t, i, face, value, stored, passed);
    if (passed) {
        t->depth[i] = value;
        t->face[i] = face;
    }
    return passed;
}

/* A stored value back as view depth d (--depth-out, --shade depth). */
static double stored_to_depth(const Target *t, float stored)
{
    const DepthSetup *s = t->depth_setup;
    return stored == cleared(s) ? INFINITY : view_depth(s, decode_depth(s->format, stored));
}

const Rasterizer DEPTH_PRECISION_ZBUFFER = {
    .clear = clear_depth, .draw_face = draw_biased_face, .stored_to_depth = stored_to_depth,
    .clips = true,
};
