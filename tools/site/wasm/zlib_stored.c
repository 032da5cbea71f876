/* zlib_stored.c: see zlib.h beside it. deflate keeps what it is given;
 * at Z_FINISH it makes the zlib stream (RFC 1950: a header, the data in
 * stored deflate blocks of at most 65535 bytes (RFC 1951), the Adler-32 of
 * the data) and hands it out as room allows. */
#include "zlib.h"

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

static int finish(Held *h)
{
    size_t n = h->size, blocks = n / 65535 + 1;
    unsigned char *s = malloc(2 + n + 5 * blocks + 4);
    if (!s)
        return 0;
    unsigned long a = 1, b = 0;
    for (size_t i = 0; i < n; i++)
        a = (a + h->data[i]) % 65521, b = (b + a) % 65521;
    size_t o = 0, i = 0;
    s[o++] = 0x78, s[o++] = 0x01; /* deflate, 32K window, check bits: 0x7801 % 31 == 0 */
    do {
        size_t len = n - i < 65535 ? n - i : 65535;
        s[o++] = i + len == n; /* BFINAL on the last block, BTYPE 00: stored */
        s[o++] = (unsigned char)len, s[o++] = (unsigned char)(len >> 8);
        s[o++] = (unsigned char)~len, s[o++] = (unsigned char)(~len >> 8);
        memcpy(s + o, h->data + i, len);
        o += len, i += len;
    } while (i < n);
    s[o++] = (unsigned char)(b >> 8), s[o++] = (unsigned char)b;
    s[o++] = (unsigned char)(a >> 8), s[o++] = (unsigned char)a;
    free(h->data);
    h->data = s, h->size = o, h->capacity = o, h->sent = 0, h->finished = 1;
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
