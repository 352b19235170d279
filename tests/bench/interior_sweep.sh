#!/bin/sh
# Decomposes each domain given at N in {2, 16, 256} and Phi0 in {60, 70},
# checks every output madd writes back with `madd check` (the -o file, and
# every --split file), and prints one line per run: C1 (smallest new angle,
# separators against boundary, separators and interior segments), C3 (area
# max/mean), seconds. For real coastlines with lanes drawn across them
# (tests/bench/add_lanes.py); docs/algorithm.md, "Interior segments".
# usage: tests/bench/interior_sweep.sh BUILD_DIR DOMAIN.poly...
set -u
build=$1
shift
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
printf '%-28s %5s %4s %9s %9s %8s %s\n' domain N Phi0 C1_min C3_max seconds outputs
for domain in "$@"; do
  for phi in 60 70; do
    for n in 2 16 256; do
      rm -rf "$work/split" "$work/all.poly"
      start=$(date +%s.%N)
      if ! out=$("$build/madd" decompose "$domain" -n "$n" --min-angle "$phi" -o "$work/all.poly" \
                 --split "$work/split" 2>&1); then
        printf '%-28s %5s %4s FAILED: %s\n' "$(basename "$domain")" "$n" "$phi" "$(echo "$out" | head -1)"
        continue
      fi
      end=$(date +%s.%N)
      c1=$(echo "$out" | sed -n 's/.*C1 new angles: min \([0-9.]*\).*/\1/p')
      c3=$(echo "$out" | sed -n 's/.*C3 area max\/mean \([0-9.]*\).*/\1/p')
      checked=ok
      for f in "$work/all.poly" "$work"/split/*.poly; do
        "$build/madd" check -q "$f" || checked="madd check refused $(basename "$f")"
      done
      printf '%-28s %5s %4s %9s %9s %8.2f %s\n' "$(basename "$domain")" "$n" "$phi" "$c1" "$c3" \
        "$(echo "$end - $start" | bc)" "$checked"
    done
  done
done
