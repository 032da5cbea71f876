/* fuzz_png.c: the reader of --compare references (common/harness/image_io.c
 * image_decode_png) against any bytes (make fuzz FUZZ=png).
 *
 * Whatever the bytes, the reader either refuses them with one line that names
 * the file (never "(null)"), or returns a picture of the size its header
 * gave, within 1 to IMAGE_MAX_SIDE on a side. The first two bytes choose a
 * wanted size (0: any), as --compare asks for the picture's size; a header
 * of another size is refused before any decoding. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "harness/image_io.h"

static void check(bool ok, const char *what)
{
    if (!ok) {
        fprintf(stderr, "fuzz_png: broken invariant: %s\n", what);
        abort();
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 2)
        return 0;
    int want = data[0] ? data[0] : 0; /* 1 .. 255 on a side, or any size */
    int want_h = data[1] ? data[1] : want;
    Image im;
    Error err;
    err.msg[0] = '\0';
    bool ok = image_decode_png(&im, data + 2, size - 2, "f.png", want, want ? want_h : 0, &err);
    if (ok) {
        check(im.rgb != NULL, "a picture read has pixels");
        check(im.width >= 1 && im.width <= IMAGE_MAX_SIDE && im.height >= 1 &&
                  im.height <= IMAGE_MAX_SIDE, "a picture read is within the size limits");
        check(!want || (im.width == want && im.height == want_h), "the wanted size");
        image_free(&im);
    } else {
        check(im.rgb == NULL, "no picture after a refusal");
        check(strstr(err.msg, "f.png") != NULL, "the message names the file");
        check(strchr(err.msg, '\n') == NULL, "the message is one line");
        check(strstr(err.msg, "(null)") == NULL, "the message gives a reason");
    }
    return 0;
}
