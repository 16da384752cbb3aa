/* A growable text buffer: the C example builds each answer in one, so that
 * a case it gives up on halfway leaves nothing half-written on stdout. */
#ifndef BUFFER_H
#define BUFFER_H

#include <stddef.h>

typedef struct {
    char *text;
    size_t length, capacity;
    int failed; /* out of memory: the text is incomplete */
} buffer;

/* Appends printf-style text. */
void buffer_printf(buffer *b, const char *format, ...);
/* Appends a JSON string literal, quotes and escapes included. */
void buffer_json_string(buffer *b, const char *text);
void buffer_clear(buffer *b);
void buffer_free(buffer *b);

#endif
