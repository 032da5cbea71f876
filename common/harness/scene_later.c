/* scene_later.c: the built-in scenes of lessons 07 to 09.
 *
 *   decals  posters and floor markings lying exactly on their walls and floor
 *           (lesson 07, depth bias): group `decal`
 *   crowd   a few hundred figures in rows, fences and trees, in shuffled
 *           order (lesson 08, early-Z): the flat fences and leaves are in
 *           group `cutout`
 *   city    a large wall drawn first, hiding a city of 510 small buildings
 *           (lesson 09, hierarchical Z)
 *
 * As in scene.c, a face's position in its build function is its index, and
 * every vertex lies in front of its camera's near plane. Coordinates are
 * small multiples of 1/8, exact in binary, so that "on the wall" means on it
 * exactly. Boxes stand sunk a little into the ground: no face of theirs lies
 * in the ground's plane, so only decals share a plane with another face. */
#include "scene_parts.h"

#include <stdint.h>

/* Every face from `first` on, to the end of the mesh, gets the groups
 * groups[0 .. n-1]. */
static bool name_faces(Mesh *m, int first, const char *const *groups, int n, Error *err)
{
    int set = mesh_add_names(m, NULL, groups, n, err);
    if (set < 0)
        return false;
    for (int f = first; f < m->nfaces; f++)
        m->faces[f].names = set;
    return true;
}

/* A small deterministic generator (a 32-bit LCG, Numerical Recipes'
 * constants): the same scene on every machine. */
static uint32_t next_random(uint32_t *state)
{
    *state = *state * 1664525u + 1013904223u;
    return *state >> 8; /* the low bits of an LCG repeat quickly */
}

/* A whole number in [0, n). */
static int random_below(uint32_t *state, int n)
{
    return (int)(next_random(state) % (uint32_t)n);
}

/* ---- decals -------------------------------------------------------------- */

/* A hall DECALS_LENGTH long: a mid-grey floor y = 0, walls x = -4 and x = 4,
 * an end wall z = DECALS_END; the camera stands at z = 3, 1.75 up, and looks
 * down the hall, so the floor runs from about 1 to 63 units away and is seen
 * at a grazing angle. Then, in the same planes and drawn after them:
 *   posters   on both walls (groups decal, poster)
 *   markings  a dashed centre line and two edge lines on the floor, and a
 *             zebra crossing at z = -12 (groups decal, marking)
 *   a sign    on the end wall (groups decal, poster)
 * and last a pillar standing 0.25 in front of the first poster on the left
 * wall (no group): too much bias pulls the poster through it. */
#define DECALS_HALF_WIDTH 4.0
#define DECALS_HEIGHT 4.0
#define DECALS_START 2.0
#define DECALS_END (-60.0)

typedef struct { double z0, z1, y0, y1; int side; } Poster; /* side -1: left wall */

static const Poster POSTERS[] = {
    {-5.0, -7.5, 1.0, 2.75, -1},  {-13.0, -15.0, 1.25, 2.5, -1},
    {-24.0, -27.0, 1.0, 3.0, -1}, {-40.0, -44.0, 1.0, 3.0, -1},
    {-8.0, -10.5, 1.0, 2.75, 1},  {-18.0, -20.0, 1.5, 3.0, 1},
    {-30.0, -34.0, 1.0, 3.0, 1},  {-48.0, -51.0, 1.25, 2.75, 1},
};

static bool add_poster(Mesh *m, const Poster *p, int mat, Error *err)
{
    double x = p->side * DECALS_HALF_WIDTH;
    Vec3 a = vec3(x, p->y0, p->z0), b = vec3(x, p->y0, p->z1);
    Vec3 c = vec3(x, p->y1, p->z1), d = vec3(x, p->y1, p->z0);
    /* Wound to face into the hall, as the walls are. */
    return p->side < 0 ? add_quad(m, a, b, c, d, mat, err) : add_quad(m, a, d, c, b, mat, err);
}

/* A rectangle on the floor, x0 < x1, z0 > z1, facing up. */
static bool add_floor_rect(Mesh *m, double x0, double x1, double z0, double z1, int mat,
                           Error *err)
{
    return add_quad(m, vec3(x0, 0, z0), vec3(x1, 0, z0), vec3(x1, 0, z1), vec3(x0, 0, z1), mat,
                    err);
}

static bool add_hall(Mesh *m, const int *mat, Error *err)
{
    double w = DECALS_HALF_WIDTH, h = DECALS_HEIGHT, z0 = DECALS_START, z1 = DECALS_END;
    return add_floor_rect(m, -w, w, z0, z1, mat[0], err) &&
           add_quad(m, vec3(-w, 0, z0), vec3(-w, 0, z1), vec3(-w, h, z1), vec3(-w, h, z0),
                    mat[1], err) &&
           add_quad(m, vec3(w, 0, z0), vec3(w, h, z0), vec3(w, h, z1), vec3(w, 0, z1), mat[2],
                    err) &&
           add_quad(m, vec3(-w, 0, z1), vec3(w, 0, z1), vec3(w, h, z1), vec3(-w, h, z1), mat[3],
                    err);
}

static bool add_markings(Mesh *m, int white, int yellow, Error *err)
{
    for (int k = 0; k < 14; k++) { /* centre dashes, 2 long every 4 */
        double z = -1.0 - 4.0 * k;
        if (!add_floor_rect(m, -0.125, 0.125, z, z - 2.0, white, err))
            return false;
    }
    for (int side = -1; side <= 1; side += 2) { /* edge lines */
        double x = side * 3.375;
        if (!add_floor_rect(m, x - 0.125, x + 0.125, 1.0, -58.0, yellow, err))
            return false;
    }
    for (int k = 0; k < 6; k++) { /* the zebra crossing, stripes across the hall */
        double x = -2.75 + k * 1.0;
        if (!add_floor_rect(m, x, x + 0.5, -11.0, -13.0, white, err))
            return false;
    }
    return true;
}

bool build_decals(Mesh *m, Error *err)
{
    int base[4] = {mesh_add_material(m, "floor", vec3(0.5, 0.5, 0.5), err),
                   mesh_add_material(m, "wall_left", vec3(0.85, 0.8, 0.68), err),
                   mesh_add_material(m, "wall_right", vec3(0.68, 0.76, 0.85), err),
                   mesh_add_material(m, "end_wall", vec3(0.35, 0.45, 0.4), err)};
    int white = mesh_add_material(m, "marking_white", vec3(0.95, 0.95, 0.92), err);
    int yellow = mesh_add_material(m, "marking_yellow", vec3(0.95, 0.8, 0.1), err);
    int poster[3] = {mesh_add_material(m, "poster_red", vec3(0.85, 0.15, 0.15), err),
                     mesh_add_material(m, "poster_blue", vec3(0.15, 0.35, 0.9), err),
                     mesh_add_material(m, "poster_orange", vec3(0.95, 0.55, 0.1), err)};
    int pillar = mesh_add_material(m, "pillar", vec3(0.3, 0.25, 0.22), err);
    if (base[0] < 0 || base[1] < 0 || base[2] < 0 || base[3] < 0 || white < 0 || yellow < 0 ||
        poster[0] < 0 || poster[1] < 0 || poster[2] < 0 || pillar < 0)
        return false;
    if (!add_hall(m, base, err))
        return false;
    static const char *const POSTER_GROUPS[] = {"decal", "poster"};
    static const char *const MARKING_GROUPS[] = {"decal", "marking"};
    int first = m->nfaces;
    for (int k = 0; k < (int)(sizeof POSTERS / sizeof POSTERS[0]); k++)
        if (!add_poster(m, &POSTERS[k], poster[k % 3], err))
            return false;
    /* The sign on the end wall, facing the camera. */
    double z = DECALS_END;
    if (!add_quad(m, vec3(-1.5, 1.5, z), vec3(1.5, 1.5, z), vec3(1.5, 3.0, z),
                  vec3(-1.5, 3.0, z), poster[1], err) ||
        !name_faces(m, first, POSTER_GROUPS, 2, err))
        return false;
    first = m->nfaces;
    if (!add_markings(m, white, yellow, err) || !name_faces(m, first, MARKING_GROUPS, 2, err))
        return false;
    /* The pillar, between the camera and the first poster (x = -4, z from -5
     * to -7.5), 0.25 from the wall, sunk into the floor. */
    return add_aligned_box(m, vec3(-3.75, -0.125, -6.5), vec3(-3.25, 2.5, -6.0), pillar, err);
}

/* ---- crowd --------------------------------------------------------------- */

/* CROWD_ROWS rows of CROWD_COLUMNS figures, from z = -2 back to z = -47,
 * each a body box with a head box pushed into its top; two low fences across
 * the crowd in panels, and trees among the rows whose crowns are crossed
 * quads: fences and crowns are flat and in group `cutout` (lesson 08 cuts
 * holes in them). Figures stand a random
 * fraction of a unit off their grid spot. The ground comes first, then
 * figures, fence panels and trees in a shuffled order: neither front to back
 * nor back to front, so that sorting has work to do. */
#define CROWD_ROWS 16
#define CROWD_COLUMNS 12
#define CROWD_ROW_STEP 3.0
#define CROWD_COLUMN_STEP 2.0
#define CROWD_FENCES 2
#define CROWD_FENCE_PANELS 12
#define CROWD_TREES 16
#define CROWD_ITEMS (CROWD_ROWS * CROWD_COLUMNS + CROWD_FENCES * CROWD_FENCE_PANELS + CROWD_TREES)
#define CROWD_COLOURS 6

typedef struct { int body[CROWD_COLOURS], head, fence, trunk, leaves; } CrowdPalette;

/* Figure i: row i / columns, column i % columns, nudged by the generator. */
static bool add_figure(Mesh *m, int i, uint32_t *rng, const CrowdPalette *p, Error *err)
{
    double x = -11.0 + CROWD_COLUMN_STEP * (i % CROWD_COLUMNS) + (random_below(rng, 9) - 4) / 16.0;
    double z = -2.0 - CROWD_ROW_STEP * (i / CROWD_COLUMNS) + (random_below(rng, 9) - 4) / 16.0;
    double height = 1.25 + random_below(rng, 5) / 8.0;
    int colour = p->body[random_below(rng, CROWD_COLOURS)];
    return add_aligned_box(m, vec3(x - 0.375, -0.125, z - 0.25), vec3(x + 0.375, height, z + 0.25),
                           colour, err) &&
           add_aligned_box(m, vec3(x - 0.1875, height - 0.125, z - 0.1875),
                           vec3(x + 0.1875, height + 0.375, z + 0.1875), p->head, err);
}

/* Panel k of fence j: 2 wide, 1 high, between rows. */
static bool add_fence_panel(Mesh *m, int j, int k, int mat, Error *err)
{
    double z = -6.5 - 15.0 * j, x = -12.0 + 2.0 * k;
    return add_quad(m, vec3(x, 0, z), vec3(x + 2.0, 0, z), vec3(x + 2.0, 1.0, z),
                    vec3(x, 1.0, z), mat, err);
}

/* Tree k: a trunk (a thin box, not a cutout) and a crown of two crossed
 * quads, 1.5 wide, from 1 to 3 up, between rows; four trees a row. Returns
 * the index of the crown's first face in *crown. */
static bool add_tree(Mesh *m, int k, int trunk, int leaves, int *crown, Error *err)
{
    double x = -9.0 + 6.0 * (k % 4), z = -3.5 - 12.0 * (k / 4) - 3.0 * (k % 2);
    double r = 0.75, y0 = 1.0, y1 = 3.0;
    if (!add_aligned_box(m, vec3(x - 0.125, -0.125, z - 0.125), vec3(x + 0.125, 1.5, z + 0.125),
                         trunk, err))
        return false;
    *crown = m->nfaces;
    return add_quad(m, vec3(x - r, y0, z), vec3(x + r, y0, z), vec3(x + r, y1, z),
                    vec3(x - r, y1, z), leaves, err) &&
           add_quad(m, vec3(x, y0, z - r), vec3(x, y0, z + r), vec3(x, y1, z + r),
                    vec3(x, y1, z - r), leaves, err);
}

static bool crowd_palette(Mesh *m, CrowdPalette *p, Error *err)
{
    static const double BODY[CROWD_COLOURS][3] = {{0.8, 0.2, 0.2}, {0.2, 0.45, 0.85},
                                                  {0.9, 0.7, 0.15}, {0.3, 0.65, 0.3},
                                                  {0.6, 0.3, 0.7},  {0.9, 0.5, 0.6}};
    static const char *const NAMES[CROWD_COLOURS] = {"coat_red",   "coat_blue",
                                                     "coat_yellow", "coat_green",
                                                     "coat_purple", "coat_pink"};
    bool ok = true;
    for (int k = 0; k < CROWD_COLOURS; k++)
        ok = ok && (p->body[k] = mesh_add_material(m, NAMES[k], vec3(BODY[k][0], BODY[k][1],
                                                                      BODY[k][2]), err)) >= 0;
    return ok && (p->head = mesh_add_material(m, "head", vec3(0.9, 0.75, 0.6), err)) >= 0 &&
           (p->fence = mesh_add_material(m, "fence", vec3(0.55, 0.38, 0.2), err)) >= 0 &&
           (p->trunk = mesh_add_material(m, "trunk", vec3(0.35, 0.25, 0.15), err)) >= 0 &&
           (p->leaves = mesh_add_material(m, "leaves", vec3(0.2, 0.55, 0.15), err)) >= 0;
}

bool build_crowd(Mesh *m, Error *err)
{
    CrowdPalette p;
    int ground = mesh_add_material(m, "ground", vec3(0.45, 0.5, 0.4), err);
    if (ground < 0 || !crowd_palette(m, &p, err))
        return false;
    if (!add_quad(m, vec3(-14, 0, 2), vec3(14, 0, 2), vec3(14, 0, -50), vec3(-14, 0, -50), ground,
                  err))
        return false;
    int order[CROWD_ITEMS];
    for (int i = 0; i < CROWD_ITEMS; i++)
        order[i] = i;
    uint32_t rng = 2024;
    for (int i = CROWD_ITEMS - 1; i > 0; i--) { /* Fisher-Yates */
        int j = random_below(&rng, i + 1), t = order[i];
        order[i] = order[j];
        order[j] = t;
    }
    static const char *const CUTOUT[] = {"cutout"};
    int cutout = mesh_add_names(m, NULL, CUTOUT, 1, err);
    if (cutout < 0)
        return false;
    const int figures = CROWD_ROWS * CROWD_COLUMNS, panels = CROWD_FENCES * CROWD_FENCE_PANELS;
    for (int k = 0; k < CROWD_ITEMS; k++) {
        int i = order[k], flat = m->nfaces; /* the first face of the item's cutouts */
        bool ok = i < figures ? add_figure(m, i, &rng, &p, err)
                  : i < figures + panels
                      ? add_fence_panel(m, (i - figures) / CROWD_FENCE_PANELS,
                                        (i - figures) % CROWD_FENCE_PANELS, p.fence, err)
                      : add_tree(m, i - figures - panels, p.trunk, p.leaves, &flat, err);
        if (!ok)
            return false;
        for (int f = flat; i >= figures && f < m->nfaces; f++)
            m->faces[f].names = cutout;
    }
    return true;
}

/* ---- city ---------------------------------------------------------------- */

/* A large wall close to the camera, one quad drawn first, hides a city of
 * CITY_ROWS x CITY_COLUMNS small buildings behind it, every one of them:
 * to the right of the wall the ground shows, empty, and the sky.
 * Each small building is a closed box on a 5-unit grid, x from -72.5 to
 * 7.5, z from -30 back to -175, sunk 0.5 into the ground (drawn second,
 * after the wall), 3 x 3 and 2 to 9 high. Nearly every fragment of the
 * city fails the depth test: lesson 09's hierarchical Z skips them. */
#define CITY_ROWS 30
#define CITY_COLUMNS 17
#define CITY_STEP 5.0
#define CITY_COLOURS 5

bool build_city(Mesh *m, Error *err)
{
    static const double COLOURS[CITY_COLOURS][3] = {
        {0.75, 0.7, 0.6}, {0.55, 0.6, 0.7}, {0.7, 0.45, 0.35}, {0.5, 0.55, 0.45},
        {0.8, 0.75, 0.45}};
    static const char *const NAMES[CITY_COLOURS] = {"stone", "glass", "brick", "concrete",
                                                    "sandstone"};
    int occluder = mesh_add_material(m, "wall", vec3(0.45, 0.45, 0.55), err);
    int ground = mesh_add_material(m, "ground", vec3(0.35, 0.35, 0.33), err);
    int colour[CITY_COLOURS];
    bool ok = occluder >= 0 && ground >= 0;
    for (int k = 0; ok && k < CITY_COLOURS; k++)
        ok = (colour[k] = mesh_add_material(m, NAMES[k], vec3(COLOURS[k][0], COLOURS[k][1],
                                                               COLOURS[k][2]), err)) >= 0;
    ok = ok &&
         add_quad(m, vec3(-60, -1, -12), vec3(6, -1, -12), vec3(6, 45, -12), vec3(-60, 45, -12),
                  occluder, err) &&
         add_quad(m, vec3(-90, 0, -8), vec3(90, 0, -8), vec3(90, 0, -190), vec3(-90, 0, -190),
                  ground, err);
    uint32_t rng = 1990;
    for (int i = 0; ok && i < CITY_ROWS * CITY_COLUMNS; i++) {
        double x = -72.5 + CITY_STEP * (i % CITY_COLUMNS), z = -30.0 - CITY_STEP * (i / CITY_COLUMNS);
        double height = 2.0 + random_below(&rng, 15) / 2.0;
        ok = add_aligned_box(m, vec3(x - 1.5, -0.5, z - 1.5), vec3(x + 1.5, height, z + 1.5),
                             colour[random_below(&rng, CITY_COLOURS)], err);
    }
    return ok;
}
