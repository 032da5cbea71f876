/* camera.h: from world space to the screen, as OpenGL does it.
 *
 *   view:      look_at(eye, target, up)           view depth d = -z_view
 *   clip:      perspective(fovy, W/H, near, far)  w_clip = d
 *   NDC:       x_ndc = x_clip / w_clip, y_ndc = y_clip / w_clip
 *   viewport:  x_s = (x_ndc + 1) * W / 2,  y_s = (1 - y_ndc) * H / 2
 *
 * The screen origin is the top-left corner and y grows downwards; pixel (x, y)
 * is sampled at its centre (x + 0.5, y + 0.5). */
#ifndef CAMERA_H
#define CAMERA_H

#include <stdbool.h>

#include "error.h"
#include "vecmath.h"

typedef struct {
    Mat4 view, proj, view_proj;
    int width, height;
    double near, far;
} Camera;

typedef struct {
    double x, y; /* screen position in pixels, meaningful when d > 0 */
    double d;    /* view depth, positive in front of the camera */
} ScreenVertex;

/* Whether camera_init can build a camera from these values: eye != target, up
 * not parallel to the view direction, 0 < near < far, 0 < fovy < 180, and
 * matrices that stay finite. False with err set otherwise; the message names
 * the command-line flag that gives the value (--eye, --up, --fovy, ...). */
bool camera_check(Vec3 eye, Vec3 target, Vec3 up, double fovy_degrees, double near,
                  double far, int width, int height, Error *err);
void camera_init(Camera *c, Vec3 eye, Vec3 target, Vec3 up, double fovy_degrees,
                 double near, double far, int width, int height);
Vec3 camera_to_view(const Camera *c, Vec3 world);
Vec4 camera_to_clip(const Camera *c, Vec3 world); /* P V (x, y, z, 1): w = d */
ScreenVertex camera_project(const Camera *c, Vec3 world);
/* clip divided by w_c and put on a width x height screen, as camera_project
 * puts it (w_c <= 0: behind the eye, x and y stay 0). */
ScreenVertex camera_divide(Vec4 clip, int width, int height);

#endif
