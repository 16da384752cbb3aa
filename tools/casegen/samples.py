"""The sample patterns of SPEC.md section 14.2 and their SplitMix64, written
from the text: each pattern's N offsets in slot order, as exact Fractions.

Shared by the antialiasing, hard and motion generators (the motion
generator's instants of section 15.3 draw from the same SplitMix64). Nothing
here decides coverage.
"""

import math
from fractions import Fraction as F

MASK64 = (1 << 64) - 1


class SplitMix64:
    def __init__(self, seed):
        self.state = seed & MASK64

    def next(self):
        self.state = (self.state + 0x9E3779B97F4A7C15) & MASK64
        z = self.state
        z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & MASK64
        z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & MASK64
        return z ^ (z >> 31)

    def draw(self, bits):
        return self.next() >> (64 - bits)


# Vulkan standardSampleLocations, in 1/16 pixel (y down), in Vulkan's order.
STANDARD = {
    1: [(F(1, 2), F(1, 2))],
    2: [(F(3, 4), F(3, 4)), (F(1, 4), F(1, 4))],
    4: [(F(3, 8), F(1, 8)), (F(7, 8), F(3, 8)), (F(1, 8), F(5, 8)), (F(5, 8), F(7, 8))],
    8: [(F(9, 16), F(5, 16)), (F(7, 16), F(11, 16)), (F(13, 16), F(9, 16)), (F(5, 16), F(3, 16)),
        (F(3, 16), F(13, 16)), (F(1, 16), F(7, 16)), (F(11, 16), F(15, 16)), (F(15, 16), F(1, 16))],
    16: [(F(9, 16), F(9, 16)), (F(7, 16), F(5, 16)), (F(5, 16), F(10, 16)), (F(12, 16), F(7, 16)),
         (F(3, 16), F(6, 16)), (F(10, 16), F(13, 16)), (F(13, 16), F(11, 16)), (F(11, 16), F(3, 16)),
         (F(6, 16), F(14, 16)), (F(8, 16), F(1, 16)), (F(4, 16), F(2, 16)), (F(2, 16), F(12, 16)),
         (F(0, 16), F(8, 16)), (F(15, 16), F(4, 16)), (F(14, 16), F(15, 16)), (F(1, 16), F(0, 16))],
}


def isqrt_exact(n):
    k = math.isqrt(n)
    assert k * k == n, n
    return k


def offsets(aa):
    """The N offsets of a pattern as Fractions in [0, 1)^2, in slot order."""
    n, pattern, seed, bits = aa["samples"], aa.get("pattern", "standard"), aa.get("seed", 0), \
        aa.get("position_bits", 8)
    L = 1 << bits
    rng = SplitMix64(seed)
    if pattern == "standard":
        pts = STANDARD[n]
        for p in pts:
            assert (p[0] * L).denominator == 1 and (p[1] * L).denominator == 1
        return list(pts)
    if pattern == "grid":
        k = isqrt_exact(n)
        # (2i + 1)/2k on the lattice, ties to even (Fraction rounds half to even).
        c = [F(round(F((2 * i + 1) * L, 2 * k)), L) for i in range(k)]
        return [(c[s % k], c[s // k]) for s in range(n)]
    if pattern == "stratified":
        k = isqrt_exact(n)
        out = []
        for s in range(n):
            i, j = s % k, s // k
            x = (i * L + rng.draw(bits)) // k
            y = (j * L + rng.draw(bits)) // k
            out.append((F(x, L), F(y, L)))
        return out
    if pattern == "random":
        out = []
        for _ in range(n):
            x = rng.draw(bits)
            y = rng.draw(bits)
            out.append((F(x, L), F(y, L)))
        return out
    if pattern == "n-rooks":
        perm = list(range(n))
        for i in range(n - 1, 0, -1):
            j = rng.next() % (i + 1)
            perm[i], perm[j] = perm[j], perm[i]
        out = []
        for i in range(n):
            x = (i * L + rng.draw(bits)) // n
            y = (perm[i] * L + rng.draw(bits)) // n
            out.append((F(x, L), F(y, L)))
        return out
    raise ValueError(pattern)

