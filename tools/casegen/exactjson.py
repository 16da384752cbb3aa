"""Exact JSON numbers for the case generators.

A case file's numbers are exact (SPEC.md section 1.1): integers and
terminating decimals are written as JSON numbers, other rationals as
"p/q" strings. Shared by every generator; it writes values, not whole
case files (casefile.py does that).
"""

import json
from fractions import Fraction as F


def exact(x):
    """A Fraction from an int, Fraction, string, or a float that is a short dyadic
    (0.5, 8.5 + 1/512): floats like 0.1 are refused, write them as strings."""
    if isinstance(x, float):
        q = F(x)
        assert q.denominator <= 2**20, "non-dyadic float %r: write it as a string" % x
        return q
    return F(x)


def num(q):
    """The JSON token for an exact rational."""
    if isinstance(q, bool):
        raise TypeError("boolean is not a number")
    q = F(q)
    if q.denominator == 1:
        return str(q.numerator)
    d = q.denominator
    twos = fives = 0
    while d % 2 == 0:
        d //= 2
        twos += 1
    while d % 5 == 0:
        d //= 5
        fives += 1
    if d != 1:
        return json.dumps("%d/%d" % (q.numerator, q.denominator))
    k = max(twos, fives)
    n = q * 10**k
    assert n.denominator == 1
    n = n.numerator
    sign = "-" if n < 0 else ""
    digits = str(abs(n)).rjust(k + 1, "0")
    return "%s%s.%s" % (sign, digits[:-k], digits[-k:])


def js(v):
    if v is None:
        return "null"
    if v is True:
        return "true"
    if v is False:
        return "false"
    if isinstance(v, (int, F, float)):
        return num(exact(v))
    if isinstance(v, str):
        return json.dumps(v, ensure_ascii=False)
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(js(x) for x in v) + "]"
    if isinstance(v, dict):
        return "{" + ", ".join("%s: %s" % (json.dumps(k), js(x)) for k, x in v.items()) + "}"
    raise TypeError(type(v))
