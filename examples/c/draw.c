/* Drawing a request (draw.h): bounding-box traversal, an exact coverage
 * test per sample (coverage.c), depth and attributes interpolated in
 * doubles at the covered samples (SPEC.md §5), depth stored in the case's
 * format (§18); clip space and points are clip.c's. */
#include "draw.h"

#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "coverage.h"
#include "fixed.h"
#include "rational.h"
#include "scene.h"

static const char *const INTERPOLATIONS[] = {"flat", "linear", "perspective"};

/* Sets the message; returns `outcome` so callers can `return fail(...)`. */
enum outcome fail(scene *s, enum outcome outcome, const char *format, ...) {
    va_list args;
    va_start(args, format);
    vsnprintf(s->why, s->why_size, format, args);
    va_end(args);
    return outcome;
}

static int word_index(const char *word, const char *const *words, int count) {
    int i;
    for (i = 0; word && i < count; i++)
        if (strcmp(word, words[i]) == 0) return i;
    return -1;
}

/* Reads a coordinate's exact spelling at `path` and snaps it. */
static enum outcome coordinate(scene *s, const json *exact, const char *path, int bits, fx16 *out) {
    const char *spelling = json_string(exact, NULL), *why;
    if (!spelling) return fail(s, FAILED, "%s must be an exact number (a string)", path);
    why = fx16_from_exact(spelling, bits, out);
    if (why) return fail(s, UNSUPPORTED, "%s: %s", path, why);
    return DRAWN;
}

enum outcome read_vertex(scene *s, const json *v, const char *path, vertex *out) {
    const json *exact = json_get(v, "exact"), *to = json_get(json_get(exact, "to"), "x");
    char at[160];
    size_t k;
    enum outcome o;
    snprintf(at, sizeof at, "%s.exact.x", path);
    if ((o = coordinate(s, json_get(exact, "x"), at, s->bits, &out->x)) != DRAWN) return o;
    snprintf(at, sizeof at, "%s.exact.y", path);
    if ((o = coordinate(s, json_get(exact, "y"), at, s->bits, &out->y)) != DRAWN) return o;
    out->tx = out->x;
    out->ty = out->y;
    if (to) {
        snprintf(at, sizeof at, "%s.exact.to.x", path);
        if ((o = coordinate(s, to, at, s->bits, &out->tx)) != DRAWN) return o;
        snprintf(at, sizeof at, "%s.exact.to.y", path);
        if ((o = coordinate(s, json_get(json_get(exact, "to"), "y"), at, s->bits, &out->ty)) != DRAWN)
            return o;
    }
    out->z = json_number(json_get(v, "z"), 0);
    out->w = json_number(json_get(v, "w"), 1);
    for (k = 0; k < (size_t)s->attributes && k < MAX_ATTRIBUTES; k++)
        out->attributes[k] = json_number(json_at(json_get(v, "attributes"), k), 0);
    return DRAWN;
}

/* A still position on the 2^-16 grid. */
point still(fx16 x, fx16 y) {
    point p;
    p.x = x.v;
    p.y = y.v;
    return p;
}

/* Where a moving vertex is at instant T (units of 2^-32 of the shutter's
 * unit interval), on the 2^-48 grid: (1 − τ)·from + τ·to, τ = T/2^32,
 * times 2^32 is from·2^32 + (to − from)·T. Exact, never snapped again
 * (SPEC.md §15.1). */
static point moving(const vertex *v, i128 t) {
    point p;
    p.x = (i128)v->x.v * INSTANT_ONE + (i128)(v->tx.v - v->x.v) * t;
    p.y = (i128)v->y.v * INSTANT_ONE + (i128)(v->ty.v - v->y.v) * t;
    return p;
}

/* The sample s of pixel (x, y) on the 2^-16 grid. */
point sample_at(const scene *s, int x, int y, int k) {
    point q;
    q.x = (i128)x * GRID_ONE + s->offsets[k][0].v;
    q.y = (i128)y * GRID_ONE + s->offsets[k][1].v;
    return q;
}

/* The pixel column (or row) holding a 2^-16 position, held to [-1, 2^20]. */
int floor_pixel(int64_t v) {
    int64_t p = v >= 0 ? v / GRID_ONE : -((-v + GRID_ONE - 1) / GRID_ONE);
    return p < -1 ? -1 : p > 1 << 20 ? 1 << 20 : (int)p;
}

box bounds(const scene *s, const vertex *v, int count) {
    box b = {1 << 20, 1 << 20, -1, -1};
    int i, k;
    for (i = 0; i < count; i++) {
        fx16 xs[2] = {v[i].x, v[i].tx}, ys[2] = {v[i].y, v[i].ty};
        for (k = 0; k < 2; k++) {
            int px = floor_pixel(xs[k].v), py = floor_pixel(ys[k].v);
            if (px < b.x0) b.x0 = px;
            if (px > b.x1) b.x1 = px;
            if (py < b.y0) b.y0 = py;
            if (py > b.y1) b.y1 = py;
        }
    }
    if (b.x0 < 0) b.x0 = 0;
    if (b.y0 < 0) b.y0 = 0;
    if (b.x1 > s->width - 1) b.x1 = s->width - 1;
    if (b.y1 > s->height - 1) b.y1 = s->height - 1;
    return b;
}

/* A depth as the format stores it (SPEC.md §18.1, §12.10), after the
 * primitive's offset: clamped to [0, 1] and, under unorm n, the nearest
 * k/(2^n − 1) given as k; under float32 its nearest f32. */
void emit_depth(buffer *out, const scene *s, double z) {
    if (s->depth_format == 0) {
        buffer_printf(out, ",%.17g", z);
        return;
    }
    z += s->offset;
    z = z < 0 ? 0 : z > 1 ? 1 : z;
    if (s->depth_format == 32) buffer_printf(out, ",%.9g", (double)(float)z);
    else buffer_printf(out, ",%.0f", floor(z * (double)((1L << s->depth_format) - 1) + 0.5));
}

/* The polygon offset of a triangle whose depth plane has the gradient
 * (dzdx, dzdy) on the screen and whose largest |depth| is `largest`
 * (SPEC.md §18.2): o = m·slope + r·constant, clamped. The specifications
 * let m be anything from max(|dzdx|, |dzdy|) to the gradient's length,
 * and r anything in a range of the format's; this takes the middle of
 * each, so that the rounding of doubles never leaves the allowed set. */
double polygon_offset(const scene *s, double dzdx, double dzdy, double largest) {
    double ax = fabs(dzdx), ay = fabs(dzdy), m, r, o;
    int e;
    if (!s->has_bias || s->ignore_offset) return 0;
    m = ((ax > ay ? ax : ay) + sqrt(ax * ax + ay * ay)) / 2;
    if (s->depth_format == 32) {
        frexp(largest, &e); /* largest = f·2^e, f in [0.5, 1): exponent e − 1 */
        e = largest == 0 || e - 1 < -126 ? -126 : e - 1;
        r = 1.5 * ldexp(1, e - 23);
    } else {
        r = 1.5 * ldexp(1, -s->depth_format);
    }
    o = m * s->bias_slope + r * s->bias_constant;
    if (s->bias_clamp > 0 && o > s->bias_clamp) o = s->bias_clamp;
    if (s->bias_clamp < 0 && o < s->bias_clamp) o = s->bias_clamp;
    return o;
}

/* The gradient of the plane through three (x, y, z) on the screen. */
void gradient(const double x[3], const double y[3], const double z[3], double *dzdx,
                     double *dzdy) {
    double area = (x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0]);
    if (area == 0) {
        *dzdx = *dzdy = 0;
        return;
    }
    *dzdx = ((z[1] - z[0]) * (y[2] - y[0]) - (z[2] - z[0]) * (y[1] - y[0])) / area;
    *dzdy = ((x[1] - x[0]) * (z[2] - z[0]) - (x[2] - x[0]) * (z[1] - z[0])) / area;
}

/* Depth and attributes at weights `b` of the n vertices `v` (SPEC.md
 * §5: barycentric for a triangle, (1 − t, t) along a line), appended to a
 * fragment. */
static void values(buffer *out, const scene *s, const vertex *v, int n, enum interpolation mode,
                   const double *b) {
    int i, k;
    double z = 0;
    for (i = 0; i < n; i++) z += b[i] * v[i].z;
    if (s->depth) emit_depth(out, s, z);
    for (k = 0; k < s->attributes; k++) {
        double a = 0, den = 0;
        if (mode == FLAT) {
            a = v[s->last_provokes ? n - 1 : 0].attributes[k];
        } else if (mode == LINEAR) {
            for (i = 0; i < n; i++) a += b[i] * v[i].attributes[k];
        } else { /* interpolate a/w and 1/w linearly, then divide */
            for (i = 0; i < n; i++) {
                a += b[i] * v[i].attributes[k] / v[i].w;
                den += b[i] / v[i].w;
            }
            a /= den;
        }
        buffer_printf(out, ",%.17g", a);
    }
}

/* Appends "[x,y" (and ",slot" when the answer names slots); the caller
 * closes it. `first` tracks the list's commas. */
void open_fragment(buffer *out, int *first, int x, int y, int slot) {
    buffer_printf(out, *first ? "[%d,%d" : ",[%d,%d", x, y);
    if (slot >= 0) buffer_printf(out, ",%d", slot);
    *first = 0;
}

static void draw_still_triangle(buffer *out, scene *s, const vertex v[3],
                                enum interpolation mode) {
    point p[3];
    box b = bounds(s, v, 3);
    int x, y, k, first = 1, i;
    double px[3], py[3], pz[3], dzdx, dzdy, largest = 0;
    for (i = 0; i < 3; i++) {
        p[i] = still(v[i].x, v[i].y);
        px[i] = (double)v[i].x.v / GRID_ONE;
        py[i] = (double)v[i].y.v / GRID_ONE;
        pz[i] = v[i].z;
        if (fabs(v[i].z) > largest) largest = fabs(v[i].z);
    }
    gradient(px, py, pz, &dzdx, &dzdy);
    s->offset = polygon_offset(s, dzdx, dzdy, largest);
    for (y = b.y0; y <= b.y1; y++)
        for (x = b.x0; x <= b.x1; x++)
            for (k = 0; k < s->samples; k++) {
                point q = sample_at(s, x, y, k);
                double weights[3];
                if (!triangle_covers(p, q, s->rule, s->tie, s->cull)) continue;
                barycentric(p, q, weights);
                /* A moving scene's still primitive covers sample k at every instant. */
                open_fragment(out, &first, x, y, s->antialiased || s->time_samples ? k : -1);
                values(out, s, v, 3, mode, weights);
                buffer_printf(out, "]");
            }
}

/* A line's parallelogram (SPEC.md §4.4): the segment a→b swept by ±h
 * along its minor axis, all on one grid. A line of zero length gives a
 * flat shape, which covers nothing. */
static void parallelogram(point a, point b, i128 h, point c[4]) {
    i128 dx = b.x - a.x, dy = b.y - a.y;
    int x_major = (dx < 0 ? -dx : dx) >= (dy < 0 ? -dy : dy);
    c[0] = a;
    c[1] = b;
    c[2] = b;
    c[3] = a;
    if (x_major) {
        c[0].y -= h, c[1].y -= h, c[2].y += h, c[3].y += h;
    } else {
        c[0].x -= h, c[1].x -= h, c[2].x += h, c[3].x += h;
    }
}

/* Whether a shape moving from `v` (a triangle, or a line's two ends with
 * `width` in 2^-16 px) covers q (on the 2^-16 grid) at instant t (units
 * of 2^-32): positions on the 2^-48 grid, a line's on the 2^-49 grid so
 * that its half-width is whole. -1 when a coordinate is beyond the
 * 128-bit arithmetic. */
static int covers_at(const scene *s, const vertex *v, int line, int64_t width, point q, i128 t) {
    point p[4];
    int i, n = line ? 4 : 3, shift = line ? 33 : 32;
    q.x *= (i128)1 << shift;
    q.y *= (i128)1 << shift;
    if (line) {
        point a = moving(&v[0], t), b = moving(&v[1], t);
        a.x *= 2, a.y *= 2, b.x *= 2, b.y *= 2;
        parallelogram(a, b, (i128)width * INSTANT_ONE, p);
    } else {
        for (i = 0; i < 3; i++) p[i] = moving(&v[i], t);
    }
    for (i = 0; i < n; i++)
        if (p[i].x - q.x >= COVERAGE_MAX_COORD || q.x - p[i].x >= COVERAGE_MAX_COORD
            || p[i].y - q.y >= COVERAGE_MAX_COORD || q.y - p[i].y >= COVERAGE_MAX_COORD)
            return -1;
    return line ? convex_covers(p, 4, q, s->rule, s->tie) : triangle_covers(p, q, s->rule, s->tie, s->cull);
}

/* The time samples of a moving triangle or line: slot j = s·N + k covers
 * spatial sample s at instant u_j of its pixel (SPEC.md §12.8, §15.3).
 * `corners` holds the shape's vertices, for its swept bounding box. */
static enum outcome draw_moving(buffer *out, scene *s, const vertex *v, int line, int64_t width,
                                const vertex *corners, int count, const char *path) {
    box b = bounds(s, corners, count);
    int x, y, j, first = 1, total = s->samples * s->time_samples;
    for (y = b.y0; y <= b.y1; y++)
        for (x = b.x0; x <= b.x1; x++) {
            const json *us = json_at(s->times, (size_t)y * (size_t)s->width + (size_t)x);
            if (json_length(us) != (size_t)total)
                return fail(s, FAILED, "$.plan.motion.times[%d] does not hold M·N = %d instants",
                            y * s->width + x, total);
            for (j = 0; j < total; j++) {
                int64_t u = (int64_t)json_number(json_at(us, (size_t)j), -1);
                /* τ = open + (close − open)·u/2^16, in units of 2^-32. */
                i128 t = (i128)s->open * 65536 + (i128)(s->close - s->open) * u;
                int covered;
                if (u < 0 || u >= 65536)
                    return fail(s, FAILED, "$.plan.motion.times[%d][%d] is not in [0, 65536)",
                                y * s->width + x, j);
                covered = covers_at(s, v, line, width, sample_at(s, x, y, j / s->time_samples), t);
                if (covered < 0)
                    return fail(s, UNSUPPORTED, "%s: a vertex 16384 px or more from a sample is "
                                "beyond this program's 128-bit arithmetic", path);
                if (!covered) continue;
                open_fragment(out, &first, x, y, j);
                buffer_printf(out, "]");
            }
        }
    return DRAWN;
}

/* A still parallelogram line, on the 2^-17 grid (its half-width whole).
 * Values along it use t (SPEC.md §4, §5): the sample's place along the
 * major axis, or its projection onto the segment, clamped to [0, 1]. */
static void draw_still_line(buffer *out, const scene *s, const vertex v[2], int64_t width,
                            const vertex *corners, enum interpolation mode, int projected) {
    point c[4], a = still(v[0].x, v[0].y), e = still(v[1].x, v[1].y), a2, e2;
    box b = bounds(s, corners, 4);
    double dx = (double)(e.x - a.x), dy = (double)(e.y - a.y);
    int x, y, k, first = 1, x_major = (dx < 0 ? -dx : dx) >= (dy < 0 ? -dy : dy);
    a2.x = 2 * a.x, a2.y = 2 * a.y, e2.x = 2 * e.x, e2.y = 2 * e.y;
    parallelogram(a2, e2, width, c);
    for (y = b.y0; y <= b.y1; y++)
        for (x = b.x0; x <= b.x1; x++)
            for (k = 0; k < s->samples; k++) {
                point q = sample_at(s, x, y, k), q2;
                /* The sample relative to v0, on the 2^-16 grid. */
                double qx = (double)(q.x - a.x), qy = (double)(q.y - a.y), t, weights[2];
                q2.x = 2 * q.x, q2.y = 2 * q.y;
                if (!convex_covers(c, 4, q2, s->rule, s->tie)) continue;
                if (projected) t = (qx * dx + qy * dy) / (dx * dx + dy * dy);
                else t = x_major ? qx / dx : qy / dy;
                t = t < 0 ? 0 : t > 1 ? 1 : t;
                weights[0] = 1 - t;
                weights[1] = t;
                open_fragment(out, &first, x, y, s->antialiased || s->time_samples ? k : -1);
                values(out, s, v, 2, mode, weights);
                buffer_printf(out, "]");
            }
}

static enum outcome draw_line(buffer *out, scene *s, const json *prim, const char *path,
                              enum interpolation mode, int moves) {
    const json *line = json_get(prim, "line");
    const char *rule = json_string(json_get(prim, "rule"), "");
    vertex v[2], corners[4];
    fx16 width;
    int64_t h;
    int i;
    char at[160];
    enum outcome o;
    if (strcmp(rule, "parallelogram") != 0)
        return fail(s, UNSUPPORTED, "%s: %s lines are not implemented", path, rule);
    if (json_length(line) != 2) return fail(s, FAILED, "%s.line must hold 2 vertices", path);
    for (i = 0; i < 2; i++) {
        snprintf(at, sizeof at, "%s.line[%d]", path, i);
        if ((o = read_vertex(s, json_at(line, (size_t)i), at, &v[i])) != DRAWN) return o;
    }
    snprintf(at, sizeof at, "%s.exact.width", path);
    if ((o = coordinate(s, json_get(json_get(prim, "exact"), "width"), at, -1, &width)) != DRAWN)
        return o;
    /* The pixels within the half-width (rounded up) of either end, at
     * either end of the shutter. */
    h = (width.v + 1) / 2;
    for (i = 0; i < 4; i++) {
        int64_t d = i < 2 ? -h : h;
        corners[i] = v[i % 2];
        corners[i].x.v += d, corners[i].y.v += d, corners[i].tx.v += d, corners[i].ty.v += d;
    }
    if (moves) return draw_moving(out, s, v, 1, width.v, corners, 4, path);
    draw_still_line(out, s, v, width.v, corners, mode,
                    strcmp(json_string(json_get(prim, "parameter"), "major"), "projected") == 0);
    return DRAWN;
}

static enum outcome draw_polygon(buffer *out, scene *s, const json *prim, const char *path) {
    const json *contours = json_get(prim, "contours");
    int even_odd = strcmp(json_string(json_get(prim, "fill"), "nonzero"), "even-odd") == 0;
    size_t c, i, total = 0, n = 0;
    point *points;
    vertex *corners; /* the same positions, for the bounding box */
    int *lengths, x, y, k, first = 1;
    enum outcome o = DRAWN;
    box b;
    for (c = 0; c < json_length(contours); c++) total += json_length(json_at(contours, c));
    if (total < 3) return fail(s, FAILED, "%s.contours must hold a contour", path);
    points = calloc(total, sizeof *points);
    corners = calloc(total, sizeof *corners);
    lengths = calloc(json_length(contours), sizeof *lengths);
    if (!points || !corners || !lengths) {
        o = fail(s, FAILED, "%s: out of memory", path);
        goto done;
    }
    for (c = 0; c < json_length(contours); c++) {
        const json *contour = json_at(contours, c);
        lengths[c] = (int)json_length(contour);
        for (i = 0; i < json_length(contour); i++, n++) {
            char at[160];
            snprintf(at, sizeof at, "%s.contours[%zu][%zu]", path, c, i);
            if ((o = read_vertex(s, json_at(contour, i), at, &corners[n])) != DRAWN) goto done;
            points[n] = still(corners[n].x, corners[n].y);
        }
    }
    b = bounds(s, corners, (int)total);
    for (y = b.y0; y <= b.y1; y++)
        for (x = b.x0; x <= b.x1; x++)
            for (k = 0; k < s->samples; k++) {
                long w = winding_number(points, lengths, (int)json_length(contours),
                                        sample_at(s, x, y, k), s->tie);
                if (even_odd ? (w % 2 == 0) : (w == 0)) continue;
                open_fragment(out, &first, x, y, s->antialiased || s->time_samples ? k : -1);
                /* Polygons carry no values; a plan that asks for some in a
                 * mixed scene gets zeros here. */
                if (s->depth) buffer_printf(out, ",0");
                for (i = 0; i < (size_t)s->attributes; i++) buffer_printf(out, ",0");
                buffer_printf(out, "]");
            }
done:
    free(points);
    free(corners);
    free(lengths);
    return o;
}

/* The plan: samples (the pixel centre, or the antialias offsets) and, in
 * a moving scene, the shutter and time samples. */
static enum outcome read_plan(scene *s, const json *plan) {
    const json *aa = json_get(plan, "antialias"), *motion = json_get(plan, "motion");
    size_t k;
    enum outcome o;
    s->depth = json_get(plan, "depth") && json_get(plan, "depth")->boolean;
    s->attributes = (int)json_number(json_get(plan, "attributes"), 0);
    if (s->attributes < 0 || s->attributes > MAX_ATTRIBUTES)
        return fail(s, FAILED, "$.plan.attributes must be at most 16");
    s->samples = 1;
    s->offsets[0][0].v = s->offsets[0][1].v = GRID_ONE / 2;
    s->antialiased = aa != NULL;
    if (aa) {
        const json *offsets = json_get(json_get(aa, "exact"), "offsets");
        if (json_length(offsets) < 1 || json_length(offsets) > MAX_SAMPLES)
            return fail(s, FAILED, "$.plan.antialias.exact.offsets must hold 1 to 256 offsets");
        s->samples = (int)json_length(offsets);
        for (k = 0; k < json_length(offsets); k++) {
            char at[160];
            snprintf(at, sizeof at, "$.plan.antialias.exact.offsets[%zu][0]", k);
            if ((o = coordinate(s, json_at(json_at(offsets, k), 0), at, -1, &s->offsets[k][0])) != DRAWN)
                return o;
            snprintf(at, sizeof at, "$.plan.antialias.exact.offsets[%zu][1]", k);
            if ((o = coordinate(s, json_at(json_at(offsets, k), 1), at, -1, &s->offsets[k][1])) != DRAWN)
                return o;
        }
    }
    s->time_samples = 0;
    if (motion) {
        const json *shutter = json_get(json_get(motion, "exact"), "shutter");
        fx16 open, close;
        if ((o = coordinate(s, json_at(shutter, 0), "$.plan.motion.exact.shutter[0]", -1, &open)) != DRAWN)
            return o;
        if ((o = coordinate(s, json_at(shutter, 1), "$.plan.motion.exact.shutter[1]", -1, &close)) != DRAWN)
            return o;
        s->open = open.v;
        s->close = close.v;
        s->time_samples = (int)json_number(json_get(motion, "samples"), 0);
        s->times = json_get(motion, "times");
        if (s->time_samples < 1)
            return fail(s, FAILED, "$.plan.motion.samples must be a positive count");
        if ((int)json_number(json_get(motion, "spatial_samples"), 1) != s->samples)
            return fail(s, FAILED, "$.plan.motion.spatial_samples differs from the antialias offsets' count");
        if (json_length(s->times) != (size_t)s->width * (size_t)s->height)
            return fail(s, FAILED, "$.plan.motion.times must hold one list per pixel");
    }
    return DRAWN;
}


static const char *const FILL_RULES[] = {"top-left", "bottom-right", "top-right", "bottom-left",
                                         "all-edges"};
static const char *const CULLS[] = {"none", "cw", "ccw"};

enum outcome draw_request(const json *request, const options *opt, buffer *out, char *why,
                          size_t why_size) {
    const json *rules = json_get(request, "rules"), *bits = json_get(rules, "subpixel_bits");
    const json *primitives = json_get(request, "primitives");
    scene s;
    size_t p;
    int rule, cull;
    enum outcome o;
    memset(&s, 0, sizeof s);
    s.why = why;
    s.why_size = why_size;
    s.width = (int)json_number(json_get(json_get(request, "canvas"), "width"), 0);
    s.height = (int)json_number(json_get(json_get(request, "canvas"), "height"), 0);
    if (s.width < 1 || s.height < 1 || s.width > 16384 || s.height > 16384)
        return fail(&s, FAILED, "$.canvas must be a size in [1, 16384]");
    s.bits = bits && bits->kind == JSON_NUMBER ? (int)bits->number : -1;
    if (s.bits > GRID_BITS) return fail(&s, UNSUPPORTED, "more than 16 subpixel bits");
    rule = word_index(json_string(json_get(rules, "fill_rule"), NULL), FILL_RULES, 5);
    cull = word_index(json_string(json_get(rules, "cull"), NULL), CULLS, 3);
    if (rule < 0) return fail(&s, FAILED, "$.rules.fill_rule is not a fill rule");
    if (cull < 0) return fail(&s, FAILED, "$.rules.cull is not a cull mode");
    s.rule = (enum fill_rule)rule;
    s.last_provokes =
        strcmp(json_string(json_get(rules, "provoking_vertex"), "first"), "last") == 0;
    s.cull = (enum cull)cull;
    s.tie = nudge_of(s.rule, opt->wrong_tie);
    if ((o = read_plan(&s, json_get(request, "plan"))) != DRAWN) return o;
    if ((o = read_depth_and_clip(&s, request)) != DRAWN) return o;
    s.ignore_offset = opt->ignore_offset;
    if (opt->fixed_clip && s.clip_space) {
        s.clip_xy = 1;
        s.per_sample_z = 0;
    }

    buffer_printf(out, "\"primitives\":[");
    for (p = 0; p < json_length(primitives); p++) {
        const json *prim = json_at(primitives, p), *triangle = json_get(prim, "triangle");
        char path[64];
        snprintf(path, sizeof path, "$.primitives[%zu]", p);
        buffer_printf(out, p ? ",{\"fragments\":[" : "{\"fragments\":[");
        s.offset = 0;
        if (triangle && s.clip_space) {
            int mode = word_index(json_string(json_get(prim, "interpolation"), "perspective"),
                                  INTERPOLATIONS, 3);
            if (json_length(triangle) != 3 || mode < 0)
                return fail(&s, FAILED, "%s is not a triangle with an interpolation mode", path);
            if ((o = draw_clip_triangle(out, &s, triangle, path, (enum interpolation)mode)) != DRAWN)
                return o;
        } else if (json_get(prim, "point")) {
            if ((o = draw_point(out, &s, prim, path)) != DRAWN) return o;
        } else if (triangle) {
            vertex v[3];
            int i, moves = json_get(prim, "moves") && json_get(prim, "moves")->boolean;
            int mode = word_index(json_string(json_get(prim, "interpolation"), "perspective"),
                                  INTERPOLATIONS, 3);
            if (json_length(triangle) != 3 || mode < 0)
                return fail(&s, FAILED, "%s is not a triangle with an interpolation mode", path);
            for (i = 0; i < 3; i++) {
                char at[160];
                snprintf(at, sizeof at, "%s.triangle[%d]", path, i);
                if ((o = read_vertex(&s, json_at(triangle, (size_t)i), at, &v[i])) != DRAWN) return o;
            }
            if (moves && !s.time_samples)
                return fail(&s, FAILED, "%s moves, and the plan has no motion", path);
            if (moves) {
                if ((o = draw_moving(out, &s, v, 0, 0, v, 3, path)) != DRAWN) return o;
            } else {
                draw_still_triangle(out, &s, v, (enum interpolation)mode);
            }
        } else if (json_get(prim, "contours")) {
            if ((o = draw_polygon(out, &s, prim, path)) != DRAWN) return o;
        } else if (json_get(prim, "line")) {
            int moves = json_get(prim, "moves") && json_get(prim, "moves")->boolean;
            int mode = word_index(json_string(json_get(prim, "interpolation"), "perspective"),
                                  INTERPOLATIONS, 3);
            if (mode < 0) return fail(&s, FAILED, "%s.interpolation is not a mode", path);
            if (moves && !s.time_samples)
                return fail(&s, FAILED, "%s moves, and the plan has no motion", path);
            if ((o = draw_line(out, &s, prim, path, (enum interpolation)mode, moves)) != DRAWN)
                return o;
        } else {
            return fail(&s, FAILED, "%s is neither a triangle, a polygon nor a line", path);
        }
        buffer_printf(out, "]}");
    }
    buffer_printf(out, "]");
    if (out->failed) return fail(&s, FAILED, "out of memory");
    return DRAWN;
}
