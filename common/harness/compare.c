/* compare.c: see compare.h. */
#include "compare.h"

#include <stdlib.h>
#include <string.h>

#define PNG_SUFFIX ".png"
#define DIFF_SUFFIX ".diff.png"
#define EXACT 0 /* channel tolerance: a reference is matched bit for bit */

bool compare_diff_path(const char *out_path, char *buf, size_t size)
{
    size_t len = strlen(out_path), suffix = strlen(PNG_SUFFIX);
    if (len > suffix && strcmp(out_path + len - suffix, PNG_SUFFIX) == 0)
        len -= suffix;
    int n = snprintf(buf, size, "%.*s%s", (int)len, out_path, DIFF_SUFFIX);
    return n >= 0 && (size_t)n < size;
}

static void print_result(FILE *out, const ImageDiff *d)
{
    if (d->differing == 0) {
        fprintf(out, "compare: the images match\n");
        return;
    }
    fprintf(out, "compare: %ld pixel%s, largest channel difference %d, in box (%d,%d)-(%d,%d)\n",
            d->differing, d->differing == 1 ? " differs" : "s differ", d->max_channel_diff,
            d->x0, d->y0, d->x1, d->y1);
}

/* Compares picture with the PNG at ref_path, prints the line on out and writes
 * the diff picture to diff_path. */
static int compare_with_reference(FILE *out, const Image *picture, const char *ref_path,
                                  const char *diff_path, Error *err)
{
    Image ref, diff;
    Error why;
    /* The reference's size is checked from its header, before decoding. */
    if (!image_read_png_sized(&ref, ref_path, picture->width, picture->height, &why)) {
        error_set(err, "--compare: %s", why.msg);
        return EXIT_RUN_FAILED;
    }
    ImageDiff d;
    bool ok = image_compare(&ref, picture, EXACT, &d, &diff, err);
    image_free(&ref);
    if (!ok)
        return EXIT_RUN_FAILED;
    ok = image_write_png(&diff, diff_path, err);
    image_free(&diff);
    if (!ok)
        return EXIT_RUN_FAILED;
    print_result(out, &d);
    fprintf(out, "  wrote %s\n", diff_path);
    return d.differing ? EXIT_IMAGES_DIFFER : EXIT_OK;
}

bool compare_reference_readable(const char *ref_path, int width, int height, Error *err)
{
    Image ref;
    Error why;
    if (!image_read_png_sized(&ref, ref_path, width, height, &why))
        return error_set(err, "--compare: %s", why.msg);
    image_free(&ref);
    return true;
}

int compare_picture(FILE *out, const Image *picture, const char *ref_path, const char *out_path,
                    Error *err)
{
    size_t size = strlen(out_path) + sizeof DIFF_SUFFIX;
    char *diff_path = malloc(size);
    if (!diff_path) {
        error_set(err, "out of memory");
        return EXIT_RUN_FAILED;
    }
    compare_diff_path(out_path, diff_path, size);
    int status = compare_with_reference(out, picture, ref_path, diff_path, err);
    free(diff_path);
    return status;
}
