/* zlib_pako.c: see zlib.h beside it. deflate keeps what it is given; at
 * Z_FINISH pako deflates it all at once, and deflate hands the zlib stream
 * out as room allows. */
#include "zlib.h"

#include <emscripten.h>

#include <stdlib.h>
#include <string.h>

typedef struct {
    unsigned char *data; /* the input so far; at the end, the stream */
    size_t size, capacity, sent;
    int finished;
} Held;

int deflateInit(z_stream *z, int level)
{
    (void)level;
    Held *h = calloc(1, sizeof *h);
    z->state = h;
    return h ? Z_OK : Z_MEM_ERROR;
}

static int keep(Held *h, const unsigned char *p, size_t n)
{
    if (h->size + n > h->capacity) {
        size_t c = h->capacity ? h->capacity : 65536;
        while (c < h->size + n)
            c *= 2;
        unsigned char *d = realloc(h->data, c);
        if (!d)
            return 0;
        h->data = d, h->capacity = c;
    }
    memcpy(h->data + h->size, p, n);
    h->size += n;
    return 1;
}

/* The held input deflated by pako (zlib's deflate ported to JavaScript,
 * which the page or run.js loads as globalThis.pako) at zlib's defaults,
 * as common/harness/image_io.c asks: the bytes native zlib gives. Its
 * length, or -1 if pako could not. pako_take copies it into dst. */
EM_JS(int, pako_deflate, (const unsigned char *data, int size), {
    try {
        Module.deflated = globalThis.pako.deflate(HEAPU8.subarray(data, data + size));
        return Module.deflated.length;
    } catch (e) {
        return -1;
    }
});
EM_JS(void, pako_take, (unsigned char *dst), {
    HEAPU8.set(Module.deflated, dst);
    Module.deflated = null;
});

static int finish(Held *h)
{
    int n = h->size <= 0x7fffffff ? pako_deflate(h->data, (int)h->size) : -1;
    unsigned char *s = n >= 0 ? malloc((size_t)n + 1) : NULL;
    if (!s)
        return 0;
    pako_take(s);
    free(h->data);
    h->data = s, h->size = (size_t)n, h->capacity = (size_t)n, h->sent = 0, h->finished = 1;
    return 1;
}

int deflate(z_stream *z, int flush)
{
    Held *h = z->state;
    if (!h)
        return Z_STREAM_ERROR;
    if (!h->finished) {
        if (z->avail_in && !keep(h, z->next_in, z->avail_in))
            return Z_MEM_ERROR;
        z->next_in += z->avail_in, z->avail_in = 0;
        if (flush != Z_FINISH)
            return Z_OK;
        if (!finish(h))
            return Z_MEM_ERROR;
    }
    size_t n = h->size - h->sent < z->avail_out ? h->size - h->sent : z->avail_out;
    memcpy(z->next_out, h->data + h->sent, n);
    z->next_out += n, z->avail_out -= (uInt)n, h->sent += n;
    return h->sent == h->size ? Z_STREAM_END : Z_OK;
}

int deflateEnd(z_stream *z)
{
    Held *h = z->state;
    if (h)
        free(h->data), free(h);
    z->state = NULL;
    return Z_OK;
}

uLong crc32(uLong crc, const Bytef *buf, uInt len)
{
    static unsigned long table[256];
    if (!table[1])
        for (unsigned long n = 0; n < 256; n++) {
            unsigned long c = n;
            for (int k = 0; k < 8; k++)
                c = c & 1 ? 0xedb88320UL ^ (c >> 1) : c >> 1;
            table[n] = c;
        }
    if (!buf)
        return 0;
    crc = ~crc & 0xffffffffUL;
    for (uInt i = 0; i < len; i++)
        crc = table[(crc ^ buf[i]) & 0xff] ^ (crc >> 8);
    return ~crc & 0xffffffffUL;
}
