/* json.h: a small, strict JSON parser (RFC 8259), for tests that check a file
 * that another program reads as JSON (make grade's results.json).
 *
 * Strict on purpose: what it accepts, any JSON reader accepts. No trailing
 * commas, no comments, no leading zeros or bare dots in numbers, no raw
 * control characters in strings, nothing after the value; \u escapes
 * (surrogate pairs too) are decoded to UTF-8. A key twice in one object is
 * refused as well: readers disagree on which one wins.
 *
 *     JsonValue v;
 *     char why[256];
 *     if (!json_parse(text, len, &v, why, sizeof why)) fail_msg("%s", why);
 *     const JsonValue *score = json_get(&v, "score");
 *     ...
 *     json_free(&v);
 */
#ifndef JSON_H
#define JSON_H

#include <stdbool.h>
#include <stddef.h>

typedef enum { JSON_NULL, JSON_BOOL, JSON_NUMBER, JSON_STRING, JSON_ARRAY, JSON_OBJECT } JsonType;

typedef struct JsonValue JsonValue;
struct JsonValue {
    JsonType type;
    bool boolean;     /* JSON_BOOL */
    double number;    /* JSON_NUMBER */
    char *string;     /* JSON_STRING: the decoded text, NUL-terminated */
    size_t count;     /* JSON_ARRAY, JSON_OBJECT: how many items */
    JsonValue *items; /* the array's items, or the object's values */
    char **keys;      /* JSON_OBJECT: keys[i] names items[i] */
};

/* Parses text[0..len). On failure returns false and says what and where
 * ("line 3, column 7: ...") in why; out is then left empty. */
bool json_parse(const char *text, size_t len, JsonValue *out, char *why, size_t why_size);
void json_free(JsonValue *v);

/* The value of key in an object; NULL if v is not an object or has no such key. */
const JsonValue *json_get(const JsonValue *v, const char *key);
/* The name of a type, for messages: "number", "string", ... */
const char *json_type_name(JsonType t);

#endif
