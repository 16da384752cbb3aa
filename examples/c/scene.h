/* What draw.c and clip.c share, for the C example rasterizer: the scene a
 * request describes, a vertex, and the helpers both draw with. */
#ifndef SCENE_H
#define SCENE_H

#include <stddef.h>
#include <stdint.h>

#include "buffer.h"
#include "coverage.h"
#include "draw.h"
#include "fixed.h"
#include "json.h"
#include "rational.h"

#define MAX_ATTRIBUTES 16
/* An instant of the shutter's unit interval is a multiple of 2^-32 (the
 * shutter's ends are multiples of 2^-16, u/65536 of it another 16 bits);
 * shifts of signed values are undefined for negatives, so multiply. */
#define INSTANT_ONE ((i128)1 << 32)
#define MAX_SAMPLES 256

typedef struct {
    fx16 x, y;   /* snapped; a moving vertex's position at shutter open */
    fx16 tx, ty; /* a moving vertex's snapped position at shutter close */
    double z, w, attributes[MAX_ATTRIBUTES];
} vertex;

enum interpolation { FLAT, LINEAR, PERSPECTIVE };

/* The scene as far as every primitive shares it. */
typedef struct {
    int width, height, bits; /* bits < 0: exact coordinates */
    enum fill_rule rule;
    enum cull cull;
    nudge tie;
    int depth, attributes;
    int last_provokes; /* flat values from the last vertex (SPEC.md §16.6) */
    int samples;                  /* spatial samples per pixel */
    int antialiased;              /* fragments name their sample slot */
    fx16 offsets[MAX_SAMPLES][2]; /* from the pixel's top-left corner */
    /* Motion (SPEC.md §12.8); time_samples == 0 in a still scene. */
    int time_samples;
    int64_t open, close; /* the shutter, in units of 2^-16 */
    const json *times;   /* per pixel y·width + x, M·N values of u */
    /* Depth as stored (SPEC.md §18, §12.10): 0 exact, 16 or 24 unorm, 32
     * float32; the polygon offset, and the offset of the primitive being
     * drawn (0 but for triangles). */
    int depth_format, has_bias, ignore_offset;
    double bias_constant, bias_slope, bias_clamp, offset;
    /* Clip space (SPEC.md §16, §17.2): the viewport and the conventions. */
    int clip_space, clip_xy, per_sample_z, depth_clamp, unsnapped, pop_points, bounds_viewport;
    rat viewport[6]; /* x, y, width, height, min_depth, max_depth */
    double depth_low, depth_high;
    char *why;
    size_t why_size;
} scene;

/* The pixels a set of positions may cover (bounds): whole pixels from the
 * one holding the smallest coordinate to the one holding the largest (a
 * sample on the far edge belongs to that pixel), clipped to the canvas. */
typedef struct {
    int x0, y0, x1, y1;
} box;

/* draw.c */
enum outcome fail(scene *s, enum outcome outcome, const char *format, ...);
enum outcome read_vertex(scene *s, const json *v, const char *path, vertex *out);
point still(fx16 x, fx16 y);
point sample_at(const scene *s, int x, int y, int k);
int floor_pixel(int64_t v);
box bounds(const scene *s, const vertex *v, int count);
void emit_depth(buffer *out, const scene *s, double z);
double polygon_offset(const scene *s, double dzdx, double dzdy, double largest);
void gradient(const double x[3], const double y[3], const double z[3], double *dzdx, double *dzdy);
void open_fragment(buffer *out, int *first, int x, int y, int slot);

/* clip.c */
enum outcome read_depth_and_clip(scene *s, const json *request);
enum outcome draw_clip_triangle(buffer *out, scene *s, const json *triangle, const char *path,
                                enum interpolation mode);
enum outcome draw_point(buffer *out, scene *s, const json *prim, const char *path);

#endif
