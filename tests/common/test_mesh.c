/* test_mesh.c: meshes, OBJ and MTL files (common/harness/mesh_build.c, common/harness/obj.c).
 * Ear clipping has its own test_triangulate.c.
 *
 * Every error test asserts the whole message, file:line included: that line is
 * what a student sees when their OBJ file is wrong. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "harness/file.h"
#include "harness/mesh_build.h"
#include "test_support.h"

/* ---- helpers ---- */

/* Parses text as "x.obj" (no .mtl files) and fails the test on an error. */
static void parse_ok(Mesh *m, const char *text)
{
    Error err;
    mesh_init(m);
    if (!mesh_parse_obj(m, text, strlen(text), "x.obj", NULL, &err))
        fail_msg("parsing failed: %s\n--- text ---\n%.400s", err.msg, text);
}

/* Parsing len bytes of text must fail with exactly `expected`. */
static void parse_fails_len(const char *text, size_t len, const char *expected)
{
    Mesh m;
    Error err = {"(no message)"};
    mesh_init(&m);
    bool ok = mesh_parse_obj(&m, text, len, "x.obj", NULL, &err);
    if (ok)
        fail_msg("parsing succeeded, expected the error \"%s\"", expected);
    if (strcmp(err.msg, expected) != 0)
        fail_msg("wrong message\n  got:      \"%s\"\n  expected: \"%s\"", err.msg, expected);
    assert_int_equal(m.nfaces, 0); /* a failed parse leaves the mesh as it was */
    mesh_free(&m);
}

static void parse_fails(const char *text, const char *expected)
{
    parse_fails_len(text, strlen(text), expected);
}

static void assert_corners(const Mesh *m, int face, const int *expected, int n)
{
    const Face *f = &m->faces[face];
    if (f->count != n)
        fail_msg("face %d has %d corners, expected %d", face, f->count, n);
    for (int i = 0; i < n; i++)
        if (m->corners[f->first + i] != expected[i])
            fail_msg("face %d corner %d is vertex %d, expected %d", face, i,
                     m->corners[f->first + i], expected[i]);
}

static void assert_warning(const Mesh *m, int i, const char *expected)
{
    if (i >= m->nwarnings)
        fail_msg("only %d warnings, expected \"%s\" as number %d", m->nwarnings, expected, i);
    if (strcmp(m->warnings[i], expected) != 0)
        fail_msg("warning %d\n  got:      \"%s\"\n  expected: \"%s\"", i, m->warnings[i],
                 expected);
}

/* Three vertices of a triangle, for texts that only need a face to exist. */
#define TRIANGLE "v 0 0 0\nv 1 0 0\nv 0 1 0\n"
#define EIGHT_VERTICES TRIANGLE "v 1 1 0\nv 0 0 1\nv 1 0 1\nv 0 1 1\nv 1 1 1\n"

/* ---- OBJ forms ---- */

static void every_corner_form_is_read(void **state)
{
    (void)state;
    Mesh m;
    parse_ok(&m, TRIANGLE "vt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 1\n"
                 "f 1 2 3\n"
                 "f 1/1 2/2 3/3\n"
                 "f 1//1 2//1 3//1\n"
                 "f 1/1/1 2/2/1 3/3/1\n");
    assert_int_equal(m.nverts, 3);
    assert_int_equal(m.nfaces, 4);
    const int expected[3] = {0, 1, 2}; /* OBJ counts from 1, the mesh from 0 */
    for (int f = 0; f < 4; f++)
        assert_corners(&m, f, expected, 3);
    assert_int_equal(m.nwarnings, 0);
    assert_true(m.verts[1].x == 1 && m.verts[2].y == 1);
    mesh_free(&m);
}

static void negative_indices_count_back_from_the_last_vertex(void **state)
{
    (void)state;
    Mesh m;
    /* After 3 vertices, -1 is vertex 3 (0-based 2), -3 is vertex 1 (0-based 0).
     * After a 4th, -1 is 0-based 3, -2 is 2 and -4 is 0. */
    parse_ok(&m, TRIANGLE "f -3 -2 -1\nv 1 1 0\nf -1 -2 -4\nf 4 -4 -3\n");
    const int f0[3] = {0, 1, 2}, f1[3] = {3, 2, 0}, f2[3] = {3, 0, 1};
    assert_corners(&m, 0, f0, 3);
    assert_corners(&m, 1, f1, 3);
    assert_corners(&m, 2, f2, 3);
    mesh_free(&m);
}

static void polygons_keep_all_their_corners(void **state)
{
    (void)state;
    Mesh m;
    /* A convex pentagon: one face of 5 corners, 5 - 2 = 3 triangles. */
    parse_ok(&m, "v 0 0 0\nv 2 0 0\nv 3 2 0\nv 1 3 0\nv -1 2 0\nf 1 2 3 4 5\n");
    assert_int_equal(m.nfaces, 1);
    assert_int_equal(m.faces[0].count, 5);
    assert_int_equal(m.ntris, 3);
    assert_int_equal(m.faces[0].first_tri, 0);
    assert_true(m.faces[0].convex);
    const int expected[5] = {0, 1, 2, 3, 4};
    assert_corners(&m, 0, expected, 5);
    mesh_free(&m);
}

static void face_index_is_position_in_file(void **state)
{
    (void)state;
    Mesh m;
    parse_ok(&m, EIGHT_VERTICES "f 1 2 3\nf 5 6 8 7\nf 2 4 3\n");
    assert_int_equal(m.nfaces, 3);
    /* first corner and first triangle follow the order of the f lines */
    assert_int_equal(m.faces[1].first, 3);
    assert_int_equal(m.faces[2].first, 7);
    assert_int_equal(m.faces[1].first_tri, 1);
    assert_int_equal(m.faces[2].first_tri, 3);
    assert_int_equal(m.ntris, 4);
    mesh_free(&m);
}

static void names_groups_and_smoothing_are_accepted_silently(void **state)
{
    (void)state;
    Mesh m;
    parse_ok(&m, "o thing\ng part one\ns 1\n" TRIANGLE "s off\nf 1 2 3\n");
    assert_int_equal(m.nfaces, 1);
    assert_int_equal(m.nwarnings, 0);
    mesh_free(&m);
}

static void fourth_coordinate_w_is_accepted(void **state)
{
    (void)state;
    Mesh m;
    parse_ok(&m, "v 1 2 3 1\nv 4 5 6 1\nv 7 8 9 0.5\nf 1 2 3\n");
    assert_true(m.verts[2].x == 7 && m.verts[2].y == 8 && m.verts[2].z == 9);
    assert_int_equal(m.nwarnings, 0);
    mesh_free(&m);
}

static void comments_blank_lines_crlf_and_odd_white_space_are_read(void **state)
{
    (void)state;
    Mesh m;
    parse_ok(&m, "# a comment\r\n\r\n   \t\n"
                 "v\t0 0 0 # the origin\r\n"
                 "v 1\v0\f0\r\n"
                 "\t v  0   1\t\t0  \r\n"
                 "f 1 2 3\r\n"
                 "f 1 2 3"); /* the last line has no line end */
    assert_int_equal(m.nverts, 3);
    assert_int_equal(m.nfaces, 2);
    assert_true(m.verts[1].x == 1 && m.verts[2].y == 1);
    mesh_free(&m);
}

static void a_very_long_line_is_read_whole(void **state)
{
    (void)state;
    /* 100 000 spaces, then a vertex, on one line; then a 100 000-byte comment. */
    size_t pad = 100000;
    const char *tail = "v 1 2 3\nv 4 5 6\nv 7 8 9\n";
    char *text = malloc(2 * pad + 64);
    assert_non_null(text);
    memset(text, ' ', pad);
    strcpy(text + pad, tail);
    size_t n = strlen(text);
    text[n] = '#';
    memset(text + n + 1, 'c', pad);
    strcpy(text + n + 1 + pad, "\nf 1 2 3\n");
    Mesh m;
    parse_ok(&m, text);
    assert_int_equal(m.nverts, 3);
    assert_true(m.verts[0].x == 1 && m.verts[0].y == 2 && m.verts[0].z == 3);
    assert_int_equal(m.nfaces, 1);
    mesh_free(&m);
    free(text);
}

static void parse_replaces_the_mesh_and_failure_keeps_it(void **state)
{
    (void)state;
    Mesh m;
    Error err;
    parse_ok(&m, EIGHT_VERTICES "f 1 2 3\nf 4 5 6\n");
    const char *bad = TRIANGLE "f 1 2 4\n";
    assert_false(mesh_parse_obj(&m, bad, strlen(bad), "x.obj", NULL, &err));
    assert_int_equal(m.nfaces, 2); /* untouched */
    assert_int_equal(m.nverts, 8);
    const char *good = TRIANGLE "f 3 2 1\n";
    assert_true(mesh_parse_obj(&m, good, strlen(good), "x.obj", NULL, &err));
    assert_int_equal(m.nfaces, 1); /* replaced, not appended */
    assert_int_equal(m.nverts, 3);
    mesh_free(&m);
}

/* ---- Warnings ---- */

static void unsupported_statements_are_warned_about(void **state)
{
    (void)state;
    Mesh m;
    parse_ok(&m, TRIANGLE "l 1 2\np 1\nvp 0.5\ncurv 0 1 1 2\nf 1 2 3\nbogus\n");
    assert_int_equal(m.nwarnings, 5);
    assert_warning(&m, 0, "x.obj:4: 'l' statements are ignored");
    assert_warning(&m, 1, "x.obj:5: 'p' statements are ignored");
    assert_warning(&m, 2, "x.obj:6: 'vp' statements are ignored");
    assert_warning(&m, 3, "x.obj:7: 'curv' statements are ignored");
    assert_warning(&m, 4, "x.obj:9: 'bogus' statements are ignored");
    assert_int_equal(m.nfaces, 1);
    mesh_free(&m);
}

static void many_warnings_end_with_a_count(void **state)
{
    (void)state;
    /* 30 ignored statements: the first 20 are kept, then one line counts the
     * other 10. */
    char text[512] = TRIANGLE "f 1 2 3\n";
    for (int i = 0; i < 30; i++)
        strcat(text, "l 1 2\n");
    Mesh m;
    parse_ok(&m, text);
    assert_int_equal(m.nwarnings, 21);
    assert_warning(&m, 0, "x.obj:5: 'l' statements are ignored");
    assert_warning(&m, 19, "x.obj:24: 'l' statements are ignored");
    assert_warning(&m, 20, "x.obj: 10 more warnings not shown");
    mesh_free(&m);
}

static void unknown_material_is_a_warning_and_no_material(void **state)
{
    (void)state;
    Mesh m;
    parse_ok(&m, TRIANGLE "usemtl ghost\nf 1 2 3\n");
    assert_int_equal(m.nwarnings, 1);
    assert_warning(&m, 0,
                   "x.obj:4: material 'ghost' is not defined; the faces that follow get none");
    assert_int_equal(m.faces[0].material, -1);
    mesh_free(&m);
}

static void vertex_colours_are_read_past_with_a_warning(void **state)
{
    (void)state;
    Mesh m;
    parse_ok(&m, "v 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 0 1 0 0 0 1\nf 1 2 3\n");
    assert_true(m.verts[1].x == 1 && m.verts[1].y == 0 && m.verts[1].z == 0);
    assert_int_equal(m.nwarnings, 3);
    assert_warning(&m, 0, "x.obj:1: vertex colours are ignored");
    mesh_free(&m);
}

/* ---- Materials ---- */

static void kd_is_read_from_the_mtl_beside_the_obj(void **state)
{
    (void)state;
    const char *dir = test_dir("mesh_kd");
    char obj[512];
    snprintf(obj, sizeof obj, "%s", path_join(dir, "x.obj"));
    write_text(path_join(dir, "y.mtl"), "# materials\n"
                                        "newmtl red\nKa 0 0 0\nKd 1 0 0\nillum 2\n"
                                        "newmtl grey\nKd 0.5\n"
                                        "newmtl clamped\r\nKd 2 -1 0.25\r\n"
                                        "newmtl plain\nNs 10\n");
    write_text(obj, "mtllib y.mtl\n" TRIANGLE
                    "usemtl grey\nf 1 2 3\n"
                    "usemtl red\nf 1 2 3\n"
                    "usemtl clamped\nf 1 2 3\n"
                    "usemtl plain\nf 1 2 3\n"
                    "usemtl\nf 1 2 3\n");
    Mesh m;
    Error err;
    mesh_init(&m);
    if (!mesh_load_obj(&m, obj, &err))
        fail_msg("%s", err.msg);
    assert_int_equal(m.nwarnings, 0);
    assert_int_equal(m.nmaterials, 4);
    /* Materials keep the .mtl file's order: red 0, grey 1, clamped 2, plain 3. */
    assert_int_equal(m.faces[0].material, 1);
    assert_int_equal(m.faces[1].material, 0);
    assert_int_equal(m.faces[2].material, 2);
    assert_int_equal(m.faces[3].material, 3);
    assert_int_equal(m.faces[4].material, -1); /* a bare usemtl: none */
    assert_string_equal(m.materials[0].name, "red");
    assert_true(m.materials[0].has_kd);
    assert_true(m.materials[0].kd.x == 1 && m.materials[0].kd.y == 0 && m.materials[0].kd.z == 0);
    /* "Kd 0.5" alone is grey: g and b take r's value. */
    Vec3 grey = m.materials[1].kd, clamped = m.materials[2].kd;
    assert_true(grey.x == 0.5 && grey.y == 0.5 && grey.z == 0.5);
    /* 2 and -1 are clamped to [0, 1]. */
    assert_true(clamped.x == 1 && clamped.y == 0 && clamped.z == 0.25);
    assert_string_equal(m.materials[2].name, "clamped"); /* no \r in the name */
    assert_false(m.materials[3].has_kd);
    mesh_free(&m);
}

static void missing_mtl_is_a_warning(void **state)
{
    (void)state;
    const char *dir = test_dir("mesh_no_mtl");
    char obj[512], expected[600];
    snprintf(obj, sizeof obj, "%s", path_join(dir, "x.obj"));
    write_text(obj, "# no library here\nmtllib nowhere.mtl\n" TRIANGLE "usemtl red\nf 1 2 3\n");
    Mesh m;
    Error err;
    mesh_init(&m);
    if (!mesh_load_obj(&m, obj, &err))
        fail_msg("%s", err.msg);
    assert_int_equal(m.nfaces, 1);
    assert_int_equal(m.nwarnings, 2);
    snprintf(expected, sizeof expected, "%s:2: material library 'nowhere.mtl' not found", obj);
    assert_warning(&m, 0, expected);
    snprintf(expected, sizeof expected,
             "%s:6: material 'red' is not defined; the faces that follow get none", obj);
    assert_warning(&m, 1, expected);
    mesh_free(&m);
}

static void mtl_oddities_are_warnings(void **state)
{
    (void)state;
    /* Kd before any newmtl, a library that is a directory, and the same
     * library named twice (read once). */
    const char *dir = test_dir("mesh_mtl_oddities");
    char obj[512], mtl[512], expected[1200];
    snprintf(obj, sizeof obj, "%s", path_join(dir, "x.obj"));
    snprintf(mtl, sizeof mtl, "%s", path_join(dir, "y.mtl"));
    write_text(mtl, "Kd 1 0 0\nnewmtl red\nKd 1 0 0\n");
    Error err;
    assert_true(make_dirs(path_join(dir, "d.mtl"), &err));
    write_text(obj, "mtllib y.mtl d.mtl\nmtllib y.mtl\n" TRIANGLE "usemtl red\nf 1 2 3\n");
    Mesh m;
    mesh_init(&m);
    if (!mesh_load_obj(&m, obj, &err))
        fail_msg("%s", err.msg);
    assert_int_equal(m.nmaterials, 1);
    assert_int_equal(m.faces[0].material, 0);
    assert_int_equal(m.nwarnings, 2);
    snprintf(expected, sizeof expected, "%s:1: 'Kd' before any 'newmtl' is ignored", mtl);
    assert_warning(&m, 0, expected);
    snprintf(expected, sizeof expected,
             "%s:1: material library 'd.mtl' not read: cannot read %s/d.mtl: Is a directory", obj,
             dir);
    assert_warning(&m, 1, expected);
    mesh_free(&m);
}

static void bad_kd_is_an_error_naming_the_mtl_line(void **state)
{
    (void)state;
    const char *dir = test_dir("mesh_bad_kd");
    char obj[512], mtl[512], expected[1200];
    snprintf(obj, sizeof obj, "%s", path_join(dir, "x.obj"));
    snprintf(mtl, sizeof mtl, "%s", path_join(dir, "y.mtl"));
    write_text(mtl, "newmtl red\nKd nan 0 0\n");
    write_text(obj, "mtllib y.mtl\n" TRIANGLE "f 1 2 3\n");
    Mesh m;
    Error err;
    mesh_init(&m);
    assert_false(mesh_load_obj(&m, obj, &err));
    snprintf(expected, sizeof expected, "%s:2: Kd value 'nan' is not a finite number", mtl);
    assert_string_equal(err.msg, expected);
    mesh_free(&m);
}

static void missing_obj_file_names_the_path(void **state)
{
    (void)state;
    const char *dir = test_dir("mesh_missing");
    char obj[512], expected[600];
    snprintf(obj, sizeof obj, "%s", path_join(dir, "absent.obj"));
    Mesh m;
    Error err;
    mesh_init(&m);
    assert_false(mesh_load_obj(&m, obj, &err));
    snprintf(expected, sizeof expected, "cannot read %s: No such file or directory", obj);
    assert_string_equal(err.msg, expected);
    mesh_free(&m);
}

/* ---- Malformed OBJ ---- */

static void index_zero_is_an_error(void **state)
{
    (void)state;
    parse_fails(TRIANGLE "f 1 2 0\n",
                "x.obj:4: vertex index 0 is invalid (the first is 1, the last is -1)");
}

static void index_past_the_last_vertex_is_an_error(void **state)
{
    (void)state;
    parse_fails(EIGHT_VERTICES "f 1 2 9\n",
                "x.obj:9: vertex index 9 is out of range (1 to 8, or -1 to -8)");
}

static void negative_index_before_the_first_vertex_is_an_error(void **state)
{
    (void)state;
    parse_fails(EIGHT_VERTICES "f -1 -2 -9\n",
                "x.obj:9: vertex index -9 is out of range (1 to 8, or -1 to -8)");
}

static void index_of_a_vertex_defined_later_is_an_error(void **state)
{
    (void)state;
    /* OBJ indices refer to the vertices defined so far. */
    parse_fails("v 0 0 0\nv 1 0 0\nf 1 2 3\nv 0 1 0\n",
                "x.obj:3: vertex index 3 is out of range (1 to 2, or -1 to -2)");
    parse_fails("f 1 2 3\n" TRIANGLE, "x.obj:1: vertex index 1 is out of range (none defined yet)");
}

static void index_too_big_for_an_int_is_out_of_range(void **state)
{
    (void)state;
    parse_fails(TRIANGLE "f 1 2 99999999999999999999\n",
                "x.obj:4: vertex index 99999999999999999999 is out of range (1 to 3, or -1 to -3)");
    parse_fails(TRIANGLE "f 1 2 -4294967298\n",
                "x.obj:4: vertex index -4294967298 is out of range (1 to 3, or -1 to -3)");
}

static void texture_and_normal_indices_are_checked(void **state)
{
    (void)state;
    parse_fails(TRIANGLE "vt 0 0\nf 1/1 2/5 3/1\n",
                "x.obj:5: texture coordinate index 5 is out of range (1 to 1, or -1 to -1)");
    parse_fails(TRIANGLE "f 1//1 2//1 3//1\n",
                "x.obj:4: normal index 1 is out of range (none defined yet)");
}

static void malformed_corners_are_errors(void **state)
{
    (void)state;
    parse_fails(TRIANGLE "f 1 2 3a\n", "x.obj:4: vertex index '3a' is not an integer");
    parse_fails(TRIANGLE "f 1 2 x\n", "x.obj:4: vertex index 'x' is not an integer");
    parse_fails(TRIANGLE "f 1 2 3/1/1/1\n",
                "x.obj:4: face corner '3/1/1/1' is not v, v/vt, v//vn or v/vt/vn");
    parse_fails(TRIANGLE "f 1 2 /3\n",
                "x.obj:4: face corner '/3' is not v, v/vt, v//vn or v/vt/vn");
    parse_fails(TRIANGLE "f 1 2 3/\n",
                "x.obj:4: face corner '3/' is not v, v/vt, v//vn or v/vt/vn");
}

static void face_with_two_corners_is_an_error(void **state)
{
    (void)state;
    parse_fails(TRIANGLE "f 1 2\n", "x.obj:4: face has 2 corners (at least 3 needed)");
    parse_fails(TRIANGLE "f\n", "x.obj:4: face has 0 corners (at least 3 needed)");
}

static void face_with_too_many_corners_is_an_error(void **state)
{
    (void)state;
    /* MESH_MAX_FACE_VERTICES + 1 = 4097 corners, "1 " each. */
    int n = MESH_MAX_FACE_VERTICES + 1;
    char *text = malloc(64 + 2 * (size_t)n);
    assert_non_null(text);
    strcpy(text, TRIANGLE "f");
    char *p = text + strlen(text);
    for (int i = 0; i < n; i++) {
        memcpy(p, " 1", 2);
        p += 2;
    }
    strcpy(p, "\n");
    parse_fails(text, "x.obj:4: face has 4097 corners (at most 4096)");
    free(text);
}

static void non_finite_coordinates_are_errors(void **state)
{
    (void)state;
    parse_fails("v 0 0 0\nv nan 0 0\n", "x.obj:2: vertex coordinate 'nan' is not a finite number");
    parse_fails("v 0 inf 0\n", "x.obj:1: vertex coordinate 'inf' is not a finite number");
    parse_fails("v 0 0 -Infinity\n",
                "x.obj:1: vertex coordinate '-Infinity' is not a finite number");
}

static void huge_coordinates_are_errors(void **state)
{
    (void)state;
    /* OBJ_MAX_COORDINATE = 1e30 is printed by %g as 1e+30. */
    parse_fails("v 1e300 0 0\n",
                "x.obj:1: vertex coordinate '1e300' is out of range (|x| <= 1e+30)");
    parse_fails("v 0 -2e30 0\n",
                "x.obj:1: vertex coordinate '-2e30' is out of range (|x| <= 1e+30)");
    /* 1e400 is not even a double: strtod overflows. */
    parse_fails("v 0 0 1e400\n",
                "x.obj:1: vertex coordinate '1e400' is out of range (|x| <= 1e+30)");
    Mesh m; /* the limit itself is allowed */
    parse_ok(&m, "v 1e30 0 0\nv 0 -1e30 0\nv 0 0 1\nf 1 2 3\n");
    mesh_free(&m);
}

static void words_that_are_not_numbers_are_errors(void **state)
{
    (void)state;
    parse_fails("v 1 x 2\n", "x.obj:1: vertex coordinate 'x' is not a number");
    parse_fails("v 1 2 3x\n", "x.obj:1: vertex coordinate '3x' is not a number");
    parse_fails("v 1 2\n", "x.obj:1: 'v' takes 3 or 4 numbers (x y z [w]), found 2");
    parse_fails("v 1 2 3 4 5\n", "x.obj:1: 'v' takes 3 or 4 numbers (x y z [w]), found 5");
    /* A long word is cut to 40 characters in the message. */
    char text[256] = "v 1 2 ";
    for (int i = 0; i < 100; i++)
        strcat(text, "a");
    parse_fails(text, "x.obj:1: vertex coordinate "
                      "'aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa...' is not a number");
}

static void nul_byte_is_an_error(void **state)
{
    (void)state;
    const char text[] = "v 0 0 0\nv 1\0 0 0\nv 0 1 0\nf 1 2 3\n";
    parse_fails_len(text, sizeof text - 1, "x.obj:2: NUL byte in line");
}

static void file_without_faces_is_an_error(void **state)
{
    (void)state;
    parse_fails(TRIANGLE, "x.obj: no faces");
    parse_fails("", "x.obj: no faces");
    parse_fails("# only a comment\n", "x.obj: no faces");
}

/* ---- Building by hand ---- */

static void add_face_refuses_bad_input(void **state)
{
    (void)state;
    Mesh m;
    Error err;
    mesh_init(&m);
    for (int i = 0; i < 3; i++)
        assert_int_equal(mesh_add_vertex(&m, vec3(i, i * i, 0), &err), i);
    const int ok[3] = {0, 1, 2}, bad[3] = {0, 1, 3};
    assert_int_equal(mesh_add_face(&m, bad, 3, -1, &err), -1);
    assert_string_equal(err.msg, "face corner 2 uses vertex 3, but the vertices are 0 to 2");
    assert_int_equal(mesh_add_face(&m, ok, 2, -1, &err), -1);
    assert_int_equal(mesh_add_face(&m, ok, 3, 0, &err), -1); /* no material 0 yet */
    assert_int_equal(mesh_add_face(&m, ok, 3, -1, &err), 0);
    assert_int_equal(mesh_add_vertex(&m, vec3(NAN, 0, 0), &err), -1);
    assert_int_equal(mesh_add_material(&m, "", vec3(1, 1, 1), &err), -1);
    assert_int_equal(mesh_add_material(&m, "has # sign", vec3(1, 1, 1), &err), -1);
    assert_int_equal(mesh_add_material(&m, "ok", vec3(1, 1, 1), &err), 0);
    assert_int_equal(m.nfaces, 1);
    mesh_free(&m);
}

/* ---- Writing ---- */

static void write_then_read_gives_the_same_mesh(void **state)
{
    (void)state;
    const char *dir = test_dir("mesh_round_trip");
    char obj[512];
    snprintf(obj, sizeof obj, "%s", path_join(dir, "out.obj"));
    Mesh m;
    Error err;
    mesh_init(&m);
    /* Coordinates that need all 17 digits, and a name with a space. */
    const Vec3 p[5] = {{0.1, 0.2, 0.3}, {1.0 / 3, -2.0 / 7, 1e-9}, {1e29, 0, -1},
                       {0, 1, 0}, {-0.5, 0.5, 0.25}};
    for (int i = 0; i < 5; i++)
        mesh_add_vertex(&m, p[i], &err);
    int red = mesh_add_material(&m, "dark red", vec3(0.5, 0.1, 0.1), &err);
    int plain = mesh_add_material(&m, "plain", vec3(0, 0, 0), &err);
    m.materials[plain].has_kd = false;
    const int quad[4] = {0, 1, 2, 3}, tri[3] = {4, 3, 0}, tri2[3] = {1, 2, 4};
    assert_int_equal(mesh_add_face(&m, quad, 4, red, &err), 0);
    assert_int_equal(mesh_add_face(&m, tri, 3, -1, &err), 1);
    assert_int_equal(mesh_add_face(&m, tri2, 3, plain, &err), 2);
    if (!mesh_write_obj(&m, obj, &err))
        fail_msg("%s", err.msg);
    assert_true(file_exists(path_join(dir, "out.mtl")));

    Mesh back;
    mesh_init(&back);
    if (!mesh_load_obj(&back, obj, &err))
        fail_msg("%s", err.msg);
    assert_int_equal(back.nwarnings, 0);
    assert_int_equal(back.nverts, 5);
    for (int i = 0; i < 5; i++)
        if (memcmp(&back.verts[i], &m.verts[i], sizeof(Vec3)) != 0)
            fail_msg("vertex %d came back as (%.17g, %.17g, %.17g)", i, back.verts[i].x,
                     back.verts[i].y, back.verts[i].z);
    assert_int_equal(back.nfaces, 3);
    assert_corners(&back, 0, quad, 4);
    assert_corners(&back, 1, tri, 3);
    assert_corners(&back, 2, tri2, 3);
    assert_int_equal(back.faces[0].material, 0);
    assert_int_equal(back.faces[1].material, -1);
    assert_int_equal(back.faces[2].material, 1);
    assert_string_equal(back.materials[0].name, "dark red");
    assert_true(back.materials[0].has_kd && back.materials[0].kd.x == 0.5 &&
                back.materials[0].kd.y == 0.1);
    assert_false(back.materials[1].has_kd);
    mesh_free(&back);
    mesh_free(&m);
}

static void mesh_without_materials_writes_no_mtl(void **state)
{
    (void)state;
    const char *dir = test_dir("mesh_no_materials");
    char obj[512];
    snprintf(obj, sizeof obj, "%s", path_join(dir, "plain.obj"));
    Mesh m;
    Error err;
    parse_ok(&m, TRIANGLE "f 1 2 3\n");
    assert_true(mesh_write_obj(&m, obj, &err));
    assert_false(file_exists(path_join(dir, "plain.mtl")));
    char *text = NULL;
    size_t len = 0;
    FILE *fp = fopen(obj, "rb");
    assert_non_null(fp);
    text = calloc(1, 4096);
    len = fread(text, 1, 4095, fp);
    fclose(fp);
    assert_true(len > 0);
    assert_null(strstr(text, "mtllib"));
    assert_non_null(strstr(text, "\nv 1 0 0\n")); /* 1.0 is written "1", not 17 digits */
    assert_non_null(strstr(text, "\nf 1 2 3\n"));
    free(text);
    mesh_free(&m);
}

static void write_to_a_missing_directory_fails_cleanly(void **state)
{
    (void)state;
    const char *dir = test_dir("mesh_write_fail");
    char obj[512];
    snprintf(obj, sizeof obj, "%s", path_join(dir, "no/such/dir/x.obj"));
    Mesh m;
    Error err = {""};
    parse_ok(&m, TRIANGLE "f 1 2 3\n");
    assert_false(mesh_write_obj(&m, obj, &err));
    assert_non_null(strstr(err.msg, "no/such/dir/x.obj"));
    mesh_free(&m);
}


/* The file at path holds exactly text. */
static void expect_text(const char *path, const char *text)
{
    char *got = read_text(path);
    assert_string_equal(got, text);
    free(got);
}

/* The .mtl and the OBJ are published together: an OBJ that cannot be
 * written leaves no new .mtl and an existing one as it was, and a .mtl that
 * is the OBJ under another name (a link) is refused, the OBJ kept. */
static void obj_and_mtl_are_written_both_or_neither(void **state)
{
    (void)state;
    const char *dir = test_dir("mesh_write_both_or_neither");
    char obj[512], mtl[512];
    Mesh m;
    Error err = {""};
    mesh_init(&m);
    const Vec3 p[3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    for (int i = 0; i < 3; i++)
        mesh_add_vertex(&m, p[i], &err);
    int red = mesh_add_material(&m, "red", vec3(1, 0, 0), &err);
    const int tri[3] = {0, 1, 2};
    assert_int_equal(mesh_add_face(&m, tri, 3, red, &err), 0);

    /* The OBJ is a directory: no .mtl appears. */
    snprintf(obj, sizeof obj, "%s", path_join(dir, "d.obj"));
    snprintf(mtl, sizeof mtl, "%s", path_join(dir, "d.mtl"));
    assert_int_equal(mkdir(obj, 0755), 0);
    assert_false(mesh_write_obj(&m, obj, &err));
    assert_non_null(strstr(err.msg, "d.obj"));
    assert_false(file_exists(mtl));

    /* The OBJ is read-only: the .mtl beside it keeps its bytes. */
    snprintf(obj, sizeof obj, "%s", path_join(dir, "ro.obj"));
    snprintf(mtl, sizeof mtl, "%s", path_join(dir, "ro.mtl"));
    write_text(obj, "read-only\n");
    assert_int_equal(chmod(obj, 0444), 0);
    write_text(mtl, "precious\n");
    assert_false(mesh_write_obj(&m, obj, &err));
    expect_text(mtl, "precious\n");

    /* The .mtl is a link to the OBJ: refused, the OBJ as it was. */
    snprintf(obj, sizeof obj, "%s", path_join(dir, "x.obj"));
    snprintf(mtl, sizeof mtl, "%s", path_join(dir, "x.mtl"));
    write_text(obj, "old\n");
    assert_int_equal(symlink("x.obj", mtl), 0);
    err.msg[0] = '\0';
    assert_false(mesh_write_obj(&m, obj, &err));
    assert_non_null(strstr(err.msg, "is the same file"));
    expect_text(obj, "old\n");
    mesh_free(&m);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(every_corner_form_is_read),
        cmocka_unit_test(negative_indices_count_back_from_the_last_vertex),
        cmocka_unit_test(polygons_keep_all_their_corners),
        cmocka_unit_test(face_index_is_position_in_file),
        cmocka_unit_test(names_groups_and_smoothing_are_accepted_silently),
        cmocka_unit_test(fourth_coordinate_w_is_accepted),
        cmocka_unit_test(comments_blank_lines_crlf_and_odd_white_space_are_read),
        cmocka_unit_test(a_very_long_line_is_read_whole),
        cmocka_unit_test(parse_replaces_the_mesh_and_failure_keeps_it),
        cmocka_unit_test(unsupported_statements_are_warned_about),
        cmocka_unit_test(many_warnings_end_with_a_count),
        cmocka_unit_test(unknown_material_is_a_warning_and_no_material),
        cmocka_unit_test(vertex_colours_are_read_past_with_a_warning),
        cmocka_unit_test(kd_is_read_from_the_mtl_beside_the_obj),
        cmocka_unit_test(missing_mtl_is_a_warning),
        cmocka_unit_test(mtl_oddities_are_warnings),
        cmocka_unit_test(bad_kd_is_an_error_naming_the_mtl_line),
        cmocka_unit_test(missing_obj_file_names_the_path),
        cmocka_unit_test(index_zero_is_an_error),
        cmocka_unit_test(index_past_the_last_vertex_is_an_error),
        cmocka_unit_test(negative_index_before_the_first_vertex_is_an_error),
        cmocka_unit_test(index_of_a_vertex_defined_later_is_an_error),
        cmocka_unit_test(index_too_big_for_an_int_is_out_of_range),
        cmocka_unit_test(texture_and_normal_indices_are_checked),
        cmocka_unit_test(malformed_corners_are_errors),
        cmocka_unit_test(face_with_two_corners_is_an_error),
        cmocka_unit_test(face_with_too_many_corners_is_an_error),
        cmocka_unit_test(non_finite_coordinates_are_errors),
        cmocka_unit_test(huge_coordinates_are_errors),
        cmocka_unit_test(words_that_are_not_numbers_are_errors),
        cmocka_unit_test(nul_byte_is_an_error),
        cmocka_unit_test(file_without_faces_is_an_error),
        cmocka_unit_test(add_face_refuses_bad_input),
        cmocka_unit_test(write_then_read_gives_the_same_mesh),
        cmocka_unit_test(mesh_without_materials_writes_no_mtl),
        cmocka_unit_test(write_to_a_missing_directory_fails_cleanly),
        cmocka_unit_test(obj_and_mtl_are_written_both_or_neither),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
