/* The minimal JSON reader of json.h: recursive descent over one document. */
#include "json.h"

#include <stdlib.h>
#include <string.h>

typedef struct {
    const char *at;
    const char *start;
    int depth;
} reader;

static json *value(reader *r);

static void skip_space(reader *r) {
    while (*r->at == ' ' || *r->at == '\t' || *r->at == '\n' || *r->at == '\r') r->at++;
}

static json *node(enum json_kind kind) {
    json *n = calloc(1, sizeof *n);
    if (n) n->kind = kind;
    return n;
}

static int push(json *parent, json *child) {
    json **grown = realloc(parent->items, (parent->count + 1) * sizeof *grown);
    if (!grown) return 0;
    parent->items = grown;
    parent->items[parent->count++] = child;
    return 1;
}

static int hex(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

/* A string's contents after the opening quote, unescaped, into a new buffer. */
static char *string_body(reader *r) {
    size_t cap = 16, len = 0;
    char *out = malloc(cap);
    if (!out) return NULL;
    while (*r->at != '"') {
        char c = *r->at++;
        if (c == '\0' || (unsigned char)c < 0x20) goto bad;
        if (c == '\\') {
            char e = *r->at++;
            switch (e) {
            case '"': case '\\': case '/': c = e; break;
            case 'b': c = '\b'; break;
            case 'f': c = '\f'; break;
            case 'n': c = '\n'; break;
            case 'r': c = '\r'; break;
            case 't': c = '\t'; break;
            case 'u': {
                int code = 0, i;
                for (i = 0; i < 4; i++) {
                    int h = hex(*r->at++);
                    if (h < 0) goto bad;
                    code = code * 16 + h;
                }
                c = code < 0x80 ? (char)code : '?';
                break;
            }
            default: goto bad;
            }
        }
        if (len + 2 > cap) {
            char *grown = realloc(out, cap *= 2);
            if (!grown) goto bad;
            out = grown;
        }
        out[len++] = c;
    }
    r->at++;
    out[len] = '\0';
    return out;
bad:
    free(out);
    return NULL;
}

static json *number(reader *r) {
    const char *begin = r->at;
    char *end;
    json *n;
    if (*r->at == '-') r->at++;
    if (*r->at < '0' || *r->at > '9') return NULL;
    while ((*r->at >= '0' && *r->at <= '9') || *r->at == '.' || *r->at == 'e' || *r->at == 'E'
           || *r->at == '+' || *r->at == '-')
        r->at++;
    n = node(JSON_NUMBER);
    if (!n) return NULL;
    n->text = malloc((size_t)(r->at - begin) + 1);
    if (!n->text) {
        free(n);
        return NULL;
    }
    memcpy(n->text, begin, (size_t)(r->at - begin));
    n->text[r->at - begin] = '\0';
    n->number = strtod(n->text, &end);
    if (*end != '\0') {
        json_free(n);
        return NULL;
    }
    return n;
}

/* An array or object after its opening bracket; `close` is ']' or '}'. */
static json *container(reader *r, enum json_kind kind, char close) {
    json *n = node(kind);
    if (!n) return NULL;
    if (++r->depth > JSON_MAX_DEPTH) goto bad;
    skip_space(r);
    if (*r->at == close) {
        r->at++;
        r->depth--;
        return n;
    }
    for (;;) {
        char *key = NULL;
        json *item;
        skip_space(r);
        if (kind == JSON_OBJECT) {
            if (*r->at != '"') goto bad;
            r->at++;
            if (!(key = string_body(r))) goto bad;
            skip_space(r);
            if (*r->at != ':') {
                free(key);
                goto bad;
            }
            r->at++;
        }
        item = value(r);
        if (!item) {
            free(key);
            goto bad;
        }
        item->key = key;
        if (!push(n, item)) {
            json_free(item);
            goto bad;
        }
        skip_space(r);
        if (*r->at == ',') {
            r->at++;
            continue;
        }
        if (*r->at != close) goto bad;
        r->at++;
        r->depth--;
        return n;
    }
bad:
    json_free(n);
    return NULL;
}

static json *value(reader *r) {
    skip_space(r);
    switch (*r->at) {
    case '{': r->at++; return container(r, JSON_OBJECT, '}');
    case '[': r->at++; return container(r, JSON_ARRAY, ']');
    case '"': {
        json *n = node(JSON_STRING);
        r->at++;
        if (n && !(n->text = string_body(r))) {
            free(n);
            return NULL;
        }
        return n;
    }
    case 't':
    case 'f':
    case 'n': {
        static const char *words[] = {"true", "false", "null"};
        int i;
        for (i = 0; i < 3; i++) {
            size_t len = strlen(words[i]);
            if (strncmp(r->at, words[i], len) == 0) {
                json *n = node(i == 2 ? JSON_NULL : JSON_BOOL);
                if (n) n->boolean = i == 0;
                r->at += len;
                return n;
            }
        }
        return NULL;
    }
    default: return number(r);
    }
}

json *json_parse(const char *text, size_t *error_at) {
    reader r = {text, text, 0};
    json *n = value(&r);
    if (n) {
        skip_space(&r);
        if (*r.at != '\0') {
            json_free(n);
            n = NULL;
        }
    }
    if (!n && error_at) *error_at = (size_t)(r.at - r.start);
    return n;
}

void json_free(json *n) {
    size_t i;
    if (!n) return;
    for (i = 0; i < n->count; i++) json_free(n->items[i]);
    free(n->items);
    free(n->text);
    free(n->key);
    free(n);
}

const json *json_get(const json *n, const char *key) {
    size_t i;
    if (!n || n->kind != JSON_OBJECT) return NULL;
    for (i = 0; i < n->count; i++)
        if (strcmp(n->items[i]->key, key) == 0) return n->items[i];
    return NULL;
}

const json *json_at(const json *n, size_t index) {
    if (!n || n->kind != JSON_ARRAY || index >= n->count) return NULL;
    return n->items[index];
}

double json_number(const json *n, double fallback) {
    return n && n->kind == JSON_NUMBER ? n->number : fallback;
}

const char *json_string(const json *n, const char *fallback) {
    return n && n->kind == JSON_STRING ? n->text : fallback;
}

size_t json_length(const json *n) {
    return n && n->kind == JSON_ARRAY ? n->count : 0;
}
