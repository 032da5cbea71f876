/* depth_bias.c: lesson 07, depth bias (polygon offset), step by step
 * (depth_bias.h, docs/07_depth_bias.md). A decal and its base have the same
 * z_w on paper, but each triangle's plane is set up from its own corners and
 * rounded on its own (lesson 06): either can come out nearer. So every
 * fragment of the decal moves by o toward the camera. */
#include "depth_bias.h"

#include <math.h>

#include "clip.h"
#include "depth_buffer.h"
#include "state.h"

/* m: the steepest slope of z_w on the screen. Over a triangle z_w is the
 * plane z_w = a0 + gx x + gy y (lesson 06), so m = max(|gx|, |gy|), as OpenGL
 * and Vulkan allow in place of sqrt(gx^2 + gy^2), and GPUs do. */
double depth_slope(const DepthPlane *p)
{
    /* SOLUTION BEGIN: the larger of the plane's two slopes, in size. */
    return fmax(fabs((double)p->gx), fabs((double)p->gy));
    /* SOLUTION STUB
    (void)p;
    return 0.0;
    */
    /* SOLUTION END */
}

/* r: the smallest difference of z_w the format resolves on this face: unorm n
 * bits, one code, 1/(2^n - 1); float32, 2^(e - 23) with e the exponent of the
 * face's largest |z_w| = 1.f x 2^e (OpenGL, Vulkan, Direct3D): depth_quantum. */
double resolvable_difference(const DepthSetup *s, const ScreenVertex *v, int n)
{
    /* SOLUTION BEGIN: the largest |z_w| of the corners, and one step there. */
    double largest = 0;
    for (int k = 0; k < n; k++)
        largest = fmax(largest, fabs(window_depth(s, v[k].d)));
    return depth_quantum(s->format, largest);
    /* SOLUTION STUB
    (void)s; (void)v; (void)n;
    return 0.0;
    */
    /* SOLUTION END */
}

/* o = m FACTOR + r UNITS. A clamp other than 0 limits it as Direct3D's
 * DepthBiasClamp and Vulkan's depthBiasClamp do: to at most the clamp when
 * it is positive, to at least the clamp when it is negative. */
double polygon_offset(const DepthBias *bias, double m, double r)
{
    /* SOLUTION BEGIN: the two terms, then the clamp. */
    double o = m * bias->factor + r * bias->units;
    return bias->clamp > 0 ? fmin(o, bias->clamp) : bias->clamp < 0 ? fmax(o, bias->clamp) : o;
    /* SOLUTION STUB
    (void)bias; (void)m; (void)r;
    return 0.0;
    */
    /* SOLUTION END */
}

/* The face's corners on the screen, as its triangles are set up: clipped at
 * near and far (clip.c) and divided, or as they are for a face made there. */
static int face_on_screen(const ScreenFace *f, int width, int height, ScreenVertex *v)
{
    Vec4 kept[CLIP_MAX_OUT(CLIP_MAX_IN)];
    if (f->n > CLIP_MAX_IN)
        return 0; /* none: a face of so many corners gets no bias */
    int n = f->clip ? clip_polygon(f->clip, f->n, kept) : f->n;
    for (int k = 0; k < n; k++)
        v[k] = f->clip ? clip_to_screen(kept[k], width, height) : f->v[k];
    return n;
}

/* One face: a decal is drawn with its o, m from its plane (its triangles lie
 * in one) and r from its corners; any other face with o = 0, exactly as
 * lesson 06 draws it. */
static void draw_biased_face(Target *t, LessonState *state, const ScreenFace *f,
                             const DrawContext *ctx)
{
    const DepthSetup *s = &state->depth;
    const DepthBias *bias = &state->bias;
    ScreenVertex v[CLIP_MAX_OUT(CLIP_MAX_IN)];
    float o = 0;
    int n;
    if (bias->mesh && mesh_face_in(bias->mesh, f->face, "decal") &&
        (n = face_on_screen(f, ctx->width, ctx->height, v)) >= 3) {
        DepthPlane p = depth_plane(s, v);
        o = (float)polygon_offset(bias, depth_slope(&p), resolvable_difference(s, v, n));
    }
    draw_triangles(t, state, f, ctx, o);
}

const Rasterizer DEPTH_BIAS_ZBUFFER = {
    .clear = clear_depth, .draw_face = draw_biased_face, .stored_to_depth = stored_to_depth,
    .clips = true,
};
