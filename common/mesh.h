/* mesh.h: polygon meshes, the OBJ files they come from, and their triangles.
 *
 * A face keeps all its vertices (lesson 04 draws convex polygons as they are);
 * each face also carries its ear-clipped triangulation (lessons 02 and 03 draw
 * triangles), which is right for non-convex polygons too. A face's index is its
 * position in the OBJ file (or the built-in scene), counting from 0: --shade id
 * and --trace report it.
 *
 * OBJ: `v x y z [w]`; `f` with `v`, `v/vt`, `v//vn`, `v/vt/vn` corners, positive
 * or negative (relative) indices, any number of corners >= 3; `o`, `g`, `s`,
 * `usemtl`, `mtllib`, `vt`, `vn` accepted. `Kd r g b` is read from the .mtl file
 * when it is there; a missing .mtl is a warning. Every error names file:line. */
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

typedef struct {
    int first;     /* first entry in mesh->corners */
    int count;     /* number of vertices, >= 3 */
    int material;  /* index into mesh->materials, -1 for none */
    int first_tri; /* first of its count - 2 triangles in mesh->tris */
    bool convex;   /* convex in its own plane: may be drawn as one polygon */
} Face;

typedef struct {
    Vec3 *verts;     int nverts,   cap_verts;
    int *corners;    int ncorners, cap_corners; /* vertex index of each face corner */
    Face *faces;     int nfaces,   cap_faces;
    Tri *tris;       int ntris,    cap_tris;
    Material *materials; int nmaterials, cap_materials;
    char **warnings; int nwarnings;             /* e.g. "x.obj:3: mtllib y.mtl not found" */
    char **libraries; int nlibraries;           /* the .mtl files read: inputs, as the OBJ is */
} Mesh;

void mesh_init(Mesh *m);
void mesh_free(Mesh *m);

/* Building a mesh by hand (built-in scenes, tests, generators). Both return the
 * new element's index, or -1 with err set (no memory, too many, bad index). */
int mesh_add_vertex(Mesh *m, Vec3 p, Error *err);
int mesh_add_material(Mesh *m, const char *name, Vec3 kd, Error *err);
/* vertex indices are 0-based into m->verts; n >= 3. Triangulates the face. */
int mesh_add_face(Mesh *m, const int *vertex_indices, int n, int material, Error *err);

/* Loads an OBJ file (and its .mtl, relative to the OBJ's directory). m must be
 * initialised (mesh_init); on success its old contents are replaced, on failure
 * they are kept. Warnings (ignored statements, a missing .mtl, an unknown
 * material) go to m->warnings, "file:line: what" each. */
bool mesh_load_obj(Mesh *m, const char *path, Error *err);
/* Parses OBJ text of len bytes (NULs included); name is used in messages and
 * mtl_dir to find mtllib files (NULL: do not read .mtl files). */
bool mesh_parse_obj(Mesh *m, const char *text, size_t len, const char *name,
                    const char *mtl_dir, Error *err);
/* Writes v and f lines (1-based) and, when there are materials, usemtl lines and
 * a .mtl file beside it (path with .obj replaced by .mtl), both atomically. */
bool mesh_write_obj(const Mesh *m, const char *path, Error *err);

/* Newell's normal of a polygon (not normalised; zero for a degenerate one). */
Vec3 polygon_normal(const Vec3 *pts, int n);
/* Ear clipping in the polygon's own plane: writes n - 2 triangles (corner
 * numbers 0 .. n-1) to out and returns n - 2. Works for convex and non-convex
 * simple polygons; a degenerate polygon gets a fan so no face is lost.
 * *convex tells whether the polygon is convex. */
int triangulate_polygon(const Vec3 *pts, int n, Tri *out, bool *convex);

#endif
