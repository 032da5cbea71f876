/* scene.c: the built-in scenes and the cameras that frame them.
 *
 * Every scene is built from quads and triangles in a fixed order: a face's
 * position in its build function is its index (--shade id, --trace). Faces
 * wind counter-clockwise seen from outside (or from the camera, for the flat
 * pieces), though the lessons draw both windings. Every vertex of every scene
 * but inside lies in front of its camera's near plane, since lessons 02 to
 * 04 drop a triangle with a corner behind it rather than clip it; inside is
 * lesson 05's: its camera stands in a room, and much of the room reaches
 * behind it. The scenes of lessons 07 to 09 (decals, crowd, city) are built in
 * scene_later.c. */
#include "scene.h"
#include "scene_parts.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "ladder.h"

/* ---- Building blocks ---------------------------------------------------- */

static int material(Mesh *m, const char *name, double r, double g, double b, Error *err)
{
    return mesh_add_material(m, name, vec3(r, g, b), err);
}

/* The vertices p[0 .. n-1], then one face through them in that order. */
bool add_polygon(Mesh *m, const Vec3 *p, int n, int mat, Error *err)
{
    int idx[4];
    for (int i = 0; i < n; i++)
        if ((idx[i] = mesh_add_vertex(m, p[i], err)) < 0)
            return false;
    return mesh_add_face(m, idx, n, mat, err) >= 0;
}

bool add_quad(Mesh *m, Vec3 a, Vec3 b, Vec3 c, Vec3 d, int mat, Error *err)
{
    Vec3 p[4] = {a, b, c, d};
    return add_polygon(m, p, 4, mat, err);
}

/* A box: its 8 corners centre + axes[0] * +-1 + axes[1] * +-1 + axes[2] * +-1
 * (axes: half-edges, right-handed), and its 6 faces wound outwards, in the
 * order -x +x -y +y -z +z of its own axes. */
bool add_box(Mesh *m, Vec3 centre, const Vec3 axes[3], int mat, Error *err)
{
    int v[8]; /* v[i]: bit 0 says +x, bit 1 +y, bit 2 +z */
    for (int i = 0; i < 8; i++) {
        Vec3 p = centre;
        for (int k = 0; k < 3; k++)
            p = vec3_add(p, vec3_scale(axes[k], (i >> k) & 1 ? 1.0 : -1.0));
        if ((v[i] = mesh_add_vertex(m, p, err)) < 0)
            return false;
    }
    static const int FACES[6][4] = {
        {0, 4, 6, 2}, /* -x */
        {1, 3, 7, 5}, /* +x */
        {0, 1, 5, 4}, /* -y */
        {2, 6, 7, 3}, /* +y */
        {0, 2, 3, 1}, /* -z */
        {4, 5, 7, 6}, /* +z */
    };
    for (int f = 0; f < 6; f++) {
        int idx[4] = {v[FACES[f][0]], v[FACES[f][1]], v[FACES[f][2]], v[FACES[f][3]]};
        if (mesh_add_face(m, idx, 4, mat, err) < 0)
            return false;
    }
    return true;
}

/* An axis-aligned box from its lowest corner lo to its highest hi. */
bool add_aligned_box(Mesh *m, Vec3 lo, Vec3 hi, int mat, Error *err)
{
    Vec3 axes[3] = {vec3((hi.x - lo.x) / 2, 0, 0), vec3(0, (hi.y - lo.y) / 2, 0),
                    vec3(0, 0, (hi.z - lo.z) / 2)};
    return add_box(m, vec3_scale(vec3_add(lo, hi), 0.5), axes, mat, err);
}

/* v turned by angle (radians) about the unit axis k (Rodrigues' formula). */
static Vec3 rotate(Vec3 v, Vec3 k, double angle)
{
    double c = cos(angle), s = sin(angle);
    return vec3_add(vec3_add(vec3_scale(v, c), vec3_scale(vec3_cross(k, v), s)),
                    vec3_scale(k, vec3_dot(k, v) * (1 - c)));
}

/* ---- 1. triangles3 ------------------------------------------------------ */

/* Three long triangles that overlap cyclically, so that no order of drawing
 * them back to front exists: the painter's algorithm fails, a depth buffer
 * does not. Each has a wide end near the camera (z = +1) and its tip far away
 * (z = -1), and lies along one side of a big triangle, its wide end over the
 * middle of the next one. Corners in face order, counter-clockwise seen from
 * the camera, the tip in the middle:
 *
 *   face 0, red    (-3, -2, 1)    tip (4, -1, -1)   (-3, 0, 1)
 *   face 1, green  (3, -1.5, 1)   tip (-1, 4, -1)   (1.5, -2.5, 1)
 *   face 2, blue   (0, 3.5, 1)    tip (-3, -3, -1)  (1.5, 2.5, 1)
 *
 * The camera sits at (0, 0, 10) looking down -Z, so a point's view depth is
 * d = 10 - z: 9 at the wide ends, 11 at the tips. Over the point where the
 * centre lines of red and green cross (x = 1.71, y = -1), green has d = 9.33
 * and red d = 10.35: green covers red. Likewise blue covers green, and red
 * covers blue. */
static bool build_triangles3(Mesh *m, Error *err)
{
    int red = material(m, "red", 0.85, 0.2, 0.15, err);
    int green = material(m, "green", 0.2, 0.7, 0.25, err);
    int blue = material(m, "blue", 0.2, 0.35, 0.85, err);
    if (red < 0 || green < 0 || blue < 0)
        return false;
    Vec3 r[3] = {vec3(-3, -2, 1), vec3(4, -1, -1), vec3(-3, 0, 1)};
    Vec3 g[3] = {vec3(3, -1.5, 1), vec3(-1, 4, -1), vec3(1.5, -2.5, 1)};
    Vec3 b[3] = {vec3(0, 3.5, 1), vec3(-3, -3, -1), vec3(1.5, 2.5, 1)};
    return add_polygon(m, r, 3, red, err) && add_polygon(m, g, 3, green, err) &&
           add_polygon(m, b, 3, blue, err);
}

/* ---- 2. interpenetrate -------------------------------------------------- */

/* Two cards that pass through each other, an X seen from above: card A lies
 * in the plane z = -x/2, card B in z = x/2. They cross along the y axis (x = 0,
 * z = 0), from y = -0.8 to 0.8, where no order of the two faces is right:
 * each covers the other on one side of that line. */
static bool build_interpenetrate(Mesh *m, Error *err)
{
    int orange = material(m, "orange", 0.95, 0.55, 0.15, err);
    int teal = material(m, "teal", 0.15, 0.6, 0.7, err);
    if (orange < 0 || teal < 0)
        return false;
    return add_quad(m, vec3(-1.2, -0.8, 0.6), vec3(1.2, -0.8, -0.6), vec3(1.2, 0.8, -0.6),
                    vec3(-1.2, 0.8, 0.6), orange, err) &&
           add_quad(m, vec3(-1, -1, -0.5), vec3(1, -1, 0.5), vec3(1, 1, 0.5),
                    vec3(-1, 1, -0.5), teal, err);
}

/* ---- 3. cubes ------------------------------------------------------------ */

/* A floor (y = 0, from -3 to 3 in x and z) and three cubes that cut into one
 * another and into the floor: depth decides every one of their seams. */
static bool build_cubes(Mesh *m, Error *err)
{
    int floor = material(m, "floor", 0.5, 0.5, 0.46, err);
    int red = material(m, "red", 0.85, 0.25, 0.2, err);
    int green = material(m, "green", 0.3, 0.75, 0.3, err);
    int blue = material(m, "blue", 0.25, 0.4, 0.9, err);
    if (floor < 0 || red < 0 || green < 0 || blue < 0)
        return false;
    if (!add_quad(m, vec3(-3, 0, -3), vec3(-3, 0, 3), vec3(3, 0, 3), vec3(3, 0, -3), floor, err))
        return false;
    /* Red: upright, its bottom 0.2 below the floor. */
    if (!add_aligned_box(m, vec3(-0.7, -0.2, -0.7), vec3(0.7, 1.2, 0.7), red, err))
        return false;
    /* Green: turned 30 degrees about y, pushed into red's side. */
    Vec3 x_axis = vec3(1, 0, 0), y_axis = vec3(0, 1, 0);
    double a = 30 * PI / 180;
    Vec3 green_axes[3] = {rotate(vec3(0.55, 0, 0), y_axis, a), vec3(0, 0.55, 0),
                          rotate(vec3(0, 0, 0.55), y_axis, a)};
    if (!add_box(m, vec3(1.05, 0.45, 0.2), green_axes, green, err))
        return false;
    /* Blue: tipped onto a corner (35 degrees about x, then 40 about y), stuck
     * into red's top. */
    double b = 35 * PI / 180, c = 40 * PI / 180;
    Vec3 blue_axes[3];
    Vec3 unit[3] = {vec3(0.5, 0, 0), vec3(0, 0.5, 0), vec3(0, 0, 0.5)};
    for (int k = 0; k < 3; k++)
        blue_axes[k] = rotate(rotate(unit[k], x_axis, b), y_axis, c);
    return add_box(m, vec3(-0.45, 1.2, 0.35), blue_axes, blue, err);
}

/* ---- 4. grazing ---------------------------------------------------------- */

/* Two long strips that cross at a shallow angle over a deep range of depths.
 * The camera is at the origin looking down -Z, so d = -z exactly:
 *   strip A (wide):   y = -0.5,                           x in [-1, 1],       d in [1.5, 100]
 *   strip B (narrow): y = -0.5 + GRAZE_SLOPE * (4 - d),   x in [-0.75, 0.75], d in [2, 100]
 * with GRAZE_SLOPE = 1/64. They cross along the line y = -0.5, d = 4: nearer
 * than that, B lies above A and shows; farther, B sinks below A and is hidden.
 * The two strips start at different depths (1.5 and 2), so interpolating d
 * linearly on the screen errs differently on each, and the naive rule puts
 * the seam some 55 rows too high at 800 x 600 (docs/03_perspective_z.md).
 * The numbers are chosen so that with --fovy 90 at 800 x 600 every corner
 * lands exactly on the 1/256-pixel grid the rasterizers snap to. */
#define GRAZE_SLOPE (1.0 / 64) /* about 0.9 degrees */
#define GRAZE_NEAR_A 1.5
#define GRAZE_NEAR_B 2.0
#define GRAZE_FAR 100.0
#define GRAZE_CROSS 4.0

static double strip_b_height(double d)
{
    return -0.5 + GRAZE_SLOPE * (GRAZE_CROSS - d);
}

static bool build_grazing(Mesh *m, Error *err)
{
    int a = material(m, "strip_a", 0.8, 0.45, 0.2, err);
    int b = material(m, "strip_b", 0.3, 0.55, 0.85, err);
    if (a < 0 || b < 0)
        return false;
    double na = GRAZE_NEAR_A, nb = GRAZE_NEAR_B, f = GRAZE_FAR;
    return add_quad(m, vec3(-1, -0.5, -na), vec3(1, -0.5, -na), vec3(1, -0.5, -f),
                    vec3(-1, -0.5, -f), a, err) &&
           add_quad(m, vec3(-0.75, strip_b_height(nb), -nb), vec3(0.75, strip_b_height(nb), -nb),
                    vec3(0.75, strip_b_height(f), -f), vec3(-0.75, strip_b_height(f), -f), b, err);
}

/* ---- 5. walls ------------------------------------------------------------ */

/* A corridor as 1990s engines drew it: floor, ceiling and walls cut into
 * segments, pillars along the walls, a doorway across it and an end wall.
 * It runs from z = CORRIDOR_START down to z = CORRIDOR_END, x in [-2, 2],
 * y in [0, 3]. */
#define CORRIDOR_HALF_WIDTH 2.0
#define CORRIDOR_HEIGHT 3.0
#define CORRIDOR_START (-1.0)
#define CORRIDOR_END (-41.0)
#define SEGMENT_LENGTH 4.0
#define DOOR_Z (-20.0)
#define DOOR_DEPTH 0.4
#define DOOR_HALF_WIDTH 0.7
#define DOOR_HEIGHT 2.2

typedef struct { int floor[2], ceiling, wall[2], pillar, door, end; } CorridorPalette;

static bool corridor_palette(Mesh *m, CorridorPalette *p, Error *err)
{
    p->floor[0] = material(m, "floor_dark", 0.45, 0.36, 0.28, err);
    p->floor[1] = material(m, "floor_light", 0.55, 0.45, 0.35, err);
    p->ceiling = material(m, "ceiling", 0.35, 0.35, 0.4, err);
    p->wall[0] = material(m, "wall_stone", 0.7, 0.66, 0.55, err);
    p->wall[1] = material(m, "wall_brick", 0.65, 0.35, 0.25, err);
    p->pillar = material(m, "pillar", 0.5, 0.5, 0.52, err);
    p->door = material(m, "door_frame", 0.35, 0.25, 0.15, err);
    p->end = material(m, "end_wall", 0.2, 0.45, 0.4, err);
    return p->floor[0] >= 0 && p->floor[1] >= 0 && p->ceiling >= 0 && p->wall[0] >= 0 &&
           p->wall[1] >= 0 && p->pillar >= 0 && p->door >= 0 && p->end >= 0;
}

/* One segment of floor, ceiling and both walls, from z0 down to z1 (< z0),
 * each wound to face into the corridor. */
static bool add_segment(Mesh *m, double z0, double z1, int k, const CorridorPalette *p,
                        Error *err)
{
    double w = CORRIDOR_HALF_WIDTH, h = CORRIDOR_HEIGHT;
    return add_quad(m, vec3(-w, 0, z0), vec3(w, 0, z0), vec3(w, 0, z1), vec3(-w, 0, z1),
                    p->floor[k % 2], err) &&
           add_quad(m, vec3(-w, h, z0), vec3(-w, h, z1), vec3(w, h, z1), vec3(w, h, z0),
                    p->ceiling, err) &&
           add_quad(m, vec3(-w, 0, z0), vec3(-w, 0, z1), vec3(-w, h, z1), vec3(-w, h, z0),
                    p->wall[k % 2], err) &&
           add_quad(m, vec3(w, 0, z0), vec3(w, h, z0), vec3(w, h, z1), vec3(w, 0, z1),
                    p->wall[(k + 1) % 2], err);
}

/* A wall across the corridor with a door in it, DOOR_DEPTH thick: front and
 * back faces each in three pieces (left of, right of and over the door), then
 * the two jambs and the lintel's underside. */
static bool add_doorway(Mesh *m, int mat, Error *err)
{
    double w = CORRIDOR_HALF_WIDTH, h = CORRIDOR_HEIGHT;
    double dw = DOOR_HALF_WIDTH, dh = DOOR_HEIGHT;
    /* Each piece as x0, x1, y0, y1. */
    const double pieces[3][4] = {{-w, -dw, 0, h}, {dw, w, 0, h}, {-dw, dw, dh, h}};
    for (int side = 0; side < 2; side++) {
        double z = DOOR_Z - side * DOOR_DEPTH;
        for (int k = 0; k < 3; k++) {
            const double *r = pieces[k];
            Vec3 a = vec3(r[0], r[2], z), b = vec3(r[1], r[2], z);
            Vec3 c = vec3(r[1], r[3], z), d = vec3(r[0], r[3], z);
            bool ok = side == 0 ? add_quad(m, a, b, c, d, mat, err)  /* facing +z */
                                : add_quad(m, a, d, c, b, mat, err); /* facing -z */
            if (!ok)
                return false;
        }
    }
    double z0 = DOOR_Z, z1 = DOOR_Z - DOOR_DEPTH;
    return add_quad(m, vec3(-dw, 0, z0), vec3(-dw, 0, z1), vec3(-dw, dh, z1),
                    vec3(-dw, dh, z0), mat, err) && /* left jamb, facing +x */
           add_quad(m, vec3(dw, 0, z0), vec3(dw, dh, z0), vec3(dw, dh, z1),
                    vec3(dw, 0, z1), mat, err) && /* right jamb, facing -x */
           add_quad(m, vec3(-dw, dh, z0), vec3(-dw, dh, z1), vec3(dw, dh, z1),
                    vec3(dw, dh, z0), mat, err); /* lintel, facing down */
}

static bool build_walls(Mesh *m, Error *err)
{
    CorridorPalette p;
    if (!corridor_palette(m, &p, err))
        return false;
    int segments = (int)((CORRIDOR_START - CORRIDOR_END) / SEGMENT_LENGTH);
    for (int k = 0; k < segments; k++) {
        double z0 = CORRIDOR_START - k * SEGMENT_LENGTH;
        if (!add_segment(m, z0, z0 - SEGMENT_LENGTH, k, &p, err))
            return false;
    }
    /* Pillars stand against both walls every 8 units, sunk a little into the
     * wall, floor and ceiling so that no face of theirs lies in a wall's plane. */
    for (int k = 1; k <= 4; k++) {
        double z = CORRIDOR_START - 8.0 * k + 2.0;
        for (int side = -1; side <= 1; side += 2) {
            double x_in = side * (CORRIDOR_HALF_WIDTH - 0.45);
            double x_out = side * (CORRIDOR_HALF_WIDTH + 0.05);
            Vec3 lo = vec3(fmin(x_in, x_out), -0.05, z - 0.3);
            Vec3 hi = vec3(fmax(x_in, x_out), CORRIDOR_HEIGHT + 0.05, z + 0.3);
            if (!add_aligned_box(m, lo, hi, p.pillar, err))
                return false;
        }
    }
    if (!add_doorway(m, p.door, err))
        return false;
    double w = CORRIDOR_HALF_WIDTH, h = CORRIDOR_HEIGHT, z = CORRIDOR_END;
    return add_quad(m, vec3(-w, 0, z), vec3(w, 0, z), vec3(w, h, z), vec3(-w, h, z), p.end, err);
}

/* ---- 6. knot ------------------------------------------------------------- */

/* The (2,3) torus knot: it winds P times around the torus's axis and Q times
 * through its hole.
 *   C(t) = ((R + cos Qt) cos Pt, (R + cos Qt) sin Pt, -sin Qt),  t in [0, 2 pi) */
#define KNOT_P 2
#define KNOT_Q 3
#define KNOT_R 2.0
#define KNOT_RINGS 256
#define KNOT_SIDES 12
#define KNOT_TUBE_RADIUS 0.35
#define KNOT_STRIPES 16 /* colour bands along the tube */
#define KNOT_MAX_SIDES 4096
#define KNOT_MAX_TUBE_RADIUS 0.5 /* thicker, and the tube runs into itself */

static Vec3 knot_point(double t)
{
    double r = KNOT_R + cos(KNOT_Q * t);
    return vec3(r * cos(KNOT_P * t), r * sin(KNOT_P * t), -sin(KNOT_Q * t));
}

static Vec3 knot_tangent(double t)
{
    double r = KNOT_R + cos(KNOT_Q * t), dr = -KNOT_Q * sin(KNOT_Q * t);
    return vec3_normalize(vec3(dr * cos(KNOT_P * t) - KNOT_P * r * sin(KNOT_P * t),
                               dr * sin(KNOT_P * t) + KNOT_P * r * cos(KNOT_P * t),
                               -KNOT_Q * cos(KNOT_Q * t)));
}

/* v mirrored in the plane through the origin perpendicular to n. */
static Vec3 reflect(Vec3 v, Vec3 n)
{
    double nn = vec3_dot(n, n);
    return nn > 0 ? vec3_sub(v, vec3_scale(n, 2 * vec3_dot(n, v) / nn)) : v;
}

/* A rotation-minimising frame along the curve (Wang et al.'s double
 * reflection): ring i's "out" vector r[i] is carried from ring i-1's by two
 * mirror images, which turn it as little as the curve allows, so the tube has
 * no twist of its own. Once round a closed curve the frame comes back turned
 * by some angle; spreading that turn evenly over the rings closes the tube
 * without a crack. */
static void knot_frames(int rings, Vec3 *x, Vec3 *t, Vec3 *r)
{
    for (int i = 0; i <= rings; i++) {
        double u = 2 * PI * (i % rings) / rings; /* ring `rings` is ring 0 again */
        x[i] = knot_point(u);
        t[i] = knot_tangent(u);
    }
    Vec3 side = fabs(t[0].z) < 0.9 ? vec3(0, 0, 1) : vec3(1, 0, 0);
    r[0] = vec3_normalize(vec3_cross(t[0], side));
    for (int i = 0; i < rings; i++) {
        Vec3 v1 = vec3_sub(x[i + 1], x[i]);
        Vec3 r_l = reflect(r[i], v1), t_l = reflect(t[i], v1);
        r[i + 1] = vec3_normalize(reflect(r_l, vec3_sub(t[i + 1], t_l)));
    }
    double closing = atan2(vec3_dot(vec3_cross(r[0], r[rings]), t[0]), vec3_dot(r[0], r[rings]));
    for (int i = 0; i < rings; i++)
        r[i] = rotate(r[i], t[i], -closing * i / rings);
}

bool torus_knot_mesh(Mesh *m, int rings, int sides, double tube_radius, Error *err)
{
    if (rings < 3 || sides < 3 || sides > KNOT_MAX_SIDES)
        return error_set(err, "torus knot: rings must be >= 3 and sides 3 to %d (got %d, %d)",
                         KNOT_MAX_SIDES, rings, sides);
    if (rings > (MESH_MAX_VERTICES - m->nverts) / sides)
        return error_set(err, "torus knot: %d rings of %d sides is more than %d vertices",
                         rings, sides, MESH_MAX_VERTICES);
    if (!(tube_radius > 0 && tube_radius <= KNOT_MAX_TUBE_RADIUS))
        return error_set(err, "torus knot: tube radius must be in (0, %g]", KNOT_MAX_TUBE_RADIUS);
    int mat[2] = {material(m, "knot_gold", 0.9, 0.7, 0.25, err),
                  material(m, "knot_red", 0.75, 0.2, 0.2, err)};
    if (mat[0] < 0 || mat[1] < 0)
        return false;
    Vec3 *x = malloc(sizeof *x * ((size_t)rings + 1));
    Vec3 *t = malloc(sizeof *t * ((size_t)rings + 1));
    Vec3 *r = malloc(sizeof *r * ((size_t)rings + 1));
    bool ok = x && t && r;
    if (!ok)
        error_set(err, "torus knot: out of memory");
    else
        knot_frames(rings, x, t, r);

    int base = m->nverts; /* vertex (i, j): ring i, side j */
    for (int i = 0; ok && i < rings; i++) {
        Vec3 s = vec3_cross(t[i], r[i]); /* (r, s, t) is right-handed */
        for (int j = 0; ok && j < sides; j++) {
            double phi = 2 * PI * j / sides;
            Vec3 out = vec3_add(vec3_scale(r[i], cos(phi)), vec3_scale(s, sin(phi)));
            ok = mesh_add_vertex(m, vec3_add(x[i], vec3_scale(out, tube_radius)), err) >= 0;
        }
    }
    /* Quad (i, j): around the tube first, then along it, which winds it
     * counter-clockwise seen from outside. */
    for (int i = 0; ok && i < rings; i++) {
        int i1 = (i + 1) % rings;
        int band = (int)((long long)i * KNOT_STRIPES / rings) % 2;
        for (int j = 0; ok && j < sides; j++) {
            int j1 = (j + 1) % sides;
            int q[4] = {base + i * sides + j, base + i * sides + j1, base + i1 * sides + j1,
                        base + i1 * sides + j};
            ok = mesh_add_face(m, q, 4, mat[band], err) >= 0;
        }
    }
    free(x);
    free(t);
    free(r);
    return ok;
}

static bool build_knot(Mesh *m, Error *err)
{
    return torus_knot_mesh(m, KNOT_RINGS, KNOT_SIDES, KNOT_TUBE_RADIUS, err);
}

/* ---- 7. inside ----------------------------------------------------------- */

/* A room with the camera standing in it (lesson 05): floor, ceiling and walls
 * run from ROOM_BACK, behind the camera, to ROOM_END in front; each is cut in
 * two at ROOM_SPLIT, so its near half crosses the near plane and its far half
 * does not. A table and a crate beside the camera and a beam overhead reach
 * behind it too; two pillars stand wholly in front, and the back wall wholly
 * behind. */
#define ROOM_HALF_WIDTH 3.0
#define ROOM_HEIGHT 3.0
#define ROOM_BACK 5.0
#define ROOM_SPLIT (-5.0)
#define ROOM_END (-15.0)

static bool build_inside(Mesh *m, Error *err)
{
    int floor[2] = {material(m, "floor_dark", 0.45, 0.36, 0.28, err),
                    material(m, "floor_light", 0.6, 0.5, 0.38, err)};
    int ceiling = material(m, "ceiling", 0.4, 0.4, 0.45, err);
    int wall[2] = {material(m, "wall_stone", 0.7, 0.66, 0.55, err),
                   material(m, "wall_brick", 0.65, 0.35, 0.25, err)};
    int end = material(m, "end_wall", 0.2, 0.45, 0.4, err);
    int back = material(m, "back_wall", 0.3, 0.3, 0.6, err);
    int wood = material(m, "table", 0.55, 0.3, 0.12, err);
    int crate = material(m, "crate", 0.75, 0.6, 0.2, err);
    int beam = material(m, "beam", 0.35, 0.22, 0.12, err);
    int pillar = material(m, "pillar", 0.5, 0.5, 0.52, err);
    if (floor[0] < 0 || floor[1] < 0 || ceiling < 0 || wall[0] < 0 || wall[1] < 0 ||
        end < 0 || back < 0 || wood < 0 || crate < 0 || beam < 0 || pillar < 0)
        return false;
    double w = ROOM_HALF_WIDTH, h = ROOM_HEIGHT;
    const double z[3] = {ROOM_BACK, ROOM_SPLIT, ROOM_END};
    for (int k = 0; k < 2; k++) {
        double z0 = z[k], z1 = z[k + 1];
        if (!(add_quad(m, vec3(-w, 0, z0), vec3(0, 0, z0), vec3(0, 0, z1), vec3(-w, 0, z1),
                       floor[k], err) &&
              add_quad(m, vec3(0, 0, z0), vec3(w, 0, z0), vec3(w, 0, z1), vec3(0, 0, z1),
                       floor[1 - k], err) &&
              add_quad(m, vec3(-w, h, z0), vec3(-w, h, z1), vec3(w, h, z1), vec3(w, h, z0),
                       ceiling, err) &&
              add_quad(m, vec3(-w, 0, z0), vec3(-w, 0, z1), vec3(-w, h, z1), vec3(-w, h, z0),
                       wall[k], err) &&
              add_quad(m, vec3(w, 0, z0), vec3(w, h, z0), vec3(w, h, z1), vec3(w, 0, z1),
                       wall[1 - k], err)))
            return false;
    }
    return add_quad(m, vec3(-w, 0, ROOM_END), vec3(w, 0, ROOM_END), vec3(w, h, ROOM_END),
                    vec3(-w, h, ROOM_END), end, err) &&
           add_quad(m, vec3(-w, 0, ROOM_BACK), vec3(-w, h, ROOM_BACK), vec3(w, h, ROOM_BACK),
                    vec3(w, 0, ROOM_BACK), back, err) &&
           add_aligned_box(m, vec3(0.6, 0.0, -3.0), vec3(1.8, 0.9, 2.0), wood, err) &&
           add_aligned_box(m, vec3(-2.8, 0.0, -1.5), vec3(-1.6, 1.2, 0.8), crate, err) &&
           add_aligned_box(m, vec3(-0.3, 2.5, ROOM_END), vec3(0.3, 2.8, ROOM_BACK), beam, err) &&
           add_aligned_box(m, vec3(-1.8, -0.05, -9.3), vec3(-1.2, h + 0.05, -8.7), pillar, err) &&
           add_aligned_box(m, vec3(1.2, -0.05, -11.3), vec3(1.8, h + 0.05, -10.7), pillar, err);
}

/* ---- The registry --------------------------------------------------------- */

static const SceneInfo SCENES[] = {
    {.name = "triangles3", .build = build_triangles3,
     .about = "three triangles that overlap in a cycle: no back-to-front order exists",
     .eye = {0, 0, 10}, .target = {0, 0, 0}, .up = {0, 1, 0},
     .fovy = 45, .near = 1, .far = 100},
    {.name = "interpenetrate", .build = build_interpenetrate,
     .about = "two cards that pass through each other in an X",
     .eye = {1.0, 1.2, 4.0}, .target = {0, 0, 0}, .up = {0, 1, 0},
     .fovy = 45, .near = 0.5, .far = 50},
    {.name = "cubes", .build = build_cubes,
     .about = "three cubes cutting into each other and into the floor",
     .eye = {3.5, 4.0, 5.5}, .target = {0.3, 0.5, 0}, .up = {0, 1, 0},
     .fovy = 45, .near = 1, .far = 50},
    {.name = "grazing", .build = build_grazing,
     .about = "two long strips crossing at under a degree, over d = 1.5 to 100",
     .eye = {0, 0, 0}, .target = {0, 0, -1}, .up = {0, 1, 0},
     .fovy = 45, .near = 0.5, .far = 150},
    {.name = "walls", .build = build_walls,
     .about = "a corridor of walls, pillars and a doorway, 1990s style",
     .eye = {0, 1.6, 1.0}, .target = {0, 1.4, -20}, .up = {0, 1, 0},
     .fovy = 60, .near = 0.5, .far = 100},
    {.name = "knot", .build = build_knot,
     .about = "a (2,3) torus knot tube of 3072 quads",
     .eye = {0, -5.5, 8.5}, .target = {0, 0, 0}, .up = {0, 1, 0},
     .fovy = 45, .near = 1, .far = 50},
    {.name = "inside", .build = build_inside,
     .about = "a room seen from inside: floor, walls and a table reach behind the camera",
     .eye = {0, 1.6, 0.5}, .target = {0.4, 1.1, -10}, .up = {0, 1, 0},
     .fovy = 60, .near = 0.25, .far = 60},
    {.name = "ladder", .build = ladder_build, /* lesson 06: ladder.h */
     .about = "pairs of plates 5 cm apart at d = 1 to 300: where the depth buffer runs out",
     .eye = {0, 0, 0}, .target = {0, 0, -1}, .up = {0, 1, 0},
     .fovy = 45, .near = 0.1, .far = 1000},
    {.name = "decals", .build = build_decals, .coplanar = true,
     .about = "posters and floor markings lying exactly on their walls and floor (group decal)",
     .eye = {0, 1.75, 3}, .target = {0, 1.25, -30}, .up = {0, 1, 0},
     .fovy = 50, .near = 0.5, .far = 100},
    {.name = "crowd", .build = build_crowd,
     .about = "192 figures in rows with fences and trees (group cutout), in shuffled order",
     .eye = {0, 6, 8}, .target = {0, 0.5, -22}, .up = {0, 1, 0},
     .fovy = 50, .near = 0.5, .far = 100},
    {.name = "city", .build = build_city,
     .about = "a wall drawn first, hiding a city of 510 small buildings behind it",
     .eye = {0, 18, 0}, .target = {0, 4, -60}, .up = {0, 1, 0},
     .fovy = 55, .near = 1, .far = 200},
};

int scene_count(void)
{
    return (int)(sizeof SCENES / sizeof SCENES[0]);
}

const SceneInfo *scene_at(int i)
{
    return i >= 0 && i < scene_count() ? &SCENES[i] : NULL;
}

const SceneInfo *scene_find(const char *name)
{
    for (int i = 0; i < scene_count(); i++)
        if (strcmp(SCENES[i].name, name) == 0)
            return &SCENES[i];
    return NULL;
}
