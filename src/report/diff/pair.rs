//! The rasterizers of two reports paired: `--pair OLD=NEW` first, then
//! equal names, then the one of each.

use super::model::Pair;
use super::read::Side;

/// Pairs the rasterizers: the `explicit` pairs (`--pair OLD=NEW`) first,
/// then equal names; when that pairs nothing, no pair was given and each
/// report has one rasterizer, those two. `Err` names a `--pair` name that
/// is not in its report.
pub fn pair(old: &Side, new: &Side, explicit: &[(String, String)]) -> Result<Vec<Pair>, String> {
    let mut pairs = Vec::new();
    for (o, n) in explicit {
        for (name, side, which) in [(o, old, "OLD"), (n, new, "NEW")] {
            if !side.rasterizers.contains(name) {
                return Err(format!(
                    "--pair {o}={n}: {which} ({}) has no rasterizer {name:?}; it has {}",
                    side.file.display(),
                    side.rasterizers.join(", ")
                ));
            }
        }
        if pairs.iter().any(|p: &Pair| &p.old == o || &p.new == n) {
            return Err(format!("--pair {o}={n}: a rasterizer is paired twice"));
        }
        pairs.push(Pair {
            old: o.clone(),
            new: n.clone(),
            how: "--pair",
        });
    }
    for name in &old.rasterizers {
        let taken = pairs.iter().any(|p| &p.old == name || &p.new == name);
        if !taken && new.rasterizers.contains(name) {
            pairs.push(Pair {
                old: name.clone(),
                new: name.clone(),
                how: "same name",
            });
        }
    }
    if pairs.is_empty() && old.rasterizers.len() == 1 && new.rasterizers.len() == 1 {
        pairs.push(Pair {
            old: old.rasterizers[0].clone(),
            new: new.rasterizers[0].clone(),
            how: "one each",
        });
    }
    Ok(pairs)
}
