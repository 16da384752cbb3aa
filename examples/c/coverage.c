/* Exact coverage decisions (coverage.h): integer edge functions for
 * triangles, an integer crossing count for polygons. */
#include "coverage.h"

nudge nudge_of(enum fill_rule rule, int flipped) {
    nudge n = {1, 1}; /* top-left: right by ε, down by ε² */
    if (rule == BOTTOM_RIGHT || rule == TOP_RIGHT) n.dx = -1;
    if (rule == BOTTOM_RIGHT || rule == BOTTOM_LEFT) n.dy = -1;
    if (flipped) {
        n.dx = -n.dx;
        n.dy = -n.dy;
    }
    return n;
}

/* The edge function of a→b at q: (b − a) × (q − a). Inside a clockwise
 * triangle (y down) all three are positive. */
static i128 edge(point a, point b, point q) {
    return (b.x - a.x) * (q.y - a.y) - (b.y - a.y) * (q.x - a.x);
}

i128 doubled_area(const point v[3]) {
    return edge(v[0], v[1], v[2]);
}

int convex_covers(const point *v, int n, point q, enum fill_rule rule, nudge tie) {
    i128 area = edge(v[0], v[1], v[2]);
    int sign = area > 0 ? 1 : -1, i;
    if (area == 0) return 0;
    for (i = 0; i < n; i++) {
        point a = v[i], b = v[(i + 1) % n];
        i128 e = edge(a, b, q) * sign;
        /* The edge function's gradient (∂E/∂x, ∂E/∂y), oriented inwards. */
        i128 gx = -(b.y - a.y) * sign, gy = (b.x - a.x) * sign;
        if (e > 0) continue;
        if (e < 0) return 0;
        /* On the edge: the nudged sample is inside when the nudge goes
         * inwards. Its ε term decides unless the edge is horizontal
         * (gx = 0); then the ε² term does. */
        if (rule == ALL_EDGES) continue;
        if (gx != 0 ? gx * tie.dx < 0 : gy * tie.dy < 0) return 0;
    }
    return 1;
}

int triangle_covers(const point v[3], point q, enum fill_rule rule, nudge tie, enum cull cull) {
    i128 area = doubled_area(v);
    if ((cull == CULL_CW && area > 0) || (cull == CULL_CCW && area < 0)) return 0;
    return convex_covers(v, 3, q, rule, tie);
}

void barycentric(const point v[3], point q, double weights[3]) {
    double area = (double)doubled_area(v);
    /* The weight of a vertex is the edge function of the opposite edge. */
    weights[0] = (double)edge(v[1], v[2], q) / area;
    weights[1] = (double)edge(v[2], v[0], q) / area;
    weights[2] = (double)edge(v[0], v[1], q) / area;
}

/* Whether the edge a→b crosses the ray to +x from q nudged by `tie`:
 * its height range holds the nudged height, and its crossing x_c lies to
 * the right of the nudged point. */
static int crosses(point a, point b, point q, nudge tie) {
    i128 lo = a.y < b.y ? a.y : b.y, hi = a.y < b.y ? b.y : a.y, side;
    if (a.y == b.y) return 0; /* horizontal: never crossed */
    /* Nudged down (dy > 0) the point sits just below q.y: [lo, hi). */
    if (tie.dy > 0 ? !(lo <= q.y && q.y < hi) : !(lo < q.y && q.y <= hi)) return 0;
    /* sign(x_c − q.x) = sign(((a.x − q.x)(b.y − a.y) + (q.y − a.y)(b.x − a.x)) / (b.y − a.y)) */
    side = (a.x - q.x) * (b.y - a.y) + (q.y - a.y) * (b.x - a.x);
    if (b.y < a.y) side = -side;
    /* x_c = q.x: the nudge decides; moved right (dx > 0) it is past x_c. */
    return side > 0 || (side == 0 && tie.dx < 0);
}

long winding_number(const point *points, const int *lengths, int contours, point q, nudge tie) {
    long winding = 0;
    int c, i, start = 0;
    for (c = 0; c < contours; c++) {
        for (i = 0; i < lengths[c]; i++) {
            point a = points[start + i], b = points[start + (i + 1) % lengths[c]];
            if (crosses(a, b, q, tie)) winding += b.y > a.y ? 1 : -1;
        }
        start += lengths[c];
    }
    return winding;
}
