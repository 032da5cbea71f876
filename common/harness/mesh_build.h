/* mesh_build.h: building a mesh (mesh.h), by hand or from an OBJ file.
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
#ifndef MESH_BUILD_H
#define MESH_BUILD_H

#include <stdbool.h>
#include <stddef.h>

#include "error.h"
#include "mesh.h"
#include "vecmath.h"

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
 * with .obj replaced by .mtl), both atomically and as one output set: a
 * failure publishes neither, and a .mtl that is the OBJ file under another
 * name is refused. An OBJ sent to a stream (obj_path_is_stream) has no
 * directory for its .mtl: it is written without materials (no mtllib, no
 * usemtl), and no .mtl is written anywhere. */
bool mesh_write_obj(const Mesh *m, const char *path, Error *err);
/* True when path is "-" or names, links followed, standard output (a file it
 * was sent to, as /dev/stdout is) or a file that exists and is neither a
 * regular file nor a directory: a device (/dev/null) or a pipe. Its "x.mtl"
 * would be no file beside it: "-.mtl" in the current directory,
 * /dev/stdout.mtl and /dev/null.mtl in /dev. */
bool obj_path_is_stream(const char *path);

/* Newell's normal of a polygon (not normalised; zero for a degenerate one). */
Vec3 polygon_normal(const Vec3 *pts, int n);
/* Ear clipping in the polygon's own plane: writes n - 2 triangles (corner
 * numbers 0 .. n-1) to out and returns n - 2. Works for convex and non-convex
 * simple polygons; a degenerate polygon gets a fan so no face is lost.
 * *convex tells whether the polygon is convex. */
int triangulate_polygon(const Vec3 *pts, int n, Tri *out, bool *convex);

#endif
