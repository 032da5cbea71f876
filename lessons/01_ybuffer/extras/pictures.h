/* pictures.h: what lesson 01 shows of its work.
 *
 *  render     the screen row, one colour per column, repeated to `height` rows
 *             because a single row is too thin to see.
 *  y-buffer   the same row as a grey strip: the nearest y (the largest) white,
 *             the farthest dark grey, like every depth picture of the series;
 *             columns still cleared (nothing seen) in DEPTH_BACKGROUND. The
 *             scale is set by the segments, not by the buffer, so that every
 *             step shows a stored y in the same grey.
 *  scene      the world from above, width x SCENE_HEIGHT pixels: world y grows
 *             UP the picture, so the viewer and the screen are at the top and
 *             look down the picture. The segments are drawn in their colours and
 *             the screen as a band at world y = SCREEN_Y showing the render.
 *
 * Each function initialises its Image (free it with image_free). */
#ifndef PICTURES_H
#define PICTURES_H

#include "harness/image_io.h"
#include "ybuffer.h"

#define SCENE_HEIGHT 500
/* The screen band of the scene picture: world rows SCREEN_Y - SCREEN_THICKNESS + 1
 * .. SCREEN_Y, above every segment of the default scene (the highest is y = 463). */
#define SCREEN_Y 490
#define SCREEN_THICKNESS 4

/* Black: a column no segment won. */
extern const Rgb RENDER_BACKGROUND;
/* The screen band where nothing was won: dark grey, so the band shows on black. */
extern const Rgb SCREEN_EMPTY;

/* The y shown white and the y shown darkest in the y-buffer strip. */
typedef struct {
    int nearest, farthest;
} GreyScale;

/* The largest and smallest y any segment brings to a column of the screen:
 * a segment is linear, so they are at the ends of its clipped column range. */
GreyScale grey_scale_of(const Segment *segs, int count, int width);

bool render_picture(const YBuffer *yb, const Segment *segs, int height, Image *out, Error *err);
bool ybuffer_picture(const YBuffer *yb, GreyScale scale, int height, Image *out, Error *err);
bool scene_picture(const Segment *segs, int count, const YBuffer *yb, Image *out, Error *err);

/* The picture's row for world height y: the one place where the scene is
 * flipped (a PNG's row 0 is its top, the world's y = 0 is at the bottom). */
int world_to_row(int y);

/* Writes a PNG, creating its directory first if it is missing. */
bool write_picture(const Image *im, const char *path, Error *err);

/* step_NNNN.png (the render) and step_NNNN_depth.png (the y-buffer strip) in
 * dir, as every lesson's --steps names them (common/harness/steps.h): the state after
 * `step` segments. */
bool write_step_pictures(const YBuffer *yb, const Segment *segs, GreyScale scale, int height,
                         const char *dir, int step, Error *err);

#endif
