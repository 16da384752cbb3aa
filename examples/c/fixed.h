/* Exact numbers to fixed point, for the C example rasterizer. rastercheck
 * sends every number twice (SPEC.md §12.1): as a double and, under
 * `exact`, as its exact spelling: an integer ("3"), a terminating decimal
 * ("12.5") or a fraction in lowest terms ("1/3"). Coordinates are read from
 * the spelling, so that snapping (SPEC.md §2: the nearest multiple of
 * 2^-bits, ties to even) is exact whatever the double would have been. */
#ifndef FIXED_H
#define FIXED_H

#include <stdint.h>

/* Every position this program handles lies on one grid of 2^-16 pixel:
 * snapped vertices (subpixel_bits <= 16, SPEC.md §8), the pixel centre and
 * the sample offsets (position_bits <= 16, SPEC.md §14.2). */
#define GRID_BITS 16
#define GRID_ONE ((int64_t)1 << GRID_BITS)

/* GCC and Clang's 128-bit integer (`__extension__` keeps -pedantic quiet):
 * an edge function needs 2 x 34 bits at 2^-16 pixel (coordinates up to
 * 32768 px, samples up to 16384 px away), so int64 products would
 * overflow; the fractions read below need 62 + 16 bits. */
__extension__ typedef __int128 i128;

/* A 48.16 fixed-point coordinate: units of 2^-16 pixel. With |x| <= 32768
 * pixels (SPEC.md §8) the value stays below 2^31 in magnitude. */
typedef struct {
    int64_t v;
} fx16;

/* Reads an exact spelling and rounds it to a multiple of 2^-bits (ties to
 * even), bits in [0, 16]; with bits < 0 it keeps the value as it is, which
 * must then be a multiple of 2^-16. Returns 0 on success, or a message
 * saying why the value cannot be read (unsnapped and off the grid, a
 * fraction too long for 64-bit arithmetic, a spelling it does not know). */
const char *fx16_from_exact(const char *spelling, int bits, fx16 *out);

#endif
