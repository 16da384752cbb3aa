"""The diamond-exit line cases (SPEC.md section 4.2): worked examples, the
diamond's open and closed edges and corners, ties, strips, long lines and
interpolation. Expectations come from check.py.
"""

from casegen.casefile import P
from casegen.lines.build import case, dia, fmt_px
from casegen.lines.cases import STAR_TEXT, iv, star_lines


# ---------------------------------------------------------------------------
# 12. Diamond-exit lines (SPEC.md section 4.2).

DIAMOND_TEXT = ("Rule diamond-exit (SPEC 4.2): each pixel has a diamond |u| + |v| < 1/2 around its centre, "
                "plus its lower-left and lower-right edges and bottom corner (and, for y-major lines, its "
                "right corner; never its upper edges, top or left corner); a pixel is lit when the segment "
                "meets its diamond and v1 does not lie in it. ")

WE_DIA_A = [(1, 1), (2, 1), (3, 2), (4, 2), (5, 3), (6, 3), (7, 4), (8, 4)]
WE_DIA_B = [(2, 6), (2, 7), (3, 8), (3, 9)]
case("diamond_exit_worked_example",
     "Worked example of the diamond-exit rule (SPEC 4.2), two lines on a 12x12 canvas. The diamond of the "
     "pixel with centre (xc, yc) is, with u = x - xc and v = y - yc (y down), the points with -u - v < 1/2 "
     "and u - v < 1/2 (the upper-left and upper-right edges excluded), -u + v <= 1/2 and u + v <= 1/2 (the "
     "lower-left and lower-right edges included): its bottom corner (0, 1/2) is in it, its top (0, -1/2) and "
     "left (-1/2, 0) corners are not, and its right corner (1/2, 0) is in it only for y-major lines. A "
     "pixel is lit when the segment meets its diamond and the second endpoint v1 is not in it. "
     "Line 1 runs from the pixel centre v0 = (1.5, 1.5) to the pixel centre v1 = (9.5, 5.5): d = (8, 4), "
     "x-major. At the column centres c = 1.5, 3.5, 5.5, 7.5, 9.5 it passes through the pixel centres of "
     "(1,1) (3,2) (5,3) (7,4) (9,5), crossing the inside of their diamonds. At c = 2.5, 4.5, 6.5, 8.5 its "
     "height y = 1.5 + (c - 1.5)/2 is an integer (2, 3, 4, 5): the point (2.5, 2) is the BOTTOM corner of "
     "the diamond of (2,1) and the TOP corner of the diamond of (2,2). The line's slope 1/2 is shallower than "
     "the diamond edges (slope +-1), so it touches each of the two diamonds at that one point and enters "
     "neither: (2,1) is lit because its bottom corner belongs to its diamond, (2,2) is not because its top "
     "corner does not. The same happens at (4,2)/(4,3), (6,3)/(6,4) and (8,4)/(8,5). Between those points "
     "the line meets no other diamond. The first pixel (1,1) contains v0 and is lit: only v1 is excluded. "
     "The last pixel (9,5) has v1 = (9.5, 5.5) at its centre, inside its diamond: the line never exits it, "
     "so it is NOT lit. Line 1 lights " + fmt_px(WE_DIA_A) + ". "
     "Line 2 runs from (2.5, 6.5) to (4.5, 10.5): d = (2, 4), y-major. At the row centres 6.5, 8.5, 10.5 "
     "it passes the pixel centres of (2,6) (3,8) (4,10); at r = 7.5 and 9.5 its x = 2.5 + (r - 6.5)/2 is an "
     "integer (3 and 4): (3, 7.5) is the RIGHT corner of the diamond of (2,7) and the LEFT corner of that of "
     "(3,7), and the line (slope 2, steeper than the edges) touches both only there. The line is y-major, so "
     "the right corner belongs to the diamond: (2,7) is lit; the left corner never does: (3,7) is not. (An "
     "x-major line through that corner would light neither.) Again the last pixel (4,10) contains v1 and is "
     "not lit. Line 2 lights " + fmt_px(WE_DIA_B) + ". 12 samples in all: the pixels of "
     "midpoint_worked_example less the two last pixels. Drawn from v1 to v0 the lines would light (9,5) and "
     "(4,10) instead of (1,1) and (2,6).",
     12, 12, [dia((1.5, 1.5), (9.5, 5.5)), dia((2.5, 6.5), (4.5, 10.5))],
     checks=[("diamond", "include_last"), ("diamond", "no_right_corner"), ("diamond", "upper"),
             ("diamond", "closed"), ("unlit", 0, 2, 2), ("unlit", 0, 9, 5), ("unlit", 1, 3, 7)],
     pixels={0: WE_DIA_A, 1: WE_DIA_B})

case("diamond_endpoints_centres",
     DIAMOND_TEXT + "Eight lines on a 24x24 canvas whose endpoints are all pixel centres, one in each octant: "
     "x-major (1.5,1.5)->(9.5,4.5) right-down, (22.5,1.5)->(14.5,4.5) left-down, (9.5,22.5)->(1.5,19.5) "
     "left-up, (14.5,22.5)->(22.5,19.5) right-up; y-major (2.5,7.5)->(5.5,16.5) down-right, "
     "(21.5,16.5)->(18.5,7.5) up-left, (8.5,16.5)->(11.5,7.5) up-right, (15.5,7.5)->(12.5,16.5) down-left. "
     "A centre is inside its pixel's diamond, so every line lights its v0 pixel and not its v1 pixel, "
     "whichever way it runs: 8 or 9 pixels each, one fewer than the midpoint rule. A rasterizer that keeps "
     "the last pixel, or drops the first one instead (an entry rule), fails every line.",
     24, 24, [dia((1.5, 1.5), (9.5, 4.5)), dia((22.5, 1.5), (14.5, 4.5)), dia((9.5, 22.5), (1.5, 19.5)),
              dia((14.5, 22.5), (22.5, 19.5)), dia((2.5, 7.5), (5.5, 16.5)), dia((21.5, 16.5), (18.5, 7.5)),
              dia((8.5, 16.5), (11.5, 7.5)), dia((15.5, 7.5), (12.5, 16.5))],
     checks=[("diamond", "include_last"), ("diamond", "exclude_first"), ("lit", 0, 1, 1),
             ("unlit", 0, 9, 4), ("lit", 5, 21, 16), ("unlit", 5, 18, 7)])

case("diamond_endpoints_edges",
     DIAMOND_TEXT + "Eight lines on a 24x24 canvas with one endpoint on a diamond edge, a quarter pixel from "
     "the centre along each axis (u, v = +-1/4). Lower edges are in the diamond, upper ones are not. "
     "(10.5,1.5)->(2.25,4.75), x-major: it crosses the inside of the diamond of (2,4) and ends on its "
     "lower-left edge: v1 is in that diamond, so (2,4) is not lit (with v1 1/256 further out it would be). "
     "(13.75,1.75)->(21.5,4.5), x-major: v0 on the lower-right edge of (13,1), and the line leaves away from "
     "the diamond at once: it meets the diamond only at v0, which is in it, so (13,1) is lit. (2.5,12.5)->(12.75,8.25), x-major: v1 on the upper-right edge of "
     "(12,8); the line arrives through the inside of that diamond and v1 is not in it (upper edge), so "
     "(12,8) IS lit. (20.25,12.25)->(14.5,8.5), x-major: v0 on the upper-left edge of (20,12), and the line "
     "leaves away from the diamond: it touches the closed diamond only at v0, which is not in it, so (20,12) "
     "is not lit. The y-major lines repeat this: (2.5,14.5)->(5.75,22.75) ends on the lower-right edge of "
     "(5,22) (not lit), (10.25,14.75)->(13.5,22.5) starts on the lower-left edge of (10,14) (lit), "
     "(16.5,22.5)->(18.25,14.25) ends on the upper-left edge of (18,14) arriving through its inside (lit), "
     "(22.75,14.25)->(21.5,3.5) starts on the upper-right edge of (22,14) leaving upward (not lit). A closed "
     "or an open diamond, or one whose upper edges are included instead (y up), gets some of these wrong.",
     24, 24, [dia((10.5, 1.5), (2.25, 4.75)), dia((13.75, 1.75), (21.5, 4.5)), dia((2.5, 12.5), (12.75, 8.25)),
              dia((20.25, 12.25), (14.5, 8.5)), dia((2.5, 14.5), (5.75, 22.75)),
              dia((10.25, 14.75), (13.5, 22.5)), dia((16.5, 22.5), (18.25, 14.25)),
              dia((22.75, 14.25), (21.5, 3.5))],
     checks=[("diamond", "closed"), ("diamond", "open"), ("diamond", "upper"),
             ("unlit", 0, 2, 4), ("lit", 1, 13, 1), ("lit", 2, 12, 8), ("unlit", 3, 20, 12),
             ("unlit", 4, 5, 22), ("lit", 5, 10, 14), ("lit", 6, 18, 14), ("unlit", 7, 22, 14)])

case("diamond_endpoints_corners",
     DIAMOND_TEXT + "Seven lines on a 24x24 canvas with an endpoint on a diamond corner, the middle of a "
     "pixel edge, which is the corner of two diamonds at once. (2.5,1.5)->(10.5,3), x-major: v1 is the "
     "bottom corner of (10,2), in its diamond, so (10,2) is not lit, and the top corner of (10,3), which the "
     "line touches only there (not in it): not lit either. (5.5,20.5)->(6.5,12), y-major upward: v1 is the "
     "top corner of (6,12), which the line reaches through the inside of that diamond: (6,12) lit, while "
     "(6,11), whose bottom corner v1 is, is not. (14.5,12)->(16.5,3.5), upward: v0 is the top corner of "
     "(14,12) (the line leaves it at once: not lit) and the bottom corner of (14,11) (in it: lit). "
     "(12,16.5)->(2.5,18.5), x-major leftward: v0 is the left corner of (12,16) (never in it: not lit) and the "
     "right corner of (11,16), not in it for an x-major line, but the line crosses that diamond's inside: "
     "lit. (19.5,13.5)->(21,20.5), y-major: v1 is the right corner of (20,20), in it for a y-major line: "
     "(20,20) not lit. (12.5,22.5)->(18,21.5), x-major: v1 is the right corner of (17,21), NOT in it for an "
     "x-major line: (17,21) lit. (3,2.5)->(5,10.5), y-major: v0 is the right corner of (2,2), in its diamond "
     "for a y-major line, and the segment meets that diamond only there: (2,2) is lit although the line never "
     "enters the pixel's square; (3,2), whose left corner v0 is, is not. Including or excluding the right "
     "corner for every line, or closing, opening or flipping the diamond, changes the result.",
     24, 24, [dia((2.5, 1.5), (10.5, 3)), dia((5.5, 20.5), (6.5, 12)), dia((14.5, 12), (16.5, 3.5)),
              dia((12, 16.5), (2.5, 18.5)), dia((19.5, 13.5), (21, 20.5)), dia((12.5, 22.5), (18, 21.5)),
              dia((3, 2.5), (5, 10.5))],
     checks=[("diamond", "no_right_corner"), ("diamond", "right_corner_always"), ("diamond", "closed"),
             ("diamond", "open"), ("diamond", "upper"),
             ("unlit", 0, 10, 2), ("unlit", 0, 10, 3), ("lit", 1, 6, 12), ("unlit", 1, 6, 11),
             ("unlit", 2, 14, 12), ("lit", 2, 14, 11), ("unlit", 3, 12, 16), ("lit", 3, 11, 16),
             ("unlit", 4, 20, 20), ("unlit", 4, 21, 20), ("lit", 5, 17, 21), ("lit", 6, 2, 2),
             ("unlit", 6, 3, 2)])

case("diamond_diagonals",
     DIAMOND_TEXT + "Lines of slope +-1 (x-major: |dx| >= |dy|) on a 32x32 canvas. (0.5,0.5)->(10.5,10.5) "
     "runs through the pixel centres and the pixel corners (i, i), which lie in no diamond: it lights "
     "(0,0)...(9,9), not (10,10) which holds v1. (2,14.5)->(12,24.5), half a pixel off (y = x + 12.5), runs "
     "exactly ALONG the lower-left edges of the diamonds of (i, i+12), which are included, and along the "
     "upper-right edges of (i, i+13), which are not, through the diamond corners (i, i+12.5) and "
     "(i+0.5, i+13): it lights (2,14)...(11,23). Its v0 is the left corner of (2,14) (excluded, but the "
     "segment goes on along that diamond's lower-left edge) and its v1 is the left corner of (12,24) and the "
     "right corner of (11,24), in neither for an x-major line. Read as y-major, the right corners on the line "
     "would light (i, i+13) too. (24.5,14)->(14.5,4) runs up-left along y = x - 10.5, the lower-left edges "
     "of (i+11, i): v0 is the bottom corner of (24,13) (lit), v1 the bottom corner of (14,3) (not lit: v1 "
     "is in it). (31.5,0.5)->(21.5,10.5) is the anti-diagonal through centres. (20,30.5)->(30,20.5) runs along "
     "y = 50.5 - x, the lower-right edges of the pixels with x + y = 49 (included) and the upper-left edges "
     "of those with x + y = 50 (excluded): it lights (20,29)...(29,20); its v1 is the right corner of "
     "(29,20), not in it for an x-major line, so (29,20) is lit.",
     32, 32, [dia((0.5, 0.5), (10.5, 10.5)), dia((2, 14.5), (12, 24.5)), dia((24.5, 14), (14.5, 4)),
              dia((31.5, 0.5), (21.5, 10.5)), dia((20, 30.5), (30, 20.5))],
     checks=[("xmajor_at_one",), ("diamond", "upper"), ("diamond", "closed"), ("diamond", "open"),
             ("unlit", 0, 10, 10), ("lit", 1, 11, 23), ("unlit", 1, 11, 24), ("lit", 2, 24, 13),
             ("unlit", 2, 14, 3), ("unlit", 2, 14, 4), ("lit", 4, 29, 20)],
     pixels={1: [(i, i + 12) for i in range(2, 12)], 4: [(i, 49 - i) for i in range(20, 30)]})

case("diamond_axis_lines",
     DIAMOND_TEXT + "Horizontal and vertical lines on a 24x16 canvas. (1.5,2.5)->(10.5,2.5) runs through "
     "the centres of row 2 and lights columns 1 to 9 (v1 holds (10,2)). (1,5)->(11,5) runs along the pixel "
     "border y = 5, through the bottom corners of row 4 (included) and the top corners of row 5 (excluded), "
     "touching each diamond in one point: it lights row 4, columns 1 to 10 (its endpoints are pixel corners, "
     "in no diamond). (11.5,8)->(1.5,8) runs leftward along y = 8 from the bottom corner of (11,7) (lit) to "
     "the bottom corner of (1,7) (v1 is in it: not lit): row 7, columns 2 to 11. (14.5,1.5)->(14.5,10.5) "
     "runs through the centres of column 14, rows 1 to 9. (17,1)->(17,11) is y-major along the pixel border "
     "x = 17, through the right corners of column 16 (included for a y-major line) and the left corners of "
     "column 17 (never): it lights column 16, rows 1 to 10; a rasterizer that never includes the right "
     "corner lights nothing. (20,12.5)->(20,2.5) runs upward along x = 20 from the right corner of (19,12) "
     "(lit) to the right corner of (19,2) (v1 is in it: not lit): column 19, rows 3 to 12.",
     24, 16, [dia((1.5, 2.5), (10.5, 2.5)), dia((1, 5), (11, 5)), dia((11.5, 8), (1.5, 8)),
              dia((14.5, 1.5), (14.5, 10.5)), dia((17, 1), (17, 11)), dia((20, 12.5), (20, 2.5))],
     checks=[("diamond", "no_right_corner"), ("diamond", "upper")],
     pixels={0: [(i, 2) for i in range(1, 10)], 1: [(i, 4) for i in range(1, 11)],
             2: [(i, 7) for i in range(2, 12)], 3: [(14, j) for j in range(1, 10)],
             4: [(16, j) for j in range(1, 11)], 5: [(19, j) for j in range(3, 13)]})

DSTRIP = [P(2.5, 2.5), P(10, 20.5), P(26.5, 26), P(8.25, 37.75), P(3.75, 55.25), P(29.5, 61.5)]
DSTRIP_TEXT = ("A polyline of 5 diamond-exit segments on a 32x64 canvas through (2.5,2.5) (10,20.5) (26.5,26) "
               "(8.25,37.75) (3.75,55.25) (29.5,61.5): consecutive segments share their endpoints exactly, "
               "mix y-major and x-major, and the joints are of every kind: (10,20.5) the right corner "
               "of (9,20) and left corner of (10,20), (26.5,26) the top corner of (26,26) and bottom corner "
               "of (26,25), (8.25,37.75) on the lower-left edge of (8,37), (3.75,55.25) on the upper-right "
               "edge of (3,55). " + DIAMOND_TEXT)
case("diamond_strip",
     DSTRIP_TEXT + "Drawn forward, each segment ends where the next starts: a joint pixel whose diamond "
     "holds the joint is lit only by the segment leaving it ((26,25) by the third segment, (8,37) by the fourth), "
     "and no sample is covered twice. At (10,20.5) the y-major segment 1 ends on the right corner of (9,20), "
     "in its diamond, and the x-major segment 2 leaves it away from (9,20), whose right corner is not in its "
     "diamond: (9,20) is lit by neither. (3,55) is lit by neither: the joint is on its excluded upper edge "
     "and both segments stay outside its diamond. The first vertex's pixel (2,2) is lit, the last one's "
     "(29,61) is not. Compare diamond_strip_reversed.",
     32, 64, [dia(DSTRIP[i], DSTRIP[i + 1]) for i in range(5)],
     checks=[("max_coverage", 1), ("lit", 0, 2, 2), ("unlit", 4, 29, 61), ("unlit", 0, 9, 20),
             ("unlit", 1, 9, 20), ("unlit", 1, 26, 25), ("lit", 2, 26, 25), ("unlit", 2, 8, 37),
             ("lit", 3, 8, 37), ("unlit", 3, 3, 55), ("unlit", 4, 3, 55)])
case("diamond_strip_reversed",
     "The segments of diamond_strip, each drawn in the other direction (segment i from vertex i+1 to "
     "vertex i). The diamond-exit rule depends on the direction, and the reversed set DIFFERS: the pixel "
     "(2,2) of the first vertex is no longer lit, the pixel (29,61) of the last vertex now is, and (9,20) is "
     "now lit: the reversed first segment is y-major and STARTS on the right corner of (9,20), which a "
     "y-major line's diamond includes, while the reversed second segment is x-major and ends there, "
     "arriving from the right without entering that diamond. The joint pixels (26,25) and (8,37) are lit once as before but by the other segment (the "
     "one that now starts there), and no sample is covered twice. " + DSTRIP_TEXT,
     32, 64, [dia(DSTRIP[i + 1], DSTRIP[i]) for i in range(5)],
     checks=[("max_coverage", 1), ("differs_from", "diamond_strip"), ("unlit", 0, 2, 2),
             ("lit", 4, 29, 61), ("lit", 0, 9, 20), ("lit", 1, 26, 25), ("lit", 2, 8, 37)])

case("diamond_joint_right_corner",
     DIAMOND_TEXT + "Two 2-segment polylines on a 12x12 canvas whose joint is a right corner, where x-major "
     "and y-major diamonds differ. (1.5,3.5)->(6,5.5) is x-major and ends on the right corner of (5,5): not "
     "in its diamond for an x-major line, and the line crosses that diamond's inside, so it lights (5,5). "
     "(6,5.5)->(8,10.5) is y-major and starts on the same right corner, which is in (5,5)'s diamond for a "
     "y-major line, so it lights (5,5) as well: (5,5) is covered TWICE. Sharing an endpoint does not always "
     "prevent a double pixel under the rule as written: an x-major segment followed by a y-major one at a "
     "right corner doubles it. The other polyline, (11.5,5.5)->(10,10.5)->(5.5,11.5), is the opposite order: "
     "the y-major segment ends on the right corner of (9,10), in its diamond (not lit), and the x-major one "
     "lights (9,10) as it leaves through that diamond's inside: no double.",
     12, 12, [dia((1.5, 3.5), (6, 5.5)), dia((6, 5.5), (8, 10.5)),
              dia((11.5, 5.5), (10, 10.5)), dia((10, 10.5), (5.5, 11.5))],
     checks=[("min_coverage_max", 2), ("max_coverage", 2), ("diamond", "no_right_corner"),
             ("lit", 0, 5, 5), ("lit", 1, 5, 5), ("unlit", 2, 9, 10), ("lit", 3, 9, 10)])

case("diamond_star_16",
     STAR_TEXT + DIAMOND_TEXT + "Drawn outward, centre to tip: every line lights the centre pixel (32,32), "
     "which holds its v0, so it is covered 16 times, and no line lights its tip pixel, which holds its v1: "
     "24 pixels per line. The slope +-1/2 and +-2 lines pass exactly through diamond corners in every other "
     "column (row): the bottom corner is lit and the top corner is not for x-major lines, and the right "
     "corner is lit and the left corner is not for y-major lines, in every octant.",
     64, 64, star_lines(dia), checks=[("min_coverage_max", 16), ("diamond", "no_right_corner"),
                                      ("diamond", "upper"), ("diamond", "include_last")])
case("diamond_star_16_reversed",
     "The 16 lines of diamond_star_16 drawn inward, tip to centre. The rule depends on the direction: now "
     "every tip pixel is lit and the centre pixel (32,32) is lit by none, so the set differs from "
     "diamond_star_16 by exactly those 17 pixels; the pixels between the ends are the same. Near the centre "
     "lines of neighbouring directions share some pixels, covered 2 or 3 times. " + STAR_TEXT,
     64, 64, star_lines(dia, inward=True),
     checks=[("differs_from", "diamond_star_16"), ("uncovered", 32, 32)])

case("diamond_subpixel_8bits",
     DIAMOND_TEXT + "Sub-pixel endpoints with subpixel_bits 8 on a 32x32 canvas; coordinates snap to "
     "multiples of 1/256, ties to even. (20.5,1.5)->(12.248046875,4.751953125) crosses the inside of the "
     "diamond of (12,4); its v1 is half way between grid points on both axes (3135.5/256 and 1216.5/256) and "
     "snaps to (12.25, 4.75), on the lower-left edge of (12,4): in its diamond, not lit; snapped half up or "
     "half down it moves 1/256 off the edge, outside the diamond, and (12,4) is lit. "
     "(16.5,12.5)->(20.498046875,6.001953125) snaps v1 to (20.5, 6), the top corner of (20,6), reached "
     "through its inside: lit; with y rounded half up v1 lands 1/256 inside that diamond and (20,6) is not "
     "lit. (9.998046875,24.501953125)->(12,31.5) snaps v0 to (10, 24.5), the right corner of (9,24), "
     "which this y-major line lights through that corner alone; a y rounded up leaves the diamond. The last "
     "line has endpoints off the grid (3.10156, 20.7109)->(27.4987, 28.0001), which must be snapped before "
     "anything else. Left unsnapped, the first line's v1 lies off the edge and (12,4) is lit.",
     32, 32, [dia((20.5, 1.5), (12.248046875, 4.751953125)), dia((16.5, 12.5), (20.498046875, 6.001953125)),
              dia((9.998046875, 24.501953125), (12, 31.5)), dia(("3.10156", "20.7109"), ("27.4987", "28.0001"))],
     checks=[("snap",), ("unlit", 0, 12, 4), ("lit", 1, 20, 6), ("lit", 2, 9, 24)])

case("diamond_subpixel_4bits",
     DIAMOND_TEXT + "subpixel_bits 4 (Vulkan's minimum): every coordinate is an odd multiple of 1/32, half "
     "way between two 1/16 grid points, and snaps to the even one. (20.46875,1.53125)->(12.28125,4.71875) "
     "becomes (20.5,1.5)->(12.25,4.75), crossing the inside of the diamond of (12,4) and ending on its "
     "lower-left edge: not lit. "
     "(26.53125,12.46875)->(20.46875,3.96875) becomes (26.5,12.5)->(20.5,4), y-major, ending on the bottom "
     "corner of (20,3) (in it: not lit) after crossing the inside of (20,4), whose top corner v1 is (lit). "
     "(16.03125,14.53125)->(16.03125,30.46875) becomes the vertical (16,14.5)->(16,30.5) along the pixel "
     "border x = 16: through the right corners of column 15, which this y-major line lights, rows 14 to 29 "
     "(v1 is the right corner of (15,30): not lit). Rounding half up, away from zero or to odd, or not "
     "snapping at all, moves ends off the corners and edges, or the vertical line off the border into "
     "column 16.",
     32, 32, [dia((20.46875, 1.53125), (12.28125, 4.71875)), dia((26.53125, 12.46875), (20.46875, 3.96875)),
              dia((16.03125, 14.53125), (16.03125, 30.46875))], bits=4,
     checks=[("snap",), ("unlit", 0, 12, 4), ("unlit", 1, 20, 3), ("lit", 1, 20, 4)],
     pixels={2: [(15, j) for j in range(14, 30)]})

case("diamond_long_shallow_1200",
     DIAMOND_TEXT + "Three x-major lines across a 1200x8 canvas. (0.5,1.5)->(1100.5,2.5) has slope 1/1100 "
     "and crosses y = 2 exactly at x = 550.5, the bottom corner of (550,1) (lit) and top corner of (550,2) "
     "(not lit): row 1 for columns 0 to 550, row 2 for columns 551 to 1099, and not (1100,2), which holds "
     "v1: 1100 pixels. (1199.5,5.5)->(0.5,4.5) runs right to left with slope 1/1199 and crosses y = 5 at the "
     "pixel corner x = 600, in no diamond; it lights 1199 pixels, all but its v1 pixel (0,4). "
     "(0,6.00390625)->(1200,7.99609375) descends almost two rows over 1200 columns, starting and ending "
     "1/256 inside rows 6 and 7. An incremental DDA in f32 drifts over 1000+ steps and gets the corner "
     "crossing or a step wrong; exact arithmetic gets all {N} pixels.",
     1200, 8, [dia((0.5, 1.5), (1100.5, 2.5)), dia((1199.5, 5.5), (0.5, 4.5)),
               dia((0, 6.00390625), (1200, 7.99609375))],
     checks=[("lit", 0, 550, 1), ("unlit", 0, 550, 2), ("lit", 0, 551, 2), ("unlit", 0, 1100, 2),
             ("unlit", 1, 0, 4), ("diamond", "upper")])

case("diamond_long_steep_1200",
     DIAMOND_TEXT + "The transpose of diamond_long_shallow_1200 on an 8x1200 canvas: three y-major lines "
     "1100 to 1200 rows long. (1.5,0.5)->(2.5,1100.5) crosses x = 2 exactly at y = 550.5, the right corner "
     "of (1,550), which a y-major line's diamond includes (lit), and the left corner of (2,550) (not lit); "
     "(5.5,1199.5)->(4.5,0.5) runs bottom to top; (6.00390625,0)->(7.99609375,1200) drifts almost two "
     "columns. {N} pixels.",
     8, 1200, [dia((1.5, 0.5), (2.5, 1100.5)), dia((5.5, 1199.5), (4.5, 0.5)),
               dia((6.00390625, 0), (7.99609375, 1200))],
     checks=[("lit", 0, 1, 550), ("unlit", 0, 2, 550), ("lit", 0, 2, 551), ("unlit", 0, 2, 1100),
             ("diamond", "no_right_corner")])

case("diamond_far_endpoints",
     DIAMOND_TEXT + "Lines with endpoints at the coordinate limits +-32768 (SPEC 8) crossing a 64x64 canvas, "
     "so neither endpoint's diamond is on the canvas and every canvas pixel the line meets is lit. The "
     "diagonal (-32768,-32768)->(32768,32768) through the pixel centres lights (i, i). The anti-diagonal "
     "(-32704.5,32768)->(32767.5,-32704), y = 63.5 - x, runs along the lower-right edges of the pixels with "
     "x + y = 62 (lit) and the upper-left edges of those with x + y = 63 (not lit). The very shallow "
     "(-32768,20.25)->(32768,43.75) rises 23.5 rows over 65536 columns. The steep (30.125,-32768)->"
     "(33.875,32768) stays within 0.004 of x = 32 on the canvas. The vertical (40,32768)->(40,-32768) runs "
     "up the pixel border x = 40, through the right corners of column 39, which this y-major line lights. "
     "In units of 1/256 the coordinates reach 2^23 and their products 2^46: 32-bit setups overflow, and f32 "
     "slopes lose the shallow line's rise.",
     64, 64, [dia((-32768, -32768), (32768, 32768)), dia((-32704.5, 32768), (32767.5, -32704)),
              dia((-32768, 20.25), (32768, 43.75)), dia((30.125, -32768), (33.875, 32768)),
              dia((40, 32768), (40, -32768))],
     checks=[("diamond", "no_right_corner"), ("diamond", "upper")],
     pixels={0: [(i, i) for i in range(64)], 1: [(i, 62 - i) for i in range(63)],
             4: [(39, j) for j in range(64)]})

case("diamond_colour_interpolation",
     DIAMOND_TEXT + "Colour along diamond-exit lines (SPEC 5) on a 32x32 canvas: four lines carrying depth z "
     "and three attributes (r, g, b), with w from 0.5 to 4. Lines 1 and 2 use parameter major, "
     "t = (c - x0)/(x1 - x0) for the pixel centre's x (y for the y-major line 2), and perspective "
     "interpolation; line 1 starts at (2.75, 3.5), a quarter pixel right of the centre of (2,3), which it "
     "lights (v0 is in its diamond), so that pixel's t is negative and clamped to 0. Lines 3 and 4 use "
     "parameter projected, the exact projection of the pixel centre onto the segment; line 3 is perspective "
     "and line 4 linear. Depth is always (1 - t) z0 + t z1. Lines 3 and 4 cross at (12,20), which takes line 4's values.",
     32, 32, [dia(iv(2.75, 3.5, 0.25, 0.5, [1, 0, 0.5]), iv(29.5, 12.25, 0.75, 4, [0, 1, -2]),
                  parameter="major"),
              dia(iv(28.25, 16.5, -1, 4, [0, 0, 1]), iv(20.5, 30.75, 3, 0.5, [1, 1, 0]), parameter="major"),
              dia(iv(2.5, 28, 0.5, 1, [0, 1, 0]), iv(16, 17.5, 0.125, 3, [1, 0, "1/3"]),
                  parameter="projected"),
              dia(iv(4, 12.5, 2, 2, [0.25, 0.5, 0.75]), iv(14, 22.5, -2, 0.75, [0.75, 0.5, 0.25]),
                  parameter="projected", interpolation="linear")],
     checks=[("parameter",), ("perspective",), ("clamp",), ("lit", 0, 2, 3)])
