/* camera.c: see camera.h. */
#include "camera.h"

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

ScreenVertex camera_project(const Camera *c, Vec3 world)
{
    Vec4 clip = mat4_mul_vec4(c->view_proj, vec4(world.x, world.y, world.z, 1.0));
    ScreenVertex sv = {0.0, 0.0, clip.w};                 /* w_clip = d = -z_view */
    if (sv.d > 0) {                                       /* d <= 0: behind the eye, x, y stay 0 */
        double x_ndc = clip.x / clip.w;                   /* x_ndc = x_clip / w_clip */
        double y_ndc = clip.y / clip.w;                   /* y_ndc = y_clip / w_clip */
        sv.x = (x_ndc + 1) * c->width / 2;                /* x_s = (x_ndc + 1) * W / 2 */
        sv.y = (1 - y_ndc) * c->height / 2;               /* y_s = (1 - y_ndc) * H / 2 */
    }
    return sv;
}
