//! The two kinds of chart the report draws: distributions by category
//! (a box and every value, one column per series in each category) and
//! lines of medians against a log2 x axis. Both use a log10 y axis with a
//! lane for zeros below it; neither is drawn without a positive value.

use super::svg::{legend, legend_height, style, LegendEntry, Log2Axis, LogAxis, Svg, CHAR_WIDTH};

pub const WIDTH: f64 = 640.0;
pub const HEIGHT: f64 = 360.0;
const LEFT: f64 = 62.0;
const RIGHT: f64 = 16.0;
const TITLE_Y: f64 = 20.0;
const LEGEND_Y: f64 = 30.0;
const BOTTOM: f64 = 44.0;
/// The zero lane's distance below the log axis' lowest decade.
const ZERO_GAP: f64 = 18.0;

/// One value of a distribution: its category, its series, the value.
#[derive(Clone, Debug, PartialEq)]
pub struct Value {
    pub category: usize,
    pub series: usize,
    pub value: f64,
}

/// A distribution chart: for each category, one column per series with
/// values there (a box from the lower to the upper quartile, the median,
/// whiskers to the extremes, and every value as a dot).
pub struct Distribution<'a> {
    pub title: &'a str,
    pub y_label: &'a str,
    pub categories: &'a [String],
    pub series: &'a [String],
    pub values: &'a [Value],
}

/// The frame both kinds share: title, legend, y axis with its zero lane.
struct Frame {
    svg: Svg,
    left: f64,
    right: f64,
    top: f64,
    bottom: f64,
    y: LogAxis,
}

fn frame(
    width: f64,
    title: &str,
    y_label: &str,
    entries: &[LegendEntry],
    y_values: &[f64],
) -> Option<Frame> {
    let (lo, hi) = LogAxis::decades(y_values.iter().copied())?;
    let zeros = y_values.contains(&0.0);
    let legend_h = legend_height(width - LEFT - RIGHT, entries);
    let height = HEIGHT + (legend_h - 16.0).max(0.0);
    let mut svg = Svg::new(width, height);
    svg.text(
        LEFT,
        TITLE_Y,
        "start",
        r#" font-size="14" font-weight="bold""#,
        title,
    );
    legend(&mut svg, LEFT, LEGEND_Y, width - LEFT - RIGHT, entries);
    let top = LEGEND_Y + legend_h + 12.0;
    let bottom = height - BOTTOM;
    let axis_from = if zeros {
        bottom - ZERO_GAP - 6.0
    } else {
        bottom
    };
    let y = LogAxis {
        lo,
        hi,
        from: axis_from,
        to: top,
        zero_at: zeros.then_some(bottom - 6.0),
    };
    let right = width - RIGHT;
    for (v, label, major) in y.ticks() {
        let py = y.map(v);
        let colour = if major { "#d0d0d0" } else { "#ececec" };
        svg.line(LEFT, py, right, py, colour, "");
        svg.text(LEFT - 6.0, py + 4.0, "end", "", &label);
    }
    if let Some(z) = y.zero_at {
        svg.line(LEFT, z, right, z, "#d0d0d0", r#" stroke-dasharray="2 3""#);
        svg.text(LEFT - 6.0, z + 4.0, "end", "", "0");
        // The break between the log axis and the zero lane.
        let mid = (z + y.from) / 2.0;
        svg.line(LEFT - 4.0, mid + 2.0, LEFT + 4.0, mid - 2.0, "#666", "");
    }
    svg.line(LEFT, top, LEFT, bottom, "#666", "");
    svg.line(LEFT, bottom, right, bottom, "#666", "");
    let cy = (top + bottom) / 2.0;
    svg.text(
        16.0,
        cy,
        "middle",
        &format!(r#" transform="rotate(-90 16 {cy:.1})""#),
        y_label,
    );
    Some(Frame {
        svg,
        left: LEFT,
        right,
        top,
        bottom,
        y,
    })
}

/// Deterministic jitter in [-1, 1] for the k-th dot.
fn jitter(k: usize) -> f64 {
    // The golden ratio's fractional part spreads dots evenly.
    let f = (k as f64 * 0.618_033_988_75).fract();
    2.0 * f - 1.0
}

/// The q-quantile of sorted values (linear between neighbours).
pub fn quantile(sorted: &[f64], q: f64) -> f64 {
    let pos = q * (sorted.len() - 1) as f64;
    let i = pos.floor() as usize;
    let j = (i + 1).min(sorted.len() - 1);
    sorted[i] + (pos - i as f64) * (sorted[j] - sorted[i])
}

pub fn median(values: &[f64]) -> f64 {
    let mut sorted = values.to_vec();
    sorted.sort_by(f64::total_cmp);
    quantile(&sorted, 0.5)
}

/// The SVG of a distribution chart; `None` without any positive value.
pub fn distribution(d: &Distribution) -> Option<String> {
    let finite: Vec<&Value> = d
        .values
        .iter()
        .filter(|v| v.value.is_finite() && v.value >= 0.0)
        .collect();
    // The columns: per category, the series with values there.
    let mut columns: Vec<(usize, Vec<usize>)> = Vec::new();
    for c in 0..d.categories.len() {
        let mut present: Vec<usize> = finite
            .iter()
            .filter(|v| v.category == c)
            .map(|v| v.series)
            .collect();
        present.sort_unstable();
        present.dedup();
        if !present.is_empty() {
            columns.push((c, present));
        }
    }
    let slot = 18.0;
    let gap = 14.0;
    let label_room = columns
        .iter()
        .map(|(c, s)| {
            (d.categories[*c].chars().count() as f64 * CHAR_WIDTH + 8.0)
                .max(s.len() as f64 * slot + gap)
        })
        .sum::<f64>();
    let width = WIDTH.max(LEFT + RIGHT + label_room + 20.0);
    let used: Vec<usize> = {
        let mut u: Vec<usize> = finite.iter().map(|v| v.series).collect();
        u.sort_unstable();
        u.dedup();
        u
    };
    let entries: Vec<LegendEntry> = used
        .iter()
        .map(|&s| {
            let (colour, marker) = style(s);
            LegendEntry {
                label: d.series[s].clone(),
                colour,
                marker: Some(marker),
                line: false,
                dashed: false,
            }
        })
        .collect();
    let ys: Vec<f64> = finite.iter().map(|v| v.value).collect();
    let mut f = frame(width, d.title, d.y_label, &entries, &ys)?;
    // Spread the categories over the plot, each as wide as it needs.
    let inner = f.right - f.left - 10.0;
    let scale = inner / label_room;
    let mut x = f.left + 5.0;
    for (k, (c, present)) in columns.iter().enumerate() {
        let needed = (d.categories[*c].chars().count() as f64 * CHAR_WIDTH + 8.0)
            .max(present.len() as f64 * slot + gap);
        let w = needed * scale;
        if k % 2 == 1 {
            f.svg.rect(x, f.top, w, f.bottom - f.top, "#f4f4f4", "");
        }
        let centre = x + w / 2.0;
        f.svg
            .text(centre, f.bottom + 16.0, "middle", "", &d.categories[*c]);
        let slot_w = slot.min((w - gap * scale) / present.len() as f64);
        let first = centre - slot_w * (present.len() as f64 - 1.0) / 2.0;
        for (i, &s) in present.iter().enumerate() {
            let sx = first + slot_w * i as f64;
            let mut vals: Vec<f64> = finite
                .iter()
                .filter(|v| v.category == *c && v.series == s)
                .map(|v| v.value)
                .collect();
            vals.sort_by(f64::total_cmp);
            draw_box(&mut f, sx, slot_w * 0.7, &vals, s);
        }
        x += w;
    }
    Some(f.svg.finish(d.title))
}

fn draw_box(f: &mut Frame, x: f64, w: f64, sorted: &[f64], series: usize) {
    let (colour, marker) = style(series);
    let y = f.y;
    let (q1, q2, q3) = (
        quantile(sorted, 0.25),
        quantile(sorted, 0.5),
        quantile(sorted, 0.75),
    );
    let (lo, hi) = (sorted[0], sorted[sorted.len() - 1]);
    f.svg.line(x, y.map(lo), x, y.map(hi), colour, "");
    let (top, bottom) = (y.map(q3), y.map(q1));
    f.svg.rect(
        x - w / 2.0,
        top,
        w,
        bottom - top,
        colour,
        &format!(r#" fill-opacity="0.15" stroke="{colour}""#),
    );
    f.svg.line(
        x - w / 2.0,
        y.map(q2),
        x + w / 2.0,
        y.map(q2),
        colour,
        r#" stroke-width="2.5""#,
    );
    for (k, &v) in sorted.iter().enumerate() {
        let dx = if sorted.len() > 1 {
            jitter(k) * w * 0.35
        } else {
            0.0
        };
        f.svg.marker(
            marker,
            x + dx,
            y.map(v),
            2.2,
            colour,
            colour,
            r#" fill-opacity="0.5" stroke-opacity="0.8""#,
        );
    }
}

/// One line of a line chart: the raw points (x, value); the line goes
/// through the median value at each x.
pub struct Series {
    pub label: String,
    pub points: Vec<(f64, f64)>,
}

/// A curve drawn dashed in grey for comparison (e.g. a default bound).
pub struct Curve<'a> {
    pub label: &'a str,
    pub f: &'a dyn Fn(f64) -> f64,
}

pub struct Lines<'a> {
    pub title: &'a str,
    pub x_label: &'a str,
    pub y_label: &'a str,
    pub series: &'a [Series],
    pub curve: Option<Curve<'a>>,
}

/// The medians of a series at each x, in increasing x.
pub fn medians(points: &[(f64, f64)]) -> Vec<(f64, f64)> {
    let mut xs: Vec<f64> = points.iter().map(|p| p.0).collect();
    xs.sort_by(f64::total_cmp);
    xs.dedup();
    xs.into_iter()
        .map(|x| {
            let at: Vec<f64> = points.iter().filter(|p| p.0 == x).map(|p| p.1).collect();
            (x, median(&at))
        })
        .collect()
}

/// The SVG of a line chart (log2 x, log10 y); `None` without any positive
/// value.
pub fn lines(l: &Lines) -> Option<String> {
    let ok = |p: &&(f64, f64)| p.0 > 0.0 && p.0.is_finite() && p.1.is_finite() && p.1 >= 0.0;
    let series: Vec<(usize, Vec<(f64, f64)>)> = l
        .series
        .iter()
        .enumerate()
        .map(|(i, s)| (i, s.points.iter().filter(ok).copied().collect::<Vec<_>>()))
        .filter(|(_, p)| !p.is_empty())
        .collect();
    let xs: Vec<f64> = series
        .iter()
        .flat_map(|(_, p)| p.iter().map(|p| p.0))
        .collect();
    let (xlo, xhi) = Log2Axis::around(xs.iter().copied())?;
    // The data alone sets the y axis; the curve is cut to it.
    let ys: Vec<f64> = series
        .iter()
        .flat_map(|(_, p)| p.iter().map(|p| p.1))
        .collect();
    let mut entries: Vec<LegendEntry> = series
        .iter()
        .map(|(i, _)| {
            let (colour, marker) = style(*i);
            LegendEntry {
                label: l.series[*i].label.clone(),
                colour,
                marker: Some(marker),
                line: true,
                dashed: false,
            }
        })
        .collect();
    if let Some(c) = &l.curve {
        entries.push(LegendEntry {
            label: c.label.to_owned(),
            colour: "#777777",
            marker: None,
            line: true,
            dashed: true,
        });
    }
    let mut f = frame(WIDTH, l.title, l.y_label, &entries, &ys)?;
    let x = Log2Axis {
        lo: xlo,
        hi: xhi,
        from: f.left + 16.0,
        to: f.right - 16.0,
    };
    for (v, label) in x.ticks() {
        let px = x.map(v);
        f.svg.line(px, f.top, px, f.bottom, "#ececec", "");
        f.svg.line(px, f.bottom, px, f.bottom + 4.0, "#666", "");
        f.svg.text(px, f.bottom + 16.0, "middle", "", &label);
    }
    f.svg.text(
        (f.left + f.right) / 2.0,
        f.bottom + 34.0,
        "middle",
        "",
        l.x_label,
    );
    if let Some(c) = &l.curve {
        let n = 48;
        let pts: Vec<Option<(f64, f64)>> = (0..=n)
            .map(|k| {
                let e = f64::from(xlo) + f64::from(xhi - xlo) * f64::from(k) / f64::from(n);
                let v = 2f64.powf(e);
                let py = f.y.map((c.f)(v));
                (py >= f.top - 0.5 && py <= f.y.from + 0.5).then_some((x.map(v), py))
            })
            .collect();
        for run in pts.split(Option::is_none) {
            let run: Vec<(f64, f64)> = run.iter().flatten().copied().collect();
            f.svg.polyline(
                &run,
                "#777777",
                r#" stroke-width="1.2" stroke-dasharray="5 3""#,
            );
        }
    }
    for (i, points) in &series {
        let (colour, marker) = style(*i);
        for (k, &(px, py)) in points.iter().enumerate() {
            f.svg.marker(
                marker,
                x.map(px) + jitter(k) * 3.0,
                f.y.map(py),
                1.8,
                colour,
                colour,
                r#" fill-opacity="0.25" stroke-opacity="0.35""#,
            );
        }
        let meds = medians(points);
        // The line is not drawn into the zero lane: a zero has no log.
        for run in meds.split(|m| m.1 <= 0.0) {
            let run: Vec<(f64, f64)> = run.iter().map(|&(a, b)| (x.map(a), f.y.map(b))).collect();
            f.svg.polyline(&run, colour, r#" stroke-width="1.8""#);
        }
        for &(a, b) in &meds {
            f.svg
                .marker(marker, x.map(a), f.y.map(b), 4.0, colour, "white", "");
        }
    }
    Some(f.svg.finish(l.title))
}
