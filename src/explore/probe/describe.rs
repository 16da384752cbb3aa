//! The profile in words: its departures from D3D11 and Vulkan as
//! sentences, the human-readable account `probe` prints, and its JSON.

use super::diagnosis::{slope_list, SamplerKind};
use super::evidence::{PROBE_BITS, RULE_NAMES};
use super::profile::Profile;

fn rule_index(name: &str) -> usize {
    RULE_NAMES.iter().position(|r| *r == name).unwrap_or(0)
}

/// Where the nearest rule does not explain a mesh, as "mesh (n of m)".
fn inconsistencies(p: &Profile) -> Vec<String> {
    let Some(rule) = &p.fill_rule else {
        return Vec::new();
    };
    let k = rule_index(rule);
    p.fill_rule_evidence
        .iter()
        .filter(|e| e.error.is_none() && e.explained[k].samples < e.tie_samples)
        .map(|e| {
            let others: Vec<&str> = e
                .explained
                .iter()
                .filter(|c| c.samples == e.tie_samples)
                .map(|c| c.rule.as_str())
                .collect();
            format!(
                "{}: {} of {} tie samples differ{}",
                e.mesh,
                e.tie_samples - e.explained[k].samples,
                e.tie_samples,
                if others.is_empty() {
                    String::new()
                } else {
                    format!(" (explained by {})", others.join(", "))
                }
            )
        })
        .collect()
}

/// The departure of a rasterizer that is not point-sampled.
fn sampler_departure(kind: SamplerKind) -> Option<&'static str> {
    match kind {
        SamplerKind::Point => None,
        SamplerKind::Area => Some(
            "It is not point-sampled (area sampler): a pixel's coverage depends on how much of it a primitive covers, where D3D11 and Vulkan decide coverage at sample points. A fill rule, subpixel bits and a sample position do not apply to it.",
        ),
        SamplerKind::AnyCoverage => Some(
            "It is not point-sampled (any-coverage): a pixel is drawn when a primitive touches any part of it, as D3D12's and Vulkan's optional conservative rasterization (overestimate) does, not their default sample-point coverage. Shared edges are drawn by both triangles; a fill rule, subpixel bits and a sample position do not apply to it.",
        ),
        SamplerKind::OutlineOverFill => Some(
            "It is not point-sampled (outline over fill): each triangle's fill is point-sampled, then its edges are stroked over it as one-pixel hairlines, so it draws pixels whose centre no triangle covers, but not every pixel an edge touches; D3D11 and Vulkan decide coverage at sample points only. Shared edges are drawn by both triangles; a fill rule, subpixel bits and a sample position do not apply to it.",
        ),
        SamplerKind::Unknown => Some(
            "Its frames fit neither a point sampler, an area sampler nor an any-coverage one, so its fill rule, subpixel bits and sample position were not measured.",
        ),
    }
}

/// Departures from D3D11 and Vulkan, as sentences.
pub(super) fn departures(p: &Profile) -> Vec<String> {
    let mut out = Vec::new();
    if let Some(d) = sampler_departure(p.sampler) {
        out.push(d.to_owned());
        if p.y_down == Some(false) {
            out.push(Y_UP.to_owned());
        }
        out.extend(interpolation_departures(p));
        return out;
    }
    let truncates = p.truncation.starts_with("truncates");
    if truncates {
        out.push(format!(
            "Vertices are truncated to whole pixels (⌊x⌋, ⌊y⌋; {}), where D3D11 snaps to 8 subpixel bits and Vulkan to at least 4. Declared as snapping \"truncate\" it is judged at its truncated vertices (SPEC.md §3.2).",
            p.truncation.trim_start_matches("truncates vertices to whole pixels (⌊x⌋, ⌊y⌋): ")
        ));
    }
    if p.sample_offset.is_none() && truncates {
        out.push(format!(
            "Sample position: {}. Its tie rule and the precision of its edges were not measured: their probe scenes place vertices inside pixels, which truncation moves.",
            p.sample_position
        ));
        out.extend(interpolation_departures(p));
        return out;
    }
    if p.sample_offset.is_none() {
        out.push(format!(
            "Sample position: {}; D3D11 and single-sampled Vulkan sample at the pixel centre. Its tie rule and subpixel bits were not measured.",
            p.sample_position
        ));
        out.extend(interpolation_departures(p));
        return out;
    }
    match p.fill_rule.as_deref() {
        Some(rule) if p.tie_verdict == "inconsistent" => out.push(format!(
            "It has no consistent tie rule: tie samples go {rule} on most slopes, but otherwise by slope ({}; {}). D3D11 (functional spec §3.4.2.1) and Vulkan give every sample on a shared edge to the same side whatever the slope. Declared as fill_rule \"none\" it is judged exactly off the ties (SPEC.md §3.1.1).",
            slope_list(&p.tie_slopes),
            p.ties_measured_on
        )),
        None => out.push("It drew none of the fill-rule meshes, so its tie rule is unknown.".to_owned()),
        Some("top-left") => {}
        Some("all-edges") => out.push(
            "Samples on an edge belong to every triangle that has the edge (closed edges): samples on shared edges are drawn twice, where D3D11's top-left rule (functional spec §3.4.2.1) and Vulkan give each to exactly one triangle.".to_owned(),
        ),
        Some("none") => out.push(
            "Samples on an edge belong to no triangle (open edges): meshes get holes along every shared edge, where D3D11 and Vulkan give each such sample to exactly one triangle.".to_owned(),
        ),
        Some(rule) => {
            let owned = match rule {
                "bottom-right" => "bottom and right",
                "top-right" => "top and right",
                _ => "bottom and left",
            };
            out.push(format!(
                "Tie samples go to the triangle whose {owned} edges hold them ({rule}); D3D11 (functional spec §3.4.2.1) and Vulkan implementations use top-left. Meshes stay watertight, but every sample on a shared edge goes to the other triangle than on D3D11."
            ));
        }
    }
    if p.fill_rule.is_some() && !p.fill_rule_consistent && p.tie_verdict != "inconsistent" {
        out.push(format!(
            "Its tie rule is not consistent: no single fill rule explains every tie sample ({}).",
            inconsistencies(p).join("; ")
        ));
    }
    if p.y_down == Some(false) {
        out.push(Y_UP.to_owned());
    }
    if p.edge_precision
        .ends_with("stepped coarser than the vertex grid")
    {
        out.push(format!(
            "Slanted edges resolve {}, fewer bits than its vertices keep ({}): it steps edges between vertices in coarser arithmetic than it stores them in. D3D11 and Vulkan decide each sample against the edge between the snapped vertices exactly.",
            p.edge_precision.trim_end_matches(": stepped coarser than the vertex grid"),
            p.vertex_precision
        ));
    }
    match p.subpixel_bits {
        Some(0) if truncates => {}
        Some(b) if b < 4 => out.push(format!(
            "Vertices snap to {b} subpixel bits (a 1/{} px grid): fewer than Vulkan's minimum subPixelPrecisionBits of 4 and D3D11's 8.",
            1u64 << b
        )),
        Some(b) if b < 8 => out.push(format!(
            "Vertices snap to {b} subpixel bits (a 1/{} px grid); D3D11 snaps to 8 (16.8 fixed point). Vulkan allows it (subPixelPrecisionBits ≥ 4).",
            1u64 << b
        )),
        Some(b) if b > 8 => out.push(format!(
            "Vertices keep {b} subpixel bits; D3D11 snaps to exactly 8, so vertices off the 1/256 px grid land elsewhere than on D3D11 (Vulkan allows any subPixelPrecisionBits ≥ 4)."
        )),
        None if p.subpixel.starts_with("exact") => out.push(
            "Vertices keep every subpixel bit the case states (up to 16); D3D11 snaps to exactly 8, so a case stating more than 8 bits is drawn finer than on D3D11 (Vulkan allows any subPixelPrecisionBits ≥ 4).".to_owned(),
        ),
        _ => {}
    }
    if p.sample_offset != Some([0.5, 0.5]) {
        out.push(format!(
            "Sample position: {}; D3D11 and single-sampled Vulkan sample at the pixel centre.",
            p.sample_position
        ));
    }
    out.extend(interpolation_departures(p));
    out
}

const Y_UP: &str = "y points up: a triangle in the top half of the canvas is drawn in the bottom rows; D3D11 and Vulkan framebuffer coordinates point down.";

fn interpolation_departures(p: &Profile) -> Vec<String> {
    let mut out = Vec::new();
    for probe in &p.interpolation {
        for c in probe.channels.iter().filter(|c| !c.within_bound) {
            out.push(format!(
                "Interpolation of {} in the {} mesh is off by {:.3e} ({:.1} ulp), beyond rastercheck's bound of {:.3e} (SPEC §6.3).",
                c.channel, probe.case, c.max_abs, c.max_ulp, c.allowed_abs
            ));
        }
    }
    out
}

impl Profile {
    /// A human-readable account of the profile.
    pub fn describe(&self) -> String {
        let mut s = String::new();
        let ties: usize = self
            .fill_rule_evidence
            .iter()
            .filter(|e| e.error.is_none())
            .map(|e| e.tie_samples)
            .sum();
        s += &format!("profile of {}\n", self.rasterizer);
        s += &format!(
            "  sampler:            {} ({})\n",
            self.sampler.words(),
            self.sampler_evidence
        );
        s += &format!(
            "  fill rule:          {}{}\n",
            match (&self.fill_rule, self.sampler) {
                (Some(rule), _) => rule.as_str(),
                (None, SamplerKind::Point) if self.sample_offset.is_some() => "unknown",
                (None, SamplerKind::Point) => "not measured (its sample position was not found)",
                (None, _) => "not applicable (no point sample to decide ties at)",
            },
            match (&self.fill_rule, self.fill_rule_consistent) {
                (None, _) => String::new(),
                (Some(_), true) => format!(" (explains all {})", self.ties_measured_on),
                (Some(_), false) if self.tie_verdict == "inconsistent" => format!(
                    " on most slopes; inconsistent: {} ({})",
                    slope_list(&self.tie_slopes),
                    self.ties_measured_on
                ),
                (Some(_), false) => format!(", inconsistent ({ties} tie samples)"),
            }
        );
        if self.tie_verdict != "inconsistent" {
            for line in inconsistencies(self) {
                s += &format!("                      {line}\n");
            }
        }
        let off: usize = self
            .fill_rule_evidence
            .iter()
            .map(|e| e.off_edge_differences)
            .sum();
        if off > 0 {
            s += &format!("                      and {off} samples away from the edges differ from the reference\n");
        }
        if let Some(c) = &self.conservative {
            s += &format!(
                "  uncertainty:        {} ({})\n",
                c.uncertainty, c.measured_on
            );
        }
        s += &format!(
            "  y direction:        {}\n",
            match self.y_down {
                Some(true) => "down",
                Some(false) => "up",
                None => "unclear",
            }
        );
        s += &format!(
            "  subpixel precision: {}{}\n",
            self.subpixel,
            if self.subpixel.starts_with("exact") {
                format!(" (all {PROBE_BITS} bits a case can state)")
            } else {
                String::new()
            }
        );
        s += &format!("  vertex grid:        {}\n", self.vertex_precision);
        s += &format!("  edge stepping:      {}\n", self.edge_precision);
        s += &format!("  truncation:         {}\n", self.truncation);
        s += &format!("  sample position:    {}\n", self.sample_position);
        if let Some(coverage) = &self.coverage {
            s += &format!("  coverage encoding:  {coverage}\n");
        }
        if let Some(declared) = &self.declared_coverage {
            s += &format!("                      {declared}\n");
        }
        if let Some(clip) = &self.clip {
            s += &format!(
                "  clipping:           {} ({} scenes)\n",
                clip.finding, clip.scenes
            );
        }
        if let Some(points) = &self.points {
            s += &format!(
                "  points:             {} ({} scenes)\n",
                points.finding, points.scenes
            );
        }
        for probe in &self.interpolation {
            match probe.status.as_str() {
                "measured" => {
                    let worst = probe
                        .channels
                        .iter()
                        .max_by(|a, b| a.max_abs.total_cmp(&b.max_abs));
                    match worst {
                        Some(c) => {
                            s += &format!(
                                "  interpolation:      {} max {:.3e} ({:.1} ulp, {}){}\n",
                                probe.case,
                                c.max_abs,
                                c.max_ulp,
                                c.channel,
                                if probe.channels.iter().all(|c| c.within_bound) {
                                    ""
                                } else {
                                    " beyond the bound"
                                }
                            )
                        }
                        None => {
                            s += &format!(
                                "  interpolation:      {} nothing to compare\n",
                                probe.case
                            )
                        }
                    }
                }
                other => {
                    s += &format!(
                        "  interpolation:      {} {other}: {}\n",
                        probe.case,
                        probe.why.as_deref().unwrap_or("")
                    )
                }
            }
        }
        if self.departures.is_empty() {
            s += "departures from D3D11/Vulkan: none found\n";
        } else {
            s += "departures from D3D11/Vulkan:\n";
            for d in &self.departures {
                s += &format!("  - {d}\n");
            }
        }
        s
    }

    pub fn to_json(&self) -> String {
        serde_json::to_string_pretty(self).unwrap_or_default() + "\n"
    }
}
