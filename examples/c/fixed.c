/* Exact spellings to 48.16 fixed point (fixed.h). Decimals are multiplied
 * by 2^bits digit by digit, so any number of decimal places is exact;
 * fractions are divided in 128-bit integers. */
#include "fixed.h"

#include <stdlib.h>
#include <string.h>

#define MAX_DIGITS 64 /* rastercheck writes decimals of at most 40 places */

/* Round half to even of (whole + rest), where `rest` is in [0, 1) and is
 * compared to 1/2 as `half` = -1 (below), 0 (exactly), 1 (above). */
static int64_t round_half_even(int64_t whole, int half) {
    if (half > 0 || (half == 0 && (whole & 1))) return whole + 1;
    return whole;
}

/* The magnitude of a decimal "I" or "I.F", times 2^bits, rounded; *exact
 * says whether nothing was rounded off. */
static const char *decimal(const char *s, int bits, int64_t *out, int *exact) {
    int64_t whole = 0;
    int frac[MAX_DIGITS];
    int n = 0, i, k, half;
    for (; *s >= '0' && *s <= '9'; s++) {
        whole = whole * 10 + (*s - '0');
        if (whole > ((int64_t)1 << 40)) return "a coordinate too large";
    }
    if (*s == '.') {
        for (s++; *s >= '0' && *s <= '9'; s++) {
            if (n == MAX_DIGITS) return "a decimal with too many places";
            frac[n++] = *s - '0';
        }
    }
    if (*s != '\0') return "a number spelling this program does not read";
    /* Double the fraction `bits` times; each carry out of its first digit
     * moves one bit into the whole part. */
    for (k = 0; k < bits; k++) {
        int carry = 0;
        for (i = n - 1; i >= 0; i--) {
            int d = frac[i] * 2 + carry;
            frac[i] = d % 10;
            carry = d / 10;
        }
        whole = whole * 2 + carry;
    }
    /* What is left of the fraction, against 1/2: its first digit decides
     * unless it is a 5, and then any later non-zero digit tips it over. */
    half = -1;
    *exact = 1;
    for (i = 0; i < n; i++) {
        if (frac[i]) *exact = 0;
    }
    if (n > 0 && frac[0] > 5) half = 1;
    if (n > 0 && frac[0] == 5) {
        half = 0;
        for (i = 1; i < n; i++)
            if (frac[i]) half = 1;
    }
    *out = round_half_even(whole, half);
    return NULL;
}

/* The magnitude of a fraction "P/Q", times 2^bits, rounded. */
static const char *fraction(const char *s, int bits, int64_t *out, int *exact) {
    char *end;
    unsigned long long p, q;
    i128 scaled, quotient, remainder;
    if (strlen(s) > 40) return "a fraction too long for 64-bit arithmetic";
    p = strtoull(s, &end, 10);
    if (*end != '/') return "a number spelling this program does not read";
    q = strtoull(end + 1, &end, 10);
    if (*end != '\0' || q == 0 || p > (1ull << 62) || q > (1ull << 62))
        return "a fraction too long for 64-bit arithmetic";
    scaled = (i128)p << bits;
    quotient = scaled / q;
    remainder = scaled % q;
    if (quotient > ((i128)1 << 56)) return "a coordinate too large";
    *exact = remainder == 0;
    /* 2·remainder against q: below, exactly or above one half. */
    *out = round_half_even((int64_t)quotient,
                           2 * remainder < q ? -1 : 2 * remainder == q ? 0 : 1);
    return NULL;
}

const char *fx16_from_exact(const char *s, int bits, fx16 *out) {
    int negative = *s == '-', exact;
    int scale_bits = bits < 0 ? GRID_BITS : bits;
    int64_t magnitude;
    const char *why;
    if (negative) s++;
    why = strchr(s, '/') ? fraction(s, scale_bits, &magnitude, &exact)
                         : decimal(s, scale_bits, &magnitude, &exact);
    if (why) return why;
    if (bits < 0 && !exact)
        return "an unsnapped coordinate that is not a multiple of 2^-16";
    /* Round-half-even is symmetric, so the sign goes on after rounding. */
    out->v = (negative ? -magnitude : magnitude) * ((int64_t)1 << (GRID_BITS - scale_bits));
    return NULL;
}
