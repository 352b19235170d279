#!/bin/sh
# madd-mpi's scaling on one machine (docs/mpi.md, "Measured"): the same mesh
# at 1 rank and at P ranks (default 2), REPEAT times each, alternating, one
# thread per rank. Prints the median wall time of the whole mpirun (start-up,
# decomposition, meshing, formatting and writing the files), the speed-up,
# the median load imbalance (slowest rank's meshing time over the mean), the
# slowest rank's decomposition, meshing and formatting seconds and the
# largest peak resident memory of a rank.
#   tests/bench/mpi_bench.sh BUILD_DIR DOMAIN.poly [-r REPEAT] [-p P] -- MESH_OPTIONS...
# for example
#   tests/bench/mpi_bench.sh build coast.poly -r 3 -- -n 64 -q 30 -a 0.005
set -eu
build=$1 domain=$2
shift 2
repeat=3 ranks=2
while [ $# -gt 0 ]; do
  case "$1" in
  -r) repeat=$2; shift 2 ;;
  -p) ranks=$2; shift 2 ;;
  --) shift; break ;;
  *) echo "usage: mpi_bench.sh BUILD_DIR DOMAIN [-r REPEAT] [-p P] -- MESH_OPTIONS..." >&2; exit 2 ;;
  esac
done
root_flag=""
[ "$(id -u)" = 0 ] && root_flag="--allow-run-as-root"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
field() { sed -n "s/^  \"$1\": \\(.*\\),\$/\\1/p" "$2" | tr -d '[]' ; }
for i in $(seq 1 "$repeat"); do
  # Alternating order, as tests/bench/end_to_end.sh: a run right after
  # another reuses its freed huge pages warm; after a pause they may be cold.
  order="1 $ranks"; [ $((i % 2)) = 0 ] && order="$ranks 1"
  for np in $order; do
    # WARMUP=1 (the default): the same run once, untimed, right before
    # (tests/bench/end_to_end.sh says why: cold memory on a virtual machine).
    if [ "${WARMUP:-1}" = 1 ]; then
      mpirun $root_flag --oversubscribe --bind-to core -np "$np" "$build/madd-mpi" mesh "$domain" -j 1 --quiet \
        -o "$work/w$np" "$@"
      rm -f "$work/w$np"*
    fi
    start=$(date +%s.%N)
    mpirun $root_flag --oversubscribe --bind-to core -np "$np" "$build/madd-mpi" mesh "$domain" -j 1 --quiet \
      --report="$work/r$np-$i.json" -o "$work/m$np" "$@"
    end=$(date +%s.%N)
    awk -v a="$start" -v b="$end" 'BEGIN { print b - a }' >> "$work/wall$np"
    field rank_imbalance "$work/r$np-$i.json" >> "$work/imbalance$np"
    field mesh_seconds "$work/r$np-$i.json" | tr ',' '\n' | sort -g | tail -1 >> "$work/slowest$np"
    field decompose_seconds "$work/r$np-$i.json" | tr ',' '\n' | sort -g | tail -1 >> "$work/decompose$np"
    field format_seconds "$work/r$np-$i.json" | tr ',' '\n' | sort -g | tail -1 >> "$work/format$np"
    field peak_resident_megabytes "$work/r$np-$i.json" | tr ',' '\n' | sort -g | tail -1 >> "$work/memory$np"
  done
done
triangles=$(field triangles "$work/r1-1.json")
printf '%s, %s triangles, %s runs each (medians; seconds)\n' "$(basename "$domain")" "$triangles" "$repeat"
printf '%-6s %8s %10s %14s %8s %10s %14s\n' ranks wall decompose "mesh(slowest)" format imbalance "MB(largest)"
for np in 1 "$ranks"; do
  printf '%-6s %8.2f %10.2f %14.2f %8.2f %10.3f %14.0f\n' "$np" "$(median < "$work/wall$np")" \
    "$(median < "$work/decompose$np")" "$(median < "$work/slowest$np")" "$(median < "$work/format$np")" \
    "$(median < "$work/imbalance$np")" "$(median < "$work/memory$np")"
done
awk -v a="$(median < "$work/wall1")" -v b="$(median < "$work/wall$ranks")" -v p="$ranks" \
  'BEGIN { printf "speed-up at %s ranks: %.2f\n", p, a / b }'
