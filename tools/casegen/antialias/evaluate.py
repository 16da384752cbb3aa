"""Evaluating an antialiasing or polygon case: the bounds it is written with
(piglit's RMS bound, Monte Carlo, min(P, 2E/sqrt N); see tools/gen_aa_cases.py),
the case registry, the writer, and evaluate(), which computes every expectation and
asserts that the exact N-sample method meets every bound it writes.
"""

import math
import os
import sys
from fractions import Fraction as F

from casegen import ROOT, casefile
from casegen.antialias.check import (clip_convex_to_box, coverage, is_convex_simple, pixel_areas,
                                     shoelace)
from casegen.samples import offsets

AA_DIR = os.path.join(ROOT, "cases", "antialias")
POLY_DIR = os.path.join(ROOT, "cases", "polygons")


# ---------------------------------------------------------------------------
# Bounds.

def seg_touches_box(e, x0, y0, x1, y1):
    """Whether a segment meets the closed box [x0, x1] x [y0, y1] (Liang-Barsky)."""
    (ax, ay), (bx, by) = e
    t0, t1 = F(0), F(1)
    for p, q in ((-(bx - ax), ax - x0), (bx - ax, x1 - ax), (-(by - ay), ay - y0), (by - ay, y1 - ay)):
        if p == 0:
            if q < 0:
                return False
            continue
        r = F(q) / p
        if p < 0:
            t0 = max(t0, r)
        else:
            t1 = min(t1, r)
        if t0 > t1:
            return False
    return True


def edges_per_pixel(c):
    """(E, P): the most primitive edges, and the most primitives, touching one
    pixel's closed square."""
    W, H = c["width"], c["height"]
    edge_count = {}
    prim_count = {}
    for p in c["prims"]:
        touched = set()
        for e in p.edges(c["bits"]):
            if e[0] == e[1]:
                continue
            xs, ys = (e[0][0], e[1][0]), (e[0][1], e[1][1])
            for y in range(max(0, math.floor(min(ys)) - 1), min(H - 1, math.ceil(max(ys))) + 1):
                for x in range(max(0, math.floor(min(xs)) - 1), min(W - 1, math.ceil(max(xs))) + 1):
                    if seg_touches_box(e, x, y, x + 1, y + 1):
                        edge_count[(x, y)] = edge_count.get((x, y), 0) + 1
                        touched.add((x, y))
        for q in touched:
            prim_count[q] = prim_count.get(q, 0) + 1
    return max(edge_count.values(), default=1), max(prim_count.values(), default=1)


def round_up(q, digits=4):
    """The smallest decimal with `digits` fractional digits that is >= q."""
    s = 10 ** digits
    return F(math.ceil(q * s), s)


def piglit_rms(n):
    return 0.333 * 0.62 ** math.log2(n)


# ---------------------------------------------------------------------------
# Cases.

CASES = []


def case(folder, name, description, width, height, prims, aa=None, bits=8, fill_rule="top-left",
         rms="piglit", max_error="edges", extra_expect=None, checks=None):
    """Registers a case. aa: the effects.antialias object or None.
    rms: 'piglit' or 'monte-carlo' (see the module docstring).
    max_error: 'edges' (min(P, 2E/sqrt N)) or 'primitives' (P: the pattern
    is known to be bad at this case, and the description says why).
    checks: functions of the computed result that must hold (the author's
    intent, asserted)."""
    assert width <= 64 and height <= 64
    if aa and aa["samples"] >= 64:
        assert width <= 32 and height <= 32, name
    CASES.append(dict(folder=folder, name=name, description=description, width=width,
                      height=height, prims=prims, aa=aa, bits=bits, fill_rule=fill_rule, rms=rms,
                      max_error=max_error, extra_expect=extra_expect or {}, checks=checks or []))


def evaluate(c):
    """Computes every expectation of a case; returns (expect dict, stats)."""
    W, H = c["width"], c["height"]
    aa = c["aa"]
    c["offsets"] = offsets(aa) if aa else [(F(1, 2), F(1, 2))]
    N = len(c["offsets"])
    counts = coverage(c)
    covered = sum(1 for k in counts if k > 0)
    expect = {"samples_covered": covered}
    stats = {"covered": covered, "N": N, "counts": counts}
    if not aa:
        return expect, stats
    # Exact areas, two ways.
    area = {}
    total_a = F(0)
    total_b = F(0)
    for p in c["prims"]:
        edges = p.edges(c["bits"])
        per = pixel_areas(edges, p.fill, W, H)
        for k, v in per.items():
            assert 0 < v <= 1, (c["name"], k, v)
            area[k] = area.get(k, F(0)) + v
        t = sum(per.values(), F(0))
        t2 = pixel_areas(edges, p.fill, W, H, per_pixel=False)
        assert t == t2, (c["name"], t, t2)
        snapped = p.snapped(c["bits"])
        if len(snapped) == 1 and is_convex_simple(snapped[0]):
            clipped = clip_convex_to_box(snapped[0], W, H)
            t3 = abs(shoelace(clipped)) if len(clipped) >= 3 else F(0)
            assert t == t3, (c["name"], t, t3)
        total_a += t
        total_b += t2
    assert total_a == total_b
    expect["area"] = str(total_a)
    # Errors of the exact N-sample method.
    errs = []
    max_err = F(0)
    for y in range(H):
        for x in range(W):
            i = (y * W + x) * N
            frac = F(sum(counts[i:i + N]), N)
            a = area.get((x, y), F(0))
            # Full and empty pixels are exact (SPEC.md 14.3): a pixel of area 0
            # covers no sample, and one of area 1 with one primitive covers all.
            err = frac - a
            max_err = max(max_err, abs(err))
            if 0 < a < 1 or frac not in (0, 1):
                errs.append(err)
    rms_exact = math.sqrt(float(sum(e * e for e in errs) / len(errs))) if errs else 0.0
    E, Pn = edges_per_pixel(c)
    # A pixel's error is at most max(resolved, area): 1 unless primitives overlap.
    cap = max(F(1), F(math.ceil(max(area.values(), default=F(0)))), F(max(counts, default=0)))
    cap = min(cap, F(Pn))
    if c["max_error"] == "edges":
        bound = min(cap, round_up(F(2 * E) / F(math.isqrt(N)) if math.isqrt(N) ** 2 == N
                                  else F(2 * E / math.sqrt(N))))
    elif c["max_error"] == "probe":
        bound = round_up(F(1, N))
    else:
        raise ValueError(c["max_error"])
    if c["rms"] == "piglit":
        rms_bound = round_up(F(piglit_rms(N)))
    elif c["rms"] == "piglit-half":
        rms_bound = round_up(F(piglit_rms(N // 2)))
    elif c["rms"] == "monte-carlo":
        rms_bound = round_up(F(1 / math.sqrt(N)))
    elif c["rms"] == "max":
        rms_bound = bound
    elif c["rms"] == "probe":
        rms_bound = round_up(F(1, N))
    else:
        raise ValueError(c["rms"])
    ok_max = max_err <= bound
    ok_rms = rms_exact <= float(rms_bound) * (1 - 1e-9)
    if "--report" in sys.argv:
        if not (ok_max and ok_rms):
            print("FAILS BOUND", c["name"], float(max_err), float(bound), rms_exact, float(rms_bound))
    else:
        assert ok_max, "%s: exact max error %s > bound %s" % (c["name"], float(max_err), float(bound))
        assert ok_rms, "%s: exact RMS %s > bound %s" % (c["name"], rms_exact, float(rms_bound))
    expect["max_coverage_error"] = bound
    expect["max_coverage_rms"] = rms_bound
    stats.update(area=area, max_err=max_err, rms=rms_exact, E=E, P=Pn, edge_pixels=len(errs))
    return expect, stats


def render(c, expect):
    """The case file, with its effects.antialias when it has one."""
    return casefile.render(c, expect, {"antialias": c["aa"]} if c["aa"] else None)


def AA(samples, pattern="standard", **kw):
    d = {"samples": samples, "pattern": pattern}
    d.update(kw)
    return d



PROBE_NOTE = ("Bounds: a probe covers at most one sample of a pixel and at most 1/256 px^2 of it, so "
              "every pixel's error is at most 1/N: that is both max_coverage_error and "
              "max_coverage_rms.")
BOUNDS_NOTE = ("Bounds: max_coverage_rms is piglit's 0.333*0.62^log2(N); max_coverage_error is "
               "min(P, 2E/sqrt(N)) with E the most edges touching one pixel and P the most primitives "
               "(tools/gen_aa_cases.py explains both; the exact N-sample method meets them).")
MC_NOTE = ("Bounds: this pattern has too few independent random samples for piglit's MSAA bound, so "
           "max_coverage_rms is the Monte Carlo bound 1/sqrt(N), twice the largest expected RMS "
           "0.5/sqrt(N) of N independent uniform samples; max_coverage_error is min(P, 2E/sqrt(N)) "
           "with E the most edges touching one pixel and P the most primitives.")
