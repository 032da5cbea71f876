/* depth_buffer.c: lesson 06's depth buffer of window depth z_w, in a format
 * and a mapping, step by step (depth_format.h, docs/06_depth_precision.md). */
#include "depth_buffer.h"

#include <math.h>

#include "clip.h"
#include "guard_band.h"
#include "state.h"

#define UNORM16_MAX 65535.0    /* 2^16 - 1: the code of z_w = 1 */
#define UNORM24_MAX 16777215.0 /* 2^24 - 1 */

/* Each mapping as z_w = a + b/d (log: its plane), from depth_format.h's formulas. */
DepthSetup depth_setup(DepthFormat format, DepthMapping mapping, double near, double far)
{
    DepthSetup s = {.format = format, .mapping = mapping, .near = near, .far = far,
                    .log_range = log(far / near)};
    /* SOLUTION BEGIN: a and b of each mapping; reversed with far = inf is n/d. */
    if (mapping == STANDARD) {
        s.a = far / (far - near); /* f/(f-n) (1 - n/d) */
        s.b = -near * s.a;
    } else if (isinf(far) || mapping == LOGARITHMIC) {
        s.b = near; /* n/d: and log's plane, whose log each fragment takes */
    } else {
        s.a = -near / (far - near); /* n/(f-n) (f/d - 1) */
        s.b = -far * s.a;
    }
    /* SOLUTION STUB
    s.b = near;
    */
    /* SOLUTION END */
    return s;
}

double window_depth(const DepthSetup *s, double d)
{
    return s->mapping == LOGARITHMIC ? log(d / s->near) / s->log_range : s->a + s->b / d;
}

double view_depth(const DepthSetup *s, double z_w)
{
    return s->mapping == LOGARITHMIC ? s->near * exp(z_w * s->log_range) : s->b / (z_w - s->a);
}

static double unorm_max(DepthFormat format)
{
    return format == UNORM16 ? UNORM16_MAX : UNORM24_MAX;
}

/* What the buffer stores for z_w: for a unorm format the integer code, z_w
 * clamped to [0, 1] (as a GPU clamps) times 2^bits - 1 in float32, rounded to
 * the nearest code (a tie to even, as rintf rounds); every code is below 2^24,
 * so a float holds it exactly. For float32, z_w itself. */
float encode_depth(DepthFormat format, float z_w)
{
    /* SOLUTION BEGIN: the code of z_w, or z_w itself for float32. */
    if (format == FLOAT32)
        return z_w;
    float z = z_w < 0 ? 0.0f : z_w > 1 ? 1.0f : z_w;
    return rintf(z * (float)unorm_max(format));
    /* SOLUTION STUB
    (void)format;
    return z_w;
    */
    /* SOLUTION END */
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
 * to store different values: one quantum over |dz_w/dd|, which is |b| / d^2,
 * or 1 / (d log(f/n)) for log. */
double depth_step(const DepthSetup *s, double d)
{
    double slope = s->mapping == LOGARITHMIC ? 1 / (d * s->log_range) : fabs(s->b) / (d * d);
    return depth_quantum(s->format, window_depth(s, d)) / slope;
}

/* A triangle's plane of z_w as a GPU sets it up, all in float32: the corners'
 * z_w = z_c (1 / w_c), z_c = a w_c + b and w_c handed on as floats; then the
 * plane through (x, y, z_w), from the centre of pixel (0, 0). A triangle
 * clockwise in OpenGL's window (y up) starts at corner 1, as in llvmpipe. */
DepthPlane depth_plane(const DepthSetup *s, const ScreenVertex v[3])
{
    double turn = (v[1].x - v[0].x) * (v[2].y - v[0].y) - (v[2].x - v[0].x) * (v[1].y - v[0].y);
    const int *order = turn < 0 ? (const int[3]){1, 0, 2} : (const int[3]){0, 1, 2};
    float x[3], y[3], z[3];
    for (int k = 0; k < 3; k++) {
        const ScreenVertex *c = &v[order[k]];
        x[k] = (float)c->x;
        y[k] = (float)c->y;
        z[k] = (float)(s->a * c->d + s->b) * (1.0f / (float)c->d);
    }
    DepthPlane p = {z[0], 0, 0};
    float dx01 = x[0] - x[1], dy01 = y[0] - y[1], dz01 = z[0] - z[1];
    float dx20 = x[2] - x[0], dy20 = y[2] - y[0], dz20 = z[2] - z[0];
    float area = dx01 * dy20 - dx20 * dy01;
    if (area == 0)
        return p; /* no pixel centre inside */
    /* SOLUTION BEGIN: the slopes from dz01 = gx dx01 + gy dy01 and dz20 = gx dx20 + gy dy20,
     * then the value at (0.5, 0.5), in the page's order (exercise 1): tests compare bits. */
    float inv_area = 1.0f / area;
    p.gx = dz01 * (dy20 * inv_area) - dz20 * (dy01 * inv_area);
    p.gy = dz20 * (dx01 * inv_area) - dz01 * (dx20 * inv_area);
    p.a0 = z[0] - (p.gx * (x[0] - 0.5f) + p.gy * (y[0] - 0.5f));
    /* SOLUTION STUB
    (void)dz01; (void)dz20;
    */
    /* SOLUTION END */
    return p;
}

/* The triangle as the GPU sets it up: clipped at near and far (clip.c),
 * divided onto the screen and clipped to the guard band (guard_band.h); its
 * plane then from its first three corners (any three give the same plane). */
static DepthPlane triangle_plane(const DepthSetup *s, const ScreenFace *tri, int width,
                                 int height)
{
    Vec4 kept[CLIP_MAX_OUT(3)];
    ScreenVertex on[CLIP_MAX_OUT(3)], v[GUARD_BAND_MAX_OUT(CLIP_MAX_OUT(3))];
    int n = tri->clip ? clip_polygon(tri->clip, 3, kept) : 3;
    for (int k = 0; k < n; k++)
        on[k] = tri->clip ? clip_to_screen(kept[k], width, height) : tri->v[k];
    DepthPlane none = {0, 0, 0};
    return guard_band_clip(on, n, width, height, LINEAR_INV_D, v) >= 3 ? depth_plane(s, v) : none;
}

/* A face, triangle by triangle as a GPU draws it: each its own plane of z_w,
 * then drawn (clipped, divided, scanned) as lesson 05 draws a face. */
void draw_triangles(Target *t, LessonState *s, const ScreenFace *f, const DrawContext *ctx,
                    float offset)
{
    for (int k = 0; k < f->n - 2; k++) {
        const int *c = f->tris[k].c;
        ScreenVertex v[3] = {f->v[c[0]], f->v[c[1]], f->v[c[2]]};
        Vec4 clip[3];
        ScreenFace tri = screen_triangle(v, f->face);
        if (f->clip) {
            for (int j = 0; j < 3; j++)
                clip[j] = f->clip[c[j]];
            tri.clip = clip;
        }
        Primitive p = {.target = t, .state = s, .face = f->face, .offset = offset,
                       .plane = triangle_plane(&s->depth, &tri, ctx->width, ctx->height)};
        draw_clipped_face(&p, &tri, ctx);
    }
}

static void draw_precise_face(Target *t, LessonState *s, const ScreenFace *f,
                              const DrawContext *ctx)
{
    draw_triangles(t, s, f, ctx, 0.0f);
}

/* The far plane everywhere, nothing drawn: 1 (standard, log) or 0 (reversed). */
static float cleared(const DepthSetup *s)
{
    return encode_depth(s->format, s->mapping == REVERSED ? 0.0f : 1.0f);
}

/* The target's buffer in the format and mapping of the lesson's state. */
void clear_depth(Target *t, LessonState *s)
{
    size_t n = (size_t)t->width * (size_t)t->height;
    float value = cleared(&s->depth);
    for (size_t i = 0; i < n; i++) {
        t->depth[i] = value;
        t->face[i] = NO_FACE;
    }
}

/* What a fragment of triangle p at pixel (x, y) stores: the triangle's plane at the
 * pixel centre in float32, as a GPU evaluates it, not the scanline's 1/d (for log,
 * -log(n/d) / log(f/n) of the plane's n/d), plus the offset (lesson 07's), encoded. */
float fragment_depth(const Primitive *p, int x, int y)
{
    const DepthSetup *s = &p->state->depth;
    float z_w = p->plane.a0 + p->plane.gx * (float)x + p->plane.gy * (float)y;
    if (s->mapping == LOGARITHMIC)
        z_w = -logf(z_w) / (float)s->log_range;
    return encode_depth(s->format, z_w + p->offset);
}

/* The depth test of one fragment of triangle p at pixel (x, y). */
inline bool depth_test(const Primitive *p, int x, int y, float inv_d)
{
    const DepthSetup *s = &p->state->depth;
    Target *t = p->target;
    size_t i = (size_t)y * (size_t)t->width + (size_t)x;
    int face = p->face;
    (void)inv_d;
    float value = fragment_depth(p, x, y), stored = t->depth[i];
    /* SOLUTION BEGIN: does the fragment win pixel i? Which way is nearer
     * depends on the mapping; a tie keeps the fragment drawn first. */
    bool passed = s->mapping == REVERSED ? value > stored : value < stored;
    /* SOLUTION STUB
    bool passed = false; (void)s;
    */
    /* SOLUTION END */
    target_record(t, i, face, value, stored, passed);
    /* SOLUTION BEGIN: a fragment that wins leaves its value and face there. */
    if (passed) {
        t->depth[i] = value;
        t->face[i] = face;
    }
    /* SOLUTION END */
    return passed;
}

/* A stored value back as view depth d (--depth-out, --shade depth). */
double stored_to_depth(const LessonState *state, float stored)
{
    const DepthSetup *s = &state->depth;
    return stored == cleared(s) ? INFINITY : view_depth(s, decode_depth(s->format, stored));
}

const Rasterizer DEPTH_PRECISION_ZBUFFER = {
    .clear = clear_depth, .draw_face = draw_precise_face, .stored_to_depth = stored_to_depth,
    .clips = true,
};
