#!/bin/sh
# Whole-process wall time of `madd mesh` at -j 1 and -j 2 against Triangle
# (issue 27's targets), K alternating runs each, medians, plus each run's
# report phases (from --report), the serial seconds of each phase by
# Amdahl's model (2 T2 - T1) and the speed-ups they predict.
#
#   tests/bench/end_to_end.sh BUILD_DIR DOMAIN.poly AREA [K] [TRIANGLE] [N]
#
# BUILD_DIR holds the madd binary; AREA is the largest triangle area (-a);
# TRIANGLE, when given, is a `triangle` binary run as -pq30aAREA on the same
# domain (writing .node, .ele and .poly, as madd writes .node and .ele); N
# the subdomain count (64). Output goes to a scratch directory, removed after.
# FRESH=1 removes each run's previous outputs before it starts (untimed), for
# madd and Triangle alike: replacing a file makes the kernel free the old
# one's pages in the rename (about 0.09 s for the pipe's 88 MB here), which
# a first run does not pay.
# WARMUP=1 (the default) runs each command once more, untimed, right before
# its timed run: on a virtual machine that hands freed memory back to its
# host (free page reporting), a run after a pause or after a program that
# used small pages finds its huge pages cold and pays 0.2-0.3 s to have
# them zeroed anew, one right after its twin finds them warm (see
# docs/performance.md, "Cold memory"); WARMUP=0 keeps the runs as they come.
set -eu
fresh=${FRESH:-0}
warmup=${WARMUP:-1}
build=$1; domain=$2; area=$3; runs=${4:-5}; triangle=${5:-}; n=${6:-64}
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
cp "$domain" "$scratch/t.poly"
now() { date +%s.%N; }
log="$scratch/times"
for i in $(seq "$runs"); do
  # The order alternates: a run that follows another one's exit reuses the
  # huge pages it freed, warm, while one that follows a pause or Triangle
  # (small pages) may find them handed back to a virtual machine's host and
  # pays to have them zeroed anew (0.3 s of 1.4 here, at -j 1 always when
  # -j 1 went first).
  order="1 2"; [ $((i % 2)) = 0 ] && order="2 1"
  for j in $order; do
    [ "$warmup" = 1 ] && "$build/madd" mesh "$domain" -n "$n" -q 30 -a "$area" -j "$j" -o "$scratch/w$j" --quiet
    [ "$fresh" = 1 ] && rm -f "$scratch/m$j".* "$scratch/w$j".*
    t0=$(now)
    "$build/madd" mesh "$domain" -n "$n" -q 30 -a "$area" -j "$j" -o "$scratch/m$j" --report="$scratch/r$j.json" --quiet
    t1=$(now)
    echo "j$j $(echo "$t1 - $t0" | bc)" >>"$log"
    python3 -c "import json,sys; r=json.load(open('$scratch/r$j.json')); print('p$j', json.dumps({'phases': r['phase_seconds'], 'threads': r['thread_seconds'], 'seconds': r['seconds'], 'triangles': r['triangles']}))" >>"$log"
  done
  if [ -n "$triangle" ]; then
    [ "$warmup" = 1 ] && "$triangle" -pq30a"$area" -Q "$scratch/t.poly"
    [ "$fresh" = 1 ] && rm -f "$scratch/t.1".*
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
    # Amdahl's model fitted per phase: a phase of one-thread time T1 and
    # two-thread time T2 = s + (T1 - s) / 2 has s = 2 T2 - T1 seconds that
    # do not speed up (serial code, and whatever does not scale: memory
    # bandwidth, the last subdomain's tail). "rest" is the whole process
    # outside the library's phases (reading, figures, writing, exit).
    def phase_medians(j):
        out = {}
        for r in reports[j]:
            for name, sec in r['phases'].items(): out.setdefault(name, []).append(sec)
        return {name: st.median(v) for name, v in out.items()}
    p1, p2 = phase_medians('1'), phase_medians('2')
    p1['rest'] = med['j1'] - sum(p1.values())
    p2['rest'] = med['j2'] - sum(p2.values())
    serial = {name: max(0.0, 2 * p2[name] - p1[name]) for name in p1 if name in p2}
    total = sum(serial.values())
    print('serial seconds by phase (2 T2 - T1):', ', '.join('%s %.3f' % kv for kv in serial.items()))
    # Clipping each phase's s at zero makes the sum an upper bound: a phase
    # that ran more than twice as fast on two threads (refinement's and the
    # merge's fresh pages, faulted in by two) counts 0, not below. The whole
    # process's own fit, from its medians, is the estimate itself.
    def amdahl(f):
        return ', '.join('%.1fx on %d cores' % (1 / (f + (1 - f) / c), c) for c in (2, 4, 16, 64))
    f = total / med['j1']
    print('serial fraction by phase (upper bound) %.1f%% of the one-thread time; Amdahl predicts %s' % (100 * f, amdahl(f)))
    whole = max(0.0, 2 * med['j2'] - med['j1'])
    f = whole / med['j1']
    print('serial fraction of the whole process (2 T2 - T1 = %.3f s) %.1f%%; Amdahl predicts %s' % (whole, 100 * f, amdahl(f)))
if 'tri' in med:
    for j in ('j1', 'j2'):
        if j in med: print('%s / Triangle: %.2f' % (j, med[j] / med['tri']))
PY
