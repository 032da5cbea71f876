/* camera.c: see camera.h. */
#include "camera.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define FOVY_MAX 180.0
/* up is parallel to the view direction when the sine of the angle between them
 * is below this: the camera's right axis (f x up) would be noise. */
#define PARALLEL_SINE_MIN 1e-6

/* Shortest of %.15g / %.17g that reads back as v: 0.1 prints as 0.1. */
static const char *number_text(double v, char buf[32])
{
    snprintf(buf, 32, "%.15g", v);
    if (strtod(buf, NULL) != v)
        snprintf(buf, 32, "%.17g", v);
    return buf;
}

/* 0 < fovy < 180, 0 < near < far. */
static bool check_lens(double fovy, double near, double far, Error *err)
{
    char a[32], b[32];
    if (!(fovy > 0 && fovy < FOVY_MAX))
        return error_set(err, "--fovy: %s is out of range (0 < fovy < 180 degrees)",
                         number_text(fovy, a));
    if (!(near > 0))
        return error_set(err, "--near: %s is out of range (near must be greater than 0)",
                         number_text(near, a));
    if (!(far > near))
        return error_set(err, "--far: %s is out of range (far must be greater than near, %s)",
                         number_text(far, a), number_text(near, b));
    return true;
}

/* eye != target, up not parallel to target - eye: otherwise look_at has no
 * direction to look in, or no way to tell right from left. */
static bool check_orientation(Vec3 eye, Vec3 target, Vec3 up, Error *err)
{
    Vec3 dir = vec3_sub(target, eye);
    double dir_len = vec3_length(dir), up_len = vec3_length(up);
    /* A length can underflow to 0 (1e-300 squared) where the vector is not 0. */
    if (eye.x == target.x && eye.y == target.y && eye.z == target.z)
        return error_set(err, "--eye and --target are the same point");
    if (dir_len == 0)
        return error_set(err, "--eye and --target are too close together to give a direction");
    if (!isfinite(dir_len))
        return error_set(err, "--eye and --target are too far apart");
    if (up.x == 0 && up.y == 0 && up.z == 0)
        return error_set(err, "--up is the zero vector");
    if (up_len == 0)
        return error_set(err, "--up is too short to give a direction");
    if (!isfinite(up_len))
        return error_set(err, "--up is too long");
    /* |dir x up| = |dir| |up| sin(angle) */
    double sine = vec3_length(vec3_cross(vec3_scale(dir, 1 / dir_len),
                                         vec3_scale(up, 1 / up_len)));
    if (!(sine >= PARALLEL_SINE_MIN))
        return error_set(err, "--up is parallel to the view direction from --eye to --target");
    return true;
}

static bool matrix_is_finite(Mat4 m)
{
    for (int r = 0; r < 4; r++)
        for (int c = 0; c < 4; c++)
            if (!isfinite(m.m[r][c]))
                return false;
    return true;
}

/* Extreme but finite values can still overflow while the matrices are built. */
static bool check_matrices(Vec3 eye, Vec3 target, Vec3 up, double fovy, double near,
                           double far, double aspect, Error *err)
{
    if (!matrix_is_finite(look_at(eye, target, up)))
        return error_set(err, "--eye and --target are too far from the origin");
    if (!matrix_is_finite(perspective(fovy, aspect, near, far)))
        return error_set(err, "--fovy, --near and --far give a projection too large to compute");
    return true;
}

bool camera_check(Vec3 eye, Vec3 target, Vec3 up, double fovy_degrees, double near,
                  double far, int width, int height, Error *err)
{
    double aspect = (double)width / height;
    return check_lens(fovy_degrees, near, far, err) && check_orientation(eye, target, up, err) &&
           check_matrices(eye, target, up, fovy_degrees, near, far, aspect, err);
}

void camera_init(Camera *c, Vec3 eye, Vec3 target, Vec3 up, double fovy_degrees,
                 double near, double far, int width, int height)
{
    double aspect = (double)width / height;                 /* aspect = W/H */
    c->width = width;
    c->height = height;
    c->near = near;
    c->far = far;
    c->view = look_at(eye, target, up);                     /* view: look_at(eye, target, up) */
    c->proj = perspective(fovy_degrees, aspect, near, far); /* clip: perspective(fovy, W/H, ...) */
    c->view_proj = mat4_mul(c->proj, c->view);              /* clip = proj * view * p */
}

Vec3 camera_to_view(const Camera *c, Vec3 world)
{
    Vec4 v = mat4_mul_vec4(c->view, vec4(world.x, world.y, world.z, 1.0));
    return vec3(v.x, v.y, v.z);
}

Vec4 camera_to_clip(const Camera *c, Vec3 world)
{
    return mat4_mul_vec4(c->view_proj, vec4(world.x, world.y, world.z, 1.0));
}

ScreenVertex camera_project(const Camera *c, Vec3 world)
{
    return camera_divide(camera_to_clip(c, world), c->width, c->height);
}

ScreenVertex camera_divide(Vec4 clip, int width, int height)
{
    ScreenVertex sv = {0.0, 0.0, clip.w};                 /* w_clip = d = -z_view */
    if (sv.d > 0) {                                       /* d <= 0: behind the eye, x, y stay 0 */
        double x_ndc = clip.x / clip.w;                   /* x_ndc = x_clip / w_clip */
        double y_ndc = clip.y / clip.w;                   /* y_ndc = y_clip / w_clip */
        sv.x = (x_ndc + 1) * width / 2;                   /* x_s = (x_ndc + 1) * W / 2 */
        sv.y = (1 - y_ndc) * height / 2;                  /* y_s = (1 - y_ndc) * H / 2 */
    }
    return sv;
}
