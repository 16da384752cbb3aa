#!/usr/bin/env node
// rastercheck's JavaScript example rasterizer: an 8-bit antialiasing 2D
// rasterizer in the style of canvas, cairo or tiny-skia, judged by
// rastercheck through its external-process protocol, version 2, in
// persistent mode (SPEC.md §12.4, §12.7).
//
//     rastercheck run cases -r 'js=external-persistent:node examples/js/rasterizer.js'
//
// What it is meant to show: how an area-coverage rasterizer is judged. In
// an antialiased scene it computes, in doubles, the area of each primitive
// inside each pixel square (the triangle clipped to the square by
// Sutherland–Hodgman, its area by the shoelace formula; a polygon cut into
// trapezoids between its edges first, so that nonzero and even-odd hold)
// and quantizes it to 8 bits, round(area·255)/255, as a canvas's alpha
// mask would. It answers that coverage per primitive (SPEC.md §12.2), so
// rastercheck judges it on coverage error, not on a sample mask. Quantizing
// each primitive on its own is what such rasterizers do, and where
// primitives meet inside a pixel the quantized parts need not add up to
// the whole: two halves of a pixel are 128/255 each, 256/255 together.
//
// In a scene without antialiasing it point-samples the pixel centres in
// doubles, with the case's tie rule (top-left nudges the sample right and
// down by infinitesimals, SPEC.md §3), and answers [x, y] fragments. Moving
// scenes (SPEC.md §12.8; --no-motion declares none) are point-sampled at
// each spatial sample and instant the request gives, in doubles.
//
// It computes no depth and no attributes: its hello declares
// coverage_only (SPEC.md §12.9), so cases that ask for values are judged
// on coverage alone, and say so. Its coverage is declared as 8-bit
// (coverage_bits), so each primitive is judged within 1/255 of its exact
// area, and a pixel that two primitives share may sum to 256/255. Of the lines it draws only the
// parallelogram (SPEC.md §4.4), a convex quadrilateral like the rest.
//
// Flags plant bugs, for the tests that rastercheck catches them:
//   --truncate  floor(area·255) instead of round: every edge pixel is light;
//   --swap      swaps the coverage of primitives 2k and 2k+1 in every
//               pixel both touch: each primitive is wrong, their sum is not.
// --no-coverage-bits leaves coverage_bits out of the hello; --no-motion
// declares no moving scenes.
//
// Node 20, built-in modules only.

"use strict";

const readline = require("node:readline");

const args = new Set(process.argv.slice(2));
for (const a of args) {
  if (!["--truncate", "--swap", "--no-motion", "--no-coverage-bits"].includes(a)) {
    process.stderr.write(`rasterizer.js: unknown argument ${a}\n`);
    process.exit(2);
  }
}
const TRUNCATE = args.has("--truncate");
const SWAP = args.has("--swap");
const MOTION = !args.has("--no-motion");

// The coverage answers are multiples of 1/LEVELS.
const COVERAGE_BITS = 8;
const LEVELS = 2 ** COVERAGE_BITS - 1;

// ---------------------------------------------------------------------------
// Snapping (SPEC.md §2): the nearest multiple of 2^-bits, ties to even. In
// doubles: exact for coordinates the protocol sends (|x| <= 32768, at most
// 16 bits), except that the double itself may be a rounded decimal.

function roundHalfEven(v) {
  const f = Math.floor(v);
  const d = v - f;
  if (d < 0.5) return f;
  if (d > 0.5) return f + 1;
  return f % 2 === 0 ? f : f + 1;
}

function snap(v, bits) {
  if (bits === null) return v;
  const scale = 2 ** bits;
  return roundHalfEven(v * scale) / scale;
}

// ---------------------------------------------------------------------------
// Point sampling: edge functions and winding numbers in doubles, ties by
// the fill rule's nudge (dx·ε, dy·ε²).

const NUDGES = {
  "top-left": [1, 1],
  "top-right": [-1, 1],
  "bottom-left": [1, -1],
  "bottom-right": [-1, -1],
};

function edge(a, b, q) {
  return (b[0] - a[0]) * (q[1] - a[1]) - (b[1] - a[1]) * (q[0] - a[0]);
}

function area2(v) {
  return edge(v[0], v[1], v[2]);
}

function culled(area, cull) {
  return area === 0 || (cull === "cw" && area > 0) || (cull === "ccw" && area < 0);
}

// A convex polygon (a triangle, a line's parallelogram) covers q when q is
// inside every edge, or on an edge the nudge leaves inwards. Its first
// three vertices give its orientation; a flat one covers nothing.
function convexCovers(v, q, rule) {
  const area = area2(v);
  if (area === 0) return false;
  const sign = area > 0 ? 1 : -1;
  for (let i = 0; i < v.length; i++) {
    const a = v[i];
    const b = v[(i + 1) % v.length];
    const e = edge(a, b, q) * sign;
    if (e > 0) continue;
    if (e < 0) return false;
    if (rule === "all-edges") continue;
    // On the edge: inside when the nudge goes inwards along the gradient.
    const [dx, dy] = NUDGES[rule];
    const gx = -(b[1] - a[1]) * sign;
    const gy = (b[0] - a[0]) * sign;
    if (gx !== 0 ? gx * dx < 0 : gy * dy < 0) return false;
  }
  return true;
}

function triangleCovers(v, q, rule, cull) {
  return !culled(area2(v), cull) && convexCovers(v, q, rule);
}

// A parallelogram line (SPEC.md §4.4): the segment swept by ±width/2 along
// its minor axis.
function parallelogram(a, b, width) {
  const h = width / 2;
  if (Math.abs(b[0] - a[0]) >= Math.abs(b[1] - a[1])) {
    return [[a[0], a[1] - h], [b[0], b[1] - h], [b[0], b[1] + h], [a[0], a[1] + h]];
  }
  return [[a[0] - h, a[1]], [b[0] - h, b[1]], [b[0] + h, b[1]], [a[0] + h, a[1]]];
}

function windingNumber(contours, q, rule) {
  const [dx, dy] = NUDGES[rule];
  let w = 0;
  for (const c of contours) {
    for (let i = 0; i < c.length; i++) {
      const a = c[i];
      const b = c[(i + 1) % c.length];
      if (a[1] === b[1]) continue;
      const lo = Math.min(a[1], b[1]);
      const hi = Math.max(a[1], b[1]);
      if (dy > 0 ? !(lo <= q[1] && q[1] < hi) : !(lo < q[1] && q[1] <= hi)) continue;
      let side = (a[0] - q[0]) * (b[1] - a[1]) + (q[1] - a[1]) * (b[0] - a[0]);
      if (b[1] < a[1]) side = -side;
      if (side > 0 || (side === 0 && dx < 0)) w += b[1] > a[1] ? 1 : -1;
    }
  }
  return w;
}

function filled(w, fill) {
  return fill === "even-odd" ? w % 2 !== 0 : w !== 0;
}

// The pixels whose squares may hold a sample of the points' hull.
function pixelBox(points, width, height) {
  const xs = points.map((p) => p[0]);
  const ys = points.map((p) => p[1]);
  return {
    x0: Math.max(0, Math.floor(Math.min(...xs))),
    x1: Math.min(width - 1, Math.floor(Math.max(...xs))),
    y0: Math.max(0, Math.floor(Math.min(...ys))),
    y1: Math.min(height - 1, Math.floor(Math.max(...ys))),
  };
}

// ---------------------------------------------------------------------------
// Area coverage: a convex polygon clipped to a pixel square.

// Sutherland–Hodgman: keeps the part of `poly` where `inside` holds, the
// boundary crossing found by `cross` (a point on the clipping line).
function clip(poly, inside, cross) {
  const out = [];
  for (let i = 0; i < poly.length; i++) {
    const p = poly[i];
    const q = poly[(i + 1) % poly.length];
    const pin = inside(p);
    const qin = inside(q);
    if (pin) out.push(p);
    if (pin !== qin) out.push(cross(p, q));
  }
  return out;
}

function atX(p, q, x) {
  return [x, p[1] + ((q[1] - p[1]) * (x - p[0])) / (q[0] - p[0])];
}

function atY(p, q, y) {
  return [p[0] + ((q[0] - p[0]) * (y - p[1])) / (q[1] - p[1]), y];
}

function shoelace(poly) {
  let s = 0;
  for (let i = 0; i < poly.length; i++) {
    const p = poly[i];
    const q = poly[(i + 1) % poly.length];
    s += p[0] * q[1] - q[0] * p[1];
  }
  return Math.abs(s) / 2;
}

// Adds the area of convex `poly` inside each pixel of the canvas to `acc`
// (a Map from pixel index to area).
function addConvex(poly, width, height, acc) {
  if (poly.length < 3) return;
  const box = pixelBox(poly, width, height);
  for (let y = box.y0; y <= box.y1; y++) {
    let row = clip(poly, (p) => p[1] >= y, (p, q) => atY(p, q, y));
    row = clip(row, (p) => p[1] <= y + 1, (p, q) => atY(p, q, y + 1));
    if (row.length < 3) continue;
    for (let x = box.x0; x <= box.x1; x++) {
      let cell = clip(row, (p) => p[0] >= x, (p, q) => atX(p, q, x));
      cell = clip(cell, (p) => p[0] <= x + 1, (p, q) => atX(p, q, x + 1));
      if (cell.length < 3) continue;
      const a = shoelace(cell);
      if (a > 0) acc.set(y * width + x, (acc.get(y * width + x) || 0) + a);
    }
  }
}

// A polygon's filled region as trapezoids: cut at every vertex height,
// every crossing of two edges and every pixel row, so that between two
// cuts no edges cross and the winding number is constant between
// neighbouring edges.
function addPolygon(contours, fill, width, height, acc) {
  const edges = [];
  for (const c of contours) {
    for (let i = 0; i < c.length; i++) {
      const a = c[i];
      const b = c[(i + 1) % c.length];
      if (a[1] !== b[1]) edges.push({ a, b, dir: b[1] > a[1] ? 1 : -1 });
    }
  }
  const xAt = (e, y) => e.a[0] + ((e.b[0] - e.a[0]) * (y - e.a[1])) / (e.b[1] - e.a[1]);
  const cuts = new Set();
  for (const e of edges) {
    cuts.add(e.a[1]);
    cuts.add(e.b[1]);
  }
  for (let i = 0; i < edges.length; i++) {
    for (let j = i + 1; j < edges.length; j++) {
      const e = edges[i];
      const f = edges[j];
      const lo = Math.max(Math.min(e.a[1], e.b[1]), Math.min(f.a[1], f.b[1]));
      const hi = Math.min(Math.max(e.a[1], e.b[1]), Math.max(f.a[1], f.b[1]));
      if (lo >= hi) continue;
      const d0 = xAt(e, lo) - xAt(f, lo);
      const d1 = xAt(e, hi) - xAt(f, hi);
      if ((d0 < 0 && d1 > 0) || (d0 > 0 && d1 < 0)) cuts.add(lo + ((hi - lo) * d0) / (d0 - d1));
    }
  }
  const ys = [...cuts];
  const top = Math.min(...ys);
  const bottom = Math.max(...ys);
  for (let r = Math.max(0, Math.ceil(top)); r <= Math.min(height, bottom); r++) cuts.add(r);
  const sorted = [...cuts].sort((p, q) => p - q);
  for (let k = 0; k + 1 < sorted.length; k++) {
    const ya = sorted[k];
    const yb = sorted[k + 1];
    const ym = (ya + yb) / 2;
    const active = edges
      .filter((e) => Math.min(e.a[1], e.b[1]) <= ym && ym < Math.max(e.a[1], e.b[1]))
      .sort((e, f) => xAt(e, ym) - xAt(f, ym));
    let w = 0;
    for (let i = 0; i + 1 < active.length; i++) {
      w += active[i].dir;
      if (!filled(w, fill)) continue;
      const l = active[i];
      const r = active[i + 1];
      addConvex(
        [[xAt(l, ya), ya], [xAt(r, ya), ya], [xAt(r, yb), yb], [xAt(l, yb), yb]],
        width,
        height,
        acc,
      );
    }
  }
}

function quantize(area) {
  const a = Math.min(1, Math.max(0, area));
  return (TRUNCATE ? Math.floor(a * LEVELS) : Math.round(a * LEVELS)) / LEVELS;
}

// ---------------------------------------------------------------------------
// A request.

function snapped(v, bits) {
  return [snap(v.x, bits), snap(v.y, bits)];
}

function unsupported(why) {
  const e = new Error(why);
  e.unsupported = true;
  return e;
}

// Each primitive as what the drawing functions take: a triangle's three
// points (and, moving, where they go), or a polygon's contours.
function shapes(request) {
  const bits = request.rules.subpixel_bits;
  return request.primitives.map((p, i) => {
    if (p.triangle) {
      return {
        triangle: p.triangle.map((v) => snapped(v, bits)),
        to: p.triangle.map((v) => (v.to ? snapped(v.to, bits) : snapped(v, bits))),
        moves: p.moves === true,
      };
    }
    if (p.contours) return { contours: p.contours.map((c) => c.map((v) => snapped(v, bits))), fill: p.fill };
    if (p.rule !== "parallelogram") throw unsupported(`$.primitives[${i}]: ${p.rule} lines are not drawn here`);
    return {
      line: p.line.map((v) => snapped(v, bits)),
      to: p.line.map((v) => (v.to ? snapped(v.to, bits) : snapped(v, bits))),
      width: p.width,
      moves: p.moves === true,
    };
  });
}

// Area coverage per primitive, quantized: [[x, y, c], ...] each.
function coverage(request, prims) {
  const { width, height } = request.canvas;
  const maps = prims.map((p) => {
    const acc = new Map();
    if (p.triangle) {
      if (!culled(area2(p.triangle), request.rules.cull)) addConvex(p.triangle, width, height, acc);
    } else if (p.line) {
      addConvex(parallelogram(p.line[0], p.line[1], p.width), width, height, acc);
    } else {
      addPolygon(p.contours, p.fill, width, height, acc);
    }
    return acc;
  });
  if (SWAP) {
    for (let i = 0; i + 1 < maps.length; i += 2) {
      for (const [k, a] of maps[i]) {
        if (!maps[i + 1].has(k)) continue;
        maps[i].set(k, maps[i + 1].get(k));
        maps[i + 1].set(k, a);
      }
    }
  }
  return maps.map((acc) => {
    const out = [];
    for (const [k, a] of acc) {
      const c = quantize(a);
      if (c > 0) out.push([k % width, Math.floor(k / width), c]);
    }
    return { coverage: out };
  });
}

// The spatial samples: the pixel centre, or the antialias offsets.
function offsets(request) {
  const aa = request.plan.antialias;
  return aa ? aa.offsets : [[0.5, 0.5]];
}

// Point sampling: the samples each primitive covers. `slot(s)` is the
// fragment's third field, or null for a plain [x, y].
function pointSample(request, prims) {
  const { width, height } = request.canvas;
  const { fill_rule: rule, cull } = request.rules;
  const motion = request.plan.motion;
  const spots = offsets(request);
  const named = request.plan.antialias || motion;
  return prims.map((p) => {
    const fragments = [];
    const ends = p.triangle || p.line;
    const reach = p.line ? p.width / 2 : 0;
    const points = ends
      ? ends.concat(p.to).flatMap(([x, y]) => [[x - reach, y - reach], [x + reach, y + reach]])
      : p.contours.flat();
    const box = pixelBox(points, width, height);
    for (let y = box.y0; y <= box.y1; y++) {
      for (let x = box.x0; x <= box.x1; x++) {
        if (p.moves) {
          movingSamples(request, p, x, y, fragments);
          continue;
        }
        spots.forEach(([dx, dy], s) => {
          const q = [x + dx, y + dy];
          const inside = p.triangle
            ? triangleCovers(p.triangle, q, rule, cull)
            : p.line
              ? convexCovers(parallelogram(p.line[0], p.line[1], p.width), q, rule)
              : filled(windingNumber(p.contours, q, rule === "all-edges" ? "top-left" : rule), p.fill);
          if (inside) fragments.push(named ? [x, y, s] : [x, y]);
        });
      }
    }
    return { fragments };
  });
}

// A moving triangle or line at pixel (x, y): slot j = s·N + k covers
// spatial sample s at instant τ = open + (close − open)·u_j/65536 (SPEC.md
// §12.8); each vertex is at (1 − τ)·snap(from) + τ·snap(to).
function movingSamples(request, p, x, y, fragments) {
  const m = request.plan.motion;
  const [open, close] = m.shutter;
  const spots = offsets(request);
  const us = m.times[y * request.canvas.width + x];
  const from = p.triangle || p.line;
  us.forEach((u, j) => {
    const t = open + ((close - open) * u) / 65536;
    const v = from.map((a, i) => [(1 - t) * a[0] + t * p.to[i][0], (1 - t) * a[1] + t * p.to[i][1]]);
    const [dx, dy] = spots[Math.floor(j / m.samples)];
    const q = [x + dx, y + dy];
    const inside = p.line
      ? convexCovers(parallelogram(v[0], v[1], p.width), q, request.rules.fill_rule)
      : triangleCovers(v, q, request.rules.fill_rule, request.rules.cull);
    if (inside) fragments.push([x, y, j]);
  });
}

function answer(request) {
  if (request.plan.motion && !MOTION) return { unsupported: "moving scenes are off (--no-motion)" };
  const prims = shapes(request);
  const areas = request.plan.antialias && !request.plan.motion;
  return { primitives: areas ? coverage(request, prims) : pointSample(request, prims) };
}

// ---------------------------------------------------------------------------
// The protocol: a hello, then one answer line per request, echoing its id.

const HELLO = {
  hello: {
    protocol: 2,
    name: "js-example",
    version: "1",
    capabilities: {
      primitives: ["triangles", "polygons", "lines"],
      line_rules: ["parallelogram"],
      polygon_fills: ["nonzero", "even-odd"],
      fill_rules: ["top-left", "bottom-right", "top-right", "bottom-left", "all-edges"],
      antialias: true,
      coverage_only: true,
      coverage_bits: COVERAGE_BITS,
      motion: MOTION,
    },
    conventions: { coverage: "area, 8-bit", arithmetic: "doubles" },
  },
};
if (args.has("--no-coverage-bits")) delete HELLO.hello.capabilities.coverage_bits;

process.stdout.write(JSON.stringify(HELLO) + "\n");
const lines = readline.createInterface({ input: process.stdin, crlfDelay: Infinity });
lines.on("line", (text) => {
  if (text.trim() === "") return;
  let request;
  let response;
  try {
    request = JSON.parse(text);
  } catch (e) {
    process.stdout.write(JSON.stringify({ error: `the request is not JSON: ${e.message}` }) + "\n");
    return;
  }
  if (request.bye) {
    // Every answer is already out (synchronous writes), so leave now.
    process.exit(0);
  }
  try {
    response = answer(request);
  } catch (e) {
    response = e.unsupported ? { unsupported: e.message } : { error: String(e.stack || e) };
  }
  if (request.id !== undefined) response.id = request.id;
  // Writes to a pipe are synchronous in Node on Linux: the line is out now.
  process.stdout.write(JSON.stringify(response) + "\n");
});
