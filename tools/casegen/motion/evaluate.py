"""Evaluating a motion case: the case registry, the bounds (section 15.4),
evaluate() with its cross-checks (the second predicate, the brute-force
Riemann sums, the sample method's estimate, the motion-ignoring and
mid-shutter guesses), and the writer of the case file.
"""

import math
import os
from fractions import Fraction as F

from casegen import ROOT
from casegen.exactjson import exact, js
from casegen.motion.instants import TIME_BITS, TIME_ONE, pixel_us, spatial_offsets
from casegen.motion.primitives import TimeCoverage, pow2_exp
from casegen.motion.quadratic import Surd

OUT_DIR = os.path.join(ROOT, "cases", "motion")

# ---------------------------------------------------------------------------
# The case registry.

CASES = []


def case(name, description, width, height, prims, mb, aa=None, fill_rule="top-left",
         cull="none", bits=8, pins=(), checks=(), ignore_max_ok=False):
    """Registers a case. mb: effects.motion_blur. pins: pixels whose exact
    time coverage is written (more are chosen automatically). checks:
    functions of the evaluated case that must hold (the author's intent).
    ignore_max_ok: the motion-ignoring method may meet the max-error bound
    here (the description says why); it must still fail the RMS bound."""
    assert (width <= 64 and height <= 64) or name.startswith("long_"), name
    assert mb["samples"] <= 64 and mb["samples"] * (aa["samples"] if aa else 1) <= 256, name
    CASES.append(dict(name=name, description=description, W=width, H=height, prims=prims,
                      mb=mb, aa=aa, rule=fill_rule, cull=cull, bits=bits, pins=list(pins),
                      checks=list(checks), ignore_max_ok=ignore_max_ok))


def MB(samples, pattern="stratified", seed=0, shutter=None):
    d = {}
    if shutter is not None:
        d["shutter"] = [exact(shutter[0]), exact(shutter[1])]
    d["samples"] = samples
    d["pattern"] = pattern
    if seed:
        d["seed"] = seed
    return d


def AA(samples, pattern="standard", seed=None):
    d = {"samples": samples, "pattern": pattern}
    if seed is not None:
        d["seed"] = seed
    return d


def round_up(q, digits=4):
    s = 10 ** digits
    return F(math.ceil(F(q) * s), s)


def sig15(q):
    """A positive rational rounded to 15 significant digits, as a Fraction."""
    q = F(q)
    if q == 0:
        return q
    e = math.floor(math.log10(float(q)))
    k = 14 - e
    return F(round(q * F(10) ** k)) / F(10) ** k


def shutter_of(mb):
    s = mb.get("shutter", [0, 1])
    return F(s[0]), F(s[1])


def bounds(rms, mx, sigma, T):
    """(max_time_rms, max_time_error) from the sample method's RMS and largest
    error, the RMS sigma of independent uniform instants, and M*N (see the
    module docstring)."""
    return round_up(max(1.25 * rms, 1.5 * sigma)), round_up(max(1.25 * mx, 2 / math.sqrt(T)))


def time_fraction(length, shutter):
    """c_P(q): the covered length over the shutter's length (SPEC 15.2)."""
    return length.scale(1 / (shutter[1] - shutter[0]))


def evaluate(c):
    """Every expectation of a case, after every cross-check; returns
    (expect dict, stats)."""
    W, H, rule, cull, mb = c["W"], c["H"], c["rule"], c["cull"], c["mb"]
    prims = c["prims"]
    for p in prims:
        p.setup(c["bits"])
    offs = spatial_offsets(c["aa"])
    M = len(offs)
    moving = [p for p in prims if p.moves()]
    shutter = shutter_of(mb)
    o16, c16 = int(shutter[0] * TIME_ONE), int(shutter[1] * TIME_ONE)
    assert shutter[0] * TIME_ONE == o16 and shutter[1] * TIME_ONE == c16
    E = max([p.exp for p in prims] + [pow2_exp(v) for o in offs for v in o] + [1])

    for p in prims:
        p.scale_to(E)
    q_ints = {}

    def test(p, n, t, q, which="alt"):
        """The predicate at tau = n/2^t, on integers (everything times 2^(E + t))."""
        qi = q_ints.get(q)
        if qi is None:
            qi = q_ints[q] = (int(q[0] * 2 ** E), int(q[1] * 2 ** E))
        h = None if p.h_int is None else p.h_int << t
        return p.pred(which, p.at_int(n, t), (qi[0] << t, qi[1] << t), h, rule, cull)

    def static_cov(p, q):
        a = p.pred("main", p.at(0), q, p.h, rule, cull)
        b = p.pred("alt", p.at(0), q, p.h, rule, cull)
        assert a == b, (c["name"], "predicates disagree on a static primitive", q)
        return a

    if not moving:
        # A static scene with effects.motion_blur: samples_covered as in section 6.
        covered = 0
        for y in range(H):
            for x in range(W):
                for ox, oy in offs:
                    q = (x + ox, y + oy)
                    if any(static_cov(p, q) for p in prims):
                        covered += 1
        return {"samples_covered": covered}, {"covered": covered, "moving_pixels": 0}

    span = shutter[1] - shutter[0]
    # --- exact values -------------------------------------------------------
    exact_px = {}
    tcs = {}
    for y in range(H):
        for x in range(W):
            total = Surd()
            for si, (ox, oy) in enumerate(offs):
                q = (x + ox, y + oy)
                for pi, p in enumerate(prims):
                    if not p.moves():
                        if static_cov(p, q):
                            total = total + F(1)
                        continue
                    if not p.touches(q):
                        continue
                    tc = TimeCoverage(p, q, shutter, rule, cull)
                    tcs[(x, y, si, pi)] = tc
                    total = total + time_fraction(tc.length, shutter)
            exact_px[(x, y)] = total.scale(F(1, M))

    # --- the sample method, the motion-ignoring method and the mid-shutter one
    N = mb["samples"]
    est, ign, mid = {}, {}, {}
    agree = 0
    for y in range(H):
        for x in range(W):
            us = pixel_us(mb, y * W + x, M)
            assert len(us) == M * N
            hits = F(0)
            ig = F(0)
            md = F(0)
            for si, (ox, oy) in enumerate(offs):
                q = (x + ox, y + oy)
                for pi, p in enumerate(prims):
                    if not p.moves():
                        if static_cov(p, q):
                            hits += N
                            ig += N
                            md += N
                        continue
                    if not p.touches(q):
                        continue
                    tc = tcs[(x, y, si, pi)]
                    ig += N * test(p, o16 << TIME_BITS, 32, q)
                    md += N * test(p, (o16 + c16) << (TIME_BITS - 1), 32, q)
                    for k in range(N):
                        u = us[si * N + k]
                        n = (o16 << TIME_BITS) + (c16 - o16) * u   # tau * 2^32
                        a = test(p, n, 32, q)
                        b = test(p, n, 32, q, "main")
                        assert a == b, (c["name"], "predicates disagree", x, y, si, pi, n)
                        mem = tc.member(F(n, 1 << 32))
                        assert mem is None or mem == a, (c["name"], "exact coverage disagrees with "
                                                         "the predicate", x, y, si, pi, n)
                        agree += mem is not None
                        hits += a
            est[(x, y)] = hits / (M * N)
            ign[(x, y)] = ig / (M * N)
            mid[(x, y)] = md / (M * N)

    def errors(cand):
        errs = []
        for key, ex in exact_px.items():
            r = ex.rational()
            whole = r is not None and r.denominator == 1
            err = float(cand[key] - ex.approx(120))
            if not whole or cand[key] != r:
                errs.append(err)
        rms = math.sqrt(sum(e * e for e in errs) / len(errs)) if errs else 0.0
        return rms, max((abs(e) for e in errs), default=0.0), len(errs)

    # The variance of the estimate with independent uniform instants: each of
    # the N tests of a moving primitive at a spatial sample is a Bernoulli
    # draw of mean c_P(q).
    var = {}
    for (x, y, si, pi), tc in tcs.items():
        cp = float(time_fraction(tc.length, shutter))
        var[(x, y)] = var.get((x, y), 0.0) + cp * (1 - cp) / (M * M * N)
    rms, mx, n_moving = errors(est)
    ig_rms, ig_max, _ = errors(ign)
    md_rms, md_max, _ = errors(mid)
    T = M * N
    moving_keys = [k for k, v in exact_px.items() if v.rational() is None or
                   v.rational().denominator != 1 or est[k] != v.rational()]
    sigma = math.sqrt(sum(var.get(k, 0.0) for k in moving_keys) / len(moving_keys))
    assert 1.5 * sigma <= 0.75 / math.sqrt(T) + 1e-12
    rms_bound, max_bound = bounds(rms, mx, sigma, T)
    name = c["name"]
    assert rms <= float(rms_bound) and mx <= float(max_bound), name
    assert ig_rms > float(rms_bound), "%s: ignoring motion passes the RMS bound (%.4f <= %s)" % (
        name, ig_rms, float(rms_bound))
    assert c["ignore_max_ok"] or ig_max > float(max_bound), \
        "%s: ignoring motion passes the max bound (%.4f <= %s)" % (name, ig_max, float(max_bound))
    # Drawing at mid-shutter is a better guess than shutter open; with 16 or more
    # tests per pixel it must still fail (with fewer, the estimate is as noisy).
    assert T < 16 or md_rms > float(rms_bound) or md_max > float(max_bound), \
        "%s: drawing at mid-shutter passes both bounds" % name

    # --- pins -----------------------------------------------------------------
    pins = list(c["pins"])
    movers = sorted(k for k, v in exact_px.items()
                    if v.rational() is None or v.rational().denominator != 1)
    irr = [k for k in movers if exact_px[k].rational() is None]
    auto = []
    for pool in (irr, movers):
        if pool:
            for k in (pool[len(pool) // 3], pool[(2 * len(pool)) // 3]):
                if k not in pins and k not in auto:
                    auto.append(k)
    pins += auto[:max(0, 5 - len(pins))]
    assert len(pins) >= 3, name

    # --- brute force: Riemann sums of the second predicate ----------------------
    def riemann(key, K):
        x, y, si, pi = key
        tc = tcs[key]
        p = prims[pi]
        q = (x + offs[si][0], y + offs[si][1])
        lk = K.bit_length() - 1
        assert 1 << lk == K
        t = TIME_BITS + lk + 1
        count = 0
        for i in range(K):
            n = o16 * (2 * K) + (c16 - o16) * (2 * i + 1)   # tau * 2^t
            a = test(p, n, t, q)
            mem = tc.member(F(n, 1 << t))
            assert mem is None or mem == a, (name, "Riemann instant disagrees", key, i)
            count += a
        exact_c = float(time_fraction(tc.length, shutter))
        assert abs(count / K - exact_c) <= (len(tc.events) + 1) / K + 1e-12, \
            (name, "Riemann sum", key, count / K, exact_c)

    pinned = set(pins)
    rest = sorted(k for k in tcs if (k[0], k[1]) not in pinned)
    for key in tcs:
        if (key[0], key[1]) in pinned:
            riemann(key, 4096 if M == 1 else 1024)
    step = max(1, len(rest) // 150)
    for key in rest[::step]:
        riemann(key, 512)

    expect = {"time_coverage": [], "max_time_error": max_bound, "max_time_rms": rms_bound}
    pin_report = []
    for (x, y) in pins:
        v = exact_px[(x, y)]
        r = v.rational()
        if r is not None:
            written = r
            shown = str(r)
        else:
            written = sig15(v.approx(200))
            shown = "%s (irrational; written %s)" % (format_dec(v.approx(200), 40), js(written))
        expect["time_coverage"].append({"pixel": [x, y], "value": written})
        pin_report.append(((x, y), shown))
    stats = dict(prims=prims, moving_pixels=n_moving, rms=rms, sigma=sigma, max=mx,
                 ig_rms=ig_rms, ig_max=ig_max,
                 md_rms=md_rms, md_max=md_max, rms_bound=rms_bound, max_bound=max_bound,
                 pins=pin_report, exact=exact_px, tcs=tcs, est=est, agree=agree, M=M, N=N)
    return expect, stats


def format_dec(q, digits):
    q = F(q)
    s = "-" if q < 0 else ""
    q = abs(q)
    ip = math.floor(q)
    frac = math.floor((q - ip) * 10 ** digits)
    return "%s%d.%0*d" % (s, ip, digits, frac)


def render(c, expect):
    lines = ["{"]
    lines.append('  "name": %s,' % js(c["name"]))
    lines.append('  "description": %s,' % js(c["description"]))
    lines.append('  "canvas": %s,' % js({"width": c["W"], "height": c["H"]}))
    lines.append('  "rules": %s,' % js({"subpixel_bits": c["bits"], "fill_rule": c["rule"],
                                          "cull": c["cull"]}))
    eff = {}
    if c["aa"]:
        eff["antialias"] = c["aa"]
    eff["motion_blur"] = c["mb"]
    lines.append('  "effects": %s,' % js(eff))
    lines.append('  "primitives": [')
    lines.append(",\n".join("    " + js(p.json()) for p in c["prims"]))
    lines.append("  ],")
    if "time_coverage" in expect:
        lines.append('  "expect": {')
        lines.append('    "time_coverage": [')
        lines.append(",\n".join("      " + js(p) for p in expect["time_coverage"]))
        lines.append("    ],")
        lines.append('    "max_time_error": %s,' % js(expect["max_time_error"]))
        lines.append('    "max_time_rms": %s' % js(expect["max_time_rms"]))
        lines.append("  }")
    else:
        lines.append('  "expect": %s' % js(expect))
    lines.append("}")
    return "\n".join(lines) + "\n"
