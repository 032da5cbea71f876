/* json.c: see json.h. A recursive-descent parser over the grammar of RFC 8259. */
#include "json.h"

#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_DEPTH 64 /* more levels of nesting are refused, not a stack overflow */

typedef struct {
    const char *text;
    size_t len, pos;
    char *why;
    size_t why_size;
    bool failed;
} Parser;

static bool fail_at(Parser *p, const char *fmt, ...)
{
    if (p->failed)
        return false;
    p->failed = true;
    size_t line = 1, column = 1;
    for (size_t i = 0; i < p->pos && i < p->len; i++) {
        if (p->text[i] == '\n') {
            line++;
            column = 1;
        } else {
            column++;
        }
    }
    int n = snprintf(p->why, p->why_size, "line %zu, column %zu: ", line, column);
    if (n >= 0 && (size_t)n < p->why_size) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(p->why + n, p->why_size - (size_t)n, fmt, ap);
        va_end(ap);
    }
    return false;
}

static int peek(const Parser *p)
{
    return p->pos < p->len ? (unsigned char)p->text[p->pos] : -1;
}

/* The four whitespace characters of JSON, and no other. */
static void skip_space(Parser *p)
{
    while (p->pos < p->len) {
        char c = p->text[p->pos];
        if (c != ' ' && c != '\t' && c != '\n' && c != '\r')
            break;
        p->pos++;
    }
}

static bool literal(Parser *p, const char *word)
{
    size_t n = strlen(word);
    if (p->len - p->pos < n || memcmp(p->text + p->pos, word, n) != 0)
        return fail_at(p, "unexpected text (a value is a string, number, object, array, "
                          "true, false or null)");
    p->pos += n;
    return true;
}

static bool is_digit(int c)
{
    return c >= '0' && c <= '9';
}

/* number = [ "-" ] ( "0" / 1-9 *DIGIT ) [ "." 1*DIGIT ] [ ( "e" / "E" ) [ "+" / "-" ] 1*DIGIT ] */
static bool parse_number(Parser *p, JsonValue *v)
{
    size_t start = p->pos;
    if (peek(p) == '-')
        p->pos++;
    if (peek(p) == '0') {
        p->pos++;
        if (is_digit(peek(p)))
            return fail_at(p, "a number has no leading zero");
    } else if (is_digit(peek(p))) {
        while (is_digit(peek(p)))
            p->pos++;
    } else {
        return fail_at(p, "a number wants a digit here");
    }
    if (peek(p) == '.') {
        p->pos++;
        if (!is_digit(peek(p)))
            return fail_at(p, "a number wants a digit after its decimal point");
        while (is_digit(peek(p)))
            p->pos++;
    }
    if (peek(p) == 'e' || peek(p) == 'E') {
        p->pos++;
        if (peek(p) == '+' || peek(p) == '-')
            p->pos++;
        if (!is_digit(peek(p)))
            return fail_at(p, "a number wants a digit in its exponent");
        while (is_digit(peek(p)))
            p->pos++;
    }
    char buf[64];
    size_t n = p->pos - start;
    if (n >= sizeof buf)
        return fail_at(p, "a number longer than %zu characters", sizeof buf - 1);
    memcpy(buf, p->text + start, n);
    buf[n] = '\0';
    v->type = JSON_NUMBER;
    v->number = strtod(buf, NULL);
    return true;
}

static int hex_value(int c)
{
    if (c >= '0' && c <= '9')
        return c - '0';
    if (c >= 'a' && c <= 'f')
        return c - 'a' + 10;
    if (c >= 'A' && c <= 'F')
        return c - 'A' + 10;
    return -1;
}

static bool parse_hex4(Parser *p, uint32_t *out)
{
    uint32_t u = 0;
    for (int i = 0; i < 4; i++) {
        int h = hex_value(peek(p));
        if (h < 0)
            return fail_at(p, "\\u wants four hexadecimal digits");
        u = u * 16 + (uint32_t)h;
        p->pos++;
    }
    *out = u;
    return true;
}

/* Appends code point u as UTF-8; buf has room (see parse_string). */
static size_t put_utf8(char *buf, uint32_t u)
{
    if (u < 0x80) {
        buf[0] = (char)u;
        return 1;
    }
    if (u < 0x800) {
        buf[0] = (char)(0xC0 | (u >> 6));
        buf[1] = (char)(0x80 | (u & 0x3F));
        return 2;
    }
    if (u < 0x10000) {
        buf[0] = (char)(0xE0 | (u >> 12));
        buf[1] = (char)(0x80 | ((u >> 6) & 0x3F));
        buf[2] = (char)(0x80 | (u & 0x3F));
        return 3;
    }
    buf[0] = (char)(0xF0 | (u >> 18));
    buf[1] = (char)(0x80 | ((u >> 12) & 0x3F));
    buf[2] = (char)(0x80 | ((u >> 6) & 0x3F));
    buf[3] = (char)(0x80 | (u & 0x3F));
    return 4;
}

/* A \u escape, with its second half if it is the first of a surrogate pair. */
static bool parse_unicode_escape(Parser *p, uint32_t *out)
{
    uint32_t u = 0;
    if (!parse_hex4(p, &u))
        return false;
    if (u >= 0xDC00 && u <= 0xDFFF)
        return fail_at(p, "a lone second half of a surrogate pair");
    if (u >= 0xD800 && u <= 0xDBFF) {
        uint32_t low = 0;
        if (peek(p) != '\\' || p->pos + 1 >= p->len || p->text[p->pos + 1] != 'u')
            return fail_at(p, "the first half of a surrogate pair without its second half");
        p->pos += 2;
        if (!parse_hex4(p, &low))
            return false;
        if (low < 0xDC00 || low > 0xDFFF)
            return fail_at(p, "a surrogate pair whose second half is not one");
        u = 0x10000 + ((u - 0xD800) << 10) + (low - 0xDC00);
    }
    *out = u;
    return true;
}

/* Decodes a string; *out is malloc'ed. The decoded text is never longer than
 * the source (an escape of n characters decodes to at most n bytes). */
static bool parse_string(Parser *p, char **out)
{
    p->pos++; /* the opening quote */
    size_t start = p->pos;
    char *buf = malloc(p->len - start + 1);
    if (!buf)
        return fail_at(p, "out of memory");
    size_t n = 0;
    for (;;) {
        int c = peek(p);
        if (c < 0) {
            free(buf);
            return fail_at(p, "a string without its closing quote");
        }
        if (c < 0x20) {
            free(buf);
            return fail_at(p, "a raw control character (0x%02x) in a string: it must be escaped", c);
        }
        p->pos++;
        if (c == '"')
            break;
        if (c != '\\') {
            buf[n++] = (char)c;
            continue;
        }
        int e = peek(p);
        p->pos++;
        uint32_t u = 0;
        switch (e) {
        case '"': buf[n++] = '"'; break;
        case '\\': buf[n++] = '\\'; break;
        case '/': buf[n++] = '/'; break;
        case 'b': buf[n++] = '\b'; break;
        case 'f': buf[n++] = '\f'; break;
        case 'n': buf[n++] = '\n'; break;
        case 'r': buf[n++] = '\r'; break;
        case 't': buf[n++] = '\t'; break;
        case 'u':
            if (!parse_unicode_escape(p, &u)) {
                free(buf);
                return false;
            }
            n += put_utf8(buf + n, u);
            break;
        default:
            p->pos--;
            free(buf);
            return fail_at(p, "an unknown escape in a string");
        }
    }
    buf[n] = '\0';
    *out = buf;
    return true;
}

static bool parse_value(Parser *p, JsonValue *v, int depth);

static bool grow(Parser *p, JsonValue *v, size_t *cap, bool with_keys)
{
    if (v->count < *cap)
        return true;
    size_t new_cap = *cap ? *cap * 2 : 8;
    JsonValue *items = realloc(v->items, new_cap * sizeof *items);
    if (!items)
        return fail_at(p, "out of memory");
    v->items = items;
    if (with_keys) {
        char **keys = realloc(v->keys, new_cap * sizeof *keys);
        if (!keys)
            return fail_at(p, "out of memory");
        v->keys = keys;
    }
    *cap = new_cap;
    return true;
}

static bool parse_array(Parser *p, JsonValue *v, int depth)
{
    p->pos++; /* [ */
    v->type = JSON_ARRAY;
    size_t cap = 0;
    skip_space(p);
    if (peek(p) == ']') {
        p->pos++;
        return true;
    }
    for (;;) {
        if (!grow(p, v, &cap, false))
            return false;
        v->count++; /* counted first, so that json_free frees it on failure */
        if (!parse_value(p, &v->items[v->count - 1], depth + 1))
            return false;
        skip_space(p);
        if (peek(p) == ',') {
            p->pos++;
            continue;
        }
        if (peek(p) == ']') {
            p->pos++;
            return true;
        }
        return fail_at(p, "an array wants ',' or ']' here");
    }
}

static bool parse_object(Parser *p, JsonValue *v, int depth)
{
    p->pos++; /* { */
    v->type = JSON_OBJECT;
    size_t cap = 0;
    skip_space(p);
    if (peek(p) == '}') {
        p->pos++;
        return true;
    }
    for (;;) {
        skip_space(p);
        if (peek(p) != '"')
            return fail_at(p, "an object wants a key, a string in double quotes, here");
        if (!grow(p, v, &cap, true))
            return false;
        size_t key_pos = p->pos;
        char *key;
        if (!parse_string(p, &key))
            return false;
        for (size_t i = 0; i < v->count; i++)
            if (strcmp(v->keys[i], key) == 0) {
                p->pos = key_pos;
                free(key);
                return fail_at(p, "the key \"%s\" twice in one object", v->keys[i]);
            }
        v->keys[v->count] = key;
        v->items[v->count] = (JsonValue){0};
        v->count++; /* counted now, so that json_free frees the key on failure */
        skip_space(p);
        if (peek(p) != ':')
            return fail_at(p, "an object wants ':' after a key");
        p->pos++;
        if (!parse_value(p, &v->items[v->count - 1], depth + 1))
            return false;
        skip_space(p);
        if (peek(p) == ',') {
            p->pos++;
            continue;
        }
        if (peek(p) == '}') {
            p->pos++;
            return true;
        }
        return fail_at(p, "an object wants ',' or '}' here");
    }
}

static bool parse_value(Parser *p, JsonValue *v, int depth)
{
    *v = (JsonValue){0};
    if (depth >= MAX_DEPTH)
        return fail_at(p, "more than %d levels of nesting", MAX_DEPTH);
    skip_space(p);
    switch (peek(p)) {
    case '{': return parse_object(p, v, depth);
    case '[': return parse_array(p, v, depth);
    case '"': v->type = JSON_STRING; return parse_string(p, &v->string);
    case 't': v->type = JSON_BOOL; v->boolean = true; return literal(p, "true");
    case 'f': v->type = JSON_BOOL; v->boolean = false; return literal(p, "false");
    case 'n': v->type = JSON_NULL; return literal(p, "null");
    case -1: return fail_at(p, "the text ends where a value should be");
    default: return parse_number(p, v);
    }
}

bool json_parse(const char *text, size_t len, JsonValue *out, char *why, size_t why_size)
{
    Parser p = {text, len, 0, why, why_size, false};
    if (why_size > 0)
        why[0] = '\0';
    bool ok = parse_value(&p, out, 0);
    if (ok) {
        skip_space(&p);
        if (p.pos != p.len)
            ok = fail_at(&p, "more text after the value");
    }
    if (!ok) {
        json_free(out);
        *out = (JsonValue){0};
    }
    return ok;
}

void json_free(JsonValue *v)
{
    if (v->type == JSON_ARRAY || v->type == JSON_OBJECT) {
        for (size_t i = 0; i < v->count; i++) {
            json_free(&v->items[i]);
            if (v->keys)
                free(v->keys[i]);
        }
    }
    free(v->items);
    free(v->keys);
    free(v->string);
    *v = (JsonValue){0};
}

const JsonValue *json_get(const JsonValue *v, const char *key)
{
    if (!v || v->type != JSON_OBJECT)
        return NULL;
    for (size_t i = 0; i < v->count; i++)
        if (strcmp(v->keys[i], key) == 0)
            return &v->items[i];
    return NULL;
}

const char *json_type_name(JsonType t)
{
    static const char *const names[] = {"null", "boolean", "number", "string", "array", "object"};
    return (unsigned)t < sizeof names / sizeof names[0] ? names[t] : "?";
}
