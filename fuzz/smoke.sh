#!/usr/bin/env bash
# The fuzz smoke test CI runs (.ci/run): not a campaign.
#  1. Builds the four libFuzzer targets with cargo-fuzz (stable Rust: no
#     sanitizer, `-s none`) and runs each over its seed corpus for a fixed
#     number of runs; none may find anything.
#  2. Builds the scene target again with `--cfg rastercheck_wrong_production`,
#     which plants a bug in production (src/production/setup.rs: bottom
#     edges owned like top ones), and checks that the same smoke budget
#     finds it: the target must stop with its finding, not pass, and not
#     crash some other way.
# Usage: fuzz/smoke.sh [RUNS]   (RUNS per target, default 2000)
set -euo pipefail
cd "$(dirname "$0")"
runs="${1:-2000}"
triple="$(rustc -vV | sed -n 's/^host: //p')"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

echo "== seed corpus (rastercheck fuzz --corpus)"
cargo run --quiet --release --manifest-path ../Cargo.toml -- \
    fuzz --corpus "$work/corpus" --corpus-cases ../cases

targets="case_json scene_reference_vs_production protocol_response exact_arithmetic"
echo "== cargo fuzz build -s none -O"
cargo fuzz build -s none -O
for t in $targets; do
    echo "== $t: $runs runs over its seeds"
    mkdir -p "$work/art/$t"
    "target/$triple/release/$t" "$work/corpus/$t" -runs="$runs" \
        -rss_limit_mb=2048 -malloc_limit_mb=2048 -timeout=25 \
        -artifact_prefix="$work/art/$t/" 2>"$work/$t.log" || {
        tail -n 40 "$work/$t.log"
        echo "error: the smoke run of $t found something (above)" >&2
        exit 1
    }
    grep -E '^Done [0-9]+ runs' "$work/$t.log" || tail -n 3 "$work/$t.log"
done

echo "== the planted bug: --cfg rastercheck_wrong_production"
RUSTFLAGS="${RUSTFLAGS:-} --cfg rastercheck_wrong_production" \
    cargo fuzz build -s none -O --target-dir target/wrong scene_reference_vs_production
mkdir -p "$work/art/wrong"
if "target/wrong/$triple/release/scene_reference_vs_production" \
    "$work/corpus/scene_reference_vs_production" -runs="$runs" -timeout=25 \
    -artifact_prefix="$work/art/wrong/" 2>"$work/wrong.log"; then
    echo "error: $runs runs did not find the bug planted in production" >&2
    exit 1
fi
if ! grep -q 'production differs from the reference' "$work/wrong.log"; then
    tail -n 40 "$work/wrong.log"
    echo "error: the target stopped, but not with the planted bug's finding (above)" >&2
    exit 1
fi
grep -m1 'production differs from the reference' "$work/wrong.log"
crash="$(ls "$work/art/wrong/"crash-* | head -n 1)"
echo "found it within $runs runs: $(basename "$crash")"
echo "fuzz smoke: ok"
