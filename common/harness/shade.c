/* shade.c: see shade.h. */
#include "shade.h"

#include <math.h>
#include <stdlib.h>

#include "target.h"

const Rgb FLAT_BACKGROUND = {24, 28, 40};
const Rgb ID_BACKGROUND = {0, 0, 0};

/* Faces without a material take these in turn: distinct hues of similar
 * brightness, so that neighbouring faces of a built-in scene are told apart. */
static const Rgb PALETTE[] = {
    {230, 85, 70},   /* red */
    {90, 180, 90},   /* green */
    {70, 120, 220},  /* blue */
    {235, 190, 60},  /* yellow */
    {170, 100, 200}, /* purple */
    {60, 190, 190},  /* teal */
    {240, 140, 60},  /* orange */
    {200, 200, 200}, /* light grey */
};
#define PALETTE_SIZE ((int)(sizeof PALETTE / sizeof PALETTE[0]))

/* --shade id (shade.h): picked by farthest-point sampling in CIELAB among
 * colours of lightness 40 to 92, then ordered so that consecutive entries
 * (and the last and the first) differ most. */
static const Rgb ID_PALETTE[ID_PALETTE_SIZE] = {
    {160, 80, 0},    /* brown */
    {255, 160, 255}, /* pink */
    {0, 255, 0},     /* green */
    {0, 200, 255},   /* sky blue */
    {255, 200, 160}, /* peach */
    {0, 255, 200},   /* aquamarine */
    {80, 160, 0},    /* grass green */
    {255, 200, 0},   /* gold */
    {255, 0, 255},   /* magenta */
    {200, 80, 120},  /* rose */
    {200, 240, 160}, /* pale green */
    {80, 120, 200},  /* steel blue */
    {255, 0, 160},   /* hot pink */
    {230, 40, 40},   /* red */
    {120, 120, 40},  /* olive */
    {0, 80, 240},    /* blue */
    {200, 240, 0},   /* lime */
};

/* Towards the light, in view space: above (+y), left (-x), behind the viewer (+z). */
static Vec3 light_direction(void)
{
    return vec3_normalize(vec3(-0.4, 0.6, 1.0));
}

static uint8_t channel(double c)
{
    double v = round(c * 255);
    return (uint8_t)(v < 0 ? 0 : v > 255 ? 255 : v);
}

Rgb face_base_colour(const Mesh *m, int face)
{
    int mat = m->faces[face].material;
    if (mat >= 0 && mat < m->nmaterials && m->materials[mat].has_kd) {
        Vec3 kd = m->materials[mat].kd;
        Rgb c = {channel(kd.x), channel(kd.y), channel(kd.z)};
        return c;
    }
    return PALETTE[face % PALETTE_SIZE];
}

/* The face's unit normal in view space; zero for a degenerate face. */
static Vec3 view_normal(const Mesh *m, const Camera *camera, int face)
{
    enum { STACK_CORNERS = 64 };
    const Face *f = &m->faces[face];
    Vec3 stack[STACK_CORNERS] = {{0, 0, 0}};
    Vec3 *pts = f->count <= STACK_CORNERS ? stack : malloc((size_t)f->count * sizeof *pts);
    if (!pts)
        return vec3(0, 0, 0); /* out of memory: the face gets ambient light only */
    for (int k = 0; k < f->count; k++)
        pts[k] = camera_to_view(camera, m->verts[m->corners[f->first + k]]);
    Vec3 n = vec3_normalize(polygon_normal(pts, f->count));
    if (pts != stack)
        free(pts);
    return n;
}

Rgb face_flat_colour(const Mesh *m, const Camera *camera, int face)
{
    Rgb base = face_base_colour(m, face);
    double lambert = fabs(vec3_dot(view_normal(m, camera, face), light_direction()));
    double k = SHADE_AMBIENT + SHADE_DIFFUSE * lambert; /* both windings are lit alike */
    Rgb c = {channel(base.r / 255.0 * k), channel(base.g / 255.0 * k),
             channel(base.b / 255.0 * k)};
    return c;
}

Rgb face_id_colour(int face)
{
    uint32_t id = (uint32_t)face + 1; /* 0 stays for the background */
    Rgb c = {(uint8_t)(id >> 16), (uint8_t)(id >> 8), (uint8_t)id};
    return c;
}

bool face_ids_fit(int nfaces, Error *err)
{
    if (nfaces <= FACE_ID_MAX_FACES)
        return true;
    return error_set(err, "--id-out: the mesh has %d faces; an id picture numbers faces in 24 "
                          "bits and tells at most %d apart", nfaces, FACE_ID_MAX_FACES);
}

Rgb face_shade_id_colour(int face)
{
    return ID_PALETTE[(unsigned)face % ID_PALETTE_SIZE];
}

int32_t id_colour_face(Rgb c)
{
    return (int32_t)(((uint32_t)c.r << 16) | ((uint32_t)c.g << 8) | c.b) - 1;
}

bool shade_image(const Mesh *m, const Camera *camera, const int32_t *face,
                 const float *view_depth, int width, int height, ShadeMode mode,
                 Image *out, Error *err)
{
    if (!image_init(out, width, height, err))
        return false;
    if (mode == SHADE_DEPTH) {
        depth_to_grey(view_depth, out);
        return true;
    }
    /* Flat colours once per face, not once per pixel. */
    Rgb *flat = NULL;
    if (mode == SHADE_FLAT) {
        flat = malloc((m->nfaces > 0 ? (size_t)m->nfaces : 1) * sizeof *flat);
        if (!flat) {
            image_free(out);
            return error_set(err, "out of memory shading %d faces", m->nfaces);
        }
        for (int i = 0; i < m->nfaces; i++)
            flat[i] = face_flat_colour(m, camera, i);
    }
    Rgb background = mode == SHADE_FLAT ? FLAT_BACKGROUND : ID_BACKGROUND;
    for (int y = 0; y < height; y++)
        for (int x = 0; x < width; x++) {
            int32_t f = face[(size_t)y * (size_t)width + (size_t)x];
            Rgb c = f == NO_FACE ? background : flat ? flat[f] : face_shade_id_colour(f);
            image_set(out, x, y, c);
        }
    free(flat);
    return true;
}

bool face_id_image(const int32_t *face, int width, int height, Image *out, Error *err)
{
    if (!image_init(out, width, height, err))
        return false;
    for (int y = 0; y < height; y++)
        for (int x = 0; x < width; x++) {
            int32_t f = face[(size_t)y * (size_t)width + (size_t)x];
            image_set(out, x, y, f == NO_FACE ? ID_BACKGROUND : face_id_colour(f));
        }
    return true;
}
