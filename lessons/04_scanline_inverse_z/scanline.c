/* scanline.c: lesson 04's z-buffer, step by step (docs/04_scanline_inverse_z.md). */
#include "scanline.h"

#include <math.h>

#include "intmath.h"
#include "polygon.h"

#define S ((int64_t)SUBPIXEL_ONE) /* sub-pixel units per pixel */
#define HALF_PIXEL ((int64_t)SUBPIXEL_HALF)
#define POLYGON_MAX_CORNERS 256 /* snapped on the stack; more: drawn as triangles */

/* A polygon corner as the rasterizer uses it: snapped, with its 1/d. */
typedef struct {
    int64_t x, y; /* sub-pixel units */
    double inv_d; /* "projection stores 1/d" */
} Corner;

/* One side of the polygon: its edges from the top corner to the bottom one,
 * going round it in direction dir (+1 or -1). */
typedef struct { const Corner *c; int n, at, bottom, dir; } Chain;

/* The first row whose centre y + 0.5 is at or below y (sub-pixel units). */
static int64_t first_row_at_or_below(int64_t y) { return ceil_div(y - HALF_PIXEL, S); }

/* A screen coordinate rounded to the nearest 1/256 of a pixel, exactly as
 * lesson 03 rounds it: from here on coverage is decided in integers. */
static int64_t snap(double pixels) { return (int64_t)floor(pixels * S + 0.5); }

/* Sets up the edge from a to b (sub-pixel units, a above b) at row y_first:
 * where it crosses that row's centre, its 1/d there, and their steps per
 * scanline. False when it crosses no row centre at or after y_first. */
bool edge_setup(Edge *e, int64_t ax, int64_t ay, double inv_a, int64_t bx, int64_t by,
                double inv_b, int y_first)
{
    /* SOLUTION BEGIN: fill in every field of Edge (scanline.h) for the
     * first row at or below both a and y_first. */
    int64_t dx = bx - ax, dy = by - ay;
    if (dy <= 0)
        return false; /* a horizontal edge crosses no row centre */
    int64_t y0 = first_row_at_or_below(ay);
    if (y0 < y_first)
        y0 = y_first; /* start at the first row asked for, not above it */
    e->y_end = (int)first_row_at_or_below(by);
    if (y0 >= e->y_end)
        return false;

    /* Where the edge crosses the centre yc of row y0, minus half a pixel:
     *     x_edge - 0.5 = num / den   (pixels),
     *     num = (ax - 0.5) * dy + (yc - ay) * dx,   den = S * dy   (sub-pixel units).
     * The first pixel centre at or right of x_edge is ceil(num / den), and it
     * lies rem / den to the right of the edge. */
    int64_t yc = y0 * S + HALF_PIXEL;
    int64_t num = (ax - HALF_PIXEL) * dy + (yc - ay) * dx;
    e->den = S * dy;
    e->x_pixel = ceil_div(num, e->den);
    e->rem = e->x_pixel * e->den - num;
    /* One row down, num grows by S * dx = step_pixel * den + step_rem. */
    e->step_pixel = floor_div(dx, dy);
    e->step_rem = S * dx - e->step_pixel * e->den;

    /* 1/d is linear along the edge on the screen: d(1/d)/dy is a constant. */
    double dy_pixels = (double)dy / S;
    e->inv_d_step = (inv_b - inv_a) / dy_pixels;
    e->inv_d = inv_a + ((double)(yc - ay) / S) * e->inv_d_step;
    return true;
    /* SOLUTION STUB
    (void)e; (void)ax; (void)ay; (void)inv_a; (void)bx; (void)by; (void)inv_b; (void)y_first;
    return false;
    */
    /* SOLUTION END */
}

/* One scanline down: one addition for x (plus a carry), one for 1/d. */
void edge_step(Edge *e)
{
    /* SOLUTION BEGIN: x and 1/d one row further down the edge. */
    e->x_pixel += e->step_pixel;
    e->rem -= e->step_rem;
    if (e->rem < 0) { /* the fraction ran out: the edge moved one pixel more */
        e->rem += e->den;
        e->x_pixel++;
    }
    e->inv_d += e->inv_d_step;
    /* SOLUTION STUB
    (void)e;
    */
    /* SOLUTION END */
}

/* Fills row y: the pixels whose centre x + 0.5 is in [left, right), on the
 * screen. 1/d starts at the first pixel centre and steps by a constant per
 * pixel; a fragment beyond the far plane (1/d < inv_far) is not tested. */
void draw_span(const Primitive *p, int y, const Edge *left, const Edge *right, double inv_far)
{
    /* SOLUTION BEGIN: the span, one addition of 1/d per pixel. */
    int64_t x_first = left->x_pixel < 0 ? 0 : left->x_pixel;
    int64_t x_stop = right->x_pixel > p->target->width ? p->target->width : right->x_pixel;
    if (x_first >= x_stop)
        return;

    /* x_right - x_left, from the exact edge positions (no large numbers cancel). */
    double left_frac = (double)left->rem / (double)left->den;
    double right_frac = (double)right->rem / (double)right->den;
    double width = (double)(right->x_pixel - left->x_pixel) + left_frac - right_frac;
    /* d(1/d)/dx: constant along the span. */
    double step = width > 0 ? (right->inv_d - left->inv_d) / width : 0.0;
    /* 1/d at the first pixel centre, (x_first + 0.5) - x_left to the right of the edge. */
    double inv_d = left->inv_d + ((double)(x_first - left->x_pixel) + left_frac) * step;

    for (int64_t x = x_first; x < x_stop; x++) {
        if (inv_d >= inv_far) /* d <= far: a fragment beyond the far plane is discarded */
            fragment(p, (int)x, y, (float)inv_d);
        inv_d += step; /* one addition per pixel */
    }
    /* SOLUTION STUB
    (void)p; (void)y; (void)left; (void)right; (void)inv_far;
    */
    /* SOLUTION END */
}

/* Sets up the next edge of the chain that crosses rows at or after y. */
static bool chain_next_edge(Chain *c, int y, Edge *e)
{
    while (c->at != c->bottom) {
        int next = (c->at + c->dir + c->n) % c->n;
        Corner a = c->c[c->at], b = c->c[next];
        c->at = next;
        if (edge_setup(e, a.x, a.y, a.inv_d, b.x, b.y, b.inv_d, y))
            return true;
    }
    return false;
}

/* Rows y_first .. y_stop - 1, top to bottom, one span each from the left edge
 * to the right; at a corner the side's next edge takes over, set up afresh. */
static void walk_edges(const Primitive *p, Chain *left_chain, Chain *right_chain, int y_first,
                       int y_stop, double inv_far)
{
    Edge left, right;
    if (!chain_next_edge(left_chain, y_first, &left) ||
        !chain_next_edge(right_chain, y_first, &right))
        return;
    for (int y = y_first; y < y_stop; y++) {
        if (y >= left.y_end && !chain_next_edge(left_chain, y, &left))
            return;
        if (y >= right.y_end && !chain_next_edge(right_chain, y, &right))
            return;
        draw_span(p, y, &left, &right, inv_far);
        edge_step(&left);
        edge_step(&right);
    }
}

/* Snapping moves a corner by up to 1/512 pixel; its 1/d moves along the plane
 * through the exact corners, as a GPU's depth follows them. The plane's normal
 * in (x, y, 1/d), (nx, ny, nz), sums the cross products a x b over the fan of
 * triangles (v0, vi, vi+1). A sliver's steep plane is not used. */
static void corners_on_plane(Corner *c, const ScreenVertex *v, int n)
{
    double w0 = c[0].inv_d, nx = 0, ny = 0, nz = 0;
    for (int i = 1; i + 1 < n; i++) {
        double ax = v[i].x - v[0].x, ay = v[i].y - v[0].y, aw = c[i].inv_d - w0;
        double bx = v[i + 1].x - v[0].x, by = v[i + 1].y - v[0].y, bw = c[i + 1].inv_d - w0;
        nx += ay * bw - aw * by;
        ny += aw * bx - ax * bw;
        nz += ax * by - ay * bx;
    }
    for (int i = 0; nz != 0 && i < n; i++) { /* 1/d changes by -(nx dx + ny dy) / nz */
        double dx = (double)c[i].x / S - v[i].x, dy = (double)c[i].y / S - v[i].y;
        double change = -(nx * dx + ny * dy) / nz;
        if (fabs(change) < c[i].inv_d)
            c[i].inv_d += change;
    }
}

static bool corner_in_range(const ScreenVertex *v)
{
    return isfinite(v->x) && isfinite(v->y) && isfinite(v->d) && v->d > 0 &&
           fabs(v->x) <= SCANLINE_MAX_COORD && fabs(v->y) <= SCANLINE_MAX_COORD;
}

/* A convex polygon, either winding, drawn whole. False, drawing nothing (its triangles
 * are drawn instead): not convex once snapped, a corner out of range, too many corners. */
bool draw_polygon(const Primitive *p, const ScreenVertex *v, int n, double far)
{
    if (n < 3 || n > POLYGON_MAX_CORNERS)
        return n < 3; /* fewer: nothing to draw; more: drawn as triangles */
    Corner c[POLYGON_MAX_CORNERS];
    for (int i = 0; i < n; i++) {
        if (!corner_in_range(&v[i]))
            return false;
        /* Snapped once: everything below works on c; between corners 1/d is stepped. */
        c[i] = (Corner){snap(v[i].x), snap(v[i].y), 1.0 / v[i].d};
    }
    int turn; /* > 0: clockwise on the screen (y down) */
    if (!convex_on_screen(v, n, SUBPIXEL_ONE, &turn))
        return false;
    corners_on_plane(c, v, n);

    int top = 0, bottom = 0;
    for (int i = 1; i < n; i++) {
        if (c[i].y < c[top].y)
            top = i;
        if (c[i].y > c[bottom].y)
            bottom = i;
    }
    /* Going forward from the top corner of a clockwise polygon (on a y-down
     * screen) runs down its right side; going backward runs down its left. */
    Chain forward = {c, n, top, bottom, +1}, backward = {c, n, top, bottom, -1};
    Chain *left = turn > 0 ? &backward : &forward;
    Chain *right = turn > 0 ? &forward : &backward;

    /* Only rows on the screen are walked, whatever the polygon's size. */
    int64_t y_first = first_row_at_or_below(c[top].y);
    int64_t y_stop = first_row_at_or_below(c[bottom].y);
    y_first = y_first < 0 ? 0 : y_first;
    y_stop = y_stop > p->target->height ? p->target->height : y_stop;
    if (y_first < y_stop)
        walk_edges(p, left, right, (int)y_first, (int)y_stop, 1.0 / far);
    return true;
}

/* One face: a convex face as one polygon, any other as its triangles (polygon.h). */
void draw_face(Target *t, LessonState *s, const ScreenFace *f, const DrawContext *ctx)
{
    Primitive p = {.target = t, .state = s, .face = f->face};
    draw_face_as_polygons(&p, f, ctx, draw_polygon);
}
