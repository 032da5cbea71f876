/* stb_image.c: stb_image's implementation, for the browser build of the
 * lessons (make wasm): natively it comes from Debian's libstb; here it is
 * compiled from the same header. */
#define STB_IMAGE_IMPLEMENTATION
#include <stb_image.h>
