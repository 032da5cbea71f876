/* test_scene.c: the built-in scenes (common/harness/scene.c).
 *
 * Every scene must build, be seen by its own camera at 4:3 and 16:9, and lie
 * wholly between the near and far planes: lessons 02 to 04 drop a triangle
 * with a corner in front of the near plane instead of clipping it. The scenes
 * that lessons test by hand (triangles3, interpenetrate, grazing) must have
 * exactly the geometry their comments document. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "camera.h"
#include "harness/mesh_build.h"
#include "harness/scene.h"
#include "test_support.h"

static void build(const char *name, Mesh *m)
{
    const SceneInfo *s = scene_find(name);
    if (!s)
        fail_msg("no scene '%s'", name);
    Error err;
    mesh_init(m);
    if (!s->build(m, &err))
        fail_msg("scene %s: %s", name, err.msg);
}

static void assert_vertex(const Mesh *m, int i, double x, double y, double z)
{
    Vec3 v = m->verts[i];
    if (v.x != x || v.y != y || v.z != z)
        fail_msg("vertex %d is (%g, %g, %g), documented as (%g, %g, %g)", i, v.x, v.y, v.z, x, y,
                 z);
}

static int compare_edges(const void *a, const void *b)
{
    const long long *x = a, *y = b;
    return (*x > *y) - (*x < *y);
}

/* The faces f with include(m, f) (every face when include is NULL) make
 * closed surfaces, consistently wound: every directed edge a -> b appears once
 * among them, and b -> a once too (in the neighbouring face). */
static void expect_closed(const Mesh *m, bool (*include)(const Mesh *, int), const char *what)
{
    int nedges = 0;
    for (int f = 0; f < m->nfaces; f++)
        nedges += !include || include(m, f) ? m->faces[f].count : 0;
    long long *edges = malloc(sizeof *edges * (size_t)nedges);
    assert_non_null(edges);
    long long n = m->nverts;
    int e = 0;
    for (int f = 0; f < m->nfaces; f++) {
        if (include && !include(m, f))
            continue;
        const Face *face = &m->faces[f];
        for (int k = 0; k < face->count; k++)
            edges[e++] = m->corners[face->first + k] * n +
                         m->corners[face->first + (k + 1) % face->count];
    }
    qsort(edges, (size_t)nedges, sizeof *edges, compare_edges);
    for (int i = 0; i < nedges; i++) {
        if (i > 0 && edges[i] == edges[i - 1])
            fail_msg("%s: edge %lld -> %lld is used twice", what, edges[i] / n, edges[i] % n);
        long long reverse = (edges[i] % n) * n + edges[i] / n;
        if (!bsearch(&reverse, edges, (size_t)nedges, sizeof *edges, compare_edges))
            fail_msg("%s: edge %lld -> %lld has no twin: a crack", what, edges[i] / n,
                     edges[i] % n);
    }
    free(edges);
}

/* ---- Every scene ---- */

static void every_scene_builds_with_faces_finite_vertices_and_colours(void **state)
{
    (void)state;
    assert_true(scene_count() >= 6);
    for (int i = 0; i < scene_count(); i++) {
        const SceneInfo *s = scene_at(i);
        assert_non_null(s);
        assert_true(s->about && strlen(s->about) > 10);
        Mesh m;
        build(s->name, &m);
        if (m.nfaces == 0)
            fail_msg("scene %s has no faces", s->name);
        for (int v = 0; v < m.nverts; v++)
            if (!isfinite(m.verts[v].x) || !isfinite(m.verts[v].y) || !isfinite(m.verts[v].z))
                fail_msg("scene %s: vertex %d is not finite", s->name, v);
        /* Flat shading uses Kd: every face has a material with a colour. */
        for (int f = 0; f < m.nfaces; f++)
            if (m.faces[f].material < 0 || !m.materials[m.faces[f].material].has_kd)
                fail_msg("scene %s: face %d has no colour", s->name, f);
        assert_int_equal(m.nwarnings, 0);
        mesh_free(&m);
    }
}

static void scene_names_are_unique_and_found(void **state)
{
    (void)state;
    const char *expected[] = {"triangles3", "interpenetrate", "cubes", "grazing", "walls",
                              "knot",       "inside",         "decals", "crowd", "city"};
    for (size_t k = 0; k < sizeof expected / sizeof expected[0]; k++) {
        const SceneInfo *s = scene_find(expected[k]);
        if (!s)
            fail_msg("scene_find(\"%s\") is NULL", expected[k]);
        assert_string_equal(s->name, expected[k]);
    }
    for (int i = 0; i < scene_count(); i++)
        for (int j = i + 1; j < scene_count(); j++)
            if (strcmp(scene_at(i)->name, scene_at(j)->name) == 0)
                fail_msg("scenes %d and %d are both called %s", i, j, scene_at(i)->name);
    assert_null(scene_find("no-such-scene"));
    assert_null(scene_find(""));
    assert_null(scene_find("triangles")); /* a prefix is not a name */
    assert_null(scene_at(-1));
    assert_null(scene_at(scene_count()));
}

/* Every vertex strictly between near and far, and some on the screen; but
 * lesson 05's scene inside is made to reach behind its camera: there, some
 * vertices must be at or behind the near plane. */
static void check_camera(const SceneInfo *s, const Mesh *m, int width, int height)
{
    Camera c;
    camera_init(&c, s->eye, s->target, s->up, s->fovy, s->near, s->far, width, height);
    int on_screen = 0, behind = 0;
    bool reaches_behind = strcmp(s->name, "inside") == 0;
    for (int v = 0; v < m->nverts; v++) {
        ScreenVertex p = camera_project(&c, m->verts[v]);
        behind += p.d <= s->near;
        if (!(p.d > s->near && p.d < s->far) && !(reaches_behind && p.d < s->far))
            fail_msg("scene %s: vertex %d (%g, %g, %g) has d = %g, outside (near %g, far %g)",
                     s->name, v, m->verts[v].x, m->verts[v].y, m->verts[v].z, p.d, s->near,
                     s->far);
        if (p.x >= 0 && p.x < width && p.y >= 0 && p.y < height)
            on_screen++;
    }
    if (reaches_behind && behind < 8)
        fail_msg("scene %s: %d vertices behind the near plane, expected at least 8", s->name,
                 behind);
    /* At least a quarter of the vertices on the screen: the camera frames the
     * scene, it does not just catch a corner of it. */
    if (on_screen * 4 < m->nverts)
        fail_msg("scene %s at %dx%d: only %d of %d vertices on screen", s->name, width, height,
                 on_screen, m->nverts);
}

static void every_camera_frames_its_scene_between_near_and_far(void **state)
{
    (void)state;
    for (int i = 0; i < scene_count(); i++) {
        const SceneInfo *s = scene_at(i);
        assert_true(s->fovy >= 45 && s->fovy <= 60);
        assert_true(s->near > 0 && s->far > s->near);
        Mesh m;
        build(s->name, &m);
        check_camera(s, &m, 640, 480);  /* 4:3 */
        check_camera(s, &m, 1280, 720); /* 16:9 */
        mesh_free(&m);
    }
}

/* ---- triangles3 ---- */

static void triangles3_has_the_documented_coordinates(void **state)
{
    (void)state;
    Mesh m;
    build("triangles3", &m);
    assert_int_equal(m.nfaces, 3);
    assert_int_equal(m.nverts, 9);
    /* red, green, blue: wide end (z = 1) corners and the tip (z = -1) */
    assert_vertex(&m, 0, -3, -2, 1);
    assert_vertex(&m, 1, 4, -1, -1);
    assert_vertex(&m, 2, -3, 0, 1);
    assert_vertex(&m, 3, 3, -1.5, 1);
    assert_vertex(&m, 4, -1, 4, -1);
    assert_vertex(&m, 5, 1.5, -2.5, 1);
    assert_vertex(&m, 6, 0, 3.5, 1);
    assert_vertex(&m, 7, -3, -3, -1);
    assert_vertex(&m, 8, 1.5, 2.5, 1);
    const SceneInfo *s = scene_find("triangles3");
    assert_true(s->eye.x == 0 && s->eye.y == 0 && s->eye.z == 10);
    mesh_free(&m);
}

/* The depth d = 10 - z of triangle f where the ray from the eye (0, 0, 10)
 * through (x, y, 0) meets it, or -1 if it misses. */
static double depth_on_ray(const Mesh *m, int f, double x, double y)
{
    Vec3 a = m->verts[m->corners[m->faces[f].first]];
    Vec3 b = m->verts[m->corners[m->faces[f].first + 1]];
    Vec3 c = m->verts[m->corners[m->faces[f].first + 2]];
    Vec3 eye = vec3(0, 0, 10), dir = vec3(x, y, -10);
    /* Moller-Trumbore: eye + t dir = a + u (b - a) + v (c - a). */
    Vec3 e1 = vec3_sub(b, a), e2 = vec3_sub(c, a);
    Vec3 p = vec3_cross(dir, e2);
    double det = vec3_dot(e1, p);
    Vec3 s = vec3_sub(eye, a);
    double u = vec3_dot(s, p) / det;
    Vec3 q = vec3_cross(s, e1);
    double v = vec3_dot(dir, q) / det;
    double t = vec3_dot(e2, q) / det;
    if (u < 0 || v < 0 || u + v > 1)
        return -1;
    return 10 - (eye.z + t * dir.z);
}

static void triangles3_overlap_in_a_cycle(void **state)
{
    (void)state;
    /* Along rays through a fine grid, record which triangle is nearer where two
     * overlap. The comment in scene.c says: green covers red, blue covers green,
     * red covers blue; the reverse must never happen, so no order works. */
    Mesh m;
    build("triangles3", &m);
    int in_front[3][3] = {{0}};
    for (double x = -5; x <= 5; x += 0.05)
        for (double y = -4; y <= 5; y += 0.05) {
            double d[3];
            for (int f = 0; f < 3; f++)
                d[f] = depth_on_ray(&m, f, x, y);
            for (int f = 0; f < 3; f++)
                for (int g = 0; g < 3; g++)
                    if (f != g && d[f] > 0 && d[g] > 0 && d[f] < d[g])
                        in_front[f][g]++;
        }
    enum { RED, GREEN, BLUE };
    assert_true(in_front[GREEN][RED] > 100);
    assert_true(in_front[BLUE][GREEN] > 100);
    assert_true(in_front[RED][BLUE] > 100);
    assert_int_equal(in_front[RED][GREEN], 0);
    assert_int_equal(in_front[GREEN][BLUE], 0);
    assert_int_equal(in_front[BLUE][RED], 0);
    mesh_free(&m);
}

/* ---- interpenetrate ---- */

static void interpenetrate_cards_pass_through_each_other(void **state)
{
    (void)state;
    Mesh m;
    build("interpenetrate", &m);
    assert_int_equal(m.nfaces, 2);
    assert_int_equal(m.faces[0].count, 4); /* quads, kept whole */
    assert_int_equal(m.faces[1].count, 4);
    /* Card A lies in z = -x/2, card B in z = x/2: each has corners on both
     * sides of the other's plane. */
    int a_sides = 0, b_sides = 0;
    for (int k = 0; k < 4; k++) {
        Vec3 a = m.verts[m.corners[m.faces[0].first + k]];
        Vec3 b = m.verts[m.corners[m.faces[1].first + k]];
        assert_true(a.z == -a.x / 2);
        assert_true(b.z == b.x / 2);
        a_sides |= (a.z - a.x / 2 > 0) ? 1 : 2; /* which side of B's plane */
        b_sides |= (b.z + b.x / 2 > 0) ? 1 : 2; /* which side of A's plane */
    }
    assert_int_equal(a_sides, 3);
    assert_int_equal(b_sides, 3);
    mesh_free(&m);
}

/* ---- grazing ---- */

static void grazing_strips_follow_their_plane_equations(void **state)
{
    (void)state;
    /* Camera at the origin looking down -Z: d = -z. Strip A: y = -0.5 for d
     * in [1.5, 100]; strip B: y = -0.5 + (4 - d) / 64 for d in [2, 100]. */
    const SceneInfo *s = scene_find("grazing");
    assert_true(s->eye.x == 0 && s->eye.y == 0 && s->eye.z == 0);
    assert_true(s->target.x == 0 && s->target.y == 0 && s->target.z < 0);
    Mesh m;
    build("grazing", &m);
    assert_int_equal(m.nfaces, 2);
    for (int f = 0; f < 2; f++)
        for (int k = 0; k < 4; k++) {
            Vec3 p = m.verts[m.corners[m.faces[f].first + k]];
            double d = -p.z;
            assert_true(d == (f == 0 ? 1.5 : 2.0) || d == 100);
            double expected_y = f == 0 ? -0.5 : -0.5 + (4 - d) / 64;
            if (fabs(p.y - expected_y) > 1e-12)
                fail_msg("strip %c corner %d: y = %g, expected %g", 'A' + f, k, p.y, expected_y);
        }
    mesh_free(&m);
}

/* ---- knot ---- */

/* The curve of scene.c's comment: C(t) = ((2 + cos 3t) cos 2t, (2 + cos 3t) sin 2t, -sin 3t). */
static Vec3 knot_curve(double t)
{
    double r = 2 + cos(3 * t);
    return vec3(r * cos(2 * t), r * sin(2 * t), -sin(3 * t));
}

static void knot_tube_is_closed_and_wound_outwards(void **state)
{
    (void)state;
    int rings = 200, sides = 10;
    double radius = 0.3;
    Mesh m;
    Error err;
    mesh_init(&m);
    if (!torus_knot_mesh(&m, rings, sides, radius, &err))
        fail_msg("%s", err.msg);
    assert_int_equal(m.nverts, rings * sides);
    assert_int_equal(m.nfaces, rings * sides);

    expect_closed(&m, NULL, "knot");

    /* Wound outwards: the enclosed volume (divergence theorem, sum over the
     * triangles of a . (b x c) / 6) is positive, and equals the cross-section,
     * a regular polygon of area sides/2 r^2 sin(2 pi / sides), times the
     * length of the polygonal centre line (Pappus's theorem for tubes). */
    double volume = 0;
    for (int f = 0; f < m.nfaces; f++)
        for (int t = 0; t < m.faces[f].count - 2; t++) {
            Tri tri = m.tris[m.faces[f].first_tri + t];
            Vec3 a = m.verts[m.corners[m.faces[f].first + tri.c[0]]];
            Vec3 b = m.verts[m.corners[m.faces[f].first + tri.c[1]]];
            Vec3 c = m.verts[m.corners[m.faces[f].first + tri.c[2]]];
            volume += vec3_dot(a, vec3_cross(b, c)) / 6;
        }
    double length = 0;
    for (int i = 0; i < rings; i++)
        length += vec3_length(vec3_sub(knot_curve(2 * PI * (i + 1) / rings),
                                       knot_curve(2 * PI * i / rings)));
    double expected = sides / 2.0 * radius * radius * sin(2 * PI / sides) * length;
    if (fabs(volume - expected) > 0.01 * expected)
        fail_msg("tube volume %g, expected %g (cross-section x length)", volume, expected);

    /* No twist where the tube closes: the edges along the tube from the last
     * ring to ring 0 are no longer than those between the rings next to them. */
    double seam = 0, next_to_it = 0;
    for (int j = 0; j < sides; j++) {
        Vec3 last = m.verts[(rings - 1) * sides + j], first = m.verts[j];
        Vec3 before = m.verts[(rings - 2) * sides + j], after = m.verts[sides + j];
        seam = fmax(seam, vec3_length(vec3_sub(first, last)));
        next_to_it = fmax(next_to_it, fmax(vec3_length(vec3_sub(last, before)),
                                           vec3_length(vec3_sub(after, first))));
    }
    if (seam > 1.05 * next_to_it)
        fail_msg("edges across the seam are %g long, %g next to it: the tube twists there",
                 seam, next_to_it);
    mesh_free(&m);
}

static void knot_refuses_bad_sizes(void **state)
{
    (void)state;
    Mesh m;
    Error err;
    mesh_init(&m);
    assert_false(torus_knot_mesh(&m, 2, 10, 0.3, &err));
    assert_false(torus_knot_mesh(&m, 100, 2, 0.3, &err));
    assert_false(torus_knot_mesh(&m, 100, 10, 0, &err));
    assert_false(torus_knot_mesh(&m, 100, 10, NAN, &err));
    assert_false(torus_knot_mesh(&m, 1 << 20, 1 << 10, 0.3, &err)); /* 2^30 vertices */
    assert_int_equal(m.nfaces, 0);
    mesh_free(&m);
}


/* ---- decals ---- */

static Vec3 corner(const Mesh *m, int f, int k)
{
    return m->verts[m->corners[m->faces[f].first + k]];
}

/* Every corner of face d lies exactly in the plane of face b's first three
 * corners (a plane worked out here, from b alone), and inside b's bounding box:
 * the coordinates are multiples of 1/8, so the products are exact. */
static bool lies_on(const Mesh *m, int d, int b)
{
    Vec3 a = corner(m, b, 0);
    Vec3 n = vec3_cross(vec3_sub(corner(m, b, 1), a), vec3_sub(corner(m, b, 2), a));
    for (int k = 0; k < m->faces[d].count; k++) {
        Vec3 p = corner(m, d, k);
        if (vec3_dot(n, vec3_sub(p, a)) != 0)
            return false;
        double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
        for (int j = 0; j < m->faces[b].count; j++) {
            Vec3 q = corner(m, b, j);
            double c[3] = {q.x, q.y, q.z};
            for (int i = 0; i < 3; i++) {
                lo[i] = fmin(lo[i], c[i]);
                hi[i] = fmax(hi[i], c[i]);
            }
        }
        double c[3] = {p.x, p.y, p.z};
        for (int i = 0; i < 3; i++)
            if (c[i] < lo[i] || c[i] > hi[i])
                return false;
    }
    return true;
}

static void decals_lie_exactly_on_a_face_drawn_before_them(void **state)
{
    (void)state;
    const SceneInfo *s = scene_find("decals");
    assert_true(s->coplanar);
    Mesh m;
    build("decals", &m);
    /* The planes scene.c documents: floor y = 0, walls x = -4 and x = 4, end
     * wall z = -60. */
    int on_floor = 0, on_walls = 0, decals = 0;
    for (int d = 0; d < m.nfaces; d++) {
        if (!mesh_face_in(&m, d, "decal"))
            continue;
        decals++;
        assert_true(mesh_face_in(&m, d, "poster") != mesh_face_in(&m, d, "marking"));
        int base = -1;
        for (int b = 0; b < d && base < 0; b++)
            if (!mesh_face_in(&m, b, "decal") && lies_on(&m, d, b))
                base = b;
        if (base < 0)
            fail_msg("decal face %d lies on no face drawn before it", d);
        Vec3 p = corner(&m, d, 0);
        bool all_y0 = true, all_x4 = true, all_z60 = true;
        for (int k = 0; k < m.faces[d].count; k++) {
            Vec3 q = corner(&m, d, k);
            all_y0 = all_y0 && q.y == 0;
            all_x4 = all_x4 && fabs(q.x) == 4 && q.x == p.x;
            all_z60 = all_z60 && q.z == -60;
        }
        assert_true(all_y0 || all_x4 || all_z60);
        on_floor += all_y0;
        on_walls += all_x4;
        if (mesh_face_in(&m, d, "marking") != all_y0)
            fail_msg("face %d: a marking is on the floor, a poster on a wall", d);
    }
    expect_count(31, decals, "decal faces (8 posters, a sign, 14 dashes, 2 lines, 6 stripes)");
    expect_count(22, on_floor, "decals on the floor");
    expect_count(8, on_walls, "decals on the side walls");
    mesh_free(&m);
}

/* The ray from eye to p enters the axis-aligned box [lo, hi] before p. */
static bool ray_hits_box(Vec3 eye, Vec3 p, Vec3 lo, Vec3 hi)
{
    double t0 = 0, t1 = 1;
    double e[3] = {eye.x, eye.y, eye.z}, q[3] = {p.x, p.y, p.z};
    double l[3] = {lo.x, lo.y, lo.z}, h[3] = {hi.x, hi.y, hi.z};
    for (int i = 0; i < 3; i++) {
        double dir = q[i] - e[i];
        if (dir == 0) {
            if (e[i] < l[i] || e[i] > h[i])
                return false;
            continue;
        }
        double a = (l[i] - e[i]) / dir, b = (h[i] - e[i]) / dir;
        t0 = fmax(t0, fmin(a, b));
        t1 = fmin(t1, fmax(a, b));
    }
    return t0 < t1;
}

static void decals_pillar_stands_in_front_of_a_poster(void **state)
{
    (void)state;
    const SceneInfo *s = scene_find("decals");
    Mesh m;
    build("decals", &m);
    /* The last face's box is the pillar (no group); the first poster is on
     * the left wall, z from -5 to -7.5, y from 1 to 2.75. */
    int last = m.nfaces - 1;
    assert_false(mesh_face_in(&m, last, "decal"));
    Vec3 lo = vec3(INFINITY, INFINITY, INFINITY), hi = vec3(-INFINITY, -INFINITY, -INFINITY);
    for (int f = last - 5; f <= last; f++)
        for (int k = 0; k < 4; k++) {
            Vec3 q = corner(&m, f, k);
            lo = vec3(fmin(lo.x, q.x), fmin(lo.y, q.y), fmin(lo.z, q.z));
            hi = vec3(fmax(hi.x, q.x), fmax(hi.y, q.y), fmax(hi.z, q.z));
        }
    assert_true(hi.x < -3 && lo.x > -4); /* off the wall, near it */
    int hidden = 0, total = 0;
    for (double z = -5.0; z >= -7.5; z -= 0.125)
        for (double y = 1.0; y <= 2.75; y += 0.125, total++)
            hidden += ray_hits_box(s->eye, vec3(-4, y, z), lo, hi);
    printf("  decals: the pillar hides %d of %d sample points of the first poster\n", hidden,
           total);
    if (hidden * 4 < total || hidden == total)
        fail_msg("the pillar hides %d of %d points of the poster: expected a good part, not all",
                 hidden, total);
    mesh_free(&m);
}

/* ---- crowd ---- */

static bool solid_and_not_ground(const Mesh *m, int f)
{
    return f > 0 && !mesh_face_in(m, f, "cutout");
}

/* The nearest view depth of face f's corners. */
static double nearest_depth(const Camera *c, const Mesh *m, int f)
{
    double d = INFINITY;
    for (int k = 0; k < m->faces[f].count; k++)
        d = fmin(d, camera_project(c, corner(m, f, k)).d);
    return d;
}

static void crowd_has_flat_cutouts_closed_figures_and_no_depth_order(void **state)
{
    (void)state;
    const SceneInfo *s = scene_find("crowd");
    assert_false(s->coplanar);
    Mesh m;
    build("crowd", &m);
    /* 1 ground + 192 figures of 2 boxes + 24 fence panels + 16 trees of a
     * trunk box and 2 crossed quads. */
    expect_count(1 + 192 * 12 + 24 + 16 * (6 + 2), m.nfaces, "faces");
    int cutouts = 0;
    for (int f = 0; f < m.nfaces; f++) {
        if (!mesh_face_in(&m, f, "cutout"))
            continue;
        cutouts++;
        /* Flat: the fourth corner in the plane of the first three. */
        Vec3 a = corner(&m, f, 0);
        Vec3 n = vec3_cross(vec3_sub(corner(&m, f, 1), a), vec3_sub(corner(&m, f, 2), a));
        assert_int_equal(m.faces[f].count, 4);
        assert_true(vec3_dot(n, vec3_sub(corner(&m, f, 3), a)) == 0);
    }
    expect_count(24 + 32, cutouts, "cutout faces (fence panels and tree crowns)");
    expect_closed(&m, solid_and_not_ground, "crowd's boxes");

    /* Neither front to back nor back to front: over all pairs of faces, the
     * later one is farther about as often as it is nearer. */
    Camera c;
    camera_init(&c, s->eye, s->target, s->up, s->fovy, s->near, s->far, 800, 600);
    double *d = malloc(sizeof *d * (size_t)m.nfaces);
    assert_non_null(d);
    for (int f = 0; f < m.nfaces; f++)
        d[f] = nearest_depth(&c, &m, f);
    long long farther = 0, nearer = 0;
    for (int i = 0; i < m.nfaces; i++)
        for (int j = i + 1; j < m.nfaces; j++) {
            farther += d[j] > d[i];
            nearer += d[j] < d[i];
        }
    double share = (double)farther / (double)(farther + nearer);
    printf("  crowd: %.1f%% of face pairs in drawing order go farther\n", 100 * share);
    if (share < 0.3 || share > 0.7)
        fail_msg("%.1f%% of face pairs go farther: the order is close to sorted", 100 * share);
    free(d);
    mesh_free(&m);
}

/* ---- city ---- */

static bool not_ground(const Mesh *m, int f)
{
    (void)m;
    return f > 1; /* the wall, face 0, and the ground, face 1, are single quads */
}

static void city_wall_comes_first_and_hides_the_whole_city(void **state)
{
    (void)state;
    const SceneInfo *s = scene_find("city");
    assert_false(s->coplanar);
    Mesh m;
    build("city", &m);
    expect_count(1 + 1 + 510 * 6, m.nfaces, "faces (wall, ground, 510 buildings)");
    expect_closed(&m, not_ground, "city's boxes");
    /* The wall, face 0, spans x -60 to 6, y -1 to 45 at z = -12, facing the
     * camera at (0, 18, 0): a building is hidden when the ray to each of its
     * corners crosses z = -12 inside that rectangle (both are convex). */
    assert_true(s->eye.x == 0 && s->eye.y == 18 && s->eye.z == 0);
    for (int k = 0; k < 4; k++) {
        Vec3 q = corner(&m, 0, k);
        assert_true((q.x == -60 || q.x == 6) && (q.y == -1 || q.y == 45) && q.z == -12);
    }
    int hidden = 0, buildings = 0;
    for (int f = 2; f < m.nfaces; f += 6, buildings++) {
        bool all = true;
        for (int b = f; b < f + 6; b++)
            for (int k = 0; k < 4; k++) {
                Vec3 q = corner(&m, b, k);
                double t = 12 / -q.z; /* eye + t (q - eye) reaches z = -12 */
                double x = q.x * t, y = 18 + (q.y - 18) * t;
                all = all && x >= -60 && x <= 6 && y >= -1 && y <= 45;
            }
        hidden += all;
    }
    printf("  city: the wall hides %d of %d buildings whole\n", hidden, buildings);
    if (hidden != buildings)
        fail_msg("the wall hides %d of %d buildings: expected all", hidden, buildings);
    mesh_free(&m);
}

static void only_the_scenes_that_say_so_have_groups(void **state)
{
    (void)state;
    for (int i = 0; i < scene_count(); i++) {
        const SceneInfo *s = scene_at(i);
        Mesh m;
        build(s->name, &m);
        int decal = 0, cutout = 0;
        for (int f = 0; f < m.nfaces; f++) {
            decal += mesh_face_in(&m, f, "decal");
            cutout += mesh_face_in(&m, f, "cutout");
        }
        bool decals = strcmp(s->name, "decals") == 0, crowd = strcmp(s->name, "crowd") == 0;
        if ((decal > 0) != decals || (cutout > 0) != crowd || s->coplanar != decals)
            fail_msg("scene %s: %d decal faces, %d cutout faces, coplanar %d", s->name, decal,
                     cutout, s->coplanar);
        mesh_free(&m);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(every_scene_builds_with_faces_finite_vertices_and_colours),
        cmocka_unit_test(scene_names_are_unique_and_found),
        cmocka_unit_test(every_camera_frames_its_scene_between_near_and_far),
        cmocka_unit_test(triangles3_has_the_documented_coordinates),
        cmocka_unit_test(triangles3_overlap_in_a_cycle),
        cmocka_unit_test(interpenetrate_cards_pass_through_each_other),
        cmocka_unit_test(grazing_strips_follow_their_plane_equations),
        cmocka_unit_test(knot_tube_is_closed_and_wound_outwards),
        cmocka_unit_test(knot_refuses_bad_sizes),
        cmocka_unit_test(decals_lie_exactly_on_a_face_drawn_before_them),
        cmocka_unit_test(decals_pillar_stands_in_front_of_a_poster),
        cmocka_unit_test(crowd_has_flat_cutouts_closed_figures_and_no_depth_order),
        cmocka_unit_test(city_wall_comes_first_and_hides_the_whole_city),
        cmocka_unit_test(only_the_scenes_that_say_so_have_groups),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
