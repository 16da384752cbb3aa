"""The per-instant predicates: does a triangle or a parallelogram line cover a
sample at one instant? Two independent formulations of the same rule (the
edge functions with the fill rule's nudge and cull; the crossing-count
winding number of the nudged sample), cross-checked by evaluate().
"""

# The per-instant predicates. Two independent formulations of the same rule;
# each works on Fractions or on integers (all coordinates scaled by one
# positive power of two: every test below is homogeneous, so its sign is
# unchanged).

NUDGE = {"top-left": (1, 1), "bottom-right": (-1, -1), "top-right": (-1, 1), "bottom-left": (1, -1)}


def nudged_positive(f, gx, gy, rule):
    """Whether the linear function with value f and gradient (gx, gy) at the
    sample is positive at the sample nudged as the fill rule says
    (x + nx*eps, y + ny*eps^2), eps infinitesimal."""
    if f != 0:
        return f > 0
    nx, ny = NUDGE[rule]
    v = gx * nx
    if v != 0:
        return v > 0
    return gy * ny > 0


def area2(pts):
    """Twice the signed area, positive for clockwise on screen (y down)."""
    n = len(pts)
    return sum(pts[i][0] * pts[(i + 1) % n][1] - pts[(i + 1) % n][0] * pts[i][1] for i in range(n))


def convex_main(pts, q, rule):
    """Section 3 by edge functions: the sample is inside every edge, and an
    edge it lies on owns it (the nudge)."""
    A = area2(pts)
    if A == 0:
        return False
    sg = 1 if A > 0 else -1
    qx, qy = q
    n = len(pts)
    for i in range(n):
        (ax, ay), (bx, by) = pts[i], pts[(i + 1) % n]
        e = ((bx - ax) * (qy - ay) - (by - ay) * (qx - ax)) * sg
        if e == 0:
            assert (ax, ay) != (bx, by)
        if not nudged_positive(e, -(by - ay) * sg, (bx - ax) * sg, rule):
            return False
    return True


def culled(A, cull):
    return (cull == "cw" and A > 0) or (cull == "ccw" and A < 0)


def tri_main(pts, q, rule, cull):
    A = area2(pts)
    if A == 0 or culled(A, cull):
        return False
    return convex_main(pts, q, rule)


def line_quads(p0, p1, h):
    """The parallelogram of section 4.4 as a quadrilateral, for the major
    axis of p1 - p0, or None for a zero-length line."""
    (x0, y0), (x1, y1) = p0, p1
    dx, dy = x1 - x0, y1 - y0
    if dx == 0 and dy == 0:
        return None
    if abs(dx) >= abs(dy):
        return [(x0, y0 - h), (x1, y1 - h), (x1, y1 + h), (x0, y0 + h)]
    return [(x0 - h, y0), (x1 - h, y1), (x1 + h, y1), (x0 + h, y0)]


def line_main(p0, p1, h, q, rule):
    quad = line_quads(p0, p1, h)
    return quad is not None and convex_main(quad, q, rule)


def winding_nudged(pts, q, rule):
    """Section 14.1: the winding number of the nudged sample, by counting
    directed crossings of the nudged horizontal ray to +x."""
    top = rule in ("top-left", "top-right")
    left = rule in ("top-left", "bottom-left")
    qx, qy = q
    w = 0
    n = len(pts)
    for i in range(n):
        (ax, ay), (bx, by) = pts[i], pts[(i + 1) % n]
        if ay == by:
            continue
        lo, hi = min(ay, by), max(ay, by)
        if not ((lo <= qy < hi) if top else (lo < qy <= hi)):
            continue
        # sign(x_c - qx), x_c the crossing's x at height qy, without dividing.
        num = (ax - qx) * (by - ay) + (qy - ay) * (bx - ax)
        s = num if by > ay else -num
        if (s > 0) if left else (s >= 0):
            w += 1 if by > ay else -1
    return w


def tri_alt(pts, q, rule, cull):
    (x0, y0), (x1, y1), (x2, y2) = pts
    A = (x1 - x0) * (y2 - y0) - (y1 - y0) * (x2 - x0)
    if A == 0 or culled(A, cull):
        return False
    return winding_nudged(pts, q, rule) != 0


def line_alt(p0, p1, h, q, rule):
    """Section 4.4 as written: between the ends along the major axis, and
    within width/2 of the line along the minor axis (scaled by |d_major| to
    stay polynomial); a border sample by the nudge."""
    (x0, y0), (x1, y1) = p0, p1
    qx, qy = q
    dx, dy = x1 - x0, y1 - y0
    if dx == 0 and dy == 0:
        return False
    if abs(dx) >= abs(dy):
        s, m = (1 if dx > 0 else -1), abs(dx)
        g = (qy - y0) * m - (qx - x0) * dy * s
        fs = [((qx - x0) * s, s, 0), ((x1 - qx) * s, -s, 0),
              (h * m - g, dy * s, -m), (h * m + g, -dy * s, m)]
    else:
        s, m = (1 if dy > 0 else -1), abs(dy)
        g = (qx - x0) * m - (qy - y0) * dx * s
        fs = [((qy - y0) * s, 0, s), ((y1 - qy) * s, 0, -s),
              (h * m - g, -m, dx * s), (h * m + g, m, -dx * s)]
    return all(nudged_positive(f, gx, gy, rule) for f, gx, gy in fs)


def quad_alt(pts, q, rule):
    return area2(pts) != 0 and winding_nudged(pts, q, rule) != 0


