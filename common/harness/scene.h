/* scene.h: the built-in scenes, by name, each with a camera that frames it.
 *
 * `--scene NAME` picks one; `--obj FILE` loads a mesh instead, framed by the
 * same default camera unless camera flags say otherwise. */
#ifndef SCENE_H
#define SCENE_H

#include "mesh_build.h"
#include "vecmath.h"

typedef struct {
    const char *name;
    const char *about;                      /* one line, for --help and the summary */
    bool (*build)(Mesh *m, Error *err);     /* into an empty mesh (mesh_init); after a
                                               failure the caller still mesh_frees it */
    Vec3 eye, target, up;                   /* the camera that shows it best */
    double fovy, near, far;
    bool coplanar;                          /* some faces lie exactly on others (decals):
                                               which one a pixel shows depends on the
                                               drawing order and on rounding, on purpose */
} SceneInfo;

int scene_count(void);
const SceneInfo *scene_at(int i);
const SceneInfo *scene_find(const char *name); /* NULL when there is none */

/* A (2,3) torus knot as a tube of rings x sides quads (2 materials in bands),
 * added to m. rings >= 3, 3 <= sides <= 4096, 0 < tube_radius <= 0.5; the
 * "knot" scene is rings 256, sides 12, radius 0.35. Built with a
 * rotation-minimising frame: no twist, no crack where the tube closes. */
bool torus_knot_mesh(Mesh *m, int rings, int sides, double tube_radius, Error *err);

#endif
