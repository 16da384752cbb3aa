/* Exact rationals in 128-bit integers, for the C example's clip space
 * (SPEC.md §16): a clip coordinate's exact spelling read as p/q, the
 * clipper's new vertices P + t·(Q − P), the divide by w and the viewport,
 * each exact; a result that would not fit sets `overflow` rather than
 * wrap, and the caller answers `unsupported`. Nothing here rounds but
 * rat_snap, which rounds once, as SPEC.md §2 snaps. */
#ifndef RATIONAL_H
#define RATIONAL_H

#include "fixed.h" /* i128, fx16 */

/* n/d in lowest terms, d > 0. */
typedef struct {
    i128 n, d;
} rat;

/* Set when an operation's result did not fit; never cleared here. */
extern int rat_overflow;

rat rat_int(long long v);
/* n/d, d != 0, put in lowest terms. */
rat rat_frac(i128 n, i128 d);
/* Reads "3", "-12.5" or "1/3"; returns NULL or why it cannot. */
const char *rat_from_exact(const char *spelling, rat *out);
rat rat_add(rat a, rat b);
rat rat_sub(rat a, rat b);
rat rat_mul(rat a, rat b);
rat rat_div(rat a, rat b); /* b != 0 */
int rat_sign(rat a);
int rat_cmp(rat a, rat b);
double rat_double(rat a);
/* a rounded to a multiple of 2^-bits (ties to even), as a 48.16 position;
 * bits < 0 keeps a, which must then be a multiple of 2^-16. Returns 0, or
 * -1 when it is not (or does not fit). */
int rat_snap(rat a, int bits, fx16 *out);

#endif
