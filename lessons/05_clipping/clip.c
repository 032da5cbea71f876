/* clip.c: lesson 05's clipping, step by step (clip.h, and docs/05_clipping.md). */
#include "clip.h"

#include "polygon.h"
#include "scanline.h"

/* How far p lies inside the plane: 0 on it, negative outside; linear in clip space. */
double plane_distance(Vec4 p, ClipPlane plane)
{
    /* SOLUTION BEGIN: a signed distance to the plane: 0 on it, positive on
     * the side the plane keeps (the clip-space inequality of each plane is
     * on the lesson's page), and linear in clip space, so that
     * plane_crossing can find where it reaches 0. */
    return plane == NEAR_PLANE ? p.z + p.w : p.w - p.z;
    /* SOLUTION STUB
    (void)p; (void)plane;
    return 1.0;
    */
    /* SOLUTION END */
}

/* Where the edge from in (d_in > 0) to out (d_out < 0) meets the plane; always
 * from the inside corner, so two faces sharing the edge get the same point. */
Vec4 plane_crossing(Vec4 in, double d_in, Vec4 out, double d_out)
{
    /* SOLUTION BEGIN: the fraction of the way from in to out where the
     * distance reaches 0, and every coordinate blended by it. */
    double s = d_in / (d_in - d_out);
    return vec4(in.x + s * (out.x - in.x), in.y + s * (out.y - in.y),
                in.z + s * (out.z - in.z), in.w + s * (out.w - in.w));
    /* SOLUTION STUB
    (void)d_in; (void)out; (void)d_out;
    return in;
    */
    /* SOLUTION END */
}

/* Sutherland-Hodgman against one plane: walk the edges a -> b; keep every
 * corner inside or on the plane, and add a corner where an edge crosses it.
 * Returns how many corners out holds (fewer than 3: nothing is left). */
int clip_to_plane(const Vec4 *in, int n, ClipPlane plane, Vec4 *out)
{
    int m = 0;
    /* SOLUTION BEGIN: each edge in turn: its crossing (if it crosses),
     * then its end corner (if inside or on the plane). */
    for (int i = 0; i < n; i++) {
        Vec4 a = in[(i + n - 1) % n], b = in[i];
        double da = plane_distance(a, plane), db = plane_distance(b, plane);
        if (da > 0 && db < 0)
            out[m++] = plane_crossing(a, da, b, db); /* going out */
        else if (da < 0 && db > 0)
            out[m++] = plane_crossing(b, db, a, da); /* coming in */
        if (db >= 0)
            out[m++] = b;
    }
    /* SOLUTION STUB
    (void)in; (void)n; (void)plane; (void)out;
    */
    /* SOLUTION END */
    return m;
}

/* The near plane, then the far plane. out holds CLIP_MAX_OUT(n) corners. */
int clip_polygon(const Vec4 *in, int n, Vec4 *out)
{
    Vec4 kept[CLIP_MAX_OUT(CLIP_MAX_IN) / 2];
    return clip_to_plane(kept, clip_to_plane(in, n, NEAR_PLANE, kept), FAR_PLANE, out);
}

/* The divide by w_c and the viewport, as camera_project does them: a corner
 * no plane moved lands exactly where lesson 04 puts it. */
ScreenVertex clip_to_screen(Vec4 c, int width, int height)
{
    /* SOLUTION BEGIN: NDC from the divide, then pixels (y down); d is w_c. */
    double x_ndc = c.x / c.w, y_ndc = c.y / c.w;
    return (ScreenVertex){(x_ndc + 1) * width / 2, (1 - y_ndc) * height / 2, c.w};
    /* SOLUTION STUB
    (void)c; (void)width; (void)height;
    return (ScreenVertex){0, 0, 0};
    */
    /* SOLUTION END */
}

/* A convex polygon in clip space: clipped, divided, and drawn by lesson 04. */
static void draw_clipped_polygon(const Primitive *p, const Vec4 *corners, int n,
                                 const DrawContext *ctx)
{
    Vec4 kept[CLIP_MAX_OUT(CLIP_MAX_IN)];
    ScreenVertex v[CLIP_MAX_OUT(CLIP_MAX_IN)];
    Tri fan[CLIP_MAX_OUT(CLIP_MAX_IN)];
    int m = clip_polygon(corners, n, kept);
    for (int i = 0; i < m; i++) {
        v[i] = clip_to_screen(kept[i], ctx->width, ctx->height);
        fan[i] = (Tri){{0, i + 1, i + 2}};
    }
    ScreenFace f = {.face = p->face, .n = m, .v = v, .tris = fan, .convex = true};
    if (m >= 3)
        draw_face_as_polygons(p, &f, ctx, draw_polygon);
}

/* One face: as lesson 04 draws it when no plane cuts it (or it was made on
 * the screen); otherwise clipped whole if convex, else triangle by triangle. */
void draw_clipped_face(const Primitive *p, const ScreenFace *f, const DrawContext *ctx)
{
    bool cut = false;
    for (int i = 0; f->clip && i < f->n; i++)
        cut = cut || !(plane_distance(f->clip[i], NEAR_PLANE) >= 0 &&
                       plane_distance(f->clip[i], FAR_PLANE) >= 0);
    if (!cut)
        draw_face_as_polygons(p, f, ctx, draw_polygon);
    else if (f->convex && f->n <= CLIP_MAX_IN)
        draw_clipped_polygon(p, f->clip, f->n, ctx);
    else
        for (int k = 0; k < f->n - 2; k++) {
            const int *c = f->tris[k].c;
            Vec4 tri[3] = {f->clip[c[0]], f->clip[c[1]], f->clip[c[2]]};
            draw_clipped_polygon(p, tri, 3, ctx);
        }
}
