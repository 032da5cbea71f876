/* compare_naive.c: the picture of --compare-naive (see compare_naive.h). */
#include "compare_naive.h"

#include <string.h>

#include "compare.h"
#include "file.h"

#define AGREED_DIM 2       /* pixels both rules agree on are shown at half brightness */

static const Rgb NAIVE_MARK = {255, 0, 255}; /* magenta */

static bool draw_with(Render *r, const Rasterizer *rz, Target *t, Error *err)
{
    return render_target_init(t, rz, r->camera.width, r->camera.height, err) &&
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

bool compare_with_naive(Render *r, const Options *opt, const Rasterizer *right,
                        const Rasterizer *naive, const char *path, long *differing, Error *err)
{
    FaceCounts counts = r->counts; /* render_faces adds to them: restored below */
    Target with_right = {0}, with_naive = {0};
    Image im = {0};
    bool ok = draw_with(r, right, &with_right, err) && draw_with(r, naive, &with_naive, err) &&
              render_image(r, &with_right, right, opt->shade, &im, err);
    if (ok) {
        *differing = mark_differences(&with_right, &with_naive, &im);
        ok = render_make_parent_dirs(path, err) && image_write_png(&im, path, err);
    }
    image_free(&im);
    target_free(&with_right);
    target_free(&with_naive);
    r->counts = counts;
    return ok;
}
