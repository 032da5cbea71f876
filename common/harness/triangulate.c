/* triangulate.c: polygon_normal and triangulate_polygon of mesh.h.
 *
 * Ear clipping. An "ear" of a polygon is a corner b whose triangle (a, b, c)
 * with its two neighbours lies inside the polygon: b turns the way the polygon
 * winds, and no other corner lies in that triangle. Cutting an ear off leaves a
 * polygon with one corner fewer, and every simple polygon with more than three
 * corners has an ear (Meisters' two-ears theorem), so n - 3 cuts and the last
 * triangle give the n - 2 triangles.
 *
 * The tests are done in 2-D, in the polygon's own plane: it is projected onto
 * the coordinate plane most nearly parallel to it (dropping the largest
 * component of Newell's normal), mirrored if need be so that it winds
 * counter-clockwise there. Triangles keep the polygon's corner order, so they
 * wind the same way as the polygon did in 3-D. */
#include "mesh_build.h"

#include <math.h>
#include <stdlib.h>

/* Scratch space for up to this many corners lives on the stack. */
#define SMALL_POLYGON 32
/* A turn smaller than this, relative to the lengths of its two edges, counts as
 * no turn when deciding convexity: collinear corners written with rounding. */
#define CONVEX_TOLERANCE 1e-12
/* Ear clipping costs about (corners) x (corners that turn right) x (tries per
 * ear) steps. A polygon gets EAR_WORK_FACTOR n^2 of them: real polygons need
 * far fewer (a 4096-corner spiral, about 4 n^2); a hostile one, built so
 * that ears are rare, runs out, and what is left of it becomes a fan. So no
 * face, however hostile, takes more than about a second. */
#define EAR_WORK_FACTOR 8

typedef struct { double u, v; } Point2;

/* Newell's method: the sum over the edges of a polygon's projected areas.
 * Computed relative to the first corner, so that a polygon far from the origin
 * keeps its precision. */
Vec3 polygon_normal(const Vec3 *pts, int n)
{
    Vec3 nrm = {0.0, 0.0, 0.0};
    if (n < 3)
        return nrm;
    for (int i = 0; i < n; i++) {
        Vec3 a = vec3_sub(pts[i], pts[0]);
        Vec3 b = vec3_sub(pts[(i + 1) % n], pts[0]);
        nrm.x += (a.y - b.y) * (a.z + b.z);
        nrm.y += (a.z - b.z) * (a.x + b.x);
        nrm.z += (a.x - b.x) * (a.y + b.y);
    }
    return nrm;
}

/* Projects the polygon onto the coordinate plane that drops the largest
 * component of its normal, counter-clockwise. False for a degenerate polygon
 * (zero or non-finite normal). */
static bool project_to_own_plane(const Vec3 *pts, int n, Point2 *out)
{
    Vec3 nrm = polygon_normal(pts, n);
    double ax = fabs(nrm.x), ay = fabs(nrm.y), az = fabs(nrm.z);
    if (!(ax > 0 || ay > 0 || az > 0) || !isfinite(ax + ay + az))
        return false;
    /* Keeping the two other axes in cyclic order (y z, z x, x y) makes the
     * projected signed area have the sign of the dropped normal component. */
    int drop = (ax >= ay && ax >= az) ? 0 : (ay >= az ? 1 : 2);
    double sign = (drop == 0 ? nrm.x : drop == 1 ? nrm.y : nrm.z) > 0 ? 1.0 : -1.0;
    for (int i = 0; i < n; i++) {
        Vec3 p = vec3_sub(pts[i], pts[0]);
        Point2 q = drop == 0 ? (Point2){p.y, p.z} : drop == 1 ? (Point2){p.z, p.x}
                                                              : (Point2){p.x, p.y};
        q.u *= sign; /* mirroring makes a clockwise outline counter-clockwise */
        out[i] = q;
    }
    return true;
}

/* Twice the signed area of triangle (a, b, c): > 0 when b turns left. */
static double turn(Point2 a, Point2 b, Point2 c)
{
    return (b.u - a.u) * (c.v - b.v) - (b.v - a.v) * (c.u - b.u);
}

static bool same_point(Point2 a, Point2 b)
{
    return a.u == b.u && a.v == b.v;
}

/* Inside or on the border of the counter-clockwise triangle (a, b, c). */
static bool in_triangle(Point2 p, Point2 a, Point2 b, Point2 c)
{
    return turn(a, b, p) >= 0 && turn(b, c, p) >= 0 && turn(c, a, p) >= 0;
}

static Point2 edge(const Point2 *p, int n, int i)
{
    Point2 e = {p[(i + 1) % n].u - p[i].u, p[(i + 1) % n].v - p[i].v};
    return e;
}

/* Convex: every turn goes left (a turn of zero, between collinear edges, is
 * ignored, as are repeated corners), and the outline goes round only once
 * (a pentagram turns left at every corner but winds twice). */
static bool is_convex(const Point2 *p, int n)
{
    int first = 0; /* edges of zero length (repeated corners) are skipped */
    while (first < n && edge(p, n, first).u == 0 && edge(p, n, first).v == 0)
        first++;
    if (first == n)
        return false;
    double total = 0.0; /* the angles turned, summed: 2 pi once round */
    Point2 f = edge(p, n, first);
    for (int k = 1; k <= n; k++) { /* k = n comes back to the first edge */
        Point2 e = edge(p, n, (first + k) % n);
        if (e.u == 0 && e.v == 0)
            continue;
        double cross = f.u * e.v - f.v * e.u;
        double dot = f.u * e.u + f.v * e.v;
        double scale = hypot(f.u, f.v) * hypot(e.u, e.v);
        if (cross < -CONVEX_TOLERANCE * scale)
            return false; /* a right turn */
        if (fabs(cross) <= CONVEX_TOLERANCE * scale && dot < 0)
            return false; /* the outline doubles back on itself */
        total += atan2(cross, dot);
        f = e;
    }
    /* Once round is 2 pi; twice round (or more) is at least 4 pi. */
    return total < 3 * PI;
}

static void fan(int first, const int *next, int remaining, Tri *out)
{
    int b = next[first];
    for (int k = 0; k < remaining - 2; k++) {
        out[k] = (Tri){{first, b, next[b]}};
        b = next[b];
    }
}

/* The state of ear clipping: the corners left, as a ring (prev, next), and
 * the list of corners that do not turn left. Only those can lie inside an
 * ear's triangle (if a triangle holds any corner, it holds one of them), so
 * only they are tested. Cutting an ear only ever straightens its neighbours,
 * so the list mostly shrinks; a corner that turned convex or was cut is
 * dropped from it when next met. */
typedef struct {
    const Point2 *p;
    int *prev, *next;
    int *waiting, nwaiting; /* corners that may lie in an ear */
    int *listed;            /* listed[i]: i is in waiting */
    bool *cut;              /* cut[i]: corner i is gone */
    long work_left;         /* corners looked at before the fan takes over */
} Clipper;

static double turn_at(const Clipper *k, int b)
{
    return turn(k->p[k->prev[b]], k->p[b], k->p[k->next[b]]);
}

static void list_if_waiting(Clipper *k, int i)
{
    if (!k->listed[i] && !(turn_at(k, i) > 0)) {
        k->listed[i] = 1;
        k->waiting[k->nwaiting++] = i;
    }
}

/* Corner b is an ear when it turns left and no corner that could be in the
 * way lies in its triangle. A corner with no turn at all is always cut: its
 * triangle has no area, and cutting it leaves the outline covering the same
 * region. */
static bool is_ear(Clipper *k, int b)
{
    const Point2 *p = k->p;
    int a = k->prev[b], c = k->next[b];
    double t = turn(p[a], p[b], p[c]);
    if (t == 0)
        return true;
    if (!(t > 0))
        return false;
    double lo_u = fmin(p[a].u, fmin(p[b].u, p[c].u)), hi_u = fmax(p[a].u, fmax(p[b].u, p[c].u));
    double lo_v = fmin(p[a].v, fmin(p[b].v, p[c].v)), hi_v = fmax(p[a].v, fmax(p[b].v, p[c].v));
    for (int w = 0; w < k->nwaiting; w++) {
        int q = k->waiting[w];
        k->work_left--;
        if (!k->cut[q] && (p[q].u < lo_u || p[q].u > hi_u || p[q].v < lo_v || p[q].v > hi_v))
            continue; /* outside the triangle's bounding box: the quick test */
        if (k->cut[q] || turn_at(k, q) > 0) { /* no longer in the way: drop it */
            k->listed[q] = 0;
            k->waiting[w--] = k->waiting[--k->nwaiting];
            continue;
        }
        if (q == a || q == c || same_point(p[q], p[a]) || same_point(p[q], p[b]) ||
            same_point(p[q], p[c]))
            continue; /* a corner of the ear, or the outline touching itself there */
        if (in_triangle(p[q], p[a], p[b], p[c]))
            return false;
    }
    return true;
}

static void clip_ears(Clipper *k, int n, Tri *out)
{
    for (int i = 0; i < n; i++) {
        k->prev[i] = (i + n - 1) % n;
        k->next[i] = (i + 1) % n;
        k->listed[i] = 0;
        k->cut[i] = false;
    }
    k->nwaiting = 0;
    for (int i = 0; i < n; i++)
        list_if_waiting(k, i);
    k->work_left = (long)EAR_WORK_FACTOR * n * n;
    int remaining = n, made = 0, misses = 0;
    int b = 1 % n; /* starting at corner 1 makes a convex polygon a fan around 0 */
    while (remaining > 3 && k->work_left > 0) {
        if (is_ear(k, b)) {
            int a = k->prev[b], c = k->next[b];
            out[made++] = (Tri){{a, b, c}};
            k->next[a] = c; /* cut the ear off */
            k->prev[c] = a;
            k->cut[b] = true;
            remaining--;
            misses = 0;
            list_if_waiting(k, a); /* only the neighbours' turns changed */
            list_if_waiting(k, c);
            b = c;
        } else {
            b = k->next[b];
            if (++misses >= remaining)
                break; /* once round without an ear: not a simple polygon */
        }
    }
    /* The last triangle, or a fan of whatever a broken outline left over. */
    fan(k->prev[b], k->next, remaining, out + made);
}

int triangulate_polygon(const Vec3 *pts, int n, Tri *out, bool *convex)
{
    *convex = false;
    if (n < 3)
        return 0;
    /* Scratch: n points and 4 n ints, on the stack for a small polygon. */
    Point2 small_p[SMALL_POLYGON];
    int small_ints[4 * SMALL_POLYGON];
    bool small_cut[SMALL_POLYGON];
    bool small = n <= SMALL_POLYGON;
    Point2 *p = small ? small_p : malloc(sizeof *p * (size_t)n);
    int *ints = small ? small_ints : malloc(sizeof *ints * 4 * (size_t)n);
    bool *cut = small ? small_cut : malloc(sizeof *cut * (size_t)n);
    if (!p || !ints || !cut || !project_to_own_plane(pts, n, p)) {
        /* Degenerate (a line or a point) or no memory: a fan loses no face. */
        for (int i = 0; i < n - 2; i++)
            out[i] = (Tri){{0, i + 1, i + 2}};
    } else {
        *convex = is_convex(p, n);
        Clipper k = {.p = p, .prev = ints, .next = ints + n, .waiting = ints + 2 * n,
                     .nwaiting = 0, .listed = ints + 3 * n, .cut = cut, .work_left = 0};
        clip_ears(&k, n, out);
    }
    if (!small) {
        free(p);
        free(ints);
        free(cut);
    }
    return n - 2;
}
