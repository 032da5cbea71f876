/* mesh.h: polygon meshes and their triangles, as the lessons read them.
 *
 * A face keeps all its vertices (lesson 04 draws convex polygons as they are);
 * each face also carries its ear-clipped triangulation (lessons 02 and 03 draw
 * triangles), which is right for non-convex polygons too. A face's index is its
 * position in the OBJ file (or the built-in scene), counting from 0: --shade id
 * and --trace report it. A face may belong to an object and to groups, by
 * name: later lessons pick faces by name, e.g. `decal` for --polygon-offset.
 * Meshes are built, and read from OBJ files, by the harness
 * (harness/mesh_build.h). */
#ifndef MESH_H
#define MESH_H

#include <stdbool.h>
#include <stddef.h>

#include "error.h"
#include "vecmath.h"

#define MATERIAL_NAME_MAX 64
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

/* Is face in the object or in a group called name? */
bool mesh_face_in(const Mesh *m, int face, const char *name);

#endif
