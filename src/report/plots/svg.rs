//! A tiny SVG writer for the report's charts: a canvas, axes with nice
//! ticks (log10 for errors, log2 for sample counts, categories), markers
//! and a legend. Standalone SVG only: no scripts, no external references,
//! text escaped.

use std::fmt::Write;

use crate::report::escape::escape;

/// Okabe and Ito's colour-blind-safe palette, darkest first (yellow last:
/// it is faint on white).
pub const PALETTE: [&str; 8] = [
    "#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9", "#000000", "#B8A000",
];

/// Marker shapes, so that series differ by more than their colour.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Marker {
    Circle,
    Square,
    Triangle,
    Diamond,
    Down,
}

pub const MARKERS: [Marker; 5] = [
    Marker::Circle,
    Marker::Square,
    Marker::Triangle,
    Marker::Diamond,
    Marker::Down,
];

/// The colour and marker of series `i`.
pub fn style(i: usize) -> (&'static str, Marker) {
    (PALETTE[i % PALETTE.len()], MARKERS[i % MARKERS.len()])
}

/// Pixels per character of 11 px sans-serif text, on average (for layout).
pub const CHAR_WIDTH: f64 = 6.6;

/// An SVG document being drawn.
pub struct Svg {
    width: f64,
    height: f64,
    body: String,
}

/// Coordinates with one decimal: enough for a screen, and short.
fn n(v: f64) -> String {
    let r = (v * 10.0).round() / 10.0;
    if r == r.trunc() {
        format!("{}", r as i64)
    } else {
        format!("{r:.1}")
    }
}

impl Svg {
    pub fn new(width: f64, height: f64) -> Svg {
        Svg {
            width,
            height,
            body: String::new(),
        }
    }

    pub fn width(&self) -> f64 {
        self.width
    }

    pub fn height(&self) -> f64 {
        self.height
    }

    pub fn line(&mut self, x1: f64, y1: f64, x2: f64, y2: f64, stroke: &str, extra: &str) {
        let _ = writeln!(
            self.body,
            r#"<line x1="{}" y1="{}" x2="{}" y2="{}" stroke="{stroke}"{extra}/>"#,
            n(x1),
            n(y1),
            n(x2),
            n(y2)
        );
    }

    pub fn rect(&mut self, x: f64, y: f64, w: f64, h: f64, fill: &str, extra: &str) {
        let _ = writeln!(
            self.body,
            r#"<rect x="{}" y="{}" width="{}" height="{}" fill="{fill}"{extra}/>"#,
            n(x),
            n(y),
            n(w.max(0.0)),
            n(h.max(0.0))
        );
    }

    /// A polyline through `points`.
    pub fn polyline(&mut self, points: &[(f64, f64)], stroke: &str, extra: &str) {
        if points.len() < 2 {
            return;
        }
        let pts: Vec<String> = points
            .iter()
            .map(|&(x, y)| format!("{},{}", n(x), n(y)))
            .collect();
        let _ = writeln!(
            self.body,
            r#"<polyline points="{}" fill="none" stroke="{stroke}"{extra}/>"#,
            pts.join(" ")
        );
    }

    /// Text at (x, y); `anchor` is `start`, `middle` or `end`.
    pub fn text(&mut self, x: f64, y: f64, anchor: &str, extra: &str, content: &str) {
        let _ = writeln!(
            self.body,
            r#"<text x="{}" y="{}" text-anchor="{anchor}"{extra}>{}</text>"#,
            n(x),
            n(y),
            escape(content)
        );
    }

    /// A marker of radius `r` centred on (x, y), filled with `colour` and
    /// outlined with `stroke`.
    #[allow(clippy::too_many_arguments)]
    pub fn marker(
        &mut self,
        marker: Marker,
        x: f64,
        y: f64,
        r: f64,
        colour: &str,
        stroke: &str,
        extra: &str,
    ) {
        let paint = format!(r#"fill="{colour}" stroke="{stroke}"{extra}"#);
        let poly = |pts: &[(f64, f64)]| {
            pts.iter()
                .map(|&(dx, dy)| format!("{},{}", n(x + dx * r), n(y + dy * r)))
                .collect::<Vec<_>>()
                .join(" ")
        };
        let _ = match marker {
            Marker::Circle => writeln!(
                self.body,
                r#"<circle cx="{}" cy="{}" r="{}" {paint}/>"#,
                n(x),
                n(y),
                n(r)
            ),
            Marker::Square => writeln!(
                self.body,
                r#"<rect x="{}" y="{}" width="{}" height="{}" {paint}/>"#,
                n(x - r * 0.85),
                n(y - r * 0.85),
                n(r * 1.7),
                n(r * 1.7)
            ),
            Marker::Triangle => writeln!(
                self.body,
                r#"<polygon points="{}" {paint}/>"#,
                poly(&[(0.0, -1.2), (1.1, 0.8), (-1.1, 0.8)])
            ),
            Marker::Down => writeln!(
                self.body,
                r#"<polygon points="{}" {paint}/>"#,
                poly(&[(0.0, 1.2), (1.1, -0.8), (-1.1, -0.8)])
            ),
            Marker::Diamond => writeln!(
                self.body,
                r#"<polygon points="{}" {paint}/>"#,
                poly(&[(0.0, -1.25), (1.1, 0.0), (0.0, 1.25), (-1.1, 0.0)])
            ),
        };
    }

    /// The whole document: `title` is also the SVG's accessible title.
    pub fn finish(self, title: &str) -> String {
        format!(
            concat!(
                r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" viewBox="0 0 {w} {h}" "#,
                r##"font-family="Helvetica, Arial, sans-serif" font-size="11" fill="#222">"##,
                "\n<title>{t}</title>\n",
                r#"<rect width="{w}" height="{h}" fill="white"/>"#,
                "\n{body}</svg>\n"
            ),
            w = n(self.width),
            h = n(self.height),
            t = escape(title),
            body = self.body
        )
    }
}

/// The smallest and largest of the positive, finite `values`; `None` when
/// there is none.
fn positive_range(values: impl IntoIterator<Item = f64>) -> Option<(f64, f64)> {
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for v in values {
        if v > 0.0 && v.is_finite() {
            lo = lo.min(v);
            hi = hi.max(v);
        }
    }
    (lo <= hi).then_some((lo, hi))
}

/// A logarithmic axis in base 10 from 10^lo to 10^hi (whole decades), over
/// the pixels `from` (at 10^lo) to `to` (at 10^hi), with an optional lane
/// for zeros beyond the `from` end.
#[derive(Clone, Copy, Debug)]
pub struct LogAxis {
    pub lo: i32,
    pub hi: i32,
    pub from: f64,
    pub to: f64,
    /// Where zeros are drawn (a lane past `from`), when there are any.
    pub zero_at: Option<f64>,
}

impl LogAxis {
    /// The whole decades around the positive values `values`; `None` when
    /// there is none.
    pub fn decades(values: impl IntoIterator<Item = f64>) -> Option<(i32, i32)> {
        let (lo, hi) = positive_range(values)?;
        let (mut a, mut b) = (lo.log10().floor() as i32, hi.log10().ceil() as i32);
        if a == b {
            b += 1;
        }
        // Keep a lone value (or a narrow range) off the axis' foot.
        if (b - a) == 1 && hi.log10() - lo.log10() < 0.5 && lo.log10() - f64::from(a) < 0.05 {
            a -= 1;
        }
        Some((a, b))
    }

    /// The pixel of `v`: zero goes to the zero lane (or `from`).
    pub fn map(&self, v: f64) -> f64 {
        if v <= 0.0 {
            return self.zero_at.unwrap_or(self.from);
        }
        let t = (v.log10() - f64::from(self.lo)) / f64::from(self.hi - self.lo);
        self.from + t * (self.to - self.from)
    }

    /// Ticks: every decade, or every few decades when there are many; with
    /// 2 and 5 between them when there are few.
    pub fn ticks(&self) -> Vec<(f64, String, bool)> {
        let span = self.hi - self.lo;
        let step = (span + 7) / 8;
        let mut ticks = Vec::new();
        for e in self.lo..=self.hi {
            if (e - self.lo) % step == 0 {
                ticks.push((10f64.powi(e), label_pow10(e, self.lo, self.hi), true));
            }
            if span <= 2 && e < self.hi {
                for m in [2.0, 5.0] {
                    let v = m * 10f64.powi(e);
                    ticks.push((v, label_value(v, self.lo, self.hi), false));
                }
            }
        }
        ticks
    }
}

/// The label of 10^e on an axis from 10^lo to 10^hi: plain numbers when
/// they are short, else `1e-5`.
fn label_pow10(e: i32, lo: i32, hi: i32) -> String {
    label_value(10f64.powi(e), lo, hi)
}

fn label_value(v: f64, lo: i32, hi: i32) -> String {
    if lo >= -3 && hi <= 5 {
        let digits = (-v.log10().floor()).max(0.0) as usize;
        format!("{v:.digits$}")
    } else {
        let e = v.log10().floor() as i32;
        let m = (v / 10f64.powi(e)).round();
        if e == 0 {
            format!("{m}")
        } else if m == 1.0 {
            format!("1e{e}")
        } else {
            format!("{m}e{e}")
        }
    }
}

/// A log2 axis over whole powers of two from 2^lo to 2^hi.
#[derive(Clone, Copy, Debug)]
pub struct Log2Axis {
    pub lo: i32,
    pub hi: i32,
    pub from: f64,
    pub to: f64,
}

impl Log2Axis {
    /// The powers of two around the positive values; `None` without any.
    pub fn around(values: impl IntoIterator<Item = f64>) -> Option<(i32, i32)> {
        let (lo, hi) = positive_range(values)?;
        let a = lo.log2().floor() as i32;
        let mut b = hi.log2().ceil() as i32;
        if a == b {
            b += 1;
        }
        Some((a, b))
    }

    pub fn map(&self, v: f64) -> f64 {
        let t = (v.log2() - f64::from(self.lo)) / f64::from(self.hi - self.lo);
        self.from + t * (self.to - self.from)
    }

    /// Every power of two, or every other one when there are many.
    pub fn ticks(&self) -> Vec<(f64, String)> {
        let step = ((self.hi - self.lo) + 9) / 10;
        (self.lo..=self.hi)
            .filter(|e| (e - self.lo) % step == 0)
            .map(|e| {
                let v = 2f64.powi(e);
                (v, format!("{v}"))
            })
            .collect()
    }
}

/// A legend laid out in rows from (x, y) within `width`: returns the height
/// it takes. Each entry: label, colour, marker, whether a line goes with
/// the marker, and whether the line is dashed.
pub fn legend(svg: &mut Svg, x: f64, y: f64, width: f64, entries: &[LegendEntry]) -> f64 {
    let rows = legend_rows(width, entries);
    for (row, items) in rows.iter().enumerate() {
        let mut cx = x;
        let cy = y + row as f64 * 16.0 + 8.0;
        for &i in items {
            let e = &entries[i];
            if e.line {
                let dash = if e.dashed {
                    r#" stroke-dasharray="5 3""#
                } else {
                    ""
                };
                svg.line(
                    cx,
                    cy,
                    cx + 18.0,
                    cy,
                    e.colour,
                    &format!(r#" stroke-width="1.5"{dash}"#),
                );
            }
            if let Some(m) = e.marker {
                svg.marker(m, cx + 9.0, cy, 3.5, e.colour, e.colour, "");
            }
            svg.text(cx + 22.0, cy + 4.0, "start", "", &e.label);
            cx += legend_item_width(&e.label);
        }
    }
    rows.len() as f64 * 16.0
}

pub struct LegendEntry {
    pub label: String,
    pub colour: &'static str,
    pub marker: Option<Marker>,
    pub line: bool,
    pub dashed: bool,
}

fn legend_item_width(label: &str) -> f64 {
    22.0 + label.chars().count() as f64 * CHAR_WIDTH + 14.0
}

fn legend_rows(width: f64, entries: &[LegendEntry]) -> Vec<Vec<usize>> {
    let mut rows: Vec<Vec<usize>> = Vec::new();
    let mut used = f64::INFINITY;
    for (i, e) in entries.iter().enumerate() {
        let w = legend_item_width(&e.label);
        if used + w > width {
            rows.push(Vec::new());
            used = 0.0;
        }
        rows.last_mut().expect("a row").push(i);
        used += w;
    }
    rows
}

/// The height `legend` will take.
pub fn legend_height(width: f64, entries: &[LegendEntry]) -> f64 {
    legend_rows(width, entries).len() as f64 * 16.0
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn log_axis_maps_decades_linearly() {
        let axis = LogAxis {
            lo: -4,
            hi: 0,
            from: 300.0,
            to: 100.0,
            zero_at: Some(320.0),
        };
        assert_eq!(axis.map(1e-4), 300.0);
        assert_eq!(axis.map(1.0), 100.0);
        assert!((axis.map(1e-2) - 200.0).abs() < 1e-9);
        assert!((axis.map(1e-3) - 250.0).abs() < 1e-9);
        assert_eq!(axis.map(0.0), 320.0);
    }

    #[test]
    fn decades_cover_the_values() {
        assert_eq!(LogAxis::decades([0.003, 0.2]), Some((-3, 0)));
        assert_eq!(LogAxis::decades([0.0, f64::NAN, 5.0]), Some((0, 1)));
        assert_eq!(LogAxis::decades([0.0, -1.0]), None);
        // A single decade keeps one decade below.
        assert_eq!(LogAxis::decades([1.0]), Some((-1, 1)));
    }

    #[test]
    fn labels_are_plain_when_short() {
        assert_eq!(label_value(0.01, -3, 0), "0.01");
        assert_eq!(label_value(100.0, 0, 3), "100");
        assert_eq!(label_value(1e-7, -8, 0), "1e-7");
        assert_eq!(label_value(5e-7, -8, 0), "5e-7");
        assert_eq!(label_value(1.0, -8, 0), "1");
    }

    #[test]
    fn log2_axis_places_powers_of_two() {
        let axis = Log2Axis {
            lo: 0,
            hi: 8,
            from: 100.0,
            to: 500.0,
        };
        assert_eq!(axis.map(1.0), 100.0);
        assert_eq!(axis.map(256.0), 500.0);
        assert_eq!(axis.map(16.0), 300.0);
        let ticks = axis.ticks();
        assert_eq!(ticks.first().unwrap().1, "1");
        assert_eq!(ticks.last().unwrap().1, "256");
    }
}
