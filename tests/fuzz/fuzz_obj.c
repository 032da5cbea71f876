/* fuzz_obj.c: the OBJ and MTL reader (common/harness/obj.c, mesh.c, triangulate.c)
 * against any bytes (make fuzz FUZZ=obj).
 *
 * The input is an OBJ file; if it holds a line "#mtl", what follows that
 * line is also written as "f.mtl" beside it, so that `mtllib f.mtl` reads it.
 * Whatever the bytes, the reader must either fail with a message that names
 * the file (and no mesh), or return a mesh that holds together:
 *   - every face has 3 .. MESH_MAX_FACE_VERTICES corners and count - 2
 *     triangles, each corner a valid vertex, each triangle's corner numbers
 *     in 0 .. count - 1 and all different;
 *   - every vertex is finite and within OBJ_MAX_COORDINATE;
 *   - every face's names are -1 or a set, whose object and groups are
 *     non-empty names shorter than MESH_NAME_MAX, the groups all different
 *     and free of white space, and that mesh_face_in finds;
 *   - every warning and the error are one line starting "f.obj".
 * Sanitizers catch the rest: overflows, leaks, undefined behaviour. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include <unistd.h>

#include "harness/mesh_build.h"

static const char OBJ_NAME[] = "f.obj";
static const char MTL_MARK[] = "\n#mtl\n";

static char mtl_dir[64];
static char mtl_path[96];

static void check(bool ok, const char *what)
{
    if (!ok) {
        fprintf(stderr, "fuzz_obj: broken invariant: %s\n", what);
        abort();
    }
}

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc;
    (void)argv;
    snprintf(mtl_dir, sizeof mtl_dir, "/tmp/fuzz_obj.XXXXXX");
    if (!mkdtemp(mtl_dir))
        abort();
    snprintf(mtl_path, sizeof mtl_path, "%s/f.mtl", mtl_dir);
    return 0;
}

/* memmem is not in POSIX 2008. */
static const char *find(const char *hay, size_t n, const char *needle)
{
    size_t k = strlen(needle);
    for (size_t i = 0; i + k <= n; i++)
        if (memcmp(hay + i, needle, k) == 0)
            return hay + i;
    return NULL;
}

static void write_mtl(const char *bytes, size_t n)
{
    FILE *fp = fopen(mtl_path, "wb");
    if (!fp)
        abort();
    fwrite(bytes, 1, n, fp);
    fclose(fp);
}

static void check_message(const char *msg)
{
    check(strncmp(msg, OBJ_NAME, strlen(OBJ_NAME)) == 0 ||
              strncmp(msg, mtl_path, strlen(mtl_path)) == 0,
          "message names the file");
    check(strchr(msg, '\n') == NULL, "message is one line");
}

static void check_name(const char *name)
{
    size_t n = strlen(name);
    check(n > 0 && n < MESH_NAME_MAX, "name length");
}

static void check_names(const Mesh *m, int face, const NameSet *set)
{
    check(set->object || set->ngroups > 0, "a set names something");
    check(set->ngroups >= 0 && set->ngroups <= MESH_MAX_GROUPS, "group count");
    if (set->object) {
        check_name(set->object);
        check(mesh_face_in(m, face, set->object), "the face is in its object");
    }
    for (int k = 0; k < set->ngroups; k++) {
        check_name(set->groups[k]);
        check(strcspn(set->groups[k], " \t\v\f\r\n") == strlen(set->groups[k]),
              "a group name is one word");
        check(mesh_face_in(m, face, set->groups[k]), "the face is in its groups");
        for (int j = 0; j < k; j++)
            check(strcmp(set->groups[j], set->groups[k]) != 0, "groups differ");
    }
}

static void check_mesh(const Mesh *m)
{
    check(m->nfaces > 0, "a mesh read has faces");
    int tris = 0;
    for (int i = 0; i < m->nverts; i++) {
        Vec3 p = m->verts[i];
        check(isfinite(p.x) && isfinite(p.y) && isfinite(p.z), "vertex finite");
        check(fabs(p.x) <= OBJ_MAX_COORDINATE && fabs(p.y) <= OBJ_MAX_COORDINATE &&
                  fabs(p.z) <= OBJ_MAX_COORDINATE,
              "vertex within OBJ_MAX_COORDINATE");
    }
    for (int i = 0; i < m->nfaces; i++) {
        const Face *f = &m->faces[i];
        check(f->count >= 3 && f->count <= MESH_MAX_FACE_VERTICES, "face corner count");
        check(f->first >= 0 && f->first + f->count <= m->ncorners, "face corners in range");
        check(f->first_tri == tris, "triangles follow each other");
        check(f->material >= -1 && f->material < m->nmaterials, "material index");
        check(f->names >= -1 && f->names < m->nsets, "name set index");
        if (f->names >= 0)
            check_names(m, i, &m->sets[f->names]);
        for (int k = 0; k < f->count; k++) {
            int v = m->corners[f->first + k];
            check(v >= 0 && v < m->nverts, "corner names a vertex");
        }
        for (int k = 0; k < f->count - 2; k++) {
            const Tri *t = &m->tris[f->first_tri + k];
            for (int j = 0; j < 3; j++)
                check(t->c[j] >= 0 && t->c[j] < f->count, "triangle corner number");
            check(t->c[0] != t->c[1] && t->c[1] != t->c[2] && t->c[0] != t->c[2],
                  "triangle corners differ");
        }
        tris += f->count - 2;
    }
    check(tris == m->ntris, "count - 2 triangles per face");
    for (int i = 0; i < m->nwarnings; i++)
        check_message(m->warnings[i]);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const char *text = (const char *)data;
    const char *mark = find(text, size, MTL_MARK);
    size_t obj_len = size;
    if (mark) {
        size_t skip = (size_t)(mark - text) + strlen(MTL_MARK);
        write_mtl(text + skip, size - skip);
        obj_len = (size_t)(mark - text) + 1; /* keep the newline ending the OBJ */
    } else {
        unlink(mtl_path);
    }

    Mesh m;
    mesh_init(&m);
    Error err;
    err.msg[0] = '\0';
    if (mesh_parse_obj(&m, text, obj_len, OBJ_NAME, mtl_dir, &err)) {
        check_mesh(&m);
    } else {
        check(m.nfaces == 0 && m.nverts == 0, "a failed read leaves the mesh empty");
        check_message(err.msg);
    }
    mesh_free(&m);
    return 0;
}
