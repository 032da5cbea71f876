/* test_make_obj.c: the make_obj tool writes the built-in scenes as OBJ files
 * that read back as the same meshes, and refuses bad command lines. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <stdio.h>
#include <string.h>

#include <stdlib.h>
#include <unistd.h>

#include "harness/mesh_build.h"
#include "harness/scene.h"
#include "shell.h"
#include "test_support.h"

static void assert_usage_error(const char *const *args, const char *expected_line)
{
    RunResult r = run_tool("make_obj", args);
    if (r.status != 2 || strcmp(r.err, expected_line) != 0)
        fail_msg("status %d, stderr \"%s\"; expected status 2 and \"%s\"", r.status, r.err,
                 expected_line);
    assert_string_equal(r.out, "");
    run_result_free(&r);
}

static const NameSet NO_NAMES = {0};

static const NameSet *names_of(const Mesh *m, int f)
{
    return m->faces[f].names >= 0 ? &m->sets[m->faces[f].names] : &NO_NAMES;
}

/* The object and groups of face f, as built and as read back (the sets may be
 * numbered differently: the writer writes names only where they change). */
static void expect_same_names(const char *scene, int f, const Mesh *built, const Mesh *read)
{
    const NameSet *a = names_of(built, f), *b = names_of(read, f);
    bool same = (a->object == NULL) == (b->object == NULL) && a->ngroups == b->ngroups &&
                (!a->object || strcmp(a->object, b->object) == 0);
    for (int k = 0; same && k < a->ngroups; k++)
        same = strcmp(a->groups[k], b->groups[k]) == 0;
    if (!same)
        fail_msg("scene %s, face %d: object and groups did not come back as built", scene, f);
}

static void every_scene_reads_back_as_itself(void **state)
{
    (void)state;
    const char *dir = test_dir("make_obj_scenes");
    for (int i = 0; i < scene_count(); i++) {
        const SceneInfo *s = scene_at(i);
        char obj[512], file[128];
        snprintf(file, sizeof file, "%s.obj", s->name);
        snprintf(obj, sizeof obj, "%s", path_join(dir, file));
        const char *args[] = {s->name, obj, NULL};
        RunResult r = run_tool("make_obj", args);
        if (r.status != 0)
            fail_msg("make_obj %s: status %d, %s", s->name, r.status, r.err);
        run_result_free(&r);

        Mesh built, read;
        Error err;
        mesh_init(&built);
        mesh_init(&read);
        assert_true(s->build(&built, &err));
        if (!mesh_load_obj(&read, obj, &err))
            fail_msg("%s", err.msg);
        assert_int_equal(read.nwarnings, 0);
        assert_int_equal(read.nverts, built.nverts);
        assert_int_equal(read.nfaces, built.nfaces);
        assert_int_equal(read.ncorners, built.ncorners);
        assert_int_equal(read.nmaterials, built.nmaterials);
        assert_memory_equal(read.verts, built.verts, sizeof(Vec3) * (size_t)built.nverts);
        assert_memory_equal(read.corners, built.corners, sizeof(int) * (size_t)built.ncorners);
        for (int f = 0; f < built.nfaces; f++) {
            assert_int_equal(read.faces[f].count, built.faces[f].count);
            assert_int_equal(read.faces[f].material, built.faces[f].material);
            expect_same_names(s->name, f, &built, &read);
        }
        for (int k = 0; k < built.nmaterials; k++) {
            assert_string_equal(read.materials[k].name, built.materials[k].name);
            assert_memory_equal(&read.materials[k].kd, &built.materials[k].kd, sizeof(Vec3));
        }
        mesh_free(&built);
        mesh_free(&read);
    }
}

static void knot_takes_rings_and_sides(void **state)
{
    (void)state;
    const char *dir = test_dir("make_obj_knot");
    char obj[512];
    snprintf(obj, sizeof obj, "%s", path_join(dir, "knot.obj"));
    const char *args[] = {"knot", obj, "20", "5", NULL};
    RunResult r = run_tool("make_obj", args);
    assert_int_equal(r.status, 0);
    run_result_free(&r);
    Mesh m;
    Error err;
    mesh_init(&m);
    if (!mesh_load_obj(&m, obj, &err))
        fail_msg("%s", err.msg);
    assert_int_equal(m.nfaces, 20 * 5); /* one quad per ring and side */
    assert_int_equal(m.nverts, 20 * 5);
    mesh_free(&m);
}

static void bad_command_lines_are_usage_errors(void **state)
{
    (void)state;
    const char *none[] = {NULL};
    assert_usage_error(none, "make_obj: error: expected SCENE OUT.obj, or knot OUT.obj RINGS "
                             "SIDES (try --help)\n");
    const char *unknown[] = {"nope", "x.obj", NULL};
    assert_usage_error(unknown, "make_obj: error: no scene named 'nope' (try --help)\n");
    const char *not_knot[] = {"cubes", "x.obj", "10", "10", NULL};
    assert_usage_error(not_knot,
                       "make_obj: error: RINGS and SIDES are for the knot only, not 'cubes' "
                       "(try --help)\n");
    const char *bad_sides[] = {"knot", "x.obj", "10", "2", NULL};
    assert_usage_error(bad_sides,
                       "make_obj: error: SIDES must be an integer from 3 to 4096, not '2' "
                       "(try --help)\n");
    const char *bad_rings[] = {"knot", "x.obj", "1e3", "10", NULL};
    assert_usage_error(bad_rings,
                       "make_obj: error: RINGS must be an integer from 3 to 1000000, not '1e3' "
                       "(try --help)\n");
    assert_false(file_exists("x.obj"));
}

static void unwritable_output_fails_with_status_1(void **state)
{
    (void)state;
    const char *dir = test_dir("make_obj_unwritable");
    char obj[512], expected[700];
    snprintf(obj, sizeof obj, "%s", path_join(dir, "missing/x.obj"));
    const char *args[] = {"triangles3", obj, NULL};
    RunResult r = run_tool("make_obj", args);
    assert_int_equal(r.status, 1);
    /* The .mtl is written first, so it is the one named. */
    snprintf(expected, sizeof expected,
             "make_obj: error: cannot write %s/missing/x.mtl: No such file or directory\n", dir);
    assert_string_equal(r.err, expected);
    run_result_free(&r);
}

/* OUT.obj on standard output ("-", or /dev/stdout sent to a file): its .mtl
 * has no place beside it. It was written as "-.mtl" in the current directory
 * (and /dev/stdout.mtl, /dev/null.mtl in /dev), the OBJ named it, and the
 * summary line went into the OBJ on standard output. Now the OBJ goes out
 * alone, without mtllib or usemtl, it reads back, and a warning says so. */
static void standard_output_gets_the_obj_alone(void **state)
{
    (void)state;
    const char *dir = test_dir("make_obj_stdout");
    char here[4096], tools[4096 + 64];
    if (!getcwd(here, sizeof here))
        fail_msg("getcwd failed");
    const char *tool_dir = getenv("TOOL_DIR") ? getenv("TOOL_DIR") : "build/tools";
    snprintf(tools, sizeof tools, "%s%s%s", tool_dir[0] == '/' ? "" : here,
             tool_dir[0] == '/' ? "" : "/", tool_dir);
    const char *names[] = {"-", "/dev/stdout"};
    for (int i = 0; i < 2; i++) {
        ShellResult r = run_shell(dir, 60, "'%s/make_obj' cubes %s >m.obj 2>err.txt; echo $?; "
                                           "ls -A; cat err.txt",
                                  tools, names[i]);
        char want[512];
        snprintf(want, sizeof want,
                 "0\nerr.txt\nm.obj\n"
                 "make_obj: warning: %s is not a file: the OBJ is written without its 4 materials "
                 "(a .mtl has no place beside it)\n"
                 "%s: 28 vertices, 19 faces, 0 materials\n",
                 names[i], names[i]);
        if (strcmp(r.output, want) != 0)
            fail_msg("make_obj cubes %s >m.obj:\n%s\nwant:\n%s", names[i], r.output, want);
        shell_result_free(&r);
        char *obj = read_text(path_join(dir, "m.obj"));
        if (strstr(obj, "mtl") || strstr(obj, "vertices, 19 faces, 0"))
            fail_msg("the OBJ on standard output names a .mtl or holds the summary:\n%.300s", obj);
        free(obj);
        Mesh m;
        mesh_init(&m);
        Error err;
        if (!mesh_load_obj(&m, path_join(dir, "m.obj"), &err))
            fail_msg("m.obj does not read back: %s", err.msg);
        assert_int_equal(m.nfaces, 19);
        mesh_free(&m);
        remove(path_join(dir, "m.obj"));
        remove(path_join(dir, "err.txt"));
    }
}

static void help_lists_the_scenes(void **state)
{
    (void)state;
    const char *args[] = {"--help", NULL};
    RunResult r = run_tool("make_obj", args);
    assert_int_equal(r.status, 0);
    assert_true(strncmp(r.out, "usage: make_obj SCENE OUT.obj\n", 30) == 0);
    for (int i = 0; i < scene_count(); i++)
        assert_non_null(strstr(r.out, scene_at(i)->name));
    run_result_free(&r);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(every_scene_reads_back_as_itself),
        cmocka_unit_test(knot_takes_rings_and_sides),
        cmocka_unit_test(bad_command_lines_are_usage_errors),
        cmocka_unit_test(unwritable_output_fails_with_status_1),
        cmocka_unit_test(standard_output_gets_the_obj_alone),
        cmocka_unit_test(help_lists_the_scenes),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
