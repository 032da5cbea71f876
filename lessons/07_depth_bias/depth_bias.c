/* depth_bias.c: lesson 07, depth bias (polygon offset), step by step
 * (depth_format.h, docs/07_depth_bias.md). A decal and its base have the same
 * z_w on paper, but each triangle's plane is set up from its own corners and
 * rounded on its own (lesson 06): either can come out nearer. So every
 * fragment of the decal moves by o toward the camera. */
#include "depth_format.h"

#include <math.h>


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

/* A triangle's o: m FACTOR + r UNITS on a face in `decal`, 0 on any other,
 * which is then drawn exactly as lesson 06 draws it. Its corners v[0 .. n-1]
 * are on the screen, clipped as the plane was set up (depth_buffer.c). */
float triangle_offset(const DepthSetup *s, int face, const ScreenVertex *v, int n)
{
    if (!s->bias.mesh || !mesh_face_in(s->bias.mesh, face, "decal") || n < 3)
        return 0.0f;
    return (float)polygon_offset(&s->bias, depth_slope(&s->plane),
                                 resolvable_difference(s, v, n));
}
