/* steps.c: see steps.h. */
#include "steps.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "file.h"

/* Room for "/step_NNNN_depth.png" (more digits past step 9999) and the NUL. */
#define STEP_NAME_MAX 40

bool steps_write(const char *dir, int step, const Image *picture, const Image *depth, Error *err)
{
    if (!make_dirs(dir, err))
        return false;
    size_t size = strlen(dir) + STEP_NAME_MAX;
    char *path = malloc(size);
    if (!path)
        return error_set(err, "out of memory");
    snprintf(path, size, "%s/step_%04d.png", dir, step);
    bool ok = image_write_png(picture, path, err);
    snprintf(path, size, "%s/step_%04d_depth.png", dir, step);
    ok = ok && image_write_png(depth, path, err);
    free(path);
    return ok;
}
