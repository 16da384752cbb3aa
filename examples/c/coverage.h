/* Which samples a triangle or a polygon covers, decided exactly in integer
 * arithmetic, for the C example rasterizer. The rules are SPEC.md §3 (the
 * fill rule owns samples on edges), §2 (winding, cull) and §14.1 (polygon
 * winding numbers at the nudged sample). Nothing here rounds: every
 * position is an integer on a grid the caller chooses (2^-16 pixel for
 * still scenes, 2^-48 for instants of a moving one), and the decisions are
 * signs of products of such integers. */
#ifndef COVERAGE_H
#define COVERAGE_H

#include "fixed.h" /* i128 */

/* A position on the caller's grid. */
typedef struct {
    i128 x, y;
} point;

/* Coordinates whose magnitude, relative to the sample, stays below this
 * keep every product below 2^124 and every edge function below 2^126. */
#define COVERAGE_MAX_COORD ((i128)1 << 62)

enum fill_rule { TOP_LEFT, BOTTOM_RIGHT, TOP_RIGHT, BOTTOM_LEFT, ALL_EDGES };
enum cull { CULL_NONE, CULL_CW, CULL_CCW };

/* The infinitesimal nudge that stands for a tie rule (SPEC.md §3): the
 * sample moves by (dx·ε, dy·ε²). top-left is (+1, +1): right and down. */
typedef struct {
    int dx, dy;
} nudge;

/* The nudge of a fill rule; `flipped` gives the opposite rule's (the
 * example's --wrong-tie bug). ALL_EDGES has none and is not asked. */
nudge nudge_of(enum fill_rule rule, int flipped);

/* Twice the signed area of a triangle: positive when it runs clockwise on
 * screen (y down). */
i128 doubled_area(const point v[3]);

/* Whether the triangle `v` covers sample `q`: §3's rule under `rule`
 * (with `tie` as its nudge), after `cull`; a triangle of zero area covers
 * nothing. Coordinates relative to q below COVERAGE_MAX_COORD. */
int triangle_covers(const point v[3], point q, enum fill_rule rule, nudge tie, enum cull cull);

/* The same for a convex polygon of n vertices whose first three are not
 * collinear unless it is flat (a parallelogram line, SPEC.md §4.4: each
 * border is owned by its outward normal as §3 owns a triangle's edges,
 * which is the nudge test here). Never culled. */
int convex_covers(const point *v, int n, point q, enum fill_rule rule, nudge tie);

/* The barycentric weights of `q` in a triangle of non-zero area, as
 * doubles (they only weight the interpolated values, never decide). */
void barycentric(const point v[3], point q, double weights[3]);

/* The winding number of the contours around q nudged by `tie` (§14.1):
 * `points` holds every contour's vertices in turn, `lengths` their
 * counts. */
long winding_number(const point *points, const int *lengths, int contours, point q, nudge tie);

#endif
