/* rasterizer.h: the pipeline (render.h) hands the lesson one ScreenFace at a
 * time; the lesson's Rasterizer says how it clears its depth buffer, draws a
 * face, and reads a stored value back as d. */
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
} ScreenFace; /* with clip, v[k] is camera_divide(clip[k]), to the bit (lesson 10 relies on it) */

/* What draw_face needs besides the target and the face. */
typedef struct {
    double near, far;  /* the camera's planes: a fragment with d > far is discarded */
    int width, height; /* the viewport: the target's size, in pixels */
} DrawContext;

/* Each lesson defines these itself. LessonState (state.h, 06 on; else NULL):
 * what it keeps besides the target. Primitive (depth_buffer.h, 04 on): a face
 * being drawn, as each of its fragments needs it: target, state, face, ... */
typedef struct LessonState LessonState;
typedef struct Primitive Primitive;

/* The lesson's depth buffer, in three functions, and its state. */
typedef struct {
    void (*clear)(Target *t, LessonState *s); /* every pixel "nothing drawn yet", face NO_FACE */
    void (*draw_face)(Target *t, LessonState *s, const ScreenFace *f, const DrawContext *ctx);
    double (*stored_to_depth)(const LessonState *s, float stored); /* as d; NULL: it holds d */
    bool clips;         /* clips itself (05): render_faces drops only faces wholly behind near */
    LessonState *state; /* handed to the three above */
} Rasterizer;

/* True when every corner's x, y and d is a finite number: draw_face draws
 * nothing of a face with a corner that is not. */
bool screen_face_is_finite(const ScreenFace *f);

/* A one-triangle ScreenFace over v[0..2], for tests and tools. */
ScreenFace screen_triangle(const ScreenVertex v[3], int face);

#endif
