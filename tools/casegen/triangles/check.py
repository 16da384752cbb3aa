"""The triangle cases' independent exact checker (`tools/gen_cases.py
--check`): coverage by exact edge functions with the fill rule's nudge,
recomputing every stated `samples_covered`, and proving each tie case
sensitive to the fill rule and each snapping case to the snapping's tie
rule. It never writes expectations.
"""

import math
from fractions import Fraction as F

from casegen.casefile import pos_of
from casegen.snapping import snap
from casegen.triangles.cases import CASES

HALF = F(1, 2)


NUDGE = {"top-left": (1, 1), "bottom-right": (-1, -1), "top-right": (-1, 1), "bottom-left": (1, -1)}
FLIP = {"top-left": "bottom-right", "bottom-right": "top-left", "top-right": "bottom-left",
        "bottom-left": "top-right", "all-edges": "all-edges"}


def coverage(c, rule=None, snap_mode="even", bits="same"):
    rule = rule or c["fill_rule"]
    bits = c["bits"] if bits == "same" else bits
    W, H = c["width"], c["height"]
    cov = [[[] for _ in range(W)] for _ in range(H)]
    for idx, t in enumerate(c["prims"]):
        p = [tuple(snap(q, bits, snap_mode) for q in pos_of(v)) for v in t.v]
        (x0, y0), (x1, y1), (x2, y2) = p
        area = (x1 - x0) * (y2 - y0) - (y1 - y0) * (x2 - x0)
        if area == 0:
            continue
        if c["cull"] == "cw" and area > 0 or c["cull"] == "ccw" and area < 0:
            continue
        sg = 1 if area > 0 else -1
        edges = []
        for i in range(3):
            a, b = p[i], p[(i + 1) % 3]
            edges.append((a, b))
        xs = [q[0] for q in p]
        ys = [q[1] for q in p]
        xa = max(0, math.floor(min(xs) - HALF))
        xb = min(W - 1, math.ceil(max(xs) - HALF))
        ya = max(0, math.floor(min(ys) - HALF))
        yb = min(H - 1, math.ceil(max(ys) - HALF))
        for yy in range(ya, yb + 1):
            sy = yy + HALF
            for xx in range(xa, xb + 1):
                sx = xx + HALF
                inside = True
                for (ax, ay), (bx, by) in edges:
                    e = ((bx - ax) * (sy - ay) - (by - ay) * (sx - ax)) * sg
                    if e > 0:
                        continue
                    if e < 0:
                        inside = False
                        break
                    if rule == "all-edges":
                        continue
                    gx = -(by - ay) * sg
                    gy = (bx - ax) * sg
                    nx, ny = NUDGE[rule]
                    val = gx * nx if gx != 0 else gy * ny
                    if val <= 0:
                        inside = False
                        break
                if inside:
                    cov[yy][xx].append(idx)
    return cov


def covered_count(cov):
    return sum(1 for row in cov for s in row if s)


def check():
    ok = True
    for c in CASES:
        cov = coverage(c)
        n = covered_count(cov)
        notes = []
        exp = c["expect"]
        if "samples_covered" in exp and exp["samples_covered"] != n:
            notes.append("EXPECTED %d BUT CHECKER COUNTS %d" % (exp["samples_covered"], n))
            ok = False
        if exp.get("watertight"):
            covs = {r: coverage(c, rule=r) for r in NUDGE}
            holes = over = 0
            for yy in range(c["height"]):
                for xx in range(c["width"]):
                    if all(covs[r][yy][xx] for r in NUDGE):
                        if not cov[yy][xx] and c["fill_rule"] != "all-edges":
                            holes += 1
                    if len(cov[yy][xx]) > 1 and c["fill_rule"] != "all-edges":
                        over += 1
            if holes or over:
                notes.append("NOT WATERTIGHT under its own rule: %d holes %d overdraw" % (holes, over))
                ok = False
        if c["ties"]:
            flipped = coverage(c, rule=FLIP[c["fill_rule"]])
            diff = sum(1 for yy in range(c["height"]) for xx in range(c["width"])
                       if (cov[yy][xx][-1:] != flipped[yy][xx][-1:]) or
                       len(cov[yy][xx]) != len(flipped[yy][xx]))
            if c["fill_rule"] == "all-edges":
                diff = -1
            notes.append("flipped-rule diffs %d" % diff)
            if diff == 0:
                notes.append("NO TIES HIT")
                ok = False
        if c["snap_sensitive"]:
            sens = []
            for mode in ("up", "down", "away", "toward", "odd"):
                other = coverage(c, snap_mode=mode)
                if other != cov:
                    sens.append(mode)
            if c["bits"] is None:
                if coverage(c, bits=8) != cov:
                    sens.append("bits8")
            elif coverage(c, bits=None) != cov:
                sens.append("unsnapped")
            notes.append("snap-sensitive to %s" % (",".join(sens) or "NOTHING"))
            if not sens:
                ok = False
        print("%-42s %4d covered  %s" % (c["name"], n, "; ".join(notes)))
    return ok

