/* depth_bias.c: lesson 07, depth bias (polygon offset), step by step
 * (depth_format.h, docs/07_depth_bias.md). A decal and its base have the same
 * z_w, each stepped from its own corners and rounded on its own: either can
 * come out nearer. So every fragment of the decal moves by o toward the camera. */
#include "depth_format.h"

#include <math.h>

#include "clip.h"

/* m: the steepest slope of z_w on the screen. 1/d is affine on the screen for
 * a flat face, so z_w = a + b/d is a plane z_w = z_0 + g_x (x - x_0) + g_y (y - y_0),
 * solved from the fan triangle of largest area. m = max(|g_x|, |g_y|), as
 * OpenGL and Vulkan allow in place of sqrt(g_x^2 + g_y^2), and GPUs do. */
double depth_slope(const DepthSetup *s, const ScreenVertex *v, int n)
{
    double m = 0, largest = 0;
    double z0 = window_depth(s, v[0].d);
    for (int k = 1; k + 1 < n; k++) {
        double x1 = v[k].x - v[0].x, y1 = v[k].y - v[0].y;
        double x2 = v[k + 1].x - v[0].x, y2 = v[k + 1].y - v[0].y;
        double z1 = window_depth(s, v[k].d) - z0, z2 = window_depth(s, v[k + 1].d) - z0;
        double area = x1 * y2 - x2 * y1; /* twice the triangle's signed area */
        if (!(fabs(area) > largest))
            continue;
        largest = fabs(area);
        double gx = (z1 * y2 - z2 * y1) / area;
        double gy = (x1 * z2 - x2 * z1) / area;
        m = fmax(fabs(gx), fabs(gy));
    }
    return m;
}

/* r: the smallest difference of z_w the format resolves on this face: unorm n
 * bits, one code, 1/(2^n - 1); float32, 2^(e - 23) with e the exponent of the
 * face's largest |z_w| = 1.f x 2^e (OpenGL, Vulkan, Direct3D): depth_quantum. */
double resolvable_difference(const DepthSetup *s, const ScreenVertex *v, int n)
{
    double largest = 0;
    for (int k = 0; k < n; k++)
        largest = fmax(largest, fabs(window_depth(s, v[k].d)));
    return depth_quantum(s->format, largest);
}

/* o = m FACTOR + r UNITS. A clamp other than 0 limits it as Direct3D's
 * DepthBiasClamp and Vulkan's depthBiasClamp do: to at most the clamp when
 * it is positive, to at least the clamp when it is negative. */
double polygon_offset(const DepthBias *bias, double m, double r)
{
    double o = m * bias->factor + r * bias->units;
    return bias->clamp > 0 ? fmin(o, bias->clamp) : bias->clamp < 0 ? fmax(o, bias->clamp) : o;
}

/* The face as the GPU sets it up: clipped at near and far (clip.c) and divided
 * onto the screen (none for a face made on the screen or of over CLIP_MAX_IN corners). */
static int face_on_screen(const Target *t, const ScreenFace *f, ScreenVertex *v)
{
    Vec4 kept[CLIP_MAX_OUT(CLIP_MAX_IN)];
    int n = f->clip && f->n <= CLIP_MAX_IN ? clip_polygon(f->clip, f->n, kept) : 0;
    for (int k = 0; k < n; k++)
        v[k] = clip_to_screen(kept[k], t->width, t->height);
    return n;
}

/* One face: a decal is drawn with its o, every other face with o = 0,
 * exactly as lesson 06 draws it. */
void draw_biased_face(Target *t, const ScreenFace *f, const DrawContext *ctx)
{
    DepthSetup *s = t->depth_setup;
    ScreenVertex v[CLIP_MAX_OUT(CLIP_MAX_IN)];
    int n;
    if (s->bias.mesh && mesh_face_in(s->bias.mesh, f->face, "decal") &&
        (n = face_on_screen(t, f, v)) >= 3)
        s->offset = polygon_offset(&s->bias, depth_slope(s, v, n), resolvable_difference(s, v, n));
    draw_clipped_face(t, f, ctx);
    s->offset = 0;
}
