"""Snapping to the subpixel grid (SPEC.md section 2) with every tie mode: the
spec's ties to even, and the wrong ones (up, down, away from zero, toward
zero, odd) that prove a case sensitive to the snapping's tie rule.

Shared by the triangle and line checkers. The hard cases' checker keeps its
own, separately written snap.
"""

import math
from fractions import Fraction as F

HALF = F(1, 2)


def snap(v, bits, mode="even"):
    if bits is None:
        return v
    s = v * 2**bits
    fl = math.floor(s)
    r = s - fl
    if r > HALF:
        n = fl + 1
    elif r < HALF:
        n = fl
    elif mode == "even":
        n = fl if fl % 2 == 0 else fl + 1
    elif mode == "up":
        n = fl + 1
    elif mode == "down":
        n = fl
    elif mode == "away":
        n = fl + 1 if v > 0 else fl
    elif mode == "toward":
        n = fl if v > 0 else fl + 1
    elif mode == "odd":
        n = fl if fl % 2 == 1 else fl + 1
    else:
        raise ValueError(mode)
    return F(n, 2**bits)
