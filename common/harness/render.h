/* render.h: everything around a rasterizer that a lesson does not teach.
 *
 * A lesson of the 3-D series (02 on) describes its depth buffer in a
 * Rasterizer (rasterizer.h); this file does the rest:
 *
 *   render_load     the scene (--scene) or OBJ file (--obj), the camera, and
 *                   every face corner projected to the screen once
 *   render_faces    hands each face, as a ScreenFace, to the lesson's draw_face,
 *                   in mesh order or in an order the lesson gives; drops a whole
 *                   face when a corner has d <= near (docs/conventions.md: lesson
 *                   05's rasterizer clips instead, and only a face wholly
 *                   behind the near plane is dropped) or a position that is not
 *                   a finite number, and counts what it drew and dropped
 *   render_write    --out PNG as --shade says (shade.h), --depth-out PFM as
 *                   view depth d, --overdraw-out PGM16, --id-out PNG of face
 *                   index + 1 (shade.h face_id_colour), --world-out
 *                   (world_view.h); atomic, and the
 *                   directories of the outputs are created when missing
 *   render_print_summary   what was drawn, what the depth test did
 *
 * A lesson's main.c calls them through lesson.h.
 *
 * Framing of --obj: the mesh is framed by a camera fitted to its bounds (see
 * render_fit_camera); camera flags given on the command line still win. With
 * --eye given and --near or --far not, that plane is fitted by the same rule
 * to the eye given: near half-way from it to the bounding sphere (a
 * thousandth of the sphere's radius from inside it), far 1.5 times the
 * distance to the sphere's back. */
#ifndef RENDER_H
#define RENDER_H

#include <stdbool.h>
#include <stdio.h>

#include "camera.h"
#include "cli.h"
#include "error.h"
#include "image_io.h"
#include "mesh_build.h"
#include "rasterizer.h"
#include "scene.h"
#include "target.h"

#define RENDER_SOURCE_MAX 256

typedef struct {
    int faces_drawn, tris_drawn;               /* handed to draw_face */
    int faces_behind_near, tris_behind_near;   /* dropped: a corner with d <= near */
    int faces_not_finite, tris_not_finite;     /* dropped: a screen position overflowed */
} FaceCounts;

typedef struct {
    Mesh mesh;
    Camera camera;
    char source[RENDER_SOURCE_MAX]; /* "scene triangles3" or "model.obj" */
    ScreenVertex *corners;          /* every face corner projected, parallel to mesh.corners */
    Vec4 *clip;                     /* the same corners in clip space (lesson 05 clips them) */
    FaceCounts counts;              /* added up over every render_faces call */
} Render;

/* Called after each face is drawn (e.g. to save a picture per step). Returns
 * false, with err set, to stop drawing. */
typedef bool (*FaceDrawnFn)(void *data, const Target *t, const ScreenFace *f, Error *err);

/* Loads opt->scene or opt->obj, resolves the camera (cli_resolve_camera; for
 * --obj from render_fit_camera) and projects every corner. Returns EXIT_OK, or
 * the status to exit with, err set: EXIT_USAGE for an unknown scene or a bad
 * camera, EXIT_RUN_FAILED for an OBJ file that is missing or malformed. On
 * failure nothing needs freeing. Mesh warnings are left in r->mesh.warnings:
 * render_print_warnings prints them. */
int render_load(Render *r, Options *opt, Error *err);

/* The same from a mesh built in memory (tests, tools): takes the mesh over
 * (*mesh is left empty) and projects it with camera. */
bool render_from_mesh(Render *r, Mesh *mesh, const Camera *camera, const char *source,
                      Error *err);

void render_free(Render *r);

/* Draws faces through rz->draw_face: order == NULL draws every face in mesh
 * order, otherwise order[0 .. count-1] (face indices, repeats allowed).
 * after_face (may be NULL) runs after each face that was drawn. False only
 * when after_face failed. */
bool render_faces(Render *r, Target *t, const Rasterizer *rz, const int *order, int count,
                  FaceDrawnFn after_face, void *data, Error *err);

/* The ScreenFace of face i (whether or not it would be dropped). */
ScreenFace render_screen_face(const Render *r, int i);
/* True when render_faces would drop face i (a corner at or behind the near
 * plane, or not finite on the screen). */
bool render_face_dropped(const Render *r, int i);
/* True when render_faces hands f to a rasterizer that clips (lesson 05 on):
 * every clip coordinate finite, and not every corner behind the near plane. */
bool render_face_clippable(const ScreenFace *f);

/* The depth buffer as view depth d, width * height floats, top row first,
 * +infinity where no face won. NULL when out of memory. Free with free(). */
float *render_view_depth(const Target *t, const Rasterizer *rz);

/* The picture --out shows: shade.h's colours resolved from t->face. */
bool render_image(const Render *r, const Target *t, const Rasterizer *rz, ShadeMode shade,
                  Image *out, Error *err);

/* Writes every output opt asks for. False (err set) when one could not be
 * written: the status is then EXIT_RUN_FAILED. */
bool render_write(const Render *r, const Target *t, const Rasterizer *rz, const Options *opt,
                  Error *err);

/* Creates the missing directories of path, as render_write does for its
 * outputs: for the outputs a lesson writes itself. */
bool render_make_parent_dirs(const char *path, Error *err);

/* "<program>: warning: <msg>" on stderr for each mesh warning. */
void render_print_warnings(const Render *r, const char *program);

/* A target of width x height, cleared by rz->clear: for tools and tests. */
bool render_target_init(Target *t, const Rasterizer *rz, int width, int height, Error *err);

/* The summary, e.g.
 *   02_zbuffer: scene triangles3 (3 faces): 3 triangles drawn, 0 dropped at the near plane
 *     fragments: 51234 tested, 40000 passed, 11234 failed; average overdraw 1.21 over
 *     42337 covered pixels            (one line)
 *     wrote out/02_zbuffer.png
 * One "wrote" line per file written; ", N dropped off the number line" is added
 * when screen positions overflowed. */
void render_print_summary(FILE *out, const char *program, const Render *r, const Target *t,
                          const Options *opt);

/* The camera --obj gets unless flags say otherwise: fovy 40, up +Y, looking at
 * the centre of the mesh's bounding box from the front, a little from the
 * right and above (along +Z, as OBJ models usually face), far enough that
 * the bounding sphere fits the view; near and far enclose the sphere. */
SceneInfo render_fit_camera(const Mesh *m, int width, int height);

#endif
