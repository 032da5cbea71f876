/* rasterizer.h: what a lesson's rasterizer is handed, and what it hands back.
 *
 * The pipeline (render.h) projects every face corner to the screen and hands
 * the lesson one ScreenFace at a time; the lesson's Rasterizer says how it
 * clears its depth buffer, draws a face, and reads a stored value back as d. */
#ifndef RASTERIZER_H
#define RASTERIZER_H

#include <stdbool.h>

#include "camera.h"
#include "mesh.h"
#include "target.h"

/* One face on the screen; the pointers stay valid while draw_face runs. */
typedef struct {
    int face;              /* index of the face in the mesh: --id-out shows face + 1 */
    int n;                 /* number of corners, >= 3 */
    const ScreenVertex *v; /* its n corners: x, y in pixels, view depth d */
    const Tri *tris;       /* its n - 2 triangles, as corner numbers into v */
    bool convex;           /* a convex polygon: may be drawn whole (lesson 04) */
    const Vec4 *clip;      /* the corners in clip space (lesson 05), or NULL if made on screen */
} ScreenFace;

/* What draw_face needs besides the target and the face. */
typedef struct {
    double near, far; /* the camera's planes: a fragment with d > far is discarded */
} DrawContext;

/* The lesson's depth buffer, in three functions. */
typedef struct {
    void (*clear)(Target *t); /* every pixel: "nothing drawn yet", face NO_FACE */
    void (*draw_face)(Target *t, const ScreenFace *f, const DrawContext *ctx);
    double (*stored_to_depth)(const Target *t, float stored); /* as d; NULL: it holds d */
    bool clips; /* clips itself (05): render_faces drops only faces wholly behind near */
    void (*finish)(Target *t); /* NULL but lesson 10's: draws the faces it held back */
} Rasterizer;

/* True when every corner's x, y and d is a finite number: draw_face draws
 * nothing of a face with a corner that is not. */
bool screen_face_is_finite(const ScreenFace *f);

/* A one-triangle ScreenFace over v[0..2], for tests and tools. */
ScreenFace screen_triangle(const ScreenVertex v[3], int face);

#endif
