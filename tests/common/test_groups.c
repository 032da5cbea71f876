/* test_groups.c: OBJ objects and groups, per face (common/harness/mesh_build.c, common/harness/obj.c).
 *
 * Later lessons pick faces by name (`decal` for --polygon-offset, `cutout`
 * for alpha-tested faces): a face is in the object of the last `o` line before
 * it and in the groups of the last `g` line. These tests read small files whose
 * membership is written out by hand next to them, check the API that asks,
 * the writer that carries the names back, and the errors bad names meet. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "harness/mesh_build.h"
#include "test_support.h"

#define TRIANGLE "v 0 0 0\nv 1 0 0\nv 0 1 0\n"

static void parse_ok(Mesh *m, const char *text)
{
    Error err;
    mesh_init(m);
    if (!mesh_parse_obj(m, text, strlen(text), "x.obj", NULL, &err))
        fail_msg("parsing failed: %s\n--- text ---\n%.400s", err.msg, text);
}

static void parse_fails(const char *text, const char *expected)
{
    Mesh m;
    Error err = {"(no message)"};
    mesh_init(&m);
    if (mesh_parse_obj(&m, text, strlen(text), "x.obj", NULL, &err))
        fail_msg("parsing succeeded, expected the error \"%s\"", expected);
    if (strcmp(err.msg, expected) != 0)
        fail_msg("wrong message\n  got:      \"%s\"\n  expected: \"%s\"", err.msg, expected);
    assert_int_equal(m.nfaces, 0);
    mesh_free(&m);
}

/* Face f is in exactly the names listed in `in` (space-separated) among
 * those of `asked` (and never in the empty name). */
static void expect_membership(const Mesh *m, int f, const char *const *asked, const char *in)
{
    for (int k = 0; asked[k]; k++) {
        char padded_in[256], padded_name[80];
        snprintf(padded_in, sizeof padded_in, " %s ", in);
        snprintf(padded_name, sizeof padded_name, " %s ", asked[k]);
        bool want = asked[k][0] != '\0' && strstr(padded_in, padded_name) != NULL;
        if (mesh_face_in(m, f, asked[k]) != want)
            fail_msg("face %d: mesh_face_in(\"%s\") is %s, expected %s", f, asked[k],
                     want ? "false" : "true", want ? "true" : "false");
    }
}

/* ---- reading ---- */

static const char *const ASKED[] = {"thing", "other", "part", "one", "two", "decal",
                                    "default", "", NULL};

static void faces_get_the_last_o_and_the_last_g_before_them(void **state)
{
    (void)state;
    Mesh m;
    parse_ok(&m, TRIANGLE
             "f 1 2 3\n"          /* 0: before any name */
             "o thing\n"
             "f 1 2 3\n"          /* 1: thing */
             "g part one\n"
             "f 1 2 3\n"          /* 2: thing, part, one */
             "o other\n"
             "f 1 2 3\n"          /* 3: other, part, one (o leaves the groups) */
             "g two\n"
             "s 1\n"
             "usemtl\n"
             "f 1 2 3\n"          /* 4: other, two */
             "g\n"
             "f 1 2 3\n"          /* 5: other only (a bare g: no group) */
             "o\n"
             "f 1 2 3\n"          /* 6: nothing (a bare o: no object) */
             "g decal\n"
             "o thing\n"
             "f 1 2 3\n");        /* 7: thing, decal */
    assert_int_equal(m.nfaces, 8);
    assert_int_equal(m.nwarnings, 0);
    const char *in[8] = {"", "thing", "thing part one", "other part one", "other two",
                         "other", "", "thing decal"};
    for (int f = 0; f < 8; f++)
        expect_membership(&m, f, ASKED, in[f]);
    assert_int_equal(m.faces[0].names, -1);
    assert_int_equal(m.faces[6].names, -1);
    mesh_free(&m);
}

static void windows_line_endings_tabs_and_comments_do_not_change_names(void **state)
{
    (void)state;
    Mesh m;
    parse_ok(&m, TRIANGLE "o  my thing \r\n" "g\tpart\t one\r\n" "f 1 2 3\r\n"
             "g decal # a comment\r\n" "f 1 2 3\r\n" "g \r\n" "f 1 2 3\r\n");
    assert_int_equal(m.nfaces, 3);
    const char *const asked[] = {"my", "thing", "part", "one", "decal", "#", "a",
                                 "part\r", "one\r", NULL};
    expect_membership(&m, 0, asked, "part one");
    assert_true(mesh_face_in(&m, 0, "my thing")); /* o takes the rest of the line */
    expect_membership(&m, 1, asked, "decal");
    assert_true(mesh_face_in(&m, 1, "my thing"));
    expect_membership(&m, 2, asked, "");
    assert_true(mesh_face_in(&m, 2, "my thing"));
    assert_string_equal(m.sets[m.faces[0].names].object, "my thing");
    mesh_free(&m);
}

static void a_group_named_twice_counts_once(void **state)
{
    (void)state;
    Mesh m;
    parse_ok(&m, TRIANGLE "g a b a b a\nf 1 2 3\n");
    const NameSet *set = &m.sets[m.faces[0].names];
    assert_int_equal(set->ngroups, 2);
    assert_string_equal(set->groups[0], "a");
    assert_string_equal(set->groups[1], "b");
    assert_null(set->object);
    mesh_free(&m);
}

static void faces_after_an_unused_name_line_are_read_as_usual(void **state)
{
    (void)state;
    /* g lines with no face after them, and names given before any vertex. */
    Mesh m;
    parse_ok(&m, "g early\no first\ng\n" TRIANGLE "g x\ng y\nf 1 2 3\n");
    expect_membership(&m, 0, ASKED, "");
    assert_true(mesh_face_in(&m, 0, "first"));
    assert_true(mesh_face_in(&m, 0, "y"));
    assert_false(mesh_face_in(&m, 0, "x"));
    assert_false(mesh_face_in(&m, 0, "early"));
    mesh_free(&m);
}

/* ---- bad names ---- */

static void a_too_long_group_name_is_an_error_at_its_line(void **state)
{
    (void)state;
    size_t n = 1 << 20; /* a megabyte of name */
    char *text = malloc(n + 64);
    assert_non_null(text);
    strcpy(text, TRIANGLE "g ");
    size_t used = strlen(text);
    memset(text + used, 'a', n);
    strcpy(text + used + n, "\nf 1 2 3\n");
    parse_fails(text, "x.obj:4: group name 'aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa...' is too long "
                      "(at most 255 bytes)");
    /* 255 bytes is still a name. */
    strcpy(text + used + 255, "\nf 1 2 3\n");
    Mesh m;
    parse_ok(&m, text);
    assert_int_equal((int)strlen(m.sets[m.faces[0].names].groups[0]), 255);
    mesh_free(&m);
    free(text);
}

static void too_many_groups_on_one_line_is_an_error(void **state)
{
    (void)state;
    char text[4096] = TRIANGLE "o x\nv 1 1 1\ng";
    for (int k = 0; k < 65; k++)
        snprintf(text + strlen(text), sizeof text - strlen(text), " g%d", k);
    strcat(text, "\nf 1 2 3\n");
    parse_fails(text, "x.obj:6: 'g' names 65 groups (at most 64)");
}

static void too_long_object_name_is_an_error(void **state)
{
    (void)state;
    char text[1024] = TRIANGLE "f 1 2 3\no ";
    size_t used = strlen(text);
    memset(text + used, 'b', 300);
    strcpy(text + used + 300, "\n");
    parse_fails(text, "x.obj:5: object name 'bbbbbbbbbbbbbbbbbbbbbbbbbbbbbbbb...' is too long "
                      "(at most 255 bytes)");
}

static void a_million_group_changes_meet_a_limit_not_the_memory(void **state)
{
    (void)state;
    /* Each `g` line makes a new set of names; after MESH_MAX_NAME_SETS the
     * reader stops with an error naming the line. */
    int lines = MESH_MAX_NAME_SETS + 1;
    const char *line = "g a b\n";
    size_t n = strlen(TRIANGLE) + (size_t)lines * strlen(line) + 16;
    char *text = malloc(n);
    assert_non_null(text);
    char *p = text + sprintf(text, TRIANGLE);
    for (int k = 0; k < lines; k++)
        p += sprintf(p, "%s", line);
    strcpy(p, "f 1 2 3\n");
    char expected[128];
    snprintf(expected, sizeof expected,
             "x.obj:%d: too many object and group changes (at most %d)", 3 + lines,
             MESH_MAX_NAME_SETS);
    parse_fails(text, expected);
    free(text);
}

static void mesh_add_names_refuses_what_a_file_cannot_hold(void **state)
{
    (void)state;
    Mesh m;
    Error err;
    mesh_init(&m);
    const char *spaced[] = {"a b"};
    const char *empty[] = {""};
    const char *hash[] = {"a#b"};
    const char *ok[] = {"decal", "decal", "cutout"};
    assert_int_equal(mesh_add_names(&m, NULL, spaced, 1, &err), -1);
    assert_string_equal(err.msg, "group name 'a b' has a character an OBJ file cannot hold");
    assert_int_equal(mesh_add_names(&m, NULL, empty, 1, &err), -1);
    assert_string_equal(err.msg, "a group needs a name");
    assert_int_equal(mesh_add_names(&m, NULL, hash, 1, &err), -1);
    assert_int_equal(mesh_add_names(&m, " lead", NULL, 0, &err), -1);
    assert_string_equal(err.msg, "object name ' lead' starts or ends with white space");
    assert_int_equal(mesh_add_names(&m, "x\ny", NULL, 0, &err), -1);
    assert_int_equal(mesh_add_names(&m, NULL, ok, MESH_MAX_GROUPS + 1, &err), -1);
    assert_int_equal(m.nsets, 0); /* nothing half-made is kept */
    assert_int_equal((int)m.name_bytes, 0);
    assert_int_equal(mesh_add_names(&m, "a poster", ok, 3, &err), 0);
    assert_int_equal(m.sets[0].ngroups, 2);
    mesh_free(&m);
}

static void faces_made_by_hand_are_in_no_group_until_named(void **state)
{
    (void)state;
    Mesh m;
    Error err;
    mesh_init(&m);
    for (int i = 0; i < 3; i++)
        mesh_add_vertex(&m, vec3(i == 1, i == 2, 0), &err);
    const int tri[3] = {0, 1, 2};
    const char *decal[] = {"decal"};
    int f0 = mesh_add_face(&m, tri, 3, -1, &err);
    int f1 = mesh_add_face(&m, tri, 3, -1, &err);
    assert_int_equal(m.faces[f0].names, -1);
    m.faces[f1].names = mesh_add_names(&m, NULL, decal, 1, &err);
    assert_false(mesh_face_in(&m, f0, "decal"));
    assert_true(mesh_face_in(&m, f1, "decal"));
    assert_false(mesh_face_in(&m, f1, "deca"));
    assert_false(mesh_face_in(&m, f1, "decals"));
    assert_false(mesh_face_in(&m, -1, "decal")); /* no such face: in nothing */
    assert_false(mesh_face_in(&m, 2, "decal"));
    mesh_free(&m);
}

/* ---- writing and reading back ---- */

static char *write_and_read_text(const Mesh *m, const char *dir, const char *file)
{
    Error err;
    char obj[512];
    snprintf(obj, sizeof obj, "%s", path_join(dir, file));
    if (!mesh_write_obj(m, obj, &err))
        fail_msg("%s", err.msg);
    return read_text(obj);
}

static void names_survive_a_round_trip(void **state)
{
    (void)state;
    const char *text = TRIANGLE "f 1 2 3\no thing\ng part one\nf 1 2 3\nf 1 2 3\n"
                                "o the other\nf 1 2 3\ng\nf 3 2 1\no\ng decal\nf 1 2 3\n"
                                "g part one\nf 1 2 3\n";
    Mesh m;
    parse_ok(&m, text);
    const char *dir = test_dir("groups_round_trip");
    char *written = write_and_read_text(&m, dir, "groups.obj");
    /* The writer writes a line only where the names change. */
    const char *faces_and_names =
        "f 1 2 3\no thing\ng part one\nf 1 2 3\nf 1 2 3\no the other\nf 1 2 3\ng\nf 3 2 1\n"
        "o\ng decal\nf 1 2 3\ng part one\nf 1 2 3\n";
    if (!strstr(written, faces_and_names))
        fail_msg("written file:\n%s\nexpected it to end with:\n%s", written, faces_and_names);
    Mesh back;
    parse_ok(&back, written);
    assert_int_equal(back.nfaces, m.nfaces);
    const char *const asked[] = {"thing", "the other", "part", "one", "decal", NULL};
    const char *in[7] = {"", "thing part one", "thing part one", "the other part one",
                         "the other", "decal", "part one"};
    for (int f = 0; f < 7; f++) {
        expect_membership(&m, f, asked, in[f]);
        expect_membership(&back, f, asked, in[f]);
    }
    /* "the other" is an object name with a space: only the object has it. */
    assert_true(mesh_face_in(&back, 3, "the other"));
    assert_false(mesh_face_in(&back, 3, "the"));
    free(written);
    mesh_free(&back);
    mesh_free(&m);
}

static void a_mesh_without_names_writes_no_o_or_g(void **state)
{
    (void)state;
    Mesh m;
    parse_ok(&m, TRIANGLE "f 1 2 3\nf 3 2 1\n");
    char *written = write_and_read_text(&m, test_dir("groups_none"), "plain.obj");
    assert_null(strstr(written, "\no"));
    assert_null(strstr(written, "\ng"));
    free(written);
    mesh_free(&m);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(faces_get_the_last_o_and_the_last_g_before_them),
        cmocka_unit_test(windows_line_endings_tabs_and_comments_do_not_change_names),
        cmocka_unit_test(a_group_named_twice_counts_once),
        cmocka_unit_test(faces_after_an_unused_name_line_are_read_as_usual),
        cmocka_unit_test(a_too_long_group_name_is_an_error_at_its_line),
        cmocka_unit_test(too_many_groups_on_one_line_is_an_error),
        cmocka_unit_test(too_long_object_name_is_an_error),
        cmocka_unit_test(a_million_group_changes_meet_a_limit_not_the_memory),
        cmocka_unit_test(mesh_add_names_refuses_what_a_file_cannot_hold),
        cmocka_unit_test(faces_made_by_hand_are_in_no_group_until_named),
        cmocka_unit_test(names_survive_a_round_trip),
        cmocka_unit_test(a_mesh_without_names_writes_no_o_or_g),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
