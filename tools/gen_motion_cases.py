#!/usr/bin/env python3
"""Writes the motion-blur cases: cases/motion/*.json (SPEC.md section 15).

Python 3 standard library only. Every expectation is computed here, by an
exact checker written from SPEC.md alone (no call into rastercheck, no code
shared with tools/gen_aa_cases.py):

- Exact time coverage (section 15.2), per spatial sample q and primitive P.
  With vertices v(tau) = snap(from) + tau*(snap(to) - snap(from)), every
  quantity the static rules look at is a polynomial of degree <= 2 in tau:
  the twice-signed area, each edge function at q, each edge's dx and dy (the
  fill rule's ownership of a sample riding on an edge), and for a
  parallelogram line dx - dy and dx + dy (its major axis) and the edge
  functions of both of its possible parallelograms. Their roots in
  (open, close) are the only instants at which "P covers q" can change. A
  rational root is kept as a Fraction; an irrational one as an exact
  quadratic surd u + v*sqrt(s), compared and ordered exactly (by intervals
  from integer square roots, refined until they separate, so the root
  values carry hundreds of correct digits; equal roots are recognised by exact
  surd arithmetic, so two edges that vanish at the same irrational instant
  make one event). Between consecutive events, coverage is decided by the
  exact predicate (section 3 with its epsilon nudge and cull; section 4.4
  for lines) at a rational instant strictly inside, and c_P(q) is the sum of
  the covered lengths: an exact surd. A pixel's value is the mean over its
  spatial samples of the sum over primitives, still exact; pins are written
  exactly when rational and to 15 significant digits otherwise.
- Cross-checks, asserted before anything is written:
  * a second, separately written per-instant predicate (a triangle by the
    crossing-count winding number of the nudged sample, section 14.1; a
    line by the inequalities of section 4.4 with the nudge) must agree with
    the first at every instant tested, and with the exact coverage's
    intervals at every instant that is not an event;
  * a brute-force Riemann sum of the second predicate at K midpoint instants
    (K = 4096, or 1024 with antialiasing, at every spatial sample of the
    pinned pixels; K = 512 at about 150 other samples per case) must lie
    within (events + 1)/K of the exact value (a midpoint sum of an indicator
    errs by at most one cell per event), and agree instant by instant with
    the exact coverage's intervals;
  * per case checks of the author's intent (a root is double, a vertex
    crosses a sample at 3/8, the three cull variants sum to the unculled
    case, a two-triangle mesh's time coverages sum exactly to its union's...).
- The sample method's estimate (section 15.3): the instants of every pixel
  (SplitMix64 seeded per pixel, the four time patterns,
  tau = open + (close - open)*u/2^16) and the spatial offsets (section 14.2),
  each test decided by the second predicate; static primitives drawn once.

Bounds written (section 15.4), per case (bounds(), rounded up to 4 decimals):

- max_time_rms = max(1.25 R, 1.5 sigma). R is the RMS over moving pixels of
  the sample method above with the case's own instants: what a correct sample
  method gets exactly, and 1.25 leaves room for one whose instants differ by
  rounding. sigma is the RMS over the same pixels of the standard deviation
  that N independent uniform instants per spatial sample give, computed from
  the exact coverages: sqrt(sum over samples and primitives of
  c(1 - c)/(M^2 N)) per pixel. As c(1 - c) <= 1/4, 1.5 sigma is at most SPEC's
  default 0.75 (M N)^-1/2 (asserted), and it is tighter where coverages are
  far from 1/2: in long_motion_112px_stratified16 every pixel is covered for
  a few percent of the shutter, and the default would let a method that
  ignores motion pass.
- max_time_error = max(1.25 X, 2 (M N)^-1/2), X that method's largest |error|;
  2 (M N)^-1/2 lets one stratum in sqrt(M N) flip.

The generator asserts that the sample method meets both; that a method that
ignores motion (draws every moving primitive at its shutter-open position)
fails max_time_rms and, unless the case says why not, max_time_error too; and
that one that draws the scene at mid-shutter fails at least one of them when
M N >= 16 (with fewer tests, the estimate is about as noisy as that guess).
--mutants shows that deliberately wrong variants of the checker trip these
checks.

Before writing, it clears the *.json files of cases/motion, except the
hand-written ones named spec_*.json (cases that pin SPEC statements; no
generator writes them).

The pieces are in casegen/motion/ (its __init__.py lists them); this file
runs them and writes the cases.

Usage: python3 tools/gen_motion_cases.py [-v] [--map] [--only TEXT]   (run from anywhere)
  -v           one line per case: moving pixels, the sample method's and the
               motion-ignoring method's RMS and max error against the bounds,
               and the pins with 40 digits
  --map        print each moving case's exact time coverage, pixel by pixel
  --only TEXT  evaluate only the cases whose name contains TEXT; writes nothing
  --mutants    run deliberately wrong variants of the checker (MUTANTS) and
               exit non-zero unless each one trips a check; writes nothing
Exits non-zero (an AssertionError) when any check fails; writes nothing then.
"""

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from casegen.motion import cases  # noqa: E402,F401 (registers the cases)
from casegen.motion.evaluate import CASES, MB, OUT_DIR, evaluate, render  # noqa: E402
from casegen.motion.instants import pixel_us  # noqa: E402
from casegen.motion.mutants import run_mutants  # noqa: E402


def main():
    if "--mutants" in sys.argv:
        run_mutants()
    names = set()
    results = []
    only = sys.argv[sys.argv.index("--only") + 1] if "--only" in sys.argv else None
    for c in CASES:
        assert c["name"] not in names, c["name"]
        names.add(c["name"])
        if only and only not in c["name"]:
            continue
        expect, stats = evaluate(c)
        for check in c["checks"]:
            assert check(stats), "check failed: %s" % c["name"]
        results.append((c, expect, stats))
        if "-v" in sys.argv:
            if stats["moving_pixels"] == 0:
                print("%-40s static, samples_covered %d" % (c["name"], stats["covered"]))
                continue
            print("%-40s M*N %3d moving %4d  sigma %.4f rms %.4f ignore %.4f mid %.4f / %s   max %.4f "
                  "ignore %.4f mid %.4f / %s  (%d instants checked against the intervals)" % (
                      c["name"], stats["M"] * stats["N"], stats["moving_pixels"], stats["sigma"],
                      stats["rms"],
                      stats["ig_rms"], stats["md_rms"], stats["rms_bound"], stats["max"],
                      stats["ig_max"], stats["md_max"], stats["max_bound"], stats["agree"]))
            for px, shown in stats["pins"]:
                print("    pin %-10s %s" % ("%d,%d" % px, shown))
        if "--map" in sys.argv and stats["moving_pixels"]:
            for y in range(c["H"]):
                print(" ".join("%4.2f" % float(stats["exact"][(x, y)]) for x in range(c["W"])))
    # The three stratified patterns draw the same instants without antialiasing
    # (SPEC 15.3; the shuffled one deals them to the N slots in another order).
    for px in range(64):
        a = [pixel_us(MB(16, p), px, 1) for p in ("stratified", "jittered-xy-t",
                                                   "stratified-shuffled")]
        assert a[0] == a[1] and sorted(a[1]) == sorted(a[2]) and a[1] != a[2]
    assert len(CASES) >= 24
    if only:
        print("evaluated %d cases (--only: nothing written)" % len(results))
        return
    os.makedirs(OUT_DIR, exist_ok=True)
    for f in os.listdir(OUT_DIR):
        if f.endswith(".json") and not f.startswith("spec_"):
            os.remove(os.path.join(OUT_DIR, f))
    for c, expect, _ in results:
        with open(os.path.join(OUT_DIR, c["name"] + ".json"), "w") as f:
            f.write(render(c, expect))
    print("wrote %d cases in cases/motion" % len(results))


if __name__ == "__main__":
    main()
