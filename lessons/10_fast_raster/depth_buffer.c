/* depth_buffer.c: lesson 06's depth buffer of window depth z_w, in a format
 * and a mapping, step by step (depth_format.h, docs/06_depth_precision.md). */
#include "depth_format.h"

#include <math.h>

#include "clip.h"
#include "guard_band.h"
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
 * clamped to [0, 1] (as a GPU clamps) times 2^bits - 1 in float32, rounded to
 * the nearest code (a tie to even, as rintf rounds); every code is below 2^24,
 * so a float holds it exactly. For float32, z_w itself. */
float encode_depth(DepthFormat format, float z_w)
{
    if (format == FLOAT32)
        return z_w;
    float z = z_w < 0 ? 0.0f : z_w > 1 ? 1.0f : z_w;
    return rintf(z * (float)unorm_max(format));
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
    float inv_area = 1.0f / area;
    p.gx = dz01 * (dy20 * inv_area) - dz20 * (dy01 * inv_area);
    p.gy = dz20 * (dx01 * inv_area) - dz01 * (dx20 * inv_area);
    p.a0 = z[0] - (p.gx * (x[0] - 0.5f) + p.gy * (y[0] - 0.5f));
    return p;
}

/* The triangle as the GPU sets it up: clipped at near and far (clip.c),
 * divided onto the screen and clipped to the guard band (guard_band.h); its
 * plane then from its first three corners (any three give the same plane). */
static void triangle_plane(Target *t, const ScreenFace *tri)
{
    Vec4 kept[CLIP_MAX_OUT(3)];
    ScreenVertex on[CLIP_MAX_OUT(3)], v[GUARD_BAND_MAX_OUT(CLIP_MAX_OUT(3))];
    int n = tri->clip ? clip_polygon(tri->clip, 3, kept) : 3;
    for (int k = 0; k < n; k++)
        on[k] = tri->clip ? clip_to_screen(kept[k], t->width, t->height) : tri->v[k];
    if (guard_band_clip(on, n, t->width, t->height, LINEAR_INV_D, v) >= 3)
        t->depth_setup->plane = depth_plane(t->depth_setup, v);
}

/* A face, triangle by triangle as a GPU draws it: each its own plane of z_w,
 * then drawn (clipped, divided, scanned) as lesson 05 draws a face. */
void draw_triangles(Target *t, const ScreenFace *f, const DrawContext *ctx)
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
        triangle_plane(t, &tri);
        draw_clipped_face(t, &tri, ctx);
    }
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

/* The depth test of one fragment at pixel i = y width + x. Its z_w is the
 * triangle's plane at the pixel centre (plus the offset, lesson 07's), in
 * float32 as a GPU evaluates it, not the scanline's 1/d; then it is stored
 * in the buffer's format. */
inline bool depth_test(Target *t, size_t i, int face, float inv_d)
{
    const DepthSetup *s = t->depth_setup;
    float x = (float)(i % (size_t)t->width), y = (float)(i / (size_t)t->width);
    float z_w = s->plane.a0 + s->plane.gx * x + s->plane.gy * y + s->offset;
    (void)inv_d;
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
double stored_to_depth(const Target *t, float stored)
{
    const DepthSetup *s = t->depth_setup;
    return stored == cleared(s) ? INFINITY : view_depth(s, decode_depth(s->format, stored));
}

const Rasterizer DEPTH_PRECISION_ZBUFFER = {
    .clear = clear_depth, .draw_face = draw_triangles, .stored_to_depth = stored_to_depth,
    .clips = true,
};
