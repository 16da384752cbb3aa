/* The growable text buffer of buffer.h. */
#include "buffer.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>

void buffer_printf(buffer *b, const char *format, ...) {
    va_list args;
    int needed;
    if (b->failed) return;
    va_start(args, format);
    needed = vsnprintf(b->text ? b->text + b->length : NULL,
                       b->text ? b->capacity - b->length : 0, format, args);
    va_end(args);
    if (needed < 0) {
        b->failed = 1;
        return;
    }
    if (!b->text || b->length + (size_t)needed + 1 > b->capacity) {
        size_t capacity = b->capacity ? b->capacity : 4096;
        char *grown;
        while (capacity < b->length + (size_t)needed + 1) capacity *= 2;
        grown = realloc(b->text, capacity);
        if (!grown) {
            b->failed = 1;
            return;
        }
        b->text = grown;
        b->capacity = capacity;
        va_start(args, format);
        vsnprintf(b->text + b->length, b->capacity - b->length, format, args);
        va_end(args);
    }
    b->length += (size_t)needed;
}

void buffer_json_string(buffer *b, const char *text) {
    buffer_printf(b, "\"");
    for (; *text; text++) {
        unsigned char c = (unsigned char)*text;
        if (c == '"' || c == '\\') buffer_printf(b, "\\%c", c);
        else if (c < 0x20) buffer_printf(b, "\\u%04x", c);
        else buffer_printf(b, "%c", c);
    }
    buffer_printf(b, "\"");
}

void buffer_clear(buffer *b) {
    b->length = 0;
    b->failed = 0;
    if (b->text) b->text[0] = '\0';
}

void buffer_free(buffer *b) {
    free(b->text);
    b->text = NULL;
    b->length = b->capacity = 0;
}
