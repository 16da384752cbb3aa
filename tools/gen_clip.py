#!/usr/bin/env python3
"""Writes the clip-space cases: cases/clip/*.json (SPEC.md section 16), and
the screen-space worked example cases/triangles/spec_provoking_last.json.

Python 3 standard library only. Every `expect.samples_covered` is computed
here by an exact model of section 16 written from SPEC.md alone
(casegen/clip/homogeneous.py: the clipper, the viewport and snapping, the
homogeneous sample test with the fill rule on homogeneous edges, culling,
the guard band's viewport rectangle, per-sample depth, depth clamp), so each
case pins the oracle to the spec independently of rastercheck. Cross-checks
run before anything is written (casegen/clip/check.py):

- a second, separately written predicate, a Moeller-Trumbore ray cast in
  (x, y, w) space from the eye through the sample, must agree with the
  homogeneous edge test on random triangles (vertices behind the eye
  included) at every sample that lies on no edge;
- unsnapped (subpixel_bits null), clipping then rasterizing must cover what
  the unclipped triangle covers under per-sample depth and the guard band,
  with the same depth and attributes, except at samples exactly on a plane;
- a triangle inside the clip volume is drawn alike under all six
  conventions, and as its screen-space triangle (section 16.7) by a
  separately written screen-space test (casegen/clip/screen.py).

Usage: python3 tools/gen_clip.py [-v] [--map NAME] [--check] [--self-test]
       python3 tools/gen_clip.py --random SEED COUNT DIR [--wrong]
  (run from anywhere)
  -v           one line per case: samples_covered and the rules
  --map NAME   print the case's coverage as a picture
  --check      write nothing: regenerate into a temporary folder and compare
               with the files in the repository; exit 1 naming each file
               that differs, is missing, or is in cases/clip but not
               generated
  --self-test  write nothing: run the cross-checks on random triangles, then
               deliberately wrong variants of the model (casegen/clip/
               mutants.py), printing how many pins each changes; exit 1
               unless each changes at least one
  --random     write nothing in the repository: COUNT random clip-space cases
               into DIR, each pinned by the model (casegen/clip/random_cases.py
               says which triangles it leaves out); with --wrong, pinned by a
               wrong model (vertices behind the eye divided by their w).
               tests/clip_cases.rs runs the reference on them
Exits non-zero (an AssertionError) when a case's own check fails.
"""

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from casegen.clip import check, mutants  # noqa: E402
from casegen.clip.random_cases import write_random  # noqa: E402
from casegen.clip.build import CASES  # noqa: E402
from casegen.clip.generate import evaluate, files, stale_against, write  # noqa: E402


def main():
    args = sys.argv[1:]
    if "--random" in args:
        seed, count, out_dir = args[args.index("--random") + 1:args.index("--random") + 4]
        write_random(int(seed), int(count), out_dir, wrong="--wrong" in args)
        print("wrote %s random cases to %s" % (count, out_dir))
        return
    frames, counts = evaluate()
    if "-v" in args:
        for c in CASES:
            r = c["rules"]
            print("%-40s %4d  %s" % (c["name"], counts[c["name"]], " ".join(
                str(r.get(k)) for k in ("subpixel_bits", "fill_rule", "cull", "clip_xy",
                                         "clip_z", "depth", "provoking_vertex"))))
    if "--map" in args:
        name = args[args.index("--map") + 1]
        c = next(c for c in CASES if c["name"] == name)
        frame = frames[name]
        for j in range(c["height"]):
            print(" ".join("%d" % frame[(i, j)][0] if (i, j) in frame else "."
                           for i in range(c["width"])))
    out = files(counts)
    if "--self-test" in args:
        ok = check.run_all() and mutants.run_mutants(counts)
        sys.exit(0 if ok else 1)
    if "--check" in args:
        bad = stale_against(out)
        for line in bad:
            print("stale: " + line)
        if bad:
            print("run python3 tools/gen_clip.py and commit the result")
            sys.exit(1)
        print("%d files up to date" % len(out))
        return
    write(out)
    print("wrote %d cases to cases/clip and cases/triangles/spec_provoking_last.json"
          % len(CASES))


if __name__ == "__main__":
    main()
