/* Clip space (SPEC.md §16), points (§17) and the rules of §12.10 a request
 * carries for them, for the C example rasterizer: a clip-space triangle
 * clipped exactly in 128-bit rationals (rational.c) under the case's
 * conventions, each piece tested on its snapped vertices by coverage.c or,
 * with a vertex behind the eye, by §16.4's homogeneous edge functions in
 * rationals; the per-sample depth test exact; a point's square against its
 * exact sides. Depth and attributes are doubles, judged within a bound. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "coverage.h"
#include "rational.h"
#include "scene.h"

/* A vertex in clip space: exact (x, y, z, w), its attributes as doubles. */
typedef struct {
    rat c[4];
    double attributes[MAX_ATTRIBUTES];
} clip_vertex;

static enum outcome read_clip_vertex(scene *s, const json *v, const char *path, clip_vertex *out) {
    const json *exact = json_get(json_get(v, "exact"), "clip");
    int i;
    if (json_length(exact) != 4) return fail(s, FAILED, "%s.exact.clip must hold 4 numbers", path);
    for (i = 0; i < 4; i++) {
        const char *why = rat_from_exact(json_string(json_at(exact, (size_t)i), "?"), &out->c[i]);
        if (why) return fail(s, UNSUPPORTED, "%s.exact.clip[%d]: %s", path, i, why);
    }
    for (i = 0; i < s->attributes; i++)
        out->attributes[i] = json_number(json_at(json_get(v, "attributes"), (size_t)i), 0);
    return DRAWN;
}

/* x_f or y_f of SPEC.md §16.1 (axis 0 or 1), exact; w > 0. */
static rat screen(const scene *s, const clip_vertex *v, int axis) {
    rat ndc = rat_div(v->c[axis], v->c[3]), half = {1, 2};
    return rat_add(s->viewport[axis],
                   rat_mul(rat_mul(s->viewport[2 + axis], half), rat_add(ndc, rat_int(1))));
}

/* z_f of SPEC.md §16.1, as a double (depth is judged within a bound). */
static double depth_of(const scene *s, const clip_vertex *v) {
    rat ndc = rat_div(v->c[2], v->c[3]);
    return rat_double(rat_add(s->viewport[4], rat_mul(rat_sub(s->viewport[5], s->viewport[4]), ndc)));
}

/* A projected vertex: snapped (coverage), unsnapped (values, when the case
 * says so), its depth z_f and 1/w. */
typedef struct {
    fx16 x, y;
    double ux, uy, z, inverse_w;
} projected;

static enum outcome project(scene *s, const clip_vertex *v, const char *path, projected *out) {
    rat x, y;
    if (rat_sign(v->c[3]) <= 0)
        return fail(s, FAILED, "%s: a vertex with w <= 0 has no projection", path);
    x = screen(s, v, 0);
    y = screen(s, v, 1);
    if (rat_snap(x, s->bits, &out->x) || rat_snap(y, s->bits, &out->y) || rat_overflow)
        return fail(s, UNSUPPORTED, "%s: a projected position off this program's grid or beyond its "
                    "128-bit arithmetic", path);
    out->ux = rat_double(x);
    out->uy = rat_double(y);
    out->z = depth_of(s, v);
    out->inverse_w = 1 / rat_double(v->c[3]);
    return DRAWN;
}

/* Whether the sample q (2^-16 grid) lies in the viewport rectangle,
 * closed at its left and top, open at its right and bottom (§16.3). */
static int in_viewport(const scene *s, point q) {
    rat qx, qy;
    qx.n = q.x, qx.d = GRID_ONE, qy.n = q.y, qy.d = GRID_ONE;
    return rat_cmp(qx, s->viewport[0]) >= 0 && rat_cmp(qx, rat_add(s->viewport[0], s->viewport[2])) < 0
        && rat_cmp(qy, s->viewport[1]) >= 0 && rat_cmp(qy, rat_add(s->viewport[1], s->viewport[3])) < 0;
}

/* The signed distance of §16.3's plane `k` (near, far, left, right, top,
 * bottom). */
static rat plane_distance(const clip_vertex *v, int k) {
    switch (k) {
    case 0: return v->c[2];
    case 1: return rat_sub(v->c[3], v->c[2]);
    case 2: return rat_add(v->c[3], v->c[0]);
    case 3: return rat_sub(v->c[3], v->c[0]);
    case 4: return rat_add(v->c[3], v->c[1]);
    default: return rat_sub(v->c[3], v->c[1]);
    }
}

#define MAX_CLIPPED 9

/* Sutherland–Hodgman against one plane, exact (§16.3). */
static int clip_polygon(const scene *s, const clip_vertex *in, int n, int k, clip_vertex *out) {
    int i, m = 0, a;
    for (i = 0; i < n; i++) {
        const clip_vertex *p = &in[i], *q = &in[(i + 1) % n];
        rat dp = plane_distance(p, k), dq = plane_distance(q, k);
        if (rat_sign(dp) >= 0) out[m++] = *p;
        if (rat_sign(dp) * rat_sign(dq) < 0) {
            rat t = rat_div(dp, rat_sub(dp, dq));
            double td = rat_double(t);
            clip_vertex *v = &out[m++];
            for (a = 0; a < 4; a++) v->c[a] = rat_add(p->c[a], rat_mul(t, rat_sub(q->c[a], p->c[a])));
            for (a = 0; a < s->attributes; a++)
                v->attributes[a] = p->attributes[a] + td * (q->attributes[a] - p->attributes[a]);
        }
    }
    return m;
}

/* A homogeneous screen point of §16.4, H = (x, y, w), and its weight k. */
typedef struct {
    rat x, y, w, k;
} hpoint;

/* H of a clip-space vertex (§16.4): for w > 0 its snapped (or, with
 * `unsnapped`, its exact) position with weight 1/w; for w <= 0 the exact
 * homogeneous point, weight 1. */
static enum outcome homogeneous(scene *s, const clip_vertex *v, int unsnapped, const char *path,
                                hpoint *h) {
    rat half = {1, 2}, w = v->c[3];
    if (rat_sign(w) > 0) {
        rat x = screen(s, v, 0), y = screen(s, v, 1);
        if (!unsnapped && s->bits >= 0) {
            fx16 sx, sy;
            if (rat_snap(x, s->bits, &sx) || rat_snap(y, s->bits, &sy))
                return fail(s, UNSUPPORTED, "%s: a projected position off this program's grid or "
                            "beyond its 128-bit arithmetic", path);
            x = rat_frac(sx.v, GRID_ONE);
            y = rat_frac(sy.v, GRID_ONE);
        }
        h->x = x, h->y = y, h->w = rat_int(1), h->k = rat_div(rat_int(1), w);
    } else {
        h->x = rat_add(rat_mul(w, s->viewport[0]),
                       rat_mul(rat_mul(s->viewport[2], half), rat_add(w, v->c[0])));
        h->y = rat_add(rat_mul(w, s->viewport[1]),
                       rat_mul(rat_mul(s->viewport[3], half), rat_add(w, v->c[1])));
        h->w = w, h->k = rat_int(1);
    }
    return rat_overflow ? fail(s, UNSUPPORTED, "%s: beyond this program's 128-bit arithmetic", path)
                        : DRAWN;
}

/* The edge functions E_i(q) = det[H_(i+1), H_(i+2), S] of §16.4 and D, as
 * a·s_x + b·s_y + c. */
typedef struct {
    rat a[3], b[3], c[3], d;
} edges;

static edges edges_of(const hpoint h[3]) {
    edges e;
    int i;
    for (i = 0; i < 3; i++) {
        const hpoint *j = &h[(i + 1) % 3], *l = &h[(i + 2) % 3];
        e.a[i] = rat_sub(rat_mul(j->y, l->w), rat_mul(j->w, l->y));
        e.b[i] = rat_sub(rat_mul(j->w, l->x), rat_mul(j->x, l->w));
        e.c[i] = rat_sub(rat_mul(j->x, l->y), rat_mul(j->y, l->x));
    }
    e.d = rat_add(rat_add(rat_mul(e.a[0], h[0].x), rat_mul(e.b[0], h[0].y)), rat_mul(e.c[0], h[0].w));
    return e;
}

static rat edge_at(const edges *e, int i, rat sx, rat sy) {
    return rat_add(rat_add(rat_mul(e->a[i], sx), rat_mul(e->b[i], sy)), e->c[i]);
}

/* §16.4's test: every σ·E_i > 0, or 0 on an edge the fill rule owns. */
static int homogeneous_covers(const scene *s, const edges *e, rat sx, rat sy, rat value[3]) {
    int sigma = rat_sign(e->d), i;
    if (sigma == 0) return 0;
    for (i = 0; i < 3; i++) {
        int sign, a, b, left, right, top, bottom;
        value[i] = edge_at(e, i, sx, sy);
        sign = sigma * rat_sign(value[i]);
        if (sign > 0) continue;
        if (sign < 0) return 0;
        a = sigma * rat_sign(e->a[i]);
        b = sigma * rat_sign(e->b[i]);
        left = a > 0, right = a < 0, top = a == 0 && b > 0, bottom = a == 0 && b < 0;
        switch (s->rule) {
        case TOP_LEFT: if (!(left || top)) return 0; break;
        case BOTTOM_RIGHT: if (!(right || bottom)) return 0; break;
        case TOP_RIGHT: if (!(right || top)) return 0; break;
        case BOTTOM_LEFT: if (!(left || bottom)) return 0; break;
        case ALL_EDGES: if (!(left || right || top || bottom)) return 0; break;
        }
    }
    return 1;
}

/* Σ E_i·k_i·z_i (the depth's numerator over D) and Σ E_i·k_i, exact. */
static void weighted(const clip_vertex *cv, const hpoint h[3], const rat value[3], rat *z, rat *k) {
    int i;
    *z = rat_int(0), *k = rat_int(0);
    for (i = 0; i < 3; i++) {
        rat ek = rat_mul(value[i], h[i].k);
        *z = rat_add(*z, rat_mul(ek, cv[i].c[2]));
        *k = rat_add(*k, ek);
    }
}

/* One piece of a clip-space triangle (§16.4), its values from the
 * positions `rules.interpolate_from` names (§16.5); `flat` the original's
 * provoking values, or NULL. A piece whose vertices all have w > 0 is
 * tested by coverage.c on its snapped vertices and shaded in doubles; one
 * with a vertex behind the eye, and every per-sample depth test, in exact
 * rationals. */
static enum outcome draw_piece(buffer *out, scene *s, const clip_vertex *cv, const char *path,
                               const double *flat, int *first) {
    projected pr[3];
    point p[3];
    vertex corners[3];
    hpoint hs[3], hu[3];
    edges es, eu;
    double ux[3], uy[3], uz[3], dzdx, dzdy, largest = 0, area = 0;
    box b;
    int i, x, y, k, a, ahead = 1, exact;
    enum outcome o;
    /* `ahead`: every w > 0 and the vertices snapped, for coverage.c. */
    for (i = 0; i < 3; i++) ahead = ahead && rat_sign(cv[i].c[3]) > 0;
    if (s->bits < 0 && ahead && s->has_bias)
        return fail(s, UNSUPPORTED, "%s: polygon offset at exact coordinates is not implemented", path);
    ahead = ahead && s->bits >= 0;
    exact = !ahead || s->per_sample_z;
    if (exact) {
        for (i = 0; i < 3; i++) {
            if ((o = homogeneous(s, &cv[i], 0, path, &hs[i])) != DRAWN) return o;
            if ((o = homogeneous(s, &cv[i], 1, path, &hu[i])) != DRAWN) return o;
        }
        es = edges_of(hs);
        eu = edges_of(hu);
        if (rat_overflow)
            return fail(s, UNSUPPORTED, "%s: beyond this program's 128-bit arithmetic", path);
    }
    if (ahead) {
        for (i = 0; i < 3; i++) {
            if ((o = project(s, &cv[i], path, &pr[i])) != DRAWN) return o;
            p[i] = still(pr[i].x, pr[i].y);
            corners[i].x = corners[i].tx = pr[i].x;
            corners[i].y = corners[i].ty = pr[i].y;
            ux[i] = s->unsnapped ? pr[i].ux : (double)pr[i].x.v / GRID_ONE;
            uy[i] = s->unsnapped ? pr[i].uy : (double)pr[i].y.v / GRID_ONE;
            uz[i] = pr[i].z;
            if (fabs(uz[i]) > largest) largest = fabs(uz[i]);
        }
        area = (ux[1] - ux[0]) * (uy[2] - uy[0]) - (ux[2] - ux[0]) * (uy[1] - uy[0]);
        gradient(ux, uy, uz, &dzdx, &dzdy);
        s->offset = polygon_offset(s, dzdx, dzdy, largest);
        b = bounds(s, corners, 3);
    } else {
        if (s->has_bias && s->bits >= 0)
            return fail(s, FAILED, "%s: an offset with a vertex behind the eye", path);
        s->offset = 0;
        b.x0 = 0, b.y0 = 0, b.x1 = s->width - 1, b.y1 = s->height - 1;
    }
    for (y = b.y0; y <= b.y1; y++)
        for (x = b.x0; x <= b.x1; x++)
            for (k = 0; k < s->samples; k++) {
                point q = sample_at(s, x, y, k);
                double sx = (double)q.x / GRID_ONE, sy = (double)q.y / GRID_ONE, wgt[3], z = 0, den;
                rat rx = rat_frac(q.x, GRID_ONE), ry = rat_frac(q.y, GRID_ONE), vs[3], vu[3];
                const edges *ev = &es;
                const rat *values_at = vs;
                if (ahead ? !triangle_covers(p, q, s->rule, s->tie, CULL_NONE)
                          : !homogeneous_covers(s, &es, rx, ry, vs))
                    continue;
                if (!s->clip_xy && !in_viewport(s, q)) continue;
                if (exact) {
                    rat zsum, ksum;
                    if (ahead) homogeneous_covers(s, &es, rx, ry, vs); /* E_i at q */
                    if (s->unsnapped && rat_sign(eu.d) != 0) {
                        for (i = 0; i < 3; i++) vu[i] = edge_at(&eu, i, rx, ry);
                        weighted(cv, hu, vu, &zsum, &ksum);
                        if (rat_sign(ksum) * rat_sign(eu.d) > 0) ev = &eu, values_at = vu;
                    }
                    weighted(cv, ev == &eu ? hu : hs, values_at, &zsum, &ksum);
                    if (rat_overflow)
                        return fail(s, UNSUPPORTED, "%s: beyond this program's 128-bit arithmetic", path);
                    if (s->per_sample_z) {
                        rat zn = rat_div(zsum, ev->d);
                        if (rat_sign(zn) < 0 || rat_cmp(zn, rat_int(1)) > 0) continue;
                    }
                    if (!ahead) {
                        /* Values from the exact edge functions, in doubles. */
                        double e[3], kk[3], dd = rat_double(ev->d), sum = 0;
                        const hpoint *h = ev == &eu ? hu : hs;
                        for (i = 0; i < 3; i++) {
                            e[i] = rat_double(values_at[i]);
                            kk[i] = rat_double(h[i].k);
                            z += e[i] * kk[i] * rat_double(cv[i].c[2]) / dd;
                            sum += e[i] * kk[i];
                        }
                        for (i = 0; i < 3; i++) wgt[i] = e[i] * kk[i] / sum;
                        z = rat_double(s->viewport[4])
                          + rat_double(rat_sub(s->viewport[5], s->viewport[4])) * z;
                        goto write;
                    }
                }
                for (i = 0; i < 3; i++) {
                    int j = (i + 1) % 3, l = (i + 2) % 3;
                    wgt[i] = ((ux[l] - ux[j]) * (sy - uy[j]) - (uy[l] - uy[j]) * (sx - ux[j])) / area;
                    z += wgt[i] * uz[i];
                }
                /* Perspective weights: barycentric over w, normalised. */
                den = 0;
                for (i = 0; i < 3; i++) den += wgt[i] * pr[i].inverse_w;
                for (i = 0; i < 3; i++) wgt[i] = wgt[i] * pr[i].inverse_w / den;
            write:
                z = z < s->depth_low ? s->depth_low : z > s->depth_high ? s->depth_high : z;
                open_fragment(out, first, x, y, s->antialiased ? k : -1);
                if (s->depth) emit_depth(out, s, z);
                for (a = 0; a < s->attributes; a++) {
                    double v = 0;
                    if (flat) {
                        v = flat[a];
                    } else {
                        for (i = 0; i < 3; i++) v += wgt[i] * cv[i].attributes[a];
                    }
                    buffer_printf(out, ",%.17g", v);
                }
                buffer_printf(out, "]");
            }
    return DRAWN;
}

enum outcome draw_clip_triangle(buffer *out, scene *s, const json *triangle, const char *path,
                                       enum interpolation mode) {
    clip_vertex poly[2][MAX_CLIPPED];
    const double *flat = NULL;
    int n = 3, i, k, cur = 0, first = 1;
    int clipped[6];
    enum outcome o;
    if (mode == LINEAR) return fail(s, FAILED, "%s: linear interpolation in clip space", path);
    for (i = 0; i < 3; i++) {
        char at[160];
        snprintf(at, sizeof at, "%s.triangle[%d]", path, i);
        if ((o = read_clip_vertex(s, json_at(triangle, (size_t)i), at, &poly[0][i])) != DRAWN) return o;
    }
    /* Cull reads the original triangle's winding (§16.4): clockwise when
     * D > 0 for its vertices put as homogeneous points. */
    if (s->cull != CULL_NONE) {
        hpoint h[3];
        edges e;
        int sign;
        for (i = 0; i < 3; i++)
            if ((o = homogeneous(s, &poly[0][i], 0, path, &h[i])) != DRAWN) return o;
        e = edges_of(h);
        sign = rat_sign(e.d);
        if (rat_overflow)
            return fail(s, UNSUPPORTED, "%s: beyond this program's 128-bit arithmetic", path);
        if ((s->cull == CULL_CW && sign > 0) || (s->cull == CULL_CCW && sign < 0)) return DRAWN;
    }
    if (mode == FLAT) {
        static double provoking[MAX_ATTRIBUTES];
        memcpy(provoking, poly[0][s->last_provokes ? 2 : 0].attributes, sizeof provoking);
        flat = provoking;
    }
    clipped[0] = clipped[1] = !s->depth_clamp && !s->per_sample_z;
    clipped[2] = clipped[3] = clipped[4] = clipped[5] = s->clip_xy;
    for (k = 0; k < 6; k++)
        if (clipped[k]) {
            n = clip_polygon(s, poly[cur], n, k, poly[1 - cur]);
            cur = 1 - cur;
            if (n < 3) return DRAWN;
        }
    if (rat_overflow)
        return fail(s, UNSUPPORTED, "%s: clipping goes beyond this program's 128-bit arithmetic", path);
    for (i = 1; i + 1 < n; i++) {
        clip_vertex fan[3];
        fan[0] = poly[cur][0];
        fan[1] = poly[cur][i];
        fan[2] = poly[cur][i + 1];
        if ((o = draw_piece(out, s, fan, path, flat, &first)) != DRAWN) return o;
    }
    return DRAWN;
}

/* Whether c − X (2^-16 units) lies within [−size/2, size/2], size = n/d,
 * with each side closed or open as the fill rule owns it (§17.1):
 * 2·(c − X)·d against ±n·2^16, exact. */
static int in_side(i128 delta, rat size, int low_closed, int high_closed) {
    i128 d2 = 2 * delta * size.d, half = size.n * GRID_ONE;
    return (low_closed ? d2 >= -half : d2 > -half) && (high_closed ? d2 <= half : d2 < half);
}

/* A point (§17): the square of side `size` around its snapped centre. */
enum outcome draw_point(buffer *out, scene *s, const json *prim, const char *path) {
    const json *pv = json_get(prim, "point");
    fx16 cx, cy, reach;
    rat size;
    double z, attributes[MAX_ATTRIBUTES];
    int x, y, k, a, first = 1, x0, x1, y0, y1;
    int left = 1, right = 0, top = 1, bottom = 0;
    char at[160];
    enum outcome o;
    const char *why = rat_from_exact(json_string(json_get(json_get(prim, "exact"), "size"), "?"), &size);
    if (why || rat_sign(size) <= 0 || rat_cmp(size, rat_int(4096)) > 0)
        return fail(s, FAILED, "%s.exact.size must be a size in (0, 4096]", path);
    reach.v = (int64_t)(size.n * GRID_ONE / size.d) + 1;
    if (s->clip_space) {
        clip_vertex v;
        projected pr;
        int i;
        snprintf(at, sizeof at, "%s.point", path);
        if ((o = read_clip_vertex(s, pv, at, &v)) != DRAWN) return o;
        if (rat_sign(v.c[3]) <= 0) return DRAWN;
        if (!s->depth_clamp && (rat_sign(v.c[2]) < 0 || rat_cmp(v.c[2], v.c[3]) > 0)) return DRAWN;
        for (i = 0; i < 2 && s->pop_points; i++)
            if (rat_sign(rat_add(v.c[3], v.c[i])) < 0 || rat_sign(rat_sub(v.c[3], v.c[i])) < 0)
                return DRAWN;
        if ((o = project(s, &v, at, &pr)) != DRAWN) return o;
        cx = pr.x, cy = pr.y;
        z = pr.z < s->depth_low ? s->depth_low : pr.z > s->depth_high ? s->depth_high : pr.z;
        memcpy(attributes, v.attributes, sizeof attributes);
    } else {
        vertex v;
        snprintf(at, sizeof at, "%s.point", path);
        if ((o = read_vertex(s, pv, at, &v)) != DRAWN) return o;
        cx = v.x, cy = v.y, z = v.z;
        memcpy(attributes, v.attributes, sizeof attributes);
    }
    switch (s->rule) {
    case TOP_LEFT: break;
    case BOTTOM_RIGHT: left = 0, right = 1, top = 0, bottom = 1; break;
    case TOP_RIGHT: left = 0, right = 1; break;
    case BOTTOM_LEFT: top = 0, bottom = 1; break;
    case ALL_EDGES: left = right = top = bottom = 1; break;
    }
    s->offset = 0; /* never offset: a point is no polygon */
    x0 = floor_pixel(cx.v - reach.v) - 1, x1 = floor_pixel(cx.v + reach.v) + 1;
    y0 = floor_pixel(cy.v - reach.v) - 1, y1 = floor_pixel(cy.v + reach.v) + 1;
    if (x0 < 0) x0 = 0;
    if (y0 < 0) y0 = 0;
    if (x1 > s->width - 1) x1 = s->width - 1;
    if (y1 > s->height - 1) y1 = s->height - 1;
    for (y = y0; y <= y1; y++)
        for (x = x0; x <= x1; x++)
            for (k = 0; k < s->samples; k++) {
                point q = sample_at(s, x, y, k);
                if (!in_side(q.x - cx.v, size, left, right)) continue;
                if (!in_side(q.y - cy.v, size, top, bottom)) continue;
                if (s->clip_space && s->bounds_viewport && !in_viewport(s, q)) continue;
                open_fragment(out, &first, x, y, s->antialiased ? k : -1);
                if (s->depth) emit_depth(out, s, z);
                for (a = 0; a < s->attributes; a++) buffer_printf(out, ",%.17g", attributes[a]);
                buffer_printf(out, "]");
            }
    return DRAWN;
}

/* The rules of SPEC.md §12.10: the depth format, the offset and, in clip
 * space, the viewport and the clip conventions. */
enum outcome read_depth_and_clip(scene *s, const json *request) {
    const json *rules = json_get(request, "rules"), *bias = json_get(rules, "depth_bias");
    const json *viewport = json_get(request, "viewport");
    const char *format = json_string(json_get(rules, "depth_format"), "exact");
    static const char *const KEYS[6] = {"x", "y", "width", "height", "min_depth", "max_depth"};
    int i;
    rat_overflow = 0;
    s->depth_format = strcmp(format, "unorm16") == 0 ? 16 : strcmp(format, "unorm24") == 0 ? 24
                    : strcmp(format, "float32") == 0 ? 32 : 0;
    if (s->depth_format == 0 && strcmp(format, "exact") != 0)
        return fail(s, UNSUPPORTED, "$.rules.depth_format %s is not known to this program", format);
    s->has_bias = bias != NULL;
    s->bias_constant = json_number(json_get(bias, "constant"), 0);
    s->bias_slope = json_number(json_get(bias, "slope"), 0);
    s->bias_clamp = json_number(json_get(bias, "clamp"), 0);
    s->clip_space = viewport != NULL;
    s->depth_low = -HUGE_VAL, s->depth_high = HUGE_VAL;
    if (!viewport) return DRAWN;
    for (i = 0; i < 6; i++) {
        const char *why = rat_from_exact(json_string(json_get(json_get(viewport, "exact"), KEYS[i]), "?"),
                                         &s->viewport[i]);
        if (why) return fail(s, UNSUPPORTED, "$.viewport.exact.%s: %s", KEYS[i], why);
    }
    s->depth_low = rat_double(s->viewport[4]);
    s->depth_high = rat_double(s->viewport[5]);
    if (s->depth_low > s->depth_high) {
        double t = s->depth_low;
        s->depth_low = s->depth_high, s->depth_high = t;
    }
    s->clip_xy = strcmp(json_string(json_get(rules, "clip_xy"), "guard-band"), "clip-then-snap") == 0;
    s->depth_clamp = strcmp(json_string(json_get(rules, "depth"), "clip"), "clamp") == 0;
    s->per_sample_z = !s->depth_clamp
                   && strcmp(json_string(json_get(rules, "clip_z"), "clip-then-snap"), "per-sample") == 0;
    s->unsnapped = strcmp(json_string(json_get(rules, "interpolate_from"), "snapped"), "unsnapped") == 0;
    s->pop_points = strcmp(json_string(json_get(rules, "clip_points"), "pop"), "pop") == 0;
    s->bounds_viewport = strcmp(json_string(json_get(rules, "point_bounds"), "canvas"), "viewport") == 0;
    return DRAWN;
}
