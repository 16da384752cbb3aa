//! Moving scenes written as case text: vertices that move from one exact
//! point to another, triangles and lines, and the setups around them.

use dashu_ratio::RBig;
use rastercheck::scene::{parse_case, Cull, FillRule, Limits, Scene};

pub fn r(n: i64, d: i64) -> RBig {
    RBig::from_parts_signed(n.into(), d.into())
}

fn text(q: &RBig) -> String {
    format!("{}/{}", q.numerator(), q.denominator())
}

/// A vertex at `from` at τ = 0 and `to` at τ = 1, in pixels.
#[derive(Clone, Debug)]
pub struct Move {
    pub from: [RBig; 2],
    pub to: [RBig; 2],
}

pub fn still(p: [RBig; 2]) -> Move {
    Move {
        from: p.clone(),
        to: p,
    }
}

pub fn moving(from: [RBig; 2], to: [RBig; 2]) -> Move {
    Move { from, to }
}

fn vertex(v: &Move) -> String {
    let [fx, fy] = &v.from;
    let [tx, ty] = &v.to;
    format!(
        r#"{{"from": ["{}", "{}"], "to": ["{}", "{}"]}}"#,
        text(fx),
        text(fy),
        text(tx),
        text(ty)
    )
}

pub fn triangle(v: &[Move]) -> String {
    let vs: Vec<String> = v.iter().map(vertex).collect();
    format!(r#"{{"triangle": [{}]}}"#, vs.join(", "))
}

pub fn line(v: &[Move], width: &RBig) -> String {
    format!(
        r#"{{"line": [{}, {}], "rule": "parallelogram", "width": "{}"}}"#,
        vertex(&v[0]),
        vertex(&v[1]),
        text(width)
    )
}

/// Everything about a scene but its primitives.
#[derive(Clone, Debug)]
pub struct Setup {
    pub size: u32,
    pub bits: u32,
    pub fill: FillRule,
    pub cull: Cull,
    /// [open, close] as fractions of [0, 1], multiples of 2^-16.
    pub shutter: [RBig; 2],
    /// `effects.antialias`, as JSON.
    pub antialias: Option<String>,
}

impl Setup {
    pub fn new(size: u32) -> Setup {
        Setup {
            size,
            bits: 8,
            fill: FillRule::TopLeft,
            cull: Cull::None,
            shutter: [RBig::ZERO, RBig::ONE],
            antialias: None,
        }
    }

    pub fn scene(&self, primitives: &[String]) -> Scene {
        let antialias = self
            .antialias
            .as_ref()
            .map_or(String::new(), |a| format!(r#", "antialias": {a}"#));
        let json = format!(
            r#"{{"name": "t", "canvas": {{"width": {s}, "height": {s}}},
                "rules": {{"subpixel_bits": {}, "fill_rule": "{}", "cull": "{}"}},
                "primitives": [{}],
                "effects": {{"motion_blur": {{"shutter": ["{}", "{}"], "samples": 4}}{antialias}}}}}"#,
            self.bits,
            self.fill.name(),
            self.cull.name(),
            primitives.join(", "),
            text(&self.shutter[0]),
            text(&self.shutter[1]),
            s = self.size,
        );
        parse_case(&json, "t.json", &Limits::default()).unwrap_or_else(|e| panic!("{e}\n{json}"))
    }
}
