/* compare_naive.c: the picture of --compare-naive (see compare_naive.h). */
#include "compare_naive.h"

#include "scanline.h"

#define AGREED_DIM 2 /* pixels both rules agree on are shown at half brightness */

const Rgb NAIVE_MARK = {255, 0, 255};

static bool draw_with(Render *r, const Rasterizer *rz, Target *t, Error *err)
{
    return target_init(t, r->camera.width, r->camera.height, rz->clear_value, err) &&
           render_faces(r, t, rz, NULL, 0, NULL, NULL, err);
}

/* Marks the pixels whose winning face differs; returns how many there are. */
static long mark_differences(const Target *right, const Target *naive, Image *im)
{
    long differing = 0;
    for (int y = 0; y < im->height; y++)
        for (int x = 0; x < im->width; x++) {
            size_t i = (size_t)y * (size_t)im->width + (size_t)x;
            Rgb c = image_get(im, x, y);
            Rgb dim = {(uint8_t)(c.r / AGREED_DIM), (uint8_t)(c.g / AGREED_DIM),
                       (uint8_t)(c.b / AGREED_DIM)};
            bool differs = right->face[i] != naive->face[i];
            differing += differs;
            image_set(im, x, y, differs ? NAIVE_MARK : dim);
        }
    return differing;
}

bool compare_with_naive(Render *r, const Options *opt, const char *path, long *differing,
                        Error *err)
{
    FaceCounts counts = r->counts; /* render_faces adds to them: restored below */
    Target right = {0}, naive = {0};
    Image im = {0};
    bool ok = draw_with(r, &SCANLINE_ZBUFFER, &right, err) &&
              draw_with(r, &SCANLINE_ZBUFFER_NAIVE, &naive, err) &&
              render_image(r, &right, &SCANLINE_ZBUFFER, opt->shade, &im, err);
    if (ok) {
        *differing = mark_differences(&right, &naive, &im);
        ok = render_make_parent_dirs(path, err) && image_write_png(&im, path, err);
    }
    image_free(&im);
    target_free(&right);
    target_free(&naive);
    r->counts = counts;
    return ok;
}
