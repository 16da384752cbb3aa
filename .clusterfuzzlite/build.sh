#!/usr/bin/env bash
# ClusterFuzzLite's build script: every cargo-fuzz target of fuzz/, with
# its seed corpus (<target>_seed_corpus.zip), into $OUT.
#
# In ClusterFuzzLite's builder (.clusterfuzzlite/Dockerfile) this file is
# $SRC/build.sh, run from $SRC/rastercheck with $OUT, $SANITIZER and
# $LIB_FUZZING_ENGINE set and the sanitizer's flags in cargo's environment.
# Anywhere else it runs as it is, without Docker: stable Rust, no
# sanitizer (SANITIZER=address with a nightly toolchain for one), into
# fuzz/out; CI runs it so (.github/workflows/rastercheck-shards.yml,
# fuzz-build) so that it cannot rot between fuzzing runs.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
if [ -f "$here/../fuzz/build.sh" ]; then
    root="$(cd "$here/.." && pwd)"
else
    # The builder's copy at $SRC/build.sh: the repository is the working folder.
    root="$(pwd)"
fi
exec "$root/fuzz/build.sh"
