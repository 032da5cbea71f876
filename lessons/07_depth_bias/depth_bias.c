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

/* Part `part` of the face on the screen, as its triangles are set up:
 * clipped at near and far (clip.c) and divided, or as it is for a face made
 * there. The face whole is one part; a face of more corners than
 * clip_polygon takes is clipped as its triangles (clip.h), one a part. */
static int face_on_screen(const ScreenFace *f, int part, int width, int height,
                          ScreenVertex *v)
{
    Vec4 in[CLIP_MAX_IN], kept[CLIP_MAX_OUT(CLIP_MAX_IN)];
    bool whole = f->n <= CLIP_MAX_IN;
    int n = whole ? f->n : 3;
    for (int k = 0; k < n; k++) {
        int c = whole ? k : f->tris[part].c[k];
        if (f->clip)
            in[k] = f->clip[c];
        else
            v[k] = f->v[c];
    }
    if (f->clip) {
        n = clip_polygon(in, n, kept);
        for (int k = 0; k < n; k++)
            v[k] = clip_to_screen(kept[k], width, height);
    }
    return n;
}

/* One face: a decal is drawn with its o, m from its plane (its triangles lie
 * in one) and r from its corners (the largest r of its parts, the one of its
 * largest |z_w|); any other face with o = 0, exactly as lesson 06 draws it. */
static void draw_biased_face(Target *t, LessonState *state, const ScreenFace *f,
                             const DrawContext *ctx)
{
    const DepthSetup *s = &state->depth;
    const DepthBias *bias = &state->bias;
    ScreenVertex v[CLIP_MAX_OUT(CLIP_MAX_IN)];
    float o = 0;
    double m = 0, r = -1;
    int parts = f->n <= CLIP_MAX_IN ? 1 : f->n - 2;
    for (int k = 0; bias->mesh && mesh_face_in(bias->mesh, f->face, "decal") && k < parts; k++) {
        int n = face_on_screen(f, k, ctx->width, ctx->height, v);
        if (n < 3)
            continue;
        if (r < 0) {
            DepthPlane p = depth_plane(s, v);
            m = depth_slope(&p);
        }
        r = fmax(r, resolvable_difference(s, v, n));
    }
    if (r >= 0)
        o = (float)polygon_offset(bias, m, r);
    draw_triangles(t, state, f, ctx, o);
}

const Rasterizer DEPTH_BIAS_ZBUFFER = {
    .clear = clear_depth, .draw_face = draw_biased_face, .stored_to_depth = stored_to_depth,
    .clips = true,
};
