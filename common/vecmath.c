/* vecmath.c: see vecmath.h. */
#include "vecmath.h"

#include <math.h>

Vec3 vec3(double x, double y, double z)
{
    Vec3 v = {x, y, z};
    return v;
}

Vec4 vec4(double x, double y, double z, double w)
{
    Vec4 v = {x, y, z, w};
    return v;
}

Vec3 vec3_add(Vec3 a, Vec3 b) { return vec3(a.x + b.x, a.y + b.y, a.z + b.z); }
Vec3 vec3_sub(Vec3 a, Vec3 b) { return vec3(a.x - b.x, a.y - b.y, a.z - b.z); }
Vec3 vec3_scale(Vec3 a, double s) { return vec3(a.x * s, a.y * s, a.z * s); }
double vec3_dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

Vec3 vec3_cross(Vec3 a, Vec3 b)
{
    return vec3(a.y * b.z - a.z * b.y,
                a.z * b.x - a.x * b.z,
                a.x * b.y - a.y * b.x);
}

double vec3_length(Vec3 a) { return sqrt(vec3_dot(a, a)); }

Vec3 vec3_normalize(Vec3 a)
{
    double len = vec3_length(a);
    return len > 0 ? vec3_scale(a, 1.0 / len) : a;
}

Mat4 mat4_identity(void)
{
    Mat4 m = {{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}};
    return m;
}

Mat4 mat4_mul(Mat4 a, Mat4 b)
{
    Mat4 r;
    for (int row = 0; row < 4; row++)
        for (int col = 0; col < 4; col++) {
            double sum = 0;
            for (int k = 0; k < 4; k++)
                sum += a.m[row][k] * b.m[k][col];
            r.m[row][col] = sum;
        }
    return r;
}

Vec4 mat4_mul_vec4(Mat4 m, Vec4 v)
{
    double in[4] = {v.x, v.y, v.z, v.w}, out[4];
    for (int row = 0; row < 4; row++)
        out[row] = m.m[row][0] * in[0] + m.m[row][1] * in[1] + m.m[row][2] * in[2] +
                   m.m[row][3] * in[3];
    return vec4(out[0], out[1], out[2], out[3]);
}

/* gluLookAt:
 *   f = normalize(target - eye)   where the camera looks
 *   s = normalize(f x up)         the camera's right (+X)
 *   u = s x f                     the camera's true up (+Y)
 * The rows s, u, -f turn world directions into view directions (the camera
 * looks down -Z); the last column moves the eye to the origin. */
Mat4 look_at(Vec3 eye, Vec3 target, Vec3 up)
{
    Vec3 f = vec3_normalize(vec3_sub(target, eye));
    Vec3 s = vec3_normalize(vec3_cross(f, up));
    Vec3 u = vec3_cross(s, f);
    Mat4 m = {{{s.x, s.y, s.z, -vec3_dot(s, eye)},
               {u.x, u.y, u.z, -vec3_dot(u, eye)},
               {-f.x, -f.y, -f.z, vec3_dot(f, eye)},
               {0, 0, 0, 1}}};
    return m;
}

/* gluPerspective, with f = cot(fovy / 2):
 *   [ f/aspect  0  0                        0                        ]
 *   [ 0         f  0                        0                        ]
 *   [ 0         0  (far+near)/(near-far)    2*far*near/(near-far)    ]
 *   [ 0         0  -1                       0                        ]
 * The last row makes w_clip = -z_view = d; z_ndc runs from -1 at the near
 * plane to +1 at the far plane. */
Mat4 perspective(double fovy_degrees, double aspect, double near, double far)
{
    double f = 1.0 / tan(fovy_degrees * PI / 180.0 / 2.0);
    Mat4 m = {{{f / aspect, 0, 0, 0},
               {0, f, 0, 0},
               {0, 0, (far + near) / (near - far), 2 * far * near / (near - far)},
               {0, 0, -1, 0}}};
    return m;
}
