/* scene_parts.h: the building blocks of the built-in scenes, shared by
 * scene.c (the registry and the first scenes) and scene_later.c (the scenes
 * of lessons 07 to 09). Not for the lessons: they get whole scenes through
 * scene.h. Each adds to m and returns false with err set on failure. */
#ifndef SCENE_PARTS_H
#define SCENE_PARTS_H

#include "mesh_build.h"
#include "vecmath.h"

/* The vertices p[0 .. n-1] (n <= 4), then one face through them in that order. */
bool add_polygon(Mesh *m, const Vec3 *p, int n, int mat, Error *err);
bool add_quad(Mesh *m, Vec3 a, Vec3 b, Vec3 c, Vec3 d, int mat, Error *err);
/* A box: its 8 corners centre + axes[0] * +-1 + axes[1] * +-1 + axes[2] * +-1
 * (axes: half-edges, right-handed), its 6 faces wound outwards, in the order
 * -x +x -y +y -z +z of its own axes. */
bool add_box(Mesh *m, Vec3 centre, const Vec3 axes[3], int mat, Error *err);
/* An axis-aligned box from its lowest corner lo to its highest hi. */
bool add_aligned_box(Mesh *m, Vec3 lo, Vec3 hi, int mat, Error *err);

/* The scenes of scene_later.c, for the registry. */
bool build_decals(Mesh *m, Error *err);
bool build_crowd(Mesh *m, Error *err);
bool build_city(Mesh *m, Error *err);

#endif
