#!/usr/bin/env python3
"""Writes the catalogue of hard cases: cases/hard/*.json.

Python 3 standard library only. Every coordinate is an exact rational
(fractions.Fraction) written as in tools/gen_cases.py (integers, terminating
decimals, or "p/q" strings), and every vertex that two triangles share is
computed once and written identically in both.

Each case's description says why it is hard. The numbers in
`expect.samples_covered` come only from the small exact checker
(casegen/hard/check.py), written from SPEC.md alone (it shares no code with
rastercheck): snapping with ties to even (section 2), edge ownership in
D3D11's words (where does the third vertex lie? section 3), the midpoint
line rule (section 4.1), and the mesh interior of section 6.2. With
`--check` it also proves each case's claims: that the mesh is watertight
under its own rule, that the stated samples are the crack, that the flipped
fill rule or snapping ties half away from zero changes the picture, that
the degenerate triangles have zero area, how many bits the edge products
need, and so on.

Families (the case names start with the family):

  edge_halfint_*    vertices at half-integers: samples exactly on shared edges
  fan_*             64+ triangles around one sample point
  flipped_*         shared edges drawn with vertex order and winding flipped
  far_b8_*          vertices near +-32768 px at 8 subpixel bits
  sliver_*          near-collinear and collinear triangles
  tjunction_*       a genuine crack (and its overdraw twin) at a T-junction
  miss_*            triangles that cover no sample
  snaptie_*         vertices exactly half a subpixel off the grid
  persp_*           w from 0.001 to 1000, attributes up to +-1e6
  line_*            midpoint ties and 1000+ px lines
  overlap_*         self-overlapping fans (coverage 2 and more)
  far_b16_*         a 16-subpixel-bit mesh at +-32768 (i128 in production)
  unsnapped_*       subpixel_bits null, dyadic coordinates with ties
  degenerate_*      zero-area triangles inside a mesh
  rules_far_*       every fill rule on one tie-heavy mesh at large coordinates

Polygons and antialiasing (SPEC.md section 14; expectations from the exact
checker of tools/gen_aa_cases.py (casegen/antialias/), imported, with each case's claims asserted
here: exact total areas from the shoelace formula, full pixels, no sample
covered twice, the same samples as a simpler scene):

  aa_abut_*         fans of 64 and 128 triangles, a 200-triangle grid tiling a
                    square, a far square with a far hole, at standard 16x:
                    coverages that must sum to exactly 1
  poly_*            self-overlapping polygons (winding twice, overlapping
                    contours, doubled edges, repeated and collinear vertices,
                    zero-area contours), with and without 16x, both fills;
                    poly_far_*: vertices near +-32768 px at 8 bits
  aa_sliver_*       antialiased slivers and near-collinear triangles
  aa_tie_*          samples on shared edges and vertices under 16x

The case model is casegen/hard/build.py, the triangle and line cases
casegen/hard/cases.py, their checker casegen/hard/check.py and the polygon
and antialiasing cases casegen/hard/aa_cases.py; this file writes them.

Usage: python3 tools/gen_hard_cases.py [--check]   (run from anywhere)
"""

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from casegen.antialias.evaluate import render as aa_render  # noqa: E402
from casegen.casefile import render  # noqa: E402
from casegen.hard import cases  # noqa: E402,F401 (registers the cases)
from casegen.hard.aa_cases import AA_CASES, aa_evaluate  # noqa: E402
from casegen.hard.build import CASES, OUT_DIR  # noqa: E402
from casegen.hard.check import check_claims, product_bits, render_frame  # noqa: E402


def main():
    names = [c["name"] for c in CASES]
    names += [c["name"] for c in AA_CASES]
    assert len(names) == len(set(names)), "duplicate case names"
    checking = "--check" in sys.argv[1:]
    os.makedirs(OUT_DIR, exist_ok=True)
    all_ok = True
    for c in CASES:
        cov, on_edges, areas, line_ties = render_frame(c)
        if "{bits}" in c["description"] or "{ties}" in c["description"]:
            c["description"] = c["description"].replace("{bits}", str(product_bits(c))).replace(
                "{ties}", str(len(on_edges)))
        expect = {"samples_covered": len(cov)}
        if c["watertight"]:
            expect = {"watertight": True, "samples_covered": len(cov)}
        with open(os.path.join(OUT_DIR, c["name"] + ".json"), "w") as f:
            f.write(render(c, expect))
        if checking:
            ok, notes = check_claims(c, cov, on_edges, areas, line_ties)
            all_ok &= ok
            print("%-36s %5d covered  %s" % (c["name"], len(cov), "; ".join(notes)), flush=True)
    for c in AA_CASES:
        expect, stats = aa_evaluate(c)
        with open(os.path.join(OUT_DIR, c["name"] + ".json"), "w") as f:
            f.write(aa_render(c, expect))
        if checking:
            print("%-36s %5d covered  area %s" % (c["name"], stats["covered"],
                                                  expect.get("area", "-")), flush=True)
    print("wrote %d cases to %s" % (len(CASES) + len(AA_CASES), OUT_DIR))
    if checking:
        sys.exit(0 if all_ok else 1)


if __name__ == "__main__":
    main()
