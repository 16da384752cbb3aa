#!/usr/bin/env bash
# Builds the fuzz targets and their seed corpora the way OSS-Fuzz's
# build.sh does: binaries and <target>_seed_corpus.zip in $OUT. On
# OSS-Fuzz, $SRC/rastercheck is this repository and `cargo fuzz build`
# picks up the sanitizer flags from the builder's environment; here,
# `fuzz/build.sh` alone builds into fuzz/out with no sanitizer (stable
# Rust), and SANITIZER=address builds with AddressSanitizer (nightly).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
out="${OUT:-$root/fuzz/out}"
mkdir -p "$out"
cd "$root/fuzz"
triple="$(rustc -vV | sed -n 's/^host: //p')"
if [ -n "${LIB_FUZZING_ENGINE:-}" ]; then
    # OSS-Fuzz's builder: its cargo carries the sanitizer's flags.
    cargo fuzz build -O
else
    cargo fuzz build -s "${SANITIZER:-none}" -O
fi

corpus="$(mktemp -d)"
trap 'rm -rf "$corpus"' EXIT
# The corpus writer is an ordinary build, without the fuzzing flags.
env -u RUSTFLAGS -u CARGO_BUILD_RUSTFLAGS cargo run --quiet --release \
    --manifest-path "$root/Cargo.toml" --target-dir "$root/target" -- \
    fuzz --corpus "$corpus" --corpus-cases "$root/cases"
# Every target cargo-fuzz knows (fuzz/Cargo.toml's [[bin]]s), so that a new
# one is built and shipped without an edit here.
targets="$(cargo fuzz list)"
for t in $targets; do
    cp "target/$triple/release/$t" "$out/"
    rm -f "$out/${t}_seed_corpus.zip"
    python3 - "$corpus/$t" "$out/${t}_seed_corpus.zip" <<'PY'
import os, sys, zipfile
src, dst = sys.argv[1], sys.argv[2]
with zipfile.ZipFile(dst, "w", zipfile.ZIP_DEFLATED) as z:
    for name in sorted(os.listdir(src)):
        z.write(os.path.join(src, name), name)
PY
done
echo "built into $out: $(ls "$out" | tr '\n' ' ')"
