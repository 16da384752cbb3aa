#!/usr/bin/env python3
"""Writes the bundled line cases: cases/lines/*.json (SPEC.md section 4).

Python 3 standard library only. Geometry is exact (fractions.Fraction) and is
written as in tools/gen_cases.py:

- integers as JSON integers,
- terminating decimals as JSON numbers (3.1015625),
- other rationals as strings "p/q".

The diamond-exit cases (diamond_*.json, SPEC.md section 4.2) are section 12.

Every case has a description saying what it tests and why it is hard.
`expect.samples_covered` is derived by the small exact checker
(casegen/lines/check.py), an implementation of the four line rules of
SPEC.md section 4 and of the line interpolation of section 5 written from
the spec alone (it shares no code with rastercheck). It runs with `--check`, which also proves that each
case is sensitive to what it claims to test (a flipped tie rule, the fill rule,
snapping, x-major at slope 1, major vs projected parameter, linear vs
perspective), that reversed lines light the same pixels, and that strips with
`last_pixel: exclude` cover no sample twice.

`--compare` additionally runs `./target/release/rastercheck run cases/lines -r
reference` (target/debug when there is no release build) and checks that the reference's coverage count of every case equals
the checker's. `--compare-dump FILE` compares whole frames (coverage, last
primitive, depth, attributes) with a JSON dump of the reference's frames: a
list of {"path", "width", "height", "coverage", "last", "depth",
"attributes"}, as written by a throwaway program that calls
rastercheck::reference::Reference on each case.

The case model is casegen/lines/build.py, the cases casegen/lines/cases.py and
casegen/lines/diamond.py, the checker casegen/lines/check.py and the
comparisons casegen/lines/compare.py; this file writes the cases.

Usage: python3 tools/gen_line_cases.py [--check] [--compare] [--compare-dump FILE]
"""

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from casegen import ROOT  # noqa: E402
from casegen.casefile import render  # noqa: E402
from casegen.lines import cases, diamond  # noqa: E402,F401 (registers the cases, in this order)
from casegen.lines.build import CASES  # noqa: E402
from casegen.lines.check import check, render_frame  # noqa: E402
from casegen.lines.compare import compare_dump, compare_run  # noqa: E402

OUT_DIR = os.path.join(ROOT, "cases", "lines")


def main():
    names = [c["name"] for c in CASES]
    assert len(names) == len(set(names)), "duplicate case names"
    os.makedirs(OUT_DIR, exist_ok=True)
    for c in CASES:
        expect = {}
        n = len(render_frame(c))
        if c["covered"]:
            expect["samples_covered"] = n
        c["description"] = c["description"].replace("{N}", str(n))
        with open(os.path.join(OUT_DIR, c["name"] + ".json"), "w") as f:
            f.write(render(c, expect))
    print("wrote %d cases to %s" % (len(CASES), OUT_DIR))
    args = sys.argv[1:]
    ok = True
    if "--check" in args:
        ok &= check()
    if "--compare" in args:
        ok &= compare_run()
    if "--compare-dump" in args:
        ok &= compare_dump(args[args.index("--compare-dump") + 1])
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
