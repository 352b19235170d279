#!/bin/sh
# Builds every libFuzzer target (clang, ASan+UBSan) and runs each for SECONDS
# (default 60) on its seed corpus: data/, data/bad/, data/pslg/ and fuzz/corpus/<target>/.
# New inputs go to a scratch directory, never into the source tree.
set -eu
cd "$(dirname "$0")/.."
seconds=${1:-60}
command -v clang++ >/dev/null 2>&1 || { apt-get update -qq && apt-get install -y -qq clang libclang-rt-14-dev; }
cmake -S . -B build-fuzz -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DMADD_FUZZ=ON -DMADD_BUILD_TESTS=OFF -DMADD_BUILD_CLI=OFF -DMADD_BUILD_BENCH=OFF
cmake --build build-fuzz -j"$(nproc 2>/dev/null || echo 2)"
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
status=0
failed=
for target in build-fuzz/fuzz/fuzz_*; do
  [ -x "$target" ] || continue
  name=$(basename "$target")
  mkdir -p "$scratch/$name"
  seeds="data data/bad data/pslg"
  [ -d "fuzz/corpus/$name" ] && seeds="$seeds fuzz/corpus/$name"
  echo "== $name for ${seconds}s"
  # -timeout: one input may not run longer than 10 s (a hang is a finding).
  if ! "$target" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=4096 \
       -artifact_prefix="$scratch/$name-" "$scratch/$name" $seeds; then
    echo "fuzz target $name found a problem:"; ls "$scratch" | grep "$name-" || true
    # Kept out of the scratch dir, and said again at the end (CI shows the tail of the output).
    mkdir -p build-fuzz/findings && cp "$scratch/$name"-* build-fuzz/findings/ 2>/dev/null || true
    failed="$failed $name"
    status=1
  fi
done
for name in $failed; do
  echo "== finding of $name (also in build-fuzz/findings/):"
  for f in "$scratch/$name"-*; do [ -f "$f" ] && { echo "--- $f"; head -c 2000 "$f" | od -c | head -40; }; done
done
exit $status
