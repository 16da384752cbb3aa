"""The line cases of the midpoint, rectangle and parallelogram rules (SPEC.md
section 4.1, 4.3, 4.4) and of line interpolation (section 5): worked
examples, stars, ties, strips and loops, borders, snapping, long and far
lines. Diamond-exit's cases are in diamond.py; expectations come from
check.py.
"""

from fractions import Fraction as F

from casegen.casefile import P
from casegen.lines.build import V, case, fmt_px, mid, para, rect


# ---------------------------------------------------------------------------
# 1. Worked examples (SPEC.md section 4 points at these three files).

WE_MID_A = [(1, 1), (2, 1), (3, 2), (4, 2), (5, 3), (6, 3), (7, 4), (8, 4), (9, 5)]
WE_MID_B = [(2, 6), (2, 7), (3, 8), (3, 9), (4, 10)]
case("midpoint_worked_example",
     "Worked example of the midpoint rule (SPEC 4.1), two lines on a 12x12 canvas. "
     "Line 1 runs from the pixel centre (1.5, 1.5) to the pixel centre (9.5, 5.5): d = (8, 4), |dx| >= |dy|, "
     "so it is x-major and draws one pixel per column. The columns drawn are those whose centre c = i + 0.5 "
     "lies in the closed interval [1.5, 9.5]: columns 1 to 9, both end columns included (last_pixel: include). "
     "In column i the line's height is y(c) = 1.5 + (c - 1.5) * 4/8, and the row drawn is ceil(y(c)) - 1, the "
     "row whose centre is nearest. Column 1: y = 1.5, row 1. Column 2: y = 2.0, an integer: the centres of "
     "rows 1 (1.5) and 2 (2.5) are equally near, a tie, and the rule gives it to the UPPER row (smaller y), "
     "row 1 = ceil(2.0) - 1. Column 3: y = 2.5, row 2. Column 4: y = 3.0, tie again, upper row 2. And so on: "
     "every even column is a tie, so the line draws pixel pairs " + fmt_px(WE_MID_A) + ". A Bresenham that "
     "breaks ties downwards draws (2,2) (4,3) (6,4) (8,5) instead. "
     "Line 2 runs from (2.5, 6.5) to (4.5, 10.5): d = (2, 4), |dy| > |dx|, so it is y-major and the axes swap: "
     "rows 6 to 10 (centres 6.5 to 10.5), and in row j the column ceil(x(r)) - 1 with x(r) = 2.5 + (r - 6.5) * 2/4. "
     "Row 6: x = 2.5, column 2. Row 7: x = 3.0, a tie between columns 2 and 3, which goes to the LEFT column 2. "
     "Row 8: x = 3.5, column 3. Row 9: x = 4.0, tie, left column 3. Row 10: x = 4.5, column 4. Pixels: "
     + fmt_px(WE_MID_B) + ". Drawing either line from its other end gives the same pixels: the rule depends "
     "only on the points of the segment. 14 samples in all.",
     12, 12, [mid((1.5, 1.5), (9.5, 5.5)), mid((2.5, 6.5), (4.5, 10.5))],
     checks=[("ties",)], pixels={0: WE_MID_A, 1: WE_MID_B})

WE_RECT = [(1, 1), (1, 2), (2, 1), (2, 2), (2, 3), (3, 2), (3, 3), (4, 3), (4, 4), (5, 3), (5, 4),
           (5, 5), (6, 4), (6, 5), (6, 6), (7, 5), (7, 6), (8, 6), (8, 7), (9, 6)]
case("rectangle_worked_example",
     "Worked example of the rectangle rule (SPEC 4.3): one line of width 2 from the pixel centre v0 = (1.5, 1.5) "
     "to the pixel centre v1 = (9.5, 7.5) on a 12x10 canvas. d = v1 - v0 = (8, 6), so |d|^2 = 100 and |d| = 10. "
     "A sample p is covered when, with q = p - v0, the projection q.d = 8qx + 6qy lies in [0, 100] (between "
     "the two end caps, which are perpendicular to the line through v0 and v1) and the cross product "
     "q x d = 6qx - 8qy satisfies |q x d| <= (width/2)|d| = 10, compared squared: (6qx - 8qy)^2 <= 100 (the two "
     "long sides, 1 pixel either side of the segment). Because v0 is a pixel centre, q is a pair of integers "
     "for every sample, so many samples land exactly ON the border, and the fill rule decides them. Each border "
     "edge is classified by its outward normal n: the side where q x d = +10 has n = (dy, -dx) = (6, -8), nx > 0, "
     "a RIGHT edge; the side q x d = -10 has n = (-6, 8), a LEFT edge; the cap at v0 has n = -d = (-8, -6), a LEFT "
     "edge; the cap at v1 has n = d, a RIGHT edge. Under top-left, left edges own their samples and right edges "
     "do not. Examples: v0's own sample (1,1) has q = (0,0), on the v0 cap (left): covered. Sample (4,2): "
     "q = (3,1), q.d = 30, q x d = 18 - 8 = 10: on the right side, not covered. Sample (2,3): q = (1,2), "
     "q x d = -10, on the left side: covered. Sample (9,7) is v1 itself: q = d, on the v1 cap (right): NOT "
     "covered, so the rectangle stops one sample short there; its neighbour (9,6) has q = (8,5), q.d = 94, "
     "q x d = 8: inside. Sample (10,7): q = (9,6), q.d = 108 > 100, beyond the v1 cap. Sample (3,1): q = (2,0), "
     "q x d = 12 > 10, outside. The 20 samples covered: " + fmt_px(WE_RECT) + ". Note the apparent thickness: the "
     "vertical extent of the band is width * |d|/|dx| = 2.5 pixels, so full columns get 2 or 3 samples.",
     12, 10, [rect((1.5, 1.5), (9.5, 7.5), width=2)], checks=[("fill_rule",)], pixels={0: WE_RECT})

WE_PARA = [(1, 1), (1, 2), (2, 2), (2, 3), (3, 2), (3, 3), (4, 3), (4, 4), (5, 3), (5, 4), (6, 4),
           (6, 5), (7, 4), (7, 5), (8, 5), (8, 6)]
case("parallelogram_worked_example",
     "Worked example of the parallelogram rule (SPEC 4.4): one line of width 2 from (1.5, 2) to (9.5, 6) on "
     "a 12x9 canvas. d = (8, 4) is x-major, so the line is the segment swept vertically: a sample p is covered "
     "when p.x lies in [1.5, 9.5] and |p.y - y(p.x)| <= 1, with y(x) = 2 + (x - 1.5)/2. Its ends are vertical "
     "(x = 1.5 and x = 9.5) and its width is measured vertically, so each column holds a band exactly 2 "
     "pixels tall whatever the slope. Both ends run through sample centres: the end x = 1.5 has outward normal "
     "(-1, 0), a LEFT edge, owned under top-left, so column 1 is drawn; the end x = 9.5 has normal (1, 0), a "
     "RIGHT edge, not owned, so column 9 is not drawn at all. Column by column, samples at y = j + 0.5: "
     "column 1, y(1.5) = 2: the band is [1, 3], samples 1.5 and 2.5 inside: rows 1, 2. Column 2, y(2.5) = 2.5: "
     "band [1.5, 3.5], sample 2.5 inside, and 1.5 and 3.5 exactly on the sides. The upper side "
     "p.y - y(p.x) = -1 has outward normal (dy/dx, -1) = (0.5, -1), nx > 0, a RIGHT edge: row 1 not covered. "
     "The lower side p.y - y(p.x) = +1 has normal (-0.5, 1), a LEFT edge: row 3 covered. So column 2 gets "
     "rows 2, 3. Odd columns are like column 1, even ones like column 2, and every column gets exactly 2 "
     "samples: " + fmt_px(WE_PARA) + ", 16 in all. Under bottom-right the ownership flips: column 9 is drawn, "
     "column 1 is not, and the even columns take their upper border sample instead of the lower one.",
     12, 9, [para((1.5, 2), (9.5, 6), width=2)], checks=[("fill_rule",)], pixels={0: WE_PARA})

# ---------------------------------------------------------------------------
# 2. Stars: slopes 0, +-1/2, +-1, +-2 and vertical in every octant.

STAR_DIRS = [(2, 0), (2, 1), (2, 2), (1, 2), (0, 2), (-1, 2), (-2, 2), (-2, 1),
             (-2, 0), (-2, -1), (-2, -2), (-1, -2), (0, -2), (1, -2), (2, -2), (2, -1)]
C = (F(65, 2), F(65, 2))


def star_lines(maker, centre=C, scale=12, inward=False, **kw):
    out = []
    for dx, dy in STAR_DIRS:
        tip = (centre[0] + dx * scale, centre[1] + dy * scale)
        a, b = (tip, centre) if inward else (centre, tip)
        out.append(maker(a, b, **kw))
    return out


STAR_TEXT = ("16 lines from the pixel centre (32.5, 32.5) of a 64x64 canvas, in the directions (2,0) (2,1) "
             "(2,2) (1,2) (0,2) (-1,2) (-2,2) (-2,1) (-2,0) (-2,-1) (-2,-2) (-1,-2) (0,-2) (1,-2) (2,-2) "
             "(2,-1) scaled by 12: slopes 0, +-1/2, +-1, +-2 and vertical, two lines in every octant, "
             "every sign of dx and dy. ")

case("midpoint_star_16",
     STAR_TEXT + "Each line is drawn outward, centre to tip, with last_pixel include: 25 pixels per line, and "
     "the centre pixel (32,32) is covered 16 times. The slope +-1/2 and +-2 lines start on a pixel centre, so "
     "every other column (row) is an exact tie, broken to the upper row (left column); a rasterizer that "
     "breaks ties by the direction of travel, or uses a DDA that rounds y(c) to nearest-up, draws them on the "
     "other side in some octants. The |slope| = 1 lines are x-major.",
     64, 64, star_lines(mid), checks=[("ties",), ("min_coverage_max", 16)])

case("midpoint_star_16_reversed",
     "The same 16 lines as midpoint_star_16, each drawn from its tip to the centre. The midpoint rule "
     "depends only on the set of points of the segment, so every pixel and every coverage count must equal "
     "those of midpoint_star_16: A->B = B->A. A Bresenham that always starts at v0 and breaks ties by the "
     "sign of its error term draws the tie pixels of the reversed slope-1/2 and slope-2 lines on the other "
     "side. " + STAR_TEXT,
     64, 64, star_lines(mid, inward=True),
     checks=[("ties",), ("same_as", "midpoint_star_16")])

case("midpoint_star_16_exclude_outward",
     STAR_TEXT + "Drawn outward with last_pixel: exclude: the interval of columns (rows for y-major lines) is "
     "half-open at v1, so the tip pixel of every line, whose centre is exactly v1, is not drawn, while the "
     "centre pixel is still covered 16 times. The tips lie in every octant, so an implementation that "
     "excludes 'the last column' in the wrong direction, or the first pixel instead of the last, fails.",
     64, 64, star_lines(mid, last_pixel="exclude"), checks=[("min_coverage_max", 16)])

case("midpoint_star_16_exclude_inward",
     STAR_TEXT + "Drawn inward (tip to centre) with last_pixel: exclude: every line ends on the centre "
     "pixel's centre, so none of them draws it, and the centre pixel (32,32) stays uncovered while all 16 tips "
     "are drawn. (Near the centre, lines of neighbouring directions share some pixels, so a few samples are "
     "covered 2 or 3 times.) Reversing a line changes which end is excluded: compare midpoint_star_16_exclude_outward.",
     64, 64, star_lines(mid, inward=True, last_pixel="exclude"), checks=[("uncovered", 32, 32)])

case("rectangle_star_16",
     STAR_TEXT + "Rule rectangle, width 1, drawn outward. The long sides of the axis-aligned lines lie on "
     "pixel edges, half way between sample rows (columns), and those of the other lines, at an irrational "
     "distance |d|/2 from the axis in q x d units, never meet a sample. The caps are perpendicular to each "
     "line through its ends, both sample centres: the centre sample lies on all 16 v0 caps and is covered only by the lines whose v0 "
     "cap is a left or top edge under top-left. The apparent thickness varies with slope: 1 sample per column "
     "for the horizontal line, 1 or 2 for the diagonals.",
     64, 64, star_lines(rect, width=1), checks=[("fill_rule",)])

case("rectangle_star_16_reversed",
     "The lines of rectangle_star_16 drawn tip to centre. The rectangle is the same set with the same "
     "border edges whichever end is v0, so every sample and every coverage count must equal those of "
     "rectangle_star_16. " + STAR_TEXT,
     64, 64, star_lines(rect, width=1, inward=True), checks=[("same_as", "rectangle_star_16")])

case("parallelogram_star_16",
     STAR_TEXT + "Rule parallelogram, width 2, drawn outward. Each band is exactly 2 samples tall in every "
     "column (x-major) or wide in every row (y-major) away from the ends, and its ends run through sample "
     "centres (the centre and the tips), so the fill rule decides the first and last column or row. At the "
     "centre the 16 ends meet and the centre sample is covered only by the lines whose end there is owned.",
     64, 64, star_lines(para, width=2), checks=[("fill_rule",)])

case("parallelogram_star_16_reversed",
     "The lines of parallelogram_star_16 drawn tip to centre: the same sets with the same borders, so every "
     "coverage count must equal those of parallelogram_star_16. " + STAR_TEXT,
     64, 64, star_lines(para, width=2, inward=True), checks=[("same_as", "parallelogram_star_16")])

# ---------------------------------------------------------------------------
# 3. Exact midpoint ties.

TIE_X = [mid((1.5, 1.5), (17.5, 9.5)), mid((38.5, 1.5), (22.5, 9.5)),
         mid((1.5, 38.5), (17.5, 30.5)), mid((38.5, 38.5), (22.5, 30.5))]
case("midpoint_tie_slope_half",
     "Four x-major lines of slope +-1/2 on a 40x40 canvas, one in each x-major octant pair and each direction "
     "of travel: (1.5,1.5)->(17.5,9.5), (38.5,1.5)->(22.5,9.5), (1.5,38.5)->(17.5,30.5), "
     "(38.5,38.5)->(22.5,30.5). Each starts on a pixel centre, so at every other column y(c) is an integer "
     "and the two nearest row centres tie. The tie rule for x-major lines: the UPPER row (the smaller y, "
     "ceil(y(c)) - 1) wins, whichever way the line runs and whether it rises or falls. A Bresenham whose "
     "decision variable is tested with > instead of >= (or vice versa) in some octant, or an implementation "
     "that rounds y(c) half-up (floor(y + 0.5)), draws the lower row. 17 columns each, 68 samples.",
     40, 40, TIE_X, checks=[("ties",)])

TIE_Y = [mid((3.5, 3.5), (11.5, 19.5)), mid((11.5, 28.5), (3.5, 12.5)),
         mid((28.5, 3.5), (20.5, 19.5)), mid((20.5, 28.5), (28.5, 12.5))]
case("midpoint_tie_slope_two",
     "Four y-major lines of slope +-2 on a 32x32 canvas, in each y-major octant pair and each direction of "
     "travel: (3.5,3.5)->(11.5,19.5), (11.5,28.5)->(3.5,12.5), (28.5,3.5)->(20.5,19.5), "
     "(20.5,28.5)->(28.5,12.5). Each starts on a pixel centre, so at every other row x(r) is an integer and "
     "two column centres tie. The tie rule for y-major lines: the LEFT column (ceil(x(r)) - 1) wins in every "
     "octant. Rounding x half-up, or mirroring the x-major code with the wrong sign, draws the right column. "
     "17 rows each, 68 samples.",
     32, 32, TIE_Y, checks=[("ties",)])

case("midpoint_tie_edge_endpoints",
     "Ties from endpoints on pixel edges rather than centres, on a 24x24 canvas: (0.5, 1)->(16.5, 9) has "
     "y(c) = 1 + (c - 0.5)/2, an integer in every even column, ties to the upper row; (23, 22.5)->(15, 6.5) "
     "is y-major with x(r) = 23 - (22.5 - r)/2, an integer in every other row, ties to the left column; "
     "(2, 20.5)->(10, 16.5) falls with slope -1/2 and starts on a vertical pixel edge, so y(c) is never an "
     "integer there (no ties) but the first column is 2 (centre 2.5), not 1. Endpoints on edges and corners "
     "are exactly where fixed-point setups that bias the start by half a pixel disagree.",
     24, 24, [mid((0.5, 1), (16.5, 9)), mid((23, 22.5), (15, 6.5)), mid((2, 20.5), (10, 16.5))],
     checks=[("ties",)])

case("midpoint_slope_one_is_x_major",
     "Lines with |slope| exactly 1 are x-major (|dx| >= |dy|), and here it matters: (0.5, 0)->(8.5, 8) "
     "passes through the points (i + 0.5, i), so in every column y(c) is an integer and the tie goes to the "
     "upper row: pixels (i, i - 1) for columns 0 to 8 (the first is above the canvas). Treated as y-major, "
     "rows 0 to 7 would tie to the left column and draw (i, i) instead. The other three lines are the same "
     "test in the other diagonal directions: (15.5, 8)->(7.5, 16) runs down-left, (16.5, 23)->(24.5, 15) "
     "up-right, and (31, 24.5)->(23, 32.5) down-left from a vertical pixel edge; each ties in every column. "
     "32x32 canvas.",
     32, 32, [mid((0.5, 0), (8.5, 8)), mid((15.5, 8), (7.5, 16)), mid((16.5, 23), (24.5, 15)),
              mid((31, 24.5), (23, 32.5))],
     checks=[("ties",), ("xmajor_at_one",)])

# ---------------------------------------------------------------------------
# 4. Endpoints: centres, corners, edges, sub-pixel.

case("midpoint_endpoints_centres",
     "Lines whose endpoints are all pixel centres, at assorted slopes (3/7, -5/2, 1, 0, -2/9) on a 24x24 "
     "canvas: both end columns (rows) are drawn and both end pixels are the endpoints' own pixels, however "
     "the line runs. A rasterizer that drops the last pixel (half-open like Vulkan) fails on every line.",
     24, 24, [mid((1.5, 1.5), (15.5, 7.5)), mid((20.5, 2.5), (16.5, 12.5)), mid((2.5, 10.5), (12.5, 20.5)),
              mid((22.5, 22.5), (14.5, 22.5)), mid((4.5, 22.5), (22.5, 18.5))])

case("midpoint_endpoints_corners",
     "Lines whose endpoints are all pixel corners (integers) on a 24x24 canvas: (1,1)->(15,7), "
     "(21,2)->(17,13), (3,10)->(13,21), (23,22)->(14,22), (4,23)->(22,18). No column centre is ever an "
     "endpoint, so the first column drawn is the one just inside v0 and the last the one just inside v1; "
     "(23,22)->(14,22) is horizontal on a pixel edge, where y(c) = 22 is an integer in every column and the "
     "whole line goes to the upper row 21.",
     24, 24, [mid((1, 1), (15, 7)), mid((21, 2), (17, 13)), mid((3, 10), (13, 21)), mid((23, 22), (14, 22)),
              mid((4, 23), (22, 18))], checks=[("ties",)])

case("midpoint_endpoints_edges",
     "Endpoints in the middle of pixel edges on a 24x24 canvas: (1.5,1)->(15.5,7) and (20,2.5)->(16,12.5) "
     "have their major coordinate on a centre and their minor one on an edge, (1,10.5)->(11,20.5) the other "
     "way round, and the vertical (12.5,3)->(12.5,9) and horizontal (3,14.5)->(9,14.5) ones run along sample "
     "centres with ends on pixel edges. Whether an end column is drawn depends on comparing its centre with "
     "the endpoint exactly.",
     24, 24, [mid((1.5, 1), (15.5, 7)), mid((20, 2.5), (16, 12.5)), mid((1, 10.5), (11, 20.5)),
              mid((12.5, 3), (12.5, 9)), mid((3, 14.5), (9, 14.5))], checks=[("ties",)])

SUB8 = [mid((3.1015625, 2.7109375), (27.49609375, 9.50390625)),
        mid((28.8984375, 3.125), (22.50390625, 29.49609375)),
        mid((2.50390625, 29.2890625), (30.49609375, 16.5)),
        mid(("123457/1000", "8.0001"), ("17.234567", "21.98765")),
        mid((9.501953125, 29.498046875), (12.498046875, 20.501953125))]
case("midpoint_subpixel_8bits",
     "Sub-pixel endpoints with subpixel_bits 8 on a 32x32 canvas. The first three lines have coordinates "
     "already on the 1/256 grid (3.1015625 = 3 + 26/256, 27.49609375 = 27.5 - 1/256, 22.50390625 = 22.5 + "
     "1/256): their end columns start or stop one 1/256 step away from a column centre, so an end column is "
     "drawn or not by a margin of 1/256. The fourth line has coordinates off the grid (123.457, 8.0001, "
     "17.234567, 21.98765) that must first be snapped to the nearest multiple of 1/256. The fifth is a short "
     "steep line (9.501953125, 29.498046875)->(12.498046875, 20.501953125) whose coordinates all lie exactly "
     "half way between grid points (9.5 + 1/512 is 128.5/256 past 9, 29.5 - 1/512 is 127.5/256 past 29): "
     "ties-to-even snaps each to 128/256, so the line runs from the pixel centre (9.5, 29.5) to the pixel "
     "centre (12.5, 20.5) and draws both end rows, 10 in all. Snapping half down puts its lower end at "
     "29.49609375, above the centre of row 29, which is then not drawn; snapping half up puts its upper "
     "end at 20.50390625, below the centre of row 20; no snapping at all loses both end rows.",
     32, 32, SUB8, checks=[("snap",)])

SUB4 = [mid((2.53125, 3.46875), (29.46875, 11.53125)),
        mid((4.21875, 28.53125), (11.46875, 4.46875)),
        mid((20.46875, 30.03125), (29.53125, 16.96875))]
case("midpoint_subpixel_4bits",
     "subpixel_bits 4 (Vulkan's minimum sub-pixel precision): coordinates snap to multiples of 1/16, ties "
     "to even. Every coordinate here is an odd multiple of 1/32, exactly half way between two 1/16 grid "
     "points: 2.53125 = 2 + 8.5/16 snaps to 2.5 (8 is even), 29.46875 = 29 + 7.5/16 snaps to 29.5, 3.46875 "
     "to 3.5, 4.21875 = 4 + 3.5/16 to 4.25, 16.96875 = 16 + 15.5/16 to 17, and so on, so most endpoints land "
     "on pixel centres or edges, and the end columns and the midpoint ties "
     "depend on the tie rule of the snapping: rounding half up, half down or half away from zero moves an "
     "endpoint off the centre and drops or adds an end pixel or flips a tie. 32x32 canvas.",
     32, 32, SUB4, bits=4, checks=[("snap",), ("ties",)])

# ---------------------------------------------------------------------------
# 5. Long lines.

case("midpoint_long_shallow_2048",
     "Three x-major lines across a 2048x32 canvas. (0.5, 8.5)->(2046.5, 9.5) has slope 1/2046 and is "
     "exactly half way between rows 8 and 9 at column 1023 (c = 1023.5, y = 9): a tie, upper row 8, so the "
     "line steps down at column 1024, not 1023. (2047.5, 2.5)->(0.5, 3.5) runs right to left with slope "
     "-1/2047 and passes y = 3 at c = 1024 (no centre, no tie). (0, 20.00390625)->(2048, 27.99609375) "
     "descends 8 rows less two 1/256 steps over 2048 columns, starting and ending one grid step inside a row. "
     "An incremental DDA in f32 (steps of 1/2046) accumulates rounding error over 2000 steps and can get a "
     "step or the tie wrong; exact (or wide enough fixed-point) arithmetic "
     "gets all {N} pixels right.",
     2048, 32, [mid((0.5, 8.5), (2046.5, 9.5)), mid((2047.5, 2.5), (0.5, 3.5)),
                mid((0, 20.00390625), (2048, 27.99609375))], checks=[("ties",)])

case("midpoint_long_steep_2048",
     "The transpose of midpoint_long_shallow_2048 on a 32x2048 canvas: three y-major lines 2000+ rows long. "
     "(8.5, 0.5)->(9.5, 2046.5) is half way between columns 8 and 9 at row 1023, a tie that goes to the LEFT "
     "column 8; (2.5, 2047.5)->(3.5, 0.5) runs bottom to top; (20.00390625, 0)->(27.99609375, 2048) drifts "
     "8 columns less two grid steps. Error accumulation in a DDA stepping 1/2046 per row gets a step or the "
     "tie wrong.",
     32, 2048, [mid((8.5, 0.5), (9.5, 2046.5)), mid((2.5, 2047.5), (3.5, 0.5)),
                mid((20.00390625, 0), (27.99609375, 2048))], checks=[("ties",)])

# ---------------------------------------------------------------------------
# 6. Zero-length lines.

case("zero_length_lines",
     "Lines with v0 = v1 cover nothing (SPEC 4), whatever the rule: a midpoint line on the pixel centre "
     "(2.5, 2.5) (whose one column centre would otherwise be in the closed interval [2.5, 2.5]), one on the "
     "corner (5, 5), one with last_pixel exclude on (6.5, 1.5), one whose endpoints differ by 1/1024 but snap "
     "to the same point (7.5, 3.5) at 8 subpixel bits, a rectangle of width 5 on (4, 4) and a parallelogram "
     "of width 3 on (3.5, 6.5) (a rectangle or parallelogram of length 0 has no direction). 8x8 canvas, "
     "0 samples covered: a rasterizer that draws a dot, or divides by zero, fails.",
     8, 8, [mid((2.5, 2.5), (2.5, 2.5)), mid((5, 5), (5, 5)), mid((6.5, 1.5), (6.5, 1.5), last_pixel="exclude"),
            mid((7.5, 3.5), (7.5 + 1 / 1024, 3.5)), rect((4, 4), (4, 4), width=5),
            para((3.5, 6.5), (3.5, 6.5), width=3)])

# ---------------------------------------------------------------------------
# 7. Strips and loops.

STRIP = [P(2.5, 2.5), P(20.5, 11.5), P(26.5, 29.5), P(8.5, 37.5), P(3.5, 55.5), P(29.5, 61.5)]
STRIP_TEXT = ("A polyline of 5 segments on a 32x64 canvas through the pixel centres (2.5,2.5) (20.5,11.5) "
              "(26.5,29.5) (8.5,37.5) (3.5,55.5) (29.5,61.5): consecutive segments share their endpoints "
              "exactly, and the segments alternate x-major and y-major and turn through several octants. ")
case("strip_exclude_joints",
     STRIP_TEXT + "With last_pixel: exclude the interval of each segment is half-open at its v1, so the joint "
     "pixel, whose centre is the shared vertex, is drawn once, by the segment that starts there: no sample "
     "is covered twice. The last vertex (29.5, 61.5) is not drawn at all. Vulkan's Bresenham lines behave "
     "this way; a rasterizer that ignores last_pixel draws 4 doubles.",
     32, 64, [mid(STRIP[i], STRIP[i + 1], last_pixel="exclude") for i in range(5)],
     checks=[("max_coverage", 1)])

case("strip_include_joints",
     STRIP_TEXT + "With last_pixel: include (the default) every segment draws both its end pixels, so each "
     "of the 4 joint pixels is covered twice (coverage 2, last primitive the later segment): the doubles are "
     "what the rule says, and a rasterizer that silently drops the last pixel fails here. Compare "
     "strip_exclude_joints.",
     32, 64, [mid(STRIP[i], STRIP[i + 1], last_pixel="include") for i in range(5)],
     checks=[("min_coverage_max", 2), ("max_coverage", 2)])

LOOP = [P(8.5, 8.5), P(40.5, 14.5), P(55.5, 44.5), P(14.5, 53.5)]
case("loop_exclude_quad",
     "A closed quadrilateral drawn as 4 midpoint lines with last_pixel: exclude, each starting where the "
     "previous ended: (8.5,8.5) (40.5,14.5) (55.5,44.5) (14.5,53.5) and back to (8.5,8.5), on a 64x64 canvas. "
     "Two sides are x-major and two y-major, running in all four quadrant directions. Each corner pixel is "
     "drawn exactly once (by the line leaving it) and no sample is covered twice, so a loop of half-open "
     "lines is a clean outline; with include every corner would double.",
     64, 64, [mid(LOOP[i], LOOP[(i + 1) % 4], last_pixel="exclude") for i in range(4)],
     checks=[("max_coverage", 1)])

# ---------------------------------------------------------------------------
# 8. Rectangle lines.

case("rectangle_width_5",
     "Two rectangle lines of width 5 on a 64x64 canvas at non-axis angles, (10.25, 12.75)->(50.5, 40.125) "
     "and (56.75, 8.5)->(40.0078125, 58.9921875): wide rotated rectangles whose corners are irrational. "
     "The side test |q x d| <= (w/2)|d| must be compared squared to stay exact; a rasterizer that expands "
     "the line into two triangles with rounded corners gets border samples wrong.",
     64, 64, [rect((10.25, 12.75), (50.5, 40.125), width=5),
              rect((56.75, 8.5), (40.0078125, 58.9921875), width=5)])

case("rectangle_width_10",
     "A rectangle line of width 10 from (8.5, 50.5) to (56.25, 14.75) on a 64x64 canvas, and one of width "
     "10 whose length 10 is exact (d = (8, -6)) from (20.5, 20.5) to (28.5, 14.5): its caps and sides run "
     "through sample centres (a 3-4-5 triangle), so the fill rule decides many border samples, including "
     "corner samples where a cap meets a side.",
     64, 64, [rect((8.5, 50.5), (56.25, 14.75), width=10), rect((20.5, 20.5), (28.5, 14.5), width=10)],
     checks=[("fill_rule",)])

case("rectangle_width_64",
     "One rectangle line of width 64 on a 128x128 canvas, from (30.5, 40.25) to (97.75, 88.5): a rotated "
     "rectangle about 83 by 64 pixels whose corners reach outside the canvas. Wide lines stress setup "
     "precision: the side test multiplies coordinates by |d|^2 and width^2.",
     128, 128, [rect((30.5, 40.25), (97.75, 88.5), width=64)])

THIN = [rect((1.25, 2.75), (30.75, 2.75), width=1), rect((1.25, 6.125), (30.75, 13.5), width=1),
        rect((1.25, 16.25), (21.25, 26.25), width=1), rect((1.25, 29.5), (23.75, 52), width=1),
        rect((26.125, 30.25), (37.375, 52.75), width=1), rect((40.75, 30.25), (40.75, 60.5), width=1),
        rect((46.75, 2.25), (60.25, 58.25), width=1)]
case("rectangle_thin_slopes",
     "Rectangle lines of width 1 at slopes 0, 1/4, 1/2, 1, 2, vertical and about 4 on a 64x64 canvas. The "
     "thin rectangle's vertical extent in a column is width * sqrt(1 + m^2) for slope m: exactly 1 sample "
     "per column for the horizontal line, 1 or 2 for the slope-1 line (extent 1.414), and for the steep lines "
     "the horizontal extent per row grows the same way. This slope-dependent thickness is what distinguishes "
     "the rectangle rule from the midpoint rule (always 1 per column) and the parallelogram rule (always "
     "width per column).",
     64, 64, THIN)


def border_case(rule_name):
    return [rect((2, 8.5), (14, 8.5), width=2), rect((20, 2.5), (20, 12.5), width=1),
            rect((24.5, 2.5), (32.5, 8.5), width=2)]


BORDER_TEXT = {
    "top-left": "top and left edges own their samples: the horizontal line covers rows 7 and 8 (its top "
                "border y = 7.5 owns row 7; its bottom border y = 9.5 does not own row 9), 24 samples; the "
                "vertical line covers column 19 (left border) from row 2 (its top cap y = 2.5 is owned) to row "
                "11 (its bottom cap y = 12.5 is not), 10 samples",
    "bottom-right": "bottom and right edges own their samples: the horizontal line covers rows 8 and 9, 24 "
                    "samples; the vertical line covers column 20 (right border x = 20.5) from row 3 to row 12 "
                    "(bottom cap y = 12.5 owned, top cap not), 10 samples",
    "top-right": "top and right edges own their samples: the horizontal line covers rows 7 and 8; the "
                 "vertical line covers column 20 from row 2 to row 11",
    "bottom-left": "bottom and left edges own their samples: the horizontal line covers rows 8 and 9; the "
                   "vertical line covers column 19 from row 3 to row 12",
}
def box(xs, ys):
    return [(x, y) for x in xs for y in ys]


BORDER_PIXELS = {  # (rows of the horizontal line, column and rows of the vertical line)
    "top-left": ((7, 8), 19, range(2, 12)), "bottom-right": ((8, 9), 20, range(3, 13)),
    "top-right": ((7, 8), 20, range(2, 12)), "bottom-left": ((8, 9), 19, range(3, 13)),
}
for fr in ("top-left", "bottom-right", "top-right", "bottom-left"):
    rows, col, vrows = BORDER_PIXELS[fr]
    case("rectangle_border_centres_" + fr.replace("-", "_"),
         "Rectangle lines whose borders run exactly through sample centres, so the fill rule %s decides "
         "every border sample. On a 40x16 canvas: a horizontal line (2, 8.5)->(14, 8.5) of width 2 has its "
         "long sides at y = 7.5 and y = 9.5, through the centres of rows 7 and 9 (its caps x = 2 and 14 miss "
         "the centres); a vertical line (20, 2.5)->(20, 12.5) of width 1 has sides x = 19.5 and 20.5 and "
         "caps y = 2.5 and 12.5, all through centres, so its 4 corner samples lie on two border edges each "
         "and are covered only when both edges are owned; and a line (24.5, 2.5)->(32.5, 8.5) of width 2 "
         "with d = (8, 6), |d| = 10, whose sides 6qx - 8qy = +-10 and caps pass through sample centres. "
         "Under %s the %s. The outward normal classifies each edge: (0, -1) top, (0, 1) bottom, nx < 0 left, "
         "nx > 0 right." % (fr, fr, BORDER_TEXT[fr]),
         40, 16, border_case(fr), fill_rule=fr, checks=[("fill_rule",)],
         pixels={0: box(range(2, 14), rows), 1: box([col], vrows)})

# ---------------------------------------------------------------------------
# 9. Parallelogram lines.

case("parallelogram_x_major",
     "X-major parallelogram lines on a 64x64 canvas at several slopes and widths: slope 1/3 width 1, "
     "slope -3/4 width 2.5, slope 0 width 3 (through sample rows: borders at y = 40 and 43 miss the centres), "
     "slope 1 width 1.5 from (4.25, 44.75) (|slope| = 1 is x-major: vertical ends, width measured "
     "vertically), and slope -1/8 width 7. Each column holds a vertical band of exactly `width` whatever the "
     "slope, unlike the rectangle rule.",
     64, 64, [para((2.5, 3.25), (32.5, 13.25), width=1), para((36.125, 30.5), (60.125, 12.5), width=2.5),
              para((3, 41.5), (28.75, 41.5), width=3), para((4.25, 44.75), (18.25, 58.75), width=1.5),
              para((62, 40.25), (30, 44.25), width=7)], checks=[("fill_rule",)])

case("parallelogram_y_major",
     "Y-major parallelogram lines on a 64x64 canvas: slope 3 width 1, slope 4/3 width 2.5 (run bottom to "
     "top), vertical width 3, slope 2 width 2 from the pixel centre (44.5, 30.5) (its sides x(r) +- 1 and "
     "its ends y = 30.5 and 62.5 run through sample centres) and slope 8 width 7 (run bottom to top). The ends are horizontal "
     "and the width is measured horizontally, so each row holds exactly `width` of band.",
     64, 64, [para((3.25, 2.5), (13.25, 32.5), width=1), para((30.5, 60.125), (12.5, 36.125), width=2.5),
              para((41.5, 3), (41.5, 28.75), width=3), para((44.5, 30.5), (60.5, 62.5), width=2),
              para((60.25, 62), (56.25, 30), width=7)], checks=[("fill_rule",)])

for fr in ("top-left", "bottom-right"):
    case("parallelogram_border_centres_" + fr.replace("-", "_"),
         "Parallelogram lines whose borders run through sample centres, fill rule %s, on a 32x16 canvas. "
         "(2.5, 8.5)->(13.5, 8.5) of width 2: sides y = 7.5 and 9.5 and vertical ends x = 2.5 and 13.5, all "
         "through centres; the top side and left end are owned under top-left, the bottom side and right end "
         "under bottom-right, so 22 samples either way but shifted by one row and one column. "
         "(16.5, 2)->(28.5, 8) of width 2, slope 1/2: every other column has both sides on centres, the upper "
         "side's outward normal (1/2, -1) makes it a right edge and the lower side's (-1/2, 1) a left edge. "
         "(18.5, 9.5)->(21.5, 15.5) of width 2, y-major with dx/dy = 1/2: "
         "horizontal ends y = 9.5 (top edge) and 15.5 (bottom edge) through centres, and sides "
         "x(r) +- 1 through centres in every other row, a left side and a right side." % fr,
         32, 16, [para((2.5, 8.5), (13.5, 8.5), width=2), para((16.5, 2), (28.5, 8), width=2),
                  para((18.5, 9.5), (21.5, 15.5), width=2)], fill_rule=fr, checks=[("fill_rule",)],
         pixels={0: box(range(2, 13), (7, 8)) if fr == "top-left" else box(range(3, 14), (8, 9))})

case("parallelogram_slope_one_is_x_major",
     "A parallelogram line with |slope| exactly 1 is x-major: its ends are vertical and its width is measured "
     "vertically. (2.25, 2)->(12.25, 12) of width 4 on a 32x32 canvas covers x in [2.25, 12.25] and "
     "|p.y - y(p.x)| <= 2; read as y-major its ends would be horizontal (y in [2, 12]) and the two end "
     "triangles would differ. A second line (29.75, 18)->(19.75, 28) of width 3 checks the other diagonal.",
     32, 32, [para((2.25, 2), (12.25, 12), width=4), para((29.75, 18), (19.75, 28), width=3)],
     checks=[("xmajor_at_one",)])

# ---------------------------------------------------------------------------
# 10. Interpolation along lines.


def iv(x, y, z, w, attrs):
    return V(x, y, z=z, w=w, attributes=attrs)


def interp_lines(parameter, interpolation):
    kw = dict(parameter=parameter, interpolation=interpolation)
    return [
        mid(iv(2.5, 3.25, 0.25, 0.5, [1, 0, 0.5]), iv(61.5, 20.75, 0.75, 4, [0, 1, -2]), **kw),
        mid(iv(60.25, 26.5, -1, 4, [0, 0, 1]), iv(44.75, 62.5, 3, 0.5, [1, 1, 0]), **kw),
        rect(iv(6.5, 30.5, 0, 0.5, [1, 0, 0]), iv(30.5, 48.5, 1, 4, [0, 0, 1]), width=12, **kw),
        para(iv(34.25, 30.125, 0.5, 1, [0, 1, 0]), iv(40.75, 58.625, 0.125, 3, [1, 0, "1/3"]), width=6, **kw),
        para(iv(4.5, 57.5, 2, 2, [0.25, 0.5, 0.75]), iv(31.5, 61.5, -2, 0.75, [0.75, 0.5, 0.25]), width=3, **kw),
    ]


INTERP_TEXT = ("Five lines on a 64x64 canvas carrying depth z and three attributes (r, g, b), with w from "
               "0.5 to 4: two midpoint lines (x-major and y-major), a rectangle of width 12 and two "
               "parallelograms of widths 6 and 3. The parameter t is clamped to [0, 1]: with parameter major "
               "the rectangle's corner samples lie beyond its ends along the major axis; with parameter "
               "projected the parallelograms' end samples (and an end sample of the y-major midpoint line) "
               "project beyond the segment. ")
PARAM_TEXT = {
    "major": "parameter: major: t = (c - x0)/(x1 - x0) for the sample's x (y for y-major lines), the value "
             "an incremental midpoint algorithm steps; samples off the segment still get the t of their "
             "column. ",
    "projected": "parameter: projected: t = ((p - v0).d)/|d|^2, the exact projection of the sample onto the "
                 "segment, which differs from the major-axis parameter for every sample off the line's axis. ",
}
INTERP_KIND = {
    "linear": "interpolation: linear: each attribute is (1 - t) a0 + t a1 in screen space. ",
    "perspective": "interpolation: perspective: ((1-t) a0/w0 + t a1/w1)/((1-t)/w0 + t/w1); with w ratios of "
                   "8 the perspective and linear values differ by far more than the tolerance. ",
}
for parameter in ("major", "projected"):
    for interpolation in ("linear", "perspective"):
        checks = [("parameter",), ("clamp",)]
        if interpolation == "perspective":
            checks.append(("perspective",))
        case("interpolation_%s_%s" % (parameter, interpolation),
             INTERP_TEXT + PARAM_TEXT[parameter] + INTERP_KIND[interpolation] +
             "Depth is always (1 - t) z0 + t z1. A rasterizer that interpolates with the other parameter, "
             "does not clamp, or confuses linear and perspective, fails the interpolation check.",
             64, 64, interp_lines(parameter, interpolation), checks=checks)

case("interpolation_flat",
     INTERP_TEXT + "interpolation: flat: every covered sample takes the first vertex's attributes exactly as "
     "written (1/3 included), but depth is still interpolated linearly, (1 - t) z0 + t z1, with the "
     "projected parameter. No two of the lines overlap.",
     64, 64, [p.with_(interpolation="flat", parameter="projected") for p in interp_lines(None, None)])

# ---------------------------------------------------------------------------
# 11. Canvas borders and far endpoints.

case("lines_cross_canvas_border",
     "Lines that start or end outside a 32x32 canvas: a midpoint line (-10.5, 5.25)->(40.75, 20.5) crossing "
     "it left to right, a steep one (16.5, -8)->(20.25, 45) crossing top to bottom, one with last_pixel "
     "exclude whose excluded end (31.5, 40.5) lies outside (so nothing inside is excluded), a rectangle of "
     "width 4 from (-5, -5) to (40, 30) and a parallelogram of width 3 from (-3, 28.5) to (35, 31.5). Only "
     "the samples inside the canvas count; a rasterizer that starts its columns at the clipped edge "
     "instead of at the true v0 computes y(c) from the wrong origin.",
     32, 32, [mid((-10.5, 5.25), (40.75, 20.5)), mid((16.5, -8), (20.25, 45)),
              mid((2.5, -3.5), (31.5, 40.5), last_pixel="exclude"), rect((-5, -5), (40, 30), width=4),
              para((-3, 28.5), (35, 31.5), width=3)])

case("lines_far_endpoints",
     "Lines with endpoints at the coordinate limits +-32768 (SPEC 8) crossing a 64x64 canvas: the diagonal "
     "(-32768, -32768)->(32768, 32768) through the sample centres (i + 0.5, i + 0.5); the anti-diagonal "
     "(-32704.5, 32768)->(32767.5, -32704), on which y(c) = 63.5 - c is an integer in every column, a tie that "
     "goes to the upper row 62 - i; a very shallow line (-32768, 20.25)->(32768, 43.75) that rises 23.5 "
     "rows over 65536 columns, only about 0.023 rows across the canvas; a steep rectangle of width 3 "
     "(30.125, -32768)->(33.875, 32768) and a parallelogram of width 5 (32768, 50.5)->(-32768, 10.5). "
     "Squared lengths reach 2^33 and the rectangle's squared side test about 2^70 in units of 1/256: "
     "fixed-point setups with 32-bit or even 64-bit intermediates overflow, and f32 slopes lose the tiny rise.",
     64, 64, [mid((-32768, -32768), (32768, 32768)), mid((-32704.5, 32768), (32767.5, -32704)),
              mid((-32768, 20.25), (32768, 43.75)), rect((30.125, -32768), (33.875, 32768), width=3),
              para((32768, 50.5), (-32768, 10.5), width=5)], checks=[("ties",)])

