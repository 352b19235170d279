#!/bin/sh
# Whole-process wall time of `madd mesh` at -j 1 and -j 2 against Triangle
# (issue 27's targets), K alternating runs each, medians, plus each run's
# report phases (from --report) and its serial fraction.
#
#   tests/bench/end_to_end.sh BUILD_DIR DOMAIN.poly AREA [K] [TRIANGLE] [N]
#
# BUILD_DIR holds the madd binary; AREA is the largest triangle area (-a);
# TRIANGLE, when given, is a `triangle` binary run as -pq30aAREA on the same
# domain (writing .node, .ele and .poly, as madd writes .node and .ele); N
# the subdomain count (64). Output goes to a scratch directory, removed after.
set -eu
build=$1; domain=$2; area=$3; runs=${4:-5}; triangle=${5:-}; n=${6:-64}
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
cp "$domain" "$scratch/t.poly"
now() { date +%s.%N; }
log="$scratch/times"
for i in $(seq "$runs"); do
  for j in 1 2; do
    t0=$(now)
    "$build/madd" mesh "$domain" -n "$n" -q 30 -a "$area" -j "$j" -o "$scratch/m$j" --report="$scratch/r$j.json" --quiet
    t1=$(now)
    echo "j$j $(echo "$t1 - $t0" | bc)" >>"$log"
    python3 -c "import json,sys; r=json.load(open('$scratch/r$j.json')); print('p$j', json.dumps({'phases': r['phase_seconds'], 'threads': r['thread_seconds'], 'seconds': r['seconds'], 'triangles': r['triangles']}))" >>"$log"
  done
  if [ -n "$triangle" ]; then
    t0=$(now)
    "$triangle" -pq30a"$area" -Q "$scratch/t.poly"
    t1=$(now)
    echo "tri $(echo "$t1 - $t0" | bc)" >>"$log"
  fi
done
python3 - "$log" <<'PY'
import json, statistics as st, sys
wall, reports = {}, {}
for line in open(sys.argv[1]):
    key, rest = line.split(' ', 1)
    if key.startswith('p'): reports.setdefault(key[1:], []).append(json.loads(rest))
    else: wall.setdefault(key, []).append(float(rest))
med = {k: st.median(v) for k, v in wall.items()}
for k, v in sorted(wall.items()):
    print('%-4s whole process median %.3f s  (runs: %s)' % (k, med[k], ' '.join('%.2f' % x for x in v)))
for j, rs in sorted(reports.items()):
    phases = {}
    for r in rs:
        for name, s in r['phases'].items(): phases.setdefault(name, []).append(s)
    print('-j %s phases (median s):' % j, ', '.join('%s %.3f' % (n, st.median(s)) for n, s in phases.items()),
          '| in-library %.3f | triangles %d' % (st.median(r['seconds'] for r in rs), rs[0]['triangles']))
if 'j1' in med and 'j2' in med:
    print('speed-up -j2 over -j1: %.2f' % (med['j1'] / med['j2']))
if 'tri' in med:
    for j in ('j1', 'j2'):
        if j in med: print('%s / Triangle: %.2f' % (j, med[j] / med['tri']))
PY
