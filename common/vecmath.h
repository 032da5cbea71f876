/* vecmath.h: vectors and 4x4 matrices, OpenGL conventions.
 *
 * Matrices are row-major in memory, m[row][col], and multiply column vectors:
 * p' = M p, so a chain reads right to left (proj * view * p), as in GLSL.
 * look_at and perspective build exactly the matrices of gluLookAt and
 * gluPerspective. Doubles everywhere: geometry is not where the lessons save time. */
#ifndef VECMATH_H
#define VECMATH_H

/* pi to more digits than a double holds: the one definition every file uses. */
#define PI 3.14159265358979323846

typedef struct { double x, y, z; } Vec3;
typedef struct { double x, y, z, w; } Vec4;
typedef struct { double m[4][4]; } Mat4;

Vec3 vec3(double x, double y, double z);
Vec4 vec4(double x, double y, double z, double w);

Vec3 vec3_add(Vec3 a, Vec3 b);
Vec3 vec3_sub(Vec3 a, Vec3 b);
Vec3 vec3_scale(Vec3 a, double s);
double vec3_dot(Vec3 a, Vec3 b);
Vec3 vec3_cross(Vec3 a, Vec3 b);
double vec3_length(Vec3 a);
Vec3 vec3_normalize(Vec3 a); /* the zero vector stays zero */

Mat4 mat4_identity(void);
Mat4 mat4_mul(Mat4 a, Mat4 b);      /* a * b */
Vec4 mat4_mul_vec4(Mat4 m, Vec4 v); /* m * v */

/* gluLookAt: camera at eye looking at target, up roughly up. The camera looks
 * down its own -Z axis, +Y up, +X right. Callers check that eye != target and
 * that up is not parallel to target - eye (camera_check in camera.h does). */
Mat4 look_at(Vec3 eye, Vec3 target, Vec3 up);

/* gluPerspective: fovy in degrees, aspect = width / height, 0 < near < far.
 * A view-space point (x, y, z, 1) maps to clip space with w = -z = d. */
Mat4 perspective(double fovy_degrees, double aspect, double near, double far);

#endif
