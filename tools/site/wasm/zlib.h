/* zlib.h for the browser build of the lessons (make wasm): the part of
 * zlib that common/harness/image_io.c uses. Debian's emscripten ships no
 * zlib, so deflate is pako's (npm), zlib's deflate ported to JavaScript,
 * which gives the bytes zlib gives: the browser build's PNGs are the native
 * ones, byte for byte (make site-test compares them). zlib_pako.c has the
 * functions. */
#ifndef ZLIB_PAKO_H
#define ZLIB_PAKO_H

typedef unsigned char Bytef;
typedef unsigned int uInt;
typedef unsigned long uLong;

typedef struct z_stream_s {
    const Bytef *next_in; /* what deflate reads next */
    uInt avail_in;
    Bytef *next_out; /* where deflate writes next */
    uInt avail_out;
    void *state; /* the stream held until Z_FINISH, then written out */
} z_stream;

#define Z_OK 0
#define Z_STREAM_END 1
#define Z_STREAM_ERROR (-2)
#define Z_MEM_ERROR (-4)
#define Z_BUF_ERROR (-5)
#define Z_NO_FLUSH 0
#define Z_FINISH 4
#define Z_DEFAULT_COMPRESSION (-1)

int deflateInit(z_stream *z, int level);
int deflate(z_stream *z, int flush);
int deflateEnd(z_stream *z);
uLong crc32(uLong crc, const Bytef *buf, uInt len);

#endif
