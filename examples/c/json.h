/* A minimal JSON reader for the C example rasterizer: one document into a
 * tree of nodes, enough for rastercheck's requests (SPEC.md §12.1). It
 * keeps every number both as a double and as its text, takes strings with
 * the common escapes (\uXXXX outside ASCII becomes '?': no request field
 * this program reads needs more), and reports the byte offset of the first
 * syntax error. It does not validate UTF-8, does not keep duplicate keys
 * apart (the first wins on lookup), and is not meant for untrusted input
 * beyond what rastercheck sends: nesting deeper than JSON_MAX_DEPTH is
 * refused so that a malformed line cannot exhaust the stack. */
#ifndef JSON_H
#define JSON_H

#include <stddef.h>

#define JSON_MAX_DEPTH 64

enum json_kind { JSON_NULL, JSON_BOOL, JSON_NUMBER, JSON_STRING, JSON_ARRAY, JSON_OBJECT };

typedef struct json json;
struct json {
    enum json_kind kind;
    int boolean;
    double number;
    char *text;     /* a string's value, or a number's spelling */
    char *key;      /* the key, when this node is an object member */
    json **items;   /* array elements or object members, in order */
    size_t count;
};

/* Parses `text` (NUL-terminated); NULL on a syntax error, with the byte
 * offset of the error in *error_at. Free the result with json_free. */
json *json_parse(const char *text, size_t *error_at);
void json_free(json *node);

/* An object's member, or NULL when `node` is not an object or lacks it. */
const json *json_get(const json *node, const char *key);
/* An array's element, or NULL when `node` is not an array or is too short. */
const json *json_at(const json *node, size_t index);
/* The number, or `fallback` when the node is missing or not a number. */
double json_number(const json *node, double fallback);
/* The string, or `fallback` when the node is missing or not a string. */
const char *json_string(const json *node, const char *fallback);
/* The array's length; 0 for anything else. */
size_t json_length(const json *node);

#endif
