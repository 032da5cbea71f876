/* mesh.h: polygon meshes, the OBJ files they come from, and their triangles.
 *
 * A face keeps all its vertices (lesson 04 draws convex polygons as they are);
 * each face also carries its ear-clipped triangulation (lessons 02 and 03 draw
 * triangles), which is right for non-convex polygons too. A face's index is its
 * position in the OBJ file (or the built-in scene), counting from 0: --shade id
 * and --trace report it.
 *
 * OBJ: `v x y z [w]`; `f` with `v`, `v/vt`, `v//vn`, `v/vt/vn` corners, positive
 * or negative (relative) indices, any number of corners >= 3; `s`, `usemtl`,
 * `mtllib`, `vt`, `vn` accepted. `Kd r g b` is read from the .mtl file when it
 * is there; a missing .mtl is a warning. Every error names file:line.
 *
 * Objects and groups: `o NAME` names the object the faces that follow belong
 * to (the rest of the line; a bare `o` ends it), `g A B ...` the groups they
 * belong to (one or more names; a bare `g` means none, OBJ's "default"). The
 * two are independent: a face keeps the last `o` and the last `g` before it.
 * Later lessons pick faces by name, e.g. `decal` for --polygon-offset. */
#ifndef MESH_H
#define MESH_H

#include <stdbool.h>
#include <stddef.h>

#include "error.h"
#include "vecmath.h"

#define MATERIAL_NAME_MAX 64
/* Limits that keep a hostile file from exhausting memory. */
#define MESH_MAX_VERTICES (1 << 24)
#define MESH_MAX_FACE_VERTICES 4096
#define OBJ_MAX_BYTES ((size_t)1 << 30)
#define MESH_MAX_CORNERS (1 << 26)   /* all faces' corners together */
#define MESH_MAX_MATERIALS (1 << 16)
#define MESH_NAME_MAX 256              /* an object or group name, NUL included */
#define MESH_MAX_GROUPS 64             /* groups one `g` line can name */
#define MESH_MAX_NAME_SETS (1 << 20)   /* `o` and `g` lines together */
#define MESH_MAX_NAME_BYTES (1 << 26)  /* all their names together, pointers included */
/* An OBJ coordinate larger than this is refused: it would overflow on the way
 * to the screen. */
#define OBJ_MAX_COORDINATE 1e30

typedef struct {
    char name[MATERIAL_NAME_MAX];
    Vec3 kd;     /* diffuse colour, each channel in [0, 1] */
    bool has_kd; /* false: the lesson picks a palette colour */
} Material;

/* One triangle of a face: three corner numbers 0 .. count-1 of that face. */
typedef struct { int c[3]; } Tri;

/* The object and groups a face belongs to. Faces share one set until the
 * next `o` or `g` line. */
typedef struct {
    char *object;  /* NULL: in no object */
    char **groups; /* ngroups names, none empty, none repeated */
    int ngroups;
} NameSet;

typedef struct {
    int first;     /* first entry in mesh->corners */
    int count;     /* number of vertices, >= 3 */
    int material;  /* index into mesh->materials, -1 for none */
    int first_tri; /* first of its count - 2 triangles in mesh->tris */
    bool convex;   /* convex in its own plane: may be drawn as one polygon */
    int names;     /* index into mesh->sets, -1: in no object or group */
} Face;

typedef struct {
    Vec3 *verts;     int nverts,   cap_verts;
    int *corners;    int ncorners, cap_corners; /* vertex index of each face corner */
    Face *faces;     int nfaces,   cap_faces;
    Tri *tris;       int ntris,    cap_tris;
    Material *materials; int nmaterials, cap_materials;
    NameSet *sets;   int nsets,    cap_sets;    /* see Face.names */
    long long name_bytes;                       /* of all the sets, against MESH_MAX_NAME_BYTES */
    char **warnings; int nwarnings;             /* e.g. "x.obj:3: mtllib y.mtl not found" */
    char **libraries; int nlibraries;           /* the .mtl files read: inputs, as the OBJ is */
} Mesh;

void mesh_init(Mesh *m);
void mesh_free(Mesh *m);

/* Building a mesh by hand (built-in scenes, tests, generators). Both return the
 * new element's index, or -1 with err set (no memory, too many, bad index). */
int mesh_add_vertex(Mesh *m, Vec3 p, Error *err);
int mesh_add_material(Mesh *m, const char *name, Vec3 kd, Error *err);
/* vertex indices are 0-based into m->verts; n >= 3. Triangulates the face.
 * The new face is in no object or group (names -1). */
int mesh_add_face(Mesh *m, const int *vertex_indices, int n, int material, Error *err);
/* A set of names for Face.names: object (NULL for none) and ngroups group
 * names, copied. Names are what an OBJ file can carry back: 1 to
 * MESH_NAME_MAX - 1 bytes, no '#' or line break; a group name has no white
 * space, an object name none at either end. A group named twice counts once.
 * Returns the set's index, or -1 with err set. */
int mesh_add_names(Mesh *m, const char *object, const char *const *groups, int ngroups,
                   Error *err);
/* Is face in the object or in a group called name? */
bool mesh_face_in(const Mesh *m, int face, const char *name);

/* Loads an OBJ file (and its .mtl, relative to the OBJ's directory). m must be
 * initialised (mesh_init); on success its old contents are replaced, on failure
 * they are kept. Warnings (ignored statements, a missing .mtl, an unknown
 * material) go to m->warnings, "file:line: what" each. */
bool mesh_load_obj(Mesh *m, const char *path, Error *err);
/* Parses OBJ text of len bytes (NULs included); name is used in messages and
 * mtl_dir to find mtllib files (NULL: do not read .mtl files). */
bool mesh_parse_obj(Mesh *m, const char *text, size_t len, const char *name,
                    const char *mtl_dir, Error *err);
/* Writes v and f lines (1-based), o and g lines where a face's names change
 * and, when there are materials, usemtl lines and a .mtl file beside it (path
 * with .obj replaced by .mtl), both atomically. */
bool mesh_write_obj(const Mesh *m, const char *path, Error *err);

/* Newell's normal of a polygon (not normalised; zero for a degenerate one). */
Vec3 polygon_normal(const Vec3 *pts, int n);
/* Ear clipping in the polygon's own plane: writes n - 2 triangles (corner
 * numbers 0 .. n-1) to out and returns n - 2. Works for convex and non-convex
 * simple polygons; a degenerate polygon gets a fan so no face is lost.
 * *convex tells whether the polygon is convex. */
int triangulate_polygon(const Vec3 *pts, int n, Tri *out, bool *convex);

#endif
