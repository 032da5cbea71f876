/* guard_band.c: see guard_band.h. */
#include "guard_band.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* A small polygon is clipped in buffers on the stack; a bigger one (lesson 04
 * draws whole faces, up to MESH_MAX_FACE_VERTICES corners) gets them from malloc. */
#define SMALL_POLYGON 16

/* One side of the band: the points p with sign * p.axis <= limit are inside. */
typedef struct {
    bool along_y; /* false: a vertical line x = limit; true: a horizontal line y = limit */
    double sign;  /* +1: keep what lies below limit, -1: keep what lies above it */
    double limit;
} BandSide;

static double coordinate(ScreenVertex v, bool along_y)
{
    return along_y ? v.y : v.x;
}

static bool inside(ScreenVertex v, BandSide s)
{
    return s.sign * coordinate(v, s.along_y) <= s.sign * s.limit;
}

bool guard_band_contains(const ScreenVertex *v, int n, int width, int height)
{
    for (int i = 0; i < n; i++)
        if (!(v[i].x >= -GUARD_BAND && v[i].x <= width + (double)GUARD_BAND &&
              v[i].y >= -GUARD_BAND && v[i].y <= height + (double)GUARD_BAND))
            return false;
    return true;
}

/* a + (b - a) t, with halved operands so that b - a cannot overflow even for
 * coordinates near the largest double. With b that far and t near 1, the
 * result itself may pass the largest double: it is held there, a number the
 * next side can still cut (an infinity would make it NaN). */
static double lerp_from(double a, double b, double t)
{
    double p = a + ((b / 2 - a / 2) * t) * 2;
    return fmax(-DBL_MAX, fmin(DBL_MAX, p));
}

/* The point where the edge from the inside corner a to the outside corner b
 * crosses the side. Stepping from the inside corner, a + (b - a) t rather than
 * a (1 - t) + b t, keeps the point exact when b is enormous and t tiny (with b
 * at 1e30, 1 - t rounds to 1 and a would be lost), and gives two faces that
 * share the edge exactly the same point whichever way each walks it. The
 * crossing coordinate is set to the limit exactly. */
static ScreenVertex crossing(ScreenVertex a, ScreenVertex b, BandSide s, DepthLinearity linear)
{
    double ca = coordinate(a, s.along_y) / 2, cb = coordinate(b, s.along_y) / 2;
    double t = (s.limit / 2 - ca) / (cb - ca);
    ScreenVertex p;
    if (s.along_y) {
        p.x = lerp_from(a.x, b.x, t);
        p.y = s.limit;
    } else {
        p.x = s.limit;
        p.y = lerp_from(a.y, b.y, t);
    }
    if (linear == LINEAR_D)
        p.d = lerp_from(a.d, b.d, t);                  /* d linear on the screen */
    else
        p.d = 1 / lerp_from(1 / a.d, 1 / b.d, t);      /* 1/d linear on the screen */
    return p;
}

/* Sutherland-Hodgman, one side: keep the inside part of polygon in[0..n-1].
 * A convex polygon gains at most one corner per side, and out has room for
 * that only. Returns -1 if this one would gain more: rounding has folded it
 * (a double cannot place the cut of an edge whose two ends both lie beyond
 * 2^53 pixels), and no picture of it would be right. */
static int clip_side(const ScreenVertex *in, int n, BandSide s, DepthLinearity linear,
                     ScreenVertex *out)
{
    int m = 0, most = n + 1;
    for (int i = 0; i < n; i++) {
        ScreenVertex a = in[i], b = in[(i + 1) % n];
        bool a_in = inside(a, s), b_in = inside(b, s);
        int adds = a_in + (a_in != b_in);
        if (m + adds > most)
            return -1;
        if (a_in)
            out[m++] = a;
        if (a_in && !b_in)
            out[m++] = crossing(a, b, s, linear); /* leaving: from a, inside */
        else if (!a_in && b_in)
            out[m++] = crossing(b, a, s, linear); /* entering: from b, inside */
    }
    return m;
}

int guard_band_clip(const ScreenVertex *in, int n, int width, int height,
                    DepthLinearity linear, ScreenVertex *out)
{
    if (n < 3)
        return 0;
    /* A corner that is not a number has no place on the screen: no picture of
     * the face can be right, so none is drawn. */
    for (int i = 0; i < n; i++)
        if (!isfinite(in[i].x) || !isfinite(in[i].y) || !isfinite(in[i].d))
            return 0;
    if (guard_band_contains(in, n, width, height)) {
        memcpy(out, in, (size_t)n * sizeof *in);
        return n;
    }
    const BandSide sides[4] = {
        /* left:   x >= -GUARD_BAND */
        {.along_y = false, .sign = -1, .limit = -GUARD_BAND},
        /* right:  x <= W + GUARD_BAND */
        {.along_y = false, .sign = +1, .limit = width + (double)GUARD_BAND},
        /* top:    y >= -GUARD_BAND */
        {.along_y = true, .sign = -1, .limit = -GUARD_BAND},
        /* bottom: y <= H + GUARD_BAND */
        {.along_y = true, .sign = +1, .limit = height + (double)GUARD_BAND},
    };
    ScreenVertex small[GUARD_BAND_MAX_OUT(SMALL_POLYGON)];
    ScreenVertex *scratch = small;
    if (GUARD_BAND_MAX_OUT(n) > GUARD_BAND_MAX_OUT(SMALL_POLYGON)) {
        scratch = malloc((size_t)GUARD_BAND_MAX_OUT(n) * sizeof *scratch);
        if (!scratch)
            return 0; /* out of memory: the polygon is not drawn rather than drawn wrong */
    }
    /* Ping-pong between scratch and out so that the last side writes into out. */
    int m = clip_side(in, n, sides[0], linear, scratch);
    if (m >= 0)
        m = clip_side(scratch, m, sides[1], linear, out);
    if (m >= 0)
        m = clip_side(out, m, sides[2], linear, scratch);
    if (m >= 0)
        m = clip_side(scratch, m, sides[3], linear, out);
    if (scratch != small)
        free(scratch);
    return m >= 3 ? m : 0;
}
