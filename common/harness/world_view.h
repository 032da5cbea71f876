/* world_view.h: --world-out, the scene and the camera seen from outside.
 *
 * Two orthographic panels side by side, each WORLD_PANEL x WORLD_PANEL pixels
 * under a title row, in the camera's own (view) axes and units, so that the
 * eye sits at the left of both and looks to the right:
 *
 *   left,  "side view":  looking along -x_view; depth d = -z_view to the right, y_view up
 *   right, "top view":   looking down -y_view;  depth d to the right, x_view down
 *
 * Each panel shows the eye (a white dot), the frustum (the lines from the eye
 * through the edges of the field of view, grey), the near plane (cyan,
 * "near d=N") and the far plane (pink, "far d=F"; when it lies beyond the
 * panel, "far d=F ->" at the right edge), the faces in their base colours
 * (shade.h face_base_colour) filled and outlined 3 pixels thick, so that a
 * face seen edge-on still shows, nearest to that panel's viewer on top
 * (a depth buffer per panel), and a scale bar in view units.
 *
 * Framing: one scale, in pixels per unit, for both panels and both axes,
 * the largest at which the eye, the near plane and every corner of every face
 * fit inside the panels with a margin of WORLD_MARGIN pixels; the far plane
 * is fitted too when it is at most WORLD_FAR_FIT times as deep as the rest.
 * A panel whose content would be thinner than an eighth of the room
 * (the strips of the grazing scene from the side) is stretched vertically by
 * a power of two up to WORLD_MAX_STRETCH, and says so ("heights x16"). */
#ifndef WORLD_VIEW_H
#define WORLD_VIEW_H

#include <stdbool.h>

#include "camera.h"
#include "error.h"
#include "image_io.h"
#include "mesh_build.h"

#define WORLD_PANEL 400       /* each panel is this many pixels on a side */
#define WORLD_GAP 4           /* between the two panels */
#define WORLD_TITLE 16        /* the title row above the panels */
#define WORLD_MARGIN 28       /* room for labels around the content */
#define WORLD_FAR_FIT 1.25
#define WORLD_MAX_STRETCH 64
#define WORLD_VIEW_WIDTH (2 * WORLD_PANEL + WORLD_GAP)  /* 804 */
#define WORLD_VIEW_HEIGHT (WORLD_TITLE + WORLD_PANEL)   /* 416 */

typedef enum { WORLD_SIDE, WORLD_TOP } WorldPanel;

extern const Rgb WORLD_EYE_COLOUR;     /* white */
extern const Rgb WORLD_NEAR_COLOUR;    /* cyan */
extern const Rgb WORLD_FAR_COLOUR;     /* pink */
extern const Rgb WORLD_FRUSTUM_COLOUR; /* grey */

/* How view space maps to the picture: panel p's pixel position of a view-space
 * point with depth d and panel height v (y_view for the side view, -x_view for
 * the top view) is
 *     x = left[p] + (d - d0) * scale,   y = top[p] + (v_top[p] - v) * scale * stretch[p]
 * (continuous pixel coordinates: pixel (i, j) covers [i, i+1) x [j, j+1)). */
typedef struct {
    double scale, d0;
    double left[2], top[2], v_top[2];
    int stretch[2];
} WorldFrame;

/* The framing described above, for mesh m seen by camera c. */
WorldFrame world_frame(const Mesh *m, const Camera *c);

/* Where view-space point p lands in panel p's part of the picture. */
void world_to_picture(const WorldFrame *f, WorldPanel panel, Vec3 view, double *x, double *y);

/* The picture, WORLD_VIEW_WIDTH x WORLD_VIEW_HEIGHT; out is initialised here. */
bool world_view_image(const Mesh *m, const Camera *c, Image *out, Error *err);

/* world_view_image written to path as PNG, atomically (image.h). */
bool world_view_write(const Mesh *m, const Camera *c, const char *path, Error *err);

#endif
