"""The sample method's instants (SPEC.md section 15.3): per pixel, SplitMix64
seeded from the case's seed and the pixel index, drawn by the four time
patterns, as u in 2^-16 of the shutter; and the spatial offsets (section
14.2) they pair with, from casegen/samples.py.
"""

from fractions import Fraction as F

from casegen.samples import MASK64, SplitMix64, offsets

# Spatial offsets (section 14.2) come from casegen/samples.py (the port of the patterns that
# the antialiasing checker uses, with its SplitMix64); the instants (section 15.3) are written
# here.

TIME_BITS = 16
TIME_ONE = 1 << TIME_BITS
PIXEL_MIX = 0xD6E8FEB86659FD93


def spatial_offsets(aa):
    """The M offsets of effects.antialias in slot order, or the pixel centre."""
    if aa is None:
        return [(F(1, 2), F(1, 2))]
    return offsets(aa)


def pixel_us(mb, pixel, M):
    """The u (in 2^-16 of the shutter) of the M*N tests of pixel y*W + x;
    slot s*N + k is instant k of spatial sample s."""
    N = mb["samples"]
    T = M * N
    rng = SplitMix64(mb.get("seed", 0) ^ (((pixel + 1) * PIXEL_MIX) & MASK64))

    def draw():
        return rng.draw(TIME_BITS)

    pattern = mb.get("pattern", "stratified")
    if pattern == "random":
        return [draw() for _ in range(T)]
    if pattern == "stratified":
        return [((j % N) * TIME_ONE + draw()) // N for j in range(T)]
    v = [(i * TIME_ONE + draw()) // T for i in range(T)]
    if pattern == "jittered-xy-t":
        return v
    if pattern == "stratified-shuffled":
        perm = list(range(T))
        for i in range(T - 1, 0, -1):
            j = rng.next() % (i + 1)
            perm[i], perm[j] = perm[j], perm[i]
        return [v[perm[j]] for j in range(T)]
    raise ValueError(pattern)
