/* compare.h: --compare REF.png, checking this run's picture against a reference.
 *
 * The picture is compared exactly (no tolerance) with REF.png. One line says
 * what was found:
 *
 *     compare: the images match
 *     compare: 1 pixel differs, largest channel difference 255, in box (3,2)-(3,2)
 *
 * and a diff picture is written next to --out, named after it: out/02_zbuffer.png
 * gets out/02_zbuffer.diff.png, this run's picture dimmed to a quarter where it
 * matches, magenta where it differs (image_compare, image.h).
 *
 * The status says it to a script: EXIT_OK when the images match,
 * EXIT_IMAGES_DIFFER (3) when they differ, EXIT_RUN_FAILED (1) when REF.png
 * cannot be read, has another size, or the diff picture cannot be written. */
#ifndef COMPARE_H
#define COMPARE_H

#include <stddef.h>
#include <stdio.h>

#include "error.h"
#include "image_io.h"

/* Where the diff picture of --out goes: a trailing ".png" becomes ".diff.png";
 * any other name gets ".diff.png" added. False when buf is too small. */
bool compare_diff_path(const char *out_path, char *buf, size_t size);

/* Whether the PNG at ref_path can be read and is width x height: checked
 * before anything is drawn, so that a run whose reference cannot be read
 * fails before its summary says "wrote" of files it will not publish. */
bool compare_reference_readable(const char *ref_path, int width, int height, Error *err);

/* Compares picture (this run's) with the PNG at ref_path, prints the line on
 * out and writes the diff picture beside out_path (compare_diff_path). */
int compare_picture(FILE *out, const Image *picture, const char *ref_path, const char *out_path,
                    Error *err);

#endif
