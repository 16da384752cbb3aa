/* Exact rationals in 128-bit integers (rational.h). */
#include "rational.h"

#include <stdlib.h>
#include <string.h>

int rat_overflow = 0;

static i128 gcd(i128 a, i128 b) {
    if (a < 0) a = -a;
    if (b < 0) b = -b;
    while (b) {
        i128 t = a % b;
        a = b;
        b = t;
    }
    return a;
}

static rat make(i128 n, i128 d) {
    rat r;
    i128 g;
    if (d < 0) n = -n, d = -d;
    g = gcd(n, d);
    if (g > 1) n /= g, d /= g;
    if (n == 0) d = 1;
    r.n = n;
    r.d = d;
    return r;
}

static i128 mul(i128 a, i128 b) {
    i128 r;
    if (__builtin_mul_overflow(a, b, &r)) {
        rat_overflow = 1;
        return 0;
    }
    return r;
}

static i128 add(i128 a, i128 b) {
    i128 r;
    if (__builtin_add_overflow(a, b, &r)) {
        rat_overflow = 1;
        return 0;
    }
    return r;
}

rat rat_int(long long v) { return make(v, 1); }

rat rat_frac(i128 n, i128 d) { return make(n, d); }

const char *rat_from_exact(const char *s, rat *out) {
    int negative = *s == '-';
    i128 n = 0, d = 1;
    if (negative) s++;
    if (*s < '0' || *s > '9') return "a number spelling this program does not read";
    for (; *s >= '0' && *s <= '9'; s++) n = add(mul(n, 10), *s - '0');
    if (*s == '.') {
        for (s++; *s >= '0' && *s <= '9'; s++) {
            n = add(mul(n, 10), *s - '0');
            d = mul(d, 10);
        }
    } else if (*s == '/') {
        d = 0;
        for (s++; *s >= '0' && *s <= '9'; s++) d = add(mul(d, 10), *s - '0');
        if (d == 0) return "a fraction with denominator 0";
    }
    if (*s != '\0') return "a number spelling this program does not read";
    if (rat_overflow) return "a number too long for 128-bit arithmetic";
    *out = make(negative ? -n : n, d);
    return NULL;
}

rat rat_add(rat a, rat b) {
    i128 g = gcd(a.d, b.d);
    return make(add(mul(a.n, b.d / g), mul(b.n, a.d / g)), mul(a.d / g, b.d));
}

rat rat_sub(rat a, rat b) {
    b.n = -b.n;
    return rat_add(a, b);
}

rat rat_mul(rat a, rat b) {
    i128 g1 = gcd(a.n, b.d), g2 = gcd(b.n, a.d);
    if (g1 == 0) g1 = 1;
    if (g2 == 0) g2 = 1;
    return make(mul(a.n / g1, b.n / g2), mul(a.d / g2, b.d / g1));
}

rat rat_div(rat a, rat b) {
    rat inverse;
    inverse.n = b.d;
    inverse.d = b.n;
    if (inverse.d < 0) inverse.n = -inverse.n, inverse.d = -inverse.d;
    return rat_mul(a, inverse);
}

int rat_sign(rat a) { return a.n > 0 ? 1 : a.n < 0 ? -1 : 0; }

int rat_cmp(rat a, rat b) { return rat_sign(rat_sub(a, b)); }

double rat_double(rat a) { return (double)a.n / (double)a.d; }

int rat_snap(rat a, int bits, fx16 *out) {
    int scale = bits < 0 ? GRID_BITS : bits;
    i128 scaled = mul(a.n, (i128)1 << scale), q, r;
    if (rat_overflow) return -1;
    /* Floor division, then the remainder against one half. */
    q = scaled / a.d;
    r = scaled % a.d;
    if (r < 0) q -= 1, r += a.d;
    if (bits < 0 && r != 0) return -1;
    if (r > a.d - r || (r == a.d - r && (q & 1))) q += 1;
    if (q > ((i128)1 << 40) || q < -((i128)1 << 40)) return -1;
    out->v = (int64_t)q * ((int64_t)1 << (GRID_BITS - scale));
    return 0;
}
