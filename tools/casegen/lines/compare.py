"""Comparing the line checker with rastercheck's own reference: by coverage
count through the binary (`--compare`), or whole frames from a JSON dump of
the reference's frames (`--compare-dump FILE`).
"""

import json
import os
import re
import subprocess
from fractions import Fraction as F

from casegen import ROOT
from casegen.lines.build import CASES, fmt_px
from casegen.lines.check import has_values, render_frame


def compare_run():
    """Compares the checker's count with what `rastercheck run -r reference` prints."""
    exe = os.path.join(ROOT, "target", "release", "rastercheck")
    if not os.path.exists(exe):
        exe = os.path.join(ROOT, "target", "debug", "rastercheck")
    res = subprocess.run([exe, "run", os.path.join(ROOT, "cases", "lines"), "-r", "reference"],
                         capture_output=True, text=True)
    got = {}
    for line in res.stdout.splitlines():
        m = re.match(r"\s*(\S+)\s+lines/(\S+)\s+reference\s+coverage (\d+)/(\d+) samples", line)
        if m:
            got[m.group(2)] = int(m.group(3))
    ok = True
    for c in CASES:
        mine = len(render_frame(c))
        theirs = got.get(c["name"])
        if theirs != mine:
            print("COUNT MISMATCH %s: checker %d, rastercheck %s" % (c["name"], mine, theirs))
            ok = False
    print("run: %d cases compared by count, %s" % (len(got), "all agree" if ok else "DISAGREEMENT"))
    print("\n".join(res.stdout.splitlines()[-3:]))
    return ok


def compare_dump(path):
    """Compares whole frames with a JSON dump of the reference's frames."""
    with open(path) as f:
        dumps = {os.path.splitext(os.path.basename(d["path"]))[0]: d for d in json.load(f)}
    ok = True
    for c in CASES:
        d = dumps.get(c["name"])
        if d is None:
            print("NOT IN DUMP %s" % c["name"])
            ok = False
            continue
        fr, _ = render_frame(c, values=True)
        W = c["width"]
        bad = []
        for i, (cov, last) in enumerate(zip(d["coverage"], d["last"])):
            key = (i % W, i // W)
            mine = fr.get(key)
            if (mine[0] if mine else 0) != cov or (mine[1] + 1 if mine else 0) != last:
                bad.append("(%d,%d) checker %s reference %d/%d" % (
                    key[0], key[1], "%d/%d" % (mine[0], mine[1] + 1) if mine else "0/0", cov, last))
                continue
            if not mine or not has_values(c):
                continue
            chans = ([("depth", mine[2], d["depth"][i])] if d["depth"] else []) + \
                    [("attribute.%d" % k, mine[3][k], d["attributes"][k][i]) for k in range(len(mine[3]))]
            for name, ex, got in chans:
                g = F(float(got))
                tol = abs(ex) * F(1, 2**50) if ex != 0 else F(0)
                if abs(g - ex) > tol:
                    bad.append("(%d,%d) %s checker %s reference %r" % (key[0], key[1], name, float(ex), got))
        if bad:
            ok = False
            mine_px = sorted(fr)
            theirs_px = sorted((i % W, i // W) for i, cov in enumerate(d["coverage"]) if cov)
            print("FRAME MISMATCH %s: %d samples differ\n  %s" % (c["name"], len(bad), "\n  ".join(bad[:40])))
            print("  checker pixels:   %s" % fmt_px(mine_px))
            print("  reference pixels: %s" % fmt_px(theirs_px))
        else:
            print("frame agrees %s" % c["name"])
    return ok
