#!/usr/bin/env python3
"""Writes the antialiasing and polygon cases: cases/antialias/*.json and
cases/polygons/*.json (SPEC.md section 14).

Python 3 standard library only. Every expectation is computed here, by an
exact checker written from SPEC.md alone (fractions.Fraction, no call into
rastercheck):

- the sample offsets of the five patterns, SplitMix64 included (section 14.2);
- each sample's coverage: the winding number of the sample nudged as the fill
  rule says (section 14.1; a triangle or a parallelogram line is a one-contour
  nonzero polygon, which section 14.1 states is the same as section 3's rule);
- each pixel's exact area: the filled region of every primitive cut into
  slabs at every vertex, every crossing of two edges, every pixel row and
  every crossing of an edge with a pixel column, so that in each slab the
  filled part of each pixel is a trapezoid (its area is exact by the
  trapezoid rule); the canvas total is checked against a second computation
  (slabs clipped to the canvas only, and for convex primitives
  Sutherland-Hodgman clipping and the shoelace formula).

Written expectations:

- `samples_covered`: sample slots covered at least once;
- `area`: the exact total area of the primitives inside the canvas, a
  fraction string;
- `max_coverage_rms` (antialiased cases): piglit's MSAA bound
  0.333 * 0.62^log2(N) over edge pixels; cases whose pattern is known to miss
  it (few independent random samples) use the Monte Carlo bound 1/sqrt(N),
  twice the largest expected RMS sqrt(a(1-a)/N) <= 0.5/sqrt(N) of N
  independent uniform samples, and say so;
- `max_coverage_error`: min(P, 2E/sqrt(N)), where E is the largest number of
  primitive edges that touch one pixel and P the largest number of
  primitives that touch one pixel (a primitive's coverage error is at most
  1). The reasoning: for a k x k grid or stratified pattern only the cells
  a straight edge touches can be wrong, at most 3k - 2 of them, so one edge
  costs at most (3k - 2)/N < 3/sqrt(N); 2/sqrt(N) per edge is the
  tighter quality requirement a good N-sample pattern meets (its worst
  single-edge error is about 1/sqrt(N): a row or column of sqrt(N) samples
  flipping at once). Cases whose pattern is bad at this say so and use a
  looser bound.

The generator asserts that the exact N-sample method (the reference's own
mask, box-resolved) meets every bound it writes: a bound the exact method
fails is a bug here, not in rastercheck.

Before writing, it clears the *.json files of cases/antialias and
cases/polygons, except the hand-written ones named spec_*.json (cases that
pin SPEC statements; no generator writes them).

The checker's primitives are in casegen/antialias/primitives.py, its exact
coverage and areas in casegen/antialias/check.py, the bounds and evaluate()
in casegen/antialias/evaluate.py, the cases in casegen/antialias/cases.py;
this file writes them.

Usage: python3 tools/gen_aa_cases.py [-v] [--report]   (run from anywhere)
  -v         one line per case: samples covered, area, the exact method's
             largest error and RMS against the written bounds
  --report   print the cases whose exact method breaks a bound instead of
             stopping at the first (for working on the bounds)
"""

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from casegen.antialias import cases  # noqa: E402,F401 (registers the cases)
from casegen.antialias.evaluate import AA_DIR, CASES, POLY_DIR, evaluate, render  # noqa: E402


def main():
    summary = {}
    for d in (AA_DIR, POLY_DIR):
        os.makedirs(d, exist_ok=True)
        for f in os.listdir(d):
            if f.endswith(".json") and not f.startswith("spec_"):
                os.remove(os.path.join(d, f))
    names = set()
    for c in CASES:
        assert c["name"] not in names, c["name"]
        names.add(c["name"])
        expect, stats = evaluate(c)
        stats["W"] = c["width"]
        for check in c["checks"]:
            assert check(stats), "check failed: %s" % c["name"]
        expect.update(c["extra_expect"])
        path = os.path.join(c["folder"], c["name"] + ".json")
        with open(path, "w") as f:
            f.write(render(c, expect))
        folder = os.path.basename(c["folder"])
        summary[folder] = summary.get(folder, 0) + 1
        if "-v" in sys.argv:
            print("%-45s covered %6d area %-14s maxerr %.4f/%.4f rms %.4f/%.4f" % (
                c["name"], stats["covered"], expect.get("area", "-"),
                float(stats.get("max_err", 0)), float(expect.get("max_coverage_error", 0)),
                stats.get("rms", 0), float(expect.get("max_coverage_rms", 0))))
    print("wrote", ", ".join("%d cases in cases/%s" % (n, k) for k, n in sorted(summary.items())))


if __name__ == "__main__":
    main()
