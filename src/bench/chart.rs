//! bench.svg: a hand-drawn log–log chart of error against time per item,
//! one point per method per workload, each workload's Pareto front marked.

use std::fmt::Write as _;
use std::time::Duration;

use super::model::{Measured, Report};
use super::text::time_text;

impl Report {
    /// A log–log chart of error against time per item, one point per method
    /// per workload, the Pareto front of each workload marked.
    pub fn to_svg(&self) -> String {
        const W: f64 = 820.0;
        const H: f64 = 520.0;
        const LEFT: f64 = 80.0;
        const RIGHT: f64 = 160.0;
        const TOP: f64 = 40.0;
        const BOTTOM: f64 = 60.0;
        const COLOURS: [&str; 5] = ["#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e"];
        let points: Vec<(usize, &Measured, f64, f64)> = self
            .workloads
            .iter()
            .enumerate()
            .flat_map(|(k, w)| {
                w.methods.iter().filter_map(move |m| {
                    Some((k, m, m.per_item?.as_secs_f64(), m.error_fraction()?))
                })
            })
            .filter(|p| p.2 > 0.0)
            .collect();
        let lt = |v: f64| v.log10();
        let (mut t0, mut t1) = points.iter().fold((f64::MAX, f64::MIN), |(a, b), p| {
            (a.min(lt(p.2)), b.max(lt(p.2)))
        });
        if points.is_empty() {
            (t0, t1) = (-9.0, -3.0);
        }
        t0 = t0.floor();
        t1 = t1.ceil().max(t0 + 1.0);
        let nonzero: Vec<f64> = points.iter().map(|p| p.3).filter(|&e| e > 0.0).collect();
        let mut e0 = nonzero.iter().fold(f64::MAX, |a, &e| a.min(lt(e)));
        let mut e1 = nonzero.iter().fold(f64::MIN, |a, &e| a.max(lt(e)));
        if nonzero.is_empty() {
            (e0, e1) = (-4.0, 0.0);
        }
        e0 = e0.floor();
        e1 = e1.ceil().max(e0 + 1.0);
        let plot_h = H - TOP - BOTTOM;
        let floor_y = TOP + plot_h; // zero errors
        let x_of = |t: f64| LEFT + (lt(t) - t0) / (t1 - t0) * (W - LEFT - RIGHT);
        let y_of = |e: f64| {
            if e <= 0.0 {
                floor_y
            } else {
                TOP + (e1 - lt(e)) / (e1 - e0) * (plot_h - 40.0)
            }
        };
        let mut svg = String::new();
        let _ = writeln!(
            svg,
            r#"<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" viewBox="0 0 {W} {H}" font-family="sans-serif" font-size="11">"#
        );
        let _ = writeln!(svg, r#"<rect width="{W}" height="{H}" fill="white"/>"#);
        let _ = writeln!(
            svg,
            r#"<text x="{}" y="20" text-anchor="middle" font-size="14">Error against time per item (log–log); filled: Pareto front of its workload</text>"#,
            W / 2.0
        );
        // Axes and grid.
        let right = W - RIGHT;
        let _ = writeln!(
            svg,
            r##"<line x1="{LEFT}" y1="{TOP}" x2="{LEFT}" y2="{floor_y}" stroke="#000"/><line x1="{LEFT}" y1="{floor_y}" x2="{right}" y2="{floor_y}" stroke="#000"/>"##
        );
        for d in (t0 as i32)..=(t1 as i32) {
            let x = x_of(10f64.powi(d));
            let _ = writeln!(
                svg,
                r##"<line x1="{x:.1}" y1="{TOP}" x2="{x:.1}" y2="{floor_y}" stroke="#ddd"/><text x="{x:.1}" y="{:.1}" text-anchor="middle">{}</text>"##,
                floor_y + 16.0,
                time_text(Duration::from_secs_f64(10f64.powi(d)))
            );
        }
        for d in (e0 as i32)..=(e1 as i32) {
            let y = y_of(10f64.powi(d));
            let _ = writeln!(
                svg,
                r##"<line x1="{LEFT}" y1="{y:.1}" x2="{right}" y2="{y:.1}" stroke="#ddd"/><text x="{:.1}" y="{:.1}" text-anchor="end">1e{d}</text>"##,
                LEFT - 6.0,
                y + 4.0
            );
        }
        let _ = writeln!(
            svg,
            r##"<line x1="{LEFT}" y1="{floor_y}" x2="{right}" y2="{floor_y}" stroke="#000" stroke-width="2"/><text x="{:.1}" y="{:.1}" text-anchor="end" font-weight="bold">exact</text>"##,
            LEFT - 6.0,
            floor_y + 4.0
        );
        let _ = writeln!(
            svg,
            r#"<text x="{:.1}" y="{:.1}" text-anchor="middle">time per item (triangle or line), log scale</text>"#,
            (LEFT + right) / 2.0,
            H - 16.0
        );
        let _ = writeln!(
            svg,
            r#"<text transform="translate(18 {:.1}) rotate(-90)" text-anchor="middle">error (mismatched sample or line fraction), log scale</text>"#,
            (TOP + floor_y) / 2.0
        );
        // Points, Pareto fronts, legend.
        for (k, w) in self.workloads.iter().enumerate() {
            let colour = COLOURS[k % COLOURS.len()];
            let mine: Vec<&(usize, &Measured, f64, f64)> =
                points.iter().filter(|p| p.0 == k).collect();
            let mut front: Vec<(f64, f64)> = mine
                .iter()
                .filter(|p| {
                    !mine
                        .iter()
                        .any(|q| q.2 <= p.2 && q.3 <= p.3 && (q.2 < p.2 || q.3 < p.3))
                })
                .map(|p| (p.2, p.3))
                .collect();
            front.sort_by(|a, b| a.0.total_cmp(&b.0));
            if front.len() > 1 {
                let path: Vec<String> = front
                    .iter()
                    .map(|&(t, e)| format!("{:.1},{:.1}", x_of(t), y_of(e)))
                    .collect();
                let _ = writeln!(
                    svg,
                    r#"<polyline points="{}" fill="none" stroke="{colour}" stroke-dasharray="4 3"/>"#,
                    path.join(" ")
                );
            }
            for p in &mine {
                let on_front = front.contains(&(p.2, p.3));
                let (x, y) = (x_of(p.2), y_of(p.3));
                let fill = if on_front { colour } else { "white" };
                let _ = writeln!(
                    svg,
                    r#"<circle cx="{x:.1}" cy="{y:.1}" r="4" fill="{fill}" stroke="{colour}" stroke-width="1.5"/><text x="{:.1}" y="{:.1}" fill="{colour}" transform="rotate(-30 {:.1} {:.1})">{} {}</text>"#,
                    x + 6.0,
                    y - 4.0,
                    x + 6.0,
                    y - 4.0,
                    p.1.method,
                    w.short
                );
            }
            let ly = TOP + 20.0 + 18.0 * k as f64;
            let _ = writeln!(
                svg,
                r#"<circle cx="{:.1}" cy="{ly:.1}" r="4" fill="{colour}"/><text x="{:.1}" y="{:.1}">{}</text>"#,
                right + 20.0,
                right + 30.0,
                ly + 4.0,
                w.short
            );
        }
        let _ = writeln!(svg, "</svg>");
        svg
    }
}
