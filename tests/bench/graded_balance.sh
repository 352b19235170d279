#!/bin/sh
# Balance by work, measured (docs/mesh.md, "Balance by work"): meshes each
# domain given at N in {16, 64, 256} with (a) a uniform bound, area/300000,
# (c) the built-in size field (hmin = extent/2000, hmax = extent/40, distance
# rate 0.15, 3 cells across, gradation 0.2) and, when SIZES_DIR holds
# NAME.node for a domain NAME.poly, (b) those samples through --sizes. One
# line per run: triangles, the largest subdomain's triangles over the mean,
# the predicted total over the actual, the range of each subdomain's actual
# over predicted count, seconds. Fails if a mesh fails.
# usage: [SIZES_DIR=DIR] tests/bench/graded_balance.sh BUILD_DIR DOMAIN.poly...
set -eu
build=$1
shift
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
madd=$build/madd
printf '%-24s %5s %4s %9s %9s %9s %13s %8s\n' domain field N triangles max/mean pred/act sub_act/pred seconds
# The figures of one --report file, as the columns above.
figures() {
  python3 - "$1" <<'EOF'
import json, sys
r = json.load(open(sys.argv[1]))
p, a = r["subdomain_predicted_triangles"], r["subdomain_triangles"]
ratios = [x / y for x, y in zip(a, p) if y > 0]
print("%9d %9.3f %9.3f %6.2f-%-6.2f" % (r["triangles"], r["max_over_mean_triangles"],
      r["predicted_triangles"] / r["triangles"], min(ratios), max(ratios)))
EOF
}
for domain in "$@"; do
  name=$(basename "$domain" .poly)
  # The extent and the area, from madd check.
  set -- $("$madd" check "$domain" | python3 -c '
import re, sys
area = extent = 0.0
for line in sys.stdin:
    if line.strip().startswith("area"):
        area = float(line.split()[1])
    if "bounding box" in line:
        v = [float(x) for x in re.findall(r"-?[0-9.]+(?:e[-+]?[0-9]+)?", line)]
        extent = max(v[1] - v[0], v[3] - v[2])
print(extent, area)')
  extent=$1 area=$2
  uniform="-a $(python3 -c "print($area / 300000)")"
  field="--hmin $(python3 -c "print($extent / 2000)") --hmax $(python3 -c "print($extent / 40)") --distance-rate 0.15 --cells-across 3 --gradation 0.2"
  for kind in a b c; do
    case $kind in
      a) args=$uniform ;;
      b) [ -n "${SIZES_DIR:-}" ] && [ -f "$SIZES_DIR/$name.node" ] || continue
         args="--sizes $SIZES_DIR/$name.node" ;;
      c) args=$field ;;
    esac
    for n in 16 64 256; do
      start=$(date +%s.%N)
      # shellcheck disable=SC2086
      "$madd" mesh "$domain" -n "$n" -q 30 $args -o "$work/m" --report="$work/r.json" --quiet >/dev/null
      end=$(date +%s.%N)
      printf '%-24s %5s %4s %s %8.2f\n' "$name" "$kind" "$n" "$(figures "$work/r.json")" \
        "$(python3 -c "print($end - $start)")"
    done
  done
done
