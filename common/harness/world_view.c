/* world_view.c: see world_view.h.
 *
 * A view-space point becomes, in panel p, a depth along the panel (d), a
 * height in it (v) and a nearness to the panel's own viewer (w):
 *     side view:  d = -z,  v = y,   w = x   (the viewer is at +x, looking along -x)
 *     top view:   d = -z,  v = -x,  w = y   (the viewer is above, looking down -y)
 * Faces are filled through a depth buffer of w per panel (larger w nearer);
 * lines are clipped to the panel before they are walked, so that a far plane
 * a million units away costs no more than one on the panel. */
#include "world_view.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "font.h"
#include "shade.h"

const Rgb WORLD_EYE_COLOUR = {255, 255, 255};
const Rgb WORLD_NEAR_COLOUR = {90, 220, 255};
const Rgb WORLD_FAR_COLOUR = {255, 120, 200};
const Rgb WORLD_FRUSTUM_COLOUR = {150, 150, 165};

static const Rgb TITLE_BACKGROUND = {12, 14, 20};
static const Rgb TITLE_COLOUR = {230, 230, 230};
static const Rgb GAP_COLOUR = {70, 70, 80};
static const Rgb AXIS_COLOUR = {70, 78, 100};     /* the line of sight through the eye */
static const Rgb SHADOW_COLOUR = {0, 0, 0};       /* under every label, so it reads on a face */
static const Rgb SCALE_COLOUR = {200, 200, 200};

#define EYE_RADIUS 3
#define PLANE_HALF_WIDTH 1   /* near and far planes: 3 pixels thick */
#define EDGE_HALF_WIDTH 1    /* face outlines: 3 pixels thick */
#define SCALE_BAR_TARGET 100 /* pixels: the scale bar is a round length about this long */
#define COORD_LIMIT 1e7      /* pixel coordinates are clamped to this before clipping */

static const char *const TITLES[2] = {
    [WORLD_SIDE] = "side view, looking along -x: y up, depth d right",
    [WORLD_TOP] = "top view, looking down -y: x down, depth d right",
};

/* ---- Framing ----------------------------------------------------------------- */

static double depth_of(Vec3 view) { return -view.z; }
static double height_of(WorldPanel p, Vec3 view) { return p == WORLD_SIDE ? view.y : -view.x; }
static double nearness_of(WorldPanel p, Vec3 view) { return p == WORLD_SIDE ? view.x : view.y; }

/* tan of half the field of view across panel p's heights: the side view shows
 * the vertical field of view, the top view the horizontal one. From
 * gluPerspective's matrix: m[1][1] = 1 / tan(fovy / 2), m[0][0] = that / aspect. */
static double half_fov_tan(const Camera *c, WorldPanel p)
{
    return p == WORLD_SIDE ? 1.0 / c->proj.m[1][1] : 1.0 / c->proj.m[0][0];
}

static double panel_left_edge(WorldPanel p)
{
    return p == WORLD_SIDE ? 0.0 : WORLD_PANEL + WORLD_GAP;
}

typedef struct { double lo, hi; } Range;

static void include(Range *r, double v)
{
    if (isfinite(v)) {
        r->lo = fmin(r->lo, v);
        r->hi = fmax(r->hi, v);
    }
}

WorldFrame world_frame(const Mesh *m, const Camera *c)
{
    Range d = {0, c->near}; /* the eye and the near plane */
    Range v[2];
    for (int p = 0; p < 2; p++) {
        double half = c->near * half_fov_tan(c, (WorldPanel)p);
        v[p] = (Range){-half, half};
    }
    for (int i = 0; i < m->ncorners; i++) {
        Vec3 view = camera_to_view(c, m->verts[m->corners[i]]);
        include(&d, depth_of(view));
        for (int p = 0; p < 2; p++)
            include(&v[p], height_of((WorldPanel)p, view));
    }
    if (c->far <= WORLD_FAR_FIT * d.hi)
        include(&d, c->far);

    double room = WORLD_PANEL - 2 * WORLD_MARGIN;
    double scale = room / (d.hi - d.lo);
    for (int p = 0; p < 2; p++)
        scale = fmin(scale, room / (v[p].hi - v[p].lo));
    if (!(isfinite(scale) && scale > 0))
        scale = 1; /* extents beyond a double: any scale shows as much */

    WorldFrame f = {.scale = scale, .d0 = d.lo};
    for (int p = 0; p < 2; p++) {
        double tall = (v[p].hi - v[p].lo) * scale;
        int stretch = 1;
        if (tall < room / 8)
            while (stretch < WORLD_MAX_STRETCH && tall * stretch * 2 <= room / 2)
                stretch *= 2;
        f.stretch[p] = stretch;
        f.left[p] = panel_left_edge((WorldPanel)p) + WORLD_MARGIN +
                    (room - (d.hi - d.lo) * scale) / 2;
        f.top[p] = WORLD_TITLE + WORLD_MARGIN + (room - tall * stretch) / 2;
        f.v_top[p] = v[p].hi;
    }
    return f;
}

static double clamp_coord(double x)
{
    return isnan(x) ? COORD_LIMIT : fmax(-COORD_LIMIT, fmin(COORD_LIMIT, x));
}

/* Panel p's picture position of depth d and height v. */
static void place(const WorldFrame *f, WorldPanel p, double d, double v, double *x, double *y)
{
    *x = clamp_coord(f->left[p] + (d - f->d0) * f->scale);
    *y = clamp_coord(f->top[p] + (f->v_top[p] - v) * f->scale * f->stretch[p]);
}

void world_to_picture(const WorldFrame *f, WorldPanel panel, Vec3 view, double *x, double *y)
{
    place(f, panel, depth_of(view), height_of(panel, view), x, y);
}

/* ---- Drawing in one panel ------------------------------------------------------ */

typedef struct {
    Image *im;
    float *nearness; /* WORLD_PANEL x WORLD_PANEL, -infinity where nothing is drawn */
    int x0, y0;      /* the panel's top-left pixel in the picture */
} Panel;

static bool inside(const Panel *pn, int x, int y)
{
    return x >= pn->x0 && x < pn->x0 + WORLD_PANEL && y >= pn->y0 && y < pn->y0 + WORLD_PANEL;
}

static void put(Panel *pn, int x, int y, Rgb c)
{
    if (inside(pn, x, y))
        image_set(pn->im, x, y, c);
}

/* A pixel of a face: drawn when at least as near as what is there
 * (or_equal) or strictly nearer. */
static void put_nearer(Panel *pn, int x, int y, double w, bool or_equal, Rgb c)
{
    if (!inside(pn, x, y))
        return;
    float *stored = &pn->nearness[(size_t)(y - pn->y0) * WORLD_PANEL + (size_t)(x - pn->x0)];
    if ((float)w > *stored || (or_equal && (float)w == *stored)) {
        *stored = (float)w;
        image_set(pn->im, x, y, c);
    }
}

/* Liang-Barsky: the part [*t0, *t1] of a + t (b - a) inside the panel grown by
 * a pixel on each side; false when none is. */
static bool clip_to_panel(const Panel *pn, const double a[2], const double b[2], double *t0,
                          double *t1)
{
    double lo[2] = {pn->x0 - 1.0, pn->y0 - 1.0};
    double hi[2] = {pn->x0 + WORLD_PANEL + 1.0, pn->y0 + WORLD_PANEL + 1.0};
    *t0 = 0;
    *t1 = 1;
    for (int k = 0; k < 2; k++) {
        double delta = b[k] - a[k];
        /* a + t delta >= lo  and  -(a + t delta) >= -hi, each as p t >= q */
        double bounds[2][2] = {{lo[k] - a[k], delta}, {a[k] - hi[k], -delta}};
        for (int s = 0; s < 2; s++) {
            double q = bounds[s][0], p = bounds[s][1];
            if (p == 0) {
                if (q > 0)
                    return false;
            } else if (p > 0) {
                *t0 = fmax(*t0, q / p);
            } else {
                *t1 = fmin(*t1, q / p);
            }
        }
    }
    return *t0 <= *t1;
}

typedef struct {
    int half_width;  /* a square of 2 half_width + 1 pixels at each step */
    bool depth;      /* tested against the panel's depth buffer (faces' edges) */
    double w0, w1;   /* nearness at the two ends, when depth */
    Rgb colour;
} LineStyle;

/* From picture position a to b, one step per pixel along the longer axis. */
static void draw_line(Panel *pn, double ax, double ay, double bx, double by, const LineStyle *s)
{
    double a[2] = {ax, ay}, b[2] = {bx, by}, t0, t1;
    if (!clip_to_panel(pn, a, b, &t0, &t1))
        return;
    double x0 = ax + (bx - ax) * t0, y0 = ay + (by - ay) * t0;
    double x1 = ax + (bx - ax) * t1, y1 = ay + (by - ay) * t1;
    int steps = (int)ceil(fmax(fabs(x1 - x0), fabs(y1 - y0)));
    steps = steps < 1 ? 1 : steps;
    for (int i = 0; i <= steps; i++) {
        double t = (double)i / steps;
        int x = (int)floor(x0 + (x1 - x0) * t), y = (int)floor(y0 + (y1 - y0) * t);
        double u = t0 + (t1 - t0) * t;
        double w = s->w0 + (s->w1 - s->w0) * u;
        for (int dy = -s->half_width; dy <= s->half_width; dy++)
            for (int dx = -s->half_width; dx <= s->half_width; dx++) {
                if (s->depth)
                    put_nearer(pn, x + dx, y + dy, w, true, s->colour);
                else
                    put(pn, x + dx, y + dy, s->colour);
            }
    }
}

static void plain_line(Panel *pn, double ax, double ay, double bx, double by, int half_width,
                       Rgb c)
{
    LineStyle s = {.half_width = half_width, .colour = c};
    draw_line(pn, ax, ay, bx, by, &s);
}

static double edge_function(const double a[2], const double b[2], double px, double py)
{
    return (b[0] - a[0]) * (py - a[1]) - (b[1] - a[1]) * (px - a[0]);
}

/* A triangle at picture positions p[k], nearness w[k]: every pixel whose
 * centre is inside, nearer than what the panel holds. Orthographic, so
 * nearness is linear on the panel. */
static void fill_triangle(Panel *pn, double p[3][2], const double w[3], Rgb c)
{
    double area = edge_function(p[0], p[1], p[2][0], p[2][1]);
    if (!(fabs(area) > 1e-9))
        return; /* edge-on: its outline shows it */
    double xmin = fmin(p[0][0], fmin(p[1][0], p[2][0])), xmax = fmax(p[0][0], fmax(p[1][0], p[2][0]));
    double ymin = fmin(p[0][1], fmin(p[1][1], p[2][1])), ymax = fmax(p[0][1], fmax(p[1][1], p[2][1]));
    int x0 = (int)fmax(pn->x0, floor(xmin)), x1 = (int)fmin(pn->x0 + WORLD_PANEL - 1, ceil(xmax));
    int y0 = (int)fmax(pn->y0, floor(ymin)), y1 = (int)fmin(pn->y0 + WORLD_PANEL - 1, ceil(ymax));
    for (int y = y0; y <= y1; y++)
        for (int x = x0; x <= x1; x++) {
            double cx = x + 0.5, cy = y + 0.5;
            double l0 = edge_function(p[1], p[2], cx, cy) / area;
            double l1 = edge_function(p[2], p[0], cx, cy) / area;
            double l2 = 1 - l0 - l1;
            if (l0 >= 0 && l1 >= 0 && l2 >= 0)
                put_nearer(pn, x, y, l0 * w[0] + l1 * w[1] + l2 * w[2], false, c);
        }
}

/* One face: its triangles filled, then its outline, both in its base colour. */
static void draw_face(Panel *pn, const WorldFrame *f, WorldPanel p, const Mesh *m,
                      const Camera *c, int face, double (*pos)[2], double *w)
{
    const Face *fc = &m->faces[face];
    for (int k = 0; k < fc->count; k++) {
        Vec3 view = camera_to_view(c, m->verts[m->corners[fc->first + k]]);
        world_to_picture(f, p, view, &pos[k][0], &pos[k][1]);
        w[k] = nearness_of(p, view);
        if (!isfinite(w[k]))
            return;
    }
    Rgb colour = face_base_colour(m, face);
    for (int t = 0; t < fc->count - 2; t++) {
        const Tri *tri = &m->tris[fc->first_tri + t];
        double tp[3][2], tw[3];
        for (int k = 0; k < 3; k++) {
            tp[k][0] = pos[tri->c[k]][0];
            tp[k][1] = pos[tri->c[k]][1];
            tw[k] = w[tri->c[k]];
        }
        fill_triangle(pn, tp, tw, colour);
    }
    for (int k = 0; k < fc->count; k++) {
        int next = (k + 1) % fc->count;
        LineStyle s = {.half_width = EDGE_HALF_WIDTH, .depth = true, .w0 = w[k], .w1 = w[next],
                       .colour = colour};
        draw_line(pn, pos[k][0], pos[k][1], pos[next][0], pos[next][1], &s);
    }
}

/* A label with a one-pixel shadow, moved inside the panel when it would leave it. */
static void label(Panel *pn, double x, double y, const char *text, Rgb c)
{
    int w = text_width(text), h = text_height(text);
    int lx = (int)fmin(fmax(x, pn->x0 + 2.0), pn->x0 + WORLD_PANEL - 3.0 - w);
    int ly = (int)fmin(fmax(y, pn->y0 + 2.0), pn->y0 + WORLD_PANEL - 3.0 - h);
    draw_text(pn->im, lx + 1, ly + 1, text, SHADOW_COLOUR);
    draw_text(pn->im, lx, ly, text, c);
}

/* The largest 1, 2 or 5 times a power of ten that is at most x. */
static double round_length(double x)
{
    double ten = pow(10, floor(log10(x)));
    return x >= 5 * ten ? 5 * ten : x >= 2 * ten ? 2 * ten : ten;
}

static void draw_scale_bar(Panel *pn, const WorldFrame *f, WorldPanel p)
{
    double units = round_length(SCALE_BAR_TARGET / f->scale);
    double len = units * f->scale;
    if (!(isfinite(units) && units > 0 && len >= 1))
        return;
    double x = pn->x0 + 8, y = pn->y0 + WORLD_PANEL - 8.5;
    plain_line(pn, x, y, x + len, y, 0, SCALE_COLOUR);
    plain_line(pn, x, y - 3, x, y + 3, 0, SCALE_COLOUR);
    plain_line(pn, x + len, y - 3, x + len, y + 3, 0, SCALE_COLOUR);
    char text[96];
    if (f->stretch[p] > 1)
        snprintf(text, sizeof text, "%g units; vertical x%d", units, f->stretch[p]);
    else
        snprintf(text, sizeof text, "%g units", units);
    label(pn, x + len + 6, y - 4, text, SCALE_COLOUR);
}

/* The eye, its line of sight, the frustum, the near and far planes. */
static void draw_camera_lines(Panel *pn, const WorldFrame *f, WorldPanel p, const Camera *c)
{
    double tan_half = half_fov_tan(c, p), ex, ey, x, y, x2, y2;
    /* The depth at the panel's right edge: lines go no farther. */
    double d_edge = f->d0 + (pn->x0 + WORLD_PANEL + 2 - f->left[p]) / f->scale;
    double d_end = fmin(c->far, d_edge);
    place(f, p, 0, 0, &ex, &ey);
    place(f, p, d_edge, 0, &x, &y);
    plain_line(pn, ex, ey, x, y, 0, AXIS_COLOUR);
    for (int side = -1; side <= 1; side += 2) {
        place(f, p, d_end, side * d_end * tan_half, &x, &y);
        plain_line(pn, ex, ey, x, y, 0, WORLD_FRUSTUM_COLOUR);
    }
    place(f, p, c->near, c->near * tan_half, &x, &y);
    place(f, p, c->near, -c->near * tan_half, &x2, &y2);
    plain_line(pn, x, y, x2, y2, PLANE_HALF_WIDTH, WORLD_NEAR_COLOUR);
    if (c->far <= d_edge) {
        place(f, p, c->far, c->far * tan_half, &x, &y);
        place(f, p, c->far, -c->far * tan_half, &x2, &y2);
        plain_line(pn, x, y, x2, y2, PLANE_HALF_WIDTH, WORLD_FAR_COLOUR);
    }
}

static void draw_labels(Panel *pn, const WorldFrame *f, WorldPanel p, const Camera *c)
{
    double tan_half = half_fov_tan(c, p), ex, ey, x, y;
    char text[64];
    place(f, p, 0, 0, &ex, &ey);
    int cx = (int)floor(ex), cy = (int)floor(ey);
    for (int dy = -EYE_RADIUS; dy <= EYE_RADIUS; dy++)
        for (int dx = -EYE_RADIUS; dx <= EYE_RADIUS; dx++)
            if (dx * dx + dy * dy <= EYE_RADIUS * EYE_RADIUS + 1)
                put(pn, cx + dx, cy + dy, WORLD_EYE_COLOUR);
    label(pn, ex - EYE_RADIUS - 3 - text_width("eye"), ey - FONT_GLYPH_HEIGHT / 2.0 - 0.5, "eye",
          WORLD_EYE_COLOUR);

    place(f, p, c->near, c->near * tan_half, &x, &y);
    snprintf(text, sizeof text, "near d=%g", c->near);
    label(pn, x + 3, y - FONT_LINE_HEIGHT - 2, text, WORLD_NEAR_COLOUR);

    double d_edge = f->d0 + (pn->x0 + WORLD_PANEL - f->left[p]) / f->scale;
    if (c->far <= d_edge) {
        place(f, p, c->far, c->far * tan_half, &x, &y);
        snprintf(text, sizeof text, "far d=%g", c->far);
        double w = text_width(text);
        double lx = x + 4 + w <= pn->x0 + WORLD_PANEL - 3 ? x + 4 : x - 4 - w;
        label(pn, lx, y - FONT_LINE_HEIGHT - 2, text, WORLD_FAR_COLOUR);
    } else {
        snprintf(text, sizeof text, "far d=%g ->", c->far);
        label(pn, pn->x0 + WORLD_PANEL - 3 - text_width(text), pn->y0 + 4, text,
              WORLD_FAR_COLOUR);
    }
}

static int largest_face(const Mesh *m)
{
    int n = 3;
    for (int i = 0; i < m->nfaces; i++)
        n = m->faces[i].count > n ? m->faces[i].count : n;
    return n;
}

bool world_view_image(const Mesh *m, const Camera *c, Image *out, Error *err)
{
    if (!image_init(out, WORLD_VIEW_WIDTH, WORLD_VIEW_HEIGHT, err))
        return false;
    size_t corners = (size_t)largest_face(m);
    float *nearness = malloc((size_t)WORLD_PANEL * WORLD_PANEL * sizeof *nearness);
    double(*pos)[2] = malloc(corners * sizeof *pos);
    double *w = malloc(corners * sizeof *w);
    if (!nearness || !pos || !w) {
        free(nearness);
        free(pos);
        free(w);
        image_free(out);
        return error_set(err, "out of memory drawing the world view");
    }
    image_fill(out, GAP_COLOUR);
    WorldFrame f = world_frame(m, c);
    for (int p = 0; p < 2; p++) {
        Panel pn = {.im = out, .nearness = nearness, .x0 = (int)panel_left_edge((WorldPanel)p),
                    .y0 = WORLD_TITLE};
        for (int y = 0; y < WORLD_TITLE; y++)
            for (int x = pn.x0; x < pn.x0 + WORLD_PANEL; x++)
                image_set(out, x, y, TITLE_BACKGROUND);
        draw_text(out, pn.x0 + 4, (WORLD_TITLE - FONT_GLYPH_HEIGHT) / 2, TITLES[p], TITLE_COLOUR);
        for (int y = 0; y < WORLD_PANEL; y++)
            for (int x = 0; x < WORLD_PANEL; x++) {
                nearness[(size_t)y * WORLD_PANEL + (size_t)x] = -INFINITY;
                image_set(out, pn.x0 + x, pn.y0 + y, FLAT_BACKGROUND);
            }
        draw_camera_lines(&pn, &f, (WorldPanel)p, c);
        for (int i = 0; i < m->nfaces; i++)
            draw_face(&pn, &f, (WorldPanel)p, m, c, i, pos, w);
        draw_labels(&pn, &f, (WorldPanel)p, c);
        draw_scale_bar(&pn, &f, (WorldPanel)p);
    }
    free(nearness);
    free(pos);
    free(w);
    return true;
}

bool world_view_write(const Mesh *m, const Camera *c, const char *path, Error *err)
{
    Image im;
    if (!world_view_image(m, c, &im, err))
        return false;
    bool ok = image_write_png(&im, path, err);
    image_free(&im);
    return ok;
}
