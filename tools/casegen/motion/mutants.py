"""Wrong variants of the motion checker (`--mutants`): each swaps one piece
(a predicate, the root finder, a bound, the time fraction, the events of a
primitive) and must make the generator's own checks fail on its case.
"""

import math
import sys

from casegen.motion import cases, evaluate as evaluation, predicates, primitives, quadratic
from casegen.motion.evaluate import CASES, bounds, evaluate, round_up
from casegen.motion.predicates import area2, convex_main, culled, tri_main
from casegen.motion.primitives import Prim
from casegen.motion.quadratic import roots_in

# The modules whose functions look the swapped names up: a swap replaces the
# name in every one that holds it, as one global would be replaced.
MODULES = (quadratic, predicates, primitives, evaluation, cases)


def _swap(name, value):
    olds = [(m, getattr(m, name)) for m in MODULES if hasattr(m, name)]
    assert olds, name
    for m, _ in olds:
        setattr(m, name, value)

    def undo():
        for m, old in olds:
            setattr(m, name, old)
    return undo


def _swap_attr(obj, name, value):
    old = getattr(obj, name)
    setattr(obj, name, value)
    return lambda: setattr(obj, name, old)


def _drop_polys(keep):
    real = Prim.polys

    def polys(self, q):
        return [p for i, p in enumerate(real(self, q)) if keep(self, i, p)]
    return _swap_attr(Prim, "polys", polys)


MUTANTS = [
    ("the second predicate gives ties to the opposite edges", "ride_top_edge_top_left",
     lambda: _swap("tri_alt", lambda pts, q, rule, cull: tri_main(
         pts, q, {"top-left": "bottom-right"}.get(rule, rule), cull))),
    ("the first predicate ignores cull", "winding_flip_cull_cw",
     lambda: _swap("tri_main", lambda pts, q, rule, cull: convex_main(pts, q, rule))),
    ("cull by the winding at shutter open (clockwise here)", "winding_flip_cull_ccw",
     lambda: _swap("tri_main", lambda pts, q, rule, cull: area2(pts) != 0 and not culled(1, cull)
                   and convex_main(pts, q, rule))),
    ("edges' dx and dy are not events (ownership changes are missed)", "edge_pivots_on_sample",
     lambda: _drop_polys(lambda prim, i, p: prim.kind != "triangle" or i % 3 == 0)),
    ("a line's major-axis switch is not an event", "line_parallelogram_major_axis_flip",
     lambda: _drop_polys(lambda prim, i, p: prim.kind != "line" or i >= 4)),
    ("irrational roots are dropped", "rotate_triangle_stratified16",
     lambda: _swap("roots_in", (lambda real: lambda poly, lo, hi: [
         r for r in real(poly, lo, hi) if r.rational() is not None])(roots_in))),
    ("max_time_rms is SPEC's default 0.75/sqrt(M*N)", "long_motion_112px_stratified16",
     lambda: _swap("bounds", (lambda real: lambda rms, mx, sigma, T: (
         round_up(0.75 / math.sqrt(T)), real(rms, mx, sigma, T)[1]))(bounds))),
    ("the covered length is not divided by the shutter's length", "coverage_starts_at_shutter_open",
     lambda: _swap("time_fraction", lambda length, shutter: length)),
]


def run_mutants():
    """Each wrong variant must trip an assertion of evaluate() or of its case's
    checks; exits non-zero otherwise."""
    by_name = {c["name"]: c for c in CASES}
    ok = True
    for what, name, patch in MUTANTS:
        undo = patch()
        try:
            c = by_name[name]
            _, stats = evaluate(c)
            for check in c["checks"]:
                assert check(stats)
            print("NOT CAUGHT  %-62s %s" % (what, name))
            ok = False
        except AssertionError as e:
            print("caught      %-62s %s: %s" % (what, name, str(e)[:70]))
        finally:
            undo()
    sys.exit(0 if ok else 1)

