/* test_json.c: the JSON parser that checks make grade's results.json
 * (tests/support/json.h) accepts what RFC 8259 allows and nothing else. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <string.h>

#include "json.h"
#include "test_support.h"

static JsonValue parse_ok(const char *text)
{
    JsonValue v;
    char why[256];
    if (!json_parse(text, strlen(text), &v, why, sizeof why))
        fail_msg("json_parse refused valid JSON %s: %s", text, why);
    return v;
}

static void expect_refused(const char *text, const char *because)
{
    JsonValue v;
    char why[256];
    if (json_parse(text, strlen(text), &v, why, sizeof why)) {
        json_free(&v);
        fail_msg("json_parse accepted %s, which is not JSON (%s)", text, because);
    }
    assert_true(strstr(why, "line ") == why); /* says where */
}

static void results_shaped_object_is_read_field_by_field(void **state)
{
    (void)state;
    JsonValue v = parse_ok("{\n  \"score\": 12.5,\n  \"tests\": [\n"
                           "    {\"name\": \"a\", \"score\": 0, \"max_score\": 2, \"output\": \"\"},\n"
                           "    {\"name\": \"b\", \"score\": 1e1, \"max_score\": -0.5E-1}\n  ],\n"
                           "  \"ok\": true, \"no\": false, \"none\": null\n}\n");
    assert_int_equal(v.type, JSON_OBJECT);
    assert_int_equal(v.count, 5);
    const JsonValue *score = json_get(&v, "score");
    assert_non_null(score);
    assert_int_equal(score->type, JSON_NUMBER);
    assert_true(score->number == 12.5);
    const JsonValue *tests = json_get(&v, "tests");
    assert_non_null(tests);
    assert_int_equal(tests->type, JSON_ARRAY);
    assert_int_equal(tests->count, 2);
    assert_string_equal(json_get(&tests->items[0], "name")->string, "a");
    assert_true(json_get(&tests->items[1], "score")->number == 10.0);
    assert_true(json_get(&tests->items[1], "max_score")->number == -0.05);
    assert_true(json_get(&v, "ok")->boolean);
    assert_false(json_get(&v, "no")->boolean);
    assert_int_equal(json_get(&v, "none")->type, JSON_NULL);
    assert_null(json_get(&v, "missing"));
    assert_null(json_get(score, "score")); /* not an object */
    json_free(&v);
}

/* Each escape decodes to its character; \u00e9 is e-acute, two bytes in
 * UTF-8 (C3 A9); \ud83d\ude00 is the pair for U+1F600, four bytes
 * (F0 9F 98 80). */
static void escapes_decode_to_utf8(void **state)
{
    (void)state;
    JsonValue v = parse_ok("\"q\\\" b\\\\ s\\/ \\b\\f\\n\\r\\t \\u001b \\u00e9 \\ud83d\\ude00\"");
    assert_int_equal(v.type, JSON_STRING);
    assert_string_equal(v.string, "q\" b\\ s/ \b\f\n\r\t \x1b \xc3\xa9 \xf0\x9f\x98\x80");
    json_free(&v);
}

static void empty_containers_and_nesting(void **state)
{
    (void)state;
    JsonValue v = parse_ok(" [ [], {}, [[1]], {\"a\": {\"b\": []}} ] ");
    assert_int_equal(v.count, 4);
    assert_int_equal(v.items[0].count, 0);
    assert_int_equal(v.items[1].type, JSON_OBJECT);
    assert_true(v.items[2].items[0].items[0].number == 1.0);
    json_free(&v);
}

static void what_is_not_json_is_refused(void **state)
{
    (void)state;
    expect_refused("", "nothing");
    expect_refused("{\"a\": 1,}", "trailing comma in an object");
    expect_refused("[1, 2,]", "trailing comma in an array");
    expect_refused("{a: 1}", "key without quotes");
    expect_refused("{'a': 1}", "single quotes");
    expect_refused("\"tab\there\"", "raw tab in a string");
    expect_refused("\"line\nbreak\"", "raw newline in a string");
    expect_refused("\"\x1b\"", "raw escape character in a string");
    expect_refused("\"open", "unterminated string");
    expect_refused("\"\\x41\"", "unknown escape");
    expect_refused("\"\\u12\"", "short \\u escape");
    expect_refused("\"\\ud83d\"", "half a surrogate pair");
    expect_refused("01", "leading zero");
    expect_refused("1.", "no digit after the point");
    expect_refused(".5", "no digit before the point");
    expect_refused("1e", "empty exponent");
    expect_refused("+1", "plus sign");
    expect_refused("NaN", "not a number literal");
    expect_refused("Infinity", "infinity literal");
    expect_refused("tru", "cut literal");
    expect_refused("{\"a\": 1} x", "text after the value");
    expect_refused("{\"a\": 1, \"a\": 2}", "a key twice");
    expect_refused("[1 2]", "missing comma");
    expect_refused("{\"a\" 1}", "missing colon");
    expect_refused("// comment\n1", "comment");
}

/* 65 nested arrays: one more level than the parser takes. */
static void deep_nesting_is_refused_not_a_crash(void **state)
{
    (void)state;
    char text[2 * 65 + 1];
    memset(text, '[', 65);
    memset(text + 65, ']', 65);
    text[130] = '\0';
    expect_refused(text, "too deep");
    text[0] = ' '; /* 64 levels: within the limit */
    text[129] = ' ';
    JsonValue v = parse_ok(text);
    json_free(&v);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(results_shaped_object_is_read_field_by_field),
        cmocka_unit_test(escapes_decode_to_utf8),
        cmocka_unit_test(empty_containers_and_nesting),
        cmocka_unit_test(what_is_not_json_is_refused),
        cmocka_unit_test(deep_nesting_is_refused_not_a_crash),
    };
    return cmocka_run_group_tests_name("tools: JSON parser of the grade check", tests, NULL, NULL);
}
