"""The line cases' independent exact checker, written from SPEC.md sections 4
and 5 alone (it shares no code with rastercheck): the four line rules
(midpoint with its ties, diamond-exit, rectangle, parallelogram) and line
interpolation, with knobs (Opts) that model wrong rasterizers. check()
proves each case's claims; render_frame() gives the counts the files carry.
"""

import math
from fractions import Fraction as F

from casegen.casefile import pos_of
from casegen.lines.build import CASES, V, fmt_px
from casegen.snapping import snap

HALF = F(1, 2)


OWNERS = {"top-left": {"top", "left"}, "bottom-right": {"bottom", "right"},
          "top-right": {"top", "right"}, "bottom-left": {"bottom", "left"},
          "all-edges": {"top", "left", "bottom", "right"}}
FLIP = {"top-left": "bottom-right", "bottom-right": "top-left", "top-right": "bottom-left",
        "bottom-left": "top-right", "all-edges": "all-edges"}


def edge_kind(nx, ny):
    if nx == 0:
        return "top" if ny < 0 else "bottom"
    return "left" if nx < 0 else "right"


def ceil(q):
    return -((-q.numerator) // q.denominator)


class Opts:
    """Knobs that model a wrong rasterizer, used to prove a case is sensitive."""

    def __init__(self, rule=None, snap_mode="even", tie="spec", xmajor_at_one=True,
                 parameter=None, interpolation=None, clamp=True, diamond="spec"):
        self.rule, self.snap_mode, self.tie = rule, snap_mode, tie
        self.diamond = diamond
        self.xmajor_at_one = xmajor_at_one
        self.parameter, self.interpolation, self.clamp = parameter, interpolation, clamp


def line_samples(c, ln, o, bits):
    """Yields (x, y, px, py) for every canvas sample the line covers, px, py
    the sample point."""
    W, H = c["width"], c["height"]
    (x0, y0), (x1, y1) = [tuple(snap(q, bits, o.snap_mode) for q in pos_of(v)) for v in ln.v]
    dx, dy = x1 - x0, y1 - y0
    if dx == 0 and dy == 0:
        return
    xmajor = abs(dx) > abs(dy) or (abs(dx) == abs(dy) and o.xmajor_at_one)
    fill = o.rule or c["fill_rule"]
    owners = OWNERS[fill]
    if ln.rule == "diamond-exit":
        yield from diamond_samples(c, (x0, y0), (x1, y1), xmajor, o.diamond)
        return
    if ln.rule == "midpoint":
        exclude = ln.last_pixel == "exclude"
        # Work in (major, minor) coordinates.
        if xmajor:
            a0, b0, a1, b1, n_major, n_minor = x0, y0, x1, y1, W, H
        else:
            a0, b0, a1, b1, n_major, n_minor = y0, x0, y1, x1, H, W
        lo, hi = min(a0, a1), max(a0, a1)
        first = max(0, ceil(lo - HALF))
        last = min(n_major - 1, math.floor(hi - HALF))
        for i in range(first, last + 1):
            m = i + HALF
            if exclude and m == a1:
                continue
            b = b0 + (m - a0) * (b1 - b0) / (a1 - a0)
            if o.tie == "spec":
                j = ceil(b) - 1
            else:  # the other row/column on a tie
                j = math.floor(b)
            if 0 <= j < n_minor:
                if xmajor:
                    yield i, j, m, j + HALF
                else:
                    yield j, i, j + HALF, m
        return
    w = ln.width if ln.width is not None else F(1)
    hw = w / 2
    for yy in range(H):
        py = yy + HALF
        for xx in range(W):
            px = xx + HALF
            on = []
            if ln.rule == "rectangle":
                qx, qy = px - x0, py - y0
                L = dx * dx + dy * dy
                a = qx * dx + qy * dy
                cr = qx * dy - qy * dx
                h2 = hw * hw * L
                if a < 0 or a > L or cr * cr > h2:
                    continue
                if a == 0:
                    on.append((-dx, -dy))
                if a == L:
                    on.append((dx, dy))
                if cr * cr == h2:
                    on.append((dy, -dx) if cr > 0 else (-dy, dx))
            else:
                if xmajor:
                    xl, xr = min(x0, x1), max(x0, x1)
                    if px < xl or px > xr:
                        continue
                    s = dy / dx
                    e = py - (y0 + (px - x0) * s)
                    if abs(e) > hw:
                        continue
                    if px == xl:
                        on.append((-1, 0))
                    if px == xr:
                        on.append((1, 0))
                    if e == hw:
                        on.append((-s, 1))
                    if e == -hw:
                        on.append((s, -1))
                else:
                    yt, yb = min(y0, y1), max(y0, y1)
                    if py < yt or py > yb:
                        continue
                    s = dx / dy
                    f = px - (x0 + (py - y0) * s)
                    if abs(f) > hw:
                        continue
                    if py == yt:
                        on.append((0, -1))
                    if py == yb:
                        on.append((0, 1))
                    if f == hw:
                        on.append((1, -s))
                    if f == -hw:
                        on.append((-1, s))
            if all(edge_kind(nx, ny) in owners for nx, ny in on):
                yield xx, yy, px, py


# The diamond-exit rule (SPEC 4.2). A diamond is the intersection of four
# half-planes a*u + b*v < 1/2 (strict) or <= 1/2 around the pixel centre, plus
# a list of extra points (the right corner of a y-major line's diamond). The
# variants other than "spec" model wrong rasterizers, to prove a case sensitive.

def diamond_shape(xmajor, variant):
    """([(a, b, strict)], [extra (u, v) points]) for the diamond of a line."""
    lower = [(-1, -1, True), (1, -1, True), (-1, 1, False), (1, 1, False)]
    right = [(HALF, F(0))]
    if variant in ("spec", "include_last", "exclude_first"):
        return lower, ([] if xmajor else right)
    if variant == "no_right_corner":       # the right corner never included
        return lower, []
    if variant == "right_corner_always":   # the right corner included for x-major lines too
        return lower, right
    if variant == "closed":                # every border point included
        return [(a, b, False) for a, b, _ in lower], []
    if variant == "open":                  # no border point included
        return [(a, b, True) for a, b, _ in lower], []
    if variant == "upper":                 # y up: upper edges and top corner instead
        return [(a, -b, st) for a, b, st in lower], ([] if xmajor else right)
    raise ValueError(variant)


def in_diamond(u, v, shape):
    planes, extra = shape
    if all((a * u + b * v < HALF) if st else (a * u + b * v <= HALF) for a, b, st in planes):
        return True
    return (u, v) in extra


def segment_meets_diamond(p0, p1, shape):
    """Whether the closed segment p0-p1 (relative to the pixel centre) has a
    point in the diamond: the parameter t in [0, 1] of p0 + t (p1 - p0) must
    satisfy every half-plane; each gives a bound on t, open or closed."""
    planes, extra = shape
    (u0, v0), (u1, v1) = p0, p1
    du, dv = u1 - u0, v1 - v0
    lo, lo_open, hi, hi_open = F(0), False, F(1), False
    feasible = True
    for a, b, st in planes:
        f0 = a * u0 + b * v0          # a*u + b*v at t = 0
        k = a * du + b * dv           # its rate in t
        if k == 0:
            if not ((f0 < HALF) if st else (f0 <= HALF)):
                feasible = False
            continue
        t = (HALF - f0) / k
        if k > 0:                     # t < bound (strict) or t <= bound
            if t < hi or (t == hi and st):
                hi, hi_open = t, (hi_open or st) if t == hi else st
        else:                         # t > bound (strict) or t >= bound
            if t > lo or (t == lo and st):
                lo, lo_open = t, (lo_open or st) if t == lo else st
    if feasible and (lo < hi or (lo == hi and not lo_open and not hi_open)):
        return True
    for eu, ev in extra:              # a lone border point on the segment
        qu, qv = eu - u0, ev - v0
        if qu * dv - qv * du == 0 and 0 <= qu * du + qv * dv <= du * du + dv * dv:
            return True
    return False


def diamond_samples(c, p0, p1, xmajor, variant):
    """Yields (x, y, px, py) for the canvas pixels a diamond-exit line lights."""
    W, H = c["width"], c["height"]
    shape = diamond_shape(xmajor, variant)
    (x0, y0), (x1, y1) = p0, p1
    excluded = p0 if variant == "exclude_first" else p1
    xa = max(0, math.floor(min(x0, x1)) - 1)
    xb = min(W - 1, math.floor(max(x0, x1)) + 1)
    ya = max(0, math.floor(min(y0, y1)) - 1)
    yb = min(H - 1, math.floor(max(y0, y1)) + 1)
    for yy in range(ya, yb + 1):
        cy = yy + HALF
        for xx in range(xa, xb + 1):
            cx = xx + HALF
            if not segment_meets_diamond((x0 - cx, y0 - cy), (x1 - cx, y1 - cy), shape):
                continue
            if variant != "include_last" and in_diamond(excluded[0] - cx, excluded[1] - cy, shape):
                continue
            yield xx, yy, cx, cy


def values_at(c, ln, o, bits, px, py):
    """(z or None, [attributes]) at the sample, exact (SPEC 5), and whether t was clamped."""
    (x0, y0), (x1, y1) = [tuple(snap(q, bits, o.snap_mode) for q in pos_of(v)) for v in ln.v]
    dx, dy = x1 - x0, y1 - y0
    parameter = o.parameter or ln.parameter or "major"
    interpolation = o.interpolation or ln.interpolation or "perspective"
    if parameter == "major":
        t = (px - x0) / dx if abs(dx) >= abs(dy) else (py - y0) / dy
    else:
        t = ((px - x0) * dx + (py - y0) * dy) / (dx * dx + dy * dy)
    clamped = t < 0 or t > 1
    if o.clamp:
        t = min(max(t, F(0)), F(1))
    v0, v1 = ln.v

    def get(v, what, default):
        if not isinstance(v, V):
            return default
        val = getattr(v, what)
        return default if val is None else val

    z0, z1 = get(v0, "z", F(0)), get(v1, "z", F(0))
    w0, w1 = get(v0, "w", F(1)), get(v1, "w", F(1))
    a0, a1 = get(v0, "attributes", []), get(v1, "attributes", [])
    z = (1 - t) * z0 + t * z1
    attrs = []
    for p, q in zip(a0, a1):
        if interpolation == "flat":
            attrs.append(p)
        elif interpolation == "linear":
            attrs.append((1 - t) * p + t * q)
        else:
            attrs.append(((1 - t) * p / w0 + t * q / w1) / ((1 - t) / w0 + t / w1))
    return z, attrs, clamped


def render_frame(c, o=None, bits="same", values=False):
    """{(x, y): [count, last index, z, attrs]} for every covered sample."""
    o = o or Opts()
    bits = c["bits"] if bits == "same" else bits
    out = {}
    clamped_any = False
    for idx, ln in enumerate(c["prims"]):
        seen = set()
        for x, y, px, py in line_samples(c, ln, o, bits):
            assert (x, y) not in seen, "a line covered a sample twice"
            seen.add((x, y))
            slot = out.setdefault((x, y), [0, None, None, None])
            slot[0] += 1
            slot[1] = idx
            if values:
                z, attrs, cl = values_at(c, ln, o, bits, px, py)
                slot[2], slot[3] = z, attrs
                clamped_any = clamped_any or cl
    if values:
        return out, clamped_any
    return out


def cover_sig(fr):
    return {k: (v[0], v[1]) for k, v in fr.items()}


def value_sig(fr):
    return {k: (v[0], v[1], v[2], tuple(v[3])) for k, v in fr.items()}


def has_values(c):
    return any(isinstance(v, V) for ln in c["prims"] for v in ln.v)


def check():
    ok = True
    frames = {}
    for c in CASES:
        notes = []
        fr = render_frame(c)
        frames[c["name"]] = fr
        n = len(fr)
        maxcov = max((v[0] for v in fr.values()), default=0)
        for kind, *arg in c["checks"]:
            if kind == "ties":
                diff = cover_sig(render_frame(c, Opts(tie="other"))) != cover_sig(fr)
                notes.append("ties %s" % ("hit" if diff else "NOT HIT"))
                ok &= diff
            elif kind == "fill_rule":
                diff = cover_sig(render_frame(c, Opts(rule=FLIP[c["fill_rule"]]))) != cover_sig(fr)
                notes.append("fill rule %s" % ("decides" if diff else "DOES NOT DECIDE"))
                ok &= diff
            elif kind == "snap":
                sens = [m for m in ("up", "down", "away", "toward", "odd")
                        if cover_sig(render_frame(c, Opts(snap_mode=m))) != cover_sig(fr)]
                if cover_sig(render_frame(c, bits=None)) != cover_sig(fr):
                    sens.append("unsnapped")
                notes.append("snap-sensitive to %s" % (",".join(sens) or "NOTHING"))
                ok &= bool(sens)
            elif kind == "xmajor_at_one":
                diff = cover_sig(render_frame(c, Opts(xmajor_at_one=False))) != cover_sig(fr)
                notes.append("x-major at slope 1 %s" % ("matters" if diff else "DOES NOT MATTER"))
                ok &= diff
            elif kind == "same_as":
                other = frames[arg[0]]
                same = {k: v[0] for k, v in other.items()} == {k: v[0] for k, v in fr.items()}
                notes.append("same pixels and counts as %s: %s" % (arg[0], same))
                ok &= same
            elif kind == "diamond":
                diff = cover_sig(render_frame(c, Opts(diamond=arg[0]))) != cover_sig(fr)
                notes.append("diamond %s %s" % (arg[0], "matters" if diff else "DOES NOT MATTER"))
                ok &= diff
            elif kind == "differs_from":
                other = frames[arg[0]]
                mine_px, theirs_px = set(fr), set(other)
                notes.append("differs from %s: only here %s, only there %s" % (
                    arg[0], fmt_px(sorted(mine_px - theirs_px)) or "-",
                    fmt_px(sorted(theirs_px - mine_px)) or "-"))
                ok &= mine_px != theirs_px
            elif kind in ("lit", "unlit"):
                idx, x, y = arg
                got = (x, y) in {(p[0], p[1]) for p in line_samples(c, c["prims"][idx], Opts(), c["bits"])}
                good = got == (kind == "lit")
                notes.append("%s (%d,%d) by %d: %s" % (kind, x, y, idx, good))
                ok &= good
            elif kind == "uncovered":
                good = (arg[0], arg[1]) not in fr
                notes.append("(%d,%d) uncovered: %s" % (arg[0], arg[1], good))
                ok &= good
            elif kind == "max_coverage":
                good = maxcov <= arg[0]
                notes.append("max coverage %d <= %d: %s" % (maxcov, arg[0], good))
                ok &= good
            elif kind == "min_coverage_max":
                good = maxcov >= arg[0]
                notes.append("max coverage %d >= %d: %s" % (maxcov, arg[0], good))
                ok &= good
            elif kind == "parameter":
                base, _ = render_frame(c, values=True)
                other_p = "major" if c["prims"][0].parameter == "projected" else "projected"
                alt, _ = render_frame(c, Opts(parameter=other_p), values=True)
                diff = value_sig(base) != value_sig(alt)
                notes.append("parameter %s" % ("matters" if diff else "DOES NOT MATTER"))
                ok &= diff
            elif kind == "perspective":
                base, _ = render_frame(c, values=True)
                alt, _ = render_frame(c, Opts(interpolation="linear"), values=True)
                diff = value_sig(base) != value_sig(alt)
                notes.append("perspective %s" % ("matters" if diff else "DOES NOT MATTER"))
                ok &= diff
            elif kind == "clamp":
                _, cl = render_frame(c, values=True)
                notes.append("clamping %s" % ("happens" if cl else "NEVER HAPPENS"))
                ok &= cl
        for idx, px in c["pixels"].items():
            got = sorted((x, y) for x, y, _, _ in line_samples(c, c["prims"][idx], Opts(), c["bits"]))
            if got != sorted(px):
                notes.append("DESCRIPTION PIXELS OF PRIMITIVE %d WRONG: checker %s" % (idx, fmt_px(got)))
                ok = False
        print("%-44s %5d covered, max %2d  %s" % (c["name"], n, maxcov, "; ".join(notes)))
    return ok
