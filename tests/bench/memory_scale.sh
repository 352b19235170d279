#!/bin/sh
# Time and peak memory of one large `madd mesh` run (issue 27: at most 100
# bytes a triangle at 10^7 triangles; 2 x 10^8 on a 24 GiB machine): the
# wall and CPU seconds and the peak resident set from /usr/bin/time, the
# triangle count and the phases from --report, and the peak over the
# triangles. The output files go to a scratch directory, removed at the end
# (2 x 10^8 triangles make 13 GB of them: the directory must hold that).
# DROP=1 drops the page cache first (root only), as the figures in
# docs/performance.md were taken.
#   tests/bench/memory_scale.sh BUILD_DIR DOMAIN -- MESH_OPTIONS...
# for example (10^7 triangles, then 2 x 10^8)
#   tests/bench/memory_scale.sh build data/pipe.poly -- -n 256 -q 30 -a 0.0000385 -j 2
#   tests/bench/memory_scale.sh build maine_coast.poly -- -n 1024 -q 30 -a 0.0001395 -j 2
set -eu
build=$1 domain=$2
shift 2
[ "$1" = "--" ] && shift
scratch=$(mktemp -d "${TMPDIR:-/tmp}/memory_scale.XXXXXX")
trap 'rm -rf "$scratch"' EXIT
if [ "${DROP:-0}" = 1 ]; then sync; echo 3 >/proc/sys/vm/drop_caches; fi
/usr/bin/time -f "%e %U %S %M" -o "$scratch/time" \
  "$build/madd" mesh "$domain" "$@" -o "$scratch/m" --quiet --report="$scratch/report.json"
read -r wall user sys peak_kb <"$scratch/time"
python3 - "$scratch/report.json" "$wall" "$user" "$sys" "$peak_kb" <<'PY'
import json, sys
report = json.load(open(sys.argv[1]))
wall, user, system, peak_kb = (float(v) for v in sys.argv[2:6])
triangles = report['triangles']
print('%d triangles in %.1f s (%.1f s user, %.1f s system), peak %.2f GB: %.0f bytes a triangle'
      % (triangles, wall, user, system, peak_kb * 1024 / 1e9, peak_kb * 1024 / triangles))
print('phases: ' + ', '.join('%s %.2f s' % kv for kv in report['phase_seconds'].items()))
PY
