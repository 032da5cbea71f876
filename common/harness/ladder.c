/* ladder.c: see ladder.h. */
#include "ladder.h"

#include <math.h>
#include <string.h>

#include "image_io.h"

const double LADDER_DISTANCE[LADDER_BANDS] = {1, 3, 10, 30, 100, 300};

#define LADDER_TAN_HALF_FOVY 0.41421356237309503 /* tan(45 / 2 degrees) */
#define LADDER_ASPECT (4.0 / 3.0)                /* the default 800 x 600 */
#define LADDER_TILT 0.05  /* 1/d varies by +-5% from a plate's top to its bottom */
#define LADDER_INSET 0.01 /* the back plate's margin inside the front one (NDC) */

/* The point at NDC (x, y) whose view depth is 1 / inv_d (camera at the origin). */
static Vec3 on_ray(double x, double y, double inv_d)
{
    double d = 1.0 / inv_d;
    return vec3(x * LADDER_TAN_HALF_FOVY * LADDER_ASPECT * d, y * LADDER_TAN_HALF_FOVY * d, -d);
}

/* A plate over the NDC rectangle [x0, x1] x [y0, y1], on the plane where
 * 1/d = inv_d0 (1 + LADDER_TILT v), v from -1 at yc - h to +1 at yc + h:
 * 1/d affine on the screen is a plane in space. */
static bool add_plate(Mesh *m, double x0, double x1, double y0, double y1, double yc, double h,
                      double inv_d0, int mat, Error *err)
{
    double ys[2] = {y0, y1}, xs[4] = {x0, x1, x1, x0};
    int idx[4];
    for (int k = 0; k < 4; k++) {
        double y = ys[k / 2], v = (y - yc) / h;
        if ((idx[k] = mesh_add_vertex(m, on_ray(xs[k], y, inv_d0 * (1 + LADDER_TILT * v)),
                                      err)) < 0)
            return false;
    }
    return mesh_add_face(m, idx, 4, mat, err) >= 0;
}

/* Band k in a 3 x 2 grid on the screen, left to right, top row first. */
bool ladder_build(Mesh *m, Error *err)
{
    int back = mesh_add_material(m, "back_plate", vec3(0.9, 0.25, 0.15), err);
    int front = mesh_add_material(m, "front_plate", vec3(0.55, 0.75, 0.95), err);
    if (back < 0 || front < 0)
        return false;
    for (int k = 0; k < LADDER_BANDS; k++) {
        double x0 = -0.94 + 0.64 * (k % 3), x1 = x0 + 0.60;
        double y1 = k < 3 ? 0.90 : -0.06, y0 = y1 - 0.84;
        double yc = (y0 + y1) / 2, h = (y1 - y0) / 2, d = LADDER_DISTANCE[k], e = LADDER_INSET;
        if (!add_plate(m, x0 + e, x1 - e, y0 + e, y1 - e, yc, h, 1.0 / (d + LADDER_GAP), back,
                       err) ||
            !add_plate(m, x0, x1, y0, y1, yc, h, 1.0 / d, front, err))
            return false;
    }
    return true;
}

static void count_face(long face, LadderScore *s)
{
    if (face >= 0 && face < 2 * LADDER_BANDS) {
        if (face % 2)
            s->front[face / 2]++;
        else
            s->back[face / 2]++;
    }
}

void ladder_score_faces(const int32_t *face, size_t n, LadderScore *s)
{
    memset(s, 0, sizeof *s);
    for (size_t i = 0; i < n; i++)
        count_face(face[i], s);
}

bool ladder_score_id_png(const char *path, LadderScore *s, Error *err)
{
    Image im;
    if (!image_read_png(&im, path, err))
        return false;
    memset(s, 0, sizeof *s);
    for (int y = 0; y < im.height; y++)
        for (int x = 0; x < im.width; x++) {
            Rgb c = image_get(&im, x, y);
            count_face(((long)c.r << 16 | (long)c.g << 8 | (long)c.b) - 1, s);
        }
    image_free(&im);
    return true;
}

double ladder_wrong_fraction(const LadderScore *s, int k)
{
    long all = s->back[k] + s->front[k];
    return all > 0 ? (double)s->back[k] / (double)all : 0.0;
}
